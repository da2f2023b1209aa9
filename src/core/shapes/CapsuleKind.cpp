// The capsule's room: its factory, mass, checks and outline.

#include "CapsuleKind.hpp"

#include "physim/core/Validate.hpp"

namespace physim {

Capsule makeCapsule(const Vec2& c1, const Vec2& c2, double radius) {
    requireTwoPoints("capsule", "center1", c1, "center2", c2);
    requirePositive("capsule radius", radius);
    return Capsule{c1, c2, radius};
}

void ShapeKind<Capsule>::validate(const Capsule& c) {
    requirePositive("capsule radius", c.radius);
    requireTwoPoints("capsule", "center1", c.center1, "center2", c.center2);
}

// A rectangle L x 2r and a disc (the two round ends), both about the midpoint:
// I = r L^3 / 6 + 2 r^3 L + pi r^2 L^2 / 4 + pi r^4 / 2 (each half disc's own moment shifted by the parallel-axis
// theorem through its centroid, 4 r / (3 pi) beyond its end).
MassProperties ShapeKind<Capsule>::mass(const Capsule& c) {
    const double r = c.radius, length = TwoPoints::length(c.center1, c.center2);
    const double area = 2.0 * r * length + M_PI * r * r;
    const double moment = r * length * length * length / 6.0 + 2.0 * r * r * r * length +
                          0.25 * M_PI * r * r * length * length + 0.5 * M_PI * r * r * r * r;
    return {area, 0.5 * (c.center1 + c.center2), moment};
}

std::vector<Vec2> ShapeKind<Capsule>::outline(const Capsule& c, const Transform& xf) {
    constexpr int kArcPoints = 21;  // per half circle, as smooth as a circle's 40
    const Vec2 axis = (c.center2 - c.center1) / TwoPoints::length(c.center1, c.center2);
    const double right = std::atan2(-axis.x(), axis.y());  // angle of the right-hand normal (axis.y, -axis.x)
    std::vector<Vec2> points;
    points.reserve(2 * kArcPoints);
    // Counter-clockwise: round the far end from the right side to the left, then round the near end back.
    for (int end = 0; end < 2; ++end) {
        const Vec2& center = end == 0 ? c.center2 : c.center1;
        for (int i = 0; i < kArcPoints; ++i) {
            const double angle = right + M_PI * end + M_PI * i / (kArcPoints - 1);
            points.push_back(xf.apply(center + c.radius * Vec2(std::cos(angle), std::sin(angle))));
        }
    }
    return points;
}

}  // namespace physim
