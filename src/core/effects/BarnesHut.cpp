#include "BarnesHut.hpp"

#include <algorithm>
#include <array>

namespace physim {
namespace {

constexpr std::uint32_t kLeafSize = 8;    // points a leaf holds before it splits
constexpr std::uint32_t kGroupSize = 64;  // points a group holds at most (a leaf of coincident points excepted)
constexpr int kMaxDepth = 48;             // coincident points stop splitting here (2^-48 of the root's width)
constexpr std::size_t kChunk = 256;       // pulls a group's list holds before its points sum them

// What pulls a group: cells (their centre of mass and G times their mass) and single points, in the order
// the traversal meets them; summed and emptied whenever full.
struct PullList {
    double x[kChunk], y[kChunk], gm[kChunk];  // m, m, m^3/s^2
    std::size_t size = 0;
};

// Adds the list's pulls to the group's points, four at a time: point j's acceleration is out[j]. Lane by lane
// pull()'s formula, in its order of operations; a pull with no direction (from the point itself, or from one on
// top of it) adds nothing.
template <bool Vector>
[[gnu::always_inline]] inline void sumPulls(const PullList& list, const double* x, const double* y,
                                            std::size_t count, double eps2, Vec2* out) {
    const Wide zero{}, e = splat(eps2);
    for (std::size_t j = 0; j < count; j += kLanes) {
        Wide px, py, ax, ay;
        for (int l = 0; l < kLanes; ++l) {
            const std::size_t k = std::min(j + l, count - 1);  // the last point again in the spare lanes
            px[l] = x[k];
            py[l] = y[k];
            ax[l] = out[k].x();
            ay[l] = out[k].y();
        }
        for (std::size_t i = 0; i < list.size; ++i) {
            const Wide dx = splat(list.x[i]) - px, dy = splat(list.y[i]) - py;
            const Wide r2 = dx * dx + dy * dy + e;
            const Wide f = splat(list.gm[i]) / (r2 * sqrtLanes<Vector>(r2));
            const WideMask pulls = (r2 > zero) & ((dx != zero) | (dy != zero));
            ax = ax + (pulls ? f * dx : zero);
            ay = ay + (pulls ? f * dy : zero);
        }
        for (int l = 0; l < kLanes && j + l < count; ++l) out[j + l] = Vec2(ax[l], ay[l]);
    }
}

}  // namespace

Vec2 directAcceleration(const std::vector<Vec2>& positions, const std::vector<double>& masses, std::size_t self,
                        double G, double eps2) {
    Vec2 a = Vec2::Zero();
    for (std::size_t j = 0; j < positions.size(); ++j)
        if (j != self) a += pull(positions[self], positions[j], masses[j], G, eps2);
    return a;
}

void BarnesHutTree::build(const std::vector<Vec2>& positions, const std::vector<double>& masses) {
    const std::size_t n = positions.size();
    nodes_.clear();
    groups_.clear();
    points_.resize(n);
    spare_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        points_[i] = {positions[i].x(), positions[i].y(), masses[i], static_cast<std::uint32_t>(i)};
    order_.resize(n);
    x_.resize(n);
    y_.resize(n);
    m_.resize(n);
    if (n == 0) return;
    Vec2 lo = positions[0], hi = positions[0];
    for (const Vec2& p : positions) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    Node root;
    root.center = 0.5 * (lo + hi);
    root.half = 0.5 * (hi - lo).maxCoeff() + 1e-12;  // every point inside, even when all coincide
    root.begin = 0;
    root.end = static_cast<std::uint32_t>(n);
    nodes_.push_back(root);
    split(0, 0);
    for (std::size_t k = 0; k < n; ++k) {
        order_[k] = points_[k].index;
        x_[k] = points_[k].x;
        y_[k] = points_[k].y;
        m_[k] = points_[k].m;
    }
    collectGroups(0);
}

void BarnesHutTree::split(std::uint32_t index, int depth) {
    const Node node = nodes_[index];  // a copy: the pushes below may move the array
    if (node.end - node.begin <= kLeafSize || depth >= kMaxDepth) {
        double m = 0.0;
        Vec2 weighted = Vec2::Zero();
        for (std::uint32_t i = node.begin; i < node.end; ++i) {
            const Point& p = points_[i];
            m += p.m;
            weighted += p.m * Vec2(p.x, p.y);
        }
        nodes_[index].mass = m;
        nodes_[index].com = m > 0.0 ? Vec2(weighted / m) : node.center;
        return;
    }
    // Quadrants: 0 lower left, 1 lower right, 2 upper left, 3 upper right. A counting sort, stable and without a
    // branch on the points (a partition's branches miss about half the time).
    const double cx = node.center.x(), cy = node.center.y();
    auto quadrant = [cx, cy](const Point& p) { return (p.y < cy ? 0u : 2u) + (p.x < cx ? 0u : 1u); };
    std::uint32_t bounds[5] = {0, 0, 0, 0, 0};
    for (std::uint32_t i = node.begin; i < node.end; ++i) ++bounds[quadrant(points_[i]) + 1];
    bounds[0] = node.begin;
    for (int c = 0; c < 4; ++c) bounds[c + 1] += bounds[c];
    std::uint32_t next[4] = {bounds[0], bounds[1], bounds[2], bounds[3]};
    for (std::uint32_t i = node.begin; i < node.end; ++i) spare_[next[quadrant(points_[i])]++] = points_[i];
    std::copy(spare_.begin() + node.begin, spare_.begin() + node.end, points_.begin() + node.begin);
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

// The largest cells of at most kGroupSize points (or leaves), in depth-first order: neighbours in space.
void BarnesHutTree::collectGroups(std::uint32_t index) {
    const Node& node = nodes_[index];
    if (node.end == node.begin) return;
    if (node.firstChild < 0 || node.end - node.begin <= kGroupSize) {
        groups_.push_back(index);
        return;
    }
    for (std::uint32_t c = 0; c < 4; ++c) collectGroups(static_cast<std::uint32_t>(node.firstChild) + c);
}

namespace {

// groupAccelerations for one build of the lanes. The opening test is the one-body test at the group's box: a
// cell is taken whole when the box lies outside its square (c - hi > h or lo - c > h on an axis, so every point
// does: |p - c| > h) and its width squared is below theta^2 times the squared distance from its centre of mass
// to the box (no farther than to any point). Each step rounds monotonically, so a cell the group takes passes the
// one-body test, as computed, for each of its points.
template <bool Vector, class Node>
[[gnu::always_inline]] inline void groupLoop(const std::vector<Node>& nodes, const double* x, const double* y,
                                             const double* m, std::uint32_t begin, std::uint32_t end, double G,
                                             double eps2, double theta, Vec2* out) {
    const std::size_t count = end - begin;
    std::fill(out, out + count, Vec2::Zero());
    double loX = x[begin], hiX = x[begin], loY = y[begin], hiY = y[begin];
    for (std::uint32_t k = begin; k < end; ++k) {
        loX = std::min(loX, x[k]);
        hiX = std::max(hiX, x[k]);
        loY = std::min(loY, y[k]);
        hiY = std::max(hiY, y[k]);
    }
    const double theta2 = theta * theta;
    PullList list;
    auto add = [&](double px, double py, double gm) {
        if (list.size == kChunk) {
            sumPulls<Vector>(list, x + begin, y + begin, count, eps2, out);
            list.size = 0;
        }
        list.x[list.size] = px;
        list.y[list.size] = py;
        list.gm[list.size] = gm;
        ++list.size;
    };
    std::array<std::uint32_t, 4 * kMaxDepth + 4> stack;  // each level leaves at most three siblings waiting
    std::size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes[stack[--top]];
        if (node.mass == 0.0) continue;
        const double h = node.half, cx = node.center.x(), cy = node.center.y();
        const bool outside = cx - hiX > h || loX - cx > h || cy - hiY > h || loY - cy > h;
        if (outside) {
            const double gx = node.com.x(), gy = node.com.y();
            const double dx = std::max(0.0, std::max(loX - gx, gx - hiX));
            const double dy = std::max(0.0, std::max(loY - gy, gy - hiY));
            const double width = 2.0 * h;
            if (width * width < theta2 * (dx * dx + dy * dy)) {
                add(gx, gy, G * node.mass);
                continue;
            }
        }
        if (node.firstChild < 0) {
            for (std::uint32_t i = node.begin; i < node.end; ++i) add(x[i], y[i], G * m[i]);
            continue;
        }
        for (int c = 3; c >= 0; --c) stack[top++] = static_cast<std::uint32_t>(node.firstChild + c);
    }
    sumPulls<Vector>(list, x + begin, y + begin, count, eps2, out);
}

template <class Node>
void groupBaseline(const std::vector<Node>& nodes, const double* x, const double* y, const double* m,
                   std::uint32_t begin, std::uint32_t end, double G, double eps2, double theta, Vec2* out) {
    groupLoop<false>(nodes, x, y, m, begin, end, G, eps2, theta, out);
}
#if PHYSIM_HAS_AVX2_CODE
template <class Node>
PHYSIM_AVX2_CODE void groupAvx2(const std::vector<Node>& nodes, const double* x, const double* y, const double* m,
                                std::uint32_t begin, std::uint32_t end, double G, double eps2, double theta,
                                Vec2* out) {
    groupLoop<true>(nodes, x, y, m, begin, end, G, eps2, theta, out);
}
template <class Node>
PHYSIM_AVX512_CODE void groupAvx512(const std::vector<Node>& nodes, const double* x, const double* y,
                                    const double* m, std::uint32_t begin, std::uint32_t end, double G, double eps2,
                                    double theta, Vec2* out) {
    groupLoop<true>(nodes, x, y, m, begin, end, G, eps2, theta, out);
}
#endif

}  // namespace

void BarnesHutTree::groupAccelerations(std::size_t g, double G, double eps2, double theta, Vec2* out,
                                       WideCode code) const {
    const std::uint32_t begin = groupBegin(g), end = groupEnd(g);
    switch (pickWideCode(code)) {
#if PHYSIM_HAS_AVX2_CODE
    case WideCode::Avx512:
        return groupAvx512(nodes_, x_.data(), y_.data(), m_.data(), begin, end, G, eps2, theta, out);
    case WideCode::Avx2: return groupAvx2(nodes_, x_.data(), y_.data(), m_.data(), begin, end, G, eps2, theta, out);
#endif
    default: return groupBaseline(nodes_, x_.data(), y_.data(), m_.data(), begin, end, G, eps2, theta, out);
    }
}

void BarnesHutTree::accelerations(double G, double eps2, double theta, std::vector<Vec2>& out) const {
    std::vector<Vec2> sorted(order_.size());
    for (std::size_t g = 0; g < groups_.size(); ++g)
        groupAccelerations(g, G, eps2, theta, sorted.data() + groupBegin(g));
    out.assign(order_.size(), Vec2::Zero());
    for (std::size_t k = 0; k < order_.size(); ++k) out[order_[k]] = sorted[k];
}

}  // namespace physim
