#pragma once
// Drives a Simulation through the paper's frame loop (section 2), in a window or headless:
//   onCreate once; then per frame: onUpdate, update of each entity, zero or more fixed steps,
//   onDrawGraphs, render of each entity, onRender, graphs refresh.

#include "physim/framework/RunOptions.hpp"
#include "physim/framework/Simulation.hpp"
#include "physim/framework/Timeline.hpp"

#include <SFML/Graphics/Rect.hpp>

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sf {
class Event;
class Font;
class RenderWindow;
}  // namespace sf

namespace physim {

class Overlay;  // the runner's internal (src/framework), not part of the installed API
class InterruptWatch;  // likewise: Ctrl-C and SIGTERM during run()
class Runner;
class Recorder;  // internal, src/framework/Recorder.hpp

using SimulationFactory = std::function<std::unique_ptr<Simulation>()>;

/// What a branch started from the window changes (Runner::startBranch): one body's velocity, every shape's
/// restitution or friction, or the accuracy (the substeps).
enum class BranchChange { Velocity, Restitution, Friction, Substeps };
/// A few words saying what the change does ("frictions halved").
const char* describe(BranchChange change);

/// A panel beside the scene, such as the gallery's scene list and sliders: it sees the window's events first
/// and draws over each finished frame.
class RunnerPanel {
public:
    virtual ~RunnerPanel() = default;
    /// The window exists (called once, before the first simulation is made).
    virtual void open(sf::RenderWindow& window) = 0;
    /// The window is about to close: let go of everything tied to it.
    virtual void close() = 0;
    /// true: the panel used the event, and neither the simulation nor the controls see it.
    virtual bool handleEvent(const sf::Event& event) = 0;
    /// Draws the panel over the frame, before it is shown; it may change the runner (switch scenes).
    virtual void draw(sf::RenderWindow& window, Runner& runner, double frameSeconds) = 0;
    /// Pixels at the window's left the panel covers: the scene is fitted to their right.
    virtual float width() const = 0;
};

class Runner {
public:
    /// `factory` makes a fresh simulation at the start and on every restart (Space).
    Runner(SimulationFactory factory, RunOptions options);
    ~Runner();

    /// Runs to the end (window closed, Esc, or --seconds reached), writes --out files and says which in one
    /// line on stdout (unless --quiet). Returns 0.
    int run();

    // The pieces run() is made of, public so tests can drive the lifecycle frame by frame.
    /// Makes the simulation (again) and calls onCreate.
    void restart();
    /// One frame of `frameSeconds` real time. `window` may be null (headless): nothing is drawn then.
    /// Returns the number of fixed steps run.
    int frame(double frameSeconds, sf::RenderWindow* window);
    /// A window event: the panel's first; key presses go to onEvent, then Space restarts, P pauses, Esc quits,
    /// and the rest (mouse, the other keys) go to the controls. `window` may be null: the window size is then
    /// --size's.
    void handleEvent(const sf::Event& event, sf::RenderWindow* window);
    bool quitRequested() const { return quit_; }

    Simulation& simulation();

    // What a panel changes in a running simulation, as the window's keys do (pausing is Simulation::paused).
    static constexpr double minTimeScale = 1.0 / 16.0;
    static constexpr double maxTimeScale = 8.0;
    /// Simulated seconds per real second, in [minTimeScale, maxTimeScale]; setTimeScale throws
    /// std::invalid_argument outside.
    double timeScale() const;
    void setTimeScale(double scale);
    /// One fixed step at the next frame, as O does (pause first: a running simulation steps anyway).
    void requestSingleStep();
    /// The window's record of the run (Timeline.hpp): kept in a window, empty headless.
    const Timeline& timeline() const { return timeline_; }
    /// Goes to simulated time `time` (s) and pauses: back within the record by Timeline::scrubTo, forward by
    /// running one-step frames. Keys Left and Right go back and forward a second, Home to the start. Returns the
    /// simulation's time after.
    double scrubTo(double time);
    /// Starts a branch from now (Simulation::startBranch) with `change`, drawn as ghosts, and a fresh distance
    /// trace. Key B does it with branchChange(), or ends the branch there is; endBranch ends it.
    void startBranch(BranchChange change);
    void endBranch();
    BranchChange branchChange() const { return branchChange_; }
    void setBranchChange(BranchChange change) { branchChange_ = change; }
    /// Simulation::branchDistance after each fixed step since the branch began, as (t s, distance m), for the
    /// gallery's live plot: it follows a scrub back (later points go) and empties when the branch ends.
    const std::vector<std::pair<double, double>>& branchTrace() const { return branchTrace_; }
    /// A live plot of one quantity of an entity's body (RecordSpec: x, y, angle, vx, vy, speed, angular_velocity,
    /// kinetic_energy): its value after each fixed step since it was added, as (t s, value); a scrub back drops
    /// the later points. Kept until removed or the scene restarts.
    struct LivePlot {
        RecordSpec spec;
        std::vector<std::pair<double, double>> points;
    };
    /// The entity whose body the left button last went down on (a click picks it), if it is still there.
    std::optional<int> pickedEntity();
    /// Adds a live plot (std::invalid_argument naming the problem: an unknown quantity, no such entity, no body).
    void addLivePlot(const RecordSpec& spec);
    void removeLivePlot(std::size_t index);
    const std::vector<LivePlot>& livePlots() const { return livePlots_; }
    /// Fits the view to the scene at the next frame, as F does.
    void requestFit();
    /// The statistics panel (Tab).
    bool statsShown() const;
    void setStatsShown(bool shown);

