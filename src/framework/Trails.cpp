#include "Trails.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace physim {

Trail::Trail(std::size_t capacity) : capacity_(capacity) {
    if (capacity == 0) throw std::invalid_argument("physim: a trail needs a capacity above 0, got 0");
    points_.reserve(capacity);
}

void Trail::push(const Vec2& point) {
    if (points_.size() < capacity_) {
        points_.push_back(point);
        return;
    }
    points_[oldest_] = point;
    oldest_ = (oldest_ + 1) % capacity_;
}

void Trail::clear() {
    points_.clear();
    oldest_ = 0;
}

Trails::Trails(std::size_t pointsPerBody, std::size_t maxBodies) : pointsPerBody_(pointsPerBody), maxBodies_(maxBodies) {
    if (pointsPerBody == 0) throw std::invalid_argument("physim: trails need points per body above 0, got 0");
    if (maxBodies == 0) throw std::invalid_argument("physim: trails need a body cap above 0, got 0");
}

void Trails::record(const std::vector<std::pair<BodyId, Vec2>>& positions) {
    const std::size_t n = std::min(positions.size(), maxBodies_);
    // Usually the same bodies in the same order as last time: each position goes to the trail at its index.
    bool same = entries_.size() == n;
    for (std::size_t i = 0; same && i < n; ++i) same = entries_[i].body == positions[i].first;
    if (!same) {  // bodies came or went: keep the trails of those still traced, start the new ones empty
        std::vector<Entry> next;
        next.reserve(n);
        for (std::size_t i = 0; i < n; ++i) {
            const BodyId body = positions[i].first;
            const auto old = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.body == body; });
            if (old != entries_.end()) next.push_back(std::move(*old));
            else next.push_back({body, Trail(pointsPerBody_)});
        }
        entries_ = std::move(next);
    }
    for (std::size_t i = 0; i < n; ++i) entries_[i].trail.push(positions[i].second);
}

}  // namespace physim
