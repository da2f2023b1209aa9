// The World's shapes: several per body, each with its own material; the body's mass, centre of mass and inertia
// from all of them; their boxes and proxies.

#include "physim/core/World.hpp"

#include "Slots.hpp"
#include "WorldImpl.hpp"
#include "shapes/PolygonCheck.hpp"
#include "shapes/ShapeKinds.hpp"

#include "physim/core/MassData.hpp"
#include "physim/core/Validate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace physim {
namespace {

double shapeMeanWidth(const Geometry& g) {
    return withKind(g, [](auto kind, const auto& s) { return kind.meanWidth(s); });
}

void validate(const ShapeDef& def) {
    validate(def.geometry);
    requireNonNegative("shape density", def.density);
    requireInRange("shape restitution", def.restitution, 0.0, 1.0);
    requireNonNegative("shape static friction", def.staticFriction);
    requireNonNegative("shape dynamic friction", def.dynamicFriction);
    requireNonNegative("shape rolling resistance", def.rollingResistance);
    requireWithin("shape tangent speed", def.tangentSpeed, kMaxSpeed);
}

// The body's mass properties per unit of its reference density (BodyData::density): each shape's weighted by its
// density over the reference, about the common centroid (parallel axis theorem). A body of one shape at the
// reference density has its shape's own. Zero-density shapes (and a zero reference) count by area alone, so a
// static body still has a centre to turn about should it become kinematic.
MassProperties combine(const WorldImpl& w, const BodyData& b) {
    if (b.shapeCount == 1) {
        const ShapeData& only = w.shapes[static_cast<std::size_t>(b.shapeHead)];
        if (only.density == b.density) return only.unitMass;
    }
    const double reference = b.density > 0.0 ? b.density : 1.0;
    auto total = [&](bool weighted) {
        std::vector<WeightedPart> parts;
        w.forEachShape(b, [&](std::uint32_t, const ShapeData& shape) {
            parts.push_back({shape.unitMass, weighted ? shape.density / reference : 1.0});
        });
        return combineParts(parts);
    };
    const MassProperties weighted = total(true);
    return weighted.area > 0.0 ? weighted : total(false);
}

}  // namespace

double extentAbout(const Geometry& g, const Vec2& center) {
    return withKind(g, [&](auto kind, const auto& s) { return kind.extentAbout(s, center); });
}

double coreRadius(const Geometry& g) {
    return withKind(g, [](auto kind, const auto& s) { return kind.coreRadius(s); });
}

// --- WorldImpl helpers ---------------------------------------------------------------------------------

void WorldImpl::updateBoxes(BodyData& b) {
    if (!b.collides) return;  // bodyBounds and shapeBounds compute its boxes where asked
    if (b.shapeHead == kNullIndex) {
        b.aabb = bodyBounds(b);
        return;
    }
    constexpr double kInf = std::numeric_limits<double>::infinity();
    Aabb box{{kInf, kInf}, {-kInf, -kInf}};  // bodyBounds' merge, in the same pass
    forEachShape(b, [&](std::uint32_t, ShapeData& shape) {
        shape.aabb = computeAabb(shape.geometry, b.xf);
        box = Aabb::merged(box, shape.aabb);
    });
    b.aabb = box;
}

Aabb WorldImpl::bodyBounds(const BodyData& b) const {
    if (b.shapeHead == kNullIndex) return {b.xf.p, b.xf.p};
    constexpr double kInf = std::numeric_limits<double>::infinity();
    Aabb box{{kInf, kInf}, {-kInf, -kInf}};  // merges into the first shape's box exactly
    forEachShape(b, [&](std::uint32_t, const ShapeData& shape) { box = Aabb::merged(box, shapeBounds(shape)); });
    return box;
}

Aabb WorldImpl::shapeBounds(const ShapeData& shape) const {
    const BodyData& b = bodies[shape.body];
    return b.collides ? shape.aabb : computeAabb(shape.geometry, b.xf);
}

void WorldImpl::createProxies(std::uint32_t body) {
    BodyData& b = bodies[body];
    updateBoxes(b);
    forEachShape(b, [&](std::uint32_t slot, ShapeData& shape) {
        if (shape.proxy == kNullIndex)
            shape.proxy = broadPhase.createProxy(proxyBox(b, shape.aabb), slot, b.type == BodyType::Static);
    });
}

