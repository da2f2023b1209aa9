// The GPU continuous solver's host side: validation, the CPU path for small batches, and the fallback to the CPU
// on a CUDA error. The device work is in ContinuousKernel.cu.

#include "physim/cuda/ContinuousSolver.hpp"

#include "ContinuousLaunch.hpp"
#include "KernelBridge.hpp"
#include "physim/cuda/Device.hpp"

#include <chrono>
#include <iostream>
#include <stdexcept>

namespace physim::cuda {

GpuContinuousSolver::GpuContinuousSolver(const GpuSolverOptions& options) : options_(options) {
    if (options_.blockSize <= 0)
        throw std::invalid_argument("physim cuda: GpuSolverOptions::blockSize must be > 0, got " +
                                    std::to_string(options_.blockSize));
    if (options_.cpuThreads == 0) options_.cpuThreads = CpuContinuousSolver(0).threads();
}

GpuContinuousSolver::~GpuContinuousSolver() = default;

void GpuContinuousSolver::solve(const ContinuousBatch& batch, ContinuousBatchResult& result) {
    const auto start = std::chrono::steady_clock::now();
    checkLayout(batch);  // O(1): the arrays are safe to index; each pair's entries are checked where it is solved
    lastRanOnGpu_ = false;
    timings_ = {};
    if (batch.pairCount() >= options_.minPairs && gpuEnabled()) {
        result.resize(batch.pairCount());
        try {
            if (!device_) {
                device_ = std::make_unique<detail::DeviceBatch>();
                deviceName_ = detail::DeviceBatch::deviceName();
            }
            const detail::BatchSizes sizes{batch.shapes.kind.size(), batch.shapes.vertexX.size(),
                                           batch.bodies.shape.size(), batch.pairCount()};
            // Shapes stay on the device while the owner keeps their revision (and, as a guard, their sizes).
            const bool shapesOnDevice = batch.shapesRevision != 0 && batch.shapesRevision == shapesRevision_ &&
                                        sizes.shapes == shapeCount_ && sizes.vertices == vertexCount_;
            shapesRevision_ = 0;  // unknown until this run has copied them
            timings_ = device_->run(viewOf(batch), sizes, viewOf(result), options_.blockSize, shapesOnDevice);
            shapesRevision_ = batch.shapesRevision;
            shapeCount_ = sizes.shapes;
            vertexCount_ = sizes.vertices;
            lastRanOnGpu_ = true;
        } catch (const std::runtime_error& e) {
            error_ = e.what();
            device_.reset();
            shapesRevision_ = 0;
            timings_ = {};
            std::ostream& log = options_.log ? *options_.log : std::clog;
            log << "physim: the GPU continuous solver stopped: " << error_
                << "; this batch and every later one run on the CPU\n";
        }
    }
    if (!lastRanOnGpu_) solveOnCpu(batch, result, options_.cpuThreads);
    reportInvalidPairs(batch, result);
    if (lastRanOnGpu_)
        timings_.totalMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

std::string GpuContinuousSolver::name() const {
    if (!gpuEnabled()) return "cpu (gpu stopped: " + error_ + ")";
    return "gpu" + (deviceName_.empty() ? std::string() : " " + deviceName_) + ", batches >= " +
           std::to_string(options_.minPairs) + " pairs";
}

std::shared_ptr<ContinuousSolver> makeContinuousSolver(std::ostream& log, const GpuSolverOptions& options) {
    const DeviceStatus status = queryDevices();
    if (status.deviceCount == 0) {
        log << "physim: " << status.message << ": continuous collision runs on the CPU\n";
        return std::make_shared<CpuContinuousSolver>(options.cpuThreads);
    }
    GpuSolverOptions withLog = options;
    if (!withLog.log) withLog.log = &log;
    return std::make_shared<GpuContinuousSolver>(withLog);
}

std::shared_ptr<ContinuousSolver> makeContinuousSolver() { return makeContinuousSolver(std::clog); }

}  // namespace physim::cuda
