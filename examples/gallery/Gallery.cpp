#include "Gallery.hpp"

#include <imgui.h>

#include <SFML/Graphics/RenderWindow.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace physim::examples {

Gallery::Gallery(std::vector<Scene> scenes, std::size_t first) : scenes_(std::move(scenes)), current_(first) {
    if (first >= scenes_.size()) throw std::invalid_argument("physim: the gallery's first scene is not in its list");
}

Gallery::~Gallery() = default;

void Gallery::open(sf::RenderWindow& window) { imgui_ = std::make_unique<ImGuiSfml>(window); }
void Gallery::close() { imgui_.reset(); }

bool Gallery::handleEvent(const sf::Event& event) { return imgui_ && imgui_->processEvent(event); }

namespace {

sf::FloatRect lastItemRect() {
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    return {lo.x, lo.y, hi.x - lo.x, hi.y - lo.y};
}

}  // namespace

std::optional<sf::FloatRect> Gallery::itemRect(const std::string& name) const {
    for (const auto& [item, rect] : itemRects_)
        if (item == name) return rect;
    return std::nullopt;
}

void Gallery::draw(sf::RenderWindow& window, Runner& runner, double frameSeconds) {
    if (!imgui_) return;
    imgui_->newFrame(frameSeconds);
    itemRects_.clear();
    ImGui::SetNextWindowPos(ImVec2(0.f, 0.f));
    ImGui::SetNextWindowSize(ImVec2(panelWidth, static_cast<float>(window.getSize().y)));
    ImGui::Begin("physim gallery", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings);
    drawScenes(runner);
    drawParameters(runner);
    drawRunControls(runner);
    drawBranch(runner);
    drawLivePlots(runner);
    drawDebugSwitches(runner);
    ImGui::Separator();
    ImGui::TextWrapped("Left drag moves a body, right drag pans, the wheel zooms. The keys are in the bar above "
                       "the scene.");
    ImGui::End();
    drawEnergy(window, runner);
    imgui_->render();
}

void Gallery::drawScenes(Runner& runner) {
    ImGui::TextUnformatted("Scenes");
    std::optional<std::size_t> chosen;
    for (std::size_t i = 0; i < scenes_.size(); ++i) {
        if (ImGui::Selectable(scenes_[i].name.c_str(), i == current_)) chosen = i;
        itemRects_.emplace_back(scenes_[i].name, lastItemRect());
    }
    ImGui::Separator();
    ImGui::TextWrapped("%s", runner.simulation().title().c_str());
    if (chosen && *chosen != current_) {
        current_ = *chosen;
        runner.setFactory(scenes_[current_].make);
        runner.restart();
        edits_.clear();
    }
}

void Gallery::drawParameters(Runner& runner) {
    Parameters& parameters = runner.simulation().parameters;
    if (parameters.empty()) return;
    ImGui::Separator();
    ImGui::TextUnformatted("Parameters (applied when the slider is let go)");
    const std::vector<Parameter>& all = parameters.all();
    if (edits_.size() != all.size() || !ImGui::IsAnyItemActive()) {  // no slider held: show the values in use
        edits_.clear();
        for (const Parameter& p : all) edits_.push_back(p.value);
    }
    std::optional<std::size_t> changed;
    for (std::size_t i = 0; i < all.size(); ++i) {
        const Parameter& p = all[i];
        ImGui::PushID(static_cast<int>(i));
        ImGui::TextUnformatted(p.label.c_str());
        ImGui::SetNextItemWidth(-1.f);
        if (p.integer) {
            int v = static_cast<int>(edits_[i]);
            if (ImGui::SliderInt("##value", &v, static_cast<int>(p.min), static_cast<int>(p.max))) edits_[i] = v;
        } else {
            ImGui::SliderScalar("##value", ImGuiDataType_Double, &edits_[i], &p.min, &p.max, "%.3g");
        }
        itemRects_.emplace_back(p.name, lastItemRect());
        if (ImGui::IsItemDeactivatedAfterEdit()) changed = i;
        ImGui::PopID();
    }
    if (ImGui::Button("Defaults")) {
        runner.setFactory(scenes_[current_].make);  // a fresh scene: its own defaults
        runner.restart();
    } else if (changed) {
        parameters.set(all[*changed].name, edits_[*changed]);
        runner.restart();  // keeps the values of the simulation it replaces
    }
}

