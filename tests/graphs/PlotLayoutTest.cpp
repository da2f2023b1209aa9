// The pure layout rules under the graphs: thinning keeps what the eye sees, a nearly constant pad is shown
// relative to its start, the legend finds a corner free of data, margins fit the tick labels.

#include "PlotLayout.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace physim::plot {
namespace {

std::vector<Point> series(std::size_t n, double (*f)(double)) {
    std::vector<Point> p;
    for (std::size_t i = 0; i < n; ++i) p.emplace_back(0.025 * static_cast<double>(i), f(0.025 * static_cast<double>(i)));
    return p;
}

double bounce(double t) { return std::abs(5.0 * std::cos(3.0 * t)) * std::exp(-0.01 * t); }

TEST(PlotLayout, ThinLineKeepsEachColumnsExtremesAndTheEnds) {
    const auto all = series(24000, bounce);  // 600 s at 40 Hz
    const std::size_t columns = 500;
    const auto thin = thinLine(all, columns);
    EXPECT_LE(thin.size(), 2 * columns + 2);
    EXPECT_EQ(thin.front(), all.front());
    EXPECT_EQ(thin.back(), all.back());
    EXPECT_TRUE(std::is_sorted(thin.begin(), thin.end())) << "points stay in their order (x rises here)";
    // Every bucket's lowest and highest point survive: the polyline spans the same y in each column, so it
    // covers the same pixels as the full one.
    for (std::size_t b = 0; b < columns; ++b) {
        const std::size_t begin = 1 + b * (all.size() - 2) / columns, end = 1 + (b + 1) * (all.size() - 2) / columns;
        const auto [lo, hi] = std::minmax_element(all.begin() + static_cast<long>(begin), all.begin() + static_cast<long>(end),
                                                  [](const Point& a, const Point& c) { return a.second < c.second; });
        EXPECT_NE(std::find(thin.begin(), thin.end(), *lo), thin.end()) << "bucket " << b;
        EXPECT_NE(std::find(thin.begin(), thin.end(), *hi), thin.end()) << "bucket " << b;
    }
    const auto shortOne = series(100, bounce);
    EXPECT_EQ(thinLine(shortOne, columns), shortOne) << "nothing to thin";
}

TEST(PlotLayout, ThinMarkersKeepsTheCountTheEndsAndASpike) {
    auto all = series(24000, [](double t) { return std::sin(t); });
    all[12345].second = 40.0;  // one spike: a reader must still see it
    const auto thin = thinMarkers(all, 120);
    EXPECT_EQ(thin.size(), 120u);
    EXPECT_EQ(thin.front(), all.front());
    EXPECT_EQ(thin.back(), all.back());
    EXPECT_NE(std::find(thin.begin(), thin.end(), all[12345]), thin.end());
    EXPECT_TRUE(std::is_sorted(thin.begin(), thin.end()));
    EXPECT_EQ(thinMarkers(thin, 200), thin) << "nothing to thin";
}

TEST(PlotLayout, NearlyConstantPadsAreShownRelativeToTheStart) {
    // Gas: 7e-5 of relative drift is within 1e-3: shown as the relative change.
    const YTransform gas = chooseYTransform(471.0, 471.0 * (1 - 7e-5), 471.0);
    EXPECT_TRUE(gas.relative);
    EXPECT_NEAR(gas.apply(471.0 * (1 - 7e-5)), -7e-5, 1e-15);
    // Falling box: the height goes from 5 m to 0.5 m: absolute.
    EXPECT_FALSE(chooseYTransform(5.0, 0.5, 5.0).relative);
    EXPECT_FALSE(chooseYTransform(100.0, 100.0, 100.2).relative) << "2e-3: plain labels still tell it";
    EXPECT_FALSE(chooseYTransform(0.0, -1e-12, 1e-12).relative) << "no relative change from 0";
    EXPECT_EQ(relativeTitle("K (J)", 3.82882), "#Delta(K) / start,  start = 3.82882 J");
    EXPECT_EQ(relativeTitle("energy", 2.0), "#Delta(energy) / start,  start = 2");
}

TEST(PlotLayout, PaddedRangeGivesRoomAndASpan) {
    const auto [lo, hi] = paddedRange(0.0, 10.0);
    EXPECT_DOUBLE_EQ(lo, -0.5);
    EXPECT_DOUBLE_EQ(hi, 10.5);
    const auto [clo, chi] = paddedRange(2.0, 2.0);
    EXPECT_LT(clo, 2.0);
    EXPECT_GT(chi, 2.0);
    const auto [zlo, zhi] = paddedRange(0.0, 0.0, 1e-12);
    EXPECT_NEAR(zhi - zlo, 1.1e-12, 1e-24) << "the minimum span, not a span of 1";
}

TEST(PlotLayout, LegendTakesAFreeCornerOrNone) {
    const Box frame{0.1, 0.1, 0.95, 0.9};
    Obstacles o;
    o.markerRadius = 0.01;
    // A curve rising to the top right: the top left is free.
    o.lines.push_back({{0.1, 0.1}, {0.5, 0.3}, {0.95, 0.9}});
    Corner c = Corner::TOP_RIGHT;
    ASSERT_TRUE(freeCorner(frame, 0.3, 0.1, 0.01, 0.01, o, Corner::TOP_RIGHT, c));
    EXPECT_EQ(c, Corner::TOP_LEFT);
    EXPECT_FALSE(boxHit(cornerBox(frame, c, 0.3, 0.1, 0.01, 0.01), o));
    // A segment crossing the box with no vertex inside still counts.
    EXPECT_TRUE(boxHit({0.4, 0.4, 0.6, 0.6}, Obstacles{{}, 0.0, {{{0.3, 0.5}, {0.7, 0.5}}}}));
    // Markers everywhere: no corner.
    for (double x = 0.1; x <= 0.95; x += 0.02)
        for (double y = 0.1; y <= 0.9; y += 0.02) o.markers.emplace_back(x, y);
    EXPECT_FALSE(freeCorner(frame, 0.3, 0.1, 0.01, 0.01, o, Corner::TOP_RIGHT, c));
}

TEST(PlotLayout, WidestTickLabelFollowsRootsDigits) {
    // Ticks every 0.5, 0.1 and 2000: the widest label has one decimal, a sign and one decimal, five digits.
    EXPECT_EQ(widestTickLabel(0.0, 4.0).size(), 3u);
    EXPECT_EQ(widestTickLabel(-0.5, 0.5), "-0.5");
    EXPECT_EQ(widestTickLabel(0.0, 20000.0).size(), 5u);
    // Too many digits: ROOT's common power of ten (a multiple of 3) and short labels. A relative energy change
    // of -2.4e-4 is drawn with ticks -0.05 ... -0.2 and "x10^-3".
    EXPECT_EQ(widestTickLabel(-2.4e-4, 1.2e-5).size(), 5u);
    EXPECT_EQ(widestTickLabel(-5.5e-13, 5.5e-13), "-0.4");
    EXPECT_EQ(widestTickLabel(0.0, 2e6).size(), 3u) << "0.2 ... 2.0 x 10^6";
    EXPECT_GT(textWidthPx("-0.5", 13.0), textWidthPx("0", 13.0));
}

TEST(PlotLayout, PadGridPrefersWidePads) {
    EXPECT_EQ(padGrid(1, 1200, 700), (std::pair<int, int>{1, 1}));
    EXPECT_EQ(padGrid(2, 1200, 700), (std::pair<int, int>{2, 1}));
    EXPECT_EQ(padGrid(2, 640, 720), (std::pair<int, int>{1, 2})) << "a narrow window stacks them";
    EXPECT_EQ(padGrid(4, 1200, 700), (std::pair<int, int>{2, 2}));
}

}  // namespace
}  // namespace physim::plot
