#pragma once
// The paper's Simulation (section 3): subclass it, create entities in onCreate, react in the other hooks.
// It owns its entities, its physics World and its GraphsManager. A Runner drives it (window or headless).

#include "physim/core/World.hpp"
#include "physim/framework/DebugDraw.hpp"
#include "physim/framework/Entity.hpp"
#include "physim/framework/Parameters.hpp"
#include "physim/framework/StateStream.hpp"
#include "physim/framework/View.hpp"
#include "physim/graphs/GraphsManager.hpp"

#include <any>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <SFML/Window/Event.hpp>

namespace sf {
class RenderWindow;
}  // namespace sf

namespace physim {

class Object;

class Simulation {
public:
    /// One headline figure of a lesson beside its analytic prediction, as summary.json's "results" lists it.
    struct Result {
        std::string name;                 ///< e.g. "period at 90 degrees"
        double measured = 0.0;            ///< in `unit`
        std::optional<double> predicted;  ///< the closed form's value in `unit`; nullopt where there is none
        std::string unit;                 ///< SI, e.g. "m/s", "s", "J"; empty for a pure number
    };

    double time = 0.0;             ///< simulated seconds since the start (advances by one fixed step at a time)
    GraphsManager graphsManager;
    bool start = false;            ///< true once onCreate has run
    bool paused = false;           ///< no fixed steps while paused (P toggles it)
    View view;                     ///< what the window shows: centre and zoom, in metres
    /// Debug drawing over the scene (keys 1 to 8 toggle each); a simulation may switch some on in onCreate.
    DebugDrawOptions debugDraw;
    /// Adjustable values (declare them in the constructor, read them in onCreate): the gallery's sliders and
    /// `--param name=value`. The runner carries them over when it makes the simulation again.
    Parameters parameters;

    Simulation();
    virtual ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    // The paper's hooks, called by the runner.
    virtual void onCreate() {}
    virtual void onEvent(sf::Event) {}
    virtual void onUpdate() {}
    /// Once per frame, after the frame's fixed steps. Headless, a frame is exactly one fixed step, so this runs
    /// once per step; in a window a frame runs zero or more steps (none while paused, several when catching up),
    /// so it may see several steps at once or the same step twice. Plot here; detect events (a contact, a
    /// crossing) in a per-step hook instead: an entity's checkCollisions or fixedUpdate.
    virtual void onDrawGraphs() {}
    virtual void onRender(sf::RenderWindow*) {}
    /// After each fixed step, once per sensor event of that step (World::sensorEvents, physim/core/Sensor.hpp):
    /// its begin events first, then its end events, each list in the world's order. `at` is the simulated time (s)
    /// at which the visitor entered (began) or left the sensor: the step's start plus the event's time within it,
    /// so a gate times a crossing more finely than the step.
    virtual void onSensor(const SensorEvent& /*event*/, bool /*began*/, double /*at*/) {}
    /// Shown in the window title and --help.
    virtual std::string title() const { return "physim"; }
    /// The simulation's own keys, shown in the window's overlay next to the runner's (e.g. "N: kick").
    virtual std::string keysHelp() const { return ""; }
    /// The region (m) the window fits its view to at the start, on resize and on F, unless onCreate set
    /// `view` itself. By default the bounding box of every body after onCreate; override to frame the subject
    /// (a flight's whole path, a stack without its wide ground). nullopt: leave the view alone.
    virtual std::optional<Aabb> viewBounds() const;

    /// Takes ownership, gives the entity the next id (1, 2, ...) and creates its physics body. Throws
    /// std::invalid_argument for a null entity, std::logic_error for one already in a simulation.
    Entity& addEntity(std::unique_ptr<Entity> entity);
    template <class T>
    T& addEntity(std::unique_ptr<T> entity) {
        static_assert(std::is_base_of_v<Entity, T>, "T must derive from physim::Entity");
        T* raw = entity.get();
        addEntity(std::unique_ptr<Entity>(std::move(entity)));
        return *raw;
    }
    /// Constructs a T from the arguments and adds it.
    template <class T, class... Args>
    T& spawn(Args&&... args) {
        return addEntity(std::make_unique<T>(std::forward<Args>(args)...));
    }
    /// Releases an entity (its body leaves the world). Throws std::invalid_argument for an unknown id and
    /// std::logic_error while the entities are being iterated (inside a phase).
    std::unique_ptr<Entity> removeEntity(int id);
    Entity* findEntity(int id) const;
    const std::vector<std::unique_ptr<Entity>>& entities() const { return entities_; }