void Gallery::drawRunControls(Runner& runner) {
    ImGui::Separator();
    Simulation& sim = runner.simulation();
    ImGui::Checkbox("Paused", &sim.paused);
    ImGui::SameLine();
    if (ImGui::Button("Step")) {
        sim.paused = true;
        runner.requestSingleStep();
    }
    ImGui::SameLine();
    if (ImGui::Button("Restart")) runner.restart();
    ImGui::SameLine();
    if (ImGui::Button("Fit view")) runner.requestFit();
    // The run's record: drag to go back to any moment of it (the run pauses there; Paused off runs on from it).
    const Timeline& timeline = runner.timeline();
    double at = sim.time;
    const double from = timeline.start(), to = std::max(timeline.end(), sim.time);
    ImGui::TextUnformatted("Time (drag to go back)");
    ImGui::SetNextItemWidth(-1.f);
    if (ImGui::SliderScalar("##time", ImGuiDataType_Double, &at, &from, &to, "t = %.2f s") && at != sim.time)
        runner.scrubTo(at);
    itemRects_.emplace_back("time", lastItemRect());
    float scale = static_cast<float>(runner.timeScale());
    ImGui::TextUnformatted("Time scale (simulated s per real s)");
    ImGui::SetNextItemWidth(-1.f);
    if (ImGui::SliderFloat("##timescale", &scale, static_cast<float>(Runner::minTimeScale),
                           static_cast<float>(Runner::maxTimeScale), "%.3gx", ImGuiSliderFlags_Logarithmic))
        runner.setTimeScale(std::clamp<double>(scale, Runner::minTimeScale, Runner::maxTimeScale));
}

// A second future from now with one thing changed (ghosts over the scene), and how far apart the two runs are:
// log10 of the distance (m) against time, live. Chaos shows as a straight rising line.
void Gallery::drawBranch(Runner& runner) {
    ImGui::Separator();
    ImGui::TextUnformatted("Branch (B): a second run with");
    constexpr BranchChange kChanges[] = {BranchChange::Velocity, BranchChange::Restitution, BranchChange::Friction,
                                         BranchChange::Substeps};
    ImGui::SetNextItemWidth(-1.f);
    if (ImGui::BeginCombo("##branchchange", describe(runner.branchChange()))) {
        for (BranchChange c : kChanges)
            if (ImGui::Selectable(describe(c), c == runner.branchChange())) runner.setBranchChange(c);
        ImGui::EndCombo();
    }
    const bool branched = runner.simulation().branch() != nullptr;
    if (ImGui::Button(branched ? "End branch" : "Start branch from now"))
        branched ? runner.endBranch() : runner.startBranch(runner.branchChange());
    itemRects_.emplace_back("branch", lastItemRect());
    const auto& trace = runner.branchTrace();
    if (trace.empty()) return;
    std::vector<float> logs;
    logs.reserve(trace.size());
    for (const auto& [t, d] : trace) logs.push_back(static_cast<float>(std::log10(std::max(d, 1e-16))));
    char caption[96];
    std::snprintf(caption, sizeof caption, "log10 distance (m), t = %.1f to %.1f s", trace.front().first,
                  trace.back().first);
    ImGui::TextUnformatted(caption);
    char now[32];
    std::snprintf(now, sizeof now, "%.3g m now", trace.back().second);
    ImGui::SetNextItemWidth(-1.f);  // the panel's width (ImGui 1.86's plots take no negative size)
    ImGui::PlotLines("##branchdistance", logs.data(), static_cast<int>(logs.size()), 0, now, FLT_MAX, FLT_MAX,
                     ImVec2(0.f, 80.f));
    itemRects_.emplace_back("branch distance", lastItemRect());
}

// Energy bars (World::energyLedger), PhET-style, from the scene's start: kinetic, potential's change, what friction,
// impacts, drag and soft contacts dissipated, the method's residue and the work put in; the last bar, kinetic +
// potential's change + dissipated - residue - work, is the start's kinetic energy while the ledger balances. Each
// bar is drawn from a zero line at the panel's middle, on one scale (the largest bar's, never shrinking within a
// run, so growth is visible).
void Gallery::drawEnergy(sf::RenderWindow& window, Runner& runner) {
    if (!energyBars_) return;
    World& world = runner.simulation().world();
    if (!world.energyLedger().enabled) {
        world.setEnergyLedger(true);
        energyScale_ = 0.0;
    }
    const EnergyLedger& e = world.energyLedger();
    const double dissipated = -(e.total.friction + e.total.impacts + e.total.drag + e.total.soft);
    const double potential = e.potential - e.startPotential;
    struct Bar {
        const char* name;
        double value;
        ImU32 colour;
    };
    const Bar bars[] = {{"kinetic", e.kinetic, IM_COL32(60, 160, 60, 255)},
                        {"potential", potential, IM_COL32(60, 110, 200, 255)},
                        {"dissipated", dissipated, IM_COL32(200, 90, 40, 255)},
                        {"residue", e.total.residue, IM_COL32(150, 150, 150, 255)},
                        {"work in", e.total.work, IM_COL32(170, 60, 170, 255)},
                        {"balance", e.kinetic + potential + dissipated - e.total.residue - e.total.work,
                         IM_COL32(90, 90, 90, 255)}};
    for (const Bar& b : bars) energyScale_ = std::max(energyScale_, std::abs(b.value));
    // A window of its own at the scene's lower right corner, so that it shows on any screen.
    const float boxWidth = 330.f, boxHeight = 6 * 15.f + 40.f;
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(window.getSize().x) - boxWidth - 8.f,
                                   static_cast<float>(window.getSize().y) - boxHeight - 8.f));
    ImGui::SetNextWindowSize(ImVec2(boxWidth, boxHeight));
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("Energy since the start", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollbar);
    const float width = ImGui::GetContentRegionAvail().x, labelWidth = 70.f, rowHeight = 15.f;
    const float barArea = width - labelWidth - 80.f, zero = labelWidth + 0.5f * barArea;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    char text[64];
    for (std::size_t k = 0; k < std::size(bars); ++k) {
        const float y = origin.y + k * rowHeight;
        draw->AddText(ImVec2(origin.x, y), IM_COL32(20, 20, 20, 255), bars[k].name);
        const float length = energyScale_ > 0.0 ? static_cast<float>(bars[k].value / energyScale_) * 0.5f * barArea
                                                : 0.f;
        const float a = origin.x + zero, b = a + length;
        draw->AddRectFilled(ImVec2(std::min(a, b), y + 2.f), ImVec2(std::max(a, b), y + rowHeight - 2.f),
                           bars[k].colour);
        std::snprintf(text, sizeof text, "%.3g J", bars[k].value);
        draw->AddText(ImVec2(origin.x + labelWidth + barArea + 4.f, y), IM_COL32(20, 20, 20, 255), text);
    }
    draw->AddLine(ImVec2(origin.x + zero, origin.y), ImVec2(origin.x + zero, origin.y + std::size(bars) * rowHeight),
                  IM_COL32(0, 0, 0, 255));
    ImGui::Dummy(ImVec2(width, std::size(bars) * rowHeight));
    itemRects_.emplace_back("energy", lastItemRect());
    ImGui::End();
}

