#include "physim/framework/Runner.hpp"

#include "AccuracyOptions.hpp"
#include "GraphsPlacement.hpp"
#include "OutputFolder.hpp"
#include "Progress.hpp"
#include "physim/framework/Summary.hpp"
#ifdef PHYSIM_WITH_CUDA
#include "physim/cuda/ContinuousSolver.hpp"
#endif

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/Text.hpp>
#include <SFML/Graphics/Texture.hpp>
#include <SFML/Window/Event.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace physim {

Runner::Runner(SimulationFactory factory, RunOptions options)
    : factory_(std::move(factory)), options_(std::move(options)), accumulator_(1.0 / 40.0, options_.maxStepsPerFrame) {
    if (!factory_) throw std::invalid_argument("physim: Runner needs a simulation factory");
#ifdef PHYSIM_WITH_CUDA
    // Built with the CUDA layer: large continuous batches go to the GPU, or a line says why they stay on the CPU.
    continuousSolver_ = cuda::makeContinuousSolver(std::clog);
#endif
}

Runner::~Runner() = default;

Simulation& Runner::simulation() {
    if (!simulation_) throw std::logic_error("physim: Runner has no simulation yet (call restart or run)");
    return *simulation_;
}

void Runner::restart() {
    simulation_.reset();  // the old simulation (and its graph windows) goes before the new one is made
    simulation_ = factory_();
    if (!simulation_) throw std::runtime_error("physim: the simulation factory returned null");
    Simulation& sim = *simulation_;
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
    sim.start = true;
    accumulator_ = FixedStepAccumulator(sim.fixedTimeStep(), options_.maxStepsPerFrame);
}

int Runner::frame(double frameSeconds, sf::RenderWindow* window) {
    Simulation& sim = simulation();
    sim.onUpdate();
    sim.updateEntities();
    if (sim.entities().size() != accuracyApplied_) {  // bodies added since (a key, a spawner): same knobs
        applyAccuracyOptions(options_, sim);
        accuracyApplied_ = sim.entities().size();
    }
    int steps = 0;
    if (!sim.paused) {
        steps = accumulator_.advance(frameSeconds);
        for (int i = 0; i < steps; ++i) sim.fixedStep();
    }
    sim.onDrawGraphs();
    if (window) {
        window->clear(sf::Color(235, 235, 235));
        sim.renderEntities(window);
        sim.onRender(window);
        drawOverlay(*window);
    }
    sim.graphsManager.render();
    if (window) window->display();
    return steps;
}

void Runner::handleEvent(const sf::Event& event, sf::RenderWindow* window) {
    Simulation& sim = simulation();
    switch (event.type) {
        case sf::Event::Closed: quit_ = true; break;
        case sf::Event::Resized:
            if (window)
                window->setView(sf::View(sf::FloatRect(0.f, 0.f, static_cast<float>(event.size.width),
                                                       static_cast<float>(event.size.height))));
            break;
        case sf::Event::MouseWheelScrolled:
            sim.view.zoom(event.mouseWheelScroll.delta > 0 ? 1.1 : 1.0 / 1.1);
            break;
        case sf::Event::KeyPressed:
            sim.onEvent(event);
            if (event.key.code == sf::Keyboard::Space) restart();
            else if (event.key.code == sf::Keyboard::P) sim.paused = !sim.paused;
            else if (event.key.code == sf::Keyboard::Escape) quit_ = true;
            break;
        default: break;
    }
}

std::vector<std::string> Runner::writeOutputs(const std::string& directory) const {
    if (!simulation_) throw std::logic_error("physim: nothing to write before the simulation started");
    std::filesystem::create_directories(directory);
    const std::filesystem::path path = std::filesystem::path(directory) / "summary.json";
    std::ofstream out(path);
    out << summaryJson(*simulation_);
    if (!out) throw std::runtime_error("physim: cannot write " + path.string());
    std::vector<std::string> written{path.string()};
    for (std::string& file : simulation_->graphsManager.writeFiles(directory)) written.push_back(std::move(file));
    return written;
}

