// Continuous batches on the CPU: the batch answers exactly what the one-pair functions answer (they are one piece
// of code, ContinuousKernel.hpp, so equality is to the last bit), on fast pairs and on spinning grazing ones, Failed
// included; a closed-form time of impact, threads that change nothing, bad input named at the boundary, and a
// World whose continuous stage goes through the solver.

#include "KernelBridge.hpp"

#include "physim/core/ContinuousBatch.hpp"
#include "physim/core/World.hpp"

#include "support/KernelShapes.hpp"
#include "support/RandomBatch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

namespace physim {
namespace {

Sweep sweepOf(const ContinuousBatch& b, std::int32_t body) {
    return {{b.bodies.x0[body], b.bodies.y0[body]}, {b.bodies.x1[body], b.bodies.y1[body]}, b.bodies.angle0[body],
            b.bodies.angle1[body]};
}

Geometry shapeOf(const ContinuousBatch& b, std::int32_t body) {
    const std::int32_t s = b.bodies.shape[body];
    const std::int32_t first = b.shapes.firstVertex[s];
    if (b.shapes.kind[s] == kernel::kCircle)
        return Circle{{b.shapes.vertexX[first], b.shapes.vertexY[first]}, b.shapes.radius[s]};
    Polygon p;
    p.count = b.shapes.vertexCount[s];
    for (int k = 0; k < p.count; ++k) {
        p.vertices[k] = {b.shapes.vertexX[first + k], b.shapes.vertexY[first + k]};
        p.normals[k] = {b.shapes.normalX[first + k], b.shapes.normalY[first + k]};
    }
    return p;
}

// Every field of pair i of the batch's result is the one-pair kernel's, to the bit (one piece of code). Fatal
// failures end the pair: call through ASSERT_NO_FATAL_FAILURE.
void expectTheOnePairKernels(const ContinuousBatchResult& result, std::size_t i, const kernel::Toi& one) {
    ASSERT_EQ(result.state[i], one.state) << "pair " << i;
    ASSERT_EQ(result.iterations[i], one.iterations) << "pair " << i;
    ASSERT_EQ(result.t[i], one.t) << "pair " << i;
    ASSERT_EQ(result.gap[i], one.gap) << "pair " << i;
    ASSERT_EQ(result.normalX[i], one.normal.x) << "pair " << i;
    ASSERT_EQ(result.normalY[i], one.normal.y) << "pair " << i;
    ASSERT_EQ(result.pointX[i], one.point.x) << "pair " << i;
    ASSERT_EQ(result.pointY[i], one.point.y) << "pair " << i;
}

TEST(ContinuousBatch, AnswersWhatTheOnePairFunctionsAnswer) {
    const ContinuousBatch batch = testing::randomBatch(3000, 11);
    ContinuousBatchResult result;
    CpuContinuousSolver().solve(batch, result);
    ASSERT_EQ(result.size(), batch.pairCount());
    int hits = 0;
    for (std::size_t i = 0; i < batch.pairCount(); ++i) {
        const Geometry a = shapeOf(batch, batch.pairs.a[i]), b = shapeOf(batch, batch.pairs.b[i]);
        const Sweep sa = sweepOf(batch, batch.pairs.a[i]), sb = sweepOf(batch, batch.pairs.b[i]);
        const ToiResult one = timeOfImpact(a, sa, b, sb, batch.tolerance, batch.maxIterations);
        const ToiResult many = result.toi(i);
        ASSERT_EQ(many.state, one.state) << "pair " << i;
        ASSERT_EQ(many.t, one.t) << "pair " << i;  // same code, same inputs: the same bits
        ASSERT_EQ(many.iterations, one.iterations) << "pair " << i;
        if (many.state != ToiState::Hit) continue;
        ++hits;
        // The contact data describes the shapes at t: the gap the distance function measures there, a unit
        // normal, and a point between the two surfaces.
        const DistanceOutput d = shapeDistance(a, sa.at(many.t), b, sb.at(many.t));
        EXPECT_EQ(result.gap[i], d.distance);
        EXPECT_LT(result.gap[i], batch.tolerance);
        EXPECT_NEAR(std::hypot(result.normalX[i], result.normalY[i]), 1.0, 1e-12);
        EXPECT_EQ(result.pointX[i], 0.5 * (d.pointA.x() + d.pointB.x()));
    }
    // The generator's design: about half the pairs collide; far fewer would mean a broken generator.
    EXPECT_GT(hits, 1000);
}

// The same on fast-spinning pairs built to graze (testing::spinningPairs), with the default budget and with one so
// small that many pairs fail: every field of every pair is the one-pair kernel's to the bit, Failed included, and
// a failed pair reports how far it was proven apart and no contact data.
TEST(ContinuousBatch, SpinningPairsAndFailuresMatchTheOnePairKernel) {
    ContinuousBatch batch = testing::toBatch(testing::spinningPairs(2000, 5));
    for (const std::int32_t budget : {100, 3}) {
        batch.maxIterations = budget;
        ContinuousBatchResult result;
        CpuContinuousSolver().solve(batch, result);
        int failed = 0;
        for (std::size_t i = 0; i < batch.pairCount(); ++i) {
            const std::int32_t a = batch.pairs.a[i], b = batch.pairs.b[i];
            const kernel::Toi one =
                kernel::timeOfImpact(toKernel(shapeOf(batch, a)), toKernel(sweepOf(batch, a)),
                                     toKernel(shapeOf(batch, b)), toKernel(sweepOf(batch, b)), batch.tolerance, budget);
            ASSERT_NO_FATAL_FAILURE(expectTheOnePairKernels(result, i, one));
            if (result.state[i] != kernel::kFailed) continue;
            ++failed;
            EXPECT_EQ(result.toi(i).state, ToiState::Failed);
            EXPECT_EQ(result.iterations[i], budget);
            EXPECT_GE(result.t[i], 0.0);
            EXPECT_LT(result.t[i], 1.0);
            EXPECT_EQ(result.gap[i], 0.0);
            EXPECT_EQ(result.normalX[i], 0.0);
            EXPECT_EQ(result.pointY[i], 0.0);
        }
        if (budget == 100)
            EXPECT_EQ(failed, 0);
        else
            EXPECT_GT(failed, 200) << "a budget of 3 settles most pairs, not all";
    }
}

TEST(ContinuousBatch, CircleAgainstAPlankMatchesTheClosedForm) {
    // A 10 cm circle moves 10 m along x from x = -5 towards a static plank 1 cm thick at the origin: contact when
    // its centre reaches -0.105, at t = 4.895 / 10. Conservative advancement stops within the tolerance before
    // that, never after: t in (t* - tol / 10, t*], the gap below the tolerance.
    ContinuousBatch batch;
    const auto ball = batch.addBody(batch.addShape(makeCircle(0.1)), Sweep{{-5, 0}, {5, 0}, 0, 0});
    const auto plank = batch.addBody(batch.addShape(makeBox(0.005, 1.0)), Sweep{{0, 0}, {0, 0}, 0, 0});
    batch.addPair(ball, plank);
    batch.addPair(plank, ball);  // the other way round: same time, normal reversed
    ContinuousBatchResult r;
    CpuContinuousSolver().solve(batch, r);
    const double exact = 4.895 / 10.0;
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(r.toi(i).state, ToiState::Hit);
        EXPECT_LE(r.t[i], exact + 1e-15);
        EXPECT_GT(r.t[i], exact - batch.tolerance / 10.0);
        EXPECT_NEAR(r.pointX[i], -0.005 - 0.5 * r.gap[i], 1e-12);
        EXPECT_NEAR(r.pointY[i], 0.0, 1e-12);
    }
    EXPECT_NEAR(r.normalX[0], 1.0, 1e-12);
    EXPECT_NEAR(r.normalX[1], -1.0, 1e-12);
}

TEST(ContinuousBatch, ThreadsChangeNothing) {
    const ContinuousBatch batch = testing::randomBatch(10000, 3);
    ContinuousBatchResult one, four;
    CpuContinuousSolver(1).solve(batch, one);
    CpuContinuousSolver(4).solve(batch, four);
    EXPECT_EQ(one.state, four.state);
    EXPECT_EQ(one.t, four.t);
    EXPECT_EQ(one.normalX, four.normalX);
    EXPECT_EQ(one.gap, four.gap);
    EXPECT_EQ(one.pointY, four.pointY);
    EXPECT_EQ(CpuContinuousSolver(4).name(), "cpu, 4 threads");
}

// A solver keeps its threads from one batch to the next (a big batch, a small one, the big one again); a moved
// solver keeps them too.
TEST(ContinuousBatch, ASolverKeepsItsThreadsFromBatchToBatch) {
    const ContinuousBatch big = testing::randomBatch(10000, 5), small = testing::randomBatch(100, 6);
    ContinuousBatchResult oneBig, oneSmall, first, second, smallOnFour, moved;
    CpuContinuousSolver(1).solve(big, oneBig);
    CpuContinuousSolver(1).solve(small, oneSmall);
    CpuContinuousSolver four(4);
    four.solve(big, first);
    four.solve(small, smallOnFour);
    four.solve(big, second);
    CpuContinuousSolver taken(std::move(four));
    taken.solve(big, moved);
    EXPECT_EQ(taken.threads(), 4u);
    for (const ContinuousBatchResult* r : {&first, &second, &moved}) {
        EXPECT_EQ(r->state, oneBig.state);
        EXPECT_EQ(r->t, oneBig.t);
        EXPECT_EQ(r->pointX, oneBig.pointX);
    }
    EXPECT_EQ(smallOnFour.state, oneSmall.state);
    EXPECT_EQ(smallOnFour.t, oneSmall.t);
    EXPECT_GE(CpuContinuousSolver(0).threads(), 1u);
}

TEST(ContinuousBatch, AnEmptyBatchGivesAnEmptyResult) {
    ContinuousBatchResult r;
    r.resize(5);
    CpuContinuousSolver().solve(ContinuousBatch{}, r);
    EXPECT_EQ(r.size(), 0u);
}

// Each bad batch is rejected with a message that names the array or value.
void expectRejected(const ContinuousBatch& batch, const std::string& expected) {
    ContinuousBatchResult r;
    try {
        CpuContinuousSolver().solve(batch, r);
        ADD_FAILURE() << "accepted; expected: " << expected;
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
}

TEST(ContinuousBatch, BadInputIsNamed) {
    const ContinuousBatch good = testing::randomBatch(6, 1);
    ContinuousBatch b = good;
    b.bodies.x1.pop_back();
    expectRejected(b, "bodies.x1 has 11 entries but bodies.shape has 12");
    b = good;
    b.shapes.kind[2] = 7;
    expectRejected(b, "unsupported shape kind 7 at shapes.kind[2]");
    b = good;
    b.shapes.vertexCount[0] = 2;  // shape 0 is a circle
    expectRejected(b, "shapes.vertexCount[0] = 2, but a circle has 1");
    b = good;
    b.shapes.firstVertex[1] = static_cast<std::int32_t>(b.shapes.vertexX.size()) - 1;
    expectRejected(b, "shapes.firstVertex[1]");
    b = good;
    b.shapes.vertexX[b.shapes.firstVertex[2] + 1] *= -3.0;  // shape 2 (a box) made non-convex
    expectRejected(b, "shape 2:");
    b = good;
    b.shapes.boundingRadius[2] = 0.0;
    expectRejected(b, "shapes.boundingRadius[2]");
    b = good;
    b.bodies.y0[3] = std::nan("");
    expectRejected(b, "bodies.y0[3] must be finite, got nan");
    b = good;
    b.bodies.angle1[0] = INFINITY;
    expectRejected(b, "bodies.angle1[0]");
    b = good;
    b.pairs.b[4] = 99;
    expectRejected(b, "pairs.b[4] = 99 is not a body index");
    b = good;
    b.pairs.b[0] = b.pairs.a[0];
    expectRejected(b, "pair 0 names body 0 twice");
    b = good;
    b.bodies.shape[5] = -1;
    expectRejected(b, "bodies.shape[5] = -1");
    b = good;
    b.tolerance = 0.0;
    expectRejected(b, "tolerance");
    b = good;
    b.maxIterations = 0;
    expectRejected(b, "maxIterations must be in [1, 1000000], got 0");
}

// Segments, capsules, chain segments and rounded polygons (shapes built by hand in the kernel's layout,
// testing::roundedKindsPairs) go through the batch as circles and polygons do: every field of every pair is the
// one-pair kernel's to the bit.
TEST(ContinuousBatch, SegmentCapsuleChainAndRoundedMatchTheOnePairKernel) {
    const std::vector<testing::KernelPair> pairs = testing::roundedKindsPairs(800, 7);
    const ContinuousBatch batch = testing::kernelBatch(pairs);
    EXPECT_NO_THROW(validate(batch));
    ContinuousBatchResult result;
    CpuContinuousSolver().solve(batch, result);
    int hits = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const testing::KernelPair& p = pairs[i];
        const kernel::Toi one = kernel::timeOfImpact(p.a, testing::kernelMotion(p.sa), p.b,
                                                     testing::kernelMotion(p.sb), batch.tolerance, batch.maxIterations);
        ASSERT_NO_FATAL_FAILURE(expectTheOnePairKernels(result, i, one));
        hits += result.state[i] == kernel::kHit;
    }
    EXPECT_GT(hits, 300);
}

// A batch of one shape, built by hand and then broken by `edit`, followed by a triangle so that a vertex count
// larger than the shape's still indexes inside the arrays (only the kind's own rule can refuse it).
ContinuousBatch oneShape(const kernel::Shape& shape, const std::function<void(ContinuousBatch::Shapes&)>& edit) {
    ContinuousBatch batch;
    testing::appendShape(batch, shape);
    testing::appendShape(batch, testing::kernelRounded(kernel::kPolygon, {{0, 0}, {1, 0}, {0, 1}}, 0.0));
    edit(batch.shapes);
    return batch;
}

// What the kernel accepts of the kinds beyond the circle and the sharp polygon (kernel::shapeHolds, which every
// pair's solve runs first): 2 vertices for a segment, a capsule or a chain segment, radius 0 for a segment and a
// chain segment, > 0 for a capsule, >= 0 for a polygon, a bounding radius that includes the radius; and a
// segment's geometry: two distinct finite points, normals[0] the unit normal on its right, normals[1] its negative.
TEST(ContinuousBatch, SegmentCapsuleChainAndRoundedEntriesTheKernelRefuses) {
    const kernel::Shape segment = testing::kernelSegment({-1.0, 0.5}, {2.0, 0.0});
    const kernel::Shape chain = testing::kernelChainSegment({1.0, 0.0}, {-1.0, 0.0});
    const kernel::Shape capsule = testing::kernelCapsule({-0.5, 0.0}, {0.5, 0.2}, 0.1);
    const kernel::Shape rounded = testing::kernelBox(0.3, 0.2, 0.05);
    auto holds = [](const ContinuousBatch& b) { return kernel::shapeHolds(viewOf(b), 0); };
    auto none = [](ContinuousBatch::Shapes&) {};
    for (const kernel::Shape& good : {segment, chain, capsule, rounded}) EXPECT_TRUE(holds(oneShape(good, none)));

    const std::vector<std::pair<const char*, std::function<void(ContinuousBatch::Shapes&)>>> broken = {
        {"3 vertices", [](auto& s) { s.vertexCount[0] = 3; }},
        {"1 vertex", [](auto& s) { s.vertexCount[0] = 1; }},
        {"zero length", [](auto& s) { s.vertexX[1] = s.vertexX[0], s.vertexY[1] = s.vertexY[0]; }},
        {"NaN point", [](auto& s) { s.vertexY[1] = std::nan(""); }},
        {"infinite points", [](auto& s) { s.vertexX[0] = s.vertexX[1] = INFINITY; }},
        {"normals on the left", [](auto& s) {
             for (int k : {0, 1}) s.normalX[k] = -s.normalX[k], s.normalY[k] = -s.normalY[k];
         }},
        {"normals[1] = normals[0]", [](auto& s) { s.normalX[1] = s.normalX[0], s.normalY[1] = s.normalY[0]; }},
        {"normal not unit", [](auto& s) { s.normalX[0] *= 1.001, s.normalY[0] *= 1.001; }},
        {"bounding radius short of the radius", [](auto& s) { s.boundingRadius[0] -= s.radius[0] + 1e-3; }},
        {"kind 5", [](auto& s) { s.kind[0] = 5; }},
        {"kind -1", [](auto& s) { s.kind[0] = -1; }},
    };
    for (const kernel::Shape& shape : {segment, chain, capsule})
        for (const auto& [what, edit] : broken)
            EXPECT_FALSE(holds(oneShape(shape, edit))) << "kind " << shape.kind << ": " << what;

    auto radius = [](double r) { return [r](ContinuousBatch::Shapes& s) { s.radius[0] = r, s.boundingRadius[0] += 1.0; }; };
    for (const double r : {0.1, -0.1, std::nan("")}) {
        EXPECT_FALSE(holds(oneShape(segment, radius(r)))) << "segment radius " << r;
        EXPECT_FALSE(holds(oneShape(chain, radius(r)))) << "chain segment radius " << r;
    }
    for (const double r : {0.0, -0.1, std::nan(""), double(INFINITY)})
        EXPECT_FALSE(holds(oneShape(capsule, radius(r)))) << "capsule radius " << r;
    for (const double r : {-0.01, std::nan(""), double(INFINITY)})
        EXPECT_FALSE(holds(oneShape(rounded, radius(r)))) << "rounded polygon radius " << r;
    EXPECT_TRUE(holds(oneShape(rounded, radius(0.0)))) << "a polygon of radius 0 is the sharp one";
    EXPECT_FALSE(holds(oneShape(rounded, [](auto& s) { s.vertexCount[0] = 2; }))) << "a polygon has 3 or more";

    // A refused entry is never solved: the solver throws std::invalid_argument (validate() names it; see below).
    ContinuousBatch bad = oneShape(capsule, radius(0.0));
    bad.addBody(0, Sweep{{0, 0}, {1, 0}, 0, 0});
    bad.addBody(1, Sweep{{3, 0}, {3, 0}, 0, 0});
    bad.addPair(0, 1);
    ContinuousBatchResult r;
    EXPECT_THROW(CpuContinuousSolver().solve(bad, r), std::invalid_argument);
}

// validate() names a refused entry of the new kinds through their rooms (src/core/shapes/: fromBatch, radiusProblem,
// validate, kernelProblem, and the normals toKernel gives), never as an unsupported kind.
TEST(ContinuousBatch, SegmentCapsuleChainAndRoundedBadInputIsNamed) {
    auto named = [](const ContinuousBatch& b, std::initializer_list<const char*> expected) {
        ContinuousBatch batch = b;
        batch.addBody(0, Sweep{{0, 0}, {1, 0}, 0, 0});
        batch.addBody(1, Sweep{{3, 0}, {3, 0}, 0, 0});
        batch.addPair(0, 1);
        try {
            validate(batch);
            ADD_FAILURE() << "accepted";
        } catch (const std::invalid_argument& e) {
            const std::string what = e.what();
            bool found = false;
            for (const char* x : expected) found = found || what.find(x) != std::string::npos;
            EXPECT_TRUE(found) << what;
            EXPECT_EQ(what.find("unsupported shape kind"), std::string::npos) << what;
        }
    };
    const kernel::Shape segment = testing::kernelSegment({-1.0, 0.5}, {2.0, 0.0});
    const kernel::Shape capsule = testing::kernelCapsule({-0.5, 0.0}, {0.5, 0.2}, 0.1);
    const kernel::Shape chain = testing::kernelChainSegment({1.0, 0.0}, {-1.0, 0.0});
    named(oneShape(segment, [](auto& s) { s.vertexCount[0] = 3; }), {"shapes.vertexCount[0] = 3"});
    named(oneShape(chain, [](auto& s) { s.vertexCount[0] = 1; }), {"shapes.vertexCount[0] = 1"});
    named(oneShape(capsule, [](auto& s) { s.radius[0] = 0.0; }), {"shapes.radius[0]", "shape 0:"});
    named(oneShape(segment, [](auto& s) { s.radius[0] = 0.1, s.boundingRadius[0] += 0.1; }),
          {"shapes.radius[0]", "shape 0:"});
    named(oneShape(segment, [](auto& s) { s.vertexX[1] = s.vertexX[0], s.vertexY[1] = s.vertexY[0]; }),
          {"shape 0:"});
    named(oneShape(chain, [](auto& s) { s.normalX[1] = s.normalX[0], s.normalY[1] = s.normalY[0]; }),
          {"shape 0:"});
    named(oneShape(capsule, [](auto& s) { s.boundingRadius[0] -= 0.05; }), {"shapes.boundingRadius[0]"});
    named(oneShape(testing::kernelBox(0.3, 0.2, 0.05), [](auto& s) { s.radius[0] = -0.05; }),
          {"shapes.radius[0]", "shape 0:"});
}

// A solver that counts what the World hands it and solves on the CPU.
class CountingSolver final : public ContinuousSolver {
public:
    void solve(const ContinuousBatch& batch, ContinuousBatchResult& result) override {
        ++batches;
        pairs += batch.pairCount();
        cpu.solve(batch, result);
    }
    std::string name() const override { return "counting"; }
    int batches = 0;
    std::size_t pairs = 0;
    CpuContinuousSolver cpu;
};

TEST(ContinuousBatch, TheWorldsContinuousStageGoesThroughItsSolver) {
    WorldSettings s;
    s.gravity = Vec2::Zero();
    World plain(s), counted(s);
    const auto bulletsA = testing::fillBulletBox(plain, 40, 9);
    const auto bulletsB = testing::fillBulletBox(counted, 40, 9);
    auto solver = std::make_shared<CountingSolver>();
    counted.setContinuousSolver(solver);
    EXPECT_EQ(counted.continuousSolver(), solver);
    EXPECT_EQ(plain.continuousSolver(), nullptr);
    for (int i = 0; i < 60; ++i) {
        plain.step(1.0 / 60.0);
        counted.step(1.0 / 60.0);
    }
    EXPECT_EQ(solver->batches, 60);  // one batch per step: every step has bullets near walls
    EXPECT_GT(solver->pairs, 0u);
    // The same kernel on the same thread: the two worlds are the same to the last bit.
    for (std::size_t i = 0; i < bulletsA.size(); ++i)
        EXPECT_EQ(plain.position(bulletsA[i]), counted.position(bulletsB[i]));
}

}  // namespace
}  // namespace physim
