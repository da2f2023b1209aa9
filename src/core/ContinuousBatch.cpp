// Continuous batches: filling, validation at the API boundary, and the CPU solve over the shared kernel.

#include "ContinuousCpu.hpp"

#include "KernelBridge.hpp"
#include "shapes/ShapeKinds.hpp"

#include "physim/core/Validate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace physim {

static_assert(static_cast<int>(ToiState::Separated) == kernel::kSeparated && static_cast<int>(ToiState::Hit) == kernel::kHit &&
                  static_cast<int>(ToiState::Touching) == kernel::kTouching &&
                  static_cast<int>(ToiState::Failed) == kernel::kFailed,
              "the batch's state codes are ToiState's");

namespace {

[[noreturn]] void reject(const std::string& what) {
    throw std::invalid_argument("physim: continuous batch: " + what);
}

std::string at(const char* array, std::size_t i) { return std::string(array) + "[" + std::to_string(i) + "]"; }

// Every array of a group has the size of the first one.
template <typename First, typename... Rest>
std::size_t sameSizes(const char* group, const char* firstName, const First& first, const Rest&... rest) {
    const std::size_t n = first.size();
    auto check = [&](const auto& named) {
        if (named.second->size() != n) {
            std::ostringstream os;
            os << group << "." << named.first << " has " << named.second->size() << " entries but " << group << "."
               << firstName << " has " << n;
            reject(os.str());
        }
    };
    (check(rest), ...);
    if (n > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        reject(std::string(group) + " has " + std::to_string(n) + " entries, more than 32-bit indices hold");
    return n;
}

template <typename T>
std::pair<const char*, const std::vector<T>*> named(const char* name, const std::vector<T>& v) {
    return {name, &v};
}

void requireFiniteAt(const char* array, const std::vector<double>& v, std::size_t i) {
    if (!std::isfinite(v[i])) requireFinite("continuous batch " + at(array, i), v[i]);
}

void requireIndex(const char* array, std::size_t i, std::int32_t value, std::size_t count, const char* what) {
    if (value < 0 || static_cast<std::size_t>(value) >= count) {
        std::ostringstream os;
        os << at(array, i) << " = " << value << " is not a " << what << " index (there are " << count << ")";
        reject(os.str());
    }
}

// The kinds by their codes, "0 circle, 1 polygon".
std::string kindCodes() {
    std::string list;
    for (std::size_t code = 0; code < kKindCount; ++code)
        withKindCode(static_cast<std::int32_t>(code), [&](auto kind) {
            list += (code == 0 ? "" : ", ") + std::to_string(code) + " " + kind.name;
        });
    return list;
}

// Shape i failed kernel::shapeHolds: say which entry is wrong and why.
[[noreturn]] void explainShape(const ContinuousBatch::Shapes& s, std::size_t i, std::size_t vertices) {
    const std::int32_t code = s.kind[i];
    withKindCode(code, [&](auto kind) {
        const std::int32_t first = s.firstVertex[i], count = s.vertexCount[i];
        if (count < kind.minVertices || count > kind.maxVertices)
            reject(at("shapes.vertexCount", i) + " = " + std::to_string(count) + ", but a " + kind.name + " has " +
                   kind.vertexCounts);
        if (first < 0 || static_cast<std::size_t>(first) + static_cast<std::size_t>(count) > vertices)
            reject(at("shapes.firstVertex", i) + " = " + std::to_string(first) + " with " + std::to_string(count) +
                   " vertices runs past the " + std::to_string(vertices) + " vertex entries");
        const std::string radius = kind.radiusProblem(s.radius[i]);
        if (!radius.empty()) reject(at("shapes.radius", i) + " = " + std::to_string(s.radius[i]) + ", but " + radius);
        // The geometry through the core's own checks, which name the problem (non-convex, bad normal, ...).
        const auto shape = kind.fromBatch(s, i);
        try {
            kind.validate(shape);
        } catch (const std::invalid_argument& e) {
            reject("shape " + std::to_string(i) + ": " + e.what());
        }
        const std::string refused = kind.kernelProblem(shape);
        if (!refused.empty()) reject("shape " + std::to_string(i) + ": " + refused);
        // Kinds built from their points alone (segments, capsules) carry normals the entry must match.
        kernel::Shape expected{};
        kind.toKernel(shape, expected);
        for (std::int32_t v = 0; v < count; ++v) {
            const std::size_t e = static_cast<std::size_t>(first + v);
            const double dx = s.normalX[e] - expected.normals[v].x, dy = s.normalY[e] - expected.normals[v].y;
            if (!(dx * dx + dy * dy <= 1e-18))  // unit normals to rounding
                reject("shape " + std::to_string(i) + ": " + at("shapes.normalX", e) + ", normalY is not the " +
                       kind.name + "'s outward unit normal there");
        }
        reject(at("shapes.boundingRadius", i) + " = " + std::to_string(s.boundingRadius[i]) +
               " does not bound the shape (at least " + std::to_string(kind.boundingRadius(shape)) + " m)");
    });
    reject("unsupported shape kind " + std::to_string(code) + " at " + at("shapes.kind", i) + " (" + kindCodes() +
           ")");
}

}  // namespace

std::int32_t ContinuousBatch::addShape(const Geometry& g) {
    const kernel::Shape k = toKernel(g);
    const auto index = static_cast<std::int32_t>(shapes.kind.size());
    shapes.kind.push_back(k.kind);
    shapes.firstVertex.push_back(static_cast<std::int32_t>(shapes.vertexX.size()));
    shapes.vertexCount.push_back(k.count);
    shapes.radius.push_back(k.radius);
    shapes.boundingRadius.push_back(k.boundingRadius);
    for (int i = 0; i < k.count; ++i) {
        shapes.vertexX.push_back(k.vertices[i].x);
        shapes.vertexY.push_back(k.vertices[i].y);
        shapes.normalX.push_back(k.normals[i].x);
        shapes.normalY.push_back(k.normals[i].y);
    }
    return index;
}

std::int32_t ContinuousBatch::addBody(std::int32_t shape, const Sweep& motion) {
    const auto index = static_cast<std::int32_t>(bodies.shape.size());
    bodies.shape.push_back(shape);
    bodies.x0.push_back(motion.p0.x());
    bodies.y0.push_back(motion.p0.y());
    bodies.angle0.push_back(motion.a0);
    bodies.x1.push_back(motion.p1.x());
    bodies.y1.push_back(motion.p1.y());
    bodies.angle1.push_back(motion.a1);
    return index;
}

void ContinuousBatch::addPair(std::int32_t a, std::int32_t b) {
    pairs.a.push_back(a);
    pairs.b.push_back(b);
}

void ContinuousBatch::clear() {
    for (auto* v : {&shapes.kind, &shapes.firstVertex, &shapes.vertexCount}) v->clear();
    for (auto* v : {&shapes.radius, &shapes.boundingRadius, &shapes.vertexX, &shapes.vertexY, &shapes.normalX,
                    &shapes.normalY})
        v->clear();
    clearBodiesAndPairs();
}

void ContinuousBatch::clearBodiesAndPairs() {
    for (auto* v : {&bodies.shape, &pairs.a, &pairs.b}) v->clear();
    for (auto* v : {&bodies.x0, &bodies.y0, &bodies.angle0, &bodies.x1, &bodies.y1, &bodies.angle1}) v->clear();
}

void ContinuousBatchResult::resize(std::size_t pairs) {
    state.resize(pairs);
    iterations.resize(pairs);
    for (auto* v : {&t, &gap, &normalX, &normalY, &pointX, &pointY}) v->resize(pairs);
}

void checkLayout(const ContinuousBatch& batch) {
    if (!(std::isfinite(batch.tolerance) && batch.tolerance > 0.0))
        requirePositive("continuous batch tolerance (m)", batch.tolerance);
    if (batch.maxIterations < 1 || batch.maxIterations > 1000000)
        reject("maxIterations must be in [1, 1000000], got " + std::to_string(batch.maxIterations));
    const auto& s = batch.shapes;
    sameSizes("shapes", "kind", s.kind, named("firstVertex", s.firstVertex), named("vertexCount", s.vertexCount),
              named("radius", s.radius), named("boundingRadius", s.boundingRadius));
    sameSizes("shapes", "vertexX", s.vertexX, named("vertexY", s.vertexY), named("normalX", s.normalX),
              named("normalY", s.normalY));
    const auto& b = batch.bodies;
    sameSizes("bodies", "shape", b.shape, named("x0", b.x0), named("y0", b.y0), named("angle0", b.angle0),
              named("x1", b.x1), named("y1", b.y1), named("angle1", b.angle1));
    sameSizes("pairs", "a", batch.pairs.a, named("b", batch.pairs.b));
}

void validate(const ContinuousBatch& batch) {
    checkLayout(batch);
    const kernel::BatchView view = viewOf(batch);
    const auto& s = batch.shapes;
    for (std::int32_t i = 0; i < view.shapeCount; ++i)
        if (!kernel::shapeHolds(view, i)) explainShape(s, static_cast<std::size_t>(i), s.vertexX.size());

    const auto& b = batch.bodies;
    for (std::size_t i = 0; i < b.shape.size(); ++i) {
        requireIndex("bodies.shape", i, b.shape[i], s.kind.size(), "shape");
        requireFiniteAt("bodies.x0", b.x0, i);
        requireFiniteAt("bodies.y0", b.y0, i);
        requireFiniteAt("bodies.angle0", b.angle0, i);
        requireFiniteAt("bodies.x1", b.x1, i);
        requireFiniteAt("bodies.y1", b.y1, i);
        requireFiniteAt("bodies.angle1", b.angle1, i);
    }

    const auto& p = batch.pairs;
    for (std::size_t i = 0; i < p.a.size(); ++i) {
        requireIndex("pairs.a", i, p.a[i], b.shape.size(), "body");
        requireIndex("pairs.b", i, p.b[i], b.shape.size(), "body");
        if (p.a[i] == p.b[i]) reject("pair " + std::to_string(i) + " names body " + std::to_string(p.a[i]) + " twice");
    }
}

void reportInvalidPairs(const ContinuousBatch& batch, const ContinuousBatchResult& result) {
    const auto bad = std::find(result.state.begin(), result.state.end(), kernel::kInvalid);
    if (bad == result.state.end()) return;
    validate(batch);  // names the entry
    reject("pair " + std::to_string(bad - result.state.begin()) + " failed the kernel's checks");
}

kernel::BatchView viewOf(const ContinuousBatch& batch) {
    const auto& s = batch.shapes;
    const auto& b = batch.bodies;
    return {s.kind.data(),    s.firstVertex.data(), s.vertexCount.data(), s.radius.data(), s.boundingRadius.data(),
            s.vertexX.data(), s.vertexY.data(),     s.normalX.data(),     s.normalY.data(), b.shape.data(),
            b.x0.data(),      b.y0.data(),          b.angle0.data(),      b.x1.data(),      b.y1.data(),
            b.angle1.data(),  batch.pairs.a.data(), batch.pairs.b.data(),
            static_cast<std::int32_t>(batch.pairCount()), batch.tolerance, batch.maxIterations,
            static_cast<std::int32_t>(s.kind.size()), static_cast<std::int32_t>(s.vertexX.size()),
            static_cast<std::int32_t>(b.shape.size())};
}

kernel::ResultView viewOf(ContinuousBatchResult& r) {
    return {r.state.data(),   r.iterations.data(), r.t.data(),      r.gap.data(),
            r.normalX.data(), r.normalY.data(),    r.pointX.data(), r.pointY.data()};
}

kernel::Shape toKernel(const Geometry& g) {
    kernel::Shape k{};
    withKind(g, [&](auto kind, const auto& s) {
        k.boundingRadius = kind.boundingRadius(s);
        kind.toKernel(s, k);
    });
    return k;
}

kernel::Motion toKernel(const Sweep& s) { return {{s.p0.x(), s.p0.y()}, {s.p1.x(), s.p1.y()}, s.a0, s.a1}; }

kernel::Xf toKernel(const Transform& xf) { return {{xf.p.x(), xf.p.y()}, {xf.q.c, xf.q.s}}; }

void solveOnCpu(const ContinuousBatch& batch, ContinuousBatchResult& result, Executor& executor) {
    result.resize(batch.pairCount());
    const kernel::BatchView in = viewOf(batch);
    const kernel::ResultView out = viewOf(result);
    // Each pair is solved alone, so any split of the pairs gives the same results.
    executor.parallelFor(batch.pairCount(), kPairGrain, [&](std::size_t begin, std::size_t end, int) {
        for (auto i = static_cast<std::int32_t>(begin); i < static_cast<std::int32_t>(end); ++i)
            kernel::solvePair(in, out, i);
    });
}

void solveOnCpu(const ContinuousBatch& batch, ContinuousBatchResult& result, unsigned threads) {
    // A thread for each kPairGrain pairs at most: a batch that takes one thread makes no arena at all.
    const std::size_t useful = std::max<std::size_t>(1, batch.pairCount() / kPairGrain);
    Executor executor(static_cast<int>(std::min<std::size_t>(std::max(threads, 1u), useful)));
    solveOnCpu(batch, result, executor);
}

struct CpuContinuousSolver::Workers {
    explicit Workers(int threads) : executor(threads) {}
    Executor executor;  // made once: a solve makes no arena or team of its own
};

// 0 threads: the executor's count (its arena's default concurrency).
CpuContinuousSolver::CpuContinuousSolver(unsigned threads)
    : workers_(std::make_unique<Workers>(static_cast<int>(threads))) {}

CpuContinuousSolver::~CpuContinuousSolver() = default;
unsigned CpuContinuousSolver::threads() const { return static_cast<unsigned>(workers_->executor.threads()); }
CpuContinuousSolver::CpuContinuousSolver(CpuContinuousSolver&&) noexcept = default;
CpuContinuousSolver& CpuContinuousSolver::operator=(CpuContinuousSolver&&) noexcept = default;

void CpuContinuousSolver::solve(const ContinuousBatch& batch, ContinuousBatchResult& result) {
    checkLayout(batch);
    solveOnCpu(batch, result, workers_->executor);
    reportInvalidPairs(batch, result);
}

std::string CpuContinuousSolver::name() const {
    const unsigned n = threads();
    return "cpu, " + std::to_string(n) + (n == 1 ? " thread" : " threads");
}

}  // namespace physim
