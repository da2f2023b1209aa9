#pragma once
// Sensors: shapes that collide with nothing and report what overlaps them (World::sensorEvents). A shape is a
// sensor from its definition (ShapeDef::isSensor, BodyDef::isSensor) or World::setSensor, on a body of any type.
//
// Who a sensor sees: shapes of other bodies that are not sensors themselves, whose body collides
// (World::setCollides), whose filter and the sensor's let them pair (shouldCollide, Filter.hpp), and of which at least
// one body is not static (a static sensor over static ground would report a permanent overlap nobody asked for).
// A sensor never pushes anything: the visitor moves exactly as it would without the sensor.
//
// When: after each step, on the bodies' motion over the step, so a visitor that enters and leaves within one step
// (a bullet through a thin gate) is reported with a begin and an end event in that step, whatever its collision
// detection. The motion between the step's start and end poses is the curve whose acceleration is the step's
// change of velocity over dt (for a body under a constant force it is the path through every substep's pose), and
// the times of entry and exit are found on it by conservative advancement to within kSensorTolerance.

#include "physim/core/Body.hpp"
#include "physim/core/Shape.hpp"

#include <vector>

namespace physim {

/// Gap (m) below which a visitor counts as touching a sensor: entry and exit times are found to within
/// kSensorTolerance / (the visitor's speed relative to the sensor).
constexpr double kSensorTolerance = 1e-6;

/// A visitor shape began or stopped overlapping a sensor shape in the last step.
struct SensorEvent {
    ShapeId sensorShape;
    ShapeId visitorShape;
    BodyId sensorBody;
    BodyId visitorBody;
    double fraction = 0.0;  ///< when it happened, as a fraction of the step, in [0, 1]
    double time = 0.0;      ///< the same in s after the step's start (fraction * dt)
};

/// The last step's sensor events, each list sorted by sensor shape index, then visitor shape index. A visitor that
/// crossed a sensor within the step is in both lists. Every begin is followed by an end (in that step or a later
/// one), except when the sensor or the visitor is destroyed, or stops being a sensor: those overlaps end silently.
/// A visitor that stops being seen without moving apart (a filter change, setCollides(false)) ends at fraction 0.
struct SensorEvents {
    std::vector<SensorEvent> begin;
    std::vector<SensorEvent> end;
};

}  // namespace physim
