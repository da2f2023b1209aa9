#include "StudyScenes.hpp"

#include "../peers/Scenes.hpp"
#include "support/Scenes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace study {

physim::BodyId SceneRun::add(physim::World& world, physim::BodyDef def) const {
    if (def.type == physim::BodyType::Dynamic) {
        def.collisionDetection = detection;
        def.precision = precision;
    }
    return world.createBody(def);
}

namespace {

using physim::BodyDef;
using physim::BodyId;
using physim::BodyType;
using physim::Vec2;
using physim::World;

double gravity(const World& w) { return -w.settings().gravity.y(); }

using physim::test::addStaticBox;

// Ground: a static box whose top face is y = 0.
BodyId addGround(World& w, double halfWidth = 50.0) { return physim::test::addGround(w, halfWidth); }

// --- closed forms -------------------------------------------------------------------------------------

// Launch at 20 m/s, 60 degrees, no drag: p(t) = p0 + v0 t + g t^2 / 2. Error: distance to it at the end, m.
class Projectile : public SceneRun {
    static constexpr double kSpeed = 20.0, kAngle = M_PI / 3.0;
    BodyId ball_;
    Vec2 v0_{kSpeed * std::cos(kAngle), kSpeed * std::sin(kAngle)};
    double t_ = 0.0;

public:
    void build(World& w) override {
        BodyDef d;
        d.shape = physim::makeCircle(0.2);
        d.velocity = v0_;
        ball_ = add(w, d);
    }
    void observe(const World&, double t) override { t_ = t; }
    double error(const World& w) const override {
        const double t = t_;  // still in flight at the end (it lands at 3.53 s)
        const Vec2 exact = v0_ * t + Vec2(0.0, -0.5 * gravity(w) * t * t);
        return (w.position(ball_) - exact).norm();
    }
};

// A ball dropped from H = 2 m onto ground, both restitution e = 0.8: the n-th apex is e^(2n) H. Error: the worst
// of the first three apexes, relative to H. Impact speeds stay above restitutionThreshold (1 m/s), so e holds.
class Bounce : public SceneRun {
    static constexpr double kH = 2.0, kE = 0.8, kR = 0.1;
    BodyId ball_;
    std::vector<double> apexes_;
    double high_ = -1.0;   // highest centre since the last bounce, m
    bool rising_ = false;

public:
    void build(World& w) override {
        const BodyId g = addGround(w);
        w.setMaterial(g, kE, 0.0, 0.0);
        BodyDef d;
        d.shape = physim::makeCircle(kR);
        d.position = {0.0, kH + kR};
        d.restitution = kE;
        d.staticFriction = d.dynamicFriction = 0.0;
        ball_ = add(w, d);
    }
    void observe(const World& w, double) override {
        const double vy = w.velocity(ball_).y(), y = w.position(ball_).y() - kR;
        if (vy > 0.0) {
            rising_ = true;
            high_ = std::max(high_, y);
        } else if (rising_) {  // the top of a flight: the sampled highest point (off by g dt^2 / 8 at most)
            apexes_.push_back(std::max(high_, y));
            rising_ = false;
            high_ = -1.0;
        }
    }
    double error(const World&) const override {
        double worst = 0.0;
        for (int n = 1; n <= 3; ++n) {
            if (static_cast<int>(apexes_.size()) < n) return 1.0;  // a lost bounce: the whole height is wrong
            worst = std::max(worst, std::abs(apexes_[n - 1] - std::pow(kE, 2 * n) * kH) / kH);
        }
        return worst;
    }
};

// A 0.5 m block on a 45 degree slope, mu_s 0.6, mu_d 0.4 (both bodies; pairs average), sliding: it accelerates
// at a = g (sin - mu_d cos). Error: distance slid against v0 t + a t^2 / 2 at the end, m. `incline` starts it at
// v0 = 1 m/s down the slope (sliding from the first substep); `incline_release` lets it go at rest, so the
// engine's stick-or-slide decision (a face slides once it slips faster than a tenth of the linear slop per step)
// enters: it holds the block at mu_s until that speed, which grows with the rate.
class Incline : public SceneRun {
    static constexpr double kAngle = M_PI / 4.0, kHalf = 0.25;
    double v0_;
    BodyId block_;
    Vec2 start_, down_{-std::cos(kAngle), -std::sin(kAngle)};
    double t_ = 0.0;

public:
    explicit Incline(double v0) : v0_(v0) {}
    void build(World& w) override {
        const Vec2 normal(-std::sin(kAngle), std::cos(kAngle));
        // Slope: a long thin box through the origin; its top face passes 0.1 m above the origin along normal.
        const BodyId slope = addStaticBox(w, Vec2::Zero(), 20.0, 0.1, kAngle);
        w.setMaterial(slope, 0.0, 0.6, 0.4);
        BodyDef d;
        d.shape = physim::makeBox(kHalf, kHalf);
        d.angle = kAngle;
        d.position = normal * (0.1 + kHalf) - down_ * 5.0;  // resting on the face, 5 m up the slope
        d.staticFriction = 0.6;
        d.dynamicFriction = 0.4;
        d.velocity = v0_ * down_;
        block_ = add(w, d);
        start_ = d.position;
    }
    void observe(const World&, double t) override { t_ = t; }
    double error(const World& w) const override {
        const double t = t_, a = gravity(w) * (std::sin(kAngle) - 0.4 * std::cos(kAngle));
        return std::abs((w.position(block_) - start_).dot(down_) - (v0_ * t + 0.5 * a * t * t));
    }
};

// Two equal frictionless discs (r 0.5 m), e = 1, no gravity: A at 5 m/s strikes B at rest off-centre by one
// radius, so the line of centres at contact is 30 degrees up. B leaves along it with (v.n) n, A keeps the rest
// (momentum and energy kept, 90 degrees apart). Error: |vA - vA*| + |vB - vB*| over |v|, at the end.
class Oblique : public SceneRun {
    static constexpr double kR = 0.5, kSpeed = 5.0;
    BodyId a_, b_;

public:
    void build(World& w) override {
        BodyDef d;
        d.shape = physim::makeCircle(kR);
        d.useGravity = false;
        d.restitution = 1.0;
        d.staticFriction = d.dynamicFriction = 0.0;
        d.position = {-2.0, 0.0};
        d.velocity = {kSpeed, 0.0};
        a_ = add(w, d);
        d.position = {0.0, kR};
        d.velocity = Vec2::Zero();
        b_ = add(w, d);
    }
    double error(const World& w) const override {
        const Vec2 v(kSpeed, 0.0), n(std::sqrt(3.0) / 2.0, 0.5);
        const Vec2 vb = v.dot(n) * n, va = v - vb;
        return ((w.velocity(a_) - va).norm() + (w.velocity(b_) - vb).norm()) / kSpeed;
    }
};

// A bob on a 1 m rigid rod released at rest from horizontal: T = 4 sqrt(L/g) K(sin(theta0/2)), K the complete
// elliptic integral of the first kind. Period measured between rightward crossings of the vertical (linear
// interpolation between steps). Error: |T_measured - T| / T.
class Pendulum : public SceneRun {
    static constexpr double kLength = 1.0;
    BodyId bob_;
    double lastX_ = 0.0, lastT_ = 0.0;
    std::vector<double> crossings_;

public:
    void build(World& w) override {
        BodyDef pivot;
        pivot.type = BodyType::Static;
        pivot.shape = physim::makeCircle(0.02);
        BodyDef bob;
        bob.shape = physim::makeCircle(0.05);
        bob.position = {-kLength, 0.0};
        physim::DistanceJointDef rod;
        rod.bodyA = w.createBody(pivot);
        rod.bodyB = bob_ = add(w, bob);
        rod.length = kLength;
        w.createDistanceJoint(rod);
        lastX_ = -kLength;
    }
    void observe(const World& w, double t) override {
        const double x = w.position(bob_).x();
        if (lastX_ < 0.0 && x >= 0.0) crossings_.push_back(lastT_ + (t - lastT_) * (-lastX_) / (x - lastX_));
        lastX_ = x;
        lastT_ = t;
    }
    double error(const World& w) const override {
        const double exact = 4.0 * std::sqrt(kLength / gravity(w)) * std::comp_ellint_1(std::sin(M_PI / 4.0));
        if (crossings_.size() < 3) return 1.0;
        const double measured = (crossings_[2] - crossings_[0]) / 2.0;
        return std::abs(measured - exact) / exact;
    }
};

// Boxes built touching at their rest places: a rigid stack would not move. Error: how far the watched box ended
// from where it was built, m.
class Stacked : public SceneRun {
protected:
    BodyId watched_;
    Vec2 built_;

public:
    double error(const World& w) const override { return (w.position(watched_) - built_).norm(); }
};

// The examples' pyramid: 210 boxes of 1 m on a 20-box base (bench/peers lays them out). Error: top box drift.
class Pyramid : public Stacked {
public:
    void build(World& w) override {
        peers::Scene s;
        peers::addPyramid(s, 20, 0.0, 0.0);
        addGround(w);
        for (const peers::ShapeSpec& b : s.dynamics) {
            BodyDef d;
            d.shape = physim::makeBox(b.halfWidth, b.halfHeight);
            d.position = {b.x, b.y};
            watched_ = add(w, d);  // the last one is the top
            built_ = d.position;
        }
    }
};

// 20 boxes of 1 m in one column. Error: the top box's sink (a soft contact lets a column of N settle about
// N^2 g / (4 pi^2 hertz^2)).
class Stack : public Stacked {
public:
    void build(World& w) override {
        addGround(w);
        for (int i = 0; i < 20; ++i) {
            BodyDef d;
            d.shape = physim::makeBox(0.5, 0.5);
            d.position = {0.0, 0.5 + i};
            watched_ = add(w, d);
            built_ = d.position;
        }
    }
};

// 40 small discs (r 2 cm) fired at 50 to 2000 m/s, no gravity, against a 2 cm thick static wall: none should pass.
// Error: fraction that ended beyond the wall.
class Bullets : public SceneRun {
    std::vector<BodyId> bullets_;

public:
    void build(World& w) override {
        // 400 m high: a bullet stopped at a slant slides along it, and must not slide off its end within the run.
        addStaticBox(w, Vec2::Zero(), 0.01, 200.0);
        for (int i = 0; i < 40; ++i) {
            BodyDef d;
            d.shape = physim::makeCircle(0.02);
            d.useGravity = false;
            d.position = {-1.0, -4.0 + 0.2 * i};
            const double speed = 50.0 * (i + 1), slant = 0.2 * std::sin(1.7 * i);  // slant: rad from level
            d.velocity = speed * Vec2(std::cos(slant), std::sin(slant));
            bullets_.push_back(add(w, d));
        }
    }
    double error(const World& w) const override {
        int missed = 0;
        for (BodyId b : bullets_) missed += w.position(b).x() > 0.0;
        return static_cast<double>(missed) / static_cast<double>(bullets_.size());
    }
};

// 100 elastic frictionless discs (r 0.1 m) in a closed 4 m box, no gravity, speeds up to 3 m/s from a fixed
// seed: kinetic energy is kept exactly. Error: |E(T) - E0| / E0 scaled to one simulated minute.
class Gas : public SceneRun {
    std::vector<BodyId> discs_;
    double e0_ = 0.0;

