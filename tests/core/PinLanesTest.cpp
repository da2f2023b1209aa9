// Revolute pins solved four at a time (joints/PinLanes): every lane must give the bits the scalar row gives
// (RevoluteJoint's warmStart and solve through Joints.hpp, which share no code with the lanes), in every build of
// the four-lane loops, so that which rows go in lanes never changes a result.

#include "joints/PinLanes.hpp"
#include "support/JointLanes.hpp"
#include "support/WideCodes.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace physim {
namespace {

test::JointLaneCase makeCase(unsigned seed) {
    return test::makeJointLaneCase(seed, 1.0 / 240.0, [](JointConstraint&, JointData& joint, int, auto& u) {
        RevoluteJoint pin;
        pin.linearImpulse = {u(), u()};
        joint.params = pin;
    });
}

bool sameBits(const test::JointLaneCase& a, const test::JointLaneCase& b) {
    if (!test::sameBodyBits(a, b)) return false;
    for (std::size_t j = 0; j < a.joints.size(); ++j)
        if (!test::sameBits(std::get<RevoluteJoint>(a.joints[j].params).linearImpulse,
                            std::get<RevoluteJoint>(b.joints[j].params).linearImpulse))
            return false;
    return true;
}

TEST(RevolutePinLanes, EveryBuildGivesTheScalarRowsBits) {
    for (unsigned seed = 1; seed <= 20; ++seed) {
        test::JointLaneCase scalar = makeCase(seed);
        test::solveJointRowsOneByOne(scalar, 1);
        for (const WideCode code : test::runnableWideCodes()) {
            test::JointLaneCase lanes = makeCase(seed);
            std::vector<PinBlock> blocks = test::packJointBlocks<PinBlock>(lanes, packPins);
            PinBlock* const begin = blocks.data();
            PinBlock* const end = begin + blocks.size();
            warmStartPins(begin, end, lanes.states(), code);
            solvePins(begin, end, lanes.states(), true, code);
            solvePins(begin, end, lanes.states(), false, code);
            storePins(begin, end, lanes.joints);
            EXPECT_TRUE(sameBits(scalar, lanes)) << "seed " << seed << ", build " << static_cast<int>(code);
        }
    }
}

}  // namespace
}  // namespace physim
