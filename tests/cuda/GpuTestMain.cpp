// main() of the GPU-only tests: on a machine without a usable CUDA device it prints why and exits with 77, which
// ctest reports as a skipped test (SKIP_RETURN_CODE in tests/cuda/CMakeLists.txt); with one, it runs them all.
// Listing the tests (ctest's discovery) works everywhere.

#include <physim/cuda/Device.hpp>

#include <gtest/gtest.h>

#include <iostream>

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    if (!::testing::GTEST_FLAG(list_tests)) {
        const physim::cuda::DeviceStatus status = physim::cuda::queryDevices();
        if (status.deviceCount == 0) {
            std::cout << "needs a CUDA GPU: " << status.message << "\n";
            return 77;
        }
    }
    return RUN_ALL_TESTS();
}
