#include "BroadPhase.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace physim {
namespace {

// A box is "large" when its bigger side exceeds this multiple of the mean: walls and ground. Large boxes
// search the rows of small boxes they span instead of making the rows tall for everyone. At most 1/kLarge of
// the bodies can be large (Markov's inequality); scenes have a handful.
constexpr double kLarge = 4.0;

// Rows are made this much taller (relatively) than the tallest small box, so two small boxes that touch are
// never two rows apart through the rounding of their centres.
constexpr double kRowMargin = 1e-6;

// The order kept from the last call is repaired by insertion sort while that takes fewer than this many moves
// per body; beyond (a first call, a scene that was shuffled) a full sort is cheaper.
constexpr std::size_t kRepairMovesPerBody = 8;

constexpr std::int64_t kLargeRow = std::numeric_limits<std::int64_t>::max();
constexpr std::uint32_t kDead = std::numeric_limits<std::uint32_t>::max();  // Proxy::body of a free slot

// What the sweep needs of one body, 48 bytes instead of the ~560 of BodyData, so the sort and the sweep touch
// a table that stays in cache.
struct Proxy {
    double lowerX, lowerY, upperX, upperY;  // world box, m
    std::int64_t row;                       // kLargeRow for a large box
    std::uint32_t body;                     // slot index
    std::uint32_t flags;                    // kMovable, kSeen
};
constexpr std::uint32_t kMovable = 1;  // dynamic or kinematic: may pair with a static body
constexpr std::uint32_t kSeen = 2;     // already taken from last call's order (repeats are dropped)
static_assert(sizeof(Proxy) % sizeof(std::uint32_t) == 0, "a proxy fills whole words");
constexpr std::size_t kProxyWords = sizeof(Proxy) / sizeof(std::uint32_t);

// A table of proxies kept in words of the scratch vector (the world hands the broad phase one
// std::vector<std::uint32_t> to keep between steps). Records go in and out by memcpy, the defined way to
// store one trivially copyable type in the storage of another.
class ProxyTable {
public:
    explicit ProxyTable(std::uint32_t* words) : words_(words) {}
    Proxy operator[](std::size_t i) const {
        Proxy p;
        std::memcpy(&p, words_ + i * kProxyWords, sizeof p);
        return p;
    }
    void set(std::size_t i, const Proxy& p) { std::memcpy(words_ + i * kProxyWords, &p, sizeof p); }

private:
    std::uint32_t* words_;
};

// The smallest power of two >= x (x > 0). Rows of a power-of-two height stay the same from step to step while
// the tallest box changes a little, so last step's order stays nearly sorted; and dividing by one is exact.
double powerOfTwoAtLeast(double x) {
    int exponent;
    const double mantissa = std::frexp(x, &exponent);  // x = mantissa * 2^exponent, mantissa in [0.5, 1)
    return std::ldexp(1.0, mantissa == 0.5 ? exponent - 1 : exponent);
}

bool overlaps(const Proxy& a, const Proxy& b) {
    return a.lowerX <= b.upperX && b.lowerX <= a.upperX && a.lowerY <= b.upperY && b.lowerY <= a.upperY;
}

}  // namespace

