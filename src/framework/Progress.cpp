#include "Progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace physim {
namespace {

double steadySeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string duration(double s) {
    char buf[64];
    if (s < 10) std::snprintf(buf, sizeof buf, "%.1f s", s);
    else if (s < 60) std::snprintf(buf, sizeof buf, "%.0f s", s);
    else if (s < 3600) std::snprintf(buf, sizeof buf, "%.0f min %02.0f s", std::floor(s / 60), std::fmod(s, 60));
    else std::snprintf(buf, sizeof buf, "%.0f h %02.0f min", std::floor(s / 3600), std::floor(std::fmod(s, 3600) / 60));
    return buf;
}

}  // namespace

Progress::Progress(double total, bool enabled)
    : Progress(total, std::cerr, isatty(STDERR_FILENO) != 0, steadySeconds) {
    enabled_ = enabled;
}

Progress::Progress(double total, std::ostream& out, bool terminal, Clock clock)
    : total_(total), out_(&out), terminal_(terminal), enabled_(true), clock_(std::move(clock)) {
    start_ = clock_();
}

std::string Progress::describe(double simulated, double total, double stepsPerSecond, double secondsLeft) {
    char buf[160];
    const double percent = total > 0 ? 100.0 * std::min(simulated / total, 1.0) : 100.0;
    std::snprintf(buf, sizeof buf, "%3.0f%%  t = %.1f of %.1f s  %.0f steps/s  about %s left", percent, simulated,
                  total, stepsPerSecond, duration(secondsLeft).c_str());
    return buf;
}

void Progress::update(double simulated, long long steps) {
    if (!enabled_) return;
    const double now = clock_(), elapsed = now - start_;
    if (elapsed < kQuietFor || now - last_ < (terminal_ ? kBarEvery : kLineEvery)) return;
    last_ = now;
    const double left = simulated > 0 ? (total_ - simulated) * elapsed / simulated : 0.0;
    const std::string text = describe(simulated, total_, static_cast<double>(steps) / elapsed, std::max(left, 0.0));
    if (!terminal_) {
        *out_ << "physim: " << text << '\n' << std::flush;
        return;
    }
    constexpr int kCells = 24;
    const int filled = total_ > 0 ? static_cast<int>(kCells * std::min(simulated / total_, 1.0)) : kCells;
    std::string line = "[" + std::string(static_cast<std::size_t>(filled), '#') +
                       std::string(static_cast<std::size_t>(kCells - filled), '.') + "] " + text;
    const std::size_t width = line.size();
    if (width < barWidth_) line += std::string(barWidth_ - width, ' ');  // the rest of a longer earlier bar
    barWidth_ = width;
    *out_ << '\r' << line << std::flush;
}

void Progress::finish() {
    if (!enabled_ || !terminal_ || barWidth_ == 0) return;
    *out_ << '\r' << std::string(barWidth_, ' ') << '\r' << std::flush;
    barWidth_ = 0;
}

}  // namespace physim
