// The World's API for the force effects (docs/effects.md), checked at the boundary. The effects themselves live in
// effects/; the spring joints' API, with the other joints', in joints/ and WorldJoints.cpp.

#include "physim/core/World.hpp"

#include "WorldImpl.hpp"

#include "physim/core/Validate.hpp"

namespace physim {

// --- bodies ------------------------------------------------------------------------------------------

void World::setGravityScale(BodyId id, double scale) {
    requireFinite("body gravity scale", scale);
    wake(id, "setGravityScale").gravityScale = scale;
}

double World::gravityScale(BodyId id) const { return at(id).gravityScale; }

void World::setDrag(BodyId id, const DragDef& drag) {
    physim::validate(drag);
    wake(id, "setDrag");
    impl_->setDrag(id.index, drag);
}

DragDef World::drag(BodyId id) const {
    at(id);
    return impl_->effects.drag.get(id.index);
}

void World::setCollides(BodyId id, bool collides) {
    BodyData& b = mutableBody(id, "setCollides");
    WorldImpl& w = *impl_;
    if (collides == b.collides) return;
    const std::uint32_t index = id.index;
    b.collides = collides;
    if (!collides) {
        // Its contacts go; whatever they held wakes.
        while (w.bodies[index].contactHead != kNullIndex)
            w.destroyContact(static_cast<std::uint32_t>(w.bodies[index].contactHead >> 1), true);
        w.destroyProxies(index);
        w.wakeBody(index);
        return;
    }
    w.createProxies(index);
    w.wakeBody(index);
    if (b.type == BodyType::Static) w.wakeShapesOverlapping(index);
}

bool World::collides(BodyId id) const { return at(id).collides; }

void World::setAttracting(BodyId id, bool attracting) {
    BodyData& b = wake(id, "setAttracting");
    b.attracting = attracting;
    if (attracting) impl_->effects.gravitation.add(id.index);
    else impl_->effects.gravitation.remove(id.index);
}

bool World::attracting(BodyId id) const { return at(id).attracting; }
std::size_t World::attractingCount() const { return impl_->effects.gravitation.count(); }

void World::setGravitation(const GravitationSettings& settings) {
    physim::validate(settings);
    impl_->requireNotStepping("setGravitation");
    impl_->effects.gravitation.setSettings(settings);
}

const GravitationSettings& World::gravitation() const { return impl_->effects.gravitation.settings(); }

ForceCallbackId World::addForceCallback(ForceCallback callback) {
    impl_->requireNotStepping("addForceCallback");
    return impl_->effects.callbacks.add(std::move(callback));
}

void World::removeForceCallback(ForceCallbackId id) {
    impl_->requireNotStepping("removeForceCallback");
    impl_->effects.callbacks.remove(id);
}

std::size_t World::forceCallbackCount() const { return impl_->effects.callbacks.count(); }

}  // namespace physim