// Sort and sweep in rows: a uniform grid built by sorting (docs/collision.md compares it with the alternatives).
//
// Plain sort and sweep on one axis costs O(n log n + m) where m counts the pairs that overlap on that axis;
// for bodies scattered over an area m grows like n^1.5 (each body meets a whole strip of the scene), and a
// stack that shares x makes it n^2 / 2. Here the small boxes are cut into horizontal rows at least as tall as
// the tallest small box and ordered by (row, lower x): a small box can then only meet boxes of its own row and
// of the rows just above and below. Each pair is found once, from the lower row, or within a row from the box
// that starts first in x:
//   - same row: sweep forward while the next box starts before this one ends in x;
//   - the row above: the boxes there that start in [lower x - widest, upper x], found from a pointer that only
//     moves forward as the lower x of this row's boxes grows.
// Large boxes go last in the order; each searches only the rows of small boxes it spans, and meets the other
// large boxes directly.
//
// `scratch` layout, in 32-bit words, for n body slots: [count m][order: m live slots, room for n][n proxies by
// slot][proxies in sorted order, room for n]. The order survives to the next call: bodies move little per step, so it is nearly sorted and insertion sort
// repairs it in O(n) moves. Cost per step: O(n) for a coherent scene at bounded density, O(n log n) after a
// shuffle, plus O(L (r log n + k) + L^2) for L large boxes spanning r rows with k small neighbours each.
void findCandidatePairs(std::vector<BodyData>& bodies, std::vector<BodyPair>& pairs,
                        std::vector<std::uint32_t>& scratch) {
    pairs.clear();
    const std::size_t slots = bodies.size();
    // Keeps last call's order (at the front) while making room for the proxy tables behind it.
    // (At most `slots` entries: the order's room; the body array never shrinks in the World, but stay safe.)
    const std::size_t previous =
        scratch.empty() ? 0 : std::min({std::size_t{scratch[0]}, scratch.size() - 1, slots});
    scratch.resize(1 + slots + 2 * slots * kProxyWords);
    std::uint32_t* const order = scratch.data() + 1;
    ProxyTable bySlot(order + slots);
    ProxyTable inOrder(order + slots + slots * kProxyWords);

    // The one pass over the bodies themselves (large records): refresh their boxes, fill the compact table.
    std::size_t live = 0;
    double sizeSum = 0.0;
    for (std::uint32_t i = 0; i < slots; ++i) {
        BodyData& b = bodies[i];
        if (!b.alive) {
            bySlot.set(i, {0.0, 0.0, 0.0, 0.0, 0, kDead, 0});
            continue;
        }
        b.aabb = computeAabb(b.shape, b.xf);
        const Vec2 size = b.aabb.upper - b.aabb.lower;
        sizeSum += std::max(size.x(), size.y());
        ++live;
        bySlot.set(i, {b.aabb.lower.x(), b.aabb.lower.y(), b.aabb.upper.x(), b.aabb.upper.y(), 0, i,
                       b.movable() ? kMovable : 0u});
    }
    scratch[0] = 0;
    if (live < 2) return;

    const double largeSize = kLarge * sizeSum / static_cast<double>(live);
    const auto isLarge = [&](const Proxy& p) {
        return std::max(p.upperX - p.lowerX, p.upperY - p.lowerY) > largeSize;
    };
    double widest = 0.0, tallest = 0.0;
    for (std::uint32_t i = 0; i < slots; ++i) {
        const Proxy p = bySlot[i];
        if (p.body == kDead || isLarge(p)) continue;
        widest = std::max(widest, p.upperX - p.lowerX);
        tallest = std::max(tallest, p.upperY - p.lowerY);
    }
    widest *= 1.0 + kRowMargin;
    const double perRow = 1.0 / powerOfTwoAtLeast(std::max(tallest * (1.0 + kRowMargin), 1e-300));  // exact
    for (std::uint32_t i = 0; i < slots; ++i) {
        Proxy p = bySlot[i];
        if (p.body == kDead) continue;
        // Two small boxes that overlap have centres at most `tallest` < row height apart: rows differ by <= 1.
        p.row = isLarge(p) ? kLargeRow : static_cast<std::int64_t>(std::floor(0.5 * (p.lowerY + p.upperY) * perRow));
        bySlot.set(i, p);
    }

    // Last call's order, minus slots that died since (and any repeat, so even a scratch written by someone
    // else gives the right answer). With distinct live entries it holds every live body iff the counts match;
    // otherwise (bodies added, first call) it is rebuilt and fully sorted.
    std::size_t kept = 0;
    for (std::size_t k = 0; k < previous; ++k) {
        const std::uint32_t i = order[k];
        if (i >= slots) continue;
        Proxy p = bySlot[i];
        if (p.body == kDead || (p.flags & kSeen)) continue;
        p.flags |= kSeen;  // cleared again as the proxies are copied into sorted order
        bySlot.set(i, p);
        order[kept++] = i;
    }
    const bool rebuilt = kept != live;
    if (rebuilt) {
        std::size_t k = 0;
        for (std::uint32_t i = 0; i < slots; ++i)
            if (bySlot[i].body != kDead) order[k++] = i;
    }
    scratch[0] = static_cast<std::uint32_t>(live);

    const auto before = [](const Proxy& a, const Proxy& b) {
        if (a.row != b.row) return a.row < b.row;
        return a.lowerX < b.lowerX || (a.lowerX == b.lowerX && a.body < b.body);
    };
    const auto fullSort = [&] {
        std::sort(order, order + live, [&](std::uint32_t a, std::uint32_t b) { return before(bySlot[a], bySlot[b]); });
    };
    // The proxies in last call's order: the one random-access pass over the table. Insertion sort then repairs
    // the order on these records, reading memory front to back, and so does the sweep.
    const auto gather = [&] {
        for (std::size_t k = 0; k < live; ++k) {
            Proxy p = bySlot[order[k]];
            p.flags &= ~kSeen;
            inOrder.set(k, p);
        }
    };
    if (rebuilt) fullSort();
    gather();
    if (!rebuilt) {
        std::size_t moves = 0;
        const std::size_t budget = kRepairMovesPerBody * live;
        bool sorted = true;
        for (std::size_t k = 1; k < live && sorted; ++k) {
            const Proxy v = inOrder[k];
            std::size_t j = k;
            for (; j > 0; --j) {
                const Proxy previousBox = inOrder[j - 1];
                if (!before(v, previousBox)) break;
                inOrder.set(j, previousBox);
                if (++moves > budget) {
                    sorted = false;  // too shuffled: a full sort is cheaper (the records stay a permutation)
                    --j;
                    break;
                }
            }
            inOrder.set(j, v);
        }
        for (std::size_t k = 0; k < live; ++k) order[k] = inOrder[k].body;
        if (!sorted) {
            fullSort();
            gather();
        }
    }
    std::size_t smallCount = 0;
    while (smallCount < live && inOrder[smallCount].row != kLargeRow) ++smallCount;

    const auto consider = [&](const Proxy& a, const Proxy& b) {
        if (((a.flags | b.flags) & kMovable) && overlaps(a, b))
            pairs.emplace_back(std::min(a.body, b.body), std::max(a.body, b.body));
    };
    std::size_t rowStart = 0;
    while (rowStart < smallCount) {
        const std::int64_t r = inOrder[rowStart].row;
        std::size_t rowEnd = rowStart + 1;
        while (rowEnd < smallCount && inOrder[rowEnd].row == r) ++rowEnd;
        std::size_t above = rowEnd;  // first box of the row above not yet left behind in x
        for (std::size_t k = rowStart; k < rowEnd; ++k) {
            const Proxy box = inOrder[k];
            for (std::size_t j = k + 1; j < rowEnd; ++j) {
                const Proxy other = inOrder[j];
                if (other.lowerX > box.upperX) break;
                consider(box, other);
            }
            while (above < smallCount && inOrder[above].row == r + 1 && inOrder[above].lowerX < box.lowerX - widest)
                ++above;
            for (std::size_t j = above; j < smallCount; ++j) {
                const Proxy other = inOrder[j];
                if (other.row != r + 1 || other.lowerX > box.upperX) break;
                consider(box, other);
            }
        }
        rowStart = rowEnd;
    }

    // Large boxes against the small ones: a small box that meets a large one has its centre within `tallest`
    // of it in y, so only those rows are searched, and in each only the boxes starting in
    // [lower x - widest, upper x]. The first box of each such stretch is found by binary search.
    const auto firstAtOrAfter = [&](std::int64_t row, double x) {  // in the sorted small boxes
        std::size_t lo = 0, hi = smallCount;
        while (lo < hi) {
            const std::size_t mid = lo + (hi - lo) / 2;
            const Proxy p = inOrder[mid];
            if (p.row < row || (p.row == row && p.lowerX < x)) lo = mid + 1; else hi = mid;
        }
        return lo;
    };
    for (std::size_t k = smallCount; k < live; ++k) {
        const Proxy big = inOrder[k];
        const double fromX = big.lowerX - widest;
        const std::int64_t lastRow = static_cast<std::int64_t>(std::floor((big.upperY + tallest) * perRow));
        std::size_t j = firstAtOrAfter(static_cast<std::int64_t>(std::floor((big.lowerY - tallest) * perRow)), fromX);
        while (j < smallCount && inOrder[j].row <= lastRow) {
            const std::int64_t r = inOrder[j].row;
            for (; j < smallCount; ++j) {
                const Proxy other = inOrder[j];
                if (other.row != r || other.lowerX > big.upperX) break;
                consider(big, other);
            }
            j = firstAtOrAfter(r + 1, fromX);
        }
        // Large against large: few of them, each pair once.
        for (std::size_t m = k + 1; m < live; ++m) consider(big, inOrder[m]);
    }
    std::sort(pairs.begin(), pairs.end());  // creation order, independent of positions
}

}  // namespace physim
