// peer_bench: physim against peer engines (Box2D 2.4 when it was found at configure time) on the same scenes,
// run interleaved (repeat -> scene -> engine) so a noisy, shared machine slows every engine alike.
// Each run steps a fresh world `--steps` times at 60 Hz; the time per step is the wall time of steps 101 to
// the last divided by their number (the first 100 steps, while the scene settles and caches warm, are not
// timed); the table gives the min and the median of that over the repeats. docs/performance.md ("Peers")
// defines the scenes and the figures.

#include "Engine.hpp"
#include "Scenes.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace peers;

constexpr int kUntimedSteps = 100;
constexpr int kDriftFromStep = 60;
constexpr double kNone = std::numeric_limits<double>::quiet_NaN();  // a figure the scene does not define

struct Options {
    std::vector<std::string> scenes{"all"};
    std::vector<std::string> engines;  // empty: all
    int repeats = 3;
    int steps = 500;
    std::vector<int> substeps;  // extra one-thread physim runs at these substep counts
    std::string json;
    bool profile = false;
};

// One engine on one scene, over the repeats.
struct Row {
    std::string scene;
    const Engine* engine = nullptr;
    std::size_t bodies = 0;
    bool pyramidGrid = false;
    std::vector<double> msPerStep;  // one per repeat
    double topDrop = kNone, topDrift = kNone, maxSideways = kNone;  // m, from the last repeat
    // Scenes on a chain, last repeat: the least of (a body's centre above the chain at its x, less its radius), m,
    // negative by the deepest overlap; and how many centres ended below the chain (fell through).
    double minClearance = kNone, belowGround = kNone;
    // Scenes with pins, last repeat: the lowest dynamic body's centre height at the last step, m (how far the
    // joints stretched under the weight they hold).
    double lowestY = kNone;
    // Scenes with cars, last repeat: the mean x the chassis travelled from its start, m, and how many cars end
    // upright (chassis within 90 degrees of its start angle).
    double carsMeanDx = kNone, carsUpright = kNone;
    std::map<std::string, double> stageSeconds;  // summed over every timed step of every repeat
    int timedSteps = 0;

    double min() const { return *std::min_element(msPerStep.begin(), msPerStep.end()); }
    double median() const {
        std::vector<double> v = msPerStep;
        std::sort(v.begin(), v.end());
        const std::size_t n = v.size();
        return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    }
};

[[noreturn]] void usageError(const std::string& message) {
    std::cerr << "peer_bench: " << message << "\n"
              << "usage: peer_bench [--scenes a,b,...] [--engines a,b,...] [--repeats n] [--steps n] "
                 "[--substeps a,b,...] [--json FILE] [--profile]\n"
              << "  --scenes   large_pyramid, pyramid<N> (N in 1..400), circles1000, many_pyramids, pyramid_grid<R> "
                 "(R rows of 20 base-10 pyramids), chain_terrain, joint_grid, cars, smash, compounds, junkyard, rain, spinner, "
                 "tumbler, washer, scaling (grids of 1k to 21k boxes, for the fit), box2d (Box2D v3's benchmark scenes: "
                 "compounds, joint_grid, junkyard, large_pyramid, many_pyramids, rain, smash, spinner, tumbler, washer), "
                 "all (default)\n"
              << "  --engines  physim and the peers this build has (default: all of them)\n"
              << "  --repeats  runs of each scene and engine, n >= 1 (default 3)\n"
              << "  --steps    steps per run, n >= " << kUntimedSteps + 1 << " (default 500); steps "
              << kUntimedSteps + 1 << "..n are timed\n"
              << "  --substeps also run physim on one thread at each substep count (1 to 1000; engine physim-substeps<n>) "
                 "and fit its step time against the count\n"
              << "  --json     also write the rows to FILE\n"
              << "  --profile  also print physim's (and the peers') time per stage\n";
    std::exit(2);
}

