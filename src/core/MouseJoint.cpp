#include "MouseJoint.hpp"

#include <cmath>

namespace physim {
namespace {

void applyAt(BodyData& body, const Vec2& r, const Vec2& impulse) {
    body.v += body.invMass * impulse;
    body.w += body.invInertia * cross(r, impulse);
}

}  // namespace

void prepareMouseJoint(BodyData& body, MouseJointData& joint, double h) {
    const double omega = 2.0 * M_PI * joint.hertz;
    const double k = body.mass * omega * omega;                // N/m
    const double d = 2.0 * body.mass * joint.dampingRatio * omega;  // N s/m
    joint.gamma = 1.0 / (h * (d + h * k));                     // mass > 0 and hertz > 0: finite
    joint.r = body.xf.q.apply(joint.localAnchor);
    const Vec2 C = body.xf.p + joint.r - joint.target;
    joint.bias = (h * k * joint.gamma) * C;
    // K: the anchor's inverse mass matrix, invM I + invI [-ry; rx] [-ry rx]; plus gamma on the diagonal.
    const double rx = joint.r.x(), ry = joint.r.y(), iI = body.invInertia;
    const double a = body.invMass + iI * ry * ry + joint.gamma, b = -iI * rx * ry;
    const double c = body.invMass + iI * rx * rx + joint.gamma;
    const double det = a * c - b * b;  // > 0: symmetric positive definite, as gamma > 0
    joint.softMass << c / det, -b / det, -b / det, a / det;
    joint.maxImpulse = joint.maxForce * h;
    // The last substep's impulse, kept within this substep's limit.
    const double n = joint.impulse.norm();
    if (n > joint.maxImpulse) joint.impulse *= joint.maxImpulse / n;
    applyAt(body, joint.r, joint.impulse);
}

void solveMouseJoint(BodyData& body, MouseJointData& joint) {
    const Vec2 cdot = body.v + cross(body.w, joint.r);
    const Vec2 old = joint.impulse;
    joint.impulse += joint.softMass * (-(cdot + joint.bias + joint.gamma * joint.impulse));
    const double n = joint.impulse.norm();
    if (n > joint.maxImpulse) joint.impulse *= joint.maxImpulse / n;
    applyAt(body, joint.r, joint.impulse - old);
}

}  // namespace physim
