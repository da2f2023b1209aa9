#include "physim/framework/Simulation.hpp"

#include "physim/framework/Object.hpp"

#include "physim/core/Validate.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace physim {

Simulation::Simulation() = default;

Simulation::~Simulation() {
    // Bodies are removed while the world still exists (it is destroyed after the entities otherwise).
    for (auto& e : entities_) e->onDetach(world_);
}

Entity& Simulation::addEntity(std::unique_ptr<Entity> entity) {
    if (!entity) throw std::invalid_argument("physim: addEntity got a null entity");
    if (entity->simulation_ != nullptr)
        throw std::logic_error("physim: entity " + std::to_string(entity->id()) + " is already in a simulation");
    entity->onAttach(world_);  // may throw (bad body settings): nothing has changed yet
    entity->id_ = nextId_++;
    entity->simulation_ = this;
    entities_.push_back(std::move(entity));
    return *entities_.back();
}

std::unique_ptr<Entity> Simulation::removeEntity(int id) {
    if (iterating_ > 0)
        throw std::logic_error("physim: removeEntity(" + std::to_string(id) + ") during an entity phase");
    for (auto it = entities_.begin(); it != entities_.end(); ++it) {
        if ((*it)->id() != id) continue;
        std::unique_ptr<Entity> e = std::move(*it);
        entities_.erase(it);
        e->onDetach(world_);
        e->simulation_ = nullptr;
        return e;
    }
    throw std::invalid_argument("physim: no entity with id " + std::to_string(id));
}

Entity* Simulation::findEntity(int id) const {
    for (const auto& e : entities_)
        if (e->id() == id) return e.get();
    return nullptr;
}

std::optional<Aabb> Simulation::viewBounds() const {
    std::optional<Aabb> bounds;
    for (BodyId id : world_.bodies())
        for (ShapeId s : world_.shapes(id)) {  // none for a shapeless body
            const Aabb box = computeAabb(world_.geometry(s), world_.transform(id));
            bounds = bounds ? Aabb::merged(*bounds, box) : box;
        }
    return bounds;
}

void Simulation::setResult(std::string name, double measured, std::optional<double> predicted, std::string unit) {
    if (name.empty()) throw std::invalid_argument("physim: setResult got an empty name");
    Result r{std::move(name), measured, predicted, std::move(unit)};
    for (Result& old : results_)
        if (old.name == r.name) {
            old = std::move(r);
            return;
        }
    results_.push_back(std::move(r));
}

void Simulation::setPhysicsRate(double hz) {
    requireInRange("physics rate (Hz)", hz, 1e-3, 1e4);
    fixedTimeStep_ = 1.0 / hz;
}

// Walks by index, so entities added during a phase are appended safely (and visited in this pass).
template <class Phase>
void Simulation::forEachEntity(Phase&& phase) {
    ++iterating_;
    try {
        for (std::size_t i = 0; i < entities_.size(); ++i) phase(*entities_[i]);
    } catch (...) {
        --iterating_;
        throw;
    }
    --iterating_;
}

void Simulation::fixedStep() {
    // The paper's three phases around the world's one step: forces go in before it, its contact events and new
    // state come out after it (docs/architecture.md says why this reading of the paper).
    debugRays_.clear();
    forEachEntity([](Entity& e) { e.beforeFixedUpdate(); });
    world_.step(fixedTimeStep_);
    if (branch_) branch_->step(fixedTimeStep_);
    forEachEntity([](Entity& e) { e.checkCollisions(); });
    forEachEntity([](Entity& e) { e.fixedUpdate(); });
    for (const SensorEvent& e : world_.sensorEvents().begin) onSensor(e, true, time + e.time);
    for (const SensorEvent& e : world_.sensorEvents().end) onSensor(e, false, time + e.time);
    time += fixedTimeStep_;
    if (energyPlot_ >= 0 && graphsManager.built()) {
        const EnergyLedger& ledger = world_.energyLedger();
        const EnergyParts& parts = ledger.total;
        // Bottom to top: the energy's change, then each loss (a negative part) stacked on it.
        double y = ledger.energy() - ledger.start;
        graphsManager.addPoint(energyPlot_, time, y);
        const double losses[] = {parts.friction, parts.impacts, parts.drag, parts.soft, parts.residue};
        for (int k = 0; k < 5; ++k) graphsManager.addPoint(energyPlot_ + 1 + k, time, y -= losses[k]);
    }
}

