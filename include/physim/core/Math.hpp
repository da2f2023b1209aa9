#pragma once
// Small 2D math layer over Eigen. SI units throughout: metres, radians, seconds. y points up.

#include <Eigen/Core>

#include <cmath>

namespace physim {

using Vec2 = Eigen::Vector2d;

/// z component of the 3D cross product (a, 0) x (b, 0).
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// omega x r for an angular velocity omega (rad/s) about z: the velocity of a point at lever arm r.
inline Vec2 cross(double omega, const Vec2& r) { return {-omega * r.y(), omega * r.x()}; }

/// The vector rotated by +90 degrees (the paper's r-perp).
inline Vec2 perp(const Vec2& v) { return {-v.y(), v.x()}; }

/// A rotation stored as cosine and sine, so applying it costs no trigonometry.
struct Rotation {
    double c = 1.0;
    double s = 0.0;

    static Rotation fromAngle(double radians) { return {std::cos(radians), std::sin(radians)}; }
    double angle() const { return std::atan2(s, c); }
    Vec2 apply(const Vec2& v) const { return {c * v.x() - s * v.y(), s * v.x() + c * v.y()}; }
    Vec2 applyInverse(const Vec2& v) const { return {c * v.x() + s * v.y(), -s * v.x() + c * v.y()}; }
};

/// A rigid transform: rotate a body-local point, then translate by the body's position.
struct Transform {
    Vec2 p = Vec2::Zero();
    Rotation q{};

    Vec2 apply(const Vec2& local) const { return q.apply(local) + p; }
    Vec2 applyInverse(const Vec2& world) const { return q.applyInverse(world - p); }
};

}  // namespace physim
