#pragma once
// Sequential impulses over all contact points (Catto, GDC 2006): each pair once per iteration, accumulated
// impulses clamped (normal >= 0, friction inside Coulomb's cone), warm started from the previous step, then a
// position projection that moves bodies apart without adding velocity (so it adds no energy).

#include "BodyData.hpp"

#include "physim/core/Contact.hpp"
#include "physim/core/WorldSettings.hpp"

#include <cstdint>
#include <vector>

namespace physim {

class ContactSolver {
public:
    /// Caches per-point lever arms and effective masses; applies the warm-start impulses already stored in
    /// the manifolds' points.
    void prepare(std::vector<BodyData>& bodies, std::vector<Manifold>& manifolds, const WorldSettings& s);
    void solveVelocities(std::vector<BodyData>& bodies, std::vector<Manifold>& manifolds);
    /// After positions were integrated: push overlapping bodies apart by position changes only. Contacts of a
    /// body marked in `moved` (the continuous stage put it elsewhere: its anchors are stale) are left alone.
    void correctPositions(std::vector<BodyData>& bodies, const std::vector<Manifold>& manifolds,
                          const WorldSettings& s, const std::vector<std::uint8_t>* moved = nullptr);

private:
    struct PointState {
        Vec2 rA, rB;             // lever arms from the centres of mass, m
        Vec2 localA, localB;     // the touching surface points in each body's frame (for position correction)
        double normalMass = 0.0;
        double tangentMass = 0.0;
        double velocityBias = 0.0;  // restitution target, m/s
    };
    struct PairState {
        std::uint32_t a = 0, b = 0;
        double restitution = 0.0, staticFriction = 0.0, dynamicFriction = 0.0;
        PointState points[2];
        bool blockSolve = false;  // two-point manifold solved as one 2x2 problem (below)
        double k11 = 0.0, k12 = 0.0, k22 = 0.0, invDet = 0.0;  // normal mass matrix K and 1/det K
    };
    void solveNormalBlock(BodyData& A, BodyData& B, Manifold& m, const PairState& ps);
    std::vector<PairState> pairs_;
};

}  // namespace physim