void WorldImpl::destroyProxies(std::uint32_t body) {
    forEachShape(bodies[body], [&](std::uint32_t, ShapeData& shape) {
        if (shape.proxy != kNullIndex) broadPhase.destroyProxy(shape.proxy);
        shape.proxy = kNullIndex;
    });
}

void WorldImpl::wakeShapesOverlapping(std::uint32_t body) {
    forEachShape(bodies[body], [&](std::uint32_t, const ShapeData& shape) {
        if (shape.proxy != kNullIndex) wakeOverlapping(broadPhase.fatBox(shape.proxy));
    });
}

void WorldImpl::updateMass(std::uint32_t body) {
    BodyData& b = bodies[body];
    BodyData trial = b;
    trial.unitMass = combine(*this, b);
    // The parts are weighed by their density over the body's: densities 1e300 apart overflow that.
    const MassProperties& unit = trial.unitMass;
    if (!(std::isfinite(unit.area) && std::isfinite(unit.centroid.x()) && std::isfinite(unit.centroid.y()) &&
          std::isfinite(unit.secondMoment))) {
        std::ostringstream os;
        os.precision(17);
        os << "physim: the shapes' densities are too far from the body's density (" << b.density
           << " kg/m^2) to combine: their mass overflows";
        throw std::invalid_argument(os.str());
    }
    if (trial.type == BodyType::Dynamic) assignMass(trial, trial.density * trial.unitMass.area);  // may throw
    const Vec2 oldCenter = b.center;
    b.unitMass = trial.unitMass;
    b.mass = trial.mass;
    b.density = trial.density;
    b.invMass = trial.invMass;
    b.inertia = trial.inertia;
    b.invInertia = trial.invInertia;
    b.localCenter = b.unitMass.centroid;
    solver.layoutChanged();  // a kept layout's pin blocks hold arms from the centre of mass (refreshPins)
    b.center = b.xf.apply(b.localCenter);
    // The body's points keep their velocities: the new centre moves as the point it is moved.
    if (b.movable()) b.v += cross(b.w, b.center - oldCenter);
    b.extent = 0.0;
    b.turnReach = 0.0;
    b.coreRadius = std::numeric_limits<double>::infinity();
    forEachShape(b, [&](std::uint32_t, const ShapeData& shape) {
        const double extent = extentAbout(shape.geometry, b.localCenter);
        b.extent = std::max(b.extent, extent);
        b.turnReach = std::max(b.turnReach, std::max(extent - rollingRadius(shape.geometry), 0.0));
        // The thinnest part with area decides how far the body may move in a step before the Continuous stage
        // looks at it; zero-area parts (segments) are ground, not what tunnels.
        if (shape.unitMass.area > 0.0) b.coreRadius = std::min(b.coreRadius, coreRadius(shape.geometry));
    });
    if (std::isinf(b.coreRadius)) b.coreRadius = 0.0;
    // The contacts' cached manifolds are kept about the old centre of mass.
    for (std::int32_t key = b.contactHead; key != kNullIndex;) {
        ContactData& c = contacts[static_cast<std::size_t>(key >> 1)];
        c.cache.margin = -1.0;
        key = c.next[key & 1];
    }
}

double WorldImpl::meanWidth(std::uint32_t body) const {
    const BodyData& b = bodies[body];
    if (b.shapeCount == 0) return 0.0;
    if (b.shapeCount == 1) return shapeMeanWidth(shapes[static_cast<std::size_t>(b.shapeHead)].geometry);
    // Cauchy: the mean width of a convex set is its perimeter over pi; air sees the convex hull of the parts.
    std::vector<Vec2> points;
    const Transform local{Vec2::Zero(), Rotation::fromAngle(0.0)};
    forEachShape(b, [&](std::uint32_t, const ShapeData& shape) {
        const std::vector<Vec2> around = outline(shape.geometry, local);
        points.insert(points.end(), around.begin(), around.end());
    });
    const std::vector<Vec2> hull = convexHullCorners(std::move(points));
    double perimeter = 0.0;
    for (std::size_t i = 0; i < hull.size(); ++i) perimeter += (hull[(i + 1) % hull.size()] - hull[i]).norm();
    return perimeter / M_PI;
}

