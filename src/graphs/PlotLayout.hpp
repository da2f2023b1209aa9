#pragma once
// How a pad of graphs is laid out, as pure functions (no ROOT): which points are drawn, the y range and
// whether it shows a deviation from the start, where the legend goes, how wide the margins must be.
// GraphsManager's ROOT drawing (live and exported) is built on these; tests check them directly.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace physim::plot {

using Point = std::pair<double, double>;

/// Line thinning: the points split into `buckets` runs of consecutive points, each run kept as its lowest and
/// highest point (in their order), plus the very first and last point. With one bucket per pixel column the
/// polyline covers exactly the pixels the full one does. Returns the input when it is not longer than
/// 2 * buckets + 2.
std::vector<Point> thinLine(const std::vector<Point>& points, std::size_t buckets);

/// Marker thinning: at most `count` points chosen by largest-triangle-three-buckets (Steinarsson 2013), which
/// keeps peaks and turns, always with the first and last point. Returns the input when it has <= count points.
std::vector<Point> thinMarkers(const std::vector<Point>& points, std::size_t count);

/// How a pad's y values are shown: y_shown = (y - origin) / scale. Absolute: origin 0, scale 1.
struct YTransform {
    bool relative = false;
    double origin = 0.0;  ///< the start value
    double scale = 1.0;   ///< |start| when relative
    double apply(double y) const { return (y - origin) / scale; }
};

/// A pad is shown relative to its start when every value on it lies within `relativeBelow` of the start value
/// |y0| (and y0 != 0): plain tick labels would then need more than about four significant digits to differ.
inline constexpr double kRelativeBelow = 1e-3;
YTransform chooseYTransform(double start, double lo, double hi);

/// The y axis title for a pad shown relative to `start`: "#Delta(name) / start,  start = 1.2346e+04 J" from an
/// axis title "name (J)".
std::string relativeTitle(const std::string& yTitle, double start);

/// A range with room around the data: 5% each side, at least `minSpan` wide (a constant series with no minSpan
/// gets a span around its value: 10% of it, or 1 when it is 0).
std::pair<double, double> paddedRange(double lo, double hi, double minSpan = 0.0);

/// Rectangle in a pad's NDC (0..1 both ways, y up).
struct Box {
    double x1 = 0, y1 = 0, x2 = 0, y2 = 0;
};

/// Legend corners, in the order they are tried.
enum class Corner { TOP_RIGHT, TOP_LEFT, BOTTOM_RIGHT, BOTTOM_LEFT };

/// What the legend must avoid, in NDC: marker centres (with their radius) and polyline vertices (segments
/// between consecutive vertices of one line count too).
struct Obstacles {
    std::vector<Point> markers;
    double markerRadius = 0.0;                  ///< NDC, the larger of the two directions
    std::vector<std::vector<Point>> lines;
};

bool boxHit(const Box& box, const Obstacles& obstacles);

/// The legend box of size w x h (NDC) in `corner` of the frame (NDC box), `inset` from its edges.
Box cornerBox(const Box& frame, Corner corner, double w, double h, double insetX, double insetY);

/// The first free corner, starting with `preferred` (the one used last, so a live legend does not jump);
/// none free: returns false.
bool freeCorner(const Box& frame, double w, double h, double insetX, double insetY, const Obstacles& obstacles,
                Corner preferred, Corner& chosen);

/// Approximate width, in pixels, of text in Helvetica (ROOT's font 4x) at `sizePx`: digits and most letters are
/// about 0.55 em, '.', ',' and '1' narrower, '-' a third.
double textWidthPx(const std::string& text, double sizePx);

/// The widest tick label ROOT draws on an axis spanning [lo, hi] with about `divisions` primary ticks: ROOT shows
/// at most `maxDigits` digits and moves a common power of ten to the axis end.
std::string widestTickLabel(double lo, double hi, int divisions = 10, int maxDigits = 5);

/// Pads in a grid of cols x rows for n pads on a canvas of width x height: the grid whose pads are closest to
/// 4:3 (wide ones read better for time series).
std::pair<int, int> padGrid(int n, int width, int height);

}  // namespace physim::plot
