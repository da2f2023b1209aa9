#pragma once
// The CUDA layer's entry point (built only with the `cuda` preset). Host code asks here whether a GPU is
// usable; every GPU path falls back to the CPU with the message this gives when none is.

#include <string>

namespace physim::cuda {

struct DeviceStatus {
    int deviceCount = 0;  ///< usable CUDA devices; 0 when there is no GPU or no driver
    std::string message;  ///< the device's name, or why there is none (CUDA's own error text)
};

DeviceStatus queryDevices();

/// Runs a small kernel (adds two arrays of n floats) and checks the answer on the host: true when the GPU
/// computed it right. Throws std::runtime_error with CUDA's message when no device is usable.
bool selfTest(int n = 1 << 16);

}  // namespace physim::cuda
