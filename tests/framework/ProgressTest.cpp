// Progress of a long headless run, with a clock the test moves: when it speaks, what it says, and how.

#include "Progress.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace physim {
namespace {

struct FakeClock {
    double now = 100.0;
    Progress::Clock clock() {
        return [this] { return now; };
    }
};

// Counts non-overlapping occurrences.
int count(const std::string& text, const std::string& what) {
    int n = 0;
    for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + what.size())) ++n;
    return n;
}

TEST(Progress, SaysWhatItDoes) {
    // 270 of 600 simulated seconds in 10 s of wall time at 40 Hz: 45%, 1080 steps/s, 12.2 s left.
    EXPECT_EQ(Progress::describe(270.0, 600.0, 1080.0, 12.2), " 45%  t = 270.0 of 600.0 s  1080 steps/s  about 12 s left");
    EXPECT_NE(Progress::describe(1.0, 7200.0, 40.0, 7199.0).find("about 1 h 59 min left"), std::string::npos);
    EXPECT_NE(Progress::describe(1.0, 200.0, 40.0, 199.0).find("about 3 min 19 s left"), std::string::npos);
}

TEST(Progress, ShortRunsSayNothing) {
    std::ostringstream out;
    FakeClock t;
    Progress p(600.0, out, false, t.clock());
    for (int step = 1; step <= 79; ++step) {
        t.now += 0.025;  // 1.975 s of wall time in all
        p.update(step * 7.5, step);
    }
    p.finish();
    EXPECT_EQ(out.str(), "");
}

TEST(Progress, ALineEveryFiveSecondsInALog) {
    std::ostringstream out;
    FakeClock t;
    Progress p(600.0, out, false, t.clock());
    // 20 s of wall time, 30 simulated seconds per wall second, 40 steps per simulated second.
    for (int ms = 10; ms <= 20000; ms += 10) {
        t.now = 100.0 + ms / 1000.0;
        p.update(0.03 * ms, static_cast<long long>(1.2 * ms));
    }
    p.finish();
    const std::string s = out.str();
    // At 2 s (the first), 7, 12 and 17 s.
    EXPECT_EQ(count(s, "\n"), 4) << s;
    EXPECT_EQ(count(s, "physim: "), 4) << s;
    EXPECT_EQ(s.find('\r'), std::string::npos) << "no carriage returns in a log";
    // At 2 s: 60 of 600 s done (10%), 1200 steps/s, 540 s left at 30 per second = 18 s.
    EXPECT_EQ(s.substr(0, s.find('\n')), "physim:  10%  t = 60.0 of 600.0 s  1200 steps/s  about 18 s left");
}

TEST(Progress, ABarInPlaceOnATerminalWipedAtTheEnd) {
    std::ostringstream out;
    FakeClock t;
    Progress p(60.0, out, true, t.clock());
    for (int ms = 10; ms <= 4000; ms += 10) {
        t.now = 100.0 + ms / 1000.0;
        p.update(0.015 * ms, ms);
    }
    const std::string during = out.str();
    EXPECT_EQ(during.find('\n'), std::string::npos) << "redrawn in place";
    EXPECT_GE(count(during, "\r["), 8) << "every quarter second from 2 s to 4 s";
    EXPECT_NE(during.find("[##########"), std::string::npos) << "about half done at 2 s: 30 of 60 s";
    p.finish();
    const std::string after = out.str();
    EXPECT_EQ(after.back(), '\r') << "the line is wiped for what comes next";
}

TEST(Progress, OffWhenQuiet) {
    Progress p(600.0, false);  // --quiet: stderr untouched
    testing::internal::CaptureStderr();
    for (int i = 0; i < 1000; ++i) p.update(i, i);
    p.finish();
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

}  // namespace
}  // namespace physim