int parseCount(const std::string& option, const std::string& text, int least, long most = 1000000) {
    std::size_t used = 0;
    long value = 0;
    try {
        value = std::stol(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || value < least || value > most)
        usageError(option + " wants a whole number from " + std::to_string(least) + " to " + std::to_string(most) +
                   ", not '" + text + "'");
    return static_cast<int>(value);
}

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h") usageError("physim against its peers");
        if (arg == "--profile") {
            o.profile = true;
            continue;
        }
        if (arg != "--scenes" && arg != "--engines" && arg != "--repeats" && arg != "--steps" && arg != "--substeps" &&
            arg != "--json")
            usageError("unknown option '" + arg + "'");
        if (i + 1 >= argc) usageError(arg + " needs a value");
        const std::string value = argv[++i];
        if (arg == "--scenes") {
            o.scenes = splitList(value);
            if (o.scenes.empty()) usageError("--scenes needs at least one scene");
        } else if (arg == "--engines") {
            o.engines = splitList(value);
            if (o.engines.empty()) usageError("--engines needs at least one engine");
        } else if (arg == "--repeats") {
            o.repeats = parseCount(arg, value, 1);
        } else if (arg == "--steps") {
            o.steps = parseCount(arg, value, kUntimedSteps + 1);
        } else if (arg == "--substeps") {
            const std::vector<std::string> counts = splitList(value);
            if (counts.empty()) usageError("--substeps needs at least one count");
            for (const std::string& c : counts) o.substeps.push_back(parseCount(arg, c, 1, 1000));
        } else {
            o.json = value;
        }
    }
    return o;
}

double distance(const Point& a, const Point& b) { return std::hypot(a.x - b.x, a.y - b.y); }

// The larger of the two; NaN (a body whose position blew up) wins, so it shows instead of hiding.
double worst(double a, double b) { return std::isnan(a) || a > b ? a : b; }

// Steps a fresh world of `scene` and adds this run's time per step (and, on the last repeat, its drop, drift
// and sideways figures) to the row.
void measure(const Scene& scene, const Options& o, bool lastRepeat, Row& row) {
    const std::unique_ptr<EngineRun> run = row.engine->start(scene);
    std::vector<Point> tops, topsAtDriftStep;
    for (std::size_t t : scene.tops) tops.push_back(run->position(t));
    std::chrono::steady_clock::time_point start;
    for (int s = 1; s <= o.steps; ++s) {
        if (s == kUntimedSteps + 1) start = std::chrono::steady_clock::now();
        run->step();
        if (o.profile && s > kUntimedSteps)
            for (const auto& [stage, seconds] : run->lastStepStages()) row.stageSeconds[stage] += seconds;
        if (s == kDriftFromStep)
            for (std::size_t t : scene.tops) topsAtDriftStep.push_back(run->position(t));
    }
    const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
    const int timed = o.steps - kUntimedSteps;
    row.msPerStep.push_back(elapsed.count() / timed);
    row.timedSteps += timed;
    if (lastRepeat && !scene.chain.empty()) {
        row.minClearance = std::numeric_limits<double>::infinity();
        row.belowGround = 0.0;
        for (std::size_t i = 0; i < scene.dynamics.size(); ++i) {
            const Point p = run->position(i);
            const double above = p.y - chainHeightAt(scene, p.x);  // NaN past the chain's ends counts as fallen
            row.minClearance = std::min(row.minClearance, above - scene.dynamics[i].radius);
            if (!(above >= 0.0)) row.belowGround += 1.0;
        }
    }
    if (lastRepeat && !scene.pins.empty() && scene.waves.empty()) {  // waves' bodies come and go
        row.lowestY = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < scene.dynamics.size(); ++i) {
            const double y = run->position(i).y;
            row.lowestY = std::isnan(y) || y < row.lowestY ? y : row.lowestY;  // NaN (blown up) shows
        }
    }
    if (lastRepeat && !scene.cars.empty()) {
        row.carsMeanDx = row.carsUpright = 0.0;
        for (std::size_t c : scene.cars) {
            row.carsMeanDx += (run->position(c).x - scene.dynamics[c].x) / scene.cars.size();
            if (std::cos(run->angle(c)) > 0.0) row.carsUpright += 1.0;
        }
    }
    if (!lastRepeat || scene.tops.empty()) return;

    row.topDrop = -std::numeric_limits<double>::infinity();  // a top that rose has a negative drop
    row.topDrift = row.maxSideways = 0.0;
    for (std::size_t k = 0; k < scene.tops.size(); ++k) {
        const Point end = run->position(scene.tops[k]);
        row.topDrop = worst(row.topDrop, tops[k].y - end.y);
        row.topDrift = worst(row.topDrift, distance(end, topsAtDriftStep[k]));
    }
    for (std::size_t i = 0; i < scene.dynamics.size(); ++i)
        row.maxSideways = worst(row.maxSideways, std::abs(run->position(i).x - scene.dynamics[i].x));
}

