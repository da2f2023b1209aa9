#include "Integrator.hpp"

namespace physim {

void integrateVelocities(std::vector<BodyData>& bodies, const Vec2& gravity, double dt) {
    for (BodyData& b : bodies) {
        b.v0 = b.v;
        b.w0 = b.w;
        if (!b.alive || b.type != BodyType::Dynamic || !b.awake) continue;
        const Vec2 acceleration = b.invMass * b.force + (b.useGravity ? gravity : Vec2::Zero());
        b.v += dt * acceleration;
        b.w += dt * b.invInertia * b.torque;
    }
}

void integratePositions(std::vector<BodyData>& bodies, double dt) {
    for (BodyData& b : bodies) {
        if (!b.alive || !b.movable() || !b.awake) continue;
        b.xf.p += dt * b.v;
        if (b.w != 0.0) {
            b.angle += dt * b.w;
            b.xf.q = Rotation::fromAngle(b.angle);
        }
    }
}

void clearForces(std::vector<BodyData>& bodies) {
    for (BodyData& b : bodies) {
        b.force.setZero();
        b.torque = 0.0;
    }
}

}  // namespace physim
