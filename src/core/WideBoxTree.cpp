// WideBoxTree's build: top-down, each node's leaves split in two by the binned surface-area heuristic (in 2D the
// perimeter stands for the area: a random box meets a box in proportion to it), then each half in two again. The
// bins' boxes give the halves' boxes, so each level reads its leaves twice: once to bin, once to partition.

#include "WideBoxTree.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace physim {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// The nearest floats outside [lower, upper], so the float box holds the double one.
float down(double v) {
    const float f = static_cast<float>(v);
    return static_cast<double>(f) > v ? std::nextafter(f, -kInf) : f;
}
float up(double v) {
    const float f = static_cast<float>(v);
    return static_cast<double>(f) < v ? std::nextafter(f, kInf) : f;
}

// Below this depth every split halves, which bounds the height (under 64, query's stack) whatever the boxes: at most
// 24 levels of heuristic splits, then four times fewer leaves per level.
constexpr int kHalvingDepth = 24;
constexpr std::size_t kBins = 16;

using Box = WideBoxTree::Box;

const Box kEmpty = {kInf, kInf, kInf, kInf};

void grow(Box& a, const Box& b) { a = a < b ? a : b; }

float perimeter(const Box& b) { return -(b[2] + b[0]) - (b[3] + b[1]); }

}  // namespace

void WideBoxTree::clear() {
    leaves_.clear();
    nodes_.clear();
    leafData_.clear();
    height_ = 0;
}

void WideBoxTree::addLeaf(const Aabb& box, std::uint32_t userData) {
    const Box b = {down(box.lower.x()), down(box.lower.y()), -up(box.upper.x()), -up(box.upper.y())};
    // Centres from the doubles (halves first, so they never overflow), held within the floats' range.
    const auto centre = [](double lower, double upper) {
        const double limit = std::numeric_limits<float>::max();
        return static_cast<float>(std::clamp(0.5 * lower + 0.5 * upper, -limit, limit));
    };
    leaves_.push_back({b, centre(box.lower.x(), box.upper.x()), centre(box.lower.y(), box.upper.y()), userData});
}

void WideBoxTree::build() {
    nodes_.clear();
    leafData_.clear();
    height_ = 0;
    if (leaves_.empty()) return;
    nodes_.reserve(leaves_.size() / 2 + 1);
    leafData_.reserve(leaves_.size());
    bin_.resize(leaves_.size());
    Range all{0, leaves_.size(), kEmpty};
    for (const Leaf& leaf : leaves_) grow(all.box, leaf.box);
    buildNode(all, 1);
}

