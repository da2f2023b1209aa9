// graphs_bench: what plotting costs. Two tables:
//  - live: addPoint, and one refresh of the live ROOT canvas window (GraphsManager::render when due), for 1 and
//    4 graphs (each with an analytic curve on its pad) of 100 to 24 000 points;
//  - export: writeFiles (CSV, PNG, .root) of the same graphs, headless.
// The live canvas is a real window: run under xvfb-run when there is no display.
//   xvfb-run -a -s "-screen 0 1920x1080x24" build/default/bench/graphs/graphs_bench

#include <physim/graphs/GraphsManager.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <thread>

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// `graphs` pads, each a simulated series (markers and line) over a curve.
void build(physim::GraphsManager& gm, int graphs) {
    for (int g = 0; g < graphs; ++g) {
        const int sim = gm.addGraph("g;time (s);y (m)", {}, physim::GraphMode::WITH_LINES);
        gm.addSeries(sim, "analytic");
    }
    gm.build();
}

// `points` points on each series.
void fill(physim::GraphsManager& gm, int graphs, int points) {
    for (int i = 0; i < points; ++i)
        for (int g = 0; g < graphs; ++g) {
            gm.addPoint(2 * g, 0.025 * i, std::sin(0.01 * i) + 1e-3 * std::sin(1.7 * i));
            gm.addPoint(2 * g + 1, 0.025 * i, std::sin(0.01 * i));
        }
}

}  // namespace

int main() {
    std::printf("live canvas (a window): one refresh redraws every pad\n");
    std::printf("%-7s %-14s %-16s %-14s\n", "graphs", "points/graph", "addPoint (ns)", "refresh (ms)");
    for (const int graphs : {1, 4})
        for (const int points : {100, 1000, 10000, 24000}) {
            physim::GraphsManager gm;
            gm.setCanvasSize(900, 700);
            // No rate limit: a render() call is a refresh once the previous one's wait (5 times its length)
            // is over, which the sleeps below ensure.
            gm.setLive(true, 1e9);
            build(gm, graphs);
            if (!gm.canvasOpen()) {
                std::fprintf(stderr, "graphs_bench: no live canvas window (no display?); run under xvfb-run\n");
                return 1;
            }
            const auto t0 = Clock::now();
            fill(gm, graphs, points);
            const double add = secondsSince(t0) / (2.0 * points * graphs);
            gm.render();  // the first full draw
            const int refreshes = 20;
            double refresh = 0.0;
            for (int r = 0; r < refreshes; ++r) {
                std::this_thread::sleep_for(std::chrono::milliseconds(300));
                gm.addPoint(0, 0.025 * (points + r), 0.0);  // new data each frame, as in a running simulation
                const auto t1 = Clock::now();
                gm.render();
                refresh += secondsSince(t1) / refreshes;
            }
            std::printf("%-7d %-14d %-16.0f %-14.2f\n", graphs, points, add * 1e9, refresh * 1e3);
        }

    std::printf("\nexport (headless writeFiles: graph_<i>.csv, graphs.png, graphs.root)\n");
    std::printf("%-7s %-14s %-14s\n", "graphs", "points/graph", "export (ms)");
    const auto dir = std::filesystem::temp_directory_path() / "physim_graphs_bench";
    for (const int graphs : {1, 4})
        for (const int points : {100, 1000, 10000, 24000}) {
            physim::GraphsManager gm;
            build(gm, graphs);
            fill(gm, graphs, points);
            const auto t0 = Clock::now();
            gm.writeFiles(dir.string());
            std::printf("%-7d %-14d %-14.1f\n", graphs, points, secondsSince(t0) * 1e3);
        }
    std::filesystem::remove_all(dir);
    return 0;
}
