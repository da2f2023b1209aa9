#include "Interrupts.hpp"

#include <cstdlib>

namespace physim {
namespace {

constexpr int kSignals[2] = {SIGINT, SIGTERM};

// A signal handler may only store to a volatile sig_atomic_t with static storage: this is the one such value, and
// only InterruptWatch reads it.
volatile std::sig_atomic_t received = 0;

extern "C" void onSignal(int number) {
    if (received != 0) std::_Exit(interruptedStatus(received));  // the second: at once, without unwinding
    received = number;
}

void install(int number, struct sigaction* previous) {
    struct sigaction action {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(number, &action, previous);
}

}  // namespace

InterruptWatch::InterruptWatch() {
    received = 0;
    for (int i = 0; i < 2; ++i) install(kSignals[i], &previous_[i]);
}

InterruptWatch::~InterruptWatch() {
    for (int i = 0; i < 2; ++i) sigaction(kSignals[i], &previous_[i], nullptr);
}

int InterruptWatch::signal() const { return received; }

void InterruptWatch::reassert() {
    for (const int number : kSignals) {
        struct sigaction now {};
        sigaction(number, nullptr, &now);
        if (now.sa_handler != onSignal) install(number, nullptr);
    }
}

}  // namespace physim
