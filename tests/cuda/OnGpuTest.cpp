// Tests that need a GPU: the GPU's answers against the CPU's, and a World whose continuous batches run on the
// GPU. GpuTestMain.cpp skips the whole program, saying why, on a machine without one.
//
// Agreement: with --fmad=false the two differ only where the device's cos/sin round differently from glibc's
// (a unit in the last place). Conservative advancement stops at the first pose with a gap under the tolerance,
// so such a difference can at most move the stop by one advancement step, which changes the reported contact
// position by less than the tolerance (1e-4 m): testing::compareResults's bound, per pair.

#include <physim/cuda/ContinuousSolver.hpp>

#include "ContinuousKernel.hpp"

#include "support/KernelShapes.hpp"
#include "support/RandomBatch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <memory>

namespace physim::cuda {
namespace {

// The batch solved on the GPU (asserting it ran there) and on the CPU, and how the answers compare; none may
// disagree. Fatal failures end the test: call through ASSERT_NO_FATAL_FAILURE.
void solveOnBoth(GpuContinuousSolver& solver, const ContinuousBatch& batch, ContinuousBatchResult& gpu,
                 ContinuousBatchResult& cpu, testing::Agreement& a) {
    solver.solve(batch, gpu);
    ASSERT_TRUE(solver.lastRanOnGpu()) << solver.error();
    CpuContinuousSolver(0).solve(batch, cpu);
    a = testing::compareResults(batch, gpu, cpu);
    std::cout << "identical " << a.identical << ", within tolerance " << a.within << ", disagreeing " << a.disagree
              << " of " << batch.pairCount() << "\n";
    EXPECT_EQ(a.disagree, 0);
}

// Hits report a gap under the tolerance on the GPU too; counts them in hits. Fatal failures end the test: call
// through ASSERT_NO_FATAL_FAILURE.
void expectGpuHitsUnderTheTolerance(const ContinuousBatch& batch, const ContinuousBatchResult& gpu, int& hits) {
    for (std::size_t i = 0; i < batch.pairCount(); ++i)
        if (gpu.state[i] == kernel::kHit) {
            ++hits;
            ASSERT_LT(gpu.gap[i], batch.tolerance) << "pair " << i;
        }
}

GpuSolverOptions everyBatchOnTheGpu() {
    GpuSolverOptions options;
    options.minPairs = 0;  // every batch on the GPU, however small
    return options;
}

TEST(GpuContinuousSolverOnGpu, AgreesWithTheCpuOnRandomPairs) {
    GpuContinuousSolver solver(everyBatchOnTheGpu());
    const ContinuousBatch batch = testing::randomBatch(20000, 21);
    ContinuousBatchResult gpu, cpu;
    testing::Agreement a;
    ASSERT_NO_FATAL_FAILURE(solveOnBoth(solver, batch, gpu, cpu, a));
    std::cout << "kernel " << solver.lastTimings().kernelMs << " ms, total " << solver.lastTimings().totalMs
              << " ms\n";
    for (std::size_t i = 0, shown = 0; i < batch.pairCount() && shown < 8 && a.disagree > 0; ++i) {
        if (gpu.state[i] == cpu.state[i] && gpu.t[i] == cpu.t[i]) continue;
        ++shown;
        const std::int32_t sa = batch.bodies.shape[batch.pairs.a[i]], sb = batch.bodies.shape[batch.pairs.b[i]];
        std::cout << "pair " << i << " kinds " << batch.shapes.kind[sa] << "/" << batch.shapes.kind[sb] << " gpu "
                  << gpu.state[i] << " t " << gpu.t[i] << " it " << gpu.iterations[i] << " gap " << gpu.gap[i]
                  << " | cpu " << cpu.state[i] << " t " << cpu.t[i] << " it " << cpu.iterations[i] << " gap "
                  << cpu.gap[i] << "\n";
    }
    int hits = 0;
    ASSERT_NO_FATAL_FAILURE(expectGpuHitsUnderTheTolerance(batch, gpu, hits));
    EXPECT_GT(solver.lastTimings().kernelMs, 0.0);
    EXPECT_GE(solver.lastTimings().totalMs, solver.lastTimings().kernelMs);
}

// A World whose continuous batches all run on the GPU keeps the CPU World's guarantees in the tests' hardest scene
// (ContinuousCrowd.BulletsNeverLeaveTheBox): no bullet leaves the box, kinetic energy never runs away. The two
// Worlds are not compared pose by pose: the crowd is chaotic, so the last-bit differences of cos and sin on the
// device (4% of pairs, within the tolerance) grow into different trajectories within a few steps.
TEST(GpuContinuousSolverOnGpu, AWorldOnTheGpuKeepsItsBulletsInTheBox) {
    WorldSettings s;
    s.gravity = Vec2::Zero();
    World world(s);
    const auto bullets = testing::fillBulletBox(world, 60, 5);
    auto gpu = std::make_shared<GpuContinuousSolver>(everyBatchOnTheGpu());
    world.setContinuousSolver(gpu);
    auto energy = [&] { return testing::kineticEnergy(world, bullets); };
    const double start = energy();
    double highest = start;
    int onGpu = 0;
    for (int step = 0; step < 60; ++step) {
        world.step(1.0 / 60.0);
        ASSERT_TRUE(gpu->gpuEnabled()) << gpu->error();
        onGpu += gpu->lastRanOnGpu();
        for (const BodyId b : bullets)
            ASSERT_LT(world.position(b).cwiseAbs().maxCoeff(), 1.995) << "a bullet's centre passed a wall's inner face in step " << step;
        highest = std::max(highest, energy());
    }
    EXPECT_GT(onGpu, 0) << "the World's batches ran on the GPU";
    EXPECT_LE(highest, 1.01 * start);  // the CPU test's bound, same reason
}

// A batch whose owner keeps shapesRevision: the second solve keeps the shapes on the device (its copy in is
// smaller) and answers the same bits; new motions with the same shapes are answered as the CPU answers them; a new
// revision copies changed shapes.
TEST(GpuContinuousSolverOnGpu, ShapesKeptOnTheDeviceGiveTheSameAnswers) {
    GpuContinuousSolver gpu(everyBatchOnTheGpu());
    ContinuousBatch batch = testing::randomBatch(20000, 33);
    batch.shapesRevision = 7;
    ContinuousBatchResult first, second, cpu;
    gpu.solve(batch, first);
    const double copiedIn = gpu.lastTimings().uploadMs;
    gpu.solve(batch, second);
    ASSERT_TRUE(gpu.lastRanOnGpu()) << gpu.error();
    EXPECT_EQ(second.t, first.t);
    EXPECT_EQ(second.state, first.state);
    EXPECT_LT(gpu.lastTimings().uploadMs, copiedIn);
    std::cout << "copy in: " << copiedIn << " ms with shapes, " << gpu.lastTimings().uploadMs << " ms without\n";

    for (double& x : batch.bodies.x1) x += 0.5;  // new motions, same shapes
    gpu.solve(batch, second);
    CpuContinuousSolver().solve(batch, cpu);
    EXPECT_EQ(testing::compareResults(batch, second, cpu).disagree, 0);

    for (double& r : batch.shapes.radius)
        if (r > 0.0) r *= 2.0;  // circles twice as big, and the boundingRadius to match
    for (std::size_t i = 0; i < batch.shapes.radius.size(); ++i)
        batch.shapes.boundingRadius[i] += batch.shapes.radius[i] / 2.0;
    batch.shapesRevision = 8;
    gpu.solve(batch, second);
    CpuContinuousSolver().solve(batch, cpu);
    EXPECT_EQ(testing::compareResults(batch, second, cpu).disagree, 0);
}

// Segments, capsules, chain segments and rounded polygons on the device (the kernel header's rounded paths as nvcc
// compiles them): the same answers as the CPU's within the tolerance, and a hit's gap under it.
TEST(GpuContinuousSolverOnGpu, AgreesWithTheCpuOnSegmentCapsuleChainAndRoundedPairs) {
    GpuContinuousSolver solver(everyBatchOnTheGpu());
    const ContinuousBatch batch = testing::kernelBatch(testing::roundedKindsPairs(20000, 41));
    ContinuousBatchResult gpu, cpu;
    testing::Agreement a;
    ASSERT_NO_FATAL_FAILURE(solveOnBoth(solver, batch, gpu, cpu, a));
    int hits = 0;
    ASSERT_NO_FATAL_FAILURE(expectGpuHitsUnderTheTolerance(batch, gpu, hits));
    EXPECT_GT(hits, 5000);
}

}  // namespace
}  // namespace physim::cuda
