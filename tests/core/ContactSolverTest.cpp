// The contact rows are solved kLanes at a time (ContactBlock). Each lane must be exactly the scalar rule on its own
// row: what shares its block, and which lane it sits in, must not change a single bit; nor may the build of the loops
// that runs (baseline x86-64, AVX2 or AVX-512), so a scene gives the same bits on any processor. And a block whose
// bodies cannot turn skips the angular terms; those terms are products with zero there, so the lean form must match
// the full one exactly. Random rows reach every path: speculative and overlapping points, the 2x2 block and one point at
// a time, points that start to push (the bounce path, with and without restitution), sticking and sliding friction.

#include "ContactData.hpp"
#include "ContactSolver.hpp"
#include "support/WideCodes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace physim {
namespace {

// A row between bodies `a` and `b` (b may be immovable: kNullIndex), with random geometry, warm-start impulses and
// material, and the masses prepareContact would give it. `turning`: the bodies have inertia (else rotation locked).
ContactConstraint randomRow(std::mt19937& rng, std::int32_t a, std::int32_t b, bool turning) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    ContactConstraint c;
    c.indexA = a;
    c.indexB = b;
    const double angle = 3.14159265358979 * u(rng);
    c.normal = {std::cos(angle), std::sin(angle)};
    c.invMassA = 1.0 + 0.5 * u(rng);
    c.invMassB = b == kNullIndex ? 0.0 : 1.0 + 0.9 * u(rng);
    c.invIA = turning ? 2.0 + u(rng) : 0.0;
    c.invIB = turning && b != kNullIndex ? 2.0 + u(rng) : 0.0;
    c.turns = turning;
    c.staticFriction = u(rng) > 0.0 ? 0.6 : 0.0;
    c.dynamicFriction = 0.5 * c.staticFriction;
    c.restitution = u(rng) > 0.0 ? 0.5 + 0.5 * u(rng) : 0.0;
    c.normalAcceleration = 10.0 * u(rng);
    c.sliding = u(rng) > 0.0;
    // A row that can bounce keeps its push-out apart, and so do some that cannot (a body of theirs bounces elsewhere).
    c.keepsPush = c.restitution > 0.0 || c.staticFriction > 0.0;
    c.pointCount = u(rng) > -0.5 ? 2 : 1;
    auto mass = [&](const Vec2& rA, const Vec2& rB, const Vec2& dir) {
        const double ra = cross(rA, dir), rb = cross(rB, dir);
        return 1.0 / (c.invMassA + c.invMassB + c.invIA * ra * ra + c.invIB * rb * rb);
    };
    for (int i = 0; i < c.pointCount; ++i) {
        ContactConstraintPoint& p = c.points[i];
        p.anchorA = {u(rng), u(rng)};
        p.anchorB = {u(rng), u(rng)};
        p.rnA = cross(p.anchorA, c.normal);
        p.rnB = cross(p.anchorB, c.normal);
        p.ndA = c.normal.dot(p.anchorA);
        p.ndB = c.normal.dot(p.anchorB);
        p.baseSeparation = 0.01 * u(rng) - (p.ndB - p.ndA);
        p.normalImpulse = u(rng) > 0.0 ? std::abs(u(rng)) : 0.0;  // some start at zero: they may bounce
        p.normalMass = mass(p.anchorA, p.anchorB, c.normal);
    }
    c.tangentImpulse = 0.1 * u(rng);
    c.frictionAnchorA = c.points[0].anchorA;
    c.frictionAnchorB = c.points[0].anchorB;
    c.tangentMass = mass(c.frictionAnchorA, c.frictionAnchorB, perp(c.normal));
    c.rtA = cross(c.frictionAnchorA, perp(c.normal));
    c.rtB = cross(c.frictionAnchorB, perp(c.normal));
    if (c.pointCount == 2) {
        const double lin = c.invMassA + c.invMassB;
        const ContactConstraintPoint &p1 = c.points[0], &p2 = c.points[1];
        c.k11 = lin + c.invIA * p1.rnA * p1.rnA + c.invIB * p1.rnB * p1.rnB;
        c.k22 = lin + c.invIA * p2.rnA * p2.rnA + c.invIB * p2.rnB * p2.rnB;
        c.k12 = lin + c.invIA * p1.rnA * p2.rnA + c.invIB * p1.rnB * p2.rnB;
        const double det = c.k11 * c.k22 - c.k12 * c.k12;
        if (turning && c.k11 * c.k11 < 1000.0 * det) c.invDet = 1.0 / det;
        if (!turning && u(rng) > 0.0) {
            c.k12 = 0.5 * lin;  // locked bodies make K singular; a regular K reaches the two-point bounce too
            c.invDet = 1.0 / (c.k11 * c.k22 - c.k12 * c.k12);
        }
    }
    return c;
}

