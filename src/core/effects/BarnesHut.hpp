#pragma once
// Barnes-Hut quadtree for gravitation (J. Barnes and P. Hut, Nature 324, 1986): a square cell of width s whose
// centre of mass is at distance r from a body, with the body outside it, acts on the body as its total mass at
// that centre when s < theta r; otherwise its four children (or, in a leaf, its bodies one by one) do. Cost per
// body O(log n) for a fixed theta. Internal.

#include "physim/core/Math.hpp"

#include <cstdint>
#include <vector>

namespace physim {

/// Softened inverse-square pull of mass m (kg) at `source` on a point at p: G m d / (|d|^2 + eps2)^(3/2),
/// d = source - p (m/s^2).
inline Vec2 pull(const Vec2& p, const Vec2& source, double m, double G, double eps2) {
    const Vec2 d = source - p;
    const double r2 = d.squaredNorm() + eps2;
    if (!(r2 > 0.0)) return Vec2::Zero();  // coincident, unsoftened: no direction to pull in
    return (G * m / (r2 * std::sqrt(r2))) * d;
}

/// The exact sum over every other point: the reference Barnes-Hut approximates.
Vec2 directAcceleration(const std::vector<Vec2>& positions, const std::vector<double>& masses, std::size_t self,
                        double G, double eps2);

class BarnesHutTree {
public:
    /// Builds the tree over the points (m) with their masses (kg); both stay the caller's and must outlive it.
    void build(const std::vector<Vec2>& positions, const std::vector<double>& masses);
    /// Acceleration (m/s^2) of point `self` from all the others.
    Vec2 acceleration(std::size_t self, double G, double eps2, double theta) const;
    std::size_t nodeCount() const { return nodes_.size(); }

private:
    struct Node {
        Vec2 center = Vec2::Zero();  // of the square, m
        double half = 0.0;           // half its width, m
        double mass = 0.0;           // kg
        Vec2 com = Vec2::Zero();     // centre of mass, m
        std::int32_t firstChild = -1;  // four consecutive children; -1: a leaf
        std::uint32_t begin = 0, end = 0;  // its points: order_[begin, end)
    };
    void split(std::uint32_t node, int depth);

    const std::vector<Vec2>* positions_ = nullptr;
    const std::vector<double>* masses_ = nullptr;
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> order_;  // point indices, grouped by leaf
};

}  // namespace physim