std::string fixed(double v, int decimals) {
    if (std::isnan(v)) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

// The min time of the row for the same scene whose engine matches `match`, or NaN.
template <class Match>
double minOf(const std::vector<Row>& rows, const std::string& scene, Match match) {
    for (const Row& r : rows)
        if (r.scene == scene && match(*r.engine)) return r.min();
    return kNone;
}

void printTable(const std::vector<Row>& rows, const std::vector<Engine>& peers) {
    std::cout << "| scene | engine | threads | bodies | ms/step min | ms/step median | x peer | x 1 thread "
                 "| top drop (m) | top drift (m) | max sideways (m) |\n"
              << "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : rows) {
        const double peer = peers.empty() ? kNone : minOf(rows, r.scene, [&](const Engine& e) {
            return e.name == peers.front().name && e.threads == peers.front().threads;
        });
        const double oneThread =
            minOf(rows, r.scene, [&](const Engine& e) { return e.name == r.engine->name && e.threads == 1; });
        std::cout << "| " << r.scene << " | " << r.engine->name << " | " << r.engine->threads << " | " << r.bodies
                  << " | " << fixed(r.min(), 3) << " | " << fixed(r.median(), 3) << " | "
                  << fixed(r.min() / peer, 2) << " | " << fixed(r.min() / oneThread, 2) << " | "
                  << fixed(r.topDrop, 4) << " | " << fixed(r.topDrift, 4) << " | " << fixed(r.maxSideways, 4)
                  << " |\n";
    }
}

// The chain scenes' check that bodies rest on the ground: the vertical distance from a body's centre down to the
// chain, less its radius, is at least the body's gap to the chain (0 resting on it, negative by an overlap).
void printGroundCheck(const std::vector<Row>& rows) {
    bool printed = false;
    for (const Row& r : rows) {
        if (std::isnan(r.belowGround)) continue;
        if (!printed) std::cout << "\nBodies on the chain at the last step (lowest: its centre's height above the chain, "
                                   "less its radius; m):\n";
        printed = true;
        std::cout << "  " << r.scene << " " << r.engine->name << " x" << r.engine->threads << ": lowest "
                  << fixed(r.minClearance, 4) << ", " << fixed(r.belowGround, 0) << " of " << r.bodies
                  << " below the chain\n";
    }
}

// The jointed scenes' stiffness: where the lowest body hangs at the last step (it starts at the lowest ShapeSpec's y).
void printLowest(const std::vector<Row>& rows, const std::vector<Scene>& scenes) {
    bool printed = false;
    for (const Row& r : rows) {
        if (std::isnan(r.lowestY)) continue;
        if (!printed) std::cout << "\nLowest body at the last step (its centre's y, m; where it started):\n";
        printed = true;
        double start = std::numeric_limits<double>::infinity();
        for (const Scene& s : scenes)
            if (s.name == r.scene)
                for (const ShapeSpec& d : s.dynamics) start = std::min(start, d.y);
        std::cout << "  " << r.scene << " " << r.engine->name << " x" << r.engine->threads << ": "
                  << fixed(r.lowestY, 3) << " (from " << fixed(start, 3) << ")\n";
    }
}

// The cars' sanity: how far they drove and whether they stayed on their wheels.
void printCars(const std::vector<Row>& rows, const std::vector<Scene>& scenes) {
    bool printed = false;
    for (const Row& r : rows) {
        if (std::isnan(r.carsMeanDx)) continue;
        if (!printed) std::cout << "\nCars at the last step (mean x travelled by the chassis, m; upright ones):\n";
        printed = true;
        std::size_t cars = 0;
        for (const Scene& s : scenes)
            if (s.name == r.scene) cars = s.cars.size();
        std::cout << "  " << r.scene << " " << r.engine->name << " x" << r.engine->threads << ": mean dx "
                  << fixed(r.carsMeanDx, 2) << ", " << fixed(r.carsUpright, 0) << " of " << cars << " upright\n";
    }
}