ContactPass substepPass() {
    ContactPass pass;
    pass.h = 1.0 / 480.0;
    pass.invH = 480.0;
    pass.softness = makeSoftness(120.0, 10.0, pass.h);
    pass.maxPushVelocity = 3.0;
    pass.restitutionThreshold = 1.0;
    pass.slipSpeed = 0.03;
    return pass;
}

// `count` random bodies' records.
std::vector<SolverBody> randomStates(std::mt19937& rng, int count, bool turning) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<SolverBody> states(static_cast<std::size_t>(count));
    for (SolverBody& s : states) {
        s.v = {3.0 * u(rng), 3.0 * u(rng)};
        s.dp = {0.01 * u(rng), 0.01 * u(rng)};
        if (turning) {
            s.w = 3.0 * u(rng);
            s.dAngle = 0.05 * u(rng);
            s.dq = Rotation::fromAngle(s.dAngle);
        }
    }
    return states;
}

// How a substep after the first warm-starts: a pass over the rows, or on the bodies (integrateVelocity).
enum class WarmStart { Rows, Bodies };

// Four substeps of warm start, solve and relax over the given blocks. The passes read an immovable side at
// states[-1]: the records go after a still one, as in the world.
void run(std::vector<ContactBlock>& blocks, std::vector<ContactBlockCold>& cold, std::vector<SolverBody>& states,
         std::vector<PushVelocity>& pushes, WideCode code = WideCode::Best, WarmStart warmStart = WarmStart::Rows) {
    std::vector<SolverBody> records(states.size() + 1);
    std::copy(states.begin(), states.end(), records.begin() + 1);
    ASSERT_EQ(reinterpret_cast<std::uintptr_t>(records.data()) % 64, 0u) << "a record is one cache line";
    SolverBody* const bodies = records.data() + 1;
    ContactPass pass = substepPass();
    pass.pushes = pushes.data();
    std::vector<RowsBase> base(states.size());
    std::vector<WarmStartVelocity> warm(states.size());
    if (warmStart == WarmStart::Bodies) pass.rowsBase = base.data();
    pass.warmStarts = warm.data();
    pass.holdPushes = true;  // as in a world with a relax pass
    for (int sub = 0; sub < 4; ++sub) {
        pass.substep = sub;
        // No forces: only the velocity the rows start from, and on the bodies the warm start.
        for (std::size_t i = 0; i < states.size(); ++i)
            integrateVelocity(bodies[i], &base[i], &warm[i], Vec2::Zero(), 0.0, false,
                              warmStart == WarmStart::Bodies && sub > 0);
        if (warmStart == WarmStart::Rows || sub == 0) {
            warmStartContacts(blocks.data(), blocks.data() + blocks.size(), bodies, code);
            for (std::size_t i = 0; i < states.size(); ++i) recordWarmStart(bodies[i], base[i], warm[i]);
        }
        for (const bool bias : {true, false}) {
            pass.useBias = bias;
            solveContacts(blocks.data(), blocks.data() + blocks.size(), cold.data(), bodies, pass, code);
        }
    }
    EXPECT_EQ(records[0].v, Vec2::Zero()) << "the still body was written";
    EXPECT_EQ(records[0].w, 0.0) << "the still body was written";
    std::copy(bodies, bodies + states.size(), states.begin());
}

// The same double, bit for bit: -0.0 and +0.0 differ here, where == calls them equal.
void expectSameBits(double x, double y, const char* what, int trial) {
    std::uint64_t a = 0, b = 0;
    std::memcpy(&a, &x, sizeof a);
    std::memcpy(&b, &y, sizeof b);
    EXPECT_EQ(a, b) << what << ": " << x << " against " << y << ", trial " << trial;
}

