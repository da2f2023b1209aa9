#pragma once
// Ctrl-C (SIGINT) and SIGTERM during a run: the first asks the runner to stop at the end of its current step, so it
// writes what it recorded and exits with 128 + the signal's number (130, 143); a second ends the process at once
// with that code. Internal.

#include <csignal>

namespace physim {

class InterruptWatch {
public:
    /// Catches SIGINT and SIGTERM, keeping the handlers it replaces.
    InterruptWatch();
    /// Puts the replaced handlers back.
    ~InterruptWatch();
    InterruptWatch(const InterruptWatch&) = delete;
    InterruptWatch& operator=(const InterruptWatch&) = delete;

    /// 0 while no signal came; else the first one's number.
    int signal() const;
    /// Catches the signals again if a library took them over since (ROOT installs its own when it starts up, which
    /// may happen during the run); cheap enough to call once per frame.
    void reassert();

private:
    struct sigaction previous_[2];
};

/// The exit status of a run ended by signal `number`.
inline int interruptedStatus(int number) { return 128 + number; }

}  // namespace physim
