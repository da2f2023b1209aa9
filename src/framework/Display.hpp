#pragma once
// The check that a window can open, done before SFML tries (SFML aborts the process when the display does not
// open). The connection it opens is held for the whole run: an X server resets when its last client leaves
// (Xvfb under xvfb-run does), and a connection closed just before SFML opens its own would leave SFML knocking
// on a server in the middle of that reset.

#include <string>

struct _XDisplay;

namespace physim {

class DisplayConnection {
public:
    /// Opens the display DISPLAY names; problem() says why when it cannot.
    DisplayConnection();
    ~DisplayConnection();
    DisplayConnection(const DisplayConnection&) = delete;
    DisplayConnection& operator=(const DisplayConnection&) = delete;

    /// "" when the display is open; else why not (DISPLAY unset, or no X server answering at it).
    const std::string& problem() const { return problem_; }

private:
    _XDisplay* display_ = nullptr;
    std::string problem_;
};

}  // namespace physim
