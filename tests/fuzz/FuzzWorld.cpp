// libFuzzer target: a World driven by the input's API calls, valid and bad (support/Fuzz.hpp). Aborts when a
// refused call changes the world or an accepted one leads to NaN; the sanitizers report the rest.
#include "support/Fuzz.hpp"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string problem = physim::fuzz::worldOnce(data, size);
    if (!problem.empty()) {
        std::fprintf(stderr, "fuzz_world: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