void expectSameRow(const ContactConstraint& x, const ContactConstraint& y, int trial) {
    for (int i = 0; i < x.pointCount; ++i) {
        expectSameBits(x.points[i].normalImpulse, y.points[i].normalImpulse, "normal impulse", trial);
        EXPECT_EQ(x.points[i].engaged, y.points[i].engaged) << "trial " << trial;
        expectSameBits(x.points[i].relativeVelocity, y.points[i].relativeVelocity, "meeting speed", trial);
    }
    expectSameBits(x.tangentImpulse, y.tangentImpulse, "tangent impulse", trial);
    EXPECT_EQ(x.sliding, y.sliding) << "trial " << trial;
}

void expectSameBody(const SolverBody& x, const SolverBody& y, int trial) {
    expectSameBits(x.v.x(), y.v.x(), "vx", trial);
    expectSameBits(x.v.y(), y.v.y(), "vy", trial);
    expectSameBits(x.w, y.w, "w", trial);
    expectSameBits(x.dp.x(), y.dp.x(), "dpx", trial);
    expectSameBits(x.dp.y(), y.dp.y(), "dpy", trial);
    expectSameBits(x.dAngle, y.dAngle, "dAngle", trial);
    expectSameBits(x.dq.c, y.dq.c, "dq.c", trial);
    expectSameBits(x.dq.s, y.dq.s, "dq.s", trial);
}

// What push-out gave a body in the last substep, the same bit for bit.
void expectSamePush(const PushVelocity& x, const PushVelocity& y, int trial) {
    expectSameBits(x.v.x(), y.v.x(), "pushed vx", trial);
    expectSameBits(x.v.y(), y.v.y(), "pushed vy", trial);
    expectSameBits(x.w, y.w, "pushed w", trial);
    EXPECT_EQ(x.substep, y.substep) << "trial " << trial;
}
void expectSamePushes(const std::vector<PushVelocity>& x, const std::vector<PushVelocity>& y, int trial) {
    ASSERT_EQ(x.size(), y.size());
    for (std::size_t i = 0; i < x.size(); ++i) expectSamePush(x[i], y[i], trial);
}

TEST(ContactSolver, EachLaneIsItsOwnRowBitForBit) {
    std::mt19937 rng(11);
    int met = 0, slid = 0, blocked = 0;
    for (int trial = 0; trial < 500; ++trial) {
        // Four rows on bodies 0-1, 2-3, 4-5, 6-7 (some against an immovable side), solved together in one block...
        // A locked row's bodies do not turn (what prepareContact's `turns` promises).
        ContactConstraint rows[kLanes];
        std::vector<SolverBody> start;
        for (int k = 0; k < kLanes; ++k) {
            const bool turning = (trial + k) % 4 != 0;
            rows[k] = randomRow(rng, 2 * k, (trial + k) % 3 == 0 ? kNullIndex : 2 * k + 1, turning);
            for (const SolverBody& s : randomStates(rng, 2, turning)) start.push_back(s);
        }
        std::vector<ContactBlock> together(1);
        std::vector<ContactBlockCold> togetherCold(1);
        startBlock(together[0], togetherCold[0], kLanes);
        for (int k = 0; k < kLanes; ++k) setRow(together[0], togetherCold[0], k, rows[k]);
        std::vector<SolverBody> togetherStates = start;
        std::vector<PushVelocity> togetherPushes(start.size());
        run(together, togetherCold, togetherStates, togetherPushes);
        // ...and each alone, in the last lane of a block whose other lanes are empty.
        for (int k = 0; k < kLanes; ++k) {
            std::vector<ContactBlock> alone(1);
            std::vector<ContactBlockCold> aloneCold(1);
            startBlock(alone[0], aloneCold[0], 0);
            setRow(alone[0], aloneCold[0], kLanes - 1, rows[k]);
            std::vector<SolverBody> aloneStates = start;
            std::vector<PushVelocity> alonePushes(start.size());
            run(alone, aloneCold, aloneStates, alonePushes);
            const ContactConstraint x = row(together[0], togetherCold[0], k);
            expectSameRow(x, row(alone[0], aloneCold[0], kLanes - 1), trial);
            for (const std::int32_t body : {rows[k].indexA, rows[k].indexB})
                if (body != kNullIndex) {
                    expectSameBody(togetherStates[body], aloneStates[body], trial);
                    expectSamePush(togetherPushes[body], alonePushes[body], trial);
                }
            for (int i = 0; i < x.pointCount; ++i) met += x.points[i].engaged && x.restitution > 0.0 ? 1 : 0;
            slid += x.sliding ? 1 : 0;
            blocked += x.invDet > 0.0 ? 1 : 0;
        }
        if (::testing::Test::HasFailure()) break;
    }
    // The random rows reached the paths that matter.
    EXPECT_GT(met, 100);
    EXPECT_GT(slid, 100);
    EXPECT_GT(blocked, 100);
}

