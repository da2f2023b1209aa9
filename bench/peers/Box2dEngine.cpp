// Box2D 2.4 (Debian's libbox2d-dev) as a peer: one world per run, Box2D's usual 8 velocity and 3 position
// iterations, sleeping off, its other settings (continuous collision against static bodies included) left
// at their defaults as a user would.
//
// Box2D 2.4 rounds every polygon by a skin of b2_polygonRadius (1 cm): a box made with SetAsBox(h, h)
// collides as a box of half-size h + 1 cm. The scenes' boxes touch their neighbours, so such boxes would
// start 2 cm into each other and push the pyramids apart. The polygon is therefore made one skin smaller,
// so the outline that collides is the scene's box, and its density is raised to keep the scene's mass
// (Box2D 2.4 computes a polygon's mass without its skin).
//
// Box2D 2.4 has no capsule: a capsule (radius r, centres +-L) stands in as a polygon with a radius, a box of core
// half-extents (L, 2.5 mm) rounded by r - 2.5 mm: as tall as the capsule and within 2.5 mm of it at its ends
// (flattened there over 5 mm). Its mass, centre and inertia are set to the capsule's (2.4 computes a polygon's
// mass without its radius).
// The scene's chain is a b2ChainShape, whose solid side is on the right of its direction (physim's on the left),
// so it is given the points in reverse, with ghost vertices continuing its end pieces straight on. Its pieces carry
// the same 1 cm skin as polygons, so the chain is lowered by it: bodies rest where they rest on physim's.
// A scene's pins are b2RevoluteJoints made with Initialize at the pin's world point; a scene without collisions
// gives every fixture a mask of nothing.
// A scene's wheels are b2WheelJoints (Initialize at the anchor and axis, bodies not colliding as in physim). 2.4.1's
// spring takes a stiffness (N/m) and damping (N s/m) where physim takes a frequency and damping ratio for the
// effective mass along the axis, 1 / (1/mA + 1/mB + sA^2/IA + sB^2/IB) with sA = rA x axis and sB = rB x axis (the
// same mass 2.4.1's spring row uses): k = m (2 pi f)^2 and c = 2 m zeta (2 pi f) for that mass at creation give
// both engines the same spring.

#include "Engine.hpp"

#include <box2d/box2d.h>

#include <cmath>
#include <vector>

namespace peers {

namespace {

constexpr int kVelocityIterations = 8;
constexpr int kPositionIterations = 3;
constexpr double kCapsuleCore = 0.0025;  // m, half the height of a capsule's stand-in's core box

class Box2dRun final : public EngineRun {
public:
    explicit Box2dRun(const Scene& scene)
        : world_(b2Vec2(0.0f, static_cast<float>(scene.gravity))), collides_(scene.collisions) {
        world_.SetAllowSleeping(scene.sleep);
        std::vector<b2Body*> statics;
        for (const ShapeSpec& s : scene.statics) statics.push_back(add(s, b2_staticBody));
        if (!scene.chain.empty()) addChain(scene.chain);
        bodies_.reserve(scene.dynamics.size());
        for (const ShapeSpec& s : scene.dynamics) bodies_.push_back(add(s, b2_dynamicBody));
        auto body = [&](const BodyRef& r) { return r.isStatic ? statics[r.index] : bodies_[r.index]; };
        for (const PinSpec& p : scene.pins) {
            b2RevoluteJointDef jd;
            jd.Initialize(body(p.a), body(p.b), b2Vec2(static_cast<float>(p.x), static_cast<float>(p.y)));
            world_.CreateJoint(&jd);  // owned by world_
        }
        for (const WheelSpec& w : scene.wheels) addWheel(w);
    }

    void step() override {
        world_.Step(static_cast<float>(kTimeStep), kVelocityIterations, kPositionIterations);
    }

    Point position(std::size_t index) const override {
        const b2Vec2& p = bodies_[index]->GetPosition();
        return {p.x, p.y};
    }

    double angle(std::size_t index) const override { return bodies_[index]->GetAngle(); }

