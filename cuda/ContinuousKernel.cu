// The continuous batch on the GPU: one thread per pair runs the shared kernel (ContinuousKernel.hpp), the code
// the CPU runs. The batch's structure of arrays is copied as it is (one copy per array), so consecutive threads
// read consecutive pair and body entries.

#include "ContinuousLaunch.hpp"

#include <cuda_runtime.h>

#include <chrono>
#include <stdexcept>
#include <string>

namespace physim::cuda::detail {
namespace {

void check(cudaError_t status, const char* what) {
    if (status != cudaSuccess)
        throw std::runtime_error(std::string("CUDA error in ") + what + ": " + cudaGetErrorName(status) + " (" +
                                 cudaGetErrorString(status) + ")");
}

__global__ void solvePairs(kernel::BatchView in, kernel::ResultView out) {
    const std::int32_t i = static_cast<std::int32_t>(blockIdx.x) * static_cast<std::int32_t>(blockDim.x) +
                           static_cast<std::int32_t>(threadIdx.x);
    if (i < in.pairCount) kernel::solvePair(in, out, i);
}

// One device array that only grows; freed with its owner.
template <typename T>
class DeviceArray {
public:
    DeviceArray() = default;
    ~DeviceArray() { cudaFree(ptr_); }  // errors ignored: nothing to do about them while freeing
    DeviceArray(const DeviceArray&) = delete;
    DeviceArray& operator=(const DeviceArray&) = delete;

    T* reserve(std::size_t count) {
        if (count > capacity_) {
            cudaFree(ptr_);
            ptr_ = nullptr;
            capacity_ = 0;
            check(cudaMalloc(&ptr_, count * sizeof(T)), "cudaMalloc");
            capacity_ = count;
        }
        return ptr_;
    }
    const T* upload(const T* host, std::size_t count) {
        T* device = reserve(count);
        if (count > 0) check(cudaMemcpy(device, host, count * sizeof(T), cudaMemcpyHostToDevice), "upload");
        return device;
    }
    const T* data() const { return ptr_; }
    void download(T* host, std::size_t count) const {
        if (count > 0) check(cudaMemcpy(host, ptr_, count * sizeof(T), cudaMemcpyDeviceToHost), "download");
    }

private:
    T* ptr_ = nullptr;
    std::size_t capacity_ = 0;
};

// A CUDA event, destroyed with its owner.
class Event {
public:
    Event() { check(cudaEventCreate(&event_), "cudaEventCreate"); }
    ~Event() { cudaEventDestroy(event_); }
    Event(const Event&) = delete;
    Event& operator=(const Event&) = delete;
    void record() { check(cudaEventRecord(event_), "cudaEventRecord"); }
    float msSince(const Event& start) const {
        check(cudaEventSynchronize(event_), "cudaEventSynchronize");
        float ms = 0.0f;
        check(cudaEventElapsedTime(&ms, start.event_, event_), "cudaEventElapsedTime");
        return ms;
    }

private:
    cudaEvent_t event_{};
};

}  // namespace

struct DeviceBatch::Impl {
    DeviceArray<std::int32_t> kind, firstVertex, vertexCount, shape, pairA, pairB, state, iterations;
    DeviceArray<double> radius, boundingRadius, vertexX, vertexY, normalX, normalY;
    DeviceArray<double> x0, y0, angle0, x1, y1, angle1;
    DeviceArray<double> t, gap, outNormalX, outNormalY, pointX, pointY;
    Event start, uploaded, solved, downloaded;
};

DeviceBatch::DeviceBatch() : impl_(std::make_unique<Impl>()) {}
DeviceBatch::~DeviceBatch() = default;

std::string DeviceBatch::deviceName() {
    int device = 0;
    check(cudaGetDevice(&device), "cudaGetDevice");
    cudaDeviceProp prop{};
    check(cudaGetDeviceProperties(&prop, device), "cudaGetDeviceProperties");
    return prop.name;
}

GpuTimings DeviceBatch::run(const kernel::BatchView& in, const BatchSizes& n, const kernel::ResultView& out,
                            int blockSize, bool shapesOnDevice) {
    Impl& d = *impl_;
    d.start.record();
    kernel::BatchView dev = in;  // same counts and settings, device pointers
    if (shapesOnDevice) {
        dev.kind = d.kind.data();
        dev.firstVertex = d.firstVertex.data();
        dev.vertexCount = d.vertexCount.data();
        dev.radius = d.radius.data();
        dev.boundingRadius = d.boundingRadius.data();
        dev.vertexX = d.vertexX.data();
        dev.vertexY = d.vertexY.data();
        dev.normalX = d.normalX.data();
        dev.normalY = d.normalY.data();
    } else {
        dev.kind = d.kind.upload(in.kind, n.shapes);
        dev.firstVertex = d.firstVertex.upload(in.firstVertex, n.shapes);
        dev.vertexCount = d.vertexCount.upload(in.vertexCount, n.shapes);
        dev.radius = d.radius.upload(in.radius, n.shapes);
        dev.boundingRadius = d.boundingRadius.upload(in.boundingRadius, n.shapes);
        dev.vertexX = d.vertexX.upload(in.vertexX, n.vertices);
        dev.vertexY = d.vertexY.upload(in.vertexY, n.vertices);
        dev.normalX = d.normalX.upload(in.normalX, n.vertices);
        dev.normalY = d.normalY.upload(in.normalY, n.vertices);
    }
    dev.shape = d.shape.upload(in.shape, n.bodies);
    dev.x0 = d.x0.upload(in.x0, n.bodies);
    dev.y0 = d.y0.upload(in.y0, n.bodies);
    dev.angle0 = d.angle0.upload(in.angle0, n.bodies);
    dev.x1 = d.x1.upload(in.x1, n.bodies);
    dev.y1 = d.y1.upload(in.y1, n.bodies);
    dev.angle1 = d.angle1.upload(in.angle1, n.bodies);
    dev.pairA = d.pairA.upload(in.pairA, n.pairs);
    dev.pairB = d.pairB.upload(in.pairB, n.pairs);
    const kernel::ResultView devOut{d.state.reserve(n.pairs),      d.iterations.reserve(n.pairs),
                                    d.t.reserve(n.pairs),          d.gap.reserve(n.pairs),
                                    d.outNormalX.reserve(n.pairs), d.outNormalY.reserve(n.pairs),
                                    d.pointX.reserve(n.pairs),     d.pointY.reserve(n.pairs)};
    d.uploaded.record();

    const auto blocks = static_cast<unsigned>((n.pairs + static_cast<std::size_t>(blockSize) - 1) /
                                              static_cast<std::size_t>(blockSize));
    if (blocks > 0) {
        solvePairs<<<blocks, static_cast<unsigned>(blockSize)>>>(dev, devOut);
        check(cudaGetLastError(), "kernel launch");
    }
    d.solved.record();

    d.state.download(out.state, n.pairs);
    d.iterations.download(out.iterations, n.pairs);
    d.t.download(out.t, n.pairs);
    d.gap.download(out.gap, n.pairs);
    d.outNormalX.download(out.normalX, n.pairs);
    d.outNormalY.download(out.normalY, n.pairs);
    d.pointX.download(out.pointX, n.pairs);
    d.pointY.download(out.pointY, n.pairs);
    d.downloaded.record();

    GpuTimings timings;
    timings.uploadMs = d.uploaded.msSince(d.start);
    timings.kernelMs = d.solved.msSince(d.uploaded);
    timings.downloadMs = d.downloaded.msSince(d.solved);
    return timings;
}

}  // namespace physim::cuda::detail
