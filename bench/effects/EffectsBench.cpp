// effects_bench: for each effect (and each stage that runs only when called for), ms per 60 Hz step of one scene
// in three forms, measured in one run: without the effect, with it available but unused (the world held it and
// let it go, or holds it where it does nothing), and using it. Time is the stepping thread's CPU time (the worlds
// step on one thread), so time spent descheduled on a shared machine does not count; rounds alternate the three
// forms; each form's time is its fastest round (what load is left, cache and memory contention, only adds time)
// and each ratio the median over rounds of that round's ratio (the three forms of a round share its load).
//
// After the table, one evaluation of the Barnes-Hut gravitation (the tree built and every body's pull summed, one
// per substep) on 3000 bodies: ms, the fastest of the steps, on one thread and on two (treeEvaluation).
//
// Usage: effects_bench [--json FILE] [--rounds N (default 41)] [--steps N per round (default 5)]
//        [--only NAME]
// Writes [{"effect":..., "without_ms":x, "unused_ms":x, "used_ms":x, "unused_ratio":x, "used_ratio":x}, ...,
// {"effect": "gravitation, Barnes-Hut", "bodies": 3000, "ms_per_evaluation": x, "ms_per_evaluation_two_threads": x}]
// to FILE and Markdown tables to stdout.

#include "physim/core/World.hpp"
#include "support/Scenes.hpp"

#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <random>
#include <stdexcept>
#include <utility>
#include <string>
#include <vector>

using namespace physim;

