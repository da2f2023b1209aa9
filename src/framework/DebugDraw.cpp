#include "physim/framework/DebugDraw.hpp"

#include "Lines.hpp"

#include "physim/core/Collide.hpp"
#include "physim/core/World.hpp"

#include <SFML/Graphics/CircleShape.hpp>
#include <SFML/Graphics/ConvexShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/VertexArray.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace physim {
namespace {

constexpr float kNormalPixels = 36.f;   // drawn length of a contact normal
constexpr float kPointPixels = 4.f;     // radius of a contact point's dot
constexpr float kCrossPixels = 6.f;     // half-length of a centre-of-mass cross
constexpr float kPinPixels = 5.f;       // radius of a revolute pin's ring
constexpr float kLimitPixels = 22.f;    // length of a revolute limit's ray
constexpr float kAxisPixels = 25.f;     // a slider's axis line reaches at least this far either side of its anchor
constexpr float kTickPixels = 6.f;      // half-length of a slider limit's tick
constexpr float kWeldPixels = 5.f;      // half-size of a weld's square
constexpr float kHitPixels = 5.f;       // radius of a ray's hit point
constexpr double kVelocitySeconds = 0.1;  // a velocity arrow shows the distance covered in this time
const sf::Color kPoint(220, 30, 30), kNormal(30, 60, 220), kBox(190, 0, 190), kVelocity(0, 140, 0),
    kJoint(20, 120, 120), kMouse(0, 170, 0), kCentre(20, 20, 20), kSensor(230, 150, 0), kRay(230, 120, 0);
const sf::Color kSleepVeil(235, 235, 235, 160);  // the window's background, half see-through
const sf::Color kGhost(70, 90, 220, 110);          // a branch's bodies: blue, see-through

sf::Color faded(sf::Color c) {
    c.a = 140;
    return c;
}

void drawContacts(sf::RenderTarget& target, const sf::Transform& toPixels, const std::vector<Manifold>& contacts,
                  bool resting, Lines& lines) {
    // Resting contacts: the same colours, see-through, the points as rings.
    sf::CircleShape dot(kPointPixels);
    dot.setOrigin(kPointPixels, kPointPixels);
    dot.setFillColor(resting ? sf::Color::Transparent : kPoint);
    dot.setOutlineColor(faded(kPoint));
    dot.setOutlineThickness(resting ? -1.5f : 0.f);
    for (const Manifold& m : contacts) {
        const sf::Vector2f n(static_cast<float>(m.normal.x()), static_cast<float>(-m.normal.y()));  // y down
        for (int i = 0; i < m.pointCount; ++i) {
            const Vec2& p = m.points[static_cast<std::size_t>(i)].point;
            const sf::Vector2f px = toPixels.transformPoint(static_cast<float>(p.x()), static_cast<float>(p.y()));
            lines.arrow(px, px + kNormalPixels * n, resting ? faded(kNormal) : kNormal);
            dot.setPosition(px);
            target.draw(dot);
        }
    }
}

// A collision shape in pixels, filled with `fill` (a veil over a sleeping body's mesh): every kind with area is
// convex, so its outline (computed by the core) fills as one convex polygon; a segment or chain piece, whose
// outline is its two points, is a line.
void drawShape(sf::RenderTarget& target, const sf::Transform& toPixels, const Geometry& g, const Transform& xf,
               sf::Color fill, Lines& lines) {
    const std::vector<Vec2> points = outline(g, xf);
    const auto px = [&](const Vec2& p) {
        return toPixels.transformPoint(static_cast<float>(p.x()), static_cast<float>(p.y()));
    };
    if (std::holds_alternative<Segment>(g) || std::holds_alternative<ChainSegment>(g)) {
        lines.add(px(points.front()), px(points.back()), fill);
        return;
    }
    sf::ConvexShape shape(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        shape.setPoint(i, px(points[i]));
    shape.setFillColor(fill);
    target.draw(shape);
}

// Bodies that the step treats as not moving: asleep, static, or kinematic at rest.
bool atRest(const World& world, BodyId id) {
    switch (world.type(id)) {
        case BodyType::Static: return true;
        case BodyType::Kinematic: return world.velocity(id) == Vec2::Zero() && world.angularVelocity(id) == 0.0;
        case BodyType::Dynamic: return !world.isAwake(id);
    }
    return false;
}

void square(Lines& lines, sf::Vector2f c, float half, sf::Color colour) {
    lines.add(c + sf::Vector2f(-half, -half), c + sf::Vector2f(half, -half), colour);
    lines.add(c + sf::Vector2f(half, -half), c + sf::Vector2f(half, half), colour);
    lines.add(c + sf::Vector2f(half, half), c + sf::Vector2f(-half, half), colour);
    lines.add(c + sf::Vector2f(-half, half), c + sf::Vector2f(-half, -half), colour);
}

void ring(Lines& lines, sf::Vector2f c, float radius, sf::Color colour) {
    constexpr int kSides = 12;
    for (int i = 0; i < kSides; ++i) {
        const float t0 = 2.f * static_cast<float>(M_PI) * i / kSides;
        const float t1 = 2.f * static_cast<float>(M_PI) * (i + 1) / kSides;
        lines.add(c + radius * sf::Vector2f(std::cos(t0), std::sin(t0)),
                  c + radius * sf::Vector2f(std::cos(t1), std::sin(t1)), colour);
    }
}

// A ray along the pixel direction u (unit) from `from` to `to` pixels off c.
void ray(Lines& lines, sf::Vector2f c, sf::Vector2f u, float from, float to, sf::Color colour) {
    lines.add(c + from * u, c + to * u, colour);
}

// One joint, drawn so its kind shows: a pin as a ring at its anchor (limits as rays out of it at the lower and upper
// angles and a shorter one at the angle now), a slider (prismatic, wheel) as a line along its axis through A's anchor
// (limits as ticks across it), a pulley as its rope, a gear as a line between its bodies' centres, a weld as a
// square, a mouse joint as a line to its target's square, the other kinds as a line between their anchors.
template <class ToPixels>
void drawJoint(const World& world, JointId id, const ToPixels& px, Lines& lines) {
    const std::pair<Vec2, Vec2> anchors = world.jointAnchors(id);  // not a structured binding: lambdas capture it
    const Vec2 a = anchors.first, b = anchors.second;
    switch (world.jointType(id)) {
        case JointType::Mouse:
            lines.add(px(a), px(b), kMouse);
            square(lines, px(a), kPointPixels, kMouse);  // the target (a mouse joint's first anchor)
            return;
        case JointType::Revolute: {
            lines.add(px(a), px(b), kJoint);  // apart only while the pin is pulled open
            ring(lines, px(a), kPinPixels, kJoint);
            const JointLimits limits = world.jointLimits(id);
            if (!limits.enabled) return;
            const double base = world.angle(world.jointBodies(id).first);  // the limits turn with A
            const auto towards = [&](double angle) {  // the pixel direction of a world angle, through the view
                const sf::Vector2f d = px(a + Vec2(std::cos(angle), std::sin(angle))) - px(a);
                return d / std::max(1e-6f, std::hypot(d.x, d.y));
            };
            ray(lines, px(a), towards(base + limits.lower), kPinPixels, kLimitPixels, kJoint);
            ray(lines, px(a), towards(base + limits.upper), kPinPixels, kLimitPixels, kJoint);
            ray(lines, px(a), towards(base + world.jointAngle(id)), kPinPixels, 0.6f * kLimitPixels, kJoint);
            return;
        }
        case JointType::Prismatic:
        case JointType::Wheel: {
            const Vec2 axis = world.jointAxis(id);
            const JointLimits limits = world.jointLimits(id);
            // Along the axis from A's anchor, m: at least kAxisPixels either side, and far enough to show B's
            // anchor and the limits.
            const sf::Vector2f unitPx = px(a + axis) - px(a);
            const double metresPerPixel = 1.0 / std::max(1e-9, static_cast<double>(std::hypot(unitPx.x, unitPx.y)));
            double lo = -kAxisPixels * metresPerPixel, hi = -lo;
            const double at = axis.dot(b - a);
            lo = std::min(lo, at);
            hi = std::max(hi, at);
            if (limits.enabled) {
                lo = std::min(lo, limits.lower);
                hi = std::max(hi, limits.upper);
            }
            lines.add(px(a + lo * axis), px(a + hi * axis), kJoint);
            lines.add(px(a), px(b), kJoint);  // off the axis only while the slider is pulled open
            if (!limits.enabled) return;
            const Vec2 across = (kTickPixels * metresPerPixel) * Vec2(-axis.y(), axis.x());
            for (const double t : {limits.lower, limits.upper})
                lines.add(px(a + t * axis - across), px(a + t * axis + across), kJoint);
            return;
        }
        case JointType::Pulley: {
            const auto [groundA, groundB] = world.jointPulleyGroundAnchors(id);
            lines.add(px(groundA), px(a), kJoint);
            lines.add(px(groundB), px(b), kJoint);
            lines.add(px(groundA), px(groundB), kJoint);
            return;
        }
        case JointType::Gear: {
            const auto [bodyA, bodyB] = world.jointBodies(id);
            lines.add(px(world.centerOfMass(bodyA)), px(world.centerOfMass(bodyB)), kJoint);
            return;
        }
        case JointType::Weld:
            lines.add(px(a), px(b), kJoint);
            square(lines, px(a), kWeldPixels, kJoint);
            return;
        case JointType::Distance:
        case JointType::Spring:
        case JointType::Motor:
            lines.add(px(a), px(b), kJoint);
            return;
    }
}

}  // namespace

std::vector<Manifold> restingContacts(const World& world) {
    std::vector<Manifold> found;
    const std::vector<BodyId> ids = world.bodies();
    const auto asleep = [&](BodyId id) { return world.type(id) == BodyType::Dynamic && !world.isAwake(id); };
    if (std::none_of(ids.begin(), ids.end(), asleep)) return found;
    std::vector<Aabb> boxes;
    std::vector<std::vector<ShapeId>> shapes;  // every body's, a chain ground's many pieces included
    boxes.reserve(ids.size());
    shapes.reserve(ids.size());
    for (BodyId id : ids) {
        boxes.push_back(world.bounds(id));
        shapes.push_back(world.shapes(id));
    }
    // Pairs the last step still computed (a body that fell asleep at its end) are the step's, not drawn twice.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> stepPairs;
    for (const Manifold& m : world.contacts()) stepPairs.emplace_back(m.bodyA.index, m.bodyB.index);
    std::sort(stepPairs.begin(), stepPairs.end());
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (!asleep(ids[i])) continue;  // a sleeper ...
        for (std::size_t j = 0; j < ids.size(); ++j) {
            // ... against another body at rest; a pair of sleepers once (i < j).
            if (j == i || !atRest(world, ids[j])) continue;
            if (world.type(ids[j]) == BodyType::Dynamic && j < i) continue;
            if (!boxes[i].overlaps(boxes[j])) continue;
            // Ordered by slot as the step orders its pairs, so the normal points the same way.
            const std::size_t a = std::min(i, j), b = std::max(i, j);
            if (std::binary_search(stepPairs.begin(), stepPairs.end(), std::make_pair(ids[a].index, ids[b].index)))
                continue;
            for (ShapeId sa : shapes[a])
                for (ShapeId sb : shapes[b]) {
                    if (world.isSensor(sa) || world.isSensor(sb)) continue;  // sensors touch nothing
                    if (!world.bounds(sa).overlaps(world.bounds(sb))) continue;
                    Manifold m = collide(world.geometry(sa), world.transform(ids[a]), world.geometry(sb),
                                         world.transform(ids[b]));
                    if (m.pointCount == 0) continue;
                    m.bodyA = ids[a];
                    m.bodyB = ids[b];
                    found.push_back(m);
                }
        }
    }
    return found;
}

