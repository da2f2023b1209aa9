#pragma once
// A set of body pairs for "does this pair have a contact already": open addressing with linear probing over a
// power-of-two table, tombstones on erase. Once entries and tombstones fill half the table it is rebuilt at four
// times the entries: contacts made and destroyed every step (wheels rolling over a chain) leave tombstones, which
// must not grow the table (a sparse table misses the cache on every look-up). No allocation while the number of
// contacts stays within what it has held. Internal.

#include <cstdint>
#include <vector>

namespace physim {

class PairSet {
public:
    static std::uint64_t key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t{a} << 32) | b; }

    bool contains(std::uint64_t k) const {
        if (slots_.empty()) return false;
        for (std::size_t i = slot(k);; i = (i + 1) & mask_) {
            if (slots_[i] == k) return true;
            if (slots_[i] == kEmpty) return false;
        }
    }
    void insert(std::uint64_t k) {
        if (2 * (count_ + tombstones_ + 1) > slots_.size()) rehash(sizeFor(count_ + 1));
        std::size_t i = slot(k);
        while (slots_[i] != kEmpty && slots_[i] != kTombstone) i = (i + 1) & mask_;
        if (slots_[i] == kTombstone) --tombstones_;
        slots_[i] = k;
        ++count_;
    }
    std::size_t size() const { return count_; }
    /// Slots in the table (entries, tombstones and empty ones): at most 4 (size() + 1) after a rebuild, and the
    /// table is rebuilt once entries and tombstones fill half of it.
    std::size_t tableSize() const { return slots_.size(); }
    void erase(std::uint64_t k) {
        for (std::size_t i = slot(k);; i = (i + 1) & mask_) {
            if (slots_[i] == kEmpty) return;
            if (slots_[i] == k) {
                slots_[i] = kTombstone;
                --count_;
                ++tombstones_;
                return;
            }
        }
    }

private:
    template <class> friend struct StateFields;  // the snapshot file's serializer (SnapshotFile.cpp)
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
    static constexpr std::uint64_t kTombstone = ~std::uint64_t{0} - 1;  // body slots never reach 2^32 - 1

    std::size_t slot(std::uint64_t k) const {
        k ^= k >> 33;  // a mixing step (splitmix64's finalizer) so neighbouring pairs spread over the table
        k *= 0xff51afd7ed558ccdULL;
        k ^= k >> 33;
        return static_cast<std::size_t>(k) & mask_;
    }
    // The table for `entries`: a quarter full at most, so as many erases again fit before the next rebuild.
    static std::size_t sizeFor(std::size_t entries) {
        std::size_t size = 64;
        while (size < 4 * entries) size *= 2;
        return size;
    }
    void rehash(std::size_t size) {
        spare_.swap(slots_);  // the old entries; the last rebuild's buffer (if large enough) becomes the table
        slots_.assign(size, kEmpty);
        mask_ = size - 1;
        count_ = tombstones_ = 0;
        for (const std::uint64_t k : spare_)
            if (k != kEmpty && k != kTombstone) insert(k);
    }

    std::vector<std::uint64_t> slots_;
    std::size_t mask_ = 0;
    std::size_t count_ = 0;
    std::size_t tombstones_ = 0;
    std::vector<std::uint64_t> spare_;  // rehash's other buffer (no state: its contents are the last table's)
};

}  // namespace physim