    double energy(const World& w) const {
        double e = 0.0;
        for (BodyId b : discs_) e += 0.5 * w.mass(b) * w.velocity(b).squaredNorm();
        return e;
    }

public:
    void build(World& w) override {
        const double half = 2.0;
        for (const Vec2& c : {Vec2(0, -half - 0.5), Vec2(0, half + 0.5)}) w.setMaterial(addStaticBox(w, c, half + 1, 0.5), 1, 0, 0);
        for (const Vec2& c : {Vec2(-half - 0.5, 0), Vec2(half + 0.5, 0)}) w.setMaterial(addStaticBox(w, c, 0.5, half + 1), 1, 0, 0);
        std::uint64_t state = 12345;  // a fixed linear congruential sequence: the same gas on every run
        auto uniform = [&state] {
            state = state * 6364136223846793005ULL + 1442695040888963407ULL;
            return static_cast<double>(state >> 11) / 9007199254740992.0;  // [0, 1)
        };
        for (int i = 0; i < 100; ++i) {
            BodyDef d;
            d.shape = physim::makeCircle(0.1);
            d.useGravity = false;
            d.restitution = 1.0;
            d.staticFriction = d.dynamicFriction = 0.0;
            d.position = {-1.8 + 0.4 * (i % 10), -1.8 + 0.4 * (i / 10)};  // a grid 0.2 m apart: no overlap
            const double speed = 3.0 * uniform(), heading = 2.0 * M_PI * uniform();
            d.velocity = speed * Vec2(std::cos(heading), std::sin(heading));
            discs_.push_back(add(w, d));
        }
        e0_ = energy(w);
    }
    double error(const World& w) const override { return std::abs(energy(w) - e0_) / e0_ * (60.0 / 5.0); }
};

// A 1 m box tilted 30 degrees dropped from 1 m onto ground (the examples' test scene): it lands on a corner and
// tips onto a face. No closed form. state(): the box's centre (m) and half a side times its angle (m), so the
// error (distance to the finer run's state) bounds how far a corner ended from where the finer run put it.
class Tumble : public SceneRun {
    BodyId box_;

public:
    void build(World& w) override {
        addGround(w);
        BodyDef d;
        d.shape = physim::makeBox(0.5, 0.5);
        d.position = {0.0, 1.5};
        d.angle = M_PI / 6.0;
        d.restitution = 0.2;
        box_ = add(w, d);
    }
    std::vector<double> state(const World& w) const override {
        const Vec2 p = w.position(box_);
        return {p.x(), p.y(), 0.5 * w.angle(box_)};
    }
    double error(const World&) const override { return 0.0; }  // unused: judged by state() against the finer run
};

// A chain of 20 links (0.2 m boxes of 8 g) on revolute pins from a fixed anchor, holding a weight 100 times a
// link's mass, hanging at rest and swung sideways at 2 m/s: rigid pins would keep every link's ends together.
// Error: the worst, over the run, of the pins' summed gaps over the chain's length (the heavy end stretches the
// soft pins: the mass ratio is the hard part).
class HeavyChain : public SceneRun {
    static constexpr int kLinks = 20;
    static constexpr double kLink = 0.2;  // m
    std::vector<physim::JointId> pins_;
    double worst_ = 0.0;

public:
    void build(World& w) override {
        BodyDef anchor;
        anchor.type = BodyType::Static;
        anchor.collides = false;
        BodyId above = w.createBody(anchor);
        const double linkMass = 1.0 * (kLink * 0.04);  // density 1 kg/m^2 times the box's area
        for (int i = 0; i <= kLinks; ++i) {
            const double top = -kLink * i;  // this body's upper pin
            BodyDef d;
            d.collides = false;
            if (i < kLinks) {
                d.shape = physim::makeBox(0.02, 0.5 * kLink);
                d.position = {0.0, top - 0.5 * kLink};
            } else {  // the weight, centred on the last pin
                d.shape = physim::makeCircle(0.05);
                d.position = {0.0, top};
                d.velocity = {2.0, 0.0};
            }
            const BodyId body = add(w, d);
            if (i == kLinks) w.setMass(body, 100.0 * linkMass);
            physim::RevoluteJointDef pin;
            pin.bodyA = above;
            pin.bodyB = body;
            pin.anchor = {0.0, top};
            pins_.push_back(w.createRevoluteJoint(pin));
            above = body;
        }
    }
    void observe(const World& w, double) override {
        double gaps = 0.0;
        for (const physim::JointId j : pins_) {
            const auto [a, b] = w.jointAnchors(j);
            gaps += (b - a).norm();
        }
        worst_ = std::max(worst_, gaps / (kLinks * kLink));
    }
    double error(const World&) const override { return worst_; }
};

// An Atwood machine: 2 kg and 1 kg on one rope over two pulleys (a pulley joint), released at rest. Error: the
// acceleration measured between 0.5 s and the end against (m1 - m2) g / (m1 + m2), relative.
class Atwood : public SceneRun {
    static constexpr double kHeavy = 2.0, kLight = 1.0;  // kg
    BodyId heavy_;
    double v0_ = 0.0, t0_ = -1.0, v1_ = 0.0, t1_ = 0.0;

public:
    void build(World& w) override {
        auto weight = [&](double x, double mass) {
            BodyDef d;
            d.shape = physim::makeBox(0.1, 0.1);
            d.position = {x, 0.0};
            d.collides = false;
            const BodyId id = add(w, d);
            w.setMass(id, mass);
            return id;
        };
        physim::PulleyJointDef rope;
        rope.bodyA = heavy_ = weight(-0.5, kHeavy);
        rope.bodyB = weight(0.5, kLight);
        rope.groundAnchorA = {-0.5, 10.0};  // the light body rises 6.5 m in the 2 s: the rope stays clear
        rope.groundAnchorB = {0.5, 10.0};
        w.createPulleyJoint(rope);
    }
    void observe(const World& w, double t) override {
        if (t0_ < 0.0 && t >= 0.5) {
            t0_ = t;
            v0_ = w.velocity(heavy_).y();
        }
        t1_ = t;
        v1_ = w.velocity(heavy_).y();
    }
    double error(const World& w) const override {
        const double exact = (kHeavy - kLight) * gravity(w) / (kHeavy + kLight);
        return std::abs(-(v1_ - v0_) / (t1_ - t0_) - exact) / exact;
    }
};

template <class T, class... Args>
std::function<std::unique_ptr<SceneRun>()> maker(Args... args) {
    return [=] { return std::make_unique<T>(args...); };
}

}  // namespace

