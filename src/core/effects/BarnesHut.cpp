#include "BarnesHut.hpp"

#include <algorithm>
#include <array>
#include <numeric>

namespace physim {
namespace {

constexpr std::uint32_t kLeafSize = 8;  // points a leaf holds before it splits
constexpr int kMaxDepth = 48;           // coincident points stop splitting here (2^-48 of the root's width)

}  // namespace

Vec2 directAcceleration(const std::vector<Vec2>& positions, const std::vector<double>& masses, std::size_t self,
                        double G, double eps2) {
    Vec2 a = Vec2::Zero();
    for (std::size_t j = 0; j < positions.size(); ++j)
        if (j != self) a += pull(positions[self], positions[j], masses[j], G, eps2);
    return a;
}

void BarnesHutTree::build(const std::vector<Vec2>& positions, const std::vector<double>& masses) {
    positions_ = &positions;
    masses_ = &masses;
    nodes_.clear();
    order_.resize(positions.size());
    std::iota(order_.begin(), order_.end(), 0u);
    if (positions.empty()) return;
    Vec2 lo = positions[0], hi = positions[0];
    for (const Vec2& p : positions) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    Node root;
    root.center = 0.5 * (lo + hi);
    root.half = 0.5 * (hi - lo).maxCoeff() + 1e-12;  // every point inside, even when all coincide
    root.begin = 0;
    root.end = static_cast<std::uint32_t>(positions.size());
    nodes_.push_back(root);
    split(0, 0);
}

void BarnesHutTree::split(std::uint32_t index, int depth) {
    const std::vector<Vec2>& pos = *positions_;
    const std::vector<double>& mass = *masses_;
    const Node node = nodes_[index];  // a copy: the pushes below may move the array
    if (node.end - node.begin <= kLeafSize || depth >= kMaxDepth) {
        double m = 0.0;
        Vec2 weighted = Vec2::Zero();
        for (std::uint32_t i = node.begin; i < node.end; ++i) {
            m += mass[order_[i]];
            weighted += mass[order_[i]] * pos[order_[i]];
        }
        nodes_[index].mass = m;
        nodes_[index].com = m > 0.0 ? Vec2(weighted / m) : node.center;
        return;
    }
    // Quadrants: 0 lower left, 1 lower right, 2 upper left, 3 upper right.
    auto* first = order_.data() + node.begin;
    auto* last = order_.data() + node.end;
    auto* upper = std::partition(first, last, [&](std::uint32_t i) { return pos[i].y() < node.center.y(); });
    auto* lowerRight = std::partition(first, upper, [&](std::uint32_t i) { return pos[i].x() < node.center.x(); });
    auto* upperRight = std::partition(upper, last, [&](std::uint32_t i) { return pos[i].x() < node.center.x(); });
    const std::uint32_t bounds[5] = {node.begin, static_cast<std::uint32_t>(lowerRight - order_.data()),
                                     static_cast<std::uint32_t>(upper - order_.data()),
                                     static_cast<std::uint32_t>(upperRight - order_.data()), node.end};
    const auto child0 = static_cast<std::uint32_t>(nodes_.size());
    nodes_[index].firstChild = static_cast<std::int32_t>(child0);
    const double q = 0.5 * node.half;
    for (int c = 0; c < 4; ++c) {
        Node child;
        child.center = node.center + Vec2((c & 1) ? q : -q, (c & 2) ? q : -q);
        child.half = q;
        child.begin = bounds[c];
        child.end = bounds[c + 1];
        nodes_.push_back(child);
    }
    double m = 0.0;
    Vec2 weighted = Vec2::Zero();
    for (std::uint32_t c = 0; c < 4; ++c) {
        split(child0 + c, depth + 1);
        m += nodes_[child0 + c].mass;
        weighted += nodes_[child0 + c].mass * nodes_[child0 + c].com;
    }
    nodes_[index].mass = m;
    nodes_[index].com = m > 0.0 ? Vec2(weighted / m) : node.center;
}

Vec2 BarnesHutTree::acceleration(std::size_t self, double G, double eps2, double theta) const {
    Vec2 a = Vec2::Zero();
    if (nodes_.empty()) return a;
    const std::vector<Vec2>& pos = *positions_;
    const std::vector<double>& mass = *masses_;
    const Vec2 p = pos[self];
    const double theta2 = theta * theta;
    std::array<std::uint32_t, 4 * kMaxDepth + 4> stack;  // each level leaves at most three siblings waiting
    std::size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (node.mass == 0.0) continue;
        const bool outside = std::abs(p.x() - node.center.x()) > node.half ||
                             std::abs(p.y() - node.center.y()) > node.half;
        const double width = 2.0 * node.half;
        if (outside && width * width < theta2 * (node.com - p).squaredNorm()) {
            a += pull(p, node.com, node.mass, G, eps2);
            continue;
        }
        if (node.firstChild < 0) {
            for (std::uint32_t i = node.begin; i < node.end; ++i)
                if (order_[i] != self) a += pull(p, pos[order_[i]], mass[order_[i]], G, eps2);
            continue;
        }
        for (int c = 3; c >= 0; --c) stack[top++] = static_cast<std::uint32_t>(node.firstChild + c);
    }
    return a;
}

}  // namespace physim