void WorldImpl::setDrag(std::uint32_t body, const DragDef& def) {
    effects.drag.set(body, def, [&] { return meanWidth(body); });
}

void WorldImpl::setShapeMaterial(std::uint32_t shape, double restitution, double staticFriction,
                                 double dynamicFriction) {
    ShapeData& s = shapes[shape];
    s.restitution = restitution;
    s.staticFriction = staticFriction;
    s.dynamicFriction = dynamicFriction;
    forEachContactOfShape(shape, [&](std::uint32_t c) { mixContact(c); });
}

void WorldImpl::setShapeSurface(std::uint32_t shape, double rollingResistance, double tangentSpeed) {
    ShapeData& s = shapes[shape];
    s.rollingResistance = rollingResistance;
    s.tangentSpeed = tangentSpeed;
    forEachContactOfShape(shape, [&](std::uint32_t c) { mixContact(c); });
}

void WorldImpl::mixContact(std::uint32_t c) {
    ContactData& contact = contacts[c];
    const ShapeData &a = shapes[contact.shapeA()], &b = shapes[contact.shapeB()];
    mixMaterials(contact, a, b, settings);
    if (contactCores.size() <= c) contactCores.resize(contacts.size());
    contactCores[c] = coresOf(a, b);
    const ContactSurface surface = mixSurfaces(a, b);
    surfaceMaterials = surfaceMaterials || surface.rolling != 0.0 || surface.tangentSpeed != 0.0;
    if (!surfaceMaterials) return;
    if (contactSurfaces.size() <= c) contactSurfaces.resize(contacts.size());
    contactSurfaces[c] = surface;
}

void WorldImpl::remixContacts() {
    for (std::uint32_t c = 0; c < contacts.size(); ++c)
        if (contacts[c].alive) mixContact(c);
}

// --- World -------------------------------------------------------------------------------------------

std::uint32_t World::firstShape(BodyId id) const {
    const BodyData& b = at(id);
    if (b.shapeHead == kNullIndex)
        throw std::invalid_argument("physim: body (index " + std::to_string(id.index) + ") has no shape");
    return static_cast<std::uint32_t>(b.shapeHead);
}

std::uint32_t World::shapeSlot(ShapeId id) const {
    if (!contains(id))
        throw std::invalid_argument("physim: shape id (index " + std::to_string(id.index) + ", generation " +
                                    std::to_string(id.generation) + ") is not a live shape of this world");
    return id.index;
}

ShapeId World::createShape(BodyId id, const ShapeDef& def) {
    validate(def);
    return addShapes(id, {def}, "createShape").front();
}

std::vector<ShapeId> World::createChain(BodyId id, const ChainDef& def) {
    requireInRange("chain restitution", def.restitution, 0.0, 1.0);
    requireNonNegative("chain static friction", def.staticFriction);
    requireNonNegative("chain dynamic friction", def.dynamicFriction);
    requireNonNegative("chain rolling resistance", def.rollingResistance);
    requireWithin("chain tangent speed", def.tangentSpeed, kMaxSpeed);
    std::vector<ShapeDef> pieces;
    for (const ChainSegment& piece : makeChain(def.points, def.loop)) {
        requireWithin("chain point", piece.segment.point1, kMaxCoordinate);
        ShapeDef d;
        d.geometry = piece;
        d.density = 0.0;
        d.restitution = def.restitution;
        d.staticFriction = def.staticFriction;
        d.dynamicFriction = def.dynamicFriction;
        d.filter = def.filter;
        d.rollingResistance = def.rollingResistance;
        d.tangentSpeed = def.tangentSpeed;
        pieces.push_back(d);
    }
    return addShapes(id, pieces, "createChain");
}

