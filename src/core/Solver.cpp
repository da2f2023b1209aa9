// The soft step over the awake bodies: gather them into contiguous arrays, colour the contact rows so rows of one
// colour share no dynamic body (they can be solved in any order, on any thread, with the same result), then
// substeps of integrate velocities -> warm start -> solve -> integrate positions -> relax, one restitution pass,
// and finalize (poses, boxes, sleep timers, proxies that left their boxes).

#include "Impulse.hpp"
#include "Joints.hpp"
#include "WorldImpl.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

namespace physim {
namespace {

// Colours tried per row before it goes to the overflow (solved serially after the coloured rows).
constexpr int kColours = 24;
constexpr std::size_t kBodyGrain = 256;
constexpr std::size_t kBlockGrain = 16;  // blocks of kLanes rows

class StageTimer {
public:
    StageTimer(StepProfile& profile, Stage stage) : profile_(profile), stage_(stage) {}
    ~StageTimer() {
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start_;
        profile_.secondsOf(stage_) += elapsed.count();
        profile_.ran[static_cast<std::size_t>(stage_)] = true;
    }

private:
    StepProfile& profile_;
    Stage stage_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace

void WorldImpl::solve() {
    const std::size_t n = awake.size();
    const int substeps = settings.substeps;
    const double h = dt / substeps, invH = 1.0 / h;
    const Softness contactSoftness = makeSoftness(settings.contactHertz, settings.contactDampingRatio, h);
    const Softness rodSoftness = makeSoftness(settings.jointHertz, settings.jointDampingRatio, h);

    {
        StageTimer timer(profile, Stage::Forces);
        solverBodies.assign(n + 1, SolverBody{});  // [0]: the still body that kNullIndex reads (ContactSolver.hpp)
        states = solverBodies.data() + 1;
        sims.resize(n);
        const Vec2 gravity = settings.gravity;
        executor.parallelFor(n, kBodyGrain, [&](std::size_t begin, std::size_t end, int) {
            for (std::size_t i = begin; i < end; ++i) {
                const BodyData& b = bodies[awake[i]];
                const bool dynamic = b.type == BodyType::Dynamic;
                SolverBody& s = states[i];
                s.v = b.v;
                s.w = b.w;
                s.dAngle = 0.0;
                s.dp.setZero();
                s.dq = Rotation{};
                SolverBodySim& sim = sims[i];
                sim.center0 = b.center;
                sim.q0 = b.xf.q;
                sim.angle0 = b.angle;
                sim.acceleration = dynamic ? Vec2(b.gravityFactor() * gravity + b.invMass * b.force) : Vec2::Zero();
                sim.angularAcceleration = dynamic ? b.invInertia * b.torque : 0.0;
                sim.invInertia = dynamic ? b.invInertia : 0.0;
                sim.body = awake[i];
                sim.dynamic = dynamic;
                sim.turns = rowSide(b).turns;
            }
        });
    }

    // Colour the rows: greedy, in the awake list's order (deterministic), each dynamic body's colours as bits.
    std::size_t rowCount = 0;
    rowContacts.clear();
    blockRows.clear();
    jointConstraints.clear();
    colourStart.assign(kColours + 2, 0);
    blockStart.assign(kColours + 2, 0);
    if (!awakeContacts.empty() || rowJointCount > 0) {
        StageTimer timer(profile, Stage::Solve);
        bodyColours.assign(n, 0);
        constexpr std::uint32_t kAllColours = (std::uint32_t{1} << kColours) - 1;
        constraintColour.assign(awakeContacts.size(), -1);
        for (std::size_t k = 0; k < awakeContacts.size(); ++k) {
            const ContactData& c = contacts[awakeContacts[k]];
            if (c.manifold.pointCount == 0) continue;
            const BodyData& A = bodies[c.a];
            const BodyData& B = bodies[c.b];
            // The lowest colour neither dynamic body has yet; the overflow if both have them all.
            auto used = [&](const BodyData& b) -> std::uint32_t* {
                const bool moves = b.type == BodyType::Dynamic && b.awakeIndex != kNullIndex;
                return moves ? &bodyColours[static_cast<std::size_t>(b.awakeIndex)] : nullptr;
            };
            std::uint32_t* const usedA = used(A);
            std::uint32_t* const usedB = used(B);
            const std::uint32_t free = ~((usedA ? *usedA : 0u) | (usedB ? *usedB : 0u)) & kAllColours;
            int colour = kColours;
            if (free != 0) {
                colour = __builtin_ctz(free);
                if (usedA) *usedA |= std::uint32_t{1} << colour;
                if (usedB) *usedB |= std::uint32_t{1} << colour;
            }
            constraintColour[k] = colour;
            ++colourStart[static_cast<std::size_t>(colour) + 1];
            ++rowCount;
        }
        for (int col = 0; col <= kColours; ++col) colourStart[col + 1] += colourStart[col];
        rowContacts.resize(rowCount);
        colourFill.assign(colourStart.begin(), colourStart.end() - 1);
        for (std::size_t k = 0; k < awakeContacts.size(); ++k)
            if (constraintColour[k] >= 0)
                rowContacts[colourFill[static_cast<std::size_t>(constraintColour[k])]++] = awakeContacts[k];
        // kLanes rows of a colour to a block; an overflow row shares no block (it may share a body with the next).
        for (int col = 0; col <= kColours; ++col) {
            const std::uint32_t first = colourStart[col], end = colourStart[col + 1];
            const std::uint32_t lanes = col < kColours ? kLanes : 1;
            for (std::uint32_t r = first; r < end; r += lanes) blockRows.push_back({r, std::min(lanes, end - r)});
            blockStart[col + 1] = static_cast<std::uint32_t>(blockRows.size());
        }
        contactBlocks.resize(blockRows.size());  // every lane is written below: no need to clear them
        contactCold.resize(blockRows.size());
        std::atomic<std::size_t> turningRows{0};  // counted while each row is at hand, one add per chunk
        executor.parallelFor(contactBlocks.size(), kBlockGrain, [&](std::size_t begin, std::size_t end, int) {
            std::size_t turning = 0;
            for (std::size_t b = begin; b < end; ++b) {
                ContactBlock& block = contactBlocks[b];
                const int lanes = static_cast<int>(blockRows[b].count);
                startBlock(block, contactCold[b], lanes);
                for (int lane = 0; lane < lanes; ++lane) {
                    ContactConstraint row;
                    row.contact = rowContacts[blockRows[b].first + static_cast<std::uint32_t>(lane)];
                    prepareContact(row, contacts[row.contact], bodies, settings.gravity);
                    setRow(block, contactCold[b], lane, row);
                    turning += row.turns ? 1 : 0;
                }
            }
            turningRows.fetch_add(turning, std::memory_order_relaxed);
        });
        profile.turningRows = turningRows.load();
        jointConstraints.clear();
        for (std::uint32_t j = 0; j < joints.size(); ++j) {
            const JointData& joint = joints[j];
            if (!joint.alive || !joint.isRow()) continue;
            const bool active = bodies[joint.b].awake() || (joint.twoBodies() && bodies[joint.a].awake());
            if (!active) continue;
            JointConstraint row;
            row.joint = j;
            prepareJoint(row, joint, bodies, h, rodSoftness);
            jointConstraints.push_back(row);
        }
    }

    SolverBody* const st = states;
    ContactBlock* const blocks = contactBlocks.data();
    ContactBlockCold* const cold = contactCold.data();
    // One pass over all rows: joints, then colour by colour (in parallel within a colour), then the overflow.
    // rowsWork(begin, end, worker) over blocks; jointWork(row, joint) for each joint.
    auto pass = [&](auto&& rowsWork, auto&& jointWork) {
        for (const JointConstraint& row : jointConstraints) jointWork(row, joints[row.joint]);
        for (int col = 0; col < kColours; ++col) {
            const std::size_t first = blockStart[col], count = blockStart[col + 1] - first;
            executor.parallelFor(count, kBlockGrain, [&](std::size_t begin, std::size_t end, int worker) {
                rowsWork(blocks + first + begin, blocks + first + end, worker);
            });
        }
        rowsWork(blocks + blockStart[kColours], blocks + blockStart[kColours + 1], 0);
    };
    ContactPass contactPass;
    contactPass.h = h;
    contactPass.invH = invH;
    contactPass.softness = contactSoftness;
    contactPass.maxPushVelocity = settings.contactPushMaxVelocity;
    contactPass.restitutionThreshold = settings.restitutionThreshold;
    contactPass.slipSpeed = 0.1 * settings.linearSlop / dt;
    pushVelocities.assign(n, PushVelocity{});
    contactPass.pushes = pushVelocities.data();
    auto solvePass = [&](bool useBias) {
        contactPass.useBias = useBias;
        pass([&](ContactBlock* b, ContactBlock* e, int) { solveContacts(b, e, cold + (b - blocks), st, contactPass); },
             [&](const JointConstraint& row, JointData& joint) { solveJoint(row, joint, st, useBias); });
    };
    const bool anyRows = rowCount > 0 || !jointConstraints.empty();

    for (int sub = 0; sub < substeps; ++sub) {
        contactPass.substep = sub;
        if (effects.perSubstep()) effects.substep(*this, h);
        {
            StageTimer timer(profile, Stage::Integrate);
            executor.parallelFor(n, kBodyGrain, [&](std::size_t begin, std::size_t end, int) {
                for (std::size_t i = begin; i < end; ++i) {
                    const SolverBodySim& sim = sims[i];
                    if (!sim.dynamic) continue;
                    st[i].v += h * sim.acceleration;
                    if (sim.turns) st[i].w += h * sim.angularAcceleration;
                }
            });
        }
        if (anyRows) {
            StageTimer timer(profile, Stage::Solve);
            pass([&](ContactBlock* b, ContactBlock* e, int) { warmStartContacts(b, e, st); },
                 [&](const JointConstraint& row, JointData& joint) { warmStartJoint(row, joint, st); });
            for (int it = 0; it < settings.velocityIterations; ++it) solvePass(true);
        }
        {
            StageTimer timer(profile, Stage::Integrate);
            executor.parallelFor(n, kBodyGrain, [&](std::size_t begin, std::size_t end, int) {
                for (std::size_t i = begin; i < end; ++i) {
                    SolverBody& s = st[i];
                    s.dp += h * s.v;
                    if (s.w != 0.0) {
                        const double turn = h * s.w;
                        s.dAngle += turn;
                        s.dq = compose(rotationBy(turn), s.dq);
                    }
                }
            });
        }
        if (anyRows) {
            StageTimer timer(profile, Stage::Solve);
            for (int it = 0; it < settings.relaxIterations; ++it) solvePass(false);
        }
    }

    if (rowCount > 0) {
        StageTimer timer(profile, Stage::Solve);
        executor.parallelFor(contactBlocks.size(), kBlockGrain, [&](std::size_t begin, std::size_t end, int) {
            for (std::size_t b = begin; b < end; ++b)
                for (std::uint32_t lane = 0; lane < blockRows[b].count; ++lane)
                    storeImpulses(blocks[b], cold[b], static_cast<int>(lane), contacts[cold[b].lanes[lane].contact]);
        });
        // Impacts, in row order (deterministic): the fastest meeting point of each contact above the threshold.
        for (std::size_t b = 0; b < contactBlocks.size(); ++b)
            for (std::uint32_t lane = 0; lane < blockRows[b].count; ++lane) {
                const ContactBlockCold::Lane& c = cold[b].lanes[lane];
                int fastest = -1;
                for (int p = 0; p < c.pointCount; ++p)
                    if (c.engaged[p] && -c.relativeVelocity[p] > settings.impactSpeedThreshold &&
                        (fastest < 0 || c.relativeVelocity[p] < c.relativeVelocity[fastest]))
                        fastest = p;
                if (fastest < 0) continue;
                const Manifold& m = contacts[c.contact].manifold;
                events.impacts.push_back({m.bodyA, m.bodyB, m.points[fastest].point, m.normal,
                                          -c.relativeVelocity[fastest]});
            }
    }

    StageTimer timer(profile, Stage::Integrate);
    enlarged.assign(n, 0);
    const double linearTolerance = settings.sleepLinearTolerance, angularTolerance = settings.sleepAngularTolerance;
    const bool sleep = settings.enableSleep;
    executor.parallelFor(n, kBodyGrain, [&](std::size_t begin, std::size_t end, int) {
        for (std::size_t i = begin; i < end; ++i) {
            const SolverBody& s = st[i];
            const SolverBodySim& sim = sims[i];
            BodyData& b = bodies[sim.body];
            b.v = s.v;
            b.w = s.w;
            b.center = sim.center0 + s.dp;
            if (sim.turns) {
                b.angle = sim.angle0 + s.dAngle;
                b.xf.q = compose(s.dq, sim.q0);
            }
            b.xf.p = b.center - b.xf.q.apply(b.localCenter);
            b.force.setZero();
            b.torque = 0.0;
            b.aabb = computeAabb(b.shape, b.xf);
            if (sleep && b.canSleep() && sim.dynamic && b.v.norm() <= linearTolerance &&
                std::abs(b.w) <= angularTolerance)
                b.sleepTime += dt;
            else
                b.sleepTime = 0.0;
            // Its proxy must move (bit 0); it moved far for its size this step (bit 1: the Continuous stage's).
            const double travel = s.dp.norm() + std::abs(s.dAngle) * b.extent;
            enlarged[i] = static_cast<std::uint8_t>((proxyOutgrown(b) ? 1 : 0) |
                                                    (sim.dynamic && b.proxy != kNullIndex &&
                                                     travel > 0.5 * b.coreRadius ? 2 : 0));
        }
    });
    fastBodies = std::any_of(enlarged.begin(), enlarged.end(), [](std::uint8_t f) { return (f & 2) != 0; });
    for (std::size_t i = 0; i < n; ++i) {
        if (!(enlarged[i] & 1)) continue;
        const BodyData& b = bodies[sims[i].body];
        // The Continuous stage may put this body back: its proxy moves after that stage, once (bit 2).
        if ((enlarged[i] & 2) || b.detection != CollisionDetection::Discrete) enlarged[i] |= 4;
        else moveProxy(b);
    }
}

void WorldImpl::moveDeferredProxies() {
    deferredKeys.clear();
    deferredBoxes.clear();
    for (std::size_t i = 0; i < enlarged.size(); ++i) {
        const BodyData& b = bodies[sims[i].body];
        if (!(enlarged[i] & 4) || !proxyOutgrown(b)) continue;
        deferredKeys.push_back(b.proxy);
        deferredBoxes.push_back(proxyBox(b, kAabbMargin));
    }
    broadPhase.moveProxies(deferredKeys, deferredBoxes);  // a crowd of fast bodies rebuilds the tree once
}

}  // namespace physim
