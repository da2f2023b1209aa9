#pragma once
// Bad input is refused with std::invalid_argument whose message names the value (the project's rule): the check.

#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>

namespace physim::testing {

/// call() throws std::invalid_argument whose message contains `name`.
inline void expectThrowsNaming(const std::function<void()>& call, const std::string& name) {
    try {
        call();
        ADD_FAILURE() << "no exception; expected one naming " << name;
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
}

}  // namespace physim::testing
