// The contact pair set (PairSet.hpp) against std::set under the churn of a running scene: pairs made and destroyed
// every step while their number stays about the same. Membership must match the reference after every change, and
// the table must not grow with the churn (only with the pairs held).

#include "PairSet.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>
#include <vector>

namespace physim {
namespace {

TEST(PairSet, ChurnKeepsMembershipAndTheTableSize) {
    std::mt19937 rng(7);
    PairSet set;
    std::set<std::uint64_t> reference;
    std::vector<std::uint64_t> live;
    auto fresh = [&] {  // a pair not held: shape slots as a chain's pieces and wheels give them
        for (;;) {
            const std::uint64_t k = PairSet::key(rng() % 4000, 4000 + rng() % 400);
            if (reference.count(k) == 0) return k;
        }
    };
    for (int i = 0; i < 900; ++i) {
        const std::uint64_t k = fresh();
        set.insert(k);
        reference.insert(k);
        live.push_back(k);
    }
    std::size_t largest = 0;
    for (int step = 0; step < 20000; ++step) {
        // One pair destroyed, one made: 900 held throughout.
        const std::size_t at = rng() % live.size();
        set.erase(live[at]);
        reference.erase(live[at]);
        live[at] = fresh();
        set.insert(live[at]);
        reference.insert(live[at]);
        largest = std::max(largest, set.tableSize());
        if (step % 1000 == 0) {
            for (const std::uint64_t k : live) ASSERT_TRUE(set.contains(k));
            for (int probe = 0; probe < 200; ++probe) {
                const std::uint64_t k = PairSet::key(rng() % 4000, 4000 + rng() % 400);
                ASSERT_EQ(set.contains(k), reference.count(k) == 1);
            }
        }
    }
    EXPECT_EQ(set.size(), reference.size());
    // 900 entries: a rebuild makes 4096 slots (the least power of two >= 4 x 901); 20000 erases leave tombstones
    // that would have doubled a table grown at each rebuild several times over.
    EXPECT_EQ(largest, 4096u);
}

}  // namespace
}  // namespace physim
