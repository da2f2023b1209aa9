#pragma once

#include <string>

namespace physim {

/// Why a window cannot be opened, or "" when it can: DISPLAY unset, or no X server answering at it. Checked
/// before SFML tries, because SFML aborts the process when the display does not open.
std::string displayProblem();

}  // namespace physim