    World& world() { return world_; }
    const World& world() const { return world_; }

    /// Records a headline figure for summary.json's "results" (Summary.hpp), replacing the one of the same name
    /// (a lesson measures again after a relaunch; the list keeps the order of first report). Report it when it
    /// is measured, e.g. from onDrawGraphs. Throws std::invalid_argument for an empty name.
    void setResult(std::string name, double measured, std::optional<double> predicted, std::string unit);
    const std::vector<Result>& results() const { return results_; }

    /// Where the energy went, in one line of onCreate (before the graphs are built): switches the world's energy
    /// ledger on (World::setEnergyLedger) and adds a live graph, one point per fixed step, of the energy now minus
    /// at the start (kinetic + potential) and, stacked on it, what friction, impacts, drag and soft contacts took
    /// and the method's residue. The top line is then the work put in (flat at zero where nothing drives the
    /// scene); the gaps between the lines are each cause's share. Returns the graph's index.
    int addEnergyPlot();

    // --- asking the world (docs/guide.md, "Asking the world: rays and queries"); World.hpp has every query -----
    /// A world query's hit and the Object whose body it hit (nullptr for a body no Object owns).
    struct Hit {
        RayHit hit;
        Object* object = nullptr;
    };
    /// The first shape along origin + f * translation, f in [0, 1] (m): World::castRayClosest (sensors unseen, no hit
    /// from inside a shape), with its Object. With debugDraw.rays on, the ray and its hit are kept for drawing (those
    /// cast since the last fixed step began, at most kDebugRays). Throws as castRayClosest does.
    std::optional<Hit> castRay(const Vec2& origin, const Vec2& translation, const QueryFilter& filter = {});
    /// The Objects whose shapes contain the point (m): World::overlapPoint, each Object once, in entity order.
    std::vector<Object*> objectsAt(const Vec2& point, const QueryFilter& filter = {}) const;
    /// The Object whose RigidBody is `body` (a linear search of the entities); nullptr when none owns it.
    Object* objectOf(BodyId body) const;
    const std::vector<DebugRay>& debugRays() const { return debugRays_; }
    static constexpr std::size_t kDebugRays = 1024;

    // --- going back in time (docs/guide.md, "Going back in time") ---------------------------------------------
    /// The simulation at one moment: its world's snapshot (World::snapshot) and its branch's, its time and results,
    /// and what the subclass saved (saveState). Immutable once taken; cheap to copy.
    struct Snapshot {
        WorldSnapshot world;
        WorldSnapshot branch;       ///< the branch's world (startBranch), empty when there was none
        double time = 0.0;
        std::vector<Result> results;
        std::any state;             ///< saveState()'s answer
        std::vector<int> entityIds;  ///< the entities then, in order: restore needs the same
        std::vector<std::size_t> graphPoints;  ///< each graph's point count: restore drops the points added since
        EnergyLedger energy;        ///< the world's energy ledger then (World::restoreEnergyLedger)
    };
    /// Between fixed steps (std::logic_error inside one, as World::snapshot).
    Snapshot snapshot() const;
    /// Puts the simulation back where the snapshot was taken: the world's state, `time`, the results, the graphs'
    /// points (those added since go; a graph whose points were replaced or reset since keeps its own) and, through
    /// restoreState, the subclass's members; fixed steps from there repeat what followed bit for bit. Throws
    /// std::invalid_argument for an empty snapshot and std::logic_error when the entities are no longer the ones
    /// it was taken with (one was added or removed since), the simulation unchanged.
    void restore(const Snapshot& snapshot);
    /// A subclass with members that steer its physics (a state machine, a counter that triggers a kick) returns
    /// them here, and restoreState puts them back. Members that only measure may stay out: they measure again.
    virtual std::any saveState() const { return {}; }
    virtual void restoreState(const std::any& /*state*/) {}

