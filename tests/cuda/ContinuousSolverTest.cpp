// The GPU continuous solver's behaviour with or without a GPU: bad input named without faulting the device, small
// batches kept on the CPU, the choice of solver with its log line, and the fallback after a real CUDA error (no
// device at all, or a launch CUDA refuses). The tests that need a GPU are in OnGpuTest.cpp.

#include <physim/cuda/ContinuousSolver.hpp>
#include <physim/cuda/Device.hpp>

#include "ContinuousKernel.hpp"

#include "support/KernelShapes.hpp"
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
    batch.shapes.kind[1] = 7;  // no kind has code 7
    batch.pairs.b[7] = 1 << 30;
    try {
        solver.solve(batch, r);
        ADD_FAILURE() << "accepted an unknown shape kind";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("unsupported shape kind 7 at shapes.kind[1]"), std::string::npos)
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

// Segments, capsules, chain segments and rounded polygons need no CPU route of their own: the device compiles the
// same kernel header, so the GPU solver takes them as it takes circles and polygons. With a GPU the batch runs
// there and agrees with the CPU (testing::compareResults' bound); without one the solver's CUDA-error fallback
// solves it on the CPU, to the CPU's bits.
TEST(GpuContinuousSolver, SegmentCapsuleChainAndRoundedKindsRunOnTheGpuOrFallBack) {
    std::ostringstream log;
    GpuSolverOptions options;
    options.minPairs = 0;
    options.log = &log;
    GpuContinuousSolver solver(options);
    const ContinuousBatch batch = testing::kernelBatch(testing::roundedKindsPairs(2000, 12));
    ContinuousBatchResult gpu, cpu;
    solver.solve(batch, gpu);
    CpuContinuousSolver().solve(batch, cpu);
    ASSERT_EQ(gpu.size(), batch.pairCount());
    if (haveGpu()) {
        EXPECT_TRUE(solver.lastRanOnGpu()) << solver.error();
        EXPECT_EQ(testing::compareResults(batch, gpu, cpu).disagree, 0);
    } else {
        EXPECT_FALSE(solver.lastRanOnGpu());
        EXPECT_NE(log.str().find("run on the CPU"), std::string::npos) << log.str();
        EXPECT_EQ(gpu.state, cpu.state);
        EXPECT_EQ(gpu.t, cpu.t);
        EXPECT_EQ(gpu.normalY, cpu.normalY);
    }
}

}  // namespace
}  // namespace physim::cuda
