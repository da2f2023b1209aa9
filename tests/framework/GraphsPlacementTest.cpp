// The live graphs window goes beside the simulation window: on the screen and, when there is room, not over it.

#include "GraphsPlacement.hpp"

#include <gtest/gtest.h>

namespace physim {
namespace {

bool overlap(const ScreenRect& a, const ScreenRect& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}
bool onScreen(const ScreenRect& r, int w, int h) { return r.x >= 0 && r.y >= 0 && r.x + r.width <= w && r.y + r.height <= h; }

TEST(GraphsPlacement, BesideTheWindowWhenThereIsRoom) {
    struct Case {
        int window, windowH, screen, screenH;
    };
    for (const Case c : {Case{1280, 720, 2560, 1440}, Case{1280, 720, 1920, 1080}, Case{640, 360, 1280, 720},
                         Case{800, 600, 1400, 900}}) {
        const SideBySide p = placeBeside(c.window, c.windowH, c.screen, c.screenH);
        EXPECT_FALSE(overlap(p.window, p.canvas)) << c.window << " on " << c.screen;
        EXPECT_TRUE(onScreen(p.window, c.screen, c.screenH)) << c.window << " on " << c.screen;
        EXPECT_TRUE(onScreen(p.canvas, c.screen, c.screenH)) << c.window << " on " << c.screen;
        EXPECT_EQ(p.canvas.x, p.window.x + p.window.width) << "right next to it";
        EXPECT_EQ(p.canvas.y, p.window.y);
        EXPECT_EQ(p.canvas.height, c.windowH);
        EXPECT_GE(p.canvas.width, 480);
    }
    // Wide screen: the pair centred, the graphs at their preferred width.
    const SideBySide wide = placeBeside(1280, 720, 2560, 1440);
    EXPECT_EQ(wide.canvas.width, 1000);
    EXPECT_EQ(wide.window.x, (2560 - 2280) / 2);
}

TEST(GraphsPlacement, OnScreenWhenThereIsNoRoom) {
    const SideBySide p = placeBeside(1280, 720, 1280, 720);  // the window fills the screen
    EXPECT_TRUE(onScreen(p.canvas, 1280, 720));
    EXPECT_EQ(p.canvas.x + p.canvas.width, 1280) << "at the right edge";
}

}  // namespace
}  // namespace physim
