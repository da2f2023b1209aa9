#pragma once
// The user's force callbacks (physim/core/ForceCallback.hpp), called in the order added. Internal.

#include "physim/core/ForceCallback.hpp"

#include <cstdint>
#include <utility>
#include <vector>

namespace physim {

class ForceCallbacks {
public:
    /// Throws std::invalid_argument for an empty callback, std::logic_error while the callbacks run.
    ForceCallbackId add(ForceCallback callback);
    /// Throws std::invalid_argument for an unknown id, std::logic_error while the callbacks run.
    void remove(ForceCallbackId id);
    bool active() const { return !callbacks_.empty(); }
    std::size_t count() const { return callbacks_.size(); }
    bool running() const { return running_; }
    /// Calls each callback with the world and the step. An exception from one leaves the rest uncalled and
    /// propagates (the step has not begun).
    void run(World& world, double dt);

private:
    std::vector<std::pair<std::uint32_t, ForceCallback>> callbacks_;
    std::uint32_t next_ = 0;
    bool running_ = false;
};

}  // namespace physim
