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
        {"--headless", "--seconds", "2.5", "--out", "dir", "--hz", "120", "--max-steps-per-frame", "3", "--size",
         "800x600", "--screenshot", "shot.png"});
    EXPECT_EQ(o.screenshot, "shot.png");
    EXPECT_TRUE(o.headless);
    EXPECT_EQ(o.seconds, 2.5);
    EXPECT_EQ(o.outDir, "dir");
    EXPECT_EQ(o.hz, 120.0);
    EXPECT_EQ(o.maxStepsPerFrame, 3);
    EXPECT_EQ(o.width, 800);
    EXPECT_EQ(o.height, 600);
    EXPECT_TRUE(parseRunOptions({"--help"}).help);
    EXPECT_FALSE(parseRunOptions({}).headless);
}

TEST(RunOptions, BadArgumentsNameTheValue) {
    EXPECT_NE(errorOf({"--bogus"}).find("--bogus"), std::string::npos);
    EXPECT_NE(errorOf({"--seconds", "-1"}).find("-1"), std::string::npos);
    EXPECT_NE(errorOf({"--seconds", "nan"}).find("nan"), std::string::npos);
    EXPECT_NE(errorOf({"--seconds", "inf"}).find("inf"), std::string::npos);
    EXPECT_NE(errorOf({"--seconds", "abc"}).find("abc"), std::string::npos);
    EXPECT_NE(errorOf({"--seconds"}).find("needs a value"), std::string::npos);
    // Beyond the longest run the step counter holds at the highest rate (it used to run 0 steps and exit 0).
    EXPECT_NE(errorOf({"--seconds", "1e18"}).find("1e18"), std::string::npos);
    EXPECT_EQ(parseRunOptions({"--seconds", "1e9"}).seconds, RunOptions::maxSeconds);
    static_assert(RunOptions::maxSeconds * RunOptions::maxHz < 9.2e18, "--seconds x --hz must count steps in a long long");
    EXPECT_NE(errorOf({"--hz", "0"}).find("--hz"), std::string::npos);
    EXPECT_NE(errorOf({"--hz", "-40"}).find("-40"), std::string::npos);
    EXPECT_NE(errorOf({"--hz", "1e9"}).find("1e9"), std::string::npos);
    EXPECT_NE(errorOf({"--max-steps-per-frame", "0"}).find("0"), std::string::npos);
    EXPECT_NE(errorOf({"--size", "big"}).find("big"), std::string::npos);
    EXPECT_NE(errorOf({"--out", ""}).find("--out"), std::string::npos);
    EXPECT_NE(errorOf({"--screenshot", ""}).find("--screenshot"), std::string::npos);
}

}  // namespace
}  // namespace physim
