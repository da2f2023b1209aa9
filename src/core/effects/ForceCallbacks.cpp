#include "ForceCallbacks.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace physim {
namespace {

void requireNotRunning(bool running, const char* call) {
    if (running)
        throw std::logic_error(std::string("physim: World::") + call + " called from a force callback");
}

}  // namespace

ForceCallbackId ForceCallbacks::add(ForceCallback callback) {
    requireNotRunning(running_, "addForceCallback");
    if (!callback) throw std::invalid_argument("physim: force callback must not be empty");
    const std::uint32_t id = next_++;
    callbacks_.emplace_back(id, std::move(callback));
    return ForceCallbackId{id};
}

void ForceCallbacks::remove(ForceCallbackId id) {
    requireNotRunning(running_, "removeForceCallback");
    const auto it = std::find_if(callbacks_.begin(), callbacks_.end(),
                                 [&](const auto& entry) { return entry.first == id.value; });
    if (it == callbacks_.end())
        throw std::invalid_argument("physim: force callback id " + std::to_string(id.value) +
                                    " is not a callback of this world");
    callbacks_.erase(it);
}

void ForceCallbacks::run(World& world, double dt) {
    struct Running {
        bool& flag;
        explicit Running(bool& f) : flag(f) { flag = true; }
        ~Running() { flag = false; }
    } guard(running_);
    for (auto& entry : callbacks_) entry.second(world, dt);
}

}  // namespace physim
