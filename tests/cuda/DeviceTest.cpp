// The CUDA layer works with and without a GPU: with one, a kernel computes the right answer; without one,
// the layer says why instead of crashing, which is what lets callers fall back to the CPU.

#include <physim/cuda/Device.hpp>

#include <gtest/gtest.h>

#include <iostream>

namespace physim::cuda {
namespace {

TEST(CudaDevice, KernelRunsOrTheLayerExplainsWhyNot) {
    const DeviceStatus status = queryDevices();
    ASSERT_GE(status.deviceCount, 0);
    ASSERT_FALSE(status.message.empty());
    std::cout << "CUDA devices: " << status.deviceCount << " (" << status.message << ")\n";
    if (status.deviceCount > 0) {
        EXPECT_TRUE(selfTest()) << "kernel result differs from the host's";
    } else {
        EXPECT_NE(status.message.find("no usable CUDA device"), std::string::npos) << status.message;
        EXPECT_THROW(selfTest(), std::runtime_error);
    }
    EXPECT_THROW(selfTest(0), std::invalid_argument);
}

}  // namespace
}  // namespace physim::cuda
