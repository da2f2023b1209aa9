// Parameters: declared with a range, set by name, bad names and values refused with a message naming them.

#include <physim/framework/Parameters.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace physim {
namespace {

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

TEST(Parameters, DeclareSetGetAndRefuseByName) {
    Parameters p;
    p.add("speed", "launch speed (m/s)", 20.0, 1.0, 40.0);
    p.add("count", "bodies", 5, 1, 10, true);
    EXPECT_EQ(p.get("speed"), 20.0);
    EXPECT_EQ(p.getInt("count"), 5);
    p.set("speed", 12.5);
    EXPECT_EQ(p.get("speed"), 12.5);
    EXPECT_NE(errorOf([&] { p.set("speed", 41.0); }).find("speed"), std::string::npos);
    EXPECT_NE(errorOf([&] { p.set("speed", NAN); }).find("nan"), std::string::npos);
    EXPECT_NE(errorOf([&] { p.set("count", 2.5); }).find("count"), std::string::npos);
    EXPECT_NE(errorOf([&] { p.set("sped", 1.0); }).find("it has: speed, count"), std::string::npos);
    EXPECT_EQ(p.get("speed"), 12.5) << "a refused value changes nothing";
    EXPECT_NE(errorOf([&] { p.add("speed", "", 1.0, 0.0, 2.0); }).find("twice"), std::string::npos);
    EXPECT_NE(errorOf([&] { p.add("a b", "", 1.0, 0.0, 2.0); }).find("a b"), std::string::npos);
    EXPECT_NE(errorOf([&] { p.add("x", "", 3.0, 0.0, 2.0); }).find("x"), std::string::npos);
    EXPECT_NE(errorOf([&] { p.add("y", "", 1.0, 2.0, 0.0); }).find("min <= max"), std::string::npos);

    Parameters fresh;
    fresh.add("speed", "", 20.0, 1.0, 40.0);
    fresh.add("angle", "", 60.0, 5.0, 85.0);
    fresh.copyValuesFrom(p);  // only the names both have
    EXPECT_EQ(fresh.get("speed"), 12.5);
    EXPECT_EQ(fresh.get("angle"), 60.0);
    EXPECT_NE(fresh.describe().find("angle"), std::string::npos);
}

}  // namespace
}  // namespace physim
