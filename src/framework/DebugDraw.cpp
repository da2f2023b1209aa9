#include "physim/framework/DebugDraw.hpp"

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
constexpr float kLinePixels = 2.f;      // width of every line
constexpr float kCrossPixels = 6.f;     // half-length of a centre-of-mass cross
constexpr double kVelocitySeconds = 0.1;  // a velocity arrow shows the distance covered in this time
const sf::Color kPoint(220, 30, 30), kNormal(30, 60, 220), kBox(190, 0, 190), kVelocity(0, 140, 0),
    kJoint(20, 120, 120), kMouse(0, 170, 0), kCentre(20, 20, 20);
const sf::Color kSleepVeil(235, 235, 235, 160);  // the window's background, half see-through

sf::Color faded(sf::Color c) {
    c.a = 140;
    return c;
}

// Pixel-space lines kLinePixels wide (quads: GL lines are one pixel), drawn in one call.
class Lines {
public:
    void add(sf::Vector2f a, sf::Vector2f b, sf::Color c) {
        const sf::Vector2f d = b - a;
        const float len = std::hypot(d.x, d.y);
        if (len <= 0.f) return;
        const sf::Vector2f n = (0.5f * kLinePixels / len) * sf::Vector2f(-d.y, d.x);
        for (const sf::Vector2f& p : {a + n, b + n, b - n, a - n}) lines_.append(sf::Vertex(p, c));
    }
    void arrow(sf::Vector2f from, sf::Vector2f to, sf::Color c) {
        add(from, to, c);
        const sf::Vector2f d = to - from;
        const float len = std::hypot(d.x, d.y);
        if (len < 1.f) return;
        const sf::Vector2f u = d / len, n(-u.y, u.x);
        const float head = std::min(8.f, 0.4f * len);
        add(to, to - head * u + 0.5f * head * n, c);
        add(to, to - head * u - 0.5f * head * n, c);
    }
    void draw(sf::RenderTarget& target) const { target.draw(lines_); }

private:
    sf::VertexArray lines_{sf::Quads};
};

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

void drawDebug(sf::RenderTarget& target, const View& view, const World& world, const DebugDrawOptions& options) {
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
        for (JointId id : world.joints()) {
            const auto [a, b] = world.jointAnchors(id);
            const bool mouse = world.jointType(id) == JointType::Mouse;
            lines.add(px(a), px(b), mouse ? kMouse : kJoint);
            if (mouse) {  // the target (a mouse joint's first anchor): a small square
                const sf::Vector2f t = px(a);
                lines.add(t + sf::Vector2f(-4, -4), t + sf::Vector2f(4, -4), kMouse);
                lines.add(t + sf::Vector2f(4, -4), t + sf::Vector2f(4, 4), kMouse);
                lines.add(t + sf::Vector2f(4, 4), t + sf::Vector2f(-4, 4), kMouse);
                lines.add(t + sf::Vector2f(-4, 4), t + sf::Vector2f(-4, -4), kMouse);
            }
        }
    if (options.centres)
        for (BodyId id : bodies) {
            if (world.type(id) == BodyType::Static) continue;
            const sf::Vector2f c = px(world.centerOfMass(id));
            lines.add(c - sf::Vector2f(kCrossPixels, 0), c + sf::Vector2f(kCrossPixels, 0), kCentre);
            lines.add(c - sf::Vector2f(0, kCrossPixels), c + sf::Vector2f(0, kCrossPixels), kCentre);
        }
    if (options.contacts) {
        drawContacts(target, toPixels, restingContacts(world), true, lines);
        drawContacts(target, toPixels, world.contacts(), false, lines);
    }
    lines.draw(target);
}

}  // namespace physim
