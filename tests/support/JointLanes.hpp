#pragma once
// Rows of one joint kind for the tests that hold the four-lane joint loops (joints/PinLanes, joints/WheelLanes) to
// the scalar rows' bits: 24 moving bodies with random velocities (every sixth spinning fast, past the pins' arc cap)
// and substep motion; blocks of 4, 3, 4, 1 and 2 rows, each block's rows on distinct bodies and later blocks reusing
// them; body 23 kinematic (no mass: read, never written) and a static end (kNullIndex) in every fifth row. The
// kind's own terms come from the test.

#include "JointData.hpp"
#include "Joints.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace physim::test {

struct JointLaneCase {
    static constexpr int kBodies = 24;
    std::vector<SolverBody> bodies;  // a still body, then kBodies
    std::vector<JointData> joints;
    std::vector<JointConstraint> rows;
    std::vector<std::vector<int>> blocks;  // rows by block: up to kLanes rows sharing no moving body

    SolverBody* states() { return bodies.data() + 1; }
};

/// The case for `seed` at substep h (s). `kind(row, joint, next, u)` draws row number `next`'s own terms after its
/// bodies, masses, anchors, centres and rod softness: the row's other fields and the joint's parameters; u() is
/// uniform in [-1, 1].
template <class Kind>
JointLaneCase makeJointLaneCase(unsigned seed, double h, Kind&& kind) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    auto u = [&] { return uniform(rng); };
    constexpr int kBodies = JointLaneCase::kBodies;
    JointLaneCase c;
    c.bodies.resize(kBodies + 1);
    for (int i = 1; i <= kBodies; ++i) {
        SolverBody& s = c.bodies[i];
        s.v = {u(), u()};
        s.w = (i % 6 == 0 ? 600.0 : 3.0) * u();  // every sixth spins fast: its turn a substep passes the arcs' cap
        s.dAngle = 0.1 * u();
        s.dp = {0.01 * u(), 0.01 * u()};
        s.dq = Rotation::fromAngle(s.dAngle);
    }
    const Softness rod = makeSoftness(60.0, 5.0, h);
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
            row.invMassA = row.indexA == kNullIndex || row.indexA == 23 ? 0.0 : 0.5 + std::abs(u());
            row.invIA = row.invMassA == 0.0 ? 0.0 : 2.0 + std::abs(u());
            row.invMassB = 0.5 + std::abs(u());
            row.invIB = 2.0 + std::abs(u());
            row.anchorA = {0.5 * u(), 0.5 * u()};
            row.anchorB = {0.5 * u(), 0.5 * u()};
            row.deltaCenter = {u(), u()};
            row.softness = rod;
            row.h = h;  // the pin's arcs (solvePoint)
            row.invH = 1.0 / h;
            JointData joint;
            kind(row, joint, next, u);
            c.joints.push_back(joint);
            block.push_back(static_cast<int>(c.rows.size()));
            c.rows.push_back(row);
            ++next;
        }
        c.blocks.push_back(block);
    }
    return c;
}

/// The scalar rows, row after row (Joints.hpp, which shares no code with the lanes): `substeps` times a warm start,
/// a solve pass and a relax pass.
inline void solveJointRowsOneByOne(JointLaneCase& c, int substeps) {
    for (int substep = 0; substep < substeps; ++substep) {
        for (const JointConstraint& row : c.rows) warmStartJoint(row, c.joints[row.joint], c.states());
        for (const bool useBias : {true, false})
            for (const JointConstraint& row : c.rows) solveJoint(row, c.joints[row.joint], c.states(), useBias);
    }
}

/// Runs `pass(begin, end)` over `blocks` a colour at a time, `perColour` blocks to a colour (1 for a case, whose
/// blocks reuse each other's bodies; 2 for sideBySide's), as the solver calls the loops.
template <class Block, class Pass>
void byColour(std::vector<Block>& blocks, std::size_t perColour, Pass&& pass) {
    for (std::size_t b = 0; b < blocks.size(); b += perColour)
        pass(blocks.data() + b, blocks.data() + std::min(b + perColour, blocks.size()));
}

/// The case's blocks packed for the lanes by `pack` (packPins, packWheels).
template <class Block, class Pack>
std::vector<Block> packJointBlocks(JointLaneCase& c, Pack&& pack) {
    std::vector<Block> blocks(c.blocks.size());
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        std::vector<const JointConstraint*> rows;
        for (const int r : c.blocks[b]) rows.push_back(&c.rows[static_cast<std::size_t>(r)]);
        pack(blocks[b], rows.data(), static_cast<std::uint32_t>(rows.size()), c.joints);
    }
    return blocks;
}

/// Cases a and b side by side on disjoint bodies (b's rows name bodies JointLaneCase::kBodies further on, and joints
/// after a's), their blocks alternating a's, b's: blocks 2k and 2k + 1 share no moving body, as the blocks of one
/// joint colour, which the four-lane loops take two at a time (LaneBlocks.hpp's inPairs).
inline JointLaneCase sideBySide(const JointLaneCase& a, const JointLaneCase& b) {
    JointLaneCase c;
    c.bodies = a.bodies;
    c.bodies.insert(c.bodies.end(), b.bodies.begin() + 1, b.bodies.end());
    c.joints = a.joints;
    c.joints.insert(c.joints.end(), b.joints.begin(), b.joints.end());
    const auto moved = [](std::int32_t index) {
        return index == kNullIndex ? index : index + JointLaneCase::kBodies;
    };
    for (std::size_t k = 0; k < a.blocks.size(); ++k)
        for (const bool second : {false, true}) {
            const JointLaneCase& from = second ? b : a;
            std::vector<int> block;
            for (const int r : from.blocks[k]) {
                JointConstraint row = from.rows[static_cast<std::size_t>(r)];
                if (second) {
                    row.indexA = moved(row.indexA);
                    row.indexB = moved(row.indexB);
                    row.joint += static_cast<std::uint32_t>(a.joints.size());
                }
                block.push_back(static_cast<int>(c.rows.size()));
                c.rows.push_back(row);
            }
            c.blocks.push_back(block);
        }
    return c;
}

/// Whether two values have the same bits (-0 and +0 differ, a NaN equals itself).
template <class T>
bool sameBits(const T& x, const T& y) {
    return std::memcmp(&x, &y, sizeof x) == 0;
}

/// Whether the two cases' bodies have the same bits.
inline bool sameBodyBits(const JointLaneCase& a, const JointLaneCase& b) {
    return std::memcmp(a.bodies.data(), b.bodies.data(), a.bodies.size() * sizeof(SolverBody)) == 0;
}

}  // namespace physim::test
