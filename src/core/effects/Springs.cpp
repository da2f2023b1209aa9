#include "Springs.hpp"

#include "Effects.hpp"

#include "../WorldImpl.hpp"

#include <variant>

namespace physim {

void SpringEffect::apply(WorldImpl& w, double h) const {
    for (const std::uint32_t index : members_.items()) {
        const JointData& j = w.joints[index];
        const SpringJoint& spring = std::get<SpringJoint>(j.params);
        const BodyNow B = bodyNow(w, j.b);
        const Vec2 rB = B.q.apply(j.localB - w.bodies[j.b].localCenter);
        BodyNow A;
        Vec2 rA = Vec2::Zero();
        if (j.toWorld) {
            A.center = j.localA;
        } else {
            A = bodyNow(w, j.a);
            rA = A.q.apply(j.localA - w.bodies[j.a].localCenter);
        }
        const Vec2 d = B.center + rB - A.center - rA;
        const double length = d.norm();
        if (!(length > 1e-12)) continue;  // coincident anchors: no direction (a zero-length spring at rest)
        const Vec2 u = d / length;
        const double stretchRate = u.dot(B.v + cross(B.w, rB) - A.v - cross(A.w, rA));
        // On B, N s (SpringJoint::reaction is the same force, N).
        const Vec2 P = -h * spring.tension(length, stretchRate) * u;
        if (w.ledger.enabled)  // the damping's share of P, whose work the ledger counts as the joint's
            w.solver.tally().addDamping({-h * spring.damping * stretchRate * u, rA, rB, A.index, B.index});
        if (B.invMass > 0.0) {
            SolverBody& s = w.solver.states()[static_cast<std::size_t>(B.index)];
            s.v += B.invMass * P;
            s.w += B.invInertia * cross(rB, P);
        }
        if (A.invMass > 0.0) {
            SolverBody& s = w.solver.states()[static_cast<std::size_t>(A.index)];
            s.v -= A.invMass * P;
            s.w -= A.invInertia * cross(rA, P);
        }
    }
}

}  // namespace physim
