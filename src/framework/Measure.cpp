#include "Measure.hpp"

#include "physim/core/Validate.hpp"

#include <cmath>
#include <stdexcept>

namespace physim {

double protractorAngle(const Vec2& vertex, const Vec2& a, const Vec2& b) {
    requireFinite("protractor vertex", vertex);
    requireFinite("protractor arm end", a);
    requireFinite("protractor arm end", b);
    const Vec2 u = a - vertex, v = b - vertex;
    if (u.squaredNorm() == 0.0 || v.squaredNorm() == 0.0)
        throw std::invalid_argument("protractor: an arm of zero length has no direction");
    // atan2 of |u x v| and u . v: accurate near 0 and 180 degrees, where acos of the normalised dot is not.
    const double cross = u.x() * v.y() - u.y() * v.x();
    return std::atan2(std::abs(cross), u.dot(v)) * (180.0 / M_PI);
}

bool Measurement::press(Kind kind, const Vec2& point) {
    if (awaiting_) {
        points_.back() = point;
        awaiting_ = false;
        return true;
    }
    clear();
    if (kind == Kind::None) return false;
    kind_ = kind;
    points_ = {point, point};
    dragging_ = true;
    return true;
}

void Measurement::move(const Vec2& point) {
    if (dragging_ || awaiting_) points_.back() = point;
}

void Measurement::release(const Vec2& point) {
    if (!dragging_) return;
    points_.back() = point;
    dragging_ = false;
    if (kind_ == Kind::Protractor) {
        points_.push_back(point);
        awaiting_ = true;
    }
}

void Measurement::clear() {
    kind_ = Kind::None;
    points_.clear();
    dragging_ = awaiting_ = false;
}

std::optional<double> Measurement::length() const {
    if (kind_ != Kind::Tape) return std::nullopt;
    return (points_[1] - points_[0]).norm();
}

std::optional<double> Measurement::angle() const {
    if (kind_ != Kind::Protractor || points_.size() < 3) return std::nullopt;
    if (points_[1] == points_[0] || points_[2] == points_[0]) return std::nullopt;
    return protractorAngle(points_[0], points_[1], points_[2]);
}

}  // namespace physim
