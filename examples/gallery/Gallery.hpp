#pragma once
// The gallery's panel: every example scene in one window (Box2D's samples app is the model). A list of the
// scenes on the left; under it the scene's parameters as sliders (a change restarts the scene with the new
// value when the slider is let go), the run controls (pause, step, time scale, restart, fit) and the debug
// drawing and statistics switches. Drawn with Dear ImGui over the runner's frame.

#include "ImGuiSfml.hpp"
#include "Scenes.hpp"

#include <SFML/Graphics/Rect.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace physim::examples {

class Gallery : public RunnerPanel {
public:
    static constexpr float panelWidth = 310.f;  // px

    /// Shows `scenes`, `first` being the one the runner starts with.
    Gallery(std::vector<Scene> scenes, std::size_t first);
    ~Gallery() override;

    void open(sf::RenderWindow& window) override;
    void close() override;
    bool handleEvent(const sf::Event& event) override;
    void draw(sf::RenderWindow& window, Runner& runner, double frameSeconds) override;
    float width() const override { return panelWidth; }

    std::size_t current() const { return current_; }
    /// Where a control was drawn in the last frame (px), for tests that click it: a scene's entry by its name,
    /// a parameter's slider by the parameter's name.
    std::optional<sf::FloatRect> itemRect(const std::string& name) const;

private:
    void drawScenes(Runner& runner);
    void drawParameters(Runner& runner);
    void drawRunControls(Runner& runner);
    void drawBranch(Runner& runner);
    void drawLivePlots(Runner& runner);
    void drawEnergy(sf::RenderWindow& window, Runner& runner);
    void drawDebugSwitches(Runner& runner);

    std::vector<Scene> scenes_;
    std::size_t current_;
    std::unique_ptr<ImGuiSfml> imgui_;
    bool energyBars_ = true;        // the energy bars shown (the scene's ledger switched on for them)
    double energyScale_ = 0.0;      // J: the energy bars' half width, the largest bar yet in this run
    std::size_t plotQuantity_ = 0;  // the quantity "Plot it" adds, an index into RecordSpec::quantities()
    std::vector<double> edits_;  // slider values while the user moves them (applied when let go)
    std::vector<std::pair<std::string, sf::FloatRect>> itemRects_;  // this frame's, for itemRect
};

}  // namespace physim::examples
