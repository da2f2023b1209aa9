// Wheel joints solved four at a time (joints/WheelLanes): every lane must give the bits the scalar row gives
// (WheelJoint's warmStart and solve through Joints.hpp, which share no code with the lanes), in every build of the
// four-lane loops, with the motor and the spring each on or off, a motor held at its cap, and fixed or kinematic
// ends, so that which rows go in lanes never changes a result.

#include "JointData.hpp"
#include "Joints.hpp"
#include "joints/WheelLanes.hpp"
#include "support/WideCodes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace physim {
namespace {

constexpr int kBodies = 24;

struct Case {
    std::vector<SolverBody> bodies;  // a still body, then kBodies (states = &bodies[1])
    std::vector<JointData> joints;
    std::vector<JointConstraint> rows;
    std::vector<std::vector<int>> blocks;  // rows by block: up to kLanes rows sharing no moving body
};

Case makeCase(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Case c;
    c.bodies.resize(kBodies + 1);
    for (int i = 1; i <= kBodies; ++i) {
        SolverBody& s = c.bodies[i];
        s.v = {u(rng), u(rng)};
        s.w = 3.0 * u(rng);
        s.dAngle = 0.1 * u(rng);
        s.dp = {0.01 * u(rng), 0.01 * u(rng)};
        s.dq = Rotation::fromAngle(s.dAngle);
    }
    const double h = 1.0 / 240.0;
    const Softness rod = makeSoftness(60.0, 5.0, h);
    // Blocks of 4, 3, 4, 1 and 2 rows; each block's rows take distinct bodies, later blocks reuse them. Body 23 is
    // kinematic (no mass: read, never written); kNullIndex is a static end.
    const int sizes[] = {4, 3, 4, 1, 2};
    int next = 0;
    for (const int size : sizes) {
        std::vector<int> block;
        for (int lane = 0; lane < size; ++lane) {
            JointConstraint row;
            row.joint = static_cast<std::uint32_t>(c.joints.size());
            row.indexA = (next % 5 == 4) ? kNullIndex : static_cast<std::int32_t>((2 * lane) % kBodies);
            row.indexB = static_cast<std::int32_t>((2 * lane + 1 + 8 * (next % 2)) % kBodies);
            if (next == 6) row.indexA = 23;
            row.invMassA = row.indexA == kNullIndex || row.indexA == 23 ? 0.0 : 0.5 + std::abs(u(rng));
            row.invIA = row.invMassA == 0.0 ? 0.0 : 2.0 + std::abs(u(rng));
            row.invMassB = 0.5 + std::abs(u(rng));
            row.invIB = 2.0 + std::abs(u(rng));
            row.anchorA = {0.5 * u(rng), 0.5 * u(rng)};
            row.anchorB = {0.5 * u(rng), 0.5 * u(rng)};
            row.deltaCenter = {u(rng), u(rng)};
            const double turn = M_PI * u(rng);
            row.axis = {std::cos(turn), std::sin(turn)};
            row.softness = rod;
            row.invH = 1.0 / h;
            row.axialMass = 1.0 / (row.invIA + row.invIB);
            WheelJoint wheel;
            // The motor on in two rows of three; one in four of those capped so low that it saturates.
            wheel.setMotor(next % 3 != 2, 10.0 * u(rng), next % 4 == 1 ? 1e-3 : 50.0 * std::abs(u(rng)));
            // The spring on in most rows; off, or on at 0 Hz (no spring), in a few.
            wheel.setSpring(next % 5 != 3, next % 7 == 5 ? 0.0 : 1.0 + 5.0 * std::abs(u(rng)), std::abs(u(rng)));
            row.maxImpulse = wheel.maxMotorTorque * h;
            row.spring = wheel.enableSpring && wheel.hertz > 0.0 ? makeSoftness(wheel.hertz, wheel.dampingRatio, h)
                                                               : Softness{};
            wheel.normalImpulse = u(rng);
            if (wheel.enableSpring) wheel.springImpulse = u(rng);
            if (wheel.enableMotor) wheel.motorImpulse = 0.5 * row.maxImpulse * u(rng);
            JointData joint;
            joint.params = wheel;
            c.joints.push_back(joint);
            block.push_back(static_cast<int>(c.rows.size()));
            c.rows.push_back(row);
            ++next;
        }
        c.blocks.push_back(block);
    }
    return c;
}

template <class T>
bool same(const T& x, const T& y) {
    return std::memcmp(&x, &y, sizeof x) == 0;
}

bool sameBits(const Case& a, const Case& b) {
    if (std::memcmp(a.bodies.data(), b.bodies.data(), a.bodies.size() * sizeof(SolverBody)) != 0) return false;
    for (std::size_t j = 0; j < a.joints.size(); ++j) {
        const WheelJoint& x = std::get<WheelJoint>(a.joints[j].params);
        const WheelJoint& y = std::get<WheelJoint>(b.joints[j].params);
        if (!same(x.normalImpulse, y.normalImpulse) || !same(x.springImpulse, y.springImpulse) ||
            !same(x.motorImpulse, y.motorImpulse) || !same(x.lastAxis, y.lastAxis))
            return false;
    }
    return true;
}

TEST(WheelJointLanes, EveryBuildGivesTheScalarRowsBits) {
    int saturated = 0;  // motors at their cap after the passes: the clamp's rule was exercised
    for (unsigned seed = 1; seed <= 20; ++seed) {
        Case scalar = makeCase(seed);
        SolverBody* states = scalar.bodies.data() + 1;
        // The scalar rows, row after row: two substeps of warm start, a solve pass, a relax pass.
        for (int substep = 0; substep < 2; ++substep) {
            for (const JointConstraint& row : scalar.rows) warmStartJoint(row, scalar.joints[row.joint], states);
            for (const bool useBias : {true, false})
                for (const JointConstraint& row : scalar.rows)
                    solveJoint(row, scalar.joints[row.joint], states, useBias);
        }
        for (const JointConstraint& row : scalar.rows) {
            const WheelJoint& wheel = std::get<WheelJoint>(scalar.joints[row.joint].params);
            if (wheel.enableMotor && std::abs(wheel.motorImpulse) == row.maxImpulse) ++saturated;
        }

        for (const WideCode code : test::runnableWideCodes()) {
            Case lanes = makeCase(seed);
            SolverBody* laneStates = lanes.bodies.data() + 1;
            std::vector<WheelBlock> blocks(lanes.blocks.size());
            for (std::size_t b = 0; b < blocks.size(); ++b) {
                std::vector<const JointConstraint*> rows;
                for (const int r : lanes.blocks[b]) rows.push_back(&lanes.rows[r]);
                packWheels(blocks[b], rows.data(), static_cast<std::uint32_t>(rows.size()), lanes.joints);
            }
            WheelBlock* const begin = blocks.data();
            WheelBlock* const end = begin + blocks.size();
            for (int substep = 0; substep < 2; ++substep) {
                warmStartWheels(begin, end, laneStates, code);
                solveWheels(begin, end, laneStates, true, code);
                solveWheels(begin, end, laneStates, false, code);
            }
            storeWheels(begin, end, lanes.joints);
            EXPECT_TRUE(sameBits(scalar, lanes)) << "seed " << seed << ", build " << static_cast<int>(code);
        }
    }
    EXPECT_GT(saturated, 0);
}

TEST(WheelJointLanes, ALimitKeepsTheRowAlone) {
    WheelJoint wheel;
    EXPECT_TRUE(wheel.solvesInLanes());
    wheel.setLimits(true, -0.1, 0.1);
    EXPECT_FALSE(wheel.solvesInLanes());
    JointData joint;
    joint.params = wheel;
    EXPECT_EQ(jointLanes(joint), RowLanes::None);
}

}  // namespace
}  // namespace physim
