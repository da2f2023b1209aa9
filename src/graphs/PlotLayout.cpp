#include "PlotLayout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace physim::plot {

std::vector<Point> thinLine(const std::vector<Point>& points, std::size_t buckets) {
    const std::size_t n = points.size();
    if (buckets == 0 || n <= 2 * buckets + 2) return points;
    std::vector<Point> out;
    out.reserve(2 * buckets + 2);
    out.push_back(points.front());
    for (std::size_t b = 0; b < buckets; ++b) {
        // Run [begin, end) of the inner points 1 .. n-2.
        const std::size_t begin = 1 + b * (n - 2) / buckets, end = 1 + (b + 1) * (n - 2) / buckets;
        if (begin >= end) continue;
        std::size_t lo = begin, hi = begin;
        for (std::size_t i = begin + 1; i < end; ++i) {
            if (points[i].second < points[lo].second) lo = i;
            if (points[i].second > points[hi].second) hi = i;
        }
        out.push_back(points[std::min(lo, hi)]);
        if (lo != hi) out.push_back(points[std::max(lo, hi)]);
    }
    out.push_back(points.back());
    return out;
}

std::vector<Point> thinMarkers(const std::vector<Point>& points, std::size_t count) {
    const std::size_t n = points.size();
    if (n <= count || count < 3) return count < 3 && n > count ? std::vector<Point>{points.front(), points.back()}
                                                               : points;
    // Largest triangle three buckets: the inner points in count - 2 buckets; from each the point making the
    // largest triangle with the point kept before it and the mean of the next bucket.
    std::vector<Point> out;
    out.reserve(count);
    out.push_back(points.front());
    const double every = static_cast<double>(n - 2) / static_cast<double>(count - 2);
    std::size_t kept = 0;
    for (std::size_t b = 0; b < count - 2; ++b) {
        const auto begin = static_cast<std::size_t>(std::floor(b * every)) + 1;
        const auto end = std::min(static_cast<std::size_t>(std::floor((b + 1) * every)) + 1, n - 1);
        const auto nextEnd = std::min(static_cast<std::size_t>(std::floor((b + 2) * every)) + 1, n);
        double mx = 0.0, my = 0.0;
        const std::size_t nextBegin = end;
        for (std::size_t i = nextBegin; i < nextEnd; ++i) mx += points[i].first, my += points[i].second;
        const double m = static_cast<double>(std::max<std::size_t>(nextEnd - nextBegin, 1));
        mx /= m, my /= m;
        if (nextEnd == nextBegin) mx = points.back().first, my = points.back().second;
        const Point& a = points[kept];
        double best = -1.0;
        std::size_t bestIndex = begin;
        for (std::size_t i = begin; i < std::max(end, begin + 1); ++i) {
            const double area = std::abs((a.first - mx) * (points[i].second - a.second) -
                                         (a.first - points[i].first) * (my - a.second));
            if (area > best) best = area, bestIndex = i;
        }
        out.push_back(points[bestIndex]);
        kept = bestIndex;
    }
    out.push_back(points.back());
    return out;
}

YTransform chooseYTransform(double start, double lo, double hi) {
    YTransform t;
    if (start == 0.0 || !std::isfinite(start)) return t;
    const double scale = std::abs(start);
    if (std::max(std::abs(hi - start), std::abs(lo - start)) <= kRelativeBelow * scale) {
        t.relative = true;
        t.origin = start;
        t.scale = scale;
    }
    return t;
}

std::string relativeTitle(const std::string& yTitle, double start) {
    std::string name = yTitle, unit;
    const auto open = yTitle.rfind(" (");
    if (open != std::string::npos && !yTitle.empty() && yTitle.back() == ')') {
        name = yTitle.substr(0, open);
        unit = yTitle.substr(open + 2, yTitle.size() - open - 3);
    }
    char value[64];
    std::snprintf(value, sizeof value, "%.6g", start);
    std::string title = "#Delta(" + (name.empty() ? std::string("y") : name) + ") / start,  start = " + value;
    if (!unit.empty()) title += " " + unit;
    return title;
}

std::pair<double, double> paddedRange(double lo, double hi, double minSpan) {
    double span = hi - lo;
    if (!(span > 0.0) && !(minSpan > 0.0)) {
        span = lo != 0.0 ? 0.1 * std::abs(lo) : 1.0;
        const double mid = lo;
        lo = mid - span / 2, hi = mid + span / 2;
    }
    if (span < minSpan) {
        const double mid = 0.5 * (lo + hi);
        lo = mid - minSpan / 2, hi = mid + minSpan / 2;
        span = minSpan;
    }
    return {lo - 0.05 * span, hi + 0.05 * span};
}

namespace {

bool segmentHitsBox(const Point& a, const Point& b, const Box& r) {
    // Liang-Barsky clipping of segment a-b against the box.
    double t0 = 0.0, t1 = 1.0;
    const double dx = b.first - a.first, dy = b.second - a.second;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.first - r.x1, r.x2 - a.first, a.second - r.y1, r.y2 - a.second};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0) return false;
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0.0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
        if (t0 > t1) return false;
    }
    return true;
}

}  // namespace

