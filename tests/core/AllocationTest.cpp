// A running scene allocates nothing per step: every buffer of the step (contacts, rows, colours, islands, the
// threads' team) keeps its capacity from step to step. This program replaces the global operator new to count
// the calls, so it is a program of its own.

#include "physim/core/World.hpp"
#include "support/Scenes.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace {
// Counted only while `counting` is set, so that gtest's own allocations outside the measured steps do not count.
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
    if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void* operator new(std::size_t size, std::align_val_t align) {
    if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
    const std::size_t a = static_cast<std::size_t>(align);
    if (void* p = std::aligned_alloc(a, (size + a - 1) / a * a)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size, std::align_val_t align) { return operator new(size, align); }
// These are the replacements themselves: memory from the operators above goes back with free().
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;

// A base-20 pyramid (210 boxes, about 600 contact points) on a static ground, sleep off so that every step does
// the whole work: broad phase, narrow phase, colouring, the solve and the islands.
void buildPyramid(World& world) {
    test::addGround(world, 30.0);
    test::addPyramid(world, 20);
}

// Twelve base-8 pyramids 10 m apart (432 boxes in twelve islands): the solver groups islands and solves the
// groups apart, with buffers of its own.
void buildPiles(World& world) {
    test::addGround(world, 70.0);
    for (int p = 0; p < 12; ++p) test::addPyramid(world, 8, 10.0 * (p - 6));
}

long allocationsOverSteps(World& world, int steps) {
    allocations.store(0);
    counting.store(true);
    for (int k = 0; k < steps; ++k) world.step(kDt);
    counting.store(false);
    return allocations.load();
}

class Allocation : public ::testing::TestWithParam<int> {};

void expectSettledStepsAllocateNothing(void (*build)(World&), int threads) {
    WorldSettings settings;
    settings.enableSleep = false;
    settings.threads = threads;
    World world(settings);
    build(world);
    for (int k = 0; k < 120; ++k) world.step(kDt);  // 2 s: settled, and every buffer at its working size
    // The check can fail: the first steps of the same world allocate (this also proves the counter counts).
    World fresh(settings);
    build(fresh);
    EXPECT_GT(allocationsOverSteps(fresh, 2), 0) << "the counter sees the first steps' allocations";
    EXPECT_EQ(allocationsOverSteps(world, 60), 0) << threads << " threads";
}

TEST_P(Allocation, ASettledPyramidStepsWithoutAllocating) {
    expectSettledStepsAllocateNothing(buildPyramid, GetParam());
}

TEST_P(Allocation, ManySettledPilesStepWithoutAllocating) {
    expectSettledStepsAllocateNothing(buildPiles, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Threads, Allocation, ::testing::Values(1, 2),
                         [](const auto& info) { return std::to_string(info.param) + "Threads"; });

}  // namespace
}  // namespace physim