TEST(ContactSolver, BlocksWithoutTurningBodiesMatchTheFullRowsExactly) {
    std::mt19937 rng(7);
    int met = 0, slid = 0;
    for (int trial = 0; trial < 500; ++trial) {
        std::vector<ContactBlock> lean(1), full(1);
        std::vector<ContactBlockCold> leanCold(1), fullCold(1);
        startBlock(lean[0], leanCold[0], kLanes);
        startBlock(full[0], fullCold[0], kLanes);
        for (int k = 0; k < kLanes; ++k) {
            const ContactConstraint c = randomRow(rng, 2 * k, (trial + k) % 4 == 0 ? kNullIndex : 2 * k + 1, false);
            setRow(lean[0], leanCold[0], k, c);
            setRow(full[0], fullCold[0], k, c);
        }
        ASSERT_FALSE(lean[0].turns);
        full[0].turns = true;
        std::vector<SolverBody> leanStates = randomStates(rng, 2 * kLanes, false), fullStates = leanStates;
        std::vector<PushVelocity> leanPushes(leanStates.size()), fullPushes(fullStates.size());
        run(lean, leanCold, leanStates, leanPushes);
        run(full, fullCold, fullStates, fullPushes);
        expectSamePushes(leanPushes, fullPushes, trial);
        for (std::size_t b = 0; b < leanStates.size(); ++b) {
            expectSameBody(leanStates[b], fullStates[b], trial);
            EXPECT_EQ(fullStates[b].w, 0.0) << "a locked body turned, trial " << trial;
        }
        for (int k = 0; k < kLanes; ++k) {
            const ContactConstraint x = row(lean[0], leanCold[0], k);
            expectSameRow(x, row(full[0], fullCold[0], k), trial);
            for (int i = 0; i < x.pointCount; ++i) met += x.points[i].engaged && x.restitution > 0.0 ? 1 : 0;
            slid += x.sliding ? 1 : 0;
        }
        if (::testing::Test::HasFailure()) break;
    }
    EXPECT_GT(met, 100);
    EXPECT_GT(slid, 100);
}

// After a step's first substep the world warm-starts on the bodies: each adds again what the rows gave it over the
// substep before, which is M^-1 J^T lambda for the rows' accumulated impulses (their J is fixed for the step), what
// the pass over the rows adds. A bounce's blow is no row impulse and is recorded apart; without that, rows that bounce
// end up metres per second off. Tolerance 1e-12 m/s on speeds of about 3 m/s: the two sums differ only in rounding,
// about 1e-16 of the speeds per operation, grown by four substeps of passes.
TEST(ContactSolver, TheWarmStartOnTheBodiesIsThePassOverTheRows) {
    std::mt19937 rng(5);
    int bounced = 0;
    double worst = 0.0;
    for (int trial = 0; trial < 500; ++trial) {
        std::vector<ContactBlock> rowsWay(1), bodiesWay(1);
        std::vector<ContactBlockCold> rowsCold(1), bodiesCold(1);
        startBlock(rowsWay[0], rowsCold[0], kLanes);
        startBlock(bodiesWay[0], bodiesCold[0], kLanes);
        const bool turning = trial % 4 != 0;
        for (int k = 0; k < kLanes; ++k) {
            const ContactConstraint c = randomRow(rng, 2 * k, (trial + k) % 3 == 0 ? kNullIndex : 2 * k + 1, turning);
            setRow(rowsWay[0], rowsCold[0], k, c);
            setRow(bodiesWay[0], bodiesCold[0], k, c);
        }
        std::vector<SolverBody> rowsStates = randomStates(rng, 2 * kLanes, turning), bodiesStates = rowsStates;
        std::vector<PushVelocity> rowsPushes(rowsStates.size()), bodiesPushes(bodiesStates.size());
        run(rowsWay, rowsCold, rowsStates, rowsPushes, WideCode::Best, WarmStart::Rows);
        run(bodiesWay, bodiesCold, bodiesStates, bodiesPushes, WideCode::Best, WarmStart::Bodies);
        for (std::size_t b = 0; b < rowsStates.size(); ++b) {
            const double off = std::max((rowsStates[b].v - bodiesStates[b].v).norm(),
                                        std::abs(rowsStates[b].w - bodiesStates[b].w));
            worst = std::max(worst, off);
            EXPECT_LT(off, 1e-12) << "body " << b << ", trial " << trial;
        }
        for (int k = 0; k < kLanes; ++k) {
            const ContactConstraint x = row(rowsWay[0], rowsCold[0], k);
            for (int i = 0; i < x.pointCount; ++i) bounced += x.points[i].engaged && x.restitution > 0.0 ? 1 : 0;
        }
        if (::testing::Test::HasFailure()) break;
    }
    std::ostringstream worstText;
    worstText << worst;
    RecordProperty("worst_speed_difference", worstText.str());
    EXPECT_GT(bounced, 100);  // points with restitution that met: the bounce path ran
}