    std::vector<std::pair<std::string, double>> lastStepStages() const override {
        const b2Profile& p = world_.GetProfile();  // ms; solve includes the broad phase and the solver parts
        const double solveOther = p.solve - p.solveInit - p.solveVelocity - p.solvePosition - p.broadphase;
        return {{"narrow phase", 1e-3 * p.collide},        {"solve init", 1e-3 * p.solveInit},
                {"solve velocity", 1e-3 * p.solveVelocity}, {"solve position", 1e-3 * p.solvePosition},
                {"broad phase", 1e-3 * p.broadphase},      {"islands, integrate", 1e-3 * solveOther},
                {"continuous", 1e-3 * p.solveTOI}};
    }

private:
    b2Body* add(const ShapeSpec& s, b2BodyType type) {
        b2BodyDef bd;
        bd.type = type;
        bd.position.Set(static_cast<float>(s.x), static_cast<float>(s.y));
        if (type == b2_dynamicBody) {
            bd.linearVelocity.Set(static_cast<float>(s.vx), static_cast<float>(s.vy));
            bd.awake = !s.asleep;
        }
        b2Body* body = world_.CreateBody(&bd);  // owned by world_
        b2PolygonShape box;
        b2CircleShape circle;
        b2FixtureDef fd;
        double density = s.density > 0.0 ? s.density : kDensity;
        if (s.isCircle()) {
            circle.m_radius = static_cast<float>(s.radius);
            fd.shape = &circle;
        } else if (s.isCapsule()) {
            box.SetAsBox(static_cast<float>(s.halfLength), static_cast<float>(kCapsuleCore));
            box.m_radius = static_cast<float>(s.radius - kCapsuleCore);
            fd.shape = &box;
        } else {
            const double hx = s.halfWidth - b2_polygonRadius, hy = s.halfHeight - b2_polygonRadius;
            box.SetAsBox(static_cast<float>(hx), static_cast<float>(hy));
            fd.shape = &box;
            density *= (s.halfWidth * s.halfHeight) / (hx * hy);
        }
        fd.density = static_cast<float>(density);
        fd.friction = static_cast<float>(kFriction);
        if (!collides_) fd.filter.maskBits = 0;
        body->CreateFixture(&fd);
        if (s.isCapsule() && type == b2_dynamicBody) {
            const CapsuleMass m = capsuleMass(s.radius, s.halfLength);
            b2MassData md;
            md.mass = static_cast<float>(kDensity * m.area);
            md.center.SetZero();
            md.I = static_cast<float>(kDensity * m.secondMoment);
            body->SetMassData(&md);
        }
        return body;
    }

    void addWheel(const WheelSpec& w) {
        b2Body* a = bodies_[w.chassis];
        b2Body* b = bodies_[w.wheel];
        const b2Vec2 anchor(static_cast<float>(w.x), static_cast<float>(w.y));
        const b2Vec2 axis(static_cast<float>(w.axisX), static_cast<float>(w.axisY));
        b2WheelJointDef jd;
        jd.Initialize(a, b, anchor, axis);
        // Centroidal inertias: GetInertia is about the body origin.
        const double iA = a->GetInertia() - a->GetMass() * b2Dot(a->GetLocalCenter(), a->GetLocalCenter());
        const double iB = b->GetInertia() - b->GetMass() * b2Dot(b->GetLocalCenter(), b->GetLocalCenter());
        const double sA = b2Cross(anchor - a->GetWorldCenter(), axis), sB = b2Cross(anchor - b->GetWorldCenter(), axis);
        const double mass = 1.0 / (1.0 / a->GetMass() + 1.0 / b->GetMass() + sA * sA / iA + sB * sB / iB);
        const double omega = 2.0 * M_PI * w.hertz;
        jd.stiffness = static_cast<float>(mass * omega * omega);
        jd.damping = static_cast<float>(2.0 * mass * w.dampingRatio * omega);
        jd.enableMotor = w.enableMotor;
        jd.motorSpeed = static_cast<float>(w.motorSpeed);
        jd.maxMotorTorque = static_cast<float>(w.maxMotorTorque);
        world_.CreateJoint(&jd);  // owned by world_
    }

    void addChain(const std::vector<ChainPoint>& points) {
        std::vector<b2Vec2> v;
        for (auto p = points.rbegin(); p != points.rend(); ++p)
            v.emplace_back(static_cast<float>(p->x), static_cast<float>(p->y));
        const b2Vec2 before = v[0] + (v[0] - v[1]), after = v.back() + (v.back() - v[v.size() - 2]);
        b2ChainShape chain;
        chain.CreateChain(v.data(), static_cast<int32>(v.size()), before, after);
        b2BodyDef bd;  // static, one skin down
        bd.position.Set(0.0f, -b2_polygonRadius);
        b2FixtureDef fd;
        fd.shape = &chain;
        fd.friction = static_cast<float>(kFriction);
        world_.CreateBody(&bd)->CreateFixture(&fd);
    }

    b2World world_;
    bool collides_ = true;
    std::vector<b2Body*> bodies_;  // not owning: world_ frees them
};

}  // namespace

Peers peerEngines() {
    // The package's version: Box2D 2.4.1's own b2_version still says 2.4.0.
    return {{Engine{"box2d-" PEERS_BOX2D_VERSION, 1, [](const Scene& s) { return std::make_unique<Box2dRun>(s); }}}, ""};
}

}  // namespace peers