namespace {

constexpr double kDt = 1.0 / 60.0;

struct Scene {
    std::unique_ptr<World> world;
    std::vector<BodyId> bodies;  // the scene's moving bodies, in creation order
};

using physim::test::addStaticBox;

// The common scene: 400 circles of 0.25 m falling into a 20 m box and churning there, sleep off (the bodies
// stay simulated, so every step does the same work).
Scene circles() {
    constexpr int count = 400;
    WorldSettings s;
    s.enableSleep = false;
    Scene scene{std::make_unique<World>(s), {}};
    World& w = *scene.world;
    addStaticBox(w, {0.0, -0.5}, 10.0, 0.5);
    addStaticBox(w, {-10.5, 10.0}, 0.5, 10.5);
    addStaticBox(w, {10.5, 10.0}, 0.5, 10.5);
    for (int i = 0; i < count; ++i) {
        BodyDef d;
        d.shape = makeCircle(0.25);
        d.position = {-9.0 + 0.6 * (i % 30) + 0.05 * ((i / 30) % 2), 1.0 + 0.6 * (i / 30)};
        scene.bodies.push_back(w.createBody(d));
    }
    return scene;
}

// A cluster of point-like bodies that touch nothing, in a disc of radius 10 m, turning slowly.
Scene cluster(int count, int threads = 1) {
    WorldSettings s;
    s.gravity = Vec2::Zero();
    s.threads = threads;
    Scene scene{std::make_unique<World>(s), {}};
    World& w = *scene.world;
    GravitationSettings g;
    g.G = 1e-3;
    g.softening = 0.1;
    w.setGravitation(g);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    while (static_cast<int>(scene.bodies.size()) < count) {
        const Vec2 p(20 * u(rng) - 10, 20 * u(rng) - 10);
        if (p.norm() > 10.0) continue;
        BodyDef d;
        d.shape = makeCircle(0.02);
        d.collides = false;
        d.position = p;
        d.velocity = 0.1 * perp(p);
        scene.bodies.push_back(w.createBody(d));
    }
    return scene;
}

// The pile a sleeping world keeps: a 20-box pyramid (210 boxes).
Scene pyramid(bool boxes) {
    Scene scene{std::make_unique<World>(), {}};
    World& w = *scene.world;
    physim::test::addGround(w, 100.0);
    if (boxes) scene.bodies = physim::test::addPyramid(w, 20);
    return scene;
}

using Build = std::function<Scene()>;

constexpr const char* kTreeRow = "gravitation, Barnes-Hut";
constexpr int kTreeBodies = 3000;

struct Row {
    std::string effect, scene, used;  // name, the scene, what "used" means
    Build without, unused, usedBuild;
};

// Joint helpers over neighbouring circles (i, i + 1 in a row of 30): they start 0.6 m apart.
template <class MakeJoint>
Scene withPairs(Scene s, MakeJoint make) {
    for (std::size_t i = 0; i + 1 < s.bodies.size(); i += 2) make(*s.world, s.bodies[i], s.bodies[i + 1]);
    return s;
}

DragDef air() {
    DragDef d;
    d.linear = 0.05;
    d.dragCoefficient = 1.0;
    return d;
}

std::vector<Row> rows() {
    std::vector<Row> r;
    r.push_back({"gravity scale", "400 circles", "every body at scale 0.5", [] { return circles(); },
                 [] {
                     Scene s = circles();
                     for (const BodyId b : s.bodies) s.world->setGravityScale(b, 1.0);
                     return s;
                 },
                 [] {
                     Scene s = circles();
                     for (const BodyId b : s.bodies) s.world->setGravityScale(b, 0.5);
                     return s;
                 }});
    r.push_back({"drag", "400 circles", "every body with linear and quadratic drag", [] { return circles(); },
                 [] {
                     Scene s = circles();
                     for (const BodyId b : s.bodies) s.world->setDrag(b, air());
                     for (const BodyId b : s.bodies) s.world->setDrag(b, DragDef{});
                     return s;
                 },
                 [] {
                     Scene s = circles();
                     for (const BodyId b : s.bodies) s.world->setDrag(b, air());
                     return s;
                 }});
    auto spring = [](World& w, BodyId a, BodyId b) {
        SpringJointDef d;
        d.bodyA = a;
        d.bodyB = b;
        d.stiffness = 20.0;
        d.damping = 0.2;
        return w.createSpringJoint(d);
    };
    auto wind = [](Scene s) {
        std::vector<BodyId> bodies = s.bodies;
        s.world->addForceCallback([bodies](World& w, double) {
            for (const BodyId b : bodies) w.applyForce(b, {0.2, 0.0});
        });
        return s;
    };
    r.push_back({"force callback", "400 circles", "one callback pushing every body", [] { return circles(); },
                 [] {
                     Scene s = circles();
                     s.world->removeForceCallback(s.world->addForceCallback([](World&, double) {}));
                     return s;
                 },
                 [wind] { return wind(circles()); }});
    auto attracting = [](int n, bool all) {
        Scene s = cluster(n);
        for (std::size_t i = 0; i < (all ? s.bodies.size() : 1); ++i) s.world->setAttracting(s.bodies[i], true);
        return s;
    };
    r.push_back({"gravitation, direct", "200 bodies that touch nothing", "all 200 attract (direct sum)",
                 [] { return cluster(200); }, [attracting] { return attracting(200, false); },
                 [attracting] { return attracting(200, true); }});
    r.push_back({kTreeRow, "3000 bodies that touch nothing", "all 3000 attract (tree, theta 0.5)",
                 [] { return cluster(3000); }, [attracting] { return attracting(3000, false); },
                 [attracting] { return attracting(3000, true); }});
    // A joint of definition `def`, made by World member `create`, joining a and b at their midpoint.
    auto atMidpoint = [](auto def, auto create) {
        return [def, create](World& w, BodyId a, BodyId b) {
            auto d = def;
            d.bodyA = a;
            d.bodyB = b;
            d.anchor = 0.5 * (w.position(a) + w.position(b));
            return (w.*create)(d);
        };
    };
    auto pin = atMidpoint(RevoluteJointDef{}, &World::createRevoluteJoint);
    auto weld = atMidpoint(WeldJointDef{}, &World::createWeldJoint);
    auto soft = [](World& w, BodyId a, BodyId b) {
        DistanceJointDef d;
        d.bodyA = a;
        d.bodyB = b;
        d.hertz = 5.0;
        return w.createDistanceJoint(d);
    };
    auto jointRow = [&r](const char* name, const char* used, auto make) {
        r.push_back({name, "400 circles", used, [] { return circles(); },
                     [make] {
                         Scene s = circles();
                         for (std::size_t i = 0; i + 1 < s.bodies.size(); i += 2)
                             s.world->destroyJoint(make(*s.world, s.bodies[i], s.bodies[i + 1]));
                         return s;
                     },
                     [make] { return withPairs(circles(), [&](World& w, BodyId a, BodyId b) { make(w, a, b); }); }});
    };
    jointRow("springs", "200 springs, each joining two circles", spring);
    jointRow("revolute joints", "200 pins, each joining two circles", pin);
    jointRow("weld joints", "200 welds, each joining two circles", weld);
    jointRow("soft distance joints", "200 soft links (5 Hz), each joining two circles", soft);
    r.push_back({"continuous detection", "400 circles", "every body exact time of impact", [] { return circles(); },
                 [] {
                     Scene s = circles();
                     for (const BodyId b : s.bodies) s.world->setCollisionDetection(b, CollisionDetection::ContinuousExact);
                     for (const BodyId b : s.bodies) s.world->setCollisionDetection(b, CollisionDetection::Discrete);
                     return s;
                 },
                 [] {
                     Scene s = circles();
                     for (const BodyId b : s.bodies) s.world->setCollisionDetection(b, CollisionDetection::ContinuousExact);
                     return s;
                 }});
    // Friction and rotation on everything (walls too), or on nothing but one far-off body that touches nothing.
    auto farBody = [](World& w, double friction, double spin) {
        BodyDef d;
        d.position = {1000.0, 0.0};
        d.gravityScale = 0.0;
        d.staticFriction = friction;
        d.angularVelocity = spin;
        w.createBody(d);
    };
    auto material = [farBody](double friction, bool far) {
        return [=] {
            Scene s = circles();
            for (const BodyId b : s.bodies) s.world->setMaterial(b, 0.0, friction, friction);
            for (std::uint32_t i = 0; i < 3; ++i)  // the walls: created first
                s.world->setMaterial(BodyId{i, 1}, 0.0, friction, friction);
            if (far) farBody(*s.world, 0.6, 0.0);
            return s;
        };
    };
    r.push_back({"friction", "400 circles", "every body mu 0.6 (without: all 0; unused: one far-off body mu 0.6)",
                 material(0.0, false), material(0.0, true), material(0.6, false)});
    auto rotation = [farBody](bool locked, bool far) {
        return [=] {
            Scene s = circles();
            for (const BodyId b : s.bodies) s.world->setFixedRotation(b, locked);
            if (far) farBody(*s.world, 0.0, 1.0);
            return s;
        };
    };
    r.push_back({"rotation", "400 circles",
                 "every body free to turn (without: all locked; unused: one far-off body turning)",
                 rotation(true, false), rotation(true, true), rotation(false, false)});
    // Sensors: the Sensors stage runs only while the world holds one. Unused: one static sensor far off, which nothing
    // visits (the stage runs and finds nothing); used: a sensor over the box's lower 2 m, which the churning circles
    // enter and leave every step.
    auto sensor = [](const Vec2& at, double halfWidth, double halfHeight) {
        return [=] {
            Scene s = circles();
            BodyDef d;
            d.type = BodyType::Static;
            d.position = at;
            d.shape = makeBox(halfWidth, halfHeight);
            d.isSensor = true;
            s.world->createBody(d);
            return s;
        };
    };
    r.push_back({"sensors", "400 circles",
                 "a sensor over the box's lower 2 m, the circles crossing it (unused: one far-off sensor)",
                 [] { return circles(); }, sensor({1000.0, 0.0}, 1.0, 1.0), sensor({0.0, 1.0}, 10.0, 1.0)});
    // Sleep: its bookkeeping (islands, rest timers, the Sleep stage) costs only while sleep is on; here nothing may
    // fall asleep, so the three forms do the same simulation. What sleeping saves is the next row's.
    auto sleepOn = [](bool on, bool off) {
        return [=] {
            Scene s = circles();
            WorldSettings settings = s.world->settings();
            settings.enableSleep = on;
            s.world->setSettings(settings);
            if (off) {
                settings.enableSleep = false;
                s.world->setSettings(settings);
            }
            for (const BodyId b : s.bodies) s.world->setAllowSleep(b, false);
            return s;
        };
    };
    r.push_back({"sleep bookkeeping", "400 circles", "sleep on, no body allowed to sleep (unused: turned on and off again)",
                 sleepOn(false, false), sleepOn(true, true), sleepOn(true, false)});
    r.push_back({"sleeping pile", "20-box-base pyramid (210 boxes)",
                 "awake pile (sleep off); without: ground only; unused: the pile asleep",
                 [] { return pyramid(false); }, [] { return pyramid(true); },
                 [] {
                     Scene s = pyramid(true);
                     WorldSettings settings = s.world->settings();
                     settings.enableSleep = false;
                     s.world->setSettings(settings);
                     return s;
                 }});
    // The energy ledger on an awake pile: without it, switched on and off again (unused), and on (used).
    auto ledger = [](bool on, bool off) {
        return [=] {
            Scene s = pyramid(true);
            WorldSettings settings = s.world->settings();
            settings.enableSleep = false;
            s.world->setSettings(settings);
            s.world->setEnergyLedger(on);
            if (off) s.world->setEnergyLedger(false);
            return s;
        };
    };
    r.push_back({"energy ledger", "20-box-base pyramid (210 boxes), awake",
                 "the ledger on (unused: switched on and off again)", ledger(false, false), ledger(true, true),
                 ledger(true, false)});
    return r;
}

// CPU time of this thread, ms.
double threadMilliseconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

struct Measured {
    double without = 0.0, unused = 0.0, used = 0.0;  // ms per step, each form's fastest round
    double unusedRatio = 0.0, usedRatio = 0.0;        // median over rounds of the round's unused / without, used / without
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Each round steps the three forms back to back (in a rotating order), so a round's three times share the
// machine's load of that moment: the median of the rounds' ratios is the comparison that load disturbs least.
Measured measure(const Row& row, int rounds, int steps) {
    Scene scenes[3] = {row.without(), row.unused(), row.usedBuild()};
    for (Scene& s : scenes)
        for (int i = 0; i < 120; ++i) s.world->step(kDt);  // settle: 2 s (the pile sleeps after about 1.5 s)
    std::vector<double> times[3], unusedRatio, usedRatio;
    for (int r = 0; r < rounds; ++r) {
        double t[3];
        for (int k = 0; k < 3; ++k) {
            const int which = (k + r) % 3;
            const double start = threadMilliseconds();
            for (int i = 0; i < steps; ++i) scenes[which].world->step(kDt);
            t[which] = (threadMilliseconds() - start) / steps;
            times[which].push_back(t[which]);
        }
        unusedRatio.push_back(t[1] / t[0]);
        usedRatio.push_back(t[2] / t[0]);
    }
    const auto fastest = [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); };
    return {fastest(times[0]), fastest(times[1]), fastest(times[2]), median(unusedRatio), median(usedRatio)};
}

// One gravitation evaluation (ms), the fastest of `steps` steps of worlds of one and two threads stepped in turn
// (so both see the same load): the effect's wall-clock time per substep from the profile; on one thread also the
// step's CPU time per substep, which is the evaluation and a little more (integrating the bodies) but leaves out
// time descheduled, and the smaller of the two counts.
std::pair<double, double> treeEvaluation(int steps) {
    Scene worlds[2] = {cluster(kTreeBodies, 1), cluster(kTreeBodies, 2)};
    double fastest[2] = {1e300, 1e300};
    for (Scene& s : worlds) {
        for (const BodyId b : s.bodies) s.world->setAttracting(b, true);
        for (int i = 0; i < 10; ++i) s.world->step(kDt);
    }
    for (int i = 0; i < steps; ++i)
        for (int k = 0; k < 2; ++k) {
            World& w = *worlds[k].world;
            const double start = threadMilliseconds();
            w.step(kDt);
            const double cpu = threadMilliseconds() - start, substeps = w.settings().substeps;
            const double wall = 1e3 * w.profile().secondsOf(Effect::Gravitation);
            fastest[k] = std::min(fastest[k], (k == 0 ? std::min(cpu, wall) : wall) / substeps);
        }
    return {fastest[0], fastest[1]};
}

[[noreturn]] void usageError(const std::string& message) {
    std::fprintf(stderr, "effects_bench: %s\nusage: effects_bench [--json FILE] [--rounds N] [--steps N] [--only NAME]\n",
                 message.c_str());
    std::exit(2);
}

int positiveInt(const std::string& flag, const char* text) {
    char* end = nullptr;
    const long v = std::strtol(text, &end, 10);
    if (*text == '\0' || *end != '\0' || v < 1 || v > 100000)
        usageError(flag + " needs an integer in [1, 100000], got '" + text + "'");
    return static_cast<int>(v);
}

}  // namespace

