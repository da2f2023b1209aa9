#include "Arrows.hpp"

#include "physim/core/Validate.hpp"
#include "physim/core/World.hpp"

#include <cmath>
#include <cstddef>

namespace physim {

namespace {

// What a contact's points passed to body B over the last step, N s (the normal points from A to B: A got the
// opposite).
Vec2 impulseOnB(const Manifold& m) {
    Vec2 onB = Vec2::Zero();
    for (int i = 0; i < m.pointCount; ++i) {
        const ContactPoint& p = m.points[static_cast<std::size_t>(i)];
        onB += p.normalImpulse * m.normal + p.tangentImpulse * perp(m.normal);
    }
    return onB;
}

}  // namespace

std::vector<BodyArrows> bodyArrows(const World& world, double dt) {
    requirePositive("arrows' step", dt);
    std::vector<BodyArrows> arrows;
    std::vector<std::size_t> slot;  // body index -> place in `arrows`, or none
    constexpr std::size_t none = static_cast<std::size_t>(-1);
    const Vec2 g = world.settings().gravity;
    for (BodyId id : world.bodies()) {
        if (world.type(id) != BodyType::Dynamic) continue;
        if (id.index >= slot.size()) slot.resize(id.index + 1, none);
        slot[id.index] = arrows.size();
        arrows.push_back({id, world.centerOfMass(id), world.velocity(id), world.mass(id) * world.gravityScale(id) * g,
                          Vec2::Zero()});
    }
    const auto add = [&](BodyId body, const Vec2& force) {
        if (body.index < slot.size() && slot[body.index] != none && arrows[slot[body.index]].body == body)
            arrows[slot[body.index]].contact += force;
    };
    const auto addAll = [&](const std::vector<Manifold>& contacts) {
        for (const Manifold& m : contacts) {
            const Vec2 onB = impulseOnB(m) / dt;
            add(m.bodyB, onB);
            add(m.bodyA, -onB);
        }
    };
    addAll(world.contacts());
    addAll(world.sleepingContacts());
    return arrows;
}

std::vector<JointArrows> jointArrows(const World& world) {
    std::vector<JointArrows> arrows;
    for (const JointId id : world.joints()) {
        const auto [a, b] = world.jointAnchors(id);
        const auto [bodyA, bodyB] = world.jointBodies(id);
        arrows.push_back({a, b, world.jointReactionForce(id), bodyA == bodyB});  // B twice: a joint to a point
    }
    return arrows;
}

Vec2 contactForceOn(const World& world, BodyId body, double dt) {
    requirePositive("contact force's step", dt);
    Vec2 force = Vec2::Zero();
    const std::vector<Manifold> lists[] = {world.contacts(), world.sleepingContacts()};
    for (const std::vector<Manifold>& list : lists)
        for (const Manifold& m : list) {
            if (m.bodyA != body && m.bodyB != body) continue;
            const Vec2 onB = impulseOnB(m);
            force += (m.bodyB == body ? onB : -onB) / dt;
        }
    return force;
}

Vec2 jointForceOn(const World& world, BodyId body) {
    Vec2 force = Vec2::Zero();
    for (const JointId id : world.joints()) {
        const auto [a, b] = world.jointBodies(id);
        if (b == body) force += world.jointReactionForce(id);
        else if (a == body) force -= world.jointReactionForce(id);
    }
    return force;
}

double roundScaleUp(double value) {
    requirePositive("arrow scale", value);
    const double decade = std::pow(10.0, std::floor(std::log10(value)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * decade >= value * (1.0 - 1e-12)) return m * decade;  // 1e-12: pow and log10's rounding
    return 10.0 * decade;
}

double ArrowScale::update(double largest, double maxLength) {
    requireNonNegative("largest arrow", largest);
    requirePositive("arrow length", maxLength);
    if (largest <= 0.0) {
        if (perMetre_ == 0.0) perMetre_ = 1.0;  // nothing to show yet: any scale
        return perMetre_;
    }
    const double wanted = largest / maxLength;
    if (perMetre_ < wanted || perMetre_ > 10.0 * wanted) perMetre_ = roundScaleUp(wanted);
    return perMetre_;
}

}  // namespace physim
