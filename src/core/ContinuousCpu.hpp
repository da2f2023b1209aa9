#pragma once
// A continuous batch solved on the CPU through the step's executor (Executor.hpp), the one way the core runs work
// on threads. Internal.

#include "Executor.hpp"

#include "physim/core/ContinuousBatch.hpp"

#include <cstddef>

namespace physim {

/// Pairs per share of a batch: below about two of them a batch runs on the calling thread alone, where handing out
/// the work would cost more than the pairs (~1 us each).
constexpr std::size_t kPairGrain = 1024;

/// solveOnCpu over `executor`'s threads: the same results on any number of them.
void solveOnCpu(const ContinuousBatch& batch, ContinuousBatchResult& result, Executor& executor);

}  // namespace physim