const std::vector<SceneInfo>& scenes() {
    const std::vector<std::string> motion{"rate", "substeps"};
    const std::vector<std::string> contact{"rate", "substeps", "iterations", "relax", "hertz", "damping", "stiff"};
    std::vector<std::string> fast = contact;
    fast.push_back("ccd");
    static const std::vector<SceneInfo> all{
        {"projectile", 3.0, "distance to the closed-form position at the end (m)", false, motion, maker<Projectile>()},
        {"bounce", 3.0, "worst of the first three apexes against e^(2n) H, relative to H", false, fast, maker<Bounce>()},
        {"incline", 1.0, "distance slid from 1 m/s against v0 t + g (sin - mu_d cos) t^2 / 2 at the end (m)", false,
         contact, maker<Incline>(1.0)},
        {"incline_release", 1.0, "distance slid from rest against g (sin - mu_d cos) t^2 / 2 at the end (m)", false,
         contact, maker<Incline>(0.0)},
        {"oblique", 1.0, "final velocity error of both discs over the impact speed", false, fast, maker<Oblique>()},
        {"pendulum", 5.6, "period against the elliptic-integral period, relative", false, contact, maker<Pendulum>()},
        {"heavy_chain", 2.0, "worst stretch of 20 pinned links holding 100 times a link, relative to the length", false,
         contact, maker<HeavyChain>()},
        {"atwood", 2.0, "acceleration against (m1 - m2) g / (m1 + m2), relative", false, contact, maker<Atwood>()},
        {"pyramid", 2.0, "top box drift from its built place after 2 s (m)", false, contact, maker<Pyramid>()},
        {"stack", 2.0, "top box sink from its built place after 2 s (m)", false, contact, maker<Stack>()},
        {"bullets", 0.2, "fraction of 40 bullets (50-2000 m/s) through a 2 cm wall", false, fast, maker<Bullets>()},
        {"gas", 5.0, "kinetic energy drift per simulated minute, relative", false, fast, maker<Gas>()},
        {"tumble", 1.5, "pose distance to the 16x finer step's run at 1.5 s (m)", true, fast, maker<Tumble>()},
    };
    return all;
}

const SceneInfo& scene(const std::string& name) {
    for (const SceneInfo& s : scenes())
        if (s.name == name) return s;
    throw std::invalid_argument("unknown scene '" + name + "'");
}

}  // namespace study