void printProfile(const std::vector<Row>& rows) {
    std::cout << "\nTime per stage, mean over every timed step (ms/step, share of the stages' sum):\n\n"
              << "| scene | engine | threads | stage | ms/step | share |\n|---|---|---|---|---|---|\n";
    for (const Row& r : rows) {
        double total = 0.0;
        for (const auto& kv : r.stageSeconds) total += kv.second;
        for (const auto& [stage, seconds] : r.stageSeconds)
            if (seconds > 0.0)
                std::cout << "| " << r.scene << " | " << r.engine->name << " | " << r.engine->threads << " | "
                          << stage << " | " << fixed(1e3 * seconds / r.timedSteps, 3) << " | "
                          << fixed(100.0 * seconds / total, 1) << "% |\n";
    }
}

// The least-squares line y = intercept + slope x through the points (at least two, not all at one x).
struct Line {
    double intercept = 0.0, slope = 0.0;
};
Line leastSquares(const std::vector<std::pair<double, double>>& pts) {
    double mx = 0, my = 0;
    for (const auto& [x, y] : pts) mx += x, my += y;
    mx /= pts.size(), my /= pts.size();
    double sxy = 0, sxx = 0;
    for (const auto& [x, y] : pts) sxy += (x - mx) * (y - my), sxx += (x - mx) * (x - mx);
    return {my - sxy / sxx * mx, sxy / sxx};
}

// Least-squares slope of log(ms) against log(bodies) over the pyramid grids of 1 000 to about 21 000 boxes,
// per engine: step time ~ bodies^k.
void printFit(const std::vector<Row>& rows, const std::vector<Engine>& engines) {
    bool printed = false;
    for (const Engine& e : engines) {
        std::vector<std::pair<double, double>> pts;
        for (const Row& r : rows)
            if (r.engine == &e && r.pyramidGrid && r.bodies >= 1000 && r.bodies <= 21000)
                pts.emplace_back(std::log(static_cast<double>(r.bodies)), std::log(r.min()));
        if (pts.size() < 3) continue;
        const double exponent = leastSquares(pts).slope;
        if (!printed) std::cout << "\nStep time against body count (grids of base-10 pyramids, min over repeats):\n";
        printed = true;
        const auto [fewest, most] = std::minmax_element(pts.begin(), pts.end());
        std::cout << "  " << e.name << " x" << e.threads << ": ms/step ~ bodies^" << fixed(exponent, 2) << " ("
                  << pts.size() << " grids, " << fixed(std::exp(fewest->first), 0) << ".."
                  << fixed(std::exp(most->first), 0) << " bodies)\n";
    }
    if (!printed) std::cout << "\n(no fit: add --scenes scaling for at least 3 pyramid grids of 1k to 21k boxes)\n";
}

// physim's one-thread step time against its substep count, per scene: a least-squares line ms = perStep +
// perSubstep * substeps over the counts that ran (at least 2). perStep is the work done once a step (contacts,
// row preparation, colouring), perSubstep that of one substep's passes and body loops.
void printSubstepFit(const std::vector<Row>& rows) {
    bool printed = false;
    std::vector<std::string> scenes;
    for (const Row& r : rows)
        if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
    for (const std::string& scene : scenes) {
        std::vector<std::pair<double, double>> pts;  // (substeps, min ms)
        for (const Row& r : rows)
            if (r.scene == scene && r.engine->substeps > 0 && r.engine->threads == 1)
                pts.emplace_back(r.engine->substeps, r.min());
        if (pts.size() < 2) continue;
        const auto [fewest, most] = std::minmax_element(pts.begin(), pts.end());
        if (fewest->first == most->first) continue;
        const Line line = leastSquares(pts);  // ms = per step + per substep x substeps
        if (!printed) std::cout << "\nphysim's step time against its substeps (one thread, min over repeats):\n";
        printed = true;
        std::cout << "  " << scene << ": " << fixed(line.intercept, 4) << " ms per step + " << fixed(line.slope, 4)
                  << " ms per substep (" << pts.size() << " runs, " << fixed(fewest->first, 0) << ".."
                  << fixed(most->first, 0) << " substeps)\n";
    }
}

