#include "physim/cuda/Device.hpp"

#include <cuda_runtime.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace physim::cuda {
namespace {

void check(cudaError_t status, const char* what) {
    if (status != cudaSuccess)
        throw std::runtime_error(std::string("physim cuda: ") + what + ": " + cudaGetErrorString(status));
}

__global__ void addArrays(const float* a, const float* b, float* out, int n) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) out[i] = a[i] + b[i];
}

// Device memory owned for the scope of one call (no leaks on early return or throw).
struct DeviceBuffer {
    float* ptr = nullptr;
    explicit DeviceBuffer(std::size_t count) { check(cudaMalloc(&ptr, count * sizeof(float)), "cudaMalloc"); }
    ~DeviceBuffer() { cudaFree(ptr); }
    DeviceBuffer(const DeviceBuffer&) = delete;
    DeviceBuffer& operator=(const DeviceBuffer&) = delete;
};

}  // namespace

DeviceStatus queryDevices() {
    DeviceStatus s;
    const cudaError_t status = cudaGetDeviceCount(&s.deviceCount);
    if (status != cudaSuccess) {
        s.deviceCount = 0;
        s.message = std::string("no usable CUDA device: ") + cudaGetErrorString(status);
        cudaGetLastError();  // clear the sticky error so later calls start clean
        return s;
    }
    if (s.deviceCount == 0) {
        s.message = "no usable CUDA device: none found";
        return s;
    }
    cudaDeviceProp prop{};
    check(cudaGetDeviceProperties(&prop, 0), "cudaGetDeviceProperties");
    s.message = prop.name;
    return s;
}

bool selfTest(int n) {
    if (n <= 0) throw std::invalid_argument("physim cuda: selfTest needs n > 0, got " + std::to_string(n));
    const DeviceStatus status = queryDevices();
    if (status.deviceCount == 0) throw std::runtime_error("physim cuda: " + status.message);
    std::vector<float> a(n), b(n), out(n);
    for (int i = 0; i < n; ++i) {
        a[i] = 0.5f * i;
        b[i] = 2.0f - i;
    }
    const std::size_t bytes = n * sizeof(float);
    DeviceBuffer da(n), db(n), dout(n);
    check(cudaMemcpy(da.ptr, a.data(), bytes, cudaMemcpyHostToDevice), "copy a");
    check(cudaMemcpy(db.ptr, b.data(), bytes, cudaMemcpyHostToDevice), "copy b");
    const int block = 256;
    addArrays<<<(n + block - 1) / block, block>>>(da.ptr, db.ptr, dout.ptr, n);
    check(cudaGetLastError(), "launch");
    check(cudaMemcpy(out.data(), dout.ptr, bytes, cudaMemcpyDeviceToHost), "copy out");
    for (int i = 0; i < n; ++i)
        if (out[i] != a[i] + b[i]) return false;
    return true;
}

}  // namespace physim::cuda
