#include "DynamicTree.hpp"

#include "physim/core/Validate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace physim {
namespace {

// The surface-area heuristic in 2D: the chance that a random line (or a small box swept at random) meets a
// convex region is proportional to its perimeter, so perimeter plays the part of a 3D tree's surface area.
inline double perimeter(const Aabb& b) { return 2.0 * ((b.upper.x() - b.lower.x()) + (b.upper.y() - b.lower.y())); }

// perimeter(Aabb::merged(a, b)) without building the box. When b lies inside a this evaluates exactly the same
// expression as perimeter(a), so "no growth" is an exact 0, which insertion's ties rely on.
inline double mergedPerimeter(const Aabb& a, const Aabb& b) {
    const double w = std::max(a.upper.x(), b.upper.x()) - std::min(a.lower.x(), b.lower.x());
    const double h = std::max(a.upper.y(), b.upper.y()) - std::min(a.lower.y(), b.lower.y());
    return 2.0 * (w + h);
}

bool sameBox(const Aabb& a, const Aabb& b) { return a.lower == b.lower && a.upper == b.upper; }

bool isValidBox(const Aabb& b) {
    return std::isfinite(b.lower.x()) && std::isfinite(b.lower.y()) && std::isfinite(b.upper.x()) &&
           std::isfinite(b.upper.y()) && b.lower.x() <= b.upper.x() && b.lower.y() <= b.upper.y();
}

// A box that cannot corrupt the tree: finite, lower <= upper. Throws before anything is touched; the message
// is built only on failure (this runs for every insertion).
void requireBox(const Aabb& box, const char* call) {
    if (isValidBox(box)) return;
    const std::string name = std::string("DynamicTree::") + call + " box";
    requireFinite(name + " lower", box.lower);
    requireFinite(name + " upper", box.upper);
    std::ostringstream os;
    os.precision(17);
    os << "physim: " << name << " must have lower <= upper, got lower (" << box.lower.x() << ", " << box.lower.y()
       << ") upper (" << box.upper.x() << ", " << box.upper.y() << ")";
    throw std::invalid_argument(os.str());
}

[[noreturn]] void broken(const std::string& invariant, std::int32_t node) {
    throw std::logic_error("DynamicTree::validate: " + invariant + " (node " + std::to_string(node) + ")");
}

// Top-down rebuild: centroids are dropped into this many equal bins along the wider axis of their bounds and
// the best of the kBins - 1 cuts between bins is taken. 16 is the usual quality/speed balance for binned SAH.
constexpr int kBins = 16;

}  // namespace

