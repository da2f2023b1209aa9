// View: fitting a region into part of a window, zoom about a point, panning. Checked by mapping points back
// and forth: what must be inside the area is, what must stay under the cursor does.

#include <physim/framework/View.hpp>

#include <gtest/gtest.h>

namespace physim {
namespace {

// A wide region fitted into the window below a 60 px bar and right of a 300 px panel: every corner lands
// inside that area (with the margin), the region's centre at the area's centre, and the tighter direction
// (here the width: 40 m into 980 px) fills it up to the margin.
TEST(View, FitPutsTheRegionInsideTheArea) {
    const sf::Vector2u window(1280, 720);
    const sf::FloatRect area(300.f, 60.f, 980.f, 660.f);
    const Aabb region{{-2.0, -1.0}, {38.0, 15.0}};
    View view;
    view.fit(region, area, window, 0.04);
    const sf::Transform t = view.worldToPixels(window);
    for (const Vec2& c : {region.lower, region.upper, Vec2(region.lower.x(), region.upper.y()),
                          Vec2(region.upper.x(), region.lower.y())}) {
        const sf::Vector2f p = t.transformPoint(float(c.x()), float(c.y()));
        EXPECT_GE(p.x, area.left + 0.04f * area.width - 1e-3f);
        EXPECT_LE(p.x, area.left + 0.96f * area.width + 1e-3f);
        EXPECT_GE(p.y, area.top + 0.04f * area.height - 1e-3f);
        EXPECT_LE(p.y, area.top + 0.96f * area.height + 1e-3f);
    }
    const sf::Vector2f centre = t.transformPoint(float(region.center().x()), float(region.center().y()));
    EXPECT_NEAR(centre.x, area.left + 0.5f * area.width, 1e-3);
    EXPECT_NEAR(centre.y, area.top + 0.5f * area.height, 1e-3);
    EXPECT_NEAR(view.pixelsPerMetre, 0.92 * 980.0 / 40.0, 1e-9);

    View point;  // a region of no size only centres
    point.fit(Aabb{{3.0, 4.0}, {3.0, 4.0}}, area, window);
    EXPECT_EQ(point.pixelsPerMetre, 100.0);
    EXPECT_THROW(view.fit(Aabb{{NAN, 0.0}, {1.0, 1.0}}, area, window), std::invalid_argument);
}

TEST(View, ZoomAtKeepsThePointAndPanFollowsTheCursor) {
    const sf::Vector2u window(800, 600);
    View view;
    view.center = {1.0, 2.0};
    const sf::Vector2i cursor(123, 456);
    const Vec2 under = view.toWorld(cursor, window);
    view.zoomAt(3.0, cursor, window);
    EXPECT_DOUBLE_EQ(view.pixelsPerMetre, 300.0);
    EXPECT_LT((view.toWorld(cursor, window) - under).norm(), 1e-12);
    view.pan({30, -40});  // the mouse moved right and up: the scene follows it
    EXPECT_LT((view.toWorld(cursor + sf::Vector2i(30, -40), window) - under).norm(), 1e-12);
    // The scale stays within its limits however far one zooms.
    for (int i = 0; i < 1000; ++i) view.zoom(10.0);
    EXPECT_EQ(view.pixelsPerMetre, View::maxPixelsPerMetre);
    EXPECT_THROW(view.zoom(0.0), std::invalid_argument);
}

}  // namespace
}  // namespace physim