int Runner::run() {
    if (options_.outDir) prepareOutputFolder(*options_.outDir);  // before any simulated time is spent
    const int code = options_.headless ? runHeadless() : runWindow();
    if (options_.outDir) {
        const auto written = writeOutputs(*options_.outDir);
        if (!options_.quiet) std::cout << writtenLine(*options_.outDir, written) << std::endl;
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
    for (long long i = 0; i < frames && !quit_; ++i) {
        frame(simulation().fixedTimeStep(), nullptr);
        progress.update(simulation().time, i + 1);
    }
    progress.finish();
    return 0;
}

void Runner::drawOverlay(sf::RenderWindow& window) {
    if (!overlayFont_) return;
    const Simulation& sim = simulation();
    char status[160];
    std::snprintf(status, sizeof status, "t = %.2f s   physics %.0f Hz   %.0f FPS%s", sim.time, sim.physicsRate(),
                  framesPerSecond_, sim.paused ? "   PAUSED" : "");
    std::string keys = "Space restart   P pause   Esc quit   wheel zoom";
    if (!sim.keysHelp().empty()) keys += "   " + sim.keysHelp();
    sf::Text text(std::string(status) + "\n" + keys, *overlayFont_, 15);
    text.setFillColor(sf::Color(30, 30, 30));
    text.setPosition(10.f, 8.f);
    sf::RectangleShape backing({text.getLocalBounds().width + 16.f, text.getLocalBounds().height + 18.f});
    backing.setFillColor(sf::Color(255, 255, 255, 200));
    backing.setPosition(2.f, 2.f);
    window.draw(backing);  // pixel space: the window's default view
    window.draw(text);
}

int Runner::runWindow() {
    sf::ContextSettings context;
    context.antialiasingLevel = 4;
    sf::RenderWindow window(sf::VideoMode(static_cast<unsigned>(options_.width), static_cast<unsigned>(options_.height)),
                            "physim", sf::Style::Default, context);
    window.setFramerateLimit(60);
    overlayFont_ = std::make_unique<sf::Font>();
    if (!overlayFont_->loadFromFile("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf")) {
        std::cerr << "physim: DejaVuSans.ttf not found (Debian: fonts-dejavu-core); the overlay is off\n";
        overlayFont_.reset();
    }
    // The live graphs window opens beside this one (the pair centred when the screen is wide enough).
    const sf::VideoMode desktop = sf::VideoMode::getDesktopMode();
    const SideBySide layout = placeBeside(options_.width, options_.height, static_cast<int>(desktop.width),
                                          static_cast<int>(desktop.height));
    graphsWindow_ = {layout.canvas.x, layout.canvas.y, layout.canvas.width, layout.canvas.height};
    restart();
    if (simulation().graphsManager.canvasOpen()) window.setPosition({layout.window.x, layout.window.y});
    sf::Clock frameClock, titleClock;
    int framesSinceTitle = 0;
    while (window.isOpen() && !quit_) {
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

int runMain(int argc, const char* const* argv, const SimulationFactory& factory) {
    const std::string program = argc > 0 ? std::filesystem::path(argv[0]).filename().string() : "physim";
    RunOptions options;
    try {
        options = parseRunOptions(std::vector<std::string>(argv + (argc > 0 ? 1 : 0), argv + argc));
        if (options.outDir && !options.help) prepareOutputFolder(*options.outDir);  // before any time is spent
    } catch (const UsageError& e) {
        std::cerr << program << ": " << e.what() << "\n";
        return 2;
    }
    try {
        if (options.help) {
            std::cout << usage(program, factory()->title());
            return 0;
        }
        if (!options.headless) {
            const char* display = std::getenv("DISPLAY");
            if (!display || !*display) {
                std::cerr << program << ": no display to open a window on; use --headless (or run under xvfb-run)\n";
                return 2;
            }
        }
        Runner runner(factory, options);
        return runner.run();
    } catch (const std::exception& e) {
        std::cerr << program << ": error: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace physim
