#pragma once
// Where the time of one GPU batch went (milliseconds, CUDA events for the device parts, the host clock for total).

namespace physim::cuda {

struct GpuTimings {
    double uploadMs = 0.0;    ///< host -> device copies of the batch's arrays
    double kernelMs = 0.0;    ///< the one launch, all pairs
    double downloadMs = 0.0;  ///< device -> host copies of the results
    double totalMs = 0.0;     ///< the whole solve() call on the host: validation, copies, launch, waits
};

}  // namespace physim::cuda
