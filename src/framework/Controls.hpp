#pragma once
// What the user does to a running simulation in a window, with the mouse and keys (the runner passes events
// here after the simulation's own onEvent):
//   left drag    moves a dynamic body through a mouse joint (a soft spring to the cursor with a force cap, so
//                the body pushes others and stops at walls)
//   right drag   pans; wheel zooms about the cursor
//   O            one fixed step (pauses first when running)
//   [ and ]      slower / faster: time scale halved or doubled, 1/16x to 8x
//   F            fits the view to the scene
//   Tab          statistics on or off
//   W            stopwatch in simulated seconds: start, stop, again a new start; Shift+W: sensors start and stop it
//   M + drag     tape measure (m); A + drag, then a click: protractor (degrees). A plain click clears them.
//   L            trails: recent paths of the moving bodies' centres of mass
//   V            arrows: velocity, weight and contact force of each body, at scales the bar states
//   1 to 6       debug draw: contacts, bounding boxes, velocities, joints, centres of mass, sleeping bodies

#include "physim/core/Joint.hpp"
#include "physim/framework/DebugDraw.hpp"

#include "Measure.hpp"
#include "Stopwatch.hpp"

#include <SFML/System/Vector2.hpp>

#include <optional>
#include <string>
#include <utility>

namespace sf {
class Event;
}

namespace physim {

class Simulation;

class Controls {
public:
    /// The mouse joint's spring (Box2D's samples use the same): stiff enough to follow the cursor closely,
    /// soft enough that a grabbed body never jerks.
    static constexpr double dragHertz = 5.0;
    static constexpr double dragDampingRatio = 0.7;
    /// The pull is capped at this many times the body's weight (with g at least 9.81 m/s^2, so bodies drag
    /// in zero gravity too).
    static constexpr double dragForcePerWeight = 1000.0;

    /// Handles a mouse or control-key event for `sim` shown in a window of `windowSize` pixels. Returns true
    /// when the event was one of the controls'.
    bool handleEvent(const sf::Event& event, Simulation& sim, sf::Vector2u windowSize);

    /// Simulated seconds per real second, in [Runner::minTimeScale, Runner::maxTimeScale]. Throws
    /// std::invalid_argument outside.
    double timeScale() const { return timeScale_; }
    void setTimeScale(double scale);
    void slower();
    void faster();

    /// True once after O was pressed (the runner then runs exactly one fixed step).
    bool takeSingleStep();
    void requestSingleStep() { singleStep_ = true; }
    /// True once after F was pressed.
    bool takeFitRequest();
    /// True once after the controls changed the world between steps, as the run's record must note (Timeline): a
    /// drag began or let go (takeWorldChange), the dragged body's target moved (takeDragMove).
    bool takeWorldChange() { return std::exchange(worldChanged_, false); }
    bool takeDragMove() { return std::exchange(dragMoved_, false); }
    void requestFit() { fit_ = true; }

    /// W's stopwatch.
    const Stopwatch& stopwatch() const { return stopwatch_; }
    Stopwatch& stopwatch() { return stopwatch_; }
    /// The tape measure or protractor laid in the window, if any.
    const Measurement& measurement() const { return measurement_; }
    /// Stopwatch and measurement cleared (a restart: time starts again, the scene may be another).
    void resetInstruments();

    bool trailsShown() const { return trailsShown_; }
    bool arrowsShown() const { return arrowsShown_; }

    bool statsShown() const { return statsShown_; }
    void setStatsShown(bool shown) { statsShown_ = shown; }

    /// The body the left button last went down on, kept after the drag and through presses elsewhere (a click on
    /// a panel beside the scene reaches the controls too).
    std::optional<BodyId> picked() const { return picked_; }
    /// The mouse joint of the body being dragged, if any.
    std::optional<JointId> dragJoint() const { return drag_; }
    /// Lets go of the dragged body; forget (no World call) when the simulation is about to be replaced.
    void releaseDrag(Simulation& sim);
    void forgetDrag();

    /// The keys, for the window's overlay.
    static std::string keysHelp();

private:
    void startDrag(Simulation& sim, const Vec2& point);

    double timeScale_ = 1.0;
    bool singleStep_ = false;
    bool fit_ = false;
    bool worldChanged_ = false;
    bool dragMoved_ = false;
    bool statsShown_ = false;
    bool trailsShown_ = false;
    bool arrowsShown_ = false;
    Stopwatch stopwatch_;
    Measurement measurement_;
    bool tapeKey_ = false;        // M is held
    bool protractorKey_ = false;  // A is held
    std::optional<JointId> drag_;
    std::optional<BodyId> picked_;
    std::optional<sf::Vector2i> panFrom_;  // pixel where the right button went down / last moved
};

}  // namespace physim