// Splits `range` (two leaves or more) into `left` and `right`, both non-empty, with their boxes. Sixteen bins along
// the axis where the centres spread most; leaves whose centres coincide, or any below kHalvingDepth, are halved by
// position along that axis.
std::size_t WideBoxTree::split(const Range& range, int depth, Range& left, Range& right) {
    const auto first = leaves_.begin() + static_cast<std::ptrdiff_t>(range.begin);
    const auto last = leaves_.begin() + static_cast<std::ptrdiff_t>(range.end);
    float lowX = kInf, lowY = kInf, highX = -kInf, highY = -kInf;
    for (auto it = first; it != last; ++it) {
        lowX = std::min(lowX, it->centreX), highX = std::max(highX, it->centreX);
        lowY = std::min(lowY, it->centreY), highY = std::max(highY, it->centreY);
    }
    const bool alongX = highX - lowX >= highY - lowY;
    const float low = alongX ? lowX : lowY, width = alongX ? highX - lowX : highY - lowY;
    const auto centreOf = [alongX](const Leaf& leaf) { return alongX ? leaf.centreX : leaf.centreY; };
    std::size_t mid = range.begin;
    const float scale = static_cast<float>(kBins) / width;
    if (width > 0.0f && std::isfinite(scale) && scale > 0.0f && depth < kHalvingDepth) {
        std::array<Box, kBins> boxes;
        boxes.fill(kEmpty);
        std::array<std::size_t, kBins> counts{};
        for (std::size_t i = range.begin; i < range.end; ++i) {
            const auto b = std::min(kBins - 1, static_cast<std::size_t>((centreOf(leaves_[i]) - low) * scale));
            bin_[i] = static_cast<std::uint8_t>(b);
            grow(boxes[b], leaves_[i].box);
            ++counts[b];
        }
        // Splitting after bin k costs each side's perimeter times its count; the least wins.
        std::array<Box, kBins> rightBox;
        std::array<float, kBins> rightCost{};
        Box r = kEmpty;
        std::size_t rightCount = 0;
        for (std::size_t k = kBins - 1; k > 0; --k) {
            grow(r, boxes[k]);
            rightCount += counts[k];
            rightBox[k] = r;
            rightCost[k] = rightCount ? perimeter(r) * static_cast<float>(rightCount) : 0.0f;
        }
        Box l = kEmpty;
        std::size_t leftCount = 0, bestBin = kBins;
        float best = kInf;
        for (std::size_t k = 0; k + 1 < kBins; ++k) {
            grow(l, boxes[k]);
            leftCount += counts[k];
            if (leftCount == 0 || leftCount == range.end - range.begin) continue;
            const float cost = perimeter(l) * static_cast<float>(leftCount) + rightCost[k + 1];
            if (cost < best) best = cost, bestBin = k, left.box = l, right.box = rightBox[k + 1];
        }
        if (bestBin < kBins) {
            // Partition by the stored bins, leaves and bins swapped together.
            std::size_t i = range.begin, j = range.end;
            while (true) {
                while (i < j && bin_[i] <= bestBin) ++i;
                while (i < j && bin_[j - 1] > bestBin) --j;
                if (i >= j) break;
                std::swap(leaves_[i], leaves_[j - 1]);
                std::swap(bin_[i], bin_[j - 1]);
            }
            mid = i;
        }
    }
    if (mid == range.begin || mid == range.end) {
        mid = range.begin + (range.end - range.begin) / 2;
        std::nth_element(first, leaves_.begin() + static_cast<std::ptrdiff_t>(mid), last,
                         [&](const Leaf& a, const Leaf& b) { return centreOf(a) < centreOf(b); });
        left.box = right.box = kEmpty;
        for (std::size_t i = range.begin; i < mid; ++i) grow(left.box, leaves_[i].box);
        for (std::size_t i = mid; i < range.end; ++i) grow(right.box, leaves_[i].box);
    }
    left.begin = range.begin, left.end = mid;
    right.begin = mid, right.end = range.end;
    return mid;
}

std::int32_t WideBoxTree::buildNode(const Range& range, int depth) {
    height_ = std::max(height_, depth);
    const auto index = static_cast<std::int32_t>(nodes_.size());
    nodes_.emplace_back();
    // Up to four children: the leaves themselves when few, else two halves each halved again where it can be.
    std::array<Range, 4> part;
    int count = 0;
    if (range.end - range.begin <= 4) {
        for (std::size_t i = range.begin; i < range.end; ++i)
            part[static_cast<std::size_t>(count++)] = {i, i + 1, leaves_[i].box};
    } else {
        Range halves[2];
        split(range, depth, halves[0], halves[1]);
        for (const Range& half : halves) {
            if (half.end - half.begin == 1) {
                part[static_cast<std::size_t>(count++)] = half;
            } else {
                split(half, depth, part[static_cast<std::size_t>(count)], part[static_cast<std::size_t>(count) + 1]);
                count += 2;
            }
        }
    }
    std::int32_t child[4] = {0, 0, 0, 0};
    for (int i = 0; i < count; ++i) {
        const Range& p = part[static_cast<std::size_t>(i)];
        if (p.end - p.begin == 1) {
            child[i] = ~static_cast<std::int32_t>(leafData_.size());
            leafData_.push_back(leaves_[p.begin].userData);
        } else {
            child[i] = buildNode(p, depth + 1);
        }
    }
    Node& n = nodes_[static_cast<std::size_t>(index)];  // after the recursion, which grows nodes_
    for (int i = 0; i < 4; ++i) {
        const Box b = i < count ? part[static_cast<std::size_t>(i)].box : kEmpty;
        n.child[i] = child[i];
        n.lowerX[i] = b[0], n.lowerY[i] = b[1], n.upperX[i] = -b[2], n.upperY[i] = -b[3];
    }
    return index;
}

}  // namespace physim