void drawGhosts(sf::RenderTarget& target, const View& view, const World& world) {
    const sf::Transform toPixels = view.worldToPixels(target.getSize());
    Lines lines;
    for (const BodyId id : world.bodies())
        if (world.type(id) != BodyType::Static)
            for (const ShapeId s : world.shapes(id))
                drawShape(target, toPixels, world.geometry(s), world.transform(id), kGhost, lines);
    lines.draw(target);
}

void drawDebug(sf::RenderTarget& target, const View& view, const World& world, const DebugDrawOptions& options,
               const std::vector<DebugRay>& rays) {
    if (!options.any()) return;
    const sf::Transform toPixels = view.worldToPixels(target.getSize());
    const auto px = [&](const Vec2& p) {
        return toPixels.transformPoint(static_cast<float>(p.x()), static_cast<float>(p.y()));
    };
    const std::vector<BodyId> bodies = world.bodies();
    Lines lines;
    if (options.sleep)
        for (BodyId id : bodies)
            if (world.type(id) == BodyType::Dynamic && !world.isAwake(id))
                for (ShapeId s : world.shapes(id))
                    drawShape(target, toPixels, world.geometry(s), world.transform(id), kSleepVeil, lines);
    if (options.boxes)
        for (BodyId id : bodies) {
            const Aabb box = world.bounds(id);  // of all its shapes
            const sf::Vector2f lo = px(box.lower), hi = px(box.upper);  // lo is bottom-left on screen
            lines.add(lo, {hi.x, lo.y}, kBox);
            lines.add({hi.x, lo.y}, hi, kBox);
            lines.add(hi, {lo.x, hi.y}, kBox);
            lines.add({lo.x, hi.y}, lo, kBox);
        }
    if (options.velocities)
        for (BodyId id : bodies)
            if (world.type(id) != BodyType::Static && world.velocity(id) != Vec2::Zero())
                lines.arrow(px(world.centerOfMass(id)),
                            px(world.centerOfMass(id) + kVelocitySeconds * world.velocity(id)), kVelocity);
    if (options.joints)
        for (JointId id : world.joints()) drawJoint(world, id, px, lines);
    if (options.centres)
        for (BodyId id : bodies) {
            if (world.type(id) == BodyType::Static) continue;
            const sf::Vector2f c = px(world.centerOfMass(id));
            lines.add(c - sf::Vector2f(kCrossPixels, 0), c + sf::Vector2f(kCrossPixels, 0), kCentre);
            lines.add(c - sf::Vector2f(0, kCrossPixels), c + sf::Vector2f(0, kCrossPixels), kCentre);
        }
    if (options.sensors)  // outlined only: a sensor holds nothing, and what passes through it stays visible
        for (BodyId id : bodies)
            for (ShapeId s : world.shapes(id)) {
                if (!world.isSensor(s)) continue;
                const sf::Color colour = world.sensorOverlaps(s).empty() ? faded(kSensor) : kSensor;
                const std::vector<Vec2> points = outline(world.geometry(s), world.transform(id));
                const std::size_t n = points.size(), edges = n > 2 ? n : n - 1;  // a segment's is its 2 points
                for (std::size_t i = 0; i < edges; ++i) lines.add(px(points[i]), px(points[(i + 1) % n]), colour);
            }
    if (options.contacts) {
        drawContacts(target, toPixels, restingContacts(world), true, lines);
        drawContacts(target, toPixels, world.contacts(), false, lines);
    }
    if (options.rays) {
        sf::CircleShape dot(kHitPixels);
        dot.setOrigin(kHitPixels, kHitPixels);
        dot.setFillColor(kRay);
        for (const DebugRay& r : rays) {
            const Vec2 end = r.origin + r.translation;
            if (!r.hit) {
                lines.add(px(r.origin), px(end), faded(kRay));
                continue;
            }
            lines.add(px(r.origin), px(r.hit->point), kRay);
            lines.add(px(r.hit->point), px(end), faded(kRay));
            const sf::Vector2f n(static_cast<float>(r.hit->normal.x()), static_cast<float>(-r.hit->normal.y()));
            lines.arrow(px(r.hit->point), px(r.hit->point) + kNormalPixels * n, kNormal);
            dot.setPosition(px(r.hit->point));
            target.draw(dot);
        }
    }
    lines.draw(target);
}

}  // namespace physim