// Rows prepared from contacts: each lane is its own row (alone in a block, or among three others, on any build of
// the loops, it gets the same bits), and its fields are what they mean: the lever arms' moments, the separation
// split into a part fixed for the step and the part the anchors carry, and the effective masses.
TEST(ContactSolver, PreparedRowsAreTheirOwnLanesAndMeanWhatTheySay) {
    const std::vector<WideCode> codes = test::runnableWideCodes();
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int pairs = 0, statics = 0;
    for (int trial = 0; trial < 200; ++trial) {
        // Four contacts between awake bodies 2k and 2k + 1, or against a static body (record slot 8).
        std::vector<SolverBodySim> sims(8);
        for (SolverBodySim& s : sims) {
            s.dynamic = true;
            s.turns = u(rng) > -0.5;
            s.center0 = {5.0 * u(rng), 5.0 * u(rng)};
            s.acceleration = {u(rng), -10.0 + u(rng)};
            s.invMass = 1.0 + 0.5 * u(rng);
            s.invInertia = s.turns ? 2.0 + u(rng) : 0.0;
        }
        std::vector<BodyData> records(9);
        records[8].type = BodyType::Static;
        records[8].center = {u(rng), u(rng)};
        std::vector<ContactData> contacts(kLanes);
        std::vector<RowRef> refs(kLanes);
        for (int k = 0; k < kLanes; ++k) {
            ContactData& c = contacts[k];
            const bool onStatic = (trial + k) % 3 == 0;
            c.manifold.bodyA.index = onStatic ? 8 : static_cast<std::uint32_t>(2 * k);
            c.manifold.bodyB.index = static_cast<std::uint32_t>(2 * k + 1);
            // The pair's material, as mixed from two shapes' (ContactData.hpp).
            c.material.restitution = u(rng) > 0.0 ? 0.5 : 0.0;
            c.material.staticFriction = u(rng) > -0.5 ? 0.6 : 0.0;
            c.material.dynamicFriction = 0.5 * c.material.staticFriction;
            c.keepsPush = c.material.restitution > 0.0;
            refs[k] = {static_cast<std::uint32_t>(k), onStatic ? kNullIndex : 2 * k, 2 * k + 1};
            const double angle = 3.14159265358979 * u(rng);
            c.manifold.normal = {std::cos(angle), std::sin(angle)};
            c.manifold.pointCount = u(rng) > -0.5 ? 2 : 1;
            for (int i = 0; i < 2; ++i) {  // a point past pointCount holds stale values, which must not leak
                ContactPoint& p = c.manifold.points[i];
                p.point = {5.0 * u(rng), 5.0 * u(rng)};
                p.separation = 0.01 * u(rng);
                p.normalImpulse = std::abs(u(rng));
                p.tangentImpulse = 0.1 * u(rng);
            }
            c.sliding = u(rng) > 0.0;
            statics += onStatic ? 1 : 0;
        }
        for (const WideCode code : codes) {
            std::vector<ContactBlock> together(1);
            std::vector<ContactBlockCold> togetherCold(1);
            const BlockRows all{0, kLanes};
            prepareContacts(together.data(), togetherCold.data(), &all, 1, refs.data(), contacts.data(), sims.data(),
                            records.data(), code);
            for (int k = 0; k < kLanes; ++k) {
                std::vector<ContactBlock> alone(1);
                std::vector<ContactBlockCold> aloneCold(1);
                const BlockRows one{static_cast<std::uint32_t>(k), 1};
                prepareContacts(alone.data(), aloneCold.data(), &one, 1, refs.data(), contacts.data(), sims.data(),
                                records.data(), WideCode::Baseline);
                const ContactConstraint x = row(together[0], togetherCold[0], k), y = row(alone[0], aloneCold[0], 0);
                ASSERT_EQ(x.pointCount, y.pointCount);
                for (int i = 0; i < 2; ++i) {
                    const ContactConstraintPoint &p = x.points[i], &q = y.points[i];
                    for (const auto& [a, b, what] : {std::tuple{p.rnA, q.rnA, "rnA"}, {p.rnB, q.rnB, "rnB"},
                                                     {p.ndA, q.ndA, "ndA"}, {p.ndB, q.ndB, "ndB"},
                                                     {p.baseSeparation, q.baseSeparation, "base separation"},
                                                     {p.normalImpulse, q.normalImpulse, "normal impulse"},
                                                     {p.normalMass, q.normalMass, "normal mass"},
                                                     {p.anchorA.x(), q.anchorA.x(), "anchor A x"},
                                                     {p.anchorB.y(), q.anchorB.y(), "anchor B y"}})
                        expectSameBits(a, b, what, trial);
                }
                for (const auto& [a, b, what] :
                     {std::tuple{x.k11, y.k11, "k11"}, {x.k12, y.k12, "k12"}, {x.k22, y.k22, "k22"},
                      {x.invDet, y.invDet, "invDet"}, {x.rtA, y.rtA, "rtA"}, {x.rtB, y.rtB, "rtB"},
                      {x.tangentMass, y.tangentMass, "tangent mass"}, {x.tangentImpulse, y.tangentImpulse, "tangent"},
                      {x.staticFriction, y.staticFriction, "mu_s"}, {x.restitution, y.restitution, "e"},
                      {x.normalAcceleration, y.normalAcceleration, "normal acceleration"}})
                    expectSameBits(a, b, what, trial);
                // What the fields mean, against the contact and bodies directly. Lever arms reach 10 m and inverse
                // masses 300, and the largest difference measured over these trials is 8.9e-16: 1e-12 leaves room for
                // the order of operations, and a wrong term would miss by far more.
                const ContactData& c = contacts[k];
                const Vec2 n = c.manifold.normal;
                const Vec2 centerA = refs[k].indexA == kNullIndex ? records[8].center : sims[2 * k].center0;
                const Vec2 centerB = sims[2 * k + 1].center0;
                for (int i = 0; i < 2; ++i) {
                    const ContactConstraintPoint& p = x.points[i];
                    if (i >= x.pointCount) {  // an unused point: no mass, no impulse
                        EXPECT_EQ(p.normalMass, 0.0);
                        EXPECT_EQ(p.normalImpulse, 0.0);
                        continue;
                    }
                    const ContactPoint& mp = c.manifold.points[i];
                    // Across a gap each side's anchor is its own surface point, half the separation from the
                    // manifold's point; overlapping, that point.
                    const double half = 0.5 * std::max(mp.separation, 0.0);
                    const Vec2 rA = mp.point - half * n - centerA, rB = mp.point + half * n - centerB;
                    EXPECT_NEAR(p.rnA, cross(rA, n), 1e-12);
                    EXPECT_NEAR(p.baseSeparation + n.dot(rB - rA), mp.separation, 1e-12);
                    const double k = x.invMassA + x.invMassB + x.invIA * cross(rA, n) * cross(rA, n) +
                                     x.invIB * cross(rB, n) * cross(rB, n);
                    EXPECT_NEAR(p.normalMass * k, 1.0, 1e-12);
                }
                if (x.pointCount == 2) {  // K's diagonal is each point's inverse effective mass
                    EXPECT_NEAR(x.k11 * x.points[0].normalMass, 1.0, 1e-12);
                    EXPECT_NEAR(x.k22 * x.points[1].normalMass, 1.0, 1e-12);
                } else {  // one point: no block
                    EXPECT_EQ(x.k11, 0.0);
                    EXPECT_EQ(x.invDet, 0.0);
                }
                EXPECT_EQ(x.invMassA, refs[k].indexA == kNullIndex ? 0.0 : sims[2 * k].invMass);
                pairs += x.invDet > 0.0 ? 1 : 0;
            }
            EXPECT_EQ(together[0].turns, std::any_of(refs.begin(), refs.end(), [&](const RowRef& r) {
                          return (r.indexA != kNullIndex && sims[r.indexA].turns) || sims[r.indexB].turns;
                      }));
        }
        if (::testing::Test::HasFailure()) break;
    }
    EXPECT_GT(pairs, 100);  // the random contacts reached a regular 2x2 matrix (a two-point bounce solves it)
    EXPECT_GT(statics, 100);
}

