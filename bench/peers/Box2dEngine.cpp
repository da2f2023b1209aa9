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
// Bodies of several parts (Box2D v3's compound bodies): one fixture each. A sharp polygon part is made one skin
// smaller (each edge moved in by it), as the boxes are, with its density raised to keep its mass; a rounded part
// takes its rounding as its radius, and its core's mass (2.4.1 counts no rounding: the spinner's bar is about a
// third light, which its motor of unbounded torque does not feel). A capsule part stands in as a capsule ShapeSpec
// does, and a body with one gets the capsules' mass and inertia (the other parts' as 2.4.1 computes them).
// 2.4.1's revolute joint has limits and a motor but no spring: a pin's spring (rain's ragdolls) is left out there.
// A loop part is a b2ChainShape loop given clockwise (its solid side on the right), not moved by its skin.
// Kinematic bodies, sweeps (SetLinearVelocity before each step) and waves (bodies destroyed with their joints,
// then made again) are as in physim.
// A scene's wheels are b2WheelJoints (Initialize at the anchor and axis, bodies not colliding as in physim). 2.4.1's
// spring takes a stiffness (N/m) and damping (N s/m) where physim takes a frequency and damping ratio for the
// effective mass along the axis, 1 / (1/mA + 1/mB + sA^2/IA + sB^2/IB) with sA = rA x axis and sB = rB x axis (the
// same mass 2.4.1's spring row uses): k = m (2 pi f)^2 and c = 2 m zeta (2 pi f) for that mass at creation give
// both engines the same spring.

#include "Engine.hpp"

#include <box2d/box2d.h>

#include <algorithm>
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
        : world_(b2Vec2(0.0f, static_cast<float>(scene.gravity))), scene_(scene), collides_(scene.collisions) {
        world_.SetAllowSleeping(scene.sleep);
        for (const ShapeSpec& s : scene.statics) statics_.push_back(add(s, b2_staticBody));
        if (!scene.chain.empty()) addChain(scene.chain);
        bodies_.assign(scene.dynamics.size(), nullptr);
        for (std::size_t i = 0; i < scene.firstWaveBody(); ++i) bodies_[i] = add(scene.dynamics[i], b2_dynamicBody);
        for (const ShapeSpec& s : scene.kinematics) kinematics_.push_back(add(s, b2_kinematicBody));
        for (std::size_t i = 0; i < scene.firstWavePin(); ++i) addPin(scene.pins[i]);
        for (const WheelSpec& w : scene.wheels) addWheel(w);
    }

    void step() override {
        beforeStep(steps_++);
        world_.Step(static_cast<float>(kTimeStep), kVelocityIterations, kPositionIterations);
    }

    // A wave's body before its wave first came: NaN.
    Point position(std::size_t index) const override {
        if (bodies_[index] == nullptr) return {std::nan(""), std::nan("")};
        const b2Vec2& p = bodies_[index]->GetPosition();
        return {p.x, p.y};
    }

    double angle(std::size_t index) const override {
        return bodies_[index] == nullptr ? std::nan("") : bodies_[index]->GetAngle();
    }

    std::vector<std::pair<std::string, double>> lastStepStages() const override {
        const b2Profile& p = world_.GetProfile();  // ms; solve includes the broad phase and the solver parts
        const double solveOther = p.solve - p.solveInit - p.solveVelocity - p.solvePosition - p.broadphase;
        return {{"narrow phase", 1e-3 * p.collide},        {"solve init", 1e-3 * p.solveInit},
                {"solve velocity", 1e-3 * p.solveVelocity}, {"solve position", 1e-3 * p.solvePosition},
                {"broad phase", 1e-3 * p.broadphase},      {"islands, integrate", 1e-3 * solveOther},
                {"continuous", 1e-3 * p.solveTOI}};
    }

