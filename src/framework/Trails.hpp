#pragma once
// The window's trails (key L): each traced body's recent path, a fixed number of positions per body in a ring
// buffer, so memory is bounded however long the run. Internal to the runner; window-free, so it can be tested
// headless.

#include "physim/core/Body.hpp"
#include "physim/core/Math.hpp"

#include <cstddef>
#include <utility>
#include <vector>

namespace physim {

/// The last `capacity` positions pushed (m), oldest first.
class Trail {
public:
    /// Throws std::invalid_argument for a capacity of 0.
    explicit Trail(std::size_t capacity);
    void push(const Vec2& point);
    std::size_t size() const { return points_.size(); }
    std::size_t capacity() const { return capacity_; }
    /// i = 0 is the oldest kept, size() - 1 the newest.
    const Vec2& operator[](std::size_t i) const { return points_[(oldest_ + i) % points_.size()]; }
    void clear();

private:
    std::size_t capacity_;
    std::vector<Vec2> points_;  // grows to capacity_, then each push overwrites the oldest
    std::size_t oldest_ = 0;
};

class Trails {
public:
    struct Entry {
        BodyId body;
        Trail trail;
    };

    /// Throws std::invalid_argument for 0 points per body or 0 bodies.
    Trails(std::size_t pointsPerBody, std::size_t maxBodies);

    /// One position per traced body, after a step: the first maxBodies of `positions` are traced, each body's
    /// trail kept from the last call; a body missing from them loses its trail.
    void record(const std::vector<std::pair<BodyId, Vec2>>& positions);
    void clear() { entries_.clear(); }
    /// The trails, in the order of the last record's positions.
    const std::vector<Entry>& entries() const { return entries_; }
    std::size_t maxBodies() const { return maxBodies_; }

private:
    std::size_t pointsPerBody_;
    std::size_t maxBodies_;
    std::vector<Entry> entries_;
};

}  // namespace physim