#if PHYSIM_HAS_AVX2_CODE  // an x86-64 build by GCC or Clang: the loops exist in all three builds
// Each build this processor runs against the baseline, and so is what the step's dispatch picks (WideCode::Best):
// on a processor without AVX2 that is the baseline loops, which must then run without a fault.
TEST(ContactSolver, EveryBuildOfTheLoopsGivesTheSameBits) {
    std::vector<WideCode> others{WideCode::Best};
    std::string compared = "dispatch";
    if (avx2CodeRuns()) others.push_back(WideCode::Avx2), compared += ", avx2";
    if (avx512CodeRuns()) others.push_back(WideCode::Avx512), compared += ", avx512";
    RecordProperty("compared_with", compared);
    std::mt19937 rng(5);
    int met = 0, slid = 0;
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<ContactBlock> baseline(2);
        std::vector<ContactBlockCold> baselineCold(2);
        std::vector<SolverBody> start;
        for (int b = 0; b < 2; ++b) {
            startBlock(baseline[b], baselineCold[b], kLanes);
            for (int k = 0; k < kLanes; ++k) {
                const bool turning = (trial + k + b) % 3 != 0;
                const std::int32_t a = static_cast<std::int32_t>(start.size());
                setRow(baseline[b], baselineCold[b], k, randomRow(rng, a, k == 1 ? kNullIndex : a + 1, turning));
                for (const SolverBody& s : randomStates(rng, 2, turning)) start.push_back(s);
            }
        }
        // Every other trial's blocks rest rounded sides on straight ones (RoundedRows.hpp) whose ends lie within a
        // millimetre, so some lanes' centres pass them: the distance past an end is the same on every build too.
        std::vector<ContactBlockEnds> ends(2);
        if (trial % 2 == 0) {
            std::uniform_real_distribution<double> within(0.0, 1e-3), turn(-M_PI, M_PI), radius(0.05, 0.5);
            for (int b = 0; b < 2; ++b) {
                for (int i = 0; i < 2; ++i)
                    for (int k = 0; k < kLanes; ++k) {
                        ends[b].lo[i][k] = -within(rng);
                        ends[b].hi[i][k] = within(rng);
                        const double low = turn(rng), high = turn(rng);
                        ends[b].loCos[i][k] = std::cos(low);
                        ends[b].loSin[i][k] = std::sin(low);
                        ends[b].hiCos[i][k] = std::cos(high);
                        ends[b].hiSin[i][k] = std::sin(high);
                    }
                for (int k = 0; k < kLanes; ++k) ends[b].rounding[k] = radius(rng);
                baseline[b].ends = &ends[b];
            }
        }
        const std::vector<ContactBlock> initial = baseline;
        const std::vector<ContactBlockCold> initialCold = baselineCold;
        std::vector<SolverBody> baselineStates = start;
        std::vector<PushVelocity> baselinePushes(start.size());
        run(baseline, baselineCold, baselineStates, baselinePushes, WideCode::Baseline);
        for (const WideCode code : others) {
            std::vector<ContactBlock> blocks = initial;
            std::vector<ContactBlockCold> cold = initialCold;
            std::vector<SolverBody> states = start;
            std::vector<PushVelocity> pushes(start.size());
            run(blocks, cold, states, pushes, code);
            for (std::size_t i = 0; i < start.size(); ++i) expectSameBody(baselineStates[i], states[i], trial);
            expectSamePushes(baselinePushes, pushes, trial);
            for (int b = 0; b < 2; ++b)
                for (int k = 0; k < kLanes; ++k)
                    expectSameRow(row(baseline[b], baselineCold[b], k), row(blocks[b], cold[b], k), trial);
        }
        for (int b = 0; b < 2; ++b)
            for (int k = 0; k < kLanes; ++k) {
                const ContactConstraint x = row(baseline[b], baselineCold[b], k);
                for (int i = 0; i < x.pointCount; ++i) met += x.points[i].engaged && x.restitution > 0.0 ? 1 : 0;
                slid += x.sliding ? 1 : 0;
            }
        if (::testing::Test::HasFailure()) break;
    }
    EXPECT_GT(met, 100);
    EXPECT_GT(slid, 100);
}
#endif

}  // namespace
}  // namespace physim
