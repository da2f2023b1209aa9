#pragma once
// Progress of a long headless run, on stderr: a bar redrawn in place when stderr is a terminal, else a line
// every few seconds (for logs). A run that ends within a couple of seconds shows nothing.

#include <functional>
#include <ostream>
#include <string>

namespace physim {

class Progress {
public:
    /// Wall-clock seconds from any fixed origin.
    using Clock = std::function<double()>;

    static constexpr double kQuietFor = 2.0;      ///< s of wall time before anything is shown
    static constexpr double kBarEvery = 0.25;     ///< s between redraws of a terminal's bar
    static constexpr double kLineEvery = 5.0;     ///< s between lines when stderr is not a terminal

    /// Reports on std::cerr (a bar if it is a terminal), unless `enabled` is false (--quiet).
    Progress(double totalSimulatedSeconds, bool enabled);
    /// For tests: any stream, terminal or not, and a clock.
    Progress(double totalSimulatedSeconds, std::ostream& out, bool terminal, Clock clock);

    /// After each step: the simulated time so far and the steps done. Reads the clock; prints when due.
    void update(double simulatedSeconds, long long steps);
    /// The run is over: a bar on a terminal is wiped, so the next line starts clean.
    void finish();

    /// One report: "45%  t = 270.0 of 600 s  12345 steps/s  about 12 s left".
    static std::string describe(double simulated, double total, double stepsPerSecond, double secondsLeft);

private:
    double total_;
    std::ostream* out_;
    bool terminal_;
    bool enabled_;
    Clock clock_;
    double start_ = 0.0, last_ = -1.0;
    std::size_t barWidth_ = 0;  // characters of the bar last drawn, to wipe
};

}  // namespace physim