std::vector<ShapeId> World::addShapes(BodyId id, const std::vector<ShapeDef>& defs, const char* call) {
    at(id);
    WorldImpl& w = *impl_;
    w.requireNotStepping(call);
    const std::uint32_t body = id.index;
    BodyData& b = w.bodies[body];
    const std::int32_t oldTail = b.shapeTail;
    std::vector<std::uint32_t> slots;
    slots.reserve(defs.size());
    for (const ShapeDef& def : defs) {
        const std::uint32_t slot = takeSlot(w.shapes, w.freeShapes);
        assignShape(w.shapes[slot], body, def, computeMassProperties(def.geometry));
        if (b.shapeTail == kNullIndex) b.shapeHead = static_cast<std::int32_t>(slot);
        else w.shapes[static_cast<std::size_t>(b.shapeTail)].next = static_cast<std::int32_t>(slot);
        b.shapeTail = static_cast<std::int32_t>(slot);
        ++b.shapeCount;
        slots.push_back(slot);
    }
    try {
        w.updateMass(body);
    } catch (...) {
        if (oldTail == kNullIndex) b.shapeHead = kNullIndex;
        else w.shapes[static_cast<std::size_t>(oldTail)].next = kNullIndex;
        b.shapeTail = oldTail;
        b.shapeCount -= static_cast<std::int32_t>(slots.size());
        // The slots go back as they came: new ones off the end, free ones onto the free list in their order.
        for (auto s = slots.rbegin(); s != slots.rend(); ++s) {
            w.shapes[*s].alive = false;
            if (*s + 1 == w.shapes.size()) w.shapes.pop_back();
            else w.freeShapes.push_back(*s);
        }
        throw;
    }
    w.shapeLiveCount += slots.size();
    for (const std::uint32_t slot : slots)
        if (w.shapes[slot].sensor) w.sensors.add(slot);
    w.updateBoxes(b);
    if (b.collides) {
        w.createProxies(body);
        if (b.type == BodyType::Static)
            for (const std::uint32_t slot : slots) w.wakeOverlapping(w.broadPhase.fatBox(w.shapes[slot].proxy));
    }
    w.setDrag(body, w.effects.drag.get(body));
    w.wakeBody(body);
    w.touched.push_back(body);
    ++w.shapeRevision;
    w.touchingValid = false;
    std::vector<ShapeId> ids;
    ids.reserve(slots.size());
    for (const std::uint32_t slot : slots) ids.push_back(ShapeId{slot, w.shapes[slot].generation});
    return ids;
}

void World::destroyShape(ShapeId id) {
    const std::uint32_t slot = shapeSlot(id);
    WorldImpl& w = *impl_;
    w.requireNotStepping("destroyShape");
    const std::uint32_t body = w.shapes[slot].body;
    BodyData& b = w.bodies[body];
    // Unlinked first, so the mass rule sees the body without it; put back if the body cannot do without it.
    std::int32_t before = kNullIndex;
    for (std::int32_t s = b.shapeHead; s != static_cast<std::int32_t>(slot); s = w.shapes[static_cast<std::size_t>(s)].next)
        before = s;
    const std::int32_t after = w.shapes[slot].next;
    auto relink = [&](bool in) {
        const std::int32_t target = in ? static_cast<std::int32_t>(slot) : after;
        if (before == kNullIndex) b.shapeHead = target;
        else w.shapes[static_cast<std::size_t>(before)].next = target;
        if (after == kNullIndex) b.shapeTail = in ? static_cast<std::int32_t>(slot) : before;
        b.shapeCount += in ? 1 : -1;
    };
    relink(false);
    try {
        if (b.type == BodyType::Dynamic && b.shapeCount == 0)
            throw std::invalid_argument("physim: destroyShape would leave a dynamic body with no shape");
        w.updateMass(body);
    } catch (...) {
        relink(true);
        throw;
    }
    // Its contacts end, waking what they held.
    w.forEachContactOfShape(slot, [&](std::uint32_t c) { w.destroyContact(c, true); });
    ShapeData& shape = w.shapes[slot];
    if (shape.sensor) w.sensors.remove(slot);
    if (shape.proxy != kNullIndex) w.broadPhase.destroyProxy(shape.proxy);
    shape.proxy = kNullIndex;
    shape.alive = false;
    shape.next = kNullIndex;
    w.freeShapes.push_back(slot);
    --w.shapeLiveCount;
    w.updateBoxes(b);
    w.setDrag(body, w.effects.drag.get(body));
    w.wakeBody(body);
    w.touched.push_back(body);
    ++w.shapeRevision;
    w.touchingValid = false;
}

