// The segment's room: its factory, its checks and its outline.

#include "SegmentKind.hpp"
#include "PolygonCheck.hpp"

#include "physim/core/Validate.hpp"

#include <sstream>
#include <stdexcept>

namespace physim {
namespace {

// Points closer than this fraction of their distance from the body origin are one point: far above rounding
// (1e-16), far below any segment worth simulating.
constexpr double kApart = 1e-12;

}  // namespace

void requireTwoPoints(const char* what, const char* first, const Vec2& p1, const char* second, const Vec2& p2) {
    requireFinite(std::string(what) + " " + first, p1);
    requireFinite(std::string(what) + " " + second, p2);
    const double length = TwoPoints::length(p1, p2);
    if (!std::isfinite(length))
        throw std::invalid_argument(std::string("physim: ") + what + " is too long: " + show(p1) + " to " + show(p2) +
                                    " overflows its length");
    if (!(length > kApart * std::max(p1.norm(), p2.norm())))
        throw std::invalid_argument(std::string("physim: ") + what + " " + first + " and " + second +
                                    " must be apart (zero length), got " + show(p1) + " and " + show(p2));
}

Segment makeSegment(const Vec2& p1, const Vec2& p2) {
    requireTwoPoints("segment", "point1", p1, "point2", p2);
    return Segment{p1, p2};
}

void ShapeKind<Segment>::validate(const Segment& s) {
    requireTwoPoints("segment", "point1", s.point1, "point2", s.point2);
}

std::vector<Vec2> ShapeKind<Segment>::outline(const Segment& s, const Transform& xf) {
    return {xf.apply(s.point1), xf.apply(s.point2)};
}

}  // namespace physim