std::int32_t DynamicTree::allocateNode() {
    std::int32_t id;
    if (freeList_ != kNull) {
        id = freeList_;
        freeList_ = at(id).parent;
    } else {
        if (nodes_.size() >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
            throw std::length_error("physim: DynamicTree is full (2^31 - 1 nodes)");
        nodes_.emplace_back();
        id = static_cast<std::int32_t>(nodes_.size() - 1);
    }
    Node& n = at(id);
    n = Node{};
    n.height = 0;
    return id;
}

void DynamicTree::freeNode(std::int32_t index) {
    Node& n = at(index);
    n = Node{};  // height kFree, no children
    n.parent = freeList_;
    freeList_ = index;
}

void DynamicTree::checkProxy(std::int32_t proxy, const char* call) const {
    const auto fail = [&](const std::string& why) {
        throw std::invalid_argument(std::string("physim: DynamicTree::") + call + ": proxy " +
                                    std::to_string(proxy) + " " + why);
    };
    if (proxy < 0 || static_cast<std::size_t>(proxy) >= nodes_.size())
        fail("is out of range (the tree has " + std::to_string(nodes_.size()) + " node slots)");
    if (at(proxy).height == kFree) fail("is not live (its slot is free: destroyed already?)");
    if (at(proxy).height != 0) fail("is an internal node, not a proxy");
}

std::int32_t DynamicTree::createProxy(const Aabb& fatBox, std::uint32_t userData) {
    requireBox(fatBox, "createProxy");
    const std::int32_t id = allocateNode();
    at(id).box = fatBox;
    at(id).userData = userData;
    try {
        insertLeaf(id);
    } catch (...) {  // out of memory in the search: leave the tree as it was
        freeNode(id);
        throw;
    }
    ++proxyCount_;
    return id;
}

void DynamicTree::destroyProxy(std::int32_t proxy) {
    checkProxy(proxy, "destroyProxy");
    removeLeaf(proxy);
    freeNode(proxy);
    --proxyCount_;
}

void DynamicTree::moveProxy(std::int32_t proxy, const Aabb& fatBox) {
    checkProxy(proxy, "moveProxy");
    requireBox(fatBox, "moveProxy");
    reinsert(proxy, fatBox);
}

// A moving body's new box overlaps its old one: the leaf keeps its place and the boxes above it are refitted. While
// it still overlaps its sibling (a wheel beside its car's other parts, a body in its pile) the place stays good and
// only the boxes change, up to the first that does not (refitOnly); one that has drifted away from its sibling is
// refitted with rotations where they lower the perimeter (refitUpward), which move it towards its new neighbours.
// Either costs a fraction of out and back in, and every query finds the same leaves: only the tree's shape differs.
// A box that jumped (a teleport) goes in anew, at its best place.
void DynamicTree::reinsert(std::int32_t proxy, const Aabb& fatBox) {
    const std::int32_t parent = at(proxy).parent;
    if (parent != kNull && at(proxy).box.overlaps(fatBox)) {
        at(proxy).box = fatBox;
        const Node& p = at(parent);
        const std::int32_t sibling = p.child1 == proxy ? p.child2 : p.child1;
        if (at(sibling).box.overlaps(fatBox)) refitOnly(parent);
        else refitUpward(parent);
        return;
    }
    removeLeaf(proxy);
    at(proxy).box = fatBox;
    insertLeaf(proxy);
}

void DynamicTree::clear() {
    nodes_.clear();
    root_ = kNull;
    freeList_ = kNull;
    proxyCount_ = 0;
}

// Branch and bound for the sibling S that minimises the perimeter the tree gains when the new leaf L is paired
// with it: cost(S) = perimeter(S + L) for the new parent plus, for every ancestor A of S, perimeter(A + L) -
// perimeter(A). Every node is costed when first seen (its box and its ancestors' growth are then known); an
// internal node N is queued to be opened with the bound perimeter(L) + (growth of N and its ancestors), below
// which nothing under N can cost. Best first, as in Bittner, Hapala, Havran 2013, "Fast Insertion-Based
// Optimization of Bounding Volume Hierarchies": the queue is a heap on that bound and the search stops when the
// smallest bound cannot beat the best found, so only nodes whose bound is below the answer are opened (about half
// the node reads of a depth-first search with the same bound).
// Equal costs go to the lower sibling and equal bounds are opened lowest first: identical boxes (a spawner's
// burst) would otherwise all pair with the root and make a chain; this grows the shorter side, as a balanced
// tree would.
std::int32_t DynamicTree::findBestSibling(const Aabb& box) {
    const double leafArea = perimeter(box);
    std::int32_t best = kNull;
    double bestCost = std::numeric_limits<double>::infinity();
    std::int32_t bestHeight = std::numeric_limits<std::int32_t>::max();
    // Can something below a node, costing at least `bound`, beat the best? A tie can if the best is not a leaf.
    const auto mayImprove = [&](double bound) { return bound < bestCost || (bound == bestCost && bestHeight > 0); };
    // Heap order: a strict total order (node ids are distinct), so the search is the same with any heap code.
    const auto later = [](const Candidate& a, const Candidate& b) {
        if (a.bound != b.bound) return a.bound > b.bound;
        if (a.height != b.height) return a.height > b.height;
        return a.node > b.node;
    };
    // Costs node `id` given the growth of its ancestors; returns whether it is internal and worth opening,
    // with its queue entry in `out`.
    const auto visit = [&](std::int32_t id, double ancestorsGrowth, Candidate& out) {
        const Node& n = at(id);
        const double direct = mergedPerimeter(n.box, box);
        const double cost = direct + ancestorsGrowth;
        if (cost < bestCost || (cost == bestCost && n.height < bestHeight)) {
            best = id;
            bestCost = cost;
            bestHeight = n.height;
        }
        if (n.isLeaf()) return false;
        const double inherited = ancestorsGrowth + (direct - perimeter(n.box));
        out = {leafArea + inherited, inherited, n.height, id};
        return mayImprove(out.bound);
    };
    const auto push = [&](const Candidate& c) {
        frontier_.push_back(c);
        std::push_heap(frontier_.begin(), frontier_.end(), later);
    };
    // The node being opened is kept out of the heap while it is the least candidate: the search mostly walks
    // down, and this saves a push and a pop per level without changing the order nodes are opened in.
    frontier_.clear();
    Candidate current{};
    bool haveCurrent = visit(root_, 0.0, current);
    while (haveCurrent) {
        if (!mayImprove(current.bound)) break;  // it is the least bound left
        const Node& n = at(current.node);
        Candidate a{}, b{};
        const bool openA = visit(n.child1, current.inherited, a);
        const bool openB = visit(n.child2, current.inherited, b);
        if (openA && openB && later(a, b)) std::swap(a, b);  // a: the lesser of the two
        if (openA && openB) push(b);
        if (!openA && openB) a = b;
        haveCurrent = openA || openB;
        if (haveCurrent && !frontier_.empty() && later(a, frontier_.front())) {
            push(a);
            haveCurrent = false;
        }
        if (haveCurrent) {
            current = a;
        } else if (!frontier_.empty()) {
            std::pop_heap(frontier_.begin(), frontier_.end(), later);
            current = frontier_.back();
            frontier_.pop_back();
            haveCurrent = true;
        }
    }
    return best;
}

void DynamicTree::replaceChild(std::int32_t parent, std::int32_t from, std::int32_t to) {
    if (parent == kNull) {
        root_ = to;
        return;
    }
    Node& p = at(parent);
    (p.child1 == from ? p.child1 : p.child2) = to;
}

void DynamicTree::insertLeaf(std::int32_t leaf) {
    if (root_ == kNull) {
        root_ = leaf;
        at(leaf).parent = kNull;
        return;
    }
    const Aabb box = at(leaf).box;
    const std::int32_t sibling = findBestSibling(box);
    const std::int32_t oldParent = at(sibling).parent;
    const std::int32_t newParent = allocateNode();  // may grow nodes_: no references held across it
    Node& p = at(newParent);
    p.parent = oldParent;
    p.child1 = sibling;
    p.child2 = leaf;
    p.box = Aabb::merged(at(sibling).box, box);
    p.height = at(sibling).height + 1;
    at(sibling).parent = newParent;
    at(leaf).parent = newParent;
    replaceChild(oldParent, sibling, newParent);
    refitUpward(newParent);  // the new parent first: a rotation there may pair the leaf lower down
}

void DynamicTree::removeLeaf(std::int32_t leaf) {
    if (leaf == root_) {
        root_ = kNull;
        return;
    }
    const std::int32_t parent = at(leaf).parent;
    const std::int32_t grand = at(parent).parent;
    const std::int32_t sibling = at(parent).child1 == leaf ? at(parent).child2 : at(parent).child1;
    at(sibling).parent = grand;
    replaceChild(grand, parent, sibling);
    freeNode(parent);
    at(leaf).parent = kNull;
    // Boxes only shrink and heights only drop: refit until nothing changes. Rotations are left to insertions,
    // which keeps a move cheaper at no cost in the tree's quality.
    for (std::int32_t i = grand; i != kNull; i = at(i).parent) {
        const Aabb before = at(i).box;
        const std::int32_t heightBefore = at(i).height;
        refitNode(i);
        if (sameBox(before, at(i).box) && at(i).height == heightBefore) break;
    }
}

void DynamicTree::refitNode(std::int32_t index) {
    Node& n = at(index);
    n.box = Aabb::merged(at(n.child1).box, at(n.child2).box);
    n.height = 1 + std::max(at(n.child1).height, at(n.child2).height);
}

// The boxes from `index` up, each the union of its children's, until one comes out the same (those above then do).
void DynamicTree::refitOnly(std::int32_t index) {
    for (std::int32_t i = index; i != kNull; i = at(i).parent) {
        const Aabb before = at(i).box;
        refitNode(i);
        if (sameBox(before, at(i).box)) return;
    }
}

// From `index` towards the root: each node's box and height from its children, then a rotation if one lowers the
// perimeter below it. A rotation at a node keeps that node's box (same leaves), so the walk stays valid.
// A node's rotation choices depend on its children's and grandchildren's boxes only. `index` is always treated
// as changed (it is the new leaf's new parent). Once two consecutive nodes come out unchanged (same box, same height, no
// rotation), the boxes and heights above cannot change and the nodes above see the same children and
// grandchildren as before, so the walk stops there. (A node above that rotated on its last visit might find a
// second rotation if visited again; skipping it leaves the tree's area within 0.1% and visits a third of the
// levels.)
void DynamicTree::refitUpward(std::int32_t index) {
    int unchanged = 0;
    for (std::int32_t i = index; i != kNull && unchanged < 2; i = at(i).parent) {
        const Aabb before = at(i).box;
        const std::int32_t heightBefore = at(i).height;
        refitNode(i);
        const bool rotated = rotate(i);
        const bool same = !rotated && i != index && sameBox(before, at(i).box) && at(i).height == heightBefore;
        unchanged = same ? unchanged + 1 : 0;
    }
}

// Tree rotations (Kopta et al. 2012, "Fast, Effective BVH Updates for Animated Scenes"; Box2D v3 uses the
// child-grandchild ones): at node A with children B (D, E) and C (F, G), swap a child with a grandchild on the
// other side (B<->F, B<->G, C<->D, C<->E) or two grandchildren across (D<->F, D<->G), whichever shrinks the summed
// perimeter of B and C the most. A's box is unchanged; only strict gains are applied, so rotations never cycle.
bool DynamicTree::rotate(std::int32_t index) {
    const Node& a = at(index);
    const std::int32_t b = a.child1, c = a.child2;
    const Node& nb = at(b);
    const Node& nc = at(c);
    if (nb.isLeaf() && nc.isLeaf()) return false;

    // Exchanging the places of nodes x and y (a child and a grandchild of A, or two grandchildren).
    struct Swap {
        std::int32_t x, y;
        double gain;
    };
    Swap best{kNull, kNull, 0.0};
    const auto consider = [&](std::int32_t x, std::int32_t y, double gain) {
        if (gain > best.gain) best = {x, y, gain};
    };
    const double areaB = perimeter(nb.box), areaC = perimeter(nc.box);
    if (!nc.isLeaf()) {
        const std::int32_t f = nc.child1, g = nc.child2;
        consider(b, f, areaC - mergedPerimeter(nb.box, at(g).box));
        consider(b, g, areaC - mergedPerimeter(at(f).box, nb.box));
    }
    if (!nb.isLeaf()) {
        const std::int32_t d = nb.child1, e = nb.child2;
        consider(c, d, areaB - mergedPerimeter(nc.box, at(e).box));
        consider(c, e, areaB - mergedPerimeter(at(d).box, nc.box));
        if (!nc.isLeaf()) {
            const std::int32_t f = nc.child1, g = nc.child2;
            consider(d, f, areaB + areaC - mergedPerimeter(at(f).box, at(e).box) - mergedPerimeter(at(d).box, at(g).box));
            consider(d, g, areaB + areaC - mergedPerimeter(at(g).box, at(e).box) - mergedPerimeter(at(f).box, at(d).box));
        }
    }
    if (best.x == kNull) return false;

    const std::int32_t px = at(best.x).parent, py = at(best.y).parent;
    replaceChild(px, best.x, best.y);
    replaceChild(py, best.y, best.x);
    at(best.x).parent = py;
    at(best.y).parent = px;
    // Refit the changed nodes below A, then A's height (its box is the same union).
    if (py != index) refitNode(py);
    if (px != index) refitNode(px);
    refitNode(index);
    return true;
}

double DynamicTree::areaRatio() const {
    if (root_ == kNull || at(root_).isLeaf()) return 0.0;
    const double rootArea = perimeter(at(root_).box);
    if (!(rootArea > 0.0)) return 0.0;
    double total = 0.0;
    for (const Node& n : nodes_)
        if (n.height > 0) total += perimeter(n.box);
    return total / rootArea;
}

void DynamicTree::moveProxies(const std::vector<std::int32_t>& proxies, const std::vector<Aabb>& boxes) {
    if (proxies.size() != boxes.size())
        throw std::invalid_argument("DynamicTree::moveProxies: " + std::to_string(proxies.size()) + " proxies but " +
                                    std::to_string(boxes.size()) + " boxes");
    for (std::size_t i = 0; i < proxies.size(); ++i) {
        checkProxy(proxies[i], "moveProxies");
        requireBox(boxes[i], "moveProxies");
    }
    if (4 * proxies.size() < proxyCount_ || proxies.size() < kRebuildAtLeast) {
        for (std::size_t i = 0; i < proxies.size(); ++i) reinsert(proxies[i], boxes[i]);
        return;
    }
    // A quarter of the tree or more: the boxes in place, then one rebuild, which costs about what a few
    // reinsertions do and leaves a better tree than many.
    for (std::size_t i = 0; i < proxies.size(); ++i) at(proxies[i]).box = boxes[i];
    rebuild();
}

void DynamicTree::rebuild() {
    std::vector<std::int32_t>& leaves = rebuildLeaves_;
    leaves.clear();
    for (std::size_t i = 0; i < nodes_.size(); ++i)
        if (nodes_[i].height == 0) leaves.push_back(static_cast<std::int32_t>(i));
    // Highest index freed first, so the free list hands the internal nodes out from the lowest slot up.
    for (std::size_t i = nodes_.size(); i-- > 0;)
        if (nodes_[i].height > 0) freeNode(static_cast<std::int32_t>(i));
    root_ = kNull;
    if (leaves.empty()) return;

    // Splits leaves[begin, end) (at least two) by the binned surface-area heuristic; returns the cut.
    const auto split = [&](std::size_t begin, std::size_t end) {
        // Centroids times two (lower + upper): the factor does not change the partition.
        const auto centroid = [&](std::int32_t id, int axis) { return at(id).box.lower[axis] + at(id).box.upper[axis]; };
        Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
        for (std::size_t k = begin; k < end; ++k) {
            const Vec2 c(centroid(leaves[k], 0), centroid(leaves[k], 1));
            lo = lo.cwiseMin(c);
            hi = hi.cwiseMax(c);
        }
        const int axis = hi.x() - lo.x() >= hi.y() - lo.y() ? 0 : 1;
        const double extent = hi[axis] - lo[axis];
        const std::size_t half = begin + (end - begin) / 2;
        if (!(extent > 0.0)) return half;  // all centroids coincide: any cut is as good; keep the tree balanced
        const double scale = kBins / extent;
        const auto binOf = [&](std::int32_t id) {
            return std::min(kBins - 1, static_cast<int>((centroid(id, axis) - lo[axis]) * scale));
        };
        std::array<std::size_t, kBins> count{};
        std::array<Aabb, kBins> bounds;
        for (std::size_t k = begin; k < end; ++k) {
            const int bin = binOf(leaves[k]);
            bounds[bin] = count[bin] == 0 ? at(leaves[k]).box : Aabb::merged(bounds[bin], at(leaves[k]).box);
            ++count[bin];
        }
        // Cost of cutting after bin i: leaves times perimeter on each side (the expected work of a query).
        std::array<double, kBins> rightCost{};
        std::size_t rightCount = 0;
        Aabb right;
        for (int i = kBins - 1; i > 0; --i) {
            if (count[i] > 0) right = rightCount == 0 ? bounds[i] : Aabb::merged(right, bounds[i]);
            rightCount += count[i];
            rightCost[i - 1] = rightCount == 0 ? -1.0 : static_cast<double>(rightCount) * perimeter(right);
        }
        int cut = -1;
        double bestCost = std::numeric_limits<double>::infinity();
        std::size_t leftCount = 0;
        Aabb left;
        for (int i = 0; i < kBins - 1; ++i) {
            if (count[i] > 0) left = leftCount == 0 ? bounds[i] : Aabb::merged(left, bounds[i]);
            leftCount += count[i];
            if (leftCount == 0 || rightCost[i] < 0.0) continue;
            const double cost = static_cast<double>(leftCount) * perimeter(left) + rightCost[i];
            if (cost < bestCost) {
                bestCost = cost;
                cut = i;
            }
        }
        if (cut < 0) return half;
        const auto middle = std::partition(leaves.begin() + static_cast<std::ptrdiff_t>(begin),
                                           leaves.begin() + static_cast<std::ptrdiff_t>(end),
                                           [&](std::int32_t id) { return binOf(id) <= cut; });
        return static_cast<std::size_t>(middle - leaves.begin());
    };

    // Top-down with an explicit stack (a lopsided split must not overflow the call stack); boxes and heights
    // bottom-up afterwards, visiting the internal nodes in the reverse of their creation order.
    std::vector<RebuildTask>& tasks = rebuildTasks_;
    tasks.assign(1, {0, leaves.size(), kNull});
    std::vector<std::int32_t>& created = rebuildCreated_;
    created.clear();
    const auto link = [&](std::int32_t child, std::int32_t parent) {
        at(child).parent = parent;
        if (parent == kNull) {
            root_ = child;
        } else {
            Node& p = at(parent);
            (p.child1 == kNull ? p.child1 : p.child2) = child;
        }
    };
    while (!tasks.empty()) {
        const RebuildTask t = tasks.back();
        tasks.pop_back();
        if (t.end - t.begin == 1) {
            link(leaves[t.begin], t.parent);
            continue;
        }
        const std::int32_t node = allocateNode();
        link(node, t.parent);
        created.push_back(node);
        const std::size_t mid = split(t.begin, t.end);
        tasks.push_back({mid, t.end, node});  // child2
        tasks.push_back({t.begin, mid, node});  // child1, taken first
    }
    for (std::size_t k = created.size(); k-- > 0;) refitNode(created[k]);
}

void DynamicTree::validate() const {
    const std::size_t size = nodes_.size();
    std::vector<char> seen(size, 0);
    std::size_t leaves = 0, internals = 0;
    const auto inRange = [&](std::int32_t i) { return i >= 0 && static_cast<std::size_t>(i) < size; };
    if (root_ != kNull) {
        if (!inRange(root_)) broken("the root id is out of range", root_);
        if (at(root_).parent != kNull) broken("the root has a parent", root_);
        std::vector<std::int32_t> stack{root_};
        while (!stack.empty()) {
            const std::int32_t id = stack.back();
            stack.pop_back();
            if (seen[static_cast<std::size_t>(id)]) broken("a node is reached twice (a cycle or a shared child)", id);
            seen[static_cast<std::size_t>(id)] = 1;
            const Node& n = at(id);
            if (n.height == kFree) broken("a free node is linked into the tree", id);
            if (n.isLeaf()) {
                if (n.child2 != kNull) broken("a node has a second child but no first", id);
                if (n.height != 0) broken("a leaf's height is not 0", id);
                if (!isValidBox(n.box)) broken("a leaf's box is NaN, infinite or inverted", id);
                ++leaves;
                continue;
            }
            ++internals;
            for (const std::int32_t child : {n.child1, n.child2}) {
                if (!inRange(child)) broken("a child id is out of range", id);
                if (at(child).parent != id) broken("a child's parent link does not point back", child);
            }
            if (n.child1 == n.child2) broken("both children are the same node", id);
            if (n.height != 1 + std::max(at(n.child1).height, at(n.child2).height))
                broken("an internal node's height is not 1 + its taller child's", id);
            if (!sameBox(n.box, Aabb::merged(at(n.child1).box, at(n.child2).box)))
                broken("an internal node's box is not the union of its children's boxes", id);
            stack.push_back(n.child2);
            stack.push_back(n.child1);
        }
    }
    if (leaves != proxyCount_)
        broken("the tree holds " + std::to_string(leaves) + " leaves but proxyCount() is " +
                   std::to_string(proxyCount_), root_);
    if (leaves > 0 && internals != leaves - 1) broken("internal nodes are not one fewer than leaves", root_);
    for (std::int32_t id = freeList_; id != kNull; id = at(id).parent) {
        if (!inRange(id)) broken("a free-list link is out of range", id);
        if (seen[static_cast<std::size_t>(id)]) broken("the free list meets the tree or itself", id);
        seen[static_cast<std::size_t>(id)] = 1;
        const Node& n = at(id);
        if (n.height != kFree || n.child1 != kNull || n.child2 != kNull)
            broken("a node on the free list is not marked free", id);
    }
    for (std::size_t i = 0; i < size; ++i)
        if (!seen[i]) broken("a node is neither in the tree nor on the free list", static_cast<std::int32_t>(i));
}

}  // namespace physim
