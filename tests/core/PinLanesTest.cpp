// Revolute pins solved four at a time (joints/PinLanes): every lane must give the bits the scalar row gives
// (RevoluteJoint's warmStart and solve through Joints.hpp, which share no code with the lanes), in every build of
// the four-lane loops, so that which rows go in lanes never changes a result.

#include "JointData.hpp"
#include "Joints.hpp"
#include "joints/PinLanes.hpp"
#include "support/WideCodes.hpp"

#include <gtest/gtest.h>

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
    const Softness rod = makeSoftness(60.0, 5.0, 1.0 / 240.0);
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
            row.softness = rod;
            row.invH = 240.0;
            RevoluteJoint pin;
            pin.linearImpulse = {u(rng), u(rng)};
            JointData joint;
            joint.params = pin;
            c.joints.push_back(joint);
            block.push_back(static_cast<int>(c.rows.size()));
            c.rows.push_back(row);
            ++next;
        }
        c.blocks.push_back(block);
    }
    return c;
}

bool sameBits(const Case& a, const Case& b) {
    if (std::memcmp(a.bodies.data(), b.bodies.data(), a.bodies.size() * sizeof(SolverBody)) != 0) return false;
    for (std::size_t j = 0; j < a.joints.size(); ++j) {
        const Vec2 x = std::get<RevoluteJoint>(a.joints[j].params).linearImpulse;
        const Vec2 y = std::get<RevoluteJoint>(b.joints[j].params).linearImpulse;
        if (std::memcmp(&x, &y, sizeof x) != 0) return false;
    }
    return true;
}

TEST(RevolutePinLanes, EveryBuildGivesTheScalarRowsBits) {
    for (unsigned seed = 1; seed <= 20; ++seed) {
        Case scalar = makeCase(seed);
        SolverBody* states = scalar.bodies.data() + 1;
        // The scalar rows, row after row: warm start, a solve pass, a relax pass.
        for (const JointConstraint& row : scalar.rows) warmStartJoint(row, scalar.joints[row.joint], states);
        for (const bool useBias : {true, false})
            for (const JointConstraint& row : scalar.rows) solveJoint(row, scalar.joints[row.joint], states, useBias);

        for (const WideCode code : test::runnableWideCodes()) {
            Case lanes = makeCase(seed);
            SolverBody* laneStates = lanes.bodies.data() + 1;
            std::vector<PinBlock> blocks(lanes.blocks.size());
            for (std::size_t b = 0; b < blocks.size(); ++b) {
                std::vector<const JointConstraint*> rows;
                for (const int r : lanes.blocks[b]) rows.push_back(&lanes.rows[r]);
                packPins(blocks[b], rows.data(), static_cast<std::uint32_t>(rows.size()), lanes.joints);
            }
            PinBlock* const begin = blocks.data();
            PinBlock* const end = begin + blocks.size();
            warmStartPins(begin, end, laneStates, code);
            solvePins(begin, end, laneStates, true, code);
            solvePins(begin, end, laneStates, false, code);
            storePins(begin, end, lanes.joints);
            EXPECT_TRUE(sameBits(scalar, lanes)) << "seed " << seed << ", build " << static_cast<int>(code);
        }
    }
}

}  // namespace
}  // namespace physim
