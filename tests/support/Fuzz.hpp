#pragma once
// Fuzz bodies shared by the libFuzzer targets (tests/fuzz) and the fixed-seed GoogleTest that runs them in every
// test run (tests/core/StabilityFuzzTest.cpp). Each takes arbitrary bytes, turns them into shapes, poses and API
// calls, valid and invalid, and returns "" or a description of what went wrong:
//   - a value the engine accepted and later turned into NaN or infinity. Valid inputs are of sane size
//     (|coordinates| <= 1e4 m, |speeds| <= 1e3 m/s, sizes 1e-3 to 1e2 m); bad ones are NaN, infinities, zero,
//     negative or huge (1e300, which the World refuses for coordinates and speeds; forces, impulses and gravity
//     are only required finite, so they get no huge values: a known limit, docs/stability.md);
//   - a refused call (std::invalid_argument) that changed the world, or one whose message is empty;
//   - any other exception.
// Crashes and undefined behaviour are the sanitizers' to report.

#include "support/Scenes.hpp"

#include "physim/core/Collide.hpp"
#include "physim/core/TimeOfImpact.hpp"
#include "physim/core/World.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace physim::fuzz {

/// Reads the input bytes as choices; past the end every read is 0.
class Bytes {
public:
    Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    bool empty() const { return pos_ >= size_; }
    std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
    std::uint16_t word() { return static_cast<std::uint16_t>(byte() | byte() << 8); }
    int pick(int n) { return byte() % n; }
    /// Uniform-ish in [lo, hi].
    double in(double lo, double hi) { return lo + (hi - lo) * word() / 65535.0; }
    /// A sane value in [lo, hi] most of the time; one time in `rarity`, a bad one (NaN, an infinity, a huge or
    /// negative number, or -0), which a checked entry point must refuse or handle.
    /// `huge` false: no huge finite values (forces, impulses and gravity are only checked to be finite).
    double maybeBad(double lo, double hi, int rarity = 16, bool huge = true) {
        if (pick(rarity) != 0) return in(lo, hi);
        static constexpr double bad[] = {-1.0, 0.0, -0.0, 1e-300, std::numeric_limits<double>::quiet_NaN(),
                                         std::numeric_limits<double>::infinity(),
                                         -std::numeric_limits<double>::infinity(), 1e300, -1e300};
        return bad[pick(static_cast<int>(std::size(bad)) - (huge ? 0 : 2))];
    }

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t pos_ = 0;
};