// Any quantity of any body, plotted live: click a body in the scene, pick the quantity, and "Plot it".
void Gallery::drawLivePlots(Runner& runner) {
    ImGui::Separator();
    const std::vector<std::string>& quantities = RecordSpec::quantities();
    const std::optional<int> picked = runner.pickedEntity();
    char text[128];
    if (picked) std::snprintf(text, sizeof text, "Plot entity %d's", *picked);
    else std::snprintf(text, sizeof text, "Plot: click a body in the scene first");
    ImGui::TextUnformatted(text);
    ImGui::SetNextItemWidth(170.f);
    if (ImGui::BeginCombo("##quantity", quantities[plotQuantity_].c_str())) {
        for (std::size_t i = 0; i < quantities.size(); ++i)
            if (ImGui::Selectable(quantities[i].c_str(), i == plotQuantity_)) plotQuantity_ = i;
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    if (ImGui::Button("Plot it") && picked) runner.addLivePlot({*picked, quantities[plotQuantity_]});
    itemRects_.emplace_back("plot it", lastItemRect());
    for (std::size_t i = 0; i < runner.livePlots().size(); ++i) {
        const Runner::LivePlot& plot = runner.livePlots()[i];
        ImGui::PushID(static_cast<int>(i));
        const double now = plot.points.empty() ? 0.0 : plot.points.back().second;
        std::snprintf(text, sizeof text, "%s of %d: %.4g %s", plot.spec.quantity.c_str(), plot.spec.entity, now,
                      RecordSpec::unit(plot.spec.quantity));
        ImGui::TextUnformatted(text);
        ImGui::SameLine();
        const bool remove = ImGui::SmallButton("x");
        std::vector<float> values;
        values.reserve(plot.points.size());
        for (const auto& [t, v] : plot.points) values.push_back(static_cast<float>(v));
        ImGui::SetNextItemWidth(-1.f);
        ImGui::PlotLines("##live", values.data(), static_cast<int>(values.size()), 0, nullptr, FLT_MAX, FLT_MAX,
                         ImVec2(0.f, 60.f));
        ImGui::PopID();
        if (remove) {
            runner.removeLivePlot(i);
            break;
        }
    }
}

void Gallery::drawDebugSwitches(Runner& runner) {
    ImGui::Separator();
    ImGui::TextUnformatted("Debug drawing");
    DebugDrawOptions& d = runner.simulation().debugDraw;
    ImGui::Checkbox("Contacts", &d.contacts);
    ImGui::SameLine(150.f);
    ImGui::Checkbox("Bounding boxes", &d.boxes);
    ImGui::Checkbox("Velocities", &d.velocities);
    ImGui::SameLine(150.f);
    ImGui::Checkbox("Joints", &d.joints);
    ImGui::Checkbox("Centres of mass", &d.centres);
    ImGui::SameLine(150.f);
    ImGui::Checkbox("Sleep (dimmed)", &d.sleep);
    ImGui::Checkbox("Rays", &d.rays);
    bool stats = runner.statsShown();
    if (ImGui::Checkbox("Statistics", &stats)) runner.setStatsShown(stats);
    ImGui::SameLine(150.f);
    ImGui::Checkbox("Energy bars", &energyBars_);
    itemRects_.emplace_back("energy bars", lastItemRect());
}

}  // namespace physim::examples
