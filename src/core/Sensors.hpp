#pragma once
// The World's Sensors stage (physim/core/Sensor.hpp): after the step's motion, each sensor's overlaps are found
// anew on the bodies' paths over the step, and what changed becomes begin and end events. Runs only while the world
// holds a sensor; then it also keeps each awake body's pose and velocity from before the solve (the path's start).
// Internal.

#include "physim/core/Aabb.hpp"
#include "physim/core/Math.hpp"
#include "physim/core/Sensor.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace physim {

struct WorldImpl;

class SensorStage {
public:
    struct Visitor {
        std::uint32_t shape = 0;       // slot
        std::uint32_t generation = 0;  // the shape's, so a destroyed visitor is told from its slot's next one
    };

    /// A shape became a sensor (creation, setSensor) or stopped being one (removal, destruction): its overlaps go.
    void add(std::uint32_t shape);
    void remove(std::uint32_t shape);
    std::size_t count() const { return sensors_.size(); }
    bool active() const { return !sensors_.empty(); }
    /// The visitors overlapping the sensor after the last run (sorted by slot); null when it is no sensor.
    const std::vector<Visitor>* overlaps(std::uint32_t shape) const;

    /// Before the solve: the awake bodies' poses and velocities, the start of their paths over the step.
    void recordStarts(const WorldImpl& w);
    /// After the motion: overlaps and events. Bodies not recorded this step stood still.
    void run(WorldImpl& w);
    const SensorEvents& events() const { return events_; }
    void clearEvents() {
        events_.begin.clear();
        events_.end.clear();
    }

private:
    template <class> friend struct StateFields;  // the snapshot file's serializer (SnapshotFile.cpp)
    struct Sensor {
        std::uint32_t shape = 0;
        std::vector<Visitor> overlaps;  // sorted by slot
    };
    struct Start {
        Vec2 center = Vec2::Zero();
        Vec2 v = Vec2::Zero();
        double angle = 0.0;
        double w = 0.0;
        std::uint64_t step = ~std::uint64_t{0};  // the World's stepCount when recorded
    };
    struct Mover {
        std::uint32_t shape = 0;
        Aabb swept;
    };
    std::vector<Sensor>::iterator find(std::uint32_t shape);

    std::vector<Sensor> sensors_;      // sorted by shape slot
    std::vector<Start> starts_;        // per body slot
    std::vector<Mover> movers_;        // shapes whose path left their proxy's box: the tree would miss them
    std::vector<std::uint32_t> candidates_;
    std::vector<Visitor> next_;
    SensorEvents events_;
};

}  // namespace physim
