// libFuzzer target: narrow phase, distance and time of impact on shapes and poses made from the input
// (support/Fuzz.hpp). Aborts on a NaN or out-of-range answer; the sanitizers report the rest.
#include "support/Fuzz.hpp"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string problem = physim::fuzz::collideOnce(data, size);
    if (!problem.empty()) {
        std::fprintf(stderr, "fuzz_collide: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
