#pragma once
// The snapshot tests' scene: everything a World can hold, busy for the whole run (SnapshotTest, SnapshotFileTest).
// Header-only; no global state.

#include "physim/core/World.hpp"

#include <cmath>

namespace physim::test {

// Everything the World can hold, busy for the whole run: a chain valley with a pile of mixed shapes and a kinematic segment paddle, a car on wheel
// joints, a pendulum on a revolute joint with limit, motor and spring, a prismatic slider, a pulley, a gear pair,
// a motor joint, a weld, soft and rigid distance joints, a spring, a mouse joint, a breakable joint, a sensor, a
// filtered pair, the pre-solve hook, drag, gravitation, a force callback and a continuous bullet. Sleep on.
inline void buildEverything(World& world) {
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.withShape = false;
    const BodyId valley = world.createBody(ground);
    ChainDef chain;
    for (int i = 0; i <= 40; ++i) {
        const double x = -20.0 + i;
        chain.points.push_back(Vec2(x, 0.01 * x * x));
    }
    world.createChain(valley, chain);

    BodyDef d;
    int k = 0;
    for (const Geometry& g :
         {Geometry(makeCircle(0.4)), Geometry(makeBox(0.4, 0.3)),
          Geometry(makeCapsule(Vec2(-0.3, 0.0), Vec2(0.3, 0.0), 0.2)), Geometry(makeRoundedBox(0.3, 0.3, 0.1))}) {
        for (int j = 0; j < 4; ++j, ++k) {
            d.position = Vec2(-3.0 + 1.1 * (k % 6), 2.0 + 1.0 * (k / 6));
            d.angle = 0.3 * k;
            d.shape = g;
            d.restitution = k % 3 == 0 ? 0.5 : 0.0;
            world.createBody(d);
        }
    }
    // A kinematic paddle of a segment, turning in the pile's way.
    d = BodyDef{};
    d.type = BodyType::Kinematic;
    d.position = Vec2(0.0, 4.0);
    d.angularVelocity = 1.5;
    d.shape = makeSegment(Vec2(-1.5, 0.0), Vec2(1.5, 0.0));
    world.createBody(d);
    // The car.
    d = BodyDef{};
    d.position = Vec2(-12.0, 3.0);
    d.shape = makeBox(1.0, 0.25);
    const BodyId chassis = world.createBody(d);
    for (const double x : {-0.7, 0.7}) {
        BodyDef w;
        w.position = Vec2(-12.0 + x, 2.5);
        w.shape = makeCircle(0.3);
        const BodyId wheel = world.createBody(w);
        WheelJointDef j;
        j.bodyA = chassis;
        j.bodyB = wheel;
        j.anchor = w.position;
        j.hertz = 4.0;
        j.enableMotor = x < 0.0;
        j.motorSpeed = -6.0;
        j.maxMotorTorque = 30.0;
        world.createWheelJoint(j);
    }
    // Hanging things from a static beam high up.
    BodyDef beamDef;
    beamDef.type = BodyType::Static;
    beamDef.position = Vec2(10.0, 12.0);
    beamDef.shape = makeBox(6.0, 0.1);
    const BodyId beam = world.createBody(beamDef);
    d = BodyDef{};
    d.position = Vec2(6.0, 10.0);
    d.shape = makeBox(0.1, 1.0);
    d.angularVelocity = 2.0;
    const BodyId arm = world.createBody(d);
    RevoluteJointDef pin;
    pin.bodyA = beam;
    pin.bodyB = arm;
    pin.anchor = Vec2(6.0, 11.0);
    pin.enableLimit = true;
    pin.lowerAngle = -1.0;
    pin.upperAngle = 1.0;
    pin.enableMotor = true;
    pin.maxMotorTorque = 5.0;
    pin.motorSpeed = 1.0;
    pin.enableSpring = true;
    pin.springHertz = 1.0;
    pin.springDampingRatio = 0.1;
    const JointId pinId = world.createRevoluteJoint(pin);
    d.position = Vec2(8.0, 10.5);
    d.shape = makeBox(0.3, 0.3);
    const BodyId slider = world.createBody(d);
    PrismaticJointDef slide;
    slide.bodyA = beam;
    slide.bodyB = slider;
    slide.anchor = d.position;
    slide.axis = Vec2(1.0, 1.0);
    slide.enableLimit = true;
    slide.lowerTranslation = -1.0;
    slide.upperTranslation = 1.0;
    slide.enableSpring = true;
    slide.hertz = 2.0;
    const JointId slideId = world.createPrismaticJoint(slide);
    GearJointDef gear;
    gear.joint1 = pinId;
    gear.joint2 = slideId;
    gear.ratio = 2.0;
    world.createGearJoint(gear);
    d.shape = makeCircle(0.3);
    d.position = Vec2(10.0, 9.0);
    const BodyId left = world.createBody(d);
    d.position = Vec2(12.0, 9.5);
    d.density = 2.0;
    const BodyId right = world.createBody(d);
    PulleyJointDef pulley;
    pulley.bodyA = left;
    pulley.bodyB = right;
    pulley.groundAnchorA = Vec2(10.0, 11.9);
    pulley.groundAnchorB = Vec2(12.0, 11.9);
    world.createPulleyJoint(pulley);
    d = BodyDef{};
    d.position = Vec2(14.0, 10.0);
    d.shape = makeBox(0.2, 0.2);
    const BodyId driven = world.createBody(d);
    MotorJointDef motor;
    motor.bodyA = beam;
    motor.bodyB = driven;
    motor.linearOffset = Vec2(4.0, -3.0);
    motor.maxForce = 50.0;
    motor.maxTorque = 5.0;
    world.createMotorJoint(motor);
    d.position = Vec2(15.0, 10.0);
    const BodyId welded = world.createBody(d);
    WeldJointDef weld;
    weld.bodyA = driven;
    weld.bodyB = welded;
    weld.anchor = Vec2(14.5, 10.0);
    world.createWeldJoint(weld);
    d.position = Vec2(15.0, 8.0);
    const BodyId hanging = world.createBody(d);
    DistanceJointDef soft;
    soft.bodyA = welded;
    soft.bodyB = hanging;
    soft.hertz = 3.0;
    soft.dampingRatio = 0.2;
    soft.breakForce = 200.0;  // the swing's peak pull breaks it partway
    world.createDistanceJoint(soft);
    d.position = Vec2(13.0, 7.0);
    const BodyId sprung = world.createBody(d);
    SpringJointDef spring;
    spring.bodyA = hanging;
    spring.bodyB = sprung;
    spring.stiffness = 40.0;
    spring.damping = 0.5;
    world.createSpringJoint(spring);
    DistanceJointDef rod;
    rod.bodyA = sprung;
    rod.bodyB = left;
    world.createDistanceJoint(rod);
    MouseJointDef mouse;
    mouse.body = arm;
    mouse.target = Vec2(5.0, 9.0);
    mouse.maxForce = 20.0;
    world.createMouseJoint(mouse);

    // A sensor the pile falls through, a pair kept apart by filters, and a hook that disables some contacts.
    BodyDef gate;
    gate.type = BodyType::Static;
    gate.position = Vec2(0.0, 1.5);
    gate.shape = makeBox(4.0, 0.2);
    gate.isSensor = true;
    world.createBody(gate);
    d = BodyDef{};
    d.position = Vec2(4.0, 6.0);
    d.shape = makeBox(0.3, 0.3);
    d.filter.groupIndex = -1;
    world.createBody(d);
    d.position = Vec2(4.1, 7.0);
    world.createBody(d);
    world.setPreSolve([](const Manifold& m) { return m.normal.x() < 0.9; });

    // Drag, gravitation between two heavy discs, a force callback and a continuous bullet.
    d = BodyDef{};
    d.position = Vec2(-6.0, 8.0);
    d.shape = makeCircle(0.5);
    d.density = 50.0;
    const BodyId heavyA = world.createBody(d);
    d.position = Vec2(-4.0, 8.5);
    const BodyId heavyB = world.createBody(d);
    world.setAttracting(heavyA, true);
    world.setAttracting(heavyB, true);
    GravitationSettings g;
    g.G = 0.5;
    world.setGravitation(g);
    DragDef drag;
    drag.dragCoefficient = 1.0;
    drag.angular = 0.1;
    world.setDrag(heavyA, drag);
    world.addForceCallback(
        [heavyB](World& w, double) { w.applyForce(heavyB, Vec2(std::sin(w.stepCount() * 0.1) * 30.0, 0.0)); });
    d = BodyDef{};
    d.position = Vec2(-15.0, 6.0);
    d.velocity = Vec2(60.0, -20.0);
    d.shape = makeCircle(0.05);
    d.collisionDetection = CollisionDetection::ContinuousExact;
    world.createBody(d);
}

}  // namespace physim::test
