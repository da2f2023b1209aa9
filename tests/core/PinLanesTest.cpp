// Revolute pins solved four at a time (joints/PinLanes): every lane must give the bits the scalar row gives
// (RevoluteJoint's warmStart and solve through Joints.hpp, which share no code with the lanes), in every build of
// the four-lane loops, so that which rows go in lanes never changes a result.

#include "joints/PinLanes.hpp"
#include "physim/core/World.hpp"
#include "support/JointLanes.hpp"
#include "support/WideCodes.hpp"

#include <gtest/gtest.h>

#include <string>
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

// Each build of the loops on a copy of `start`, `perColour` blocks to a call: its bits must be the scalar rows'.
void expectScalarBits(const test::JointLaneCase& scalar, const test::JointLaneCase& start, std::size_t perColour,
                      const std::string& what) {
    for (const WideCode code : test::runnableWideCodes()) {
        test::JointLaneCase lanes = start;
        std::vector<PinBlock> blocks = test::packJointBlocks<PinBlock>(lanes, packPins);
        test::byColour(blocks, perColour, [&](PinBlock* b, PinBlock* e) { warmStartPins(b, e, lanes.states(), code); });
        for (const bool useBias : {true, false})
            test::byColour(blocks, perColour, [&](PinBlock* b, PinBlock* e) {
                solvePins(b, e, lanes.states(), useBias, code);
            });
        storePins(blocks.data(), blocks.data() + blocks.size(), lanes.joints);
        EXPECT_TRUE(sameBits(scalar, lanes)) << what << ", build " << static_cast<int>(code);
    }
}

// The scalar rows run a warm start, a solve and a relax pass over all rows; the lanes a colour (a call) at a time.
// Side by side, two blocks go to each call, which the loops take together (inPairs).
TEST(RevolutePinLanes, EveryBuildGivesTheScalarRowsBits) {
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const test::JointLaneCase start = makeCase(seed);
        test::JointLaneCase scalar = start;
        test::solveJointRowsOneByOne(scalar, 1);
        expectScalarBits(scalar, start, 1, "seed " + std::to_string(seed));
        const test::JointLaneCase pairs = test::sideBySide(start, makeCase(seed + 100));
        test::JointLaneCase pairsScalar = pairs;
        test::solveJointRowsOneByOne(pairsScalar, 1);
        expectScalarBits(pairsScalar, pairs, 2, "side by side, seed " + std::to_string(seed));
    }
}

// A step that keeps the last one's layout makes its pin blocks ready from the bodies (refreshPins) instead of
// preparing their rows again (jointRow) and packing them (packPins); a world with the energy ledger on does the
// latter every step, and the ledger changes no bit. So the two worlds must agree bit for bit, step after step,
// through what a kept layout must notice: a static anchor moved, a body's centre of mass moved by a new shape, a
// motor switched on and off (the pin leaves the lanes and comes back), another time step.
TEST(RevolutePinLanes, AKeptLayoutsBlocksAreMadeReadyAsPreparedRowsWouldBe) {
    struct Grid {
        std::vector<BodyId> bodies;
        std::vector<JointId> pins;
        BodyId anchor;
    };
    auto build = [](World& w) {
        Grid g;
        BodyDef fixed;
        fixed.type = BodyType::Static;
        fixed.shape = makeCircle(0.2);
        fixed.collides = false;
        g.anchor = w.createBody(fixed);
        constexpr int kSide = 6;  // 6 x 6 discs, each pinned to the one above and the one on its left
        for (int k = 0; k < kSide; ++k)
            for (int i = 0; i < kSide; ++i) {
                BodyDef d;
                d.shape = makeCircle(0.3);
                d.position = {1.0 * k + 0.5, -1.0 * i};
                d.angularVelocity = 0.3 * (k - i);
                d.collides = false;
                g.bodies.push_back(w.createBody(d));
            }
        auto at = [&](int k, int i) { return g.bodies[static_cast<std::size_t>(k * kSide + i)]; };
        auto pin = [&](BodyId a, BodyId b, Vec2 p) {
            RevoluteJointDef def;
            def.bodyA = a;
            def.bodyB = b;
            def.anchor = p;
            g.pins.push_back(w.createRevoluteJoint(def));
        };
        pin(g.anchor, at(0, 0), {0.0, 0.0});
        for (int k = 0; k < kSide; ++k)
            for (int i = 0; i < kSide; ++i) {
                if (i > 0) pin(at(k, i - 1), at(k, i), {1.0 * k + 0.5, -1.0 * i + 0.5});
                if (k > 0) pin(at(k - 1, i), at(k, i), {1.0 * k, -1.0 * i});
            }
        return g;
    };
    WorldSettings settings;
    settings.enableSleep = false;
    World on(settings), off(settings);
    const Grid a = build(on), b = build(off);
    on.setEnergyLedger(true);
    int kept = 0;
    for (int s = 0; s < 240; ++s) {
        for (auto [world, grid] : {std::pair<World*, const Grid*>{&on, &a}, {&off, &b}}) {
            if (s == 60) world->setTransform(grid->anchor, {0.1, 0.05}, 0.2);
            if (s == 100) {
                ShapeDef part;
                part.geometry = Circle{{0.4, 0.0}, 0.2};
                world->createShape(grid->bodies[7], part);
            }
            if (s == 140) world->setJointMotor(grid->pins[5], true, 1.0, 5.0);
            if (s == 160) world->setJointMotor(grid->pins[5], false, 0.0, 0.0);
            world->step(s < 200 ? 1.0 / 60.0 : 1.0 / 90.0);
        }
        if (!off.profile().rowsLaidOut) ++kept;
        ASSERT_EQ(on.stateHash(), off.stateHash()) << "step " << s;
        if (s == 150) {
            EXPECT_NE(off.jointMotorTorque(b.pins[5]), 0.0) << "the motor acts: its row left the lanes";
        }
    }
    EXPECT_GT(kept, 200) << "most steps kept their layout, and made their pin blocks ready from the bodies";
}

}  // namespace
}  // namespace physim
