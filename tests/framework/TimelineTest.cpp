// The window's timeline (Timeline): a run recorded step by step, then scrubbed back to earlier moments, lands on
// exactly the states the run had then (equal World::stateHash: the replay from the nearest snapshot repeats the
// deterministic steps) and on the graphs' points as they were; a small memory budget thins the record but keeps its
// start, so every moment stays reachable; going back and running on repeats the same future.

#include <physim/core/CircleShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Simulation.hpp>
#include <physim/framework/Timeline.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>

namespace physim {
namespace {

// Balls bouncing in a box, and a graph of the first one's height: every step changes the state.
class Bouncing : public Simulation {
public:
    Bouncing() {
        auto& ground = spawn<Object>(RectangleShape({20.0, 0.5}), sf::Color::Black);
        ground.rb.setMass(0.0);
        for (int i = 0; i < 12; ++i) {
            Object& ball = spawn<Object>(CircleShape(0.3), sf::Color::Black);
            ball.setPosition({-5.0 + 0.9 * i, 2.0 + 0.7 * (i % 4)});
            ball.rb.setRestitution(0.8);
            balls.push_back(&ball);
        }
        height = graphsManager.addGraph("height;t (s);y (m)");
        graphsManager.build();
    }
    void onDrawGraphs() override { graphsManager.addPoint(height, time, balls[0]->getPosition().y()); }
    std::vector<Object*> balls;
    int height = -1;
};

struct Recording {
    Bouncing sim;
    Timeline timeline;
    std::map<long long, std::uint64_t> hashAtStep;  // the first run's states
    explicit Recording(const Timeline::Settings& s) : timeline(s) { timeline.record(sim); }
    long long step() const { return std::llround(sim.time / sim.fixedTimeStep()); }
    void frame(bool record) {  // as the runner's one-step frame
        sim.onUpdate();
        sim.fixedStep();
        sim.onDrawGraphs();
        if (record) timeline.record(sim);
    }
};

// The bytes of one snapshot of the scene, about (its first, after a step).
std::size_t oneSnapshot() {
    Recording probe(Timeline::Settings{});
    probe.frame(true);
    return probe.timeline.bytes();
}

// A snapshot every `interval` steps whatever they cost (no cost limit), within `budget` bytes (0: the default).
Timeline::Settings everySteps(int interval, std::size_t budget = 0) {
    Timeline::Settings settings;
    settings.minInterval = interval;
    settings.costShare = 1e9;
    if (budget > 0) settings.budgetBytes = budget;
    return settings;
}

TEST(Timeline, ScrubbingBackLandsOnTheStatesTheRunHad) {
    Recording run(Timeline::Settings{});
    for (int i = 0; i < 400; ++i) {
        run.frame(true);
        run.hashAtStep[run.step()] = run.sim.world().stateHash();
    }
    EXPECT_GE(run.timeline.size(), 2u);
    EXPECT_DOUBLE_EQ(run.timeline.end(), run.sim.time);
    // Each scrub drops the record after its point, so the times go down.
    for (const double t : {9.975, 7.5, 5.0125, 3.0, 0.025, 0.0}) {
        const double at = run.timeline.scrubTo(run.sim, t, [&] { run.frame(false); });
        const long long step = run.step();
        EXPECT_LE(at, t + 1e-9) << "the last step at or before " << t;
        EXPECT_GT(at, t - run.sim.fixedTimeStep()) << t;
        if (step > 0) {
            EXPECT_EQ(run.sim.world().stateHash(), run.hashAtStep.at(step)) << "t = " << t;
        }
        // One point per step so far (the graph follows the scrub).
        EXPECT_EQ(run.sim.graphsManager.points(run.sim.height).size(), static_cast<std::size_t>(step)) << t;
        EXPECT_LE(run.timeline.end(), at + 1e-12) << "the future after the scrub point is dropped";
    }
}

TEST(Timeline, GoingBackAndRunningOnRepeatsTheFuture) {
    Recording run(Timeline::Settings{});
    for (int i = 0; i < 200; ++i) {
        run.frame(true);
        run.hashAtStep[run.step()] = run.sim.world().stateHash();
    }
    run.timeline.scrubTo(run.sim, 2.0, [&] { run.frame(false); });
    while (run.step() < 200) {
        run.frame(true);
        ASSERT_EQ(run.sim.world().stateHash(), run.hashAtStep.at(run.step())) << "step " << run.step();
    }
}

// A budget of a few snapshots: the record thins (every other of its older half goes) but keeps its first one, so
// the start stays reachable, and holds no more than the budget.
TEST(Timeline, ASmallBudgetThinsTheRecordButKeepsItsStart) {
    const std::size_t one = oneSnapshot();
    const Timeline::Settings settings = everySteps(4, 6 * one);
    Recording run(settings);
    for (int i = 0; i < 400; ++i) {
        run.frame(true);
        run.hashAtStep[run.step()] = run.sim.world().stateHash();
        ASSERT_LE(run.timeline.bytes(), settings.budgetBytes + one) << "step " << i;
    }
    EXPECT_LE(run.timeline.size(), 7u);
    EXPECT_EQ(run.timeline.start(), 0.0);
    run.timeline.scrubTo(run.sim, 0.5, [&] { run.frame(false); });
    EXPECT_EQ(run.sim.world().stateHash(), run.hashAtStep.at(20));
}

// A change made between steps (here a ball thrown up; in the window a branch, a drag, a key the scene handles)
// cannot be replayed from an earlier snapshot. mark keeps a snapshot of that moment, so a scrub to any later moment
// lands on the states the run had, with no other snapshot since the start, and after the budget thinned the record.
TEST(Timeline, AMarkedChangeIsNeverReplayedAcross) {
    Recording run(everySteps(1000));  // no snapshot but the start's and the mark's
    for (int i = 0; i < 20; ++i) run.frame(true);
    run.sim.balls[0]->rb.setVelocity({0.0, 6.0});
    run.timeline.mark(run.sim);
    EXPECT_EQ(run.timeline.size(), 2u);
    for (int i = 0; i < 100; ++i) {
        run.frame(true);
        run.hashAtStep[run.step()] = run.sim.world().stateHash();
    }
    run.timeline.scrubTo(run.sim, 2.0, [&] { run.frame(false); });
    ASSERT_EQ(run.step(), 80);
    EXPECT_EQ(run.sim.world().stateHash(), run.hashAtStep.at(80));

    Recording thinned(everySteps(4, 6 * oneSnapshot()));  // room for about six snapshots
    for (int i = 0; i < 20; ++i) thinned.frame(true);
    thinned.timeline.mark(thinned.sim);  // the record already holds step 20's: the mark replaces it
    thinned.sim.balls[0]->rb.setVelocity({0.0, 6.0});
    thinned.timeline.mark(thinned.sim);
    for (int i = 0; i < 400; ++i) {
        thinned.frame(true);
        thinned.hashAtStep[thinned.step()] = thinned.sim.world().stateHash();
    }
    EXPECT_LE(thinned.timeline.size(), 7u) << "the budget holds";
    thinned.timeline.scrubTo(thinned.sim, 0.6, [&] { thinned.frame(false); });
    ASSERT_EQ(thinned.step(), 24) << "the mark was kept: the scrub lands where asked";
    EXPECT_EQ(thinned.sim.world().stateHash(), thinned.hashAtStep.at(24));
}

// A budget too small to keep the mark (the first snapshot and the latest only): a scrub past the change stops at
// its moment, on the state just before it, which the run had; it never replays across it into states the run never
// had. Running on from there is a new future, without the change.
TEST(Timeline, AScrubStopsAtAChangeItsRecordNoLongerHolds) {
    Recording run(everySteps(4, 2 * oneSnapshot()));
    for (int i = 0; i < 20; ++i) run.frame(true);
    const std::uint64_t beforeChange = run.sim.world().stateHash();
    run.sim.balls[0]->rb.setVelocity({0.0, 6.0});
    run.timeline.mark(run.sim);
    for (int i = 0; i < 100; ++i) run.frame(true);
    ASSERT_EQ(run.timeline.size(), 2u) << "the mark is thinned out";
    run.timeline.scrubTo(run.sim, 2.0, [&] { run.frame(false); });
    EXPECT_EQ(run.step(), 20);
    EXPECT_EQ(run.sim.world().stateHash(), beforeChange);
    // The change is gone from the record with the future it began: a later scrub back within it replays freely.
    for (int i = 0; i < 40; ++i) run.frame(true);
    Recording unchanged(Timeline::Settings{});
    for (int i = 0; i < 50; ++i) unchanged.frame(false);
    run.timeline.scrubTo(run.sim, 1.25, [&] { run.frame(false); });
    EXPECT_EQ(run.step(), 50);
    EXPECT_EQ(run.sim.world().stateHash(), unchanged.sim.world().stateHash());
}

// A change made often (a drag's moves) is noted with a snapshot only where one is due, or where one of the same step
// was taken before the change (it is taken again). A scrub lands exactly where the record allows, and else stops at
// the first noted change after its snapshot, on the state just before it.
TEST(Timeline, ANotedChangeKeepsASnapshotOnlyWhereOneIsDue) {
    Recording run(everySteps(4));
    for (int i = 0; i < 10; ++i) run.frame(true);  // snapshots at steps 0, 4, 8
    ASSERT_EQ(run.timeline.size(), 3u);
    const std::uint64_t beforeFirst = run.sim.world().stateHash();
    run.sim.balls[0]->rb.setVelocity({0.0, 6.0});
    run.timeline.noteChange(run.sim);
    EXPECT_EQ(run.timeline.size(), 3u) << "none due at step 10";
    for (int i = 0; i < 2; ++i) run.frame(true);  // step 12's
    ASSERT_EQ(run.timeline.size(), 4u);
    run.sim.balls[1]->rb.setVelocity({0.0, 6.0});
    run.timeline.noteChange(run.sim);  // step 12's snapshot is taken again, with the change
    EXPECT_EQ(run.timeline.size(), 4u);
    for (int i = 0; i < 20; ++i) {
        run.frame(true);
        run.hashAtStep[run.step()] = run.sim.world().stateHash();
    }
    run.timeline.scrubTo(run.sim, 0.7, [&] { run.frame(false); });
    ASSERT_EQ(run.step(), 28);
    EXPECT_EQ(run.sim.world().stateHash(), run.hashAtStep.at(28));
    run.timeline.scrubTo(run.sim, 0.325, [&] { run.frame(false); });  // step 13: from step 12's snapshot
    ASSERT_EQ(run.step(), 13);
    EXPECT_EQ(run.sim.world().stateHash(), run.hashAtStep.at(13));
    run.timeline.scrubTo(run.sim, 0.275, [&] { run.frame(false); });  // step 11: from step 8's, stopped at 10
    ASSERT_EQ(run.step(), 10);
    EXPECT_EQ(run.sim.world().stateHash(), beforeFirst);
}

// The interval adapts so that a snapshot costs at most costShare of the steps between two, never below minInterval:
// with no cost limit one comes every minInterval steps; with a limit no snapshot can meet (a share of 1e-12) the
// first measured one sets an interval beyond the run.
TEST(Timeline, SnapshotsAreSpacedByTheirCost) {
    const Timeline::Settings free = everySteps(3);
    Recording often(free);
    for (int i = 0; i < 99; ++i) often.frame(true);
    EXPECT_EQ(often.timeline.size(), 99u / 3u + 1u);  // at steps 0, 3, ..., 99

    Timeline::Settings dear = free;
    dear.costShare = 1e-12;
    Recording rarely(dear);
    for (int i = 0; i < 99; ++i) rarely.frame(true);
    EXPECT_EQ(rarely.timeline.size(), 2u);  // step 0, then step 3, whose cost spaces the next past the run
    EXPECT_GT(rarely.timeline.interval(), 99);

    Timeline empty;
    Bouncing sim;
    EXPECT_THROW(empty.scrubTo(sim, 1.0, [] {}), std::logic_error);
}

}  // namespace
}  // namespace physim
