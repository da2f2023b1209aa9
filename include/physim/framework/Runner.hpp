#pragma once
// Drives a Simulation through the paper's frame loop (section 2), in a window or headless:
//   onCreate once; then per frame: onUpdate, update of each entity, zero or more fixed steps,
//   onDrawGraphs, render of each entity, onRender, graphs refresh.

#include "physim/framework/FixedStepAccumulator.hpp"
#include "physim/framework/RunOptions.hpp"
#include "physim/framework/Simulation.hpp"

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sf {
class Event;
class Font;
class RenderWindow;
}  // namespace sf

namespace physim {

using SimulationFactory = std::function<std::unique_ptr<Simulation>()>;

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
    /// A window event: key presses go to onEvent, then Space restarts, P pauses, Esc quits.
    void handleEvent(const sf::Event& event, sf::RenderWindow* window);
    bool quitRequested() const { return quit_; }

    Simulation& simulation();
    const FixedStepAccumulator& accumulator() const { return accumulator_; }
    /// summary.json and the graphs' files into `directory`. Returns the paths written.
    std::vector<std::string> writeOutputs(const std::string& directory) const;

private:
    int runHeadless();
    int runWindow();
    /// Top-left overlay: simulated time, physics rate, frames per second, pause state and the keys.
    void drawOverlay(sf::RenderWindow& window);

    SimulationFactory factory_;
    RunOptions options_;
    std::unique_ptr<Simulation> simulation_;
    std::shared_ptr<ContinuousSolver> continuousSolver_;  // the CUDA layer's, in a `cuda` build; else null (CPU)
    FixedStepAccumulator accumulator_;
    bool quit_ = false;
    std::unique_ptr<sf::Font> overlayFont_;  // null when no font file is found: no overlay then
    std::optional<std::array<int, 4>> graphsWindow_;  // x, y, width, height beside the window; none headless
    double framesPerSecond_ = 0.0;
    std::size_t accuracyApplied_ = 0;  // entities given the command line's accuracy knobs so far
};

/// Parses the command line and runs. Prints usage errors with exit code 2, runtime errors with 1.
int runMain(int argc, const char* const* argv, const SimulationFactory& factory);

template <class T>
int runMain(int argc, const char* const* argv) {
    return runMain(argc, argv, [] { return std::make_unique<T>(); });
}

}  // namespace physim
