// The World's API for sensors (physim/core/Sensor.hpp), checked at the boundary; the Sensors stage is Sensors.cpp.

#include "physim/core/World.hpp"

#include "WorldImpl.hpp"

#include <stdexcept>
#include <string>

namespace physim {

void World::setSensor(ShapeId id, bool sensor) {
    const std::uint32_t slot = shapeSlot(id);
    WorldImpl& w = *impl_;
    const std::uint32_t body = w.shapes[slot].body;
    wake(BodyId{body, w.bodies[body].generation}, "setSensor");
    ShapeData& shape = w.shapes[slot];
    if (shape.sensor == sensor) return;
    shape.sensor = sensor;
    if (sensor) {
        // Its contacts end now, waking what they held; its pairs are dropped from the next step on.
        w.forEachContactOfShape(slot, [&](std::uint32_t c) { w.destroyContact(c, true); });
        w.sensors.add(slot);
    } else {
        // The pairs it had were taken and dropped, so they are offered only when asked again.
        w.sensors.remove(slot);
        if (shape.proxy != kNullIndex) w.broadPhase.requery(shape.proxy);
    }
    w.touchingValid = false;
}

bool World::isSensor(ShapeId id) const { return impl_->shapes[shapeSlot(id)].sensor; }

std::size_t World::sensorCount() const { return impl_->sensors.count(); }

std::vector<ShapeId> World::sensorOverlaps(ShapeId id) const {
    const std::uint32_t slot = shapeSlot(id);
    const auto* overlaps = impl_->sensors.overlaps(slot);
    if (!overlaps)
        throw std::invalid_argument("physim: sensorOverlaps: shape (index " + std::to_string(id.index) +
                                    ") is not a sensor");
    std::vector<ShapeId> ids;
    for (const auto& v : *overlaps)
        if (contains(ShapeId{v.shape, v.generation})) ids.push_back(ShapeId{v.shape, v.generation});
    return ids;
}

const SensorEvents& World::sensorEvents() const { return impl_->sensors.events(); }

}  // namespace physim
