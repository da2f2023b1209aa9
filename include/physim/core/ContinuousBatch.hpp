#pragma once
// Many exact time-of-impact queries at once (the paper's section 5.2.4 made to pay off: one launch for all pairs
// instead of one per pair). The data is a structure of arrays, so the GPU threads of a warp read neighbouring
// memory and the whole batch moves to the device in a few copies; the CPU solves the same arrays with the same
// code (the shared kernel, src/core/ContinuousKernel.hpp). docs/cuda.md explains the design.
//
//   shapes: one entry per distinct shape; its kind's points (and edge normals, where it has edges) sit in the flat
//           vertex arrays from firstVertex, as addShape lays them out: a circle its centre; a polygon 3 to 8
//           counter-clockwise vertices with outward unit normals, radius >= 0 (> 0: rounded); a segment, capsule or
//           chain segment its 2 points, normal 0 the unit normal of 0 -> 1 on its right ((dy, -dx) / length) and
//           normal 1 its negative, radius the capsule's (0 for the others).
//   bodies: a shape and a motion (pose at t = 0 and at t = 1, linear in between).
//   pairs:  two bodies each; result i belongs to pair i.

#include "physim/core/Geometry.hpp"
#include "physim/core/TimeOfImpact.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace physim {

struct ContinuousBatch {
    struct Shapes {
        std::vector<std::int32_t> kind;         ///< the shape's kind: its alternative's index in Geometry
        std::vector<std::int32_t> firstVertex;  ///< index into the vertex arrays
        std::vector<std::int32_t> vertexCount;  ///< the points the kind keeps (validate() names each kind's range)
        std::vector<double> radius;             ///< m, the kind's radius about its points (0 for a kind without)
        std::vector<double> boundingRadius;     ///< m, farthest point from the body origin
        std::vector<double> vertexX, vertexY;   ///< m, body frame
        std::vector<double> normalX, normalY;   ///< unit outward edge normals (0 for a kind without edges)
    } shapes;
    struct Bodies {
        std::vector<std::int32_t> shape;              ///< index into shapes
        std::vector<double> x0, y0, angle0;           ///< m, rad at t = 0
        std::vector<double> x1, y1, angle1;           ///< m, rad at t = 1
    } bodies;
    struct Pairs {
        std::vector<std::int32_t> a, b;  ///< body indices; the normal in the result points from a to b
    } pairs;
    double tolerance = kToiTolerance;  ///< m, > 0: the gap at which a hit is reported
    std::int32_t maxIterations = 100;  ///< in [1, 1e6], distance evaluations per pair before it is Failed
    /// 0 (the default): the shape arrays may differ from the last batch's, and a GPU solver copies them. Any other
    /// value is the owner's promise that the shape arrays are exactly those of the last batch it solved with this
    /// value, so a GPU solver may keep them on the device (shapes rarely change between steps; they are most of
    /// the bytes). Bodies and pairs are always copied.
    std::uint64_t shapesRevision = 0;

    /// Appends a shape (already valid: built by makeCircle, makeBox, makePolygon) and returns its index.
    std::int32_t addShape(const Geometry& g);
    /// Appends a body with the given shape and motion and returns its index.
    std::int32_t addBody(std::int32_t shape, const Sweep& motion);
    void addPair(std::int32_t a, std::int32_t b);
    /// Empties every array and keeps their capacity, so a batch refilled every step does not allocate.
    void clear();
    /// Empties the bodies and pairs only: the next batch keeps the same shapes (see shapesRevision).
    void clearBodiesAndPairs();
    std::size_t pairCount() const { return pairs.a.size(); }
};

/// One entry per pair: state is a ToiState code (Separated 0, Hit 1, Touching 2, Failed 3; -1, invalid, only inside
/// a solve); at a Hit or Touching, t is the time of impact (fraction of the motion), gap the distance then (m,
/// < tolerance), normal (a to b) and point (m, world) the contact's; normal and point are zero when the shapes
/// overlap at t. Separated pairs have t = 1. Failed pairs (no convergence within maxIterations: no impact found,
/// never a hit) have t = how far the shapes were proven apart, and zero gap, normal and point.
struct ContinuousBatchResult {
    std::vector<std::int32_t> state;
    std::vector<std::int32_t> iterations;
    std::vector<double> t, gap, normalX, normalY, pointX, pointY;

    void resize(std::size_t pairs);
    std::size_t size() const { return state.size(); }
    ToiResult toi(std::size_t i) const {
        return {static_cast<ToiState>(state[i]), t[i], iterations[i]};
    }
};

/// Throws std::invalid_argument naming the array or the value when the batch is not one the kernel can read:
/// arrays of one group with different sizes, an unknown shape kind, a vertex count or range
/// that does not fit, a radius the kind does not take (circle and capsule > 0, polygon >= 0, segment and chain
/// segment 0), a polygon that is not strictly convex and counter-clockwise with its outward unit normals or a
/// segment of zero length or with other normals (validate(Geometry) names the problem), a bounding radius that
/// does not bound its shape (radius included), a non-finite
/// coordinate or pose, a body or pair index out of range, a pair of one body with itself, tolerance <= 0 or
/// maxIterations outside [1, 1e6], or more entries than 32-bit indices hold.
void validate(const ContinuousBatch& batch);

/// The part of validate() that costs O(1) and makes the arrays safe to index: the groups' sizes, tolerance and
/// maxIterations. Solvers call it before any work; the kernel checks every pair's entries as it solves it,
/// and reportInvalidPairs turns a failed pair into validate()'s named error.
void checkLayout(const ContinuousBatch& batch);
void reportInvalidPairs(const ContinuousBatch& batch, const ContinuousBatchResult& result);

/// Who solves a continuous batch. The World hands its continuous stage's pairs to one (World::setContinuousSolver);
/// the CUDA layer provides a GPU one (physim/cuda/ContinuousSolver.hpp).
class ContinuousSolver {
public:
    virtual ~ContinuousSolver() = default;
    /// Fills result, resized to the pair count; throws std::invalid_argument as validate() would for a bad batch
    /// (checkLayout before any work; each pair's own entries as it is solved, see checkLayout).
    virtual void solve(const ContinuousBatch& batch, ContinuousBatchResult& result) = 0;
    /// What solves it, for log lines and bench tables ("cpu, 1 thread", "gpu NVIDIA H100 ...").
    virtual std::string name() const = 0;
};

/// The batch on the CPU: `threads` worker threads over contiguous ranges of pairs (0: as many as the core's thread
/// pool has by default, about one per hardware thread), kept from one solve to the next; a batch under a few
/// thousand pairs runs on the calling thread, where handing out the work would cost more than it saves.
class CpuContinuousSolver final : public ContinuousSolver {
public:
    explicit CpuContinuousSolver(unsigned threads = 1);
    ~CpuContinuousSolver() override;
    CpuContinuousSolver(CpuContinuousSolver&&) noexcept;
    CpuContinuousSolver& operator=(CpuContinuousSolver&&) noexcept;
    void solve(const ContinuousBatch& batch, ContinuousBatchResult& result) override;
    std::string name() const override;
    unsigned threads() const;

private:
    struct Workers;  // the core's executor for this solver's threads (src/core)
    std::unique_ptr<Workers> workers_;
};

/// Solves a batch that passed checkLayout on the CPU with `threads` threads (>= 1); pairs that fail their checks
/// come back kInvalid (reportInvalidPairs). The CPU solver's work; also the GPU solver's fallback.
void solveOnCpu(const ContinuousBatch& batch, ContinuousBatchResult& result, unsigned threads);

}  // namespace physim