int Simulation::addEnergyPlot() {
    if (energyPlot_ >= 0) return energyPlot_;
    world_.setEnergyLedger(true);
    // Lines without markers, one colour each (ROOT's indices), so that the bands between them read as each
    // cause's share.
    energyPlot_ = graphsManager.addGraph("Where the energy went;time (s);energy since the start (J)",
                                         "kinetic + potential - start", lineInColour(601), GraphMode::WITH_LINES);
    const std::pair<const char*, int> stacked[] = {{"+ friction", 633},      {"+ impacts", 418},
                                                   {"+ drag", 617},          {"+ soft contacts", 807},
                                                   {"+ residue = work in", 922}};
    for (const auto& [label, colour] : stacked)
        graphsManager.addSeries(energyPlot_, label, lineInColour(colour), GraphMode::WITH_LINES);
    return energyPlot_;
}

Simulation::Snapshot Simulation::snapshot() const {
    Snapshot s;
    s.world = world_.snapshot();
    if (branch_) s.branch = branch_->snapshot();
    s.time = time;
    s.energy = world_.energyLedger();
    s.results = results_;
    s.state = saveState();
    for (const std::unique_ptr<Entity>& e : entities_) s.entityIds.push_back(e->id());
    if (graphsManager.built())
        for (std::size_t i = 0; i < graphsManager.graphCount(); ++i)
            s.graphPoints.push_back(graphsManager.points(static_cast<int>(i)).size());
    return s;
}

void Simulation::restore(const Snapshot& snapshot) {
    if (snapshot.world.empty()) throw std::invalid_argument("physim: Simulation::restore: the snapshot is empty");
    std::vector<int> ids;
    for (const std::unique_ptr<Entity>& e : entities_) ids.push_back(e->id());
    if (ids != snapshot.entityIds)
        throw std::logic_error("physim: Simulation::restore: the entities changed since the snapshot (" +
                               std::to_string(snapshot.entityIds.size()) + " then, " + std::to_string(ids.size()) +
                               " now, or other ids)");
    world_.restore(snapshot.world);
    if (snapshot.branch.empty()) {
        branch_.reset();
    } else {
        if (!branch_) branch_ = std::make_unique<World>(world_.settings());
        branch_->restore(snapshot.branch);
    }
    if (snapshot.energy.enabled) world_.restoreEnergyLedger(snapshot.energy);  // its totals go on from then
    time = snapshot.time;
    results_ = snapshot.results;
    if (graphsManager.built())
        for (std::size_t i = 0; i < std::min(snapshot.graphPoints.size(), graphsManager.graphCount()); ++i) {
            const auto& points = graphsManager.points(static_cast<int>(i));
            const auto kept = static_cast<std::ptrdiff_t>(snapshot.graphPoints[i]);
            if (static_cast<std::ptrdiff_t>(points.size()) > kept)
                graphsManager.setPoints(static_cast<int>(i), {points.begin(), points.begin() + kept});
        }
    restoreState(snapshot.state);
}

void Simulation::startBranch(const Snapshot& from, const std::function<void(World&)>& change) {
    if (from.world.empty()) throw std::invalid_argument("physim: Simulation::startBranch: the snapshot is empty");
    auto branch = std::make_unique<World>(world_.settings());
    branch->restore(from.world);
    if (change) change(*branch);
    branch_ = std::move(branch);
}

double Simulation::branchDistance() const {
    if (!branch_) return 0.0;
    double sum = 0.0;
    for (const BodyId id : world_.bodies())
        if (branch_->contains(id)) sum += (world_.centerOfMass(id) - branch_->centerOfMass(id)).squaredNorm();
    return std::sqrt(sum);
}

void Simulation::updateEntities() {
    forEachEntity([](Entity& e) {
        e.update();
        for (Behavior* b : e.behaviors()) b->update();
    });
}

void Simulation::renderEntities(sf::RenderWindow* window) {
    forEachEntity([window](Entity& e) { e.render(window); });
}

Object* Simulation::objectOf(BodyId body) const {
    for (const std::unique_ptr<Entity>& e : entities_)
        if (auto* object = dynamic_cast<Object*>(e.get()); object && object->rb.bodyId() == body) return object;
    return nullptr;
}

std::optional<Simulation::Hit> Simulation::castRay(const Vec2& origin, const Vec2& translation,
                                                   const QueryFilter& filter) {
    const std::optional<RayHit> hit = world_.castRayClosest(origin, translation, filter);
    if (debugDraw.rays && debugRays_.size() < kDebugRays) debugRays_.push_back({origin, translation, hit});
    if (!hit) return std::nullopt;
    return Hit{*hit, objectOf(hit->body)};
}

std::vector<Object*> Simulation::objectsAt(const Vec2& point, const QueryFilter& filter) const {
    std::vector<BodyId> bodies;
    for (const ShapeId s : world_.overlapPoint(point, filter)) bodies.push_back(world_.body(s));
    std::vector<Object*> found;
    for (const std::unique_ptr<Entity>& e : entities_) {
        auto* object = dynamic_cast<Object*>(e.get());
        if (object && std::find(bodies.begin(), bodies.end(), object->rb.bodyId()) != bodies.end())
            found.push_back(object);
    }
    return found;
}

}  // namespace physim
