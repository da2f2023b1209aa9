// The live graphs window, seen from the X server as a user's desktop sees it (run under Xvfb by
// tests/support/with-display.sh): a window run opens it beside the simulation window, its pixels change while
// the simulation runs, closing it (as a window manager does) leaves the simulation running; headless never
// opens it.

#include "XClient.hpp"

#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <SFML/Graphics/RenderWindow.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>

namespace physim {
namespace {

using namespace std::chrono_literals;
using test::XClient;
using test::XRect;

// A box in free fall, its height plotted: every refresh adds points.
class Drop : public Simulation {
public:
    std::string title() const override { return "live graphs test"; }
    void onCreate() override {
        box_ = &spawn<Object>(Vec2(1.0, 1.0));
        box_->setPosition({0.0, 100.0});
        graphsManager.addGraph("Height;time (s);y (m)");
        graphsManager.build();
    }
    void onDrawGraphs() override { graphsManager.addPoint(0, time, box_->getPosition().y()); }

private:
    Object* box_ = nullptr;
};

bool overlap(const XRect& a, const XRect& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

TEST(LiveGraphs, BesideTheWindowRefreshingAndClosableWhileTheSimulationRuns) {
    XClient x;
    ASSERT_TRUE(x) << "no X display";
    RunOptions options;
    options.seconds = 8.0;
    options.width = 400;
    options.height = 300;
    Runner runner([] { return std::make_unique<Drop>(); }, options);

    // What the checker saw, from its own thread and X connection while run() drives the frames.
    bool canvasFound = false, windowFound = false, changed = false, closedGone = false, overlapped = true;
    XRect canvas, window;
    std::thread checker([&] {
        const auto deadline = std::chrono::steady_clock::now() + 60s;
        std::optional<XClient::Window> c, w;
        while (std::chrono::steady_clock::now() < deadline && !(c && w)) {
            c = x.find("live graphs test: graphs");
            w = x.find("live graphs test |");
            std::this_thread::sleep_for(50ms);
        }
        canvasFound = c.has_value(), windowFound = w.has_value();
        if (!c || !w) return;
        std::this_thread::sleep_for(1s);  // both mapped and drawn
        canvas = x.geometry(*c), window = x.geometry(*w);
        overlapped = overlap(canvas, window);
        const std::string before = x.pixels(*c);
        std::this_thread::sleep_for(1500ms);  // several 10 Hz refreshes, 1.5 s more of the fall
        changed = !before.empty() && x.pixels(*c) != before;
        x.close(*c);
        for (int i = 0; i < 40 && x.find("live graphs test: graphs"); ++i) std::this_thread::sleep_for(50ms);
        closedGone = !x.find("live graphs test: graphs");
    });
    testing::internal::CaptureStderr();
    const int code = runner.run();
    const std::string err = testing::internal::GetCapturedStderr();
    checker.join();

    EXPECT_EQ(code, 0);
    ASSERT_TRUE(canvasFound) << "no graphs window on the X server";
    ASSERT_TRUE(windowFound) << "no simulation window";
    EXPECT_FALSE(overlapped) << "graphs at " << canvas.x << "," << canvas.y << " " << canvas.width << "x" << canvas.height
                             << ", simulation window at " << window.x << "," << window.y << " " << window.width << "x"
                             << window.height;
    EXPECT_TRUE(changed) << "the graphs window's pixels did not change in 1.5 s of simulation";
    EXPECT_TRUE(closedGone) << "closing did not close the graphs window";
    EXPECT_FALSE(runner.simulation().graphsManager.canvasOpen());
    EXPECT_GE(runner.simulation().time, 8.0 - 1e-9) << "the simulation ran to its end after the window closed";
    EXPECT_NE(err.find("graphs window closed; the simulation goes on"), std::string::npos) << err;
    EXPECT_GT(runner.simulation().graphsManager.points(0).size(), 100u) << "points kept coming";
}

TEST(LiveGraphs, AWindowRunWritesItsFilesToo) {
    // The export draws off screen while the live window is open (ROOT then draws through X11 otherwise).
    const auto dir = std::filesystem::temp_directory_path() / "physim_live_graphs_out";
    std::filesystem::remove_all(dir);
    RunOptions options;
    options.seconds = 1.0;
    options.width = 320;
    options.height = 240;
    options.quiet = true;
    options.outDir = dir.string();
    Runner runner([] { return std::make_unique<Drop>(); }, options);
    EXPECT_EQ(runner.run(), 0);
    EXPECT_TRUE(runner.simulation().graphsManager.canvasOpen());
    EXPECT_GT(std::filesystem::file_size(dir / "graphs.png"), 1000u);
    EXPECT_TRUE(std::filesystem::exists(dir / "graphs.root"));
    std::filesystem::remove_all(dir);
}

TEST(LiveGraphs, ARestartReplacesTheWindow) {
    // Space makes a new simulation with a new GraphsManager: one graphs window before and after.
    XClient x;
    ASSERT_TRUE(x) << "no X display";
    Runner runner([] { return std::make_unique<Drop>(); }, RunOptions{});
    sf::RenderWindow window(sf::VideoMode(320, 240), "physim test");
    runner.restart();
    for (int i = 0; i < 5; ++i) runner.frame(0.025, &window);
    const auto first = x.find("physim graphs");
    ASSERT_TRUE(first);
    runner.restart();
    for (int i = 0; i < 5; ++i) runner.frame(0.025, &window);
    const auto second = x.find("physim graphs");
    ASSERT_TRUE(second);
    EXPECT_NE(*first, *second) << "a new window";
    EXPECT_EQ(x.count("physim graphs"), 1) << "the old one is gone";
}

TEST(LiveGraphs, HeadlessNeverOpensIt) {
    XClient x;
    ASSERT_TRUE(x) << "no X display";
    RunOptions options;
    options.headless = true;
    options.seconds = 2.0;
    Runner runner([] { return std::make_unique<Drop>(); }, options);
    EXPECT_EQ(runner.run(), 0);
    EXPECT_FALSE(runner.simulation().graphsManager.canvasOpen());
    EXPECT_FALSE(x.find("graphs")) << "a graphs window appeared in a headless run";
    EXPECT_EQ(runner.simulation().graphsManager.points(0).size(), 80u);
}

}  // namespace
}  // namespace physim
