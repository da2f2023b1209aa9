#pragma once
// Slot arrays with free lists: bodies, contacts, joints and islands keep their index for life. Internal.

#include <cstdint>
#include <vector>

namespace physim {

/// Takes a slot for a new element: a freed one if any, else a new one at the end. The slot is reset to a fresh,
/// live element whose generation is one past the slot's last, so handles to what lived there before go stale.
template <class Data>
std::uint32_t takeSlot(std::vector<Data>& slots, std::vector<std::uint32_t>& freeList) {
    std::uint32_t index;
    if (!freeList.empty()) {
        index = freeList.back();
        freeList.pop_back();
    } else {
        index = static_cast<std::uint32_t>(slots.size());
        slots.emplace_back();
    }
    const std::uint32_t generation = slots[index].generation + 1;
    slots[index] = Data{};
    slots[index].generation = generation;
    slots[index].alive = true;
    return index;
}

}  // namespace physim