    /// The next restart makes its simulation with `factory` (the gallery switching scenes), with that
    /// simulation's own parameter values and debug drawing.
    void setFactory(SimulationFactory factory);
    void setPanel(std::unique_ptr<RunnerPanel> panel);
    /// Fits the simulation's view to its viewBounds() inside sceneArea().
    void fitView();
    /// The part of the window the scene is fitted into: below the overlay's bar, right of the panel (px).
    sf::FloatRect sceneArea() const;
    /// summary.json and the graphs' files into `directory`. Returns the paths written.
    std::vector<std::string> writeOutputs(const std::string& directory) const;

private:
    friend struct RunnerAccess;  // physim's own tests reach the loop's internals (src/framework/RunnerAccess.hpp)

    int runHeadless();
    int runWindow();
    /// --from: the snapshot file read into the new simulation; a file that cannot be resumed throws UsageError.
    void resumeFrom(const std::string& file);
    /// A snapshot of the simulation now into --out's snapshots folder, named for the step count. Returns its path.
    std::string writeSnapshotFile() const;
    /// The bar across the top (simulated time, physics rate, frames per second, time scale, pause, the
    /// catch-up warning, the keys) and, on demand, the statistics. Returns the bar's height (px).
    float drawOverlay(sf::RenderWindow& window);

    SimulationFactory factory_;
    RunOptions options_;
    std::unique_ptr<Simulation> simulation_;
    std::shared_ptr<ContinuousSolver> continuousSolver_;  // the CUDA layer's, in a `cuda` build; else null (CPU)
    struct Loop;                  // the frame loop's state (src/framework/RunnerAccess.hpp): step accumulator,
                                  // controls, pace, step times
    std::unique_ptr<Loop> loop_;  // never null
    bool quit_ = false;
    Timeline timeline_;
    bool recording_ = false;  // in a window: timeline_ records each step
    bool changePending_ = false;  // the world changed by hand since the last step (an event, a branch): to mark
    bool movePending_ = false;    // a drag moved its target since: timeline_ must note it
    void markChange();            // marks or notes them, before the next step or scrub
    void oneStepFrame(bool record);  // a frame of exactly one fixed step (scrubbing: the hooks run as in a run)
    void fixedStep();                // the simulation's, and the branch trace's point
    BranchChange branchChange_ = BranchChange::Velocity;
    std::unique_ptr<Recorder> recorder_;  // --record's table, from the start of the run; null without it
    std::vector<LivePlot> livePlots_;
    std::vector<std::pair<double, double>> branchTrace_;
    InterruptWatch* interrupts_ = nullptr;  // run()'s, while it runs
    bool stopRequested();                   // a signal came (run() then writes its outputs and exits 128 + it)
    std::optional<std::array<int, 4>> graphsWindow_;  // x, y, width, height beside the window; none headless
    bool factoryChanged_ = false;  // setFactory since the last restart: start from the new scene's defaults
    bool viewSetByScene_ = false;  // onCreate set the view: the runner does not refit it on resize
    std::unique_ptr<RunnerPanel> panel_;
    std::unique_ptr<Overlay> overlay_;  // window runs only
    sf::Vector2u windowSize_;           // px: the window's, or --size's without one
    double framesPerSecond_ = 0.0;
    std::size_t accuracyApplied_ = 0;  // entities given the command line's accuracy knobs so far
};

/// Parses the command line and runs. Prints usage errors (bad arguments or parameters, no display to open a
/// window on) with exit code 2, runtime errors with 1. `setup`, when given, prepares the runner before it runs
/// (the gallery adds its panel).
int runMain(int argc, const char* const* argv, const SimulationFactory& factory,
            const std::function<void(Runner&)>& setup = {});

template <class T>
int runMain(int argc, const char* const* argv) {
    return runMain(argc, argv, [] { return std::make_unique<T>(); });
}

}  // namespace physim
