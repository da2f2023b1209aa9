#include "DistanceJoint.hpp"

#include "Impulse.hpp"

#include <algorithm>
#include <cmath>

namespace physim {
namespace {

constexpr double kBaumgarte = 0.2;        // fraction of the length error removed per position pass
constexpr double kMaxCorrection = 0.2;    // m per pass

}  // namespace

void prepareJoints(std::vector<BodyData>& bodies, std::vector<JointData>& joints, double h) {
    for (JointData& j : joints) {
        if (!j.alive || !j.active || j.type != JointType::Distance) continue;
        BodyData& A = bodies[j.a];
        BodyData& B = bodies[j.b];
        j.rA = A.xf.q.apply(j.localA);
        j.rB = B.xf.q.apply(j.localB);
        const Vec2 d = B.xf.p + j.rB - A.xf.p - j.rA;
        const double len = d.norm();
        j.u = len > 1e-12 ? Vec2(d / len) : Vec2(0.0, 1.0);  // coincident anchors: any direction, no NaN
        j.mass = effectiveMass(A, B, j.rA, j.rB, j.u);
        // Moving along the tangent at speed vt for h lengthens the rod by vt^2 h^2 / (2 L). Aiming the rod-wise
        // speed at -vt^2 h / (2 L) keeps the length after the position update to second order, so the
        // position pass has (almost) nothing to pull back: without it a swinging pendulum loses energy fast.
        const Vec2 dv = relativeVelocity(A, B, j.rA, j.rB);
        const Vec2 tangential = dv - j.u.dot(dv) * j.u;
        j.bias = len > 1e-12 ? -tangential.squaredNorm() * h / (2.0 * len) : 0.0;
        applyImpulse(A, B, j.rA, j.rB, j.impulse * j.u);  // warm start
    }
}

void solveJointVelocities(std::vector<BodyData>& bodies, std::vector<JointData>& joints) {
    for (JointData& j : joints) {
        if (!j.alive || !j.active || j.type != JointType::Distance) continue;
        BodyData& A = bodies[j.a];
        BodyData& B = bodies[j.b];
        const Vec2 dv = relativeVelocity(A, B, j.rA, j.rB);
        const double lambda = -j.mass * (j.u.dot(dv) - j.bias);
        j.impulse += lambda;
        applyImpulse(A, B, j.rA, j.rB, lambda * j.u);
    }
}

void correctJointPositions(std::vector<BodyData>& bodies, std::vector<JointData>& joints) {
    for (JointData& j : joints) {
        if (!j.alive || !j.active || j.type != JointType::Distance) continue;
        BodyData& A = bodies[j.a];
        BodyData& B = bodies[j.b];
        const Vec2 rA = A.xf.q.apply(j.localA), rB = B.xf.q.apply(j.localB);
        const Vec2 d = B.xf.p + rB - A.xf.p - rA;
        const double len = d.norm();
        if (len < 1e-12) continue;
        const Vec2 u = d / len;
        const double C = std::clamp(len - j.length, -kMaxCorrection, kMaxCorrection);
        applyPositionImpulse(A, B, rA, rB, (-kBaumgarte * C * effectiveMass(A, B, rA, rB, u)) * u);
    }
}

}  // namespace physim
