#pragma once
// The builds of the four-lane loops this processor runs (src/core/Wide.hpp), for tests that hold every build to the
// same bits: the baseline and Best always, AVX2 and AVX-512 where they run.

#include "Wide.hpp"

#include <vector>

namespace physim::test {

inline std::vector<WideCode> runnableWideCodes() {
    std::vector<WideCode> codes{WideCode::Baseline, WideCode::Best};
    if (avx2CodeRuns()) codes.push_back(WideCode::Avx2);
    if (avx512CodeRuns()) codes.push_back(WideCode::Avx512);
    return codes;
}

}  // namespace physim::test