private:
    // What physim's step does before each step of the scene (Scene::sweeps, Scene::waves).
    void beforeStep(long n) {
        for (const SweepSpec& sw : scene_.sweeps) {
            const ShapeSpec& k = scene_.kinematics[sw.kinematic];
            b2Body* body = kinematics_[sw.kinematic];
            const double tx = k.x + sw.amplitude * std::sin(sw.rate * n * kTimeStep);
            const b2Vec2 p = body->GetPosition();
            body->SetLinearVelocity(b2Vec2(static_cast<float>((tx - p.x) / kTimeStep),
                                           static_cast<float>((k.y - p.y) / kTimeStep)));
        }
        const long w = scene_.waveBefore(n);
        if (w < 0) return;
        const WaveSpec& wave = scene_.waves[static_cast<std::size_t>(w)];
        for (std::size_t i = wave.firstBody; i < wave.firstBody + wave.bodyCount; ++i) {
            if (bodies_[i] != nullptr) world_.DestroyBody(bodies_[i]);  // its joints go with it
            bodies_[i] = add(scene_.dynamics[i], b2_dynamicBody);
        }
        for (std::size_t i = wave.firstPin; i < wave.firstPin + wave.pinCount; ++i) addPin(scene_.pins[i]);
    }

    b2Body* add(const ShapeSpec& s, b2BodyType type) {
        b2BodyDef bd;
        bd.type = type;
        bd.position.Set(static_cast<float>(s.x), static_cast<float>(s.y));
        if (type != b2_staticBody) {
            bd.linearVelocity.Set(static_cast<float>(s.vx), static_cast<float>(s.vy));
            bd.angularVelocity = static_cast<float>(s.angularVelocity);
            bd.linearDamping = static_cast<float>(s.linearDamping);
            bd.allowSleep = s.allowSleep;
        }
        if (type == b2_dynamicBody) bd.awake = !s.asleep;
        b2Body* body = world_.CreateBody(&bd);  // owned by world_
        if (s.isShapeless()) return body;
        if (s.isCompound()) {
            bool capsules = false;
            for (const PartSpec& p : s.parts) {
                addPart(body, p);
                capsules = capsules || p.kind == PartSpec::Kind::Capsule;
            }
            if (capsules && type == b2_dynamicBody) setCompoundMass(body, s.parts);
            return body;
        }
        b2PolygonShape box;
        b2CircleShape circle;
        b2FixtureDef fd;
        double density = s.material.density;
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
        setMaterial(fd, s.material);
        body->CreateFixture(&fd);
        if (s.isCapsule() && type == b2_dynamicBody) {
            const CapsuleMass m = capsuleMass(s.radius, s.halfLength);
            b2MassData md;
            md.mass = static_cast<float>(s.material.density * m.area);
            md.center.SetZero();
            md.I = static_cast<float>(s.material.density * m.secondMoment);
            body->SetMassData(&md);
        }
        return body;
    }

    void setMaterial(b2FixtureDef& fd, const Material& m) const {
        fd.friction = static_cast<float>(m.friction);
        fd.restitution = static_cast<float>(m.restitution);
        fd.filter.categoryBits = static_cast<uint16>(m.category);
        fd.filter.maskBits = collides_ ? static_cast<uint16>(m.mask) : 0;
        fd.filter.groupIndex = static_cast<int16>(m.group);
    }

    void addPart(b2Body* body, const PartSpec& p) {
        b2FixtureDef fd;
        setMaterial(fd, p.material);
        double density = p.material.density;
        std::vector<b2Vec2> v;
        for (const ChainPoint& c : p.points) v.emplace_back(static_cast<float>(c.x), static_cast<float>(c.y));
        b2PolygonShape polygon;
        b2CircleShape circle;
        b2EdgeShape edge;
        b2ChainShape loop;
        switch (p.kind) {
        case PartSpec::Kind::Loop:
            std::reverse(v.begin(), v.end());  // clockwise: solid on the right of its direction
            loop.CreateLoop(v.data(), static_cast<int32>(v.size()));
            fd.shape = &loop;
            break;
        case PartSpec::Kind::Circle:
            circle.m_p = v.at(0);
            circle.m_radius = static_cast<float>(p.radius);
            fd.shape = &circle;
            break;
        case PartSpec::Kind::Segment:
            edge.SetTwoSided(v.at(0), v.at(1));
            fd.shape = &edge;
            break;
        case PartSpec::Kind::Capsule: {
            const b2Vec2 axis = v.at(1) - v.at(0);
            polygon.SetAsBox(0.5f * axis.Length(), static_cast<float>(kCapsuleCore), 0.5f * (v[0] + v[1]),
                             std::atan2(axis.y, axis.x));
            polygon.m_radius = static_cast<float>(p.radius - kCapsuleCore);
            fd.shape = &polygon;
            break;
        }
        case PartSpec::Kind::Polygon:
            polygon.Set(v.data(), static_cast<int32>(v.size()));  // the convex hull, counter-clockwise
            if (p.radius > 0.0) {
                polygon.m_radius = static_cast<float>(p.radius);
            } else {
                // Each corner moved in along both its edges' normals by the skin, the density raised by the areas'
                // ratio.
                const float outer = area(polygon);
                std::vector<b2Vec2> inner;
                const int n = polygon.m_count;
                for (int i = 0; i < n; ++i) {
                    const b2Vec2 a = polygon.m_normals[(i + n - 1) % n], b = polygon.m_normals[i];
                    inner.push_back(polygon.m_vertices[i] - (b2_polygonRadius / (1.0f + b2Dot(a, b))) * (a + b));
                }
                polygon.Set(inner.data(), n);
                density *= outer / area(polygon);
            }
            fd.shape = &polygon;
            break;
        }
        fd.density = static_cast<float>(density);
        body->CreateFixture(&fd);
    }

    static float area(const b2PolygonShape& polygon) {
        b2MassData md;
        polygon.ComputeMass(&md, 1.0f);
        return md.mass;
    }

    // The body's mass with each capsule part's own (its stand-in's is too small), the other parts' as 2.4.1 has
    // them. Fixtures come back in reverse order of creation.
    static void setCompoundMass(b2Body* body, const std::vector<PartSpec>& parts) {
        std::vector<b2Fixture*> fixtures;
        for (b2Fixture* f = body->GetFixtureList(); f != nullptr; f = f->GetNext()) fixtures.push_back(f);
        double mass = 0.0, cx = 0.0, cy = 0.0, inertia = 0.0;  // inertia about the body origin
        for (std::size_t i = 0; i < parts.size(); ++i) {
            const PartSpec& p = parts[i];
            if (p.kind == PartSpec::Kind::Capsule) {
                const ChainPoint& a = p.points[0];
                const ChainPoint& b = p.points[1];
                const CapsuleMass m = capsuleMass(p.radius, 0.5 * std::hypot(b.x - a.x, b.y - a.y));
                const double mm = p.material.density * m.area, x = 0.5 * (a.x + b.x), y = 0.5 * (a.y + b.y);
                mass += mm;
                cx += mm * x;
                cy += mm * y;
                inertia += p.material.density * m.secondMoment + mm * (x * x + y * y);
            } else {
                b2MassData md;
                fixtures[fixtures.size() - 1 - i]->GetMassData(&md);
                mass += md.mass;
                cx += md.mass * md.center.x;
                cy += md.mass * md.center.y;
                inertia += md.I;
            }
        }
        b2MassData md;
        md.mass = static_cast<float>(mass);
        md.center.Set(static_cast<float>(cx / mass), static_cast<float>(cy / mass));
        md.I = static_cast<float>(inertia);
        body->SetMassData(&md);
    }

    void addPin(const PinSpec& p) {
        auto body = [&](const BodyRef& r) { return r.isStatic ? statics_[r.index] : bodies_[r.index]; };
        b2RevoluteJointDef jd;
        jd.Initialize(body(p.a), body(p.b), b2Vec2(static_cast<float>(p.x), static_cast<float>(p.y)));
        jd.enableLimit = p.enableLimit;
        jd.lowerAngle = static_cast<float>(p.lowerAngle);
        jd.upperAngle = static_cast<float>(p.upperAngle);
        jd.enableMotor = p.enableMotor;
        jd.motorSpeed = static_cast<float>(p.motorSpeed);
        jd.maxMotorTorque = static_cast<float>(p.maxMotorTorque);
        world_.CreateJoint(&jd);  // owned by world_
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
    Scene scene_;  // a copy: what it does between steps
    bool collides_ = true;
    long steps_ = 0;
    std::vector<b2Body*> statics_, bodies_, kinematics_;  // not owning: world_ frees them; null: a wave not yet come
};

}  // namespace

Peers peerEngines() {
    // The package's version: Box2D 2.4.1's own b2_version still says 2.4.0.
    return {{Engine{"box2d-" PEERS_BOX2D_VERSION, 1, [](const Scene& s) { return std::make_unique<Box2dRun>(s); }, 0,
                    [](const Scene& s) { return s.box2d24Skip; }}},
            ""};
}

}  // namespace peers