std::string jsonNumber(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

void writeJson(std::ostream& out, const std::vector<Row>& rows) {
    out << "[\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const Row& r = rows[i];
        out << "  {\"scene\": \"" << r.scene << "\", \"engine\": \"" << r.engine->name
            << "\", \"threads\": " << r.engine->threads << ", \"bodies\": " << r.bodies
            << ", \"ms_per_step_min\": " << jsonNumber(r.min())
            << ", \"ms_per_step_median\": " << jsonNumber(r.median()) << ", \"top_drop\": " << jsonNumber(r.topDrop)
            << ", \"top_drift\": " << jsonNumber(r.topDrift) << ", \"max_sideways\": " << jsonNumber(r.maxSideways)
            << ", \"min_clearance\": " << jsonNumber(r.minClearance)
            << ", \"below_ground\": " << jsonNumber(r.belowGround) << ", \"lowest_y\": " << jsonNumber(r.lowestY)
            << ", \"cars_mean_dx\": " << jsonNumber(r.carsMeanDx) << ", \"cars_upright\": " << jsonNumber(r.carsUpright)
            << "}" << (i + 1 < rows.size() ? "," : "") << "\n";
    }
    out << "]\n";
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    std::vector<Scene> scenes;
    try {
        for (const std::string& name : expandSceneList(o.scenes)) scenes.push_back(makeScene(name));
    } catch (const std::invalid_argument& e) {
        usageError(e.what());
    }
    std::ofstream json;
    if (!o.json.empty()) {
        json.open(o.json);  // opened now so a bad path fails before the runs, not after
        if (!json) {
            std::cerr << "peer_bench: cannot write '" << o.json << "'\n";
            return 1;
        }
    }

    const Peers peers = peerEngines();
    std::vector<Engine> engines = physimEngines(o.substeps);
    engines.insert(engines.end(), peers.engines.begin(), peers.engines.end());
    for (const std::string& name : o.engines)
        if (std::none_of(engines.begin(), engines.end(), [&](const Engine& e) { return e.name == name; }))
            usageError("unknown engine '" + name + "' (this build has physim" +
                       (peers.engines.empty() ? std::string() : " and " + peers.engines.front().name) + ")");
    // --substeps runs are physim's: `--engines physim` keeps them.
    auto selected = [&](const std::string& name) {
        return std::find(o.engines.begin(), o.engines.end(), name) != o.engines.end();
    };
    if (!o.engines.empty())
        engines.erase(std::remove_if(engines.begin(), engines.end(),
                                     [&](const Engine& e) {
                                         return !selected(e.name) && !(e.substeps > 0 && selected("physim"));
                                     }),
                      engines.end());
    if (!peers.missing.empty()) std::cout << "note: " << peers.missing << "\n\n";
    std::cout << "Steps " << kUntimedSteps + 1 << ".." << o.steps << " timed, " << o.repeats
              << " interleaved repeat(s), " << std::thread::hardware_concurrency() << " hardware threads\n\n";

    std::vector<Row> rows;
    std::vector<std::size_t> rowScene;  // each row's index into scenes
    for (std::size_t si = 0; si < scenes.size(); ++si)
        for (const Engine& e : engines) {
            const Scene& s = scenes[si];
            const std::string skip = e.skips ? e.skips(s) : std::string();
            if (!skip.empty()) {
                std::cout << "note: " << e.name << " does not run " << s.name << ": " << skip << "\n";
                continue;
            }
            rowScene.push_back(si);
            Row r;
            r.scene = s.name;
            r.engine = &e;
            r.bodies = s.dynamics.size();
            r.pyramidGrid = s.pyramidGrid;
            rows.push_back(r);
        }
    for (int rep = 0; rep < o.repeats; ++rep)
        for (std::size_t ri = 0; ri < rows.size(); ++ri) {
            Row& row = rows[ri];
            measure(scenes[rowScene[ri]], o, rep + 1 == o.repeats, row);
            std::cerr << "[" << rep + 1 << "/" << o.repeats << "] " << row.scene << " " << row.engine->name << " x"
                      << row.engine->threads << ": " << fixed(row.msPerStep.back(), 3) << " ms/step\n";
        }

    printTable(rows, peers.engines);
    printGroundCheck(rows);
    printLowest(rows, scenes);
    printCars(rows, scenes);
    if (o.profile) printProfile(rows);
    printFit(rows, engines);
    printSubstepFit(rows);
    if (json.is_open()) {
        writeJson(json, rows);
        if (!json) {
            std::cerr << "peer_bench: writing '" << o.json << "' failed\n";
            return 1;
        }
    }
    return 0;
}