inline bool finite(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

/// A valid geometry of size 1e-3 to 1e2 m: a circle, a box, a rounded box, a capsule, a segment (no mass: a dynamic
/// body of one is refused), or the convex hull-ordered polygon of 3 to 8 points on an ellipse (so makePolygon accepts
/// it unless points nearly coincide; then a box).
inline Geometry geometry(Bytes& in) {
    const double scale = std::pow(10.0, in.in(-3.0, 2.0));
    switch (in.pick(6)) {
    case 0:
        return makeCircle(scale * in.in(0.1, 1.0), scale * Vec2(in.in(-1.0, 1.0), in.in(-1.0, 1.0)));
    case 1:
        return makeBox(scale * in.in(0.05, 1.0), scale * in.in(0.05, 1.0));
    case 2:
        return makeRoundedBox(scale * in.in(0.05, 1.0), scale * in.in(0.05, 1.0), scale * in.in(0.01, 0.5));
    case 3:
        return makeCapsule(scale * Vec2(in.in(-1.0, -0.1), in.in(-1.0, 1.0)),
                           scale * Vec2(in.in(0.1, 1.0), in.in(-1.0, 1.0)), scale * in.in(0.05, 0.5));
    case 4:
        return makeSegment(scale * Vec2(in.in(-1.0, -0.1), in.in(-1.0, 1.0)),
                           scale * Vec2(in.in(0.1, 1.0), in.in(-1.0, 1.0)));
    default: {
        const int n = 3 + in.pick(Polygon::maxVertices - 2);
        const double rx = scale * in.in(0.1, 1.0), ry = scale * in.in(0.1, 1.0);
        std::vector<Vec2> points;
        double angle = in.in(0.0, 1.0);
        for (int i = 0; i < n; ++i) {
            points.push_back({rx * std::cos(angle), ry * std::sin(angle)});
            angle += (2.0 * M_PI - 0.3) / n * in.in(0.2, 1.0);
        }
        try {
            return makePolygon(points);
        } catch (const std::invalid_argument&) {
            return makeBox(rx, ry);
        }
    }
    }
}

inline Transform pose(Bytes& in, double reach) {
    return {Vec2(in.in(-reach, reach), in.in(-reach, reach)), Rotation::fromAngle(in.in(-10.0, 10.0))};
}

/// Narrow phase, distance and time of impact on random valid shapes and finite poses: the answers are finite and
/// within their documented ranges.
inline std::string collideOnce(const std::uint8_t* data, std::size_t size) {
    Bytes in(data, size);
    const Geometry a = geometry(in), b = geometry(in);
    // Near each other most of the time (so they touch), anywhere up to 1e4 m otherwise.
    const double reach = in.pick(4) ? 2.0 : 1e4;
    const Transform xa = pose(in, reach), xb = pose(in, reach);
    const Manifold m = collide(a, xa, b, xb);
    if (m.pointCount < 0 || m.pointCount > 2) return "collide: pointCount " + std::to_string(m.pointCount);
    if (m.pointCount > 0 && !(finite(m.normal) && std::abs(m.normal.norm() - 1.0) < 1e-9))
        return "collide: normal not a finite unit vector";
    for (int i = 0; i < m.pointCount; ++i)
        if (!(finite(m.points[i].point) && std::isfinite(m.points[i].separation)))
            return "collide: non-finite point " + std::to_string(i);
    const Colliding c = computeColliding(a, xa, b, xb);
    if (!(std::isfinite(c.penetration) && finite(c.normal))) return "computeColliding: non-finite";
    const DistanceOutput d = shapeDistance(a, xa, b, xb);
    if (!(std::isfinite(d.distance) && d.distance >= 0.0 && finite(d.pointA) && finite(d.pointB)))
        return "shapeDistance: non-finite or negative distance";
    Sweep sa{xa.p, xa.p + Vec2(in.in(-50.0, 50.0), in.in(-50.0, 50.0)), 0.0, in.in(-5.0, 5.0)};
    Sweep sb{xb.p, xb.p + Vec2(in.in(-50.0, 50.0), in.in(-50.0, 50.0)), 0.0, in.in(-5.0, 5.0)};
    for (const ToiResult& r : {timeOfImpact(a, sa, b, sb), sampledTimeOfImpact(a, sa, b, sb, in.in(0.01, 1.0))})
        if (!(r.t >= 0.0 && r.t <= 1.0)) return "time of impact: t = " + std::to_string(r.t) + " outside [0, 1]";
    if (!(finite(sweptAabb(a, sa).lower) && finite(sweptAabb(a, sa).upper))) return "sweptAabb: non-finite";
    return "";
}

/// The state a refused call must leave as it was: the bodies' motion (test::stateHash) and their mass and shapes.
inline std::uint64_t refusalHash(const World& world, const std::vector<BodyId>& ids) {
    std::uint64_t h = test::stateHash(world, ids);
    for (const BodyId id : ids) {
        double mass[2] = {world.mass(id), world.inertia(id)};
        std::uint64_t bits[2];
        std::memcpy(bits, mass, sizeof bits);
        h = (h ^ bits[0]) * 1099511628211ull;
        h = (h ^ bits[1]) * 1099511628211ull;
        h = (h ^ world.shapes(id).size()) * 1099511628211ull;
    }
    return h;
}

/// A world driven by the bytes: bodies of every kind created, changed, pushed, joined and destroyed (with stale
/// ids and bad values among them), settings changed, steps taken. Refused calls leave the world bit-identical;
/// accepted sane values never lead to NaN or infinity.
inline std::string worldOnce(const std::uint8_t* data, std::size_t size) {
    Bytes in(data, size);
    World world(test::awakeSettings());
    std::vector<BodyId> ids;      // every id handed out, destroyed ones included
    std::vector<JointId> joints;  // likewise
    std::vector<ShapeId> shapes;  // shapes added after their bodies, destroyed ones included
    auto anyBody = [&]() { return ids.empty() ? BodyId{} : ids[in.pick(static_cast<int>(ids.size()))]; };
    auto live = [&]() {
        std::vector<BodyId> alive;
        for (const BodyId id : ids)
            if (world.contains(id)) alive.push_back(id);
        return alive;
    };
    for (int op = 0; op < 64 && !in.empty(); ++op) {
        const std::vector<BodyId> before = live();
        const std::uint64_t hash = refusalHash(world, before);
        const std::size_t joinedBefore = world.jointCount();
        try {
            switch (in.pick(15)) {
            case 0:
            case 1: {
                BodyDef d;
                d.type = static_cast<BodyType>(in.pick(16) == 0 ? 3 + in.pick(200) : in.pick(3));
                d.shape = geometry(in);
                d.position = {in.maybeBad(-20.0, 20.0), in.maybeBad(-20.0, 20.0)};
                d.angle = in.maybeBad(-4.0, 4.0, 32);
                d.velocity = {in.maybeBad(-1e3, 1e3, 32), in.maybeBad(-1e3, 1e3, 32)};
                d.angularVelocity = in.maybeBad(-100.0, 100.0, 32);
                d.density = in.maybeBad(0.01, 100.0);
                d.restitution = in.maybeBad(0.0, 1.0, 32);
                d.staticFriction = in.maybeBad(0.0, 1.0, 32);
                d.dynamicFriction = in.maybeBad(0.0, 1.0, 32);
                d.fixedRotation = in.pick(8) == 0;
                d.collisionDetection =
                    static_cast<CollisionDetection>(in.pick(16) == 0 ? 3 + in.pick(9) : in.pick(3));
                d.precision = in.maybeBad(0.01, 1.0, 32);
                ids.push_back(world.createBody(d));
                break;
            }
            case 2:
                world.destroyBody(anyBody());
                break;
            case 3:
                world.setTransform(anyBody(), {in.maybeBad(-20.0, 20.0), in.maybeBad(-20.0, 20.0)},
                                   in.maybeBad(-4.0, 4.0));
                break;
            case 4:
                if (in.pick(2))
                    world.setVelocity(anyBody(), {in.maybeBad(-1e3, 1e3), in.maybeBad(-1e3, 1e3)});
                else
                    world.setAngularVelocity(anyBody(), in.maybeBad(-100.0, 100.0));
                break;
            case 5:  // one call per operation, so a refusal can be checked to change nothing
                switch (in.pick(3)) {
                case 0:
                    world.applyLinearImpulseAtPoint(
                        anyBody(), {in.maybeBad(-10.0, 10.0, 16, false), in.maybeBad(-10.0, 10.0, 16, false)},
                        {in.maybeBad(-20.0, 20.0), in.maybeBad(-20.0, 20.0)});
                    break;
                case 1:
                    world.applyForce(anyBody(), {in.maybeBad(-1e3, 1e3, 16, false), in.maybeBad(-1e3, 1e3, 16, false)});
                    break;
                default:
                    world.applyTorque(anyBody(), in.maybeBad(-1e3, 1e3, 16, false));
                    break;
                }
                break;
            case 6:
                world.setType(anyBody(), static_cast<BodyType>(in.pick(16) == 0 ? -1 - in.pick(100) : in.pick(3)));
                break;
            case 7:
                switch (in.pick(4)) {
                case 0:
                    world.setMass(anyBody(), in.maybeBad(0.01, 100.0));
                    break;
                case 1:
                    world.setMaterial(anyBody(), in.maybeBad(0.0, 1.0), in.maybeBad(0.0, 1.0), in.maybeBad(0.0, 1.0));
                    break;
                case 2:
                    world.setCollisionDetection(anyBody(), static_cast<CollisionDetection>(in.pick(5)),
                                                in.maybeBad(0.01, 1.0));
                    break;
                default:
                    world.setFixedRotation(anyBody(), in.pick(2) == 0);
                    break;
                }
                break;
            case 8: {
                // The options every kind shares, sometimes bad. Motors' speeds and caps, like forces, get no huge
                // values (only required finite: the known limit above).
                auto shared = [&](JointDefBase& j) {
                    j.collideConnected = in.pick(2) == 0;
                    if (in.pick(4) == 0) j.breakForce = in.maybeBad(1.0, 1e4);
                    if (in.pick(4) == 0) j.breakTorque = in.maybeBad(1.0, 1e4);
                };
                const int kind = in.pick(7);
                if (kind == 0) {
                    DistanceJointDef j;
                    shared(j);
                    j.bodyA = anyBody();
                    j.bodyB = anyBody();
                    j.localAnchorA = {in.maybeBad(-1.0, 1.0), in.maybeBad(-1.0, 1.0)};
                    j.length = in.pick(2) ? 0.0 : in.maybeBad(0.01, 10.0);
                    joints.push_back(world.createDistanceJoint(j));
                } else if (kind == 1) {
                    RevoluteJointDef j;
                    shared(j);
                    j.bodyA = anyBody();
                    j.bodyB = anyBody();
                    j.anchor = {in.maybeBad(-20.0, 20.0), in.maybeBad(-20.0, 20.0)};
                    j.enableLimit = in.pick(2) == 0;
                    j.lowerAngle = in.maybeBad(-3.0, 0.0);
                    j.upperAngle = in.maybeBad(0.0, 3.0);
                    j.enableMotor = in.pick(2) == 0;
                    j.motorSpeed = in.maybeBad(-10.0, 10.0, 16, false);
                    j.maxMotorTorque = in.maybeBad(0.0, 1e3, 16, false);
                    j.enableSpring = in.pick(2) == 0;
                    j.springHertz = in.maybeBad(0.0, 30.0);
                    j.springDampingRatio = in.maybeBad(0.0, 2.0);
                    joints.push_back(world.createRevoluteJoint(j));
                } else if (kind == 2) {
                    PrismaticJointDef j;
                    shared(j);
                    j.bodyA = anyBody();
                    j.bodyB = anyBody();
                    j.anchor = {in.maybeBad(-20.0, 20.0), in.maybeBad(-20.0, 20.0)};
                    j.axis = {in.maybeBad(-1.0, 1.0), in.maybeBad(-1.0, 1.0)};
                    j.enableLimit = in.pick(2) == 0;
                    j.lowerTranslation = in.maybeBad(-2.0, 0.0);
                    j.upperTranslation = in.maybeBad(0.0, 2.0);
                    j.enableMotor = in.pick(2) == 0;
                    j.motorSpeed = in.maybeBad(-10.0, 10.0, 16, false);
                    j.maxMotorForce = in.maybeBad(0.0, 1e3, 16, false);
                    j.enableSpring = in.pick(2) == 0;
                    j.hertz = in.maybeBad(0.0, 30.0);
                    j.dampingRatio = in.maybeBad(0.0, 2.0);
                    joints.push_back(world.createPrismaticJoint(j));
                } else if (kind == 3) {
                    WheelJointDef j;
                    shared(j);
                    j.bodyA = anyBody();
                    j.bodyB = anyBody();
                    j.anchor = {in.maybeBad(-20.0, 20.0), in.maybeBad(-20.0, 20.0)};
                    j.axis = {in.maybeBad(-1.0, 1.0), in.maybeBad(-1.0, 1.0)};
                    j.hertz = in.maybeBad(0.0, 30.0);
                    j.dampingRatio = in.maybeBad(0.0, 2.0);
                    j.enableMotor = in.pick(2) == 0;
                    j.motorSpeed = in.maybeBad(-10.0, 10.0, 16, false);
                    j.maxMotorTorque = in.maybeBad(0.0, 1e3, 16, false);
                    joints.push_back(world.createWheelJoint(j));
                } else if (kind == 4) {
                    PulleyJointDef j;
                    shared(j);
                    j.bodyA = anyBody();
                    j.bodyB = anyBody();
                    j.groundAnchorA = {in.maybeBad(-20.0, 20.0), in.maybeBad(-20.0, 20.0)};
                    j.groundAnchorB = {in.maybeBad(-20.0, 20.0), in.maybeBad(-20.0, 20.0)};
                    j.ratio = in.maybeBad(0.1, 4.0);
                    joints.push_back(world.createPulleyJoint(j));
                } else if (kind == 5) {
                    MotorJointDef j;
                    shared(j);
                    j.bodyA = anyBody();
                    j.bodyB = anyBody();
                    j.linearOffset = {in.maybeBad(-5.0, 5.0), in.maybeBad(-5.0, 5.0)};
                    j.angularOffset = in.maybeBad(-3.0, 3.0);
                    j.maxForce = in.maybeBad(0.0, 1e3, 16, false);
                    j.maxTorque = in.maybeBad(0.0, 1e3, 16, false);
                    j.correctionFactor = in.maybeBad(0.0, 1.0);
                    joints.push_back(world.createMotorJoint(j));
                } else {
                    MouseJointDef j;
                    j.body = anyBody();
                    j.target = {in.maybeBad(-20.0, 20.0), in.maybeBad(-20.0, 20.0)};
                    j.maxForce = in.maybeBad(1.0, 1e4);
                    j.hertz = in.maybeBad(0.1, 30.0);
                    j.dampingRatio = in.maybeBad(0.0, 2.0);
                    joints.push_back(world.createMouseJoint(j));
                }
                break;
            }
            case 9:
                if (joints.empty()) break;
                if (in.pick(3) == 0) {  // a gear between two of the joints made so far, any kind, live or not
                    GearJointDef g;
                    g.joint1 = joints[in.pick(static_cast<int>(joints.size()))];
                    g.joint2 = joints[in.pick(static_cast<int>(joints.size()))];
                    g.ratio = in.maybeBad(-4.0, 4.0);
                    joints.push_back(world.createGearJoint(g));
                } else {
                    world.destroyJoint(joints[in.pick(static_cast<int>(joints.size()))]);
                }
                break;
            case 10: {
                WorldSettings s = world.settings();
                s.gravity = {in.maybeBad(-20.0, 20.0, 32, false), in.maybeBad(-20.0, 20.0, 32, false)};
                s.substeps = in.pick(16) == 0 ? in.pick(3) - 1 : 1 + in.pick(8);
                s.contactHertz = in.maybeBad(10.0, 240.0, 32);
                s.restitutionThreshold = in.maybeBad(0.0, 2.0, 32);
                s.enableSleep = in.pick(2) == 0;
                s.threads = in.pick(16) == 0 ? -1 : 1 + in.pick(2);
                world.setSettings(s);
                break;
            }
            case 12: {
                ShapeDef d;
                d.geometry = geometry(in);
                d.density = in.maybeBad(0.0, 100.0);
                d.restitution = in.maybeBad(0.0, 1.0, 32);
                d.staticFriction = in.maybeBad(0.0, 1.0, 32);
                shapes.push_back(world.createShape(anyBody(), d));
                break;
            }
            case 13:
                if (!shapes.empty()) world.destroyShape(shapes[in.pick(static_cast<int>(shapes.size()))]);
                break;
            case 14: {
                ChainDef c;
                const int n = in.pick(8);
                for (int i = 0; i < n; ++i)  // sometimes a repeated or non-finite point
                    c.points.push_back(in.pick(8) == 0 && i > 0 ? c.points.back()
                                                                : Vec2(in.maybeBad(-20.0, 20.0), in.maybeBad(-5.0, 5.0)));
                c.loop = in.pick(3) == 0;
                c.restitution = in.maybeBad(0.0, 1.0, 32);
                for (const ShapeId s : world.createChain(anyBody(), c)) shapes.push_back(s);
                break;
            }
            default:
                world.step(in.pick(16) == 0 ? in.maybeBad(0.0, 1.0, 1) : in.in(1e-3, 1.0 / 30.0));
                break;
            }
        } catch (const std::invalid_argument& e) {
            if (std::string(e.what()).empty()) return "a refusal with no message";
            if (live() != before || refusalHash(world, before) != hash || world.jointCount() != joinedBefore)
                return std::string("a refused call changed the world: ") + e.what();
        } catch (const std::exception& e) {
            return std::string("unexpected exception: ") + e.what();
        }
        for (const BodyId id : live())
            if (!(finite(world.position(id)) && finite(world.velocity(id)) && std::isfinite(world.angle(id)) &&
                  std::isfinite(world.angularVelocity(id))))
                return "non-finite state of body " + std::to_string(id.index) + " after operation " +
                       std::to_string(op);
    }
    return "";
}

}  // namespace physim::fuzz