bool boxHit(const Box& box, const Obstacles& o) {
    const Box grown{box.x1 - o.markerRadius, box.y1 - o.markerRadius, box.x2 + o.markerRadius,
                    box.y2 + o.markerRadius};
    for (const Point& m : o.markers)
        if (m.first >= grown.x1 && m.first <= grown.x2 && m.second >= grown.y1 && m.second <= grown.y2) return true;
    for (const auto& line : o.lines) {
        if (line.size() == 1 && segmentHitsBox(line[0], line[0], box)) return true;
        for (std::size_t i = 1; i < line.size(); ++i)
            if (segmentHitsBox(line[i - 1], line[i], box)) return true;
    }
    return false;
}

Box cornerBox(const Box& frame, Corner corner, double w, double h, double insetX, double insetY) {
    const bool right = corner == Corner::TOP_RIGHT || corner == Corner::BOTTOM_RIGHT;
    const bool top = corner == Corner::TOP_RIGHT || corner == Corner::TOP_LEFT;
    const double x1 = right ? frame.x2 - insetX - w : frame.x1 + insetX;
    const double y1 = top ? frame.y2 - insetY - h : frame.y1 + insetY;
    return {x1, y1, x1 + w, y1 + h};
}

bool freeCorner(const Box& frame, double w, double h, double insetX, double insetY, const Obstacles& obstacles,
                Corner preferred, Corner& chosen) {
    const Corner order[] = {preferred, Corner::TOP_RIGHT, Corner::TOP_LEFT, Corner::BOTTOM_RIGHT,
                            Corner::BOTTOM_LEFT};
    for (Corner c : order)
        if (!boxHit(cornerBox(frame, c, w, h, insetX, insetY), obstacles)) {
            chosen = c;
            return true;
        }
    return false;
}

double textWidthPx(const std::string& text, double sizePx) {
    double em = 0.0;
    for (char c : text) {
        switch (c) {
            case '.': case ',': case ' ': case 'i': case 'l': case 'j': case 't': case 'f': case '1': em += 0.28; break;
            case '-': case '(': case ')': case 'r': em += 0.33; break;
            case 'm': case 'w': case 'M': case 'W': em += 0.83; break;
            case '#': em += 0.0; break;  // TLatex markup, roughly: "#Delta" is drawn as one glyph
            default: em += (c >= 'A' && c <= 'Z') ? 0.67 : 0.556;
        }
    }
    return em * sizePx;
}

std::string widestTickLabel(double lo, double hi, int divisions, int maxDigits) {
    if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return "0";
    // Nice step: 1, 2 or 5 times a power of ten, as ROOT's axis optimiser picks.
    const double raw = (hi - lo) / std::max(divisions, 1);
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    double step = p;
    for (double f : {1.0, 2.0, 5.0, 10.0})
        if (f * p >= raw * 0.999) {
            step = f * p;
            break;
        }
    const double first = std::ceil(lo / step - 1e-9), last = std::floor(hi / step + 1e-9);
    const double maxAbs = std::max(std::abs(first * step), std::abs(last * step));
    auto decimalsFor = [](double s) { return std::max(0, -static_cast<int>(std::floor(std::log10(s) + 1e-9))); };
    const int intDigits = maxAbs >= 1.0 ? static_cast<int>(std::floor(std::log10(maxAbs))) + 1 : 1;
    // Too many digits: ROOT divides the labels by 10^e, e a multiple of 3 that brings the largest into
    // [0.1, 100), and writes the power at the axis end (seen: 2e-4 as 0.2 x 10^-3, 5e-13 as 0.5 x 10^-12).
    double scale = 1.0;
    if (intDigits + decimalsFor(step) > maxDigits && maxAbs > 0.0)
        scale = std::pow(10.0, 3.0 * std::floor((std::log10(maxAbs) + 1.0) / 3.0));
    const int decimals = decimalsFor(step / scale);
    std::string widest = "0";
    double widestPx = textWidthPx(widest, 1.0);
    for (double k = first; k <= last && k - first < 100; k += 1.0) {
        const double v = k * step / scale;
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.*f", decimals, std::abs(v) < 1e-9 * step / scale ? 0.0 : v);
        const double px = textWidthPx(buf, 1.0);
        if (px > widestPx) widest = buf, widestPx = px;
    }
    return widest;
}

std::pair<int, int> padGrid(int n, int width, int height) {
    if (n <= 1) return {1, 1};
    int bestCols = 1;
    double bestScore = std::numeric_limits<double>::infinity();
    for (int cols = 1; cols <= n; ++cols) {
        const int rows = (n + cols - 1) / cols;
        if ((cols - 1) * rows >= n) continue;  // a whole empty column
        const double aspect = (static_cast<double>(width) / cols) / (static_cast<double>(height) / rows);
        const double score = std::abs(std::log(aspect / (4.0 / 3.0))) + 0.15 * (cols * rows - n);
        if (score < bestScore) bestScore = score, bestCols = cols;
    }
    return {bestCols, (n + bestCols - 1) / bestCols};
}

}  // namespace physim::plot
