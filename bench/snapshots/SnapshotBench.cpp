// snapshot_bench: what time travel costs. In one of peer_bench's scenes (default large_pyramid; physim at defaults,
// sleep off, one thread), after --steps steps, times a step, World::snapshot and World::restore in turn (the least of
// --repeats each), and the memory a snapshot holds; a snapshot's file (WorldSnapshot::write into memory, and
// WorldSnapshot::read back: the format's cost, without the disk's) and its size; then the window's timeline (Timeline
// at its default settings): blocks of 50 fixed steps of a Simulation holding the scene, with the timeline recording
// after each and without, alternating, the least block of each. Prints a table; with --json writes [{"scene": s,
// "step_ms": x, "snapshot_ms": y, "restore_ms": z, "snapshot_mb": m, "file_mb": f, "write_ms": w, "read_ms": v,
// "timeline_step_ratio": r}].

#include "../peers/PhysimScene.hpp"
#include "../peers/Scenes.hpp"

#include "physim/core/World.hpp"
#include "physim/framework/Simulation.hpp"
#include "physim/framework/Timeline.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace {

struct Options {
    std::string scene = "large_pyramid";
    int steps = 60;
    int repeats = 10;
    std::string json;
};

[[noreturn]] void usage(const std::string& problem) {
    std::cerr << "snapshot_bench: " << problem << "\n"
              << "usage: snapshot_bench [--scene NAME] [--steps N] [--repeats N] [--json FILE]\n";
    std::exit(2);
}

int positive(const std::string& flag, const char* text) {
    char* end = nullptr;
    const long v = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || v < 1 || v > 1000000) usage(flag + " takes a positive count, got '" + text + "'");
    return static_cast<int>(v);
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> const char* {
            if (i + 1 >= argc) usage(a + " needs a value");
            return argv[++i];
        };
        if (a == "--scene") o.scene = next();
        else if (a == "--steps") o.steps = positive(a, next());
        else if (a == "--repeats") o.repeats = positive(a, next());
        else if (a == "--json") o.json = next();
        else usage("unknown option '" + a + "'");
    }
    return o;
}

template <class F>
double milliseconds(F&& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    peers::Scene scene;
    try {
        scene = peers::makeScene(o.scene);
    } catch (const std::invalid_argument& e) {
        usage(e.what());
    }
    physim::World world(peers::physimSettings(1));
    peers::buildPhysim(world, scene);
    for (int i = 0; i < o.steps; ++i) world.step(peers::kTimeStep);

    // Each round: a step, a snapshot of the state after it, a restore of that snapshot (the same state back, so
    // the next round's step is like the last).
    double step = 1e300, take = 1e300, put = 1e300;
    physim::WorldSnapshot snapshot;
    for (int r = 0; r < o.repeats; ++r) {
        step = std::min(step, milliseconds([&] { world.step(peers::kTimeStep); }));
        take = std::min(take, milliseconds([&] { snapshot = world.snapshot(); }));
        put = std::min(put, milliseconds([&] { world.restore(snapshot); }));
    }
    // The file: written to memory and read back (read checks the whole payload before it returns).
    double write = 1e300, read = 1e300;
    std::string file;
    for (int r = 0; r < o.repeats; ++r) {
        std::ostringstream out(std::ios::binary);
        write = std::min(write, milliseconds([&] { snapshot.write(out); }));
        file = out.str();
        std::istringstream in(file, std::ios::binary);
        physim::WorldSnapshot back;
        read = std::min(read, milliseconds([&] { back = physim::WorldSnapshot::read(in); }));
        if (back.stateHash() != snapshot.stateHash()) {
            std::cerr << "snapshot_bench: the file read back differs\n";
            return 1;
        }
    }
    const double fileMb = static_cast<double>(file.size()) / 1048576.0;
    // The timeline's share: the same scene in a Simulation (the runner's frame: a fixed step, then the record).
    physim::Simulation sim;
    sim.setPhysicsRate(1.0 / peers::kTimeStep);
    sim.world().setSettings(peers::physimSettings(1));
    peers::buildPhysim(sim.world(), scene);
    for (int i = 0; i < o.steps; ++i) sim.fixedStep();
    physim::Timeline timeline;
    timeline.record(sim);
    double bare = 1e300, recorded = 1e300;
    for (int r = 0; r < o.repeats; ++r) {
        bare = std::min(bare, milliseconds([&] {
            for (int i = 0; i < 50; ++i) sim.fixedStep();
        }));
        timeline.record(sim);  // catches up on the bare block's steps, outside the timing
        recorded = std::min(recorded, milliseconds([&] {
            for (int i = 0; i < 50; ++i) {
                sim.fixedStep();
                timeline.record(sim);
            }
        }));
    }
    const double ratio = recorded / bare;
    const double mb = snapshot.bytes() / 1048576.0;
    std::printf("snapshot_bench: %s, %zu bodies, least of %d\n", o.scene.c_str(), world.bodyCount(), o.repeats);
    std::printf(
        "| scene | step ms | snapshot ms | restore ms | snapshot MB | snapshot / step | restore / step | steps with "
        "timeline / without |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    std::printf("| %s | %.3f | %.3f | %.3f | %.2f | %.3f | %.3f | %.3f |\n", o.scene.c_str(), step, take, put, mb,
                take / step, put / step, ratio);
    std::printf("| scene | file MB | write ms | read ms | write / step | read / step |\n|---|---|---|---|---|---|\n");
    std::printf("| %s | %.2f | %.3f | %.3f | %.3f | %.3f |\n", o.scene.c_str(), fileMb, write, read, write / step,
                read / step);
    std::printf("timeline: %zu snapshots, every %d steps, %.1f MB\n", timeline.size(), timeline.interval(),
                timeline.bytes() / 1048576.0);
    if (!o.json.empty()) {
        std::ofstream out(o.json);
        out << "[{\"scene\": \"" << o.scene << "\", \"step_ms\": " << step << ", \"snapshot_ms\": " << take
            << ", \"restore_ms\": " << put << ", \"snapshot_mb\": " << mb << ", \"file_mb\": " << fileMb
            << ", \"write_ms\": " << write << ", \"read_ms\": " << read << ", \"timeline_step_ratio\": " << ratio
            << "}]\n";
        if (!out) {
            std::cerr << "snapshot_bench: cannot write " << o.json << "\n";
            return 1;
        }
    }
    return 0;
}
