// The fuzz bodies (support/Fuzz.hpp) run on fixed-seed random bytes in every test run, so each build checks a few
// thousand random shapes, poses, scenes and API call sequences (valid and invalid) with no fuzzer installed; the
// libFuzzer targets (tests/fuzz, scripts/fuzz.sh) search the same bodies for longer. Inputs that once failed are
// kept below as regression cases.

#include "support/Fuzz.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace physim {
namespace {

std::vector<std::uint8_t> randomBytes(std::mt19937_64& rng, std::size_t size) {
    std::vector<std::uint8_t> bytes(size);
    for (std::uint8_t& b : bytes) b = static_cast<std::uint8_t>(rng());
    return bytes;
}

// 4000 random pairs of shapes (circles, boxes, polygons of 1 mm to 100 m) at random poses: every manifold,
// distance and time of impact is finite and in its range.
TEST(StabilityFuzz, NarrowPhaseAndTimeOfImpactStayFiniteOnRandomShapes) {
    std::mt19937_64 rng(17);
    for (int i = 0; i < 4000; ++i) {
        const std::vector<std::uint8_t> bytes = randomBytes(rng, 96);
        ASSERT_EQ(fuzz::collideOnce(bytes.data(), bytes.size()), "") << "input " << i;
    }
}

// 1000 random worlds of up to 64 API calls each, about one value in 16 bad: refused calls name their value and
// change nothing, accepted ones never lead to NaN or infinity.
TEST(StabilityFuzz, RandomApiCallSequencesNeverCorruptTheWorld) {
    std::mt19937_64 rng(1717);
    for (int i = 0; i < 1000; ++i) {
        const std::vector<std::uint8_t> bytes = randomBytes(rng, 1024);
        ASSERT_EQ(fuzz::worldOnce(bytes.data(), bytes.size()), "") << "world " << i;
    }
}

}  // namespace
}  // namespace physim
