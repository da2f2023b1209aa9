#include <physim/framework/RunOptions.hpp>

#include <gtest/gtest.h>

namespace physim {
namespace {

std::string errorOf(const std::vector<std::string>& args) {
    try {
        parseRunOptions(args);
    } catch (const UsageError& e) {
        return e.what();
    }
    return "";
}

TEST(RunOptions, ParsesEveryFlag) {
    const RunOptions o = parseRunOptions(
        {"--seconds", "2.5", "--out", "dir", "--hz", "120", "--max-steps-per-frame", "3", "--size",
         "800x600", "--screenshot", "shot.png", "--param", "speed=12.5", "--param", "count=3"});
    EXPECT_EQ(o.screenshot, "shot.png");
    EXPECT_FALSE(o.headless);
    EXPECT_EQ(o.parameters, (std::vector<std::pair<std::string, double>>{{"speed", 12.5}, {"count", 3.0}}));
    EXPECT_EQ(o.seconds, 2.5);
    EXPECT_EQ(o.outDir, "dir");
    EXPECT_EQ(o.hz, 120.0);
    EXPECT_EQ(o.maxStepsPerFrame, 3);
    EXPECT_EQ(o.width, 800);
    EXPECT_EQ(o.height, 600);
    EXPECT_TRUE(parseRunOptions({"--help"}).help);
    EXPECT_FALSE(parseRunOptions({}).headless);
    EXPECT_FALSE(parseRunOptions({}).maxStepsPerFrame) << "unset: the window paces its frames (FramePacer)";
    EXPECT_TRUE(parseRunOptions({"--headless"}).headless);
}

// --name=value is --name value, for every option that takes a value.
TEST(RunOptions, AcceptsNameEqualsValue) {
    const RunOptions o = parseRunOptions({"--headless", "--seconds=2", "--out=a=b", "--hz=60", "--size=640x360",
                                          "--max-steps-per-frame=2", "--param=angle=45"});
    EXPECT_EQ(o.seconds, 2.0);
    EXPECT_EQ(o.outDir, "a=b") << "only the first '=' separates";
    EXPECT_EQ(o.hz, 60.0);
    EXPECT_EQ(o.width, 640);
    EXPECT_EQ(o.height, 360);
    EXPECT_EQ(o.maxStepsPerFrame, 2);
    EXPECT_EQ(o.parameters, (std::vector<std::pair<std::string, double>>{{"angle", 45.0}}));
    EXPECT_NE(errorOf({"--headless=yes"}).find("takes no value"), std::string::npos);
    EXPECT_NE(errorOf({"--seconds="}).find("--seconds"), std::string::npos);
}

// Values that parse but cannot be run are refused up front, not discovered as a run that does nothing.
TEST(RunOptions, AbsurdValuesAreRefused) {
    // 1e18 s is 4e19 steps at 40 Hz, more than a step counter holds: the run would do nothing and exit 0.
    EXPECT_NE(errorOf({"--headless", "--seconds", "1e18"}).find("1e18"), std::string::npos);
    EXPECT_EQ(parseRunOptions({"--seconds", "1e7"}).seconds, 1e7) << "the limit itself is allowed";
    // Below 1 Hz a step is over a second, which the world refuses as a unit mistake.
    EXPECT_NE(errorOf({"--hz", "0.5"}).find("0.5"), std::string::npos);
    EXPECT_NE(errorOf({"--headless", "--screenshot", "x.png"}).find("--screenshot"), std::string::npos);
    EXPECT_NE(errorOf({"--screenshot", "x.png", "--headless"}).find("--headless"), std::string::npos);
    EXPECT_NE(errorOf({"--param", "speed"}).find("NAME=VALUE"), std::string::npos);
    EXPECT_NE(errorOf({"--param", "=3"}).find("NAME=VALUE"), std::string::npos);
    EXPECT_NE(errorOf({"--param", "speed=fast"}).find("fast"), std::string::npos);
    EXPECT_NE(errorOf({"--param", "speed=inf"}).find("inf"), std::string::npos) << "one number rule: finite";
}

TEST(RunOptions, BadArgumentsNameTheValue) {
    EXPECT_NE(errorOf({"--bogus"}).find("--bogus"), std::string::npos);
    EXPECT_NE(errorOf({"--seconds", "-1"}).find("-1"), std::string::npos);
    EXPECT_NE(errorOf({"--seconds", "nan"}).find("nan"), std::string::npos);
    EXPECT_NE(errorOf({"--seconds", "inf"}).find("inf"), std::string::npos);
    EXPECT_NE(errorOf({"--seconds", "abc"}).find("abc"), std::string::npos);
    EXPECT_NE(errorOf({"--seconds"}).find("needs a value"), std::string::npos);
    EXPECT_NE(errorOf({"--seconds", "1e8"}).find("1e8"), std::string::npos) << "just past the longest run";
    static_assert(RunOptions::maxSeconds * RunOptions::maxHz < 9.2e18, "--seconds x --hz must count steps in a long long");
    EXPECT_NE(errorOf({"--hz", "0"}).find("--hz"), std::string::npos);
    EXPECT_NE(errorOf({"--hz", "-40"}).find("-40"), std::string::npos);
    EXPECT_NE(errorOf({"--hz", "1e9"}).find("1e9"), std::string::npos);
    EXPECT_NE(errorOf({"--max-steps-per-frame", "0"}).find("0"), std::string::npos);
    EXPECT_NE(errorOf({"--size", "big"}).find("big"), std::string::npos);
    EXPECT_NE(errorOf({"--out", ""}).find("--out"), std::string::npos);
    EXPECT_NE(errorOf({"--screenshot", ""}).find("--screenshot"), std::string::npos);
}

TEST(RunOptions, RecordTakesAnIdAndAKnownQuantityAndNeedsOut) {
    const RunOptions o = parseRunOptions({"--out", "d", "--record", "3:kinetic_energy", "--record=12:y"});
    ASSERT_EQ(o.records.size(), 2u);
    EXPECT_EQ(o.records[0].entity, 3);
    EXPECT_EQ(o.records[0].quantity, "kinetic_energy");
    EXPECT_EQ(o.records[1].entity, 12);
    EXPECT_EQ(o.records[1].quantity, "y");
    EXPECT_NE(errorOf({"--out", "d", "--record", "3:mass"}).find("'mass'"), std::string::npos);
    EXPECT_NE(errorOf({"--out", "d", "--record", "box:x"}).find("box:x"), std::string::npos);
    EXPECT_NE(errorOf({"--out", "d", "--record", "-1:x"}).find("-1:x"), std::string::npos);
    EXPECT_NE(errorOf({"--out", "d", "--record", "3"}).find("ID:QUANTITY"), std::string::npos);
    EXPECT_NE(errorOf({"--record", "3:x"}).find("--out"), std::string::npos);
    EXPECT_NE(usage("p", "t").find("--record ID:QUANTITY"), std::string::npos);
}

}  // namespace
}  // namespace physim