    /// Snapshot files (docs/guide.md, "Going back in time"): the simulation now, to a stream opened in binary mode.
    /// It holds the world's snapshot file (WorldSnapshot::write) and the branch's if there is one, `time`, the
    /// results, the physics rate, the entities' ids and what writeState writes; not the graphs' points (a run that
    /// reads it plots from the time it resumes at), nor callbacks and hooks (the reading world keeps its own, which
    /// its onCreate set up). Between fixed steps (std::logic_error inside one); std::runtime_error if the stream
    /// fails.
    void writeSnapshot(std::ostream& out) const;
    /// Reads a file writeSnapshot wrote and puts the simulation back there, as restore does (the graphs keep their
    /// points): fixed steps from there repeat what followed bit for bit. Call it after onCreate built the same
    /// scene. The whole file is checked first: a wrong magic, another format version, a truncated or corrupt file, or
    /// a world snapshot that WorldSnapshot::read refuses throw std::runtime_error naming the problem; another physics
    /// rate or other entities than the file's throw std::logic_error; either way the simulation is unchanged.
    /// readState reading other than writeState wrote throws std::runtime_error after the rest was restored.
    void readSnapshot(std::istream& in);
    /// The byte-level twin of saveState/restoreState, for files: write the members that steer the physics, read them
    /// back in the same order.
    virtual void writeState(StateWriter& /*out*/) const {}
    virtual void readState(StateReader& /*in*/) {}
    /// The format's version of writeSnapshot's files: a file of another version is refused.
    static constexpr std::uint32_t kSnapshotFormatVersion = 1;

    /// A branch: a second run from a snapshot with one thing changed, stepped beside this one. Its world is the
    /// snapshot's world changed by `change` (a restitution, a velocity, the settings...), and every fixedStep steps
    /// it right after this one's, with the same time step. What lives in the world acts in both (joints and their
    /// motors, effects, force callbacks); forces that entities add in their hooks act on this world only. The window
    /// draws the branch's bodies as ghosts over the scene. Replaces any branch there was; throws as World::restore.
    void startBranch(const Snapshot& from, const std::function<void(World&)>& change = {});
    void endBranch() { branch_.reset(); }
    /// The branch's world, or nullptr.
    const World* branch() const { return branch_.get(); }
    World* branch() { return branch_.get(); }
    /// How far the branch has gone from this run: the root-sum-square, over the bodies alive in both, of the
    /// distance between their centres of mass (m); 0 without a branch.
    double branchDistance() const;

    /// Fixed physics rate in Hz (default 40, the paper's 1/40 s step). Throws for hz <= 0, NaN or > 10000.
    void setPhysicsRate(double hz);
    double physicsRate() const { return 1.0 / fixedTimeStep_; }
    double fixedTimeStep() const { return fixedTimeStep_; }

    /// One fixed step: every entity's beforeFixedUpdate (forces added there act in this step), the world's
    /// step, every entity's checkCollisions (world().contactEvents() and contacts() describe this step), every
    /// entity's fixedUpdate (sees the new state). Forces added in the last two act in the next step. Advances
    /// `time` by fixedTimeStep().
    void fixedStep();
    /// Per frame, before the fixed steps: every entity's update() and then its behaviors' update().
    void updateEntities();
    void renderEntities(sf::RenderWindow* window);

private:
    template <class Phase>
    void forEachEntity(Phase&& phase);

    World world_;
    std::unique_ptr<World> branch_;  // startBranch's, stepped after world_
    std::vector<std::unique_ptr<Entity>> entities_;
    std::vector<Result> results_;
    std::vector<DebugRay> debugRays_;  // castRay's rays since the last fixed step began, for debug drawing
    int nextId_ = 1;
    int energyPlot_ = -1;  // addEnergyPlot's first series, or -1
    int iterating_ = 0;  // > 0 while a phase walks the entity list
    double fixedTimeStep_ = 1.0 / 40.0;
};

}  // namespace physim