int main(int argc, char** argv) {
    std::string json, only;
    int rounds = 41, steps = 5;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> const char* {
            if (i + 1 >= argc) usageError(arg + " needs a value");
            return argv[++i];
        };
        if (arg == "--json") json = value();
        else if (arg == "--rounds") rounds = positiveInt(arg, value());
        else if (arg == "--steps") steps = positiveInt(arg, value());
        else if (arg == "--only") only = value();
        else usageError("unknown argument '" + arg + "'");
    }
    const std::vector<Row> all = rows();
    if (!only.empty() && std::none_of(all.begin(), all.end(), [&](const Row& r) { return r.effect == only; }))
        usageError("--only: no effect named '" + only + "'");
    std::FILE* out = nullptr;
    if (!json.empty()) {
        out = std::fopen(json.c_str(), "w");
        if (!out) usageError("cannot write '" + json + "'");
        std::fprintf(out, "[");
    }
    std::printf("| effect | scene | used means | without (ms) | unused (ms) | used (ms) | unused / without | used / without |\n");
    std::printf("|---|---|---|---:|---:|---:|---:|---:|\n");
    bool first = true;
    for (const Row& row : all) {
        if (!only.empty() && row.effect != only) continue;
        const Measured m = measure(row, rounds, steps);
        std::printf("| %s | %s | %s | %.4f | %.4f | %.4f | %.3f | %.2f |\n", row.effect.c_str(), row.scene.c_str(),
                    row.used.c_str(), m.without, m.unused, m.used, m.unusedRatio, m.usedRatio);
        std::fflush(stdout);
        if (out) {
            std::fprintf(out,
                         "%s\n  {\"effect\": \"%s\", \"without_ms\": %.6f, \"unused_ms\": %.6f, \"used_ms\": %.6f, "
                         "\"unused_ratio\": %.4f, \"used_ratio\": %.4f}",
                         first ? "" : ",", row.effect.c_str(), m.without, m.unused, m.used, m.unusedRatio, m.usedRatio);
        }
        first = false;
    }
    if (only.empty() || only == kTreeRow) {
        const auto [one, two] = treeEvaluation(rounds * steps);
        std::printf("\n| effect | bodies | ms per evaluation, 1 thread | 2 threads |\n|---|---:|---:|---:|\n");
        std::printf("| %s | %d | %.4f | %.4f |\n", kTreeRow, kTreeBodies, one, two);
        if (out)
            std::fprintf(out,
                         "%s\n  {\"effect\": \"%s\", \"bodies\": %d, \"ms_per_evaluation\": %.6f, "
                         "\"ms_per_evaluation_two_threads\": %.6f}",
                         first ? "" : ",", kTreeRow, kTreeBodies, one, two);
    }
    if (out) {
        std::fprintf(out, "\n]\n");
        std::fclose(out);
    }
    return 0;
}
