#pragma once
// Barnes-Hut quadtree for gravitation (J. Barnes and P. Hut, Nature 324, 1986): a square cell of width s whose
// centre of mass is at distance r from a body, with the body outside it, acts on the body as its total mass at
// that centre when s < theta r; otherwise its four children (or, in a leaf, its bodies one by one) do. Cost per
// body O(log n) for a fixed theta.
//
// Bodies are evaluated in groups (J. Barnes, J. Comput. Phys. 87, 1990): the few neighbouring bodies of a small
// cell share one list of what pulls them, built with the opening test applied to the group's bounding box, so a
// cell is taken whole only where the test passes for every body of the group (never a cell the one-body test
// would open: the accuracy bound stands). Each body then sums its list in order, four bodies per lane set
// (Wide.hpp). Internal.

#include "../Wide.hpp"

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
    /// Builds the tree over the points (m) with their masses (kg), which it copies.
    void build(const std::vector<Vec2>& positions, const std::vector<double>& masses);
    /// Groups of neighbouring points; together they hold each point once.
    std::size_t groupCount() const { return groups_.size(); }
    /// Group g's points: indices into the positions, order()[groupBegin(g)] to order()[groupEnd(g) - 1].
    std::uint32_t groupBegin(std::size_t g) const { return nodes_[groups_[g]].begin; }
    std::uint32_t groupEnd(std::size_t g) const { return nodes_[groups_[g]].end; }
    const std::vector<std::uint32_t>& order() const { return order_; }
    /// Accelerations (m/s^2) of group g's points from all the others: out[j] for the point order()[groupBegin(g) + j].
    /// Each point's sum is its own, in an order fixed by the tree: the same bits whichever thread runs which group
    /// and whichever build of the lanes (`code`) runs.
    void groupAccelerations(std::size_t g, double G, double eps2, double theta, Vec2* out,
                            WideCode code = WideCode::Best) const;
    /// Every point's acceleration, out[i] for point i (one thread).
    void accelerations(double G, double eps2, double theta, std::vector<Vec2>& out) const;
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
    struct Point {
        double x, y, m;      // m, m, kg
        std::uint32_t index;  // in the positions
    };
    void split(std::uint32_t node, int depth);
    void collectGroups(std::uint32_t node);

    std::vector<Point> points_;  // the points, moved into their cells as the tree splits (contiguous, no lookups)
    std::vector<Point> spare_;   // a split's scratch
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> order_;  // point indices, grouped by leaf
    std::vector<double> x_, y_, m_;     // the points' coordinates (m) and masses (kg) in order_'s order
    std::vector<std::uint32_t> groups_;  // nodes, in depth-first order
};

}  // namespace physim
