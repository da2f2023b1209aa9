#include "physim/framework/Runner.hpp"

#include "AccuracyOptions.hpp"
#include "BranchChanges.hpp"
#include "GraphsPlacement.hpp"
#include "OutputFolder.hpp"
#include "Progress.hpp"
#include "Recorder.hpp"
#include "RunRecord.hpp"
#include "RunnerAccess.hpp"
#include "Summary.hpp"
#ifdef PHYSIM_WITH_CUDA
#include "physim/cuda/ContinuousSolver.hpp"
#endif
#include "physim/framework/RigidBody.hpp"

#include "Display.hpp"
#include "Instruments.hpp"
#include "Interrupts.hpp"
#include "Overlay.hpp"

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/Texture.hpp>
#include <SFML/Window/Event.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>

namespace physim {
namespace {

// "1x", "1/4x", "2x": the time scale as the overlay shows it.
std::string showScale(double scale) {
    char text[32];
    if (scale >= 1.0) std::snprintf(text, sizeof text, "%gx", scale);
    else std::snprintf(text, sizeof text, "1/%gx", 1.0 / scale);
    return text;
}

// What holds the run below real time, as the bar's slow-motion warning ends: the user's cap, or the pacing.
std::string holdingBack(const std::optional<int>& maxStepsPerFrame, const FramePacer& pacer) {
    char text[128];
    if (maxStepsPerFrame)
        std::snprintf(text, sizeof text, "the catch-up cap is %d steps per frame", *maxStepsPerFrame);
    else
        std::snprintf(text, sizeof text, "steps take %.3g ms and drawing %.3g ms, so at most %d a frame (for %.0f FPS)",
                      1e3 * pacer.stepCost(), 1e3 * pacer.otherCost(), pacer.maxSteps(),
                      1.0 / FramePacer::frameBudget);
    return text;
}

// The overlay bar's text: status, then the keys. `holdingBack`: the slow-motion warning's end. `arrowsLegend`: V's
// scales, empty while off. `tallest`: with every optional item, for the bar's most height.
std::vector<Overlay::Item> overlayItems(const Simulation& sim, const Controls& controls, const PaceMeter& pace,
                                        const std::string& holdingBack, double framesPerSecond,
                                        const std::string& arrowsLegend, bool tallest) {
    const sf::Color warning(190, 40, 0), keyColor(85, 85, 85);
    char text[160];
    std::vector<Overlay::Item> items;
    std::snprintf(text, sizeof text, "t = %.2f s", sim.time);
    items.push_back({text});
    std::snprintf(text, sizeof text, "physics %.0f Hz", sim.physicsRate());
    items.push_back({text});
    std::snprintf(text, sizeof text, "%.0f FPS", framesPerSecond);
    items.push_back({text});
    items.push_back({"speed " + showScale(controls.timeScale())});
    if (sim.paused || tallest) items.push_back({"PAUSED (O steps)", warning});
    if (sim.branch() || tallest) {
        std::snprintf(text, sizeof text, "branch %.3g m away (B ends it)", sim.branchDistance());
        items.push_back({text, sf::Color(30, 90, 170)});
    }
    const Stopwatch& stopwatch = controls.stopwatch();
    if (stopwatch.state() != Stopwatch::State::Idle || stopwatch.armed() || tallest) {
        const bool running = stopwatch.state() == Stopwatch::State::Running;
        std::snprintf(text, sizeof text,
                      stopwatch.armed() ? (running ? "stopwatch %.3f s (the next sensor entry stops it)"
                                                   : "stopwatch %.3f s (armed: a sensor entry starts it)")
                      : running         ? "stopwatch %.3f s (W stops)"
                                        : "stopwatch stopped: %.3f s (W restarts)",
                      stopwatch.reading(sim.time));
        items.push_back({text, sf::Color(120, 60, 160)});
    }
    if (!arrowsLegend.empty() || tallest)
        items.push_back({tallest && arrowsLegend.empty() ? arrowsLegendText(500.0, 5000.0) : arrowsLegend});
    if (tallest || (!sim.paused && pace.cappedBelow(controls.timeScale()))) {
        std::snprintf(text, sizeof text, "slower than real time: %.2fx, %s", pace.pace(), holdingBack.c_str());
        items.push_back({text, warning});
    }
    // The keys start a new line: a long first line of status would otherwise run into them.
    std::string keys = Controls::keysHelp();
    if (!sim.keysHelp().empty()) keys += "   " + sim.keysHelp();
    bool first = true;
    for (std::size_t from = 0; from < keys.size();) {
        const std::size_t to = std::min(keys.find("   ", from), keys.size());
        items.push_back({keys.substr(from, to - from), keyColor});
        items.back().newLine = first;
        first = false;
        from = to == keys.size() ? to : keys.find_first_not_of(' ', to);
    }
    return items;
}

// After a step: each traced body's centre of mass, the picked body first, then the dynamic bodies already traced
// or faster than kTrailStartSpeed (a resting body's trail would be a dot, and would take a place under the cap).
// `positions`: a buffer kept between steps.
constexpr double kTrailStartSpeed = 0.1;  // m/s
void recordTrails(Trails& trails, std::vector<std::pair<BodyId, Vec2>>& positions, std::optional<BodyId> picked,
                  const World& world) {
    positions.clear();
    const bool tracePicked = picked && world.contains(*picked) && world.type(*picked) == BodyType::Dynamic;
    if (tracePicked) positions.emplace_back(*picked, world.centerOfMass(*picked));
    const auto before = [](BodyId a, BodyId b) {
        return a.index != b.index ? a.index < b.index : a.generation < b.generation;
    };
    std::vector<BodyId> traced;  // at most maxBodies, sorted to be looked up
    for (const Trails::Entry& e : trails.entries()) traced.push_back(e.body);
    std::sort(traced.begin(), traced.end(), before);
    for (BodyId id : world.bodies()) {
        if (positions.size() >= trails.maxBodies()) break;
        if (world.type(id) != BodyType::Dynamic || (tracePicked && id == *picked)) continue;
        if (std::binary_search(traced.begin(), traced.end(), id, before) ||
            world.velocity(id).norm() > kTrailStartSpeed)
            positions.emplace_back(id, world.centerOfMass(id));
    }
    trails.record(positions);
}

}  // namespace

Runner::Runner(SimulationFactory factory, RunOptions options)
    : factory_(std::move(factory)), options_(std::move(options)),
      loop_(std::make_unique<Loop>(options_.maxStepsPerFrame.value_or(FramePacer::mostSteps))),
      windowSize_(static_cast<unsigned>(options_.width), static_cast<unsigned>(options_.height)) {
    if (!factory_) throw std::invalid_argument("physim: Runner needs a simulation factory");
#ifdef PHYSIM_WITH_CUDA
    // Built with the CUDA layer: large continuous batches go to the GPU, or a line says why they stay on the CPU
    // (not under --quiet). A GPU that fails later is always reported.
    std::ostream silent(nullptr);
    cuda::GpuSolverOptions gpu;
    gpu.log = &std::clog;
    continuousSolver_ = cuda::makeContinuousSolver(options_.quiet ? silent : std::clog, gpu);
#endif
}

Simulation& Runner::simulation() {
    if (!simulation_) throw std::logic_error("physim: Runner has no simulation yet (call restart or run)");
    return *simulation_;
}

Runner::~Runner() = default;

double Runner::timeScale() const { return loop_->controls.timeScale(); }
void Runner::setTimeScale(double scale) { loop_->controls.setTimeScale(scale); }
void Runner::requestSingleStep() { loop_->controls.requestSingleStep(); }
void Runner::requestFit() { loop_->controls.requestFit(); }
bool Runner::statsShown() const { return loop_->controls.statsShown(); }
void Runner::setStatsShown(bool shown) { loop_->controls.setStatsShown(shown); }

void Runner::restart() {
    // A restart of the same simulation keeps what the user chose: parameter values and debug drawing.
    std::optional<Parameters> keptParameters;
    std::optional<DebugDrawOptions> keptDrawing;
    if (simulation_ && !factoryChanged_) {
        keptParameters = simulation_->parameters;
        keptDrawing = simulation_->debugDraw;
    }
    loop_->controls.forgetDrag();  // its joint lives in the old world
    loop_->controls.resetInstruments();  // simulated time starts again at 0
    loop_->trails.clear();
    simulation_.reset();  // the old simulation (and its graph windows) goes before the new one is made
    simulation_ = factory_();
    if (!simulation_) throw std::runtime_error("physim: the simulation factory returned null");
    Simulation& sim = *simulation_;
    if (keptParameters) {
        sim.parameters.copyValuesFrom(*keptParameters);
    } else {
        for (const auto& [name, value] : options_.parameters)
            if (sim.parameters.contains(name)) sim.parameters.set(name, value);
    }
    const bool sceneSwitched = factoryChanged_;  // the gallery's new scene: --from's file is another scene's
    factoryChanged_ = false;
    if (continuousSolver_) sim.world().setContinuousSolver(continuousSolver_);
    sim.graphsManager.setLive(!options_.headless);
    if (graphsWindow_) {  // beside the window; onCreate may place it elsewhere
        const auto [x, y, w, h] = *graphsWindow_;
        sim.graphsManager.setCanvasPosition(x, y);
        sim.graphsManager.setCanvasSize(w, h);
        sim.graphsManager.setCanvasTitle(sim.title() + ": graphs");
    }
    if (options_.hz) sim.setPhysicsRate(*options_.hz);
    sim.onCreate();
    if (options_.hz) sim.setPhysicsRate(*options_.hz);  // the command line wins over onCreate's choice
    applyAccuracyOptions(options_, sim);
    accuracyApplied_ = sim.entities().size();
    if (keptDrawing) sim.debugDraw = *keptDrawing;
    // The file's world replaces onCreate's, with the settings and detection modes it was run with.
    if (options_.from && !sceneSwitched) resumeFrom(*options_.from);
    sim.start = true;
    loop_->accumulator =
        FixedStepAccumulator(sim.fixedTimeStep(), options_.maxStepsPerFrame.value_or(FramePacer::mostSteps));
    loop_->stepTimes.clear();
    loop_->pace.clear();
    // The pacer keeps its estimates: a restart is most often of the same scene, and another scene's costs replace
    // them within frames (a rise at once). Unmeasured, the first frame could run a long restart's time in steps.
    viewSetByScene_ = sim.view != View{};
    if (!viewSetByScene_) fitView();
    timeline_.clear();
    changePending_ = movePending_ = false;
    branchTrace_.clear();
    livePlots_.clear();
    recorder_.reset();
    if (!options_.records.empty()) {  // a bad spec is a usage error (exit 2) naming it
        try {
            recorder_ = std::make_unique<Recorder>(options_.records, sim);
        } catch (const std::invalid_argument& e) {
            throw UsageError(e.what());
        }
        recorder_->sample(sim);
    }
    if (recording_) timeline_.record(sim);
}

void Runner::resumeFrom(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw UsageError("--from: cannot open " + file);
    try {
        simulation().readSnapshot(in);
    } catch (const std::exception& e) {  // a bad file (runtime_error) or another scene's (logic_error)
        throw UsageError("--from " + file + ": " + e.what());
    }
}

std::string Runner::writeSnapshotFile() const {
    if (!simulation_ || !options_.outDir) throw std::logic_error("physim: a snapshot file needs a run and --out");
    const std::filesystem::path folder = std::filesystem::path(*options_.outDir) / "snapshots";
    std::filesystem::create_directories(folder);
    char name[64];
    std::snprintf(name, sizeof name, "step-%09llu.psnap",
                  static_cast<unsigned long long>(simulation_->world().stepCount()));
    const std::filesystem::path path = folder / name, partial = folder / (std::string(name) + ".part");
    {
        std::ofstream out(partial, std::ios::binary);
        simulation_->writeSnapshot(out);  // throws if the stream fails
    }
    std::filesystem::rename(partial, path);  // a reader never sees half a file
    return path.string();
}

void Runner::oneStepFrame(bool record) {
    Simulation& sim = simulation();
    sim.onUpdate();
    sim.updateEntities();
    fixedStep();
    sim.onDrawGraphs();
    if (record) timeline_.record(sim);
}

void Runner::fixedStep() {
    Simulation& sim = simulation();
    sim.fixedStep();
    if (recorder_) recorder_->sample(sim);
    if (loop_->controls.stopwatch().armed())  // Shift+W: bodies entering sensors start and stop it, on time
        for (const SensorEvent& e : sim.world().sensorEvents().begin)
            loop_->controls.stopwatch().sensorEntered(sim.time - sim.fixedTimeStep() + e.time);
    if (loop_->controls.trailsShown())
        recordTrails(loop_->trails, loop_->trailPositions, loop_->controls.picked(), sim.world());
    for (LivePlot& plot : livePlots_) {
        while (!plot.points.empty() && plot.points.back().first > sim.time - 0.5 * sim.fixedTimeStep())
            plot.points.pop_back();
        plot.points.emplace_back(sim.time, recordValue(sim, plot.spec));
    }
    if (!sim.branch()) branchTrace_.clear();
    else if (branchTrace_.empty() || sim.time > branchTrace_.back().first + 0.5 * sim.fixedTimeStep())
        branchTrace_.emplace_back(sim.time, sim.branchDistance());
}

void Runner::startBranch(BranchChange change) {
    Simulation& sim = simulation();
    sim.startBranch(sim.snapshot(), branchChangeFor(change));
    branchTrace_.assign(1, {sim.time, sim.branchDistance()});
    changePending_ = true;  // a replay from before could not start the branch
}

std::optional<int> Runner::pickedEntity() {
    const std::optional<BodyId> body = loop_->controls.picked();
    if (!body || !simulation().world().contains(*body)) return std::nullopt;
    for (const auto& e : simulation().entities())  // any entity with that body (an Object, or a RigidBody's owner)
        if (const auto* rb = e->TryGetBehavior<RigidBody>(); rb && rb->attached() && rb->bodyId() == *body)
            return e->id();
    return std::nullopt;
}

void Runner::addLivePlot(const RecordSpec& spec) {
    const auto& known = RecordSpec::quantities();
    if (std::find(known.begin(), known.end(), spec.quantity) == known.end())
        throw std::invalid_argument("physim: addLivePlot: unknown quantity '" + spec.quantity + "'");
    const Recorder check({spec}, simulation());  // throws for an id no entity has, or one without a body
    livePlots_.push_back({spec, {{simulation().time, recordValue(simulation(), spec)}}});
}

void Runner::removeLivePlot(std::size_t index) {
    if (index >= livePlots_.size())
        throw std::out_of_range("physim: removeLivePlot: no live plot " + std::to_string(index));
    livePlots_.erase(livePlots_.begin() + static_cast<std::ptrdiff_t>(index));
}

void Runner::endBranch() {
    simulation().endBranch();
    branchTrace_.clear();
    changePending_ = true;
}

void Runner::markChange() {
    // Marked where the hooks of the frame before have run and those of the next have not, as the frame-end record.
    const bool changed = std::exchange(changePending_, false), moved = std::exchange(movePending_, false);
    if (!recording_) return;
    if (changed) timeline_.mark(simulation());
    else if (moved) timeline_.noteChange(simulation());
}

double Runner::scrubTo(double time) {
    markChange();
    Simulation& sim = simulation();
    sim.paused = true;
    if (timeline_.empty()) timeline_.record(sim);
    const double dt = sim.fixedTimeStep();
    if (time > sim.time + 0.5 * dt) {
        const auto steps = static_cast<long long>(std::floor((time - sim.time) / dt + 0.5));
        for (long long i = 0; i < steps; ++i) oneStepFrame(recording_);
        loop_->trails.clear();  // as going back: a scrub starts the paths anew
        return sim.time;
    }
    // Back: the replayed steps repeat the trace's points (fixedStep adds none), and the later ones go.
    const double restored = timeline_.scrubTo(sim, time, [this] { oneStepFrame(false); });
    const double last = restored + 0.5 * sim.fixedTimeStep();
    while (!branchTrace_.empty() && branchTrace_.back().first > last) branchTrace_.pop_back();
    for (LivePlot& plot : livePlots_)
        while (!plot.points.empty() && plot.points.back().first > last) plot.points.pop_back();
    if (!sim.branch()) branchTrace_.clear();
    loop_->trails.clear();  // the paths led to the state left behind
    return restored;
}

void Runner::setFactory(SimulationFactory factory) {
    if (!factory) throw std::invalid_argument("physim: Runner needs a simulation factory");
    factory_ = std::move(factory);
    factoryChanged_ = true;
}

void Runner::setPanel(std::unique_ptr<RunnerPanel> panel) { panel_ = std::move(panel); }

sf::FloatRect Runner::sceneArea() const {
    const float left = panel_ ? std::min(panel_->width(), static_cast<float>(windowSize_.x)) : 0.f;
    float top = 0.f;
    if (overlay_ && simulation_) {
        // The bar at its tallest (paused, the instruments' readings and the catch-up warning shown), so the scene
        // stays clear of it.
        const std::vector<Overlay::Item> items =
            overlayItems(*simulation_, loop_->controls, loop_->pace,
                         holdingBack(options_.maxStepsPerFrame, loop_->pacer), framesPerSecond_, loop_->arrowsLegend,
                         true);
        top = overlay_->barHeight(items, static_cast<float>(windowSize_.x) - left);
    }
    return {left, top, static_cast<float>(windowSize_.x) - left, static_cast<float>(windowSize_.y) - top};
}

void Runner::fitView() {
    Simulation& sim = simulation();
    if (const std::optional<Aabb> bounds = sim.viewBounds()) sim.view.fit(*bounds, sceneArea(), windowSize_);
}

int Runner::frame(double frameSeconds, sf::RenderWindow* window) {
    const double frameStart = loop_->clock();
    markChange();
    Simulation& sim = simulation();
    sim.onUpdate();
    sim.updateEntities();
    if (sim.entities().size() != accuracyApplied_) {  // bodies added since (a key, a spawner): same knobs
        applyAccuracyOptions(options_, sim);
        accuracyApplied_ = sim.entities().size();
    }
    int steps = 0;
    const std::uint64_t droppedBefore = loop_->accumulator.droppedSteps();
    const bool singleStep = loop_->controls.takeSingleStep();  // O: one step, asked for while paused
    // Paced (no --max-steps-per-frame): no more steps than keep the frame within 1/20 s. The pacing sets only how
    // many steps run, never their length: a headless run's one step a frame is always allowed.
    const int limit = options_.maxStepsPerFrame ? *options_.maxStepsPerFrame : loop_->pacer.maxSteps();
    if (!sim.paused) steps = loop_->accumulator.advance(frameSeconds * loop_->controls.timeScale(), limit);
    else if (singleStep) steps = 1;
    const double stepsStart = loop_->clock();
    for (int i = 0; i < steps; ++i) {
        fixedStep();
        loop_->stepTimes.record(sim.world().profile());
    }
    const double stepsEnd = loop_->clock();
    loop_->pace.record(frameSeconds, steps * sim.fixedTimeStep(), loop_->accumulator.droppedSteps() - droppedBefore,
                       sim.paused);
    sim.onDrawGraphs();
    if (recording_ && steps > 0) timeline_.record(sim);  // the frame's end: what a scrub lands on
    if (loop_->controls.takeFitRequest()) fitView();
    if (!loop_->controls.trailsShown() && !loop_->trails.entries().empty()) loop_->trails.clear();  // L turned them off
    if (window) {
        window->clear(sf::Color(235, 235, 235));
        sim.renderEntities(window);
        sim.onRender(window);
        if (const World* branch = sim.branch()) drawGhosts(*window, sim.view, *branch);
        drawDebug(*window, sim.view, sim.world(), sim.debugDraw, sim.debugRays());
        if (loop_->controls.trailsShown()) drawTrails(*window, sim.view, loop_->trails);
        if (loop_->controls.arrowsShown())
            loop_->arrowsLegend = drawArrows(*window, sim.view, sim.world(), sim.fixedTimeStep(), loop_->velocityScale,
                                             loop_->forceScale);
        else
            loop_->arrowsLegend.clear();
        if (overlay_) drawMeasurement(*window, sim.view, loop_->controls.measurement(), *overlay_);
        drawOverlay(*window);
        if (panel_) panel_->draw(*window, *this, frameSeconds);  // may restart: `sim` is stale after it
    }
    simulation().graphsManager.render();
    if (window) window->display();
    // The rest of the frame: hooks, drawing, display (with its wait for the 60 FPS limit, only in a frame with time
    // to spare).
    loop_->pacer.record(steps, stepsEnd - stepsStart, (stepsStart - frameStart) + (loop_->clock() - stepsEnd));
    return steps;
}

void Runner::handleEvent(const sf::Event& event, sf::RenderWindow* window) {
    if (panel_ && panel_->handleEvent(event)) return;
    Simulation& sim = simulation();
    switch (event.type) {
        case sf::Event::Closed: quit_ = true; break;
        case sf::Event::Resized:
            windowSize_ = {event.size.width, event.size.height};
            if (window)
                window->setView(sf::View(sf::FloatRect(0.f, 0.f, static_cast<float>(event.size.width),
                                                       static_cast<float>(event.size.height))));
            if (!viewSetByScene_) fitView();
            break;
        case sf::Event::KeyPressed:
            sim.onEvent(event);
            changePending_ = true;  // the scene may have changed its world: the replay could not repeat that
            if (event.key.code == sf::Keyboard::Space) restart();
            else if (event.key.code == sf::Keyboard::P) sim.paused = !sim.paused;
            else if (event.key.code == sf::Keyboard::Left) scrubTo(sim.time - 1.0);
            else if (event.key.code == sf::Keyboard::Right) scrubTo(sim.time + 1.0);
            else if (event.key.code == sf::Keyboard::Home) scrubTo(0.0);
            else if (event.key.code == sf::Keyboard::B) sim.branch() ? endBranch() : startBranch(branchChange_);
            else if (event.key.code == sf::Keyboard::Escape) quit_ = true;
            else loop_->controls.handleEvent(event, sim, window ? window->getSize() : windowSize_);
            break;
        default: loop_->controls.handleEvent(event, sim, window ? window->getSize() : windowSize_); break;
    }
    if (loop_->controls.takeWorldChange()) changePending_ = true;
    if (loop_->controls.takeDragMove()) movePending_ = true;
}

std::vector<std::string> Runner::writeOutputs(const std::string& directory) const {
    if (!simulation_) throw std::logic_error("physim: nothing to write before the simulation started");
    std::filesystem::create_directories(directory);
    const std::filesystem::path path = std::filesystem::path(directory) / "summary.json";
    std::ofstream out(path);
    out << summaryJson(*simulation_);
    if (!out) throw std::runtime_error("physim: cannot write " + path.string());
    std::vector<std::string> written{path.string()};
    const std::filesystem::path record = std::filesystem::path(directory) / "run.json";
    std::ofstream recordOut(record);
    recordOut << runRecordJson(options_.program.empty() ? "physim" : options_.program, options_.arguments,
                               *simulation_);
    if (!recordOut) throw std::runtime_error("physim: cannot write " + record.string());
    written.push_back(record.string());
    for (std::string& file : simulation_->graphsManager.writeFiles(directory)) written.push_back(std::move(file));
    if (recorder_)  // after the graphs: their graphs.root is written anew, and the records' tree joins it
        for (std::string& file : recorder_->write(directory))
            if (std::find(written.begin(), written.end(), file) == written.end()) written.push_back(std::move(file));
    return written;
}

bool Runner::stopRequested() {
    if (!interrupts_) return false;
    interrupts_->reassert();
    return interrupts_->signal() != 0;
}

int Runner::run() {
    if (options_.outDir) prepareOutputFolder(*options_.outDir);  // before any simulated time is spent
    InterruptWatch interrupts;  // the loops stop at the end of the step a signal comes in
    interrupts_ = &interrupts;
    struct Unwatch {
        Runner& runner;
        ~Unwatch() { runner.interrupts_ = nullptr; }
    } unwatch{*this};
    const int code = options_.headless ? runHeadless() : runWindow();
    if (options_.outDir) {
        const auto written = writeOutputs(*options_.outDir);
        if (!options_.quiet) std::cout << writtenLine(*options_.outDir, written) << std::endl;
    }
    if (const int number = interrupts.signal()) {
        const std::string snapshot = options_.outDir ? writeSnapshotFile() : std::string();
        std::cerr << "physim: stopped by " << (number == SIGINT ? "SIGINT" : "SIGTERM") << " at t = " << simulation().time
                  << " s" << (options_.outDir ? ", after writing what was recorded to " + *options_.outDir : "")
                  << (snapshot.empty() ? "" : " and a snapshot that --from resumes, " + snapshot) << "; exit status "
                  << interruptedStatus(number) << std::endl;
        return interruptedStatus(number);
    }
    return code;
}

int Runner::runHeadless() {
    restart();
    if (options_.outDir) simulation().graphsManager.prepareExport();  // ROOT's start-up while the run goes on
    const double seconds = options_.seconds.value_or(RunOptions::defaultHeadlessSeconds);
    // One fixed step per frame: the frame loop and every hook run exactly as in a window, with no clock.
    const double dt = simulation().fixedTimeStep();
    const auto frames = static_cast<long long>(std::ceil(seconds / dt - 1e-9));
    Progress progress(seconds, !options_.quiet);
    const std::uint64_t every = options_.outDir && options_.snapshotEvery ? *options_.snapshotEvery : 0;
    for (long long i = 0; i < frames && !quit_ && !stopRequested(); ++i) {
        frame(simulation().fixedTimeStep(), nullptr);
        progress.update(simulation().time, i + 1);
        if (every > 0 && simulation().world().stepCount() % every == 0) writeSnapshotFile();
    }
    progress.finish();
    return 0;
}

float Runner::drawOverlay(sf::RenderWindow& window) {
    if (!overlay_) return 0.f;
    const float left = panel_ ? panel_->width() : 0.f;
    const float height =
        overlay_->drawBar(window, left, static_cast<float>(window.getSize().x) - left,
                          overlayItems(simulation(), loop_->controls, loop_->pace,
                                       holdingBack(options_.maxStepsPerFrame, loop_->pacer), framesPerSecond_,
                                       loop_->arrowsLegend, false));
    if (loop_->controls.statsShown())
        overlay_->drawPanel(window, height, formatStats(computeStats(simulation().world()), loop_->stepTimes));
    return height;
}

int Runner::runWindow() {
    recording_ = true;
    sf::ContextSettings context;
    context.antialiasingLevel = 4;
    sf::RenderWindow window(sf::VideoMode(static_cast<unsigned>(options_.width), static_cast<unsigned>(options_.height)),
                            "physim", sf::Style::Default, context);
    window.setFramerateLimit(60);
    windowSize_ = window.getSize();
    overlay_ = std::make_unique<Overlay>();
    struct PanelOnWindow {  // the panel lets go of the window before the window goes, even on an exception
        RunnerPanel* panel;
        ~PanelOnWindow() {
            if (panel) panel->close();
        }
    } panelOnWindow{panel_.get()};
    if (panel_) panel_->open(window);
    // The live graphs window opens beside this one (the pair centred when the screen is wide enough).
    const sf::VideoMode desktop = sf::VideoMode::getDesktopMode();
    const SideBySide layout = placeBeside(options_.width, options_.height, static_cast<int>(desktop.width),
                                          static_cast<int>(desktop.height));
    graphsWindow_ = {layout.canvas.x, layout.canvas.y, layout.canvas.width, layout.canvas.height};
    restart();
    if (simulation().graphsManager.canvasOpen()) window.setPosition({layout.window.x, layout.window.y});
    sf::Clock frameClock, titleClock;
    int framesSinceTitle = 0;
    while (window.isOpen() && !quit_ && !stopRequested()) {
        sf::Event event;
        while (window.pollEvent(event)) handleEvent(event, &window);
        if (quit_) break;
        frame(frameClock.restart().asSeconds(), &window);
        ++framesSinceTitle;
        const double sinceTitle = titleClock.getElapsedTime().asSeconds();
        if (sinceTitle >= 0.25) {
            framesPerSecond_ = framesSinceTitle / sinceTitle;
            const Simulation& sim = simulation();
            char title[256];
            std::snprintf(title, sizeof title, "%s | t = %.2f s | physics %.0f Hz | %.0f FPS%s", sim.title().c_str(),
                          sim.time, sim.physicsRate(), framesSinceTitle / sinceTitle, sim.paused ? " | PAUSED" : "");
            window.setTitle(title);
            titleClock.restart();
            framesSinceTitle = 0;
        }
        if (options_.seconds && simulation().time >= *options_.seconds) break;
    }
    if (options_.screenshot) {
        // What the window shows now: the last frame, after display().
        sf::Texture texture;
        texture.create(window.getSize().x, window.getSize().y);
        texture.update(window);
        if (!texture.copyToImage().saveToFile(*options_.screenshot))
            throw std::runtime_error("physim: cannot write the screenshot " + *options_.screenshot);
    }
    return 0;
}

namespace {

// --replay: the recorded run again, headless and for the recorded number of steps; 0 when it ends in the recorded
// state, 1 when not (or on an error while running), 2 for a run.json that cannot be replayed.
int replayRun(const std::string& program, const std::string& path, bool quiet, const SimulationFactory& factory,
              const std::function<void(Runner&)>& setup) {
    RecordedRun recorded;
    RunOptions options;
    try {
        recorded = readRunRecord(path, program);
        options = parseRunOptions(recorded.arguments);
    } catch (const UsageError& e) {
        std::cerr << program << ": " << e.what() << "\n";
        return 2;
    }
    if (options.from) {
        std::cerr << program << ": " << path << " records a run started --from a snapshot: --replay cannot rerun it\n";
        return 2;
    }
    options.program = program;
    options.headless = true;
    options.quiet = quiet;
    options.outDir.reset();
    options.screenshot.reset();
    options.snapshotEvery.reset();
    options.seconds = static_cast<double>(recorded.steps) * recorded.timeStep;
    try {
        Runner runner(factory, options);
        if (setup) setup(runner);
        runner.run();
        const Simulation& sim = runner.simulation();
        const std::uint64_t steps = sim.world().stepCount(), hash = sim.world().stateHash();
        if (steps == recorded.steps && hash == recorded.stateHash) {
            std::cout << program << ": replayed " << steps << " steps of " << path << ": the final state hash "
                      << hashText(hash) << " matches" << std::endl;
            return 0;
        }
        std::cout << program << ": replayed " << path << ": it ended differently: " << steps << " steps (recorded "
                  << recorded.steps << "), final state hash " << hashText(hash) << " (recorded "
                  << hashText(recorded.stateHash) << "); recorded with " << recorded.build << ", replayed with "
                  << buildDescription() << std::endl;
        return 1;
    } catch (const std::exception& e) {
        std::cerr << program << ": error: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace

int runMain(int argc, const char* const* argv, const SimulationFactory& factory,
            const std::function<void(Runner&)>& setup) {
    const std::string program = argc > 0 ? std::filesystem::path(argv[0]).filename().string() : "physim";
    RunOptions options;
    try {
        options = parseRunOptions(std::vector<std::string>(argv + (argc > 0 ? 1 : 0), argv + argc));
        if (options.outDir && !options.help) prepareOutputFolder(*options.outDir);  // before any time is spent
    } catch (const UsageError& e) {
        std::cerr << program << ": " << e.what() << "\n";
        return 2;
    }
    options.program = program;
    if (options.replay) return replayRun(program, *options.replay, options.quiet, factory, setup);
    try {
        if (options.help) {
            const std::unique_ptr<Simulation> sim = factory();
            std::cout << usage(program, sim->title());
            if (!sim->parameters.empty())
                std::cout << "\nparameters (--param name=value):\n" << sim->parameters.describe();
            return 0;
        }
        // Parameters are checked against the simulation's declarations before anything runs.
        const std::unique_ptr<Simulation> probe = factory();
        try {
            for (const auto& [name, value] : options.parameters) probe->parameters.set(name, value);
        } catch (const std::invalid_argument& e) {
            std::cerr << program << ": --param: " << e.what() << "\n";
            return 2;
        }
        std::optional<DisplayConnection> display;  // held open until the run ends (Display.hpp says why)
        if (!options.headless) {
            display.emplace();
            if (!display->problem().empty()) {
                std::cerr << program << ": " << display->problem() << "; use --headless (or run under xvfb-run)\n";
                return 2;
            }
        }
        Runner runner(factory, options);
        if (setup) setup(runner);
        return runner.run();
    } catch (const UsageError& e) {  // found once the scene exists: --record's ids, --from's file
        std::cerr << program << ": " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << program << ": error: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace physim
