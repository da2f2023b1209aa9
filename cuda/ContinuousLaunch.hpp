#pragma once
// Internal to physim::cuda: the device side of the continuous batch, kept free of Eigen so nvcc compiles only the
// shared kernel (ContinuousKernel.hpp) and CUDA's own headers.

#include "ContinuousKernel.hpp"
#include "physim/cuda/GpuTimings.hpp"

#include <cstddef>
#include <memory>
#include <string>

namespace physim::cuda::detail {

/// Entry counts of the arrays a BatchView points at.
struct BatchSizes {
    std::size_t shapes = 0;
    std::size_t vertices = 0;
    std::size_t bodies = 0;
    std::size_t pairs = 0;
};

/// Device copies of a batch's arrays, kept between calls and grown when a batch needs more, so a World that
/// solves a batch every substep allocates only while its batches grow.
class DeviceBatch {
public:
    DeviceBatch();  ///< creates the timing events; throws std::runtime_error with CUDA's message
    ~DeviceBatch();
    DeviceBatch(const DeviceBatch&) = delete;
    DeviceBatch& operator=(const DeviceBatch&) = delete;

    /// Copies the batch (host arrays) to the device, runs one thread per pair (blockSize threads a block) and
    /// copies the results into `out` (host arrays). Throws std::runtime_error with CUDA's message on any CUDA
    /// error; `out` is then incomplete.
    /// shapesOnDevice: the device already holds these shape arrays (the last run's), so they are not copied.
    GpuTimings run(const kernel::BatchView& in, const BatchSizes& sizes, const kernel::ResultView& out,
                   int blockSize, bool shapesOnDevice);

    /// Name of the current device ("NVIDIA H100 80GB HBM3"); throws std::runtime_error with CUDA's message.
    static std::string deviceName();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace physim::cuda::detail
