// The GPU continuous solver against the CPU, which runs the same kernel code (ContinuousKernel.hpp).
//
// Runs everywhere: bad input named without faulting the device, small batches kept on the CPU, the choice of solver
// with its log line, and the fallback after a CUDA error (no device at all, or a launch CUDA refuses).
// Needs a GPU (skipped, saying so, without one): the GPU's answers against the CPU's over 20 000 random pairs, and a
// World whose continuous stage runs on the GPU keeping a crowd of bullets in their box.
//
// Agreement: with --fmad=false the two differ only where the device's cos/sin round differently from glibc's
// (a few units in the last place). Conservative advancement stops at the first pose with a gap under the tolerance,
// so such a difference can at most move the stop by one advancement step, which changes the reported contact
// position by less than the tolerance (1e-4 m): that is the bound the comparison uses, per pair, as
// |t_gpu - t_cpu| * (fastest speed of a point of the pair per unit t) <= tolerance.

#include <physim/cuda/ContinuousSolver.hpp>
#include <physim/cuda/Device.hpp>

#include "support/RandomBatch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace physim::cuda {
namespace {

bool haveGpu() { return queryDevices().deviceCount > 0; }

// The one place a test is skipped: it needs a GPU and this machine has none (the reason is CUDA's own message).
#define PHYSIM_NEEDS_GPU()                                                                       \
    do {                                                                                         \
        const DeviceStatus status = queryDevices();                                              \
        if (status.deviceCount == 0) GTEST_SKIP() << "needs a CUDA GPU: " << status.message;      \
    } while (false)

TEST(GpuContinuousSolver, BadInputIsNamedAndNeverFaultsTheDevice) {
    GpuSolverOptions options;
    options.minPairs = 0;
    std::ostringstream log;
    options.log = &log;
    GpuContinuousSolver solver(options);
    ContinuousBatchResult r;
    // Arrays of different sizes: refused before any device work.
    ContinuousBatch batch = testing::randomBatch(10, 2);
    batch.pairs.a.pop_back();
    try {
        solver.solve(batch, r);
        ADD_FAILURE() << "accepted arrays of different sizes";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("pairs.b has 10 entries but pairs.a has 9"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(solver.gpuEnabled()) << "bad input is the caller's error, not a reason to leave the GPU";
    EXPECT_EQ(log.str(), "");
    // Bad entries: the kernel checks each pair before reading it, so a wild index or an unknown shape kind is
    // reported by name, and with a GPU, the device is still usable afterwards.
    batch = testing::randomBatch(10, 2);
    batch.shapes.kind[1] = 3;
    batch.pairs.b[7] = 1 << 30;
    try {
        solver.solve(batch, r);
        ADD_FAILURE() << "accepted an unknown shape kind";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("unsupported shape kind 3 at shapes.kind[1]"), std::string::npos)
            << e.what();
    }
    batch.shapes.kind[1] = kernel::kPolygon;
    EXPECT_THROW(solver.solve(batch, r), std::invalid_argument);  // pairs.b[7] out of range
    EXPECT_EQ(solver.gpuEnabled(), haveGpu()) << solver.error();
    GpuSolverOptions bad;
    bad.blockSize = 0;
    EXPECT_THROW(GpuContinuousSolver{bad}, std::invalid_argument);
}

TEST(GpuContinuousSolver, SmallBatchesStayOnTheCpu) {
    GpuContinuousSolver solver;  // default minPairs
    const ContinuousBatch batch = testing::randomBatch(100, 4);
    ContinuousBatchResult gpu, cpu;
    solver.solve(batch, gpu);
    CpuContinuousSolver().solve(batch, cpu);
    EXPECT_FALSE(solver.lastRanOnGpu());
    EXPECT_EQ(gpu.t, cpu.t);
    EXPECT_EQ(gpu.state, cpu.state);
}

TEST(GpuContinuousSolver, MakeContinuousSolverPicksTheGpuOrSaysWhyNot) {
    std::ostringstream log;
    const std::shared_ptr<ContinuousSolver> solver = makeContinuousSolver(log);
    ASSERT_NE(solver, nullptr);
    std::cout << "solver: " << solver->name() << "; log: " << log.str();
    if (haveGpu()) {
        EXPECT_NE(dynamic_cast<GpuContinuousSolver*>(solver.get()), nullptr);
        EXPECT_EQ(log.str(), "");
    } else {
        EXPECT_NE(dynamic_cast<CpuContinuousSolver*>(solver.get()), nullptr);
        EXPECT_NE(log.str().find("no usable CUDA device"), std::string::npos) << log.str();
        EXPECT_NE(log.str().find("continuous collision runs on the CPU"), std::string::npos) << log.str();
    }
}

TEST(GpuContinuousSolver, ACudaErrorIsReportedAndTheCpuSolvesTheBatch) {
    // Without a GPU the first allocation fails; with one, a block of 4096 threads is a launch CUDA refuses
    // (at most 1024). Either way the error is real CUDA's, and the batch must still be solved, on the CPU.
    std::ostringstream log;
    GpuSolverOptions options;
    options.minPairs = 0;
    options.blockSize = haveGpu() ? 4096 : 128;
    options.log = &log;
    GpuContinuousSolver solver(options);
    const ContinuousBatch batch = testing::randomBatch(500, 8);
    ContinuousBatchResult gpu, cpu;
    solver.solve(batch, gpu);
    CpuContinuousSolver().solve(batch, cpu);
    std::cout << log.str();
    EXPECT_FALSE(solver.gpuEnabled());
    EXPECT_FALSE(solver.lastRanOnGpu());
    EXPECT_NE(solver.error().find("CUDA error"), std::string::npos) << solver.error();
    EXPECT_NE(log.str().find("the GPU continuous solver stopped: CUDA error"), std::string::npos) << log.str();
    EXPECT_NE(log.str().find("run on the CPU"), std::string::npos) << log.str();
    EXPECT_EQ(gpu.state, cpu.state);  // nothing lost: the CPU's answers, to the last bit
    EXPECT_EQ(gpu.t, cpu.t);
    EXPECT_EQ(gpu.pointX, cpu.pointX);
    // Later batches go straight to the CPU, without another line.
    const std::string before = log.str();
    solver.solve(batch, gpu);
    EXPECT_EQ(log.str(), before);
    EXPECT_EQ(gpu.t, cpu.t);
    EXPECT_NE(solver.name().find("gpu stopped"), std::string::npos) << solver.name();
}

TEST(GpuContinuousSolverOnGpu, AgreesWithTheCpuOnRandomPairs) {
    PHYSIM_NEEDS_GPU();
    GpuSolverOptions options;
    options.minPairs = 0;
    GpuContinuousSolver solver(options);
    const ContinuousBatch batch = testing::randomBatch(20000, 21);
    ContinuousBatchResult gpu, cpu;
    solver.solve(batch, gpu);
    ASSERT_TRUE(solver.lastRanOnGpu()) << solver.error();
    CpuContinuousSolver(0).solve(batch, cpu);
    const testing::Agreement a = testing::compareResults(batch, gpu, cpu);
    std::cout << "identical " << a.identical << ", within tolerance " << a.within << ", disagreeing " << a.disagree
              << " of " << batch.pairCount() << "; kernel " << solver.lastTimings().kernelMs << " ms, total "
              << solver.lastTimings().totalMs << " ms\n";
    EXPECT_EQ(a.disagree, 0);
    for (std::size_t i = 0, shown = 0; i < batch.pairCount() && shown < 8 && a.disagree > 0; ++i) {
        if (gpu.state[i] == cpu.state[i] && gpu.t[i] == cpu.t[i]) continue;
        ++shown;
        const std::int32_t sa = batch.bodies.shape[batch.pairs.a[i]], sb = batch.bodies.shape[batch.pairs.b[i]];
        std::cout << "pair " << i << " kinds " << batch.shapes.kind[sa] << "/" << batch.shapes.kind[sb] << " gpu "
                  << gpu.state[i] << " t " << gpu.t[i] << " it " << gpu.iterations[i] << " gap " << gpu.gap[i]
                  << " | cpu " << cpu.state[i] << " t " << cpu.t[i] << " it " << cpu.iterations[i] << " gap "
                  << cpu.gap[i] << "\n";
    }
    // Hits report a gap under the tolerance on the GPU too.
    for (std::size_t i = 0; i < batch.pairCount(); ++i)
        if (gpu.state[i] == kernel::kHit) {
            ASSERT_LT(gpu.gap[i], batch.tolerance) << "pair " << i;
        }
    EXPECT_GT(solver.lastTimings().kernelMs, 0.0);
    EXPECT_GE(solver.lastTimings().totalMs, solver.lastTimings().kernelMs);
}

// A World whose continuous batches all run on the GPU keeps the CPU World's guarantees in the tests' hardest scene
// (ContinuousCrowd.BulletsNeverLeaveTheBox): no bullet leaves the box, kinetic energy never runs away. The two
// Worlds are not compared pose by pose: the crowd is chaotic, so the last-bit differences of cos and sin on the
// device (4% of pairs, within the tolerance) grow into different trajectories within a few steps.
TEST(GpuContinuousSolverOnGpu, AWorldOnTheGpuKeepsItsBulletsInTheBox) {
    PHYSIM_NEEDS_GPU();
    WorldSettings s;
    s.gravity = Vec2::Zero();
    World world(s);
    const auto bullets = testing::fillBulletBox(world, 60, 5);
    GpuSolverOptions options;
    options.minPairs = 0;  // every batch on the GPU, however small
    auto gpu = std::make_shared<GpuContinuousSolver>(options);
    world.setContinuousSolver(gpu);
    auto energy = [&] {
        double e = 0.0;
        for (const BodyId b : bullets)
            e += 0.5 * world.mass(b) * world.velocity(b).squaredNorm() +
                 0.5 * world.inertia(b) * world.angularVelocity(b) * world.angularVelocity(b);
        return e;
    };
    const double start = energy();
    double highest = start;
    int onGpu = 0;
    for (int step = 0; step < 60; ++step) {
        world.step(1.0 / 60.0);
        ASSERT_TRUE(gpu->gpuEnabled()) << gpu->error();
        onGpu += gpu->lastRanOnGpu();
        for (const BodyId b : bullets)
            ASSERT_LT(world.position(b).cwiseAbs().maxCoeff(), 2.0) << "a bullet left the box in step " << step;
        highest = std::max(highest, energy());
    }
    EXPECT_EQ(onGpu, 60) << "every step's last batch ran on the GPU";
    EXPECT_LE(highest, 1.01 * start);  // the CPU test's bound, same reason
}

}  // namespace
}  // namespace physim::cuda
