#pragma once
// Continuous collision on the GPU (built only with the `cuda` preset): a ContinuousSolver that sends a whole batch
// of time-of-impact pairs to the device in one launch, one thread per pair, running the kernel code the CPU runs
// (src/core/ContinuousKernel.hpp). Small batches stay on the CPU, where a launch would cost more than it saves;
// any CUDA error is logged with its message and the batch (and every later one) is solved on the CPU instead, so
// no result is lost. docs/cuda.md has the design and the measured crossover.
//
//   world.setContinuousSolver(physim::cuda::makeContinuousSolver());  // GPU if there is one, else CPU + a log line

#include "physim/core/ContinuousBatch.hpp"
#include "physim/cuda/GpuTimings.hpp"

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>

namespace physim::cuda {

namespace detail {
class DeviceBatch;
}

/// Batches of fewer pairs run on the CPU: below about a thousand pairs the copies to and from the device cost more
/// than the GPU saves (docs/cuda.md has the crossover).
constexpr std::size_t kDefaultGpuMinPairs = 1000;

struct GpuSolverOptions {
    std::size_t minPairs = kDefaultGpuMinPairs;  ///< smaller batches are solved on the CPU
    int blockSize = 128;                         ///< threads per block, > 0 (CUDA refuses more than 1024)
    unsigned cpuThreads = 1;                     ///< threads of the CPU path (small batches, fallback); 0: all
    std::ostream* log = nullptr;                 ///< where the fallback line goes; null: std::clog
};

/// One solver serves one caller at a time (it is not thread-safe), and it keeps the shapes of one batch owner: two
/// owners sharing it must not use the same shapesRevision values.
class GpuContinuousSolver final : public ContinuousSolver {
public:
    /// Touches no device yet (the first large batch does). Throws std::invalid_argument for blockSize <= 0.
    explicit GpuContinuousSolver(const GpuSolverOptions& options = {});
    ~GpuContinuousSolver() override;
    GpuContinuousSolver(const GpuContinuousSolver&) = delete;
    GpuContinuousSolver& operator=(const GpuContinuousSolver&) = delete;

    /// Solves on the GPU when the batch has at least minPairs pairs and no CUDA error has happened yet; otherwise,
    /// and after a CUDA error, on the CPU. Bad input throws std::invalid_argument as validate() would: inconsistent
    /// array sizes before any device work; bad entries (an unsupported shape kind, an index out of range) after
    /// the kernel, which checks every pair before it reads it, so a bad batch never faults the device.
    void solve(const ContinuousBatch& batch, ContinuousBatchResult& result) override;
    std::string name() const override;

    /// False once a CUDA error has sent this solver to the CPU for good; error() says which.
    bool gpuEnabled() const { return error_.empty(); }
    const std::string& error() const { return error_; }
    /// Whether the last batch ran on the GPU, and its timings (all zero when it did not).
    bool lastRanOnGpu() const { return lastRanOnGpu_; }
    const GpuTimings& lastTimings() const { return timings_; }
    const GpuSolverOptions& options() const { return options_; }

private:
    GpuSolverOptions options_;
    std::unique_ptr<detail::DeviceBatch> device_;
    std::uint64_t shapesRevision_ = 0;  // of the shapes on the device; 0: none known
    std::size_t shapeCount_ = 0, vertexCount_ = 0;  // of the shapes on the device
    std::string deviceName_;
    std::string error_;
    bool lastRanOnGpu_ = false;
    GpuTimings timings_;
};

/// The continuous solver for this machine: a GpuContinuousSolver when a CUDA device is usable; otherwise a
/// CpuContinuousSolver, after one line on `log` that says why ("physim: no usable CUDA device (...): continuous
/// collision runs on the CPU").
std::shared_ptr<ContinuousSolver> makeContinuousSolver(std::ostream& log, const GpuSolverOptions& options = {});
std::shared_ptr<ContinuousSolver> makeContinuousSolver();  ///< logs to std::clog

}  // namespace physim::cuda
