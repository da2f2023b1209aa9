#pragma once
// A set of slots (bodies or joints) an effect acts on, kept dense so the effect's loop visits only its members,
// never every body. Internal.

#include <cstdint>
#include <vector>

namespace physim {

class Members {
public:
    /// Adds the slot (no-op when present); returns its position in items().
    std::size_t add(std::uint32_t slot) {
        if (slot >= position_.size()) position_.resize(slot + 1, kAbsent);
        if (position_[slot] == kAbsent) {
            position_[slot] = static_cast<std::int32_t>(items_.size());
            items_.push_back(slot);
        }
        return static_cast<std::size_t>(position_[slot]);
    }
    /// Removes the slot (no-op when absent); the last item takes its place. Returns the old position, or -1.
    std::int32_t remove(std::uint32_t slot) {
        if (!contains(slot)) return kAbsent;
        const std::int32_t at = position_[slot];
        const std::uint32_t last = items_.back();
        items_[static_cast<std::size_t>(at)] = last;
        position_[last] = at;
        items_.pop_back();
        position_[slot] = kAbsent;
        return at;
    }
    bool contains(std::uint32_t slot) const { return slot < position_.size() && position_[slot] != kAbsent; }
    std::int32_t positionOf(std::uint32_t slot) const { return contains(slot) ? position_[slot] : kAbsent; }
    const std::vector<std::uint32_t>& items() const { return items_; }
    std::size_t size() const { return items_.size(); }
    bool empty() const { return items_.empty(); }

    static constexpr std::int32_t kAbsent = -1;

private:
    template <class> friend struct StateFields;  // the snapshot file's serializer (SnapshotFile.cpp)
    std::vector<std::uint32_t> items_;
    std::vector<std::int32_t> position_;  // per slot: index in items_, or kAbsent
};

}  // namespace physim