bool World::contains(ShapeId id) const {
    const auto& shapes = impl_->shapes;
    return !id.isNull() && id.index < shapes.size() && shapes[id.index].alive &&
           shapes[id.index].generation == id.generation;
}

std::size_t World::shapeCount() const { return impl_->shapeLiveCount; }

std::vector<ShapeId> World::shapes(BodyId id) const {
    std::vector<ShapeId> ids;
    impl_->forEachShape(at(id), [&](std::uint32_t slot, const ShapeData& shape) {
        ids.push_back(ShapeId{slot, shape.generation});
    });
    return ids;
}

BodyId World::body(ShapeId id) const {
    const std::uint32_t b = impl_->shapes[shapeSlot(id)].body;
    return BodyId{b, impl_->bodies[b].generation};
}

const Geometry& World::geometry(ShapeId id) const { return impl_->shapes[shapeSlot(id)].geometry; }
Aabb World::bounds(ShapeId id) const { return impl_->shapeBounds(impl_->shapes[shapeSlot(id)]); }
double World::density(ShapeId id) const { return impl_->shapes[shapeSlot(id)].density; }
double World::restitution(ShapeId id) const { return impl_->shapes[shapeSlot(id)].restitution; }
double World::staticFriction(ShapeId id) const { return impl_->shapes[shapeSlot(id)].staticFriction; }
double World::dynamicFriction(ShapeId id) const { return impl_->shapes[shapeSlot(id)].dynamicFriction; }

void World::setMaterial(ShapeId id, double restitution, double staticFriction, double dynamicFriction) {
    requireInRange("shape restitution", restitution, 0.0, 1.0);
    requireNonNegative("shape static friction", staticFriction);
    requireNonNegative("shape dynamic friction", dynamicFriction);
    const std::uint32_t slot = shapeSlot(id);
    const std::uint32_t body = impl_->shapes[slot].body;
    wake(BodyId{body, impl_->bodies[body].generation}, "setMaterial");
    impl_->setShapeMaterial(slot, restitution, staticFriction, dynamicFriction);
}

double World::rollingResistance(ShapeId id) const { return impl_->shapes[shapeSlot(id)].rollingResistance; }
double World::tangentSpeed(ShapeId id) const { return impl_->shapes[shapeSlot(id)].tangentSpeed; }

void World::setRollingResistance(ShapeId id, double coefficient) {
    requireNonNegative("shape rolling resistance", coefficient);
    const std::uint32_t slot = shapeSlot(id);
    const std::uint32_t body = impl_->shapes[slot].body;
    wake(BodyId{body, impl_->bodies[body].generation}, "setRollingResistance");
    impl_->setShapeSurface(slot, coefficient, impl_->shapes[slot].tangentSpeed);
}

void World::setTangentSpeed(ShapeId id, double speed) {
    requireWithin("shape tangent speed", speed, kMaxSpeed);
    const std::uint32_t slot = shapeSlot(id);
    const std::uint32_t body = impl_->shapes[slot].body;
    wake(BodyId{body, impl_->bodies[body].generation}, "setTangentSpeed");
    impl_->setShapeSurface(slot, impl_->shapes[slot].rollingResistance, speed);
}

double World::rollingResistance(BodyId id) const { return impl_->shapes[firstShape(id)].rollingResistance; }
double World::tangentSpeed(BodyId id) const { return impl_->shapes[firstShape(id)].tangentSpeed; }

void World::setRollingResistance(BodyId id, double coefficient) {
    requireNonNegative("body rolling resistance", coefficient);
    const BodyData& b = wake(id, "setRollingResistance");
    impl_->forEachShape(b, [&](std::uint32_t slot, const ShapeData& shape) {
        impl_->setShapeSurface(slot, coefficient, shape.tangentSpeed);
    });
}

void World::setTangentSpeed(BodyId id, double speed) {
    requireWithin("body tangent speed", speed, kMaxSpeed);
    const BodyData& b = wake(id, "setTangentSpeed");
    impl_->forEachShape(b, [&](std::uint32_t slot, const ShapeData& shape) {
        impl_->setShapeSurface(slot, shape.rollingResistance, speed);
    });
}

}  // namespace physim
