#pragma once
// Continuous collision detection (the paper's sections 5.1.2-5.1.5): the distance between two placed convex
// shapes, and the first time two moving shapes touch, found either by the paper's sampling or exactly by
// conservative advancement. No allocation, no exceptions (callers validate at the API boundary, see
// checkPrecision). shapeDistance and timeOfImpact are thin wrappers over ContinuousKernel.hpp, the one copy of
// that math which the CUDA layer compiles for the GPU; ContinuousBatch.hpp runs many queries at once.
// SI units: metres, radians; time is the fraction t in [0, 1] of the motion (of one step in the World).

#include "physim/core/Geometry.hpp"
#include "physim/core/Math.hpp"

namespace physim {

/// How a body's collisions are found (the paper's discrete and continuous modes, section 5.1):
/// Discrete: only at the end of each step (can tunnel through thin obstacles);
/// ContinuousSampled: the paper's loop, testing poses at fractions 0, p, 2p, ..., 1 of the step (p = precision);
/// ContinuousExact: time of impact by conservative advancement, within kToiTolerance.
enum class CollisionDetection { Discrete, ContinuousSampled, ContinuousExact };

/// Default spacing of the sampled method, as a fraction of the step (the paper's `precision = 0.1f`).
constexpr double kDefaultPrecision = 0.1;

/// Linear target of the exact time of impact, m: it returns a pose whose gap to the other shape is in
/// [0, kToiTolerance) (conservative: never past the true contact, up to rounding). 1/50 of the World's default
/// linear slop, so a body placed there is in contact for every practical purpose.
constexpr double kToiTolerance = 1e-4;

/// Throws std::invalid_argument naming the value unless 0 < precision <= 1 (NaN rejected).
void checkPrecision(double precision);

/// A body's motion over the interval: its origin and angle move linearly from (p0, a0) to (p1, a1). (The World
/// turns a body about its centre of mass, so for an off-centre shape this straight path is an approximation.)
struct Sweep {
    Vec2 p0 = Vec2::Zero();  ///< m
    Vec2 p1 = Vec2::Zero();  ///< m
    double a0 = 0.0;         ///< rad
    double a1 = 0.0;         ///< rad

    Transform at(double t) const {
        return {p0 + t * (p1 - p0), Rotation::fromAngle(a0 + t * (a1 - a0))};
    }
    double angleAt(double t) const { return a0 + t * (a1 - a0); }
};

/// Largest distance (m) from the body origin to a point of the shape: how far a point can move per radian.
double boundingRadius(const Geometry& g);

/// Closest points of two placed shapes. distance is 0 when they touch or overlap (then the other fields are
/// left zero); otherwise pointA (on a) and pointB (on b) are closest points and normal = (pointB - pointA) / distance.
struct DistanceOutput {
    double distance = 0.0;       ///< m, >= 0
    Vec2 normal = Vec2::Zero();  ///< unit, from a to b (only when distance > 0)
    Vec2 pointA = Vec2::Zero();  ///< m, world
    Vec2 pointB = Vec2::Zero();  ///< m, world
};

/// Exact Euclidean distance between two convex shapes (circle, polygon); no NaN for valid input.
DistanceOutput shapeDistance(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb);

enum class ToiState {
    Separated,  ///< no contact during the motion (exact: the shapes stay more than tolerance / 2 apart)
    Hit,        ///< first contact at t
    Touching,   ///< already touching at t = 0 (within the tolerance, or overlapping for the sampled method)
    Failed      ///< exact method only: neither a contact nor its absence proven within maxIterations; not a hit
};

struct ToiResult {
    ToiState state = ToiState::Separated;
    double t = 1.0;      ///< fraction of the motion; 1 when separated; when failed, how far they were proven apart
    int iterations = 0;  ///< distance (exact) or narrow-phase (sampled) evaluations
};

/// Exact time of impact by conservative advancement (docs/ccd.md): from t = 0, measure the distance and advance
/// t by as much as provably keeps the shapes more than tolerance / 2 apart, until the distance is below the
/// tolerance (m, > 0: Hit at that t, or Touching at t = 0) or t reaches 1 (Separated). The advance takes the best of
/// several bounds: the classic one (no point closes the gap along the closest-point normal faster than
/// (motion_a - motion_b) . n + |turn_a| R_a + |turn_b| R_b), and second-order ones that follow separating lines
/// turning with a and with b, which converge on grazing, fast-spinning pairs. Never reports a
/// time past the first contact (up to rounding), and never Separated for shapes that come closer than
/// tolerance / 2. Failed when maxIterations distance evaluations settle neither: callers treat it as no impact
/// found (the World's discrete contacts then see the pair).
ToiResult timeOfImpact(const Geometry& a, const Sweep& sa, const Geometry& b, const Sweep& sb,
                       double tolerance = kToiTolerance, int maxIterations = 100);

/// The paper's sampled continuous detection: the first of t = 0, 1/n, 2/n, ..., 1 where the narrow phase finds
/// a contact, with n = ceil(1 / precision) (so the spacing is at most precision; the paper's (int)(1 / p)
/// rounded down). precision in (0, 1] (checkPrecision; not checked here).
ToiResult sampledTimeOfImpact(const Geometry& a, const Sweep& sa, const Geometry& b, const Sweep& sb,
                              double precision = kDefaultPrecision);

/// World box covering the shape at every pose of the sweep (the paper's swept volume, section 5.1.5, as a box):
/// exact for translation; with rotation, the origin's path fattened by boundingRadius.
Aabb sweptAabb(const Geometry& g, const Sweep& s);

}  // namespace physim
