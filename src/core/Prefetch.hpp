#pragma once
// Software prefetch of whole records, for loops that visit records in an order no hardware prefetcher follows.
// Internal.

#include <cstddef>
#include <cstdint>

namespace physim {

constexpr std::size_t kCacheLine = 64;  // bytes

// Asks for every cache line that holds some of the `bytes` from p (records are not line-aligned: a record of n
// lines may span n + 1).
inline void prefetchLines(const void* p, std::size_t bytes) {
    const std::uintptr_t first = reinterpret_cast<std::uintptr_t>(p) & ~std::uintptr_t{kCacheLine - 1};
    const std::uintptr_t end = reinterpret_cast<std::uintptr_t>(p) + bytes;
    for (std::uintptr_t line = first; line < end; line += kCacheLine)
        __builtin_prefetch(reinterpret_cast<const void*>(line));
}

}  // namespace physim
