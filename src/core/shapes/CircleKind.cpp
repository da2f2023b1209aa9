// The circle's room: its factory, its checks and its outline; CollideCircles.cpp holds its narrow phase.

#include "CircleKind.hpp"

#include "physim/core/Validate.hpp"

namespace physim {

Circle makeCircle(double radius, const Vec2& center) {
    requirePositive("circle radius", radius);
    requireFinite("circle center", center);
    return Circle{center, radius};
}

void ShapeKind<Circle>::validate(const Circle& c) {
    requirePositive("circle radius", c.radius);
    requireFinite("circle center", c.center);
}

std::vector<Vec2> ShapeKind<Circle>::outline(const Circle& c, const Transform& xf) {
    constexpr int kPoints = 40;  // smooth at the sizes a window shows
    const Vec2 center = xf.apply(c.center);
    std::vector<Vec2> points(kPoints);
    for (int i = 0; i < kPoints; ++i) {
        const double angle = 2.0 * M_PI * i / kPoints;
        points[static_cast<std::size_t>(i)] = center + c.radius * Vec2(std::cos(angle), std::sin(angle));
    }
    return points;
}

}  // namespace physim
