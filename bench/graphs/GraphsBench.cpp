// graphs_bench: what live plotting costs a frame. Prints a table: time of addPoint, and of one refresh of a
// live ROOT canvas (GraphsManager::render when due) for 1 to 4 graphs of 100 to 10 000 points.
// Needs an X display for the live canvas: run under xvfb-run when there is none.
//   xvfb-run -a build/default/bench/graphs/graphs_bench

#include <physim/graphs/GraphsManager.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

int main() {
    std::printf("%-7s %-14s %-18s %-20s\n", "graphs", "points/graph", "addPoint (ns)", "refresh (ms/frame)");
    for (const int graphs : {1, 4})
        for (const int points : {100, 1000, 10000}) {
            physim::GraphsManager gm;
            // A refresh rate this high makes every render() call a real refresh, so each one is timed.
            gm.setLive(true, 1e9);
            for (int g = 0; g < graphs; ++g) gm.addGraph("g;x;y");
            gm.build();
            const auto t0 = Clock::now();
            for (int i = 0; i < points; ++i)
                for (int g = 0; g < graphs; ++g) gm.addPoint(g, i, std::sin(0.01 * i));
            const double add = secondsSince(t0) / (double(points) * graphs);
            gm.render();  // first draw of the pads
            const int refreshes = 20;
            const auto t1 = Clock::now();
            for (int r = 0; r < refreshes; ++r) {
                gm.addPoint(0, points + r, 0.0);  // new data each frame, as in a running simulation
                gm.render();
            }
            const double refresh = secondsSince(t1) / refreshes;
            std::printf("%-7d %-14d %-18.0f %-20.2f\n", graphs, points, add * 1e9, refresh * 1e3);
        }
    return 0;
}
