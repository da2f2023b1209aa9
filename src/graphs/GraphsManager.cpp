#include "physim/graphs/GraphsManager.hpp"

#include <TAxis.h>
#include <TCanvas.h>
#include <TError.h>
#include <TFile.h>
#include <TGraph.h>
#include <TROOT.h>
#include <TSystem.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <stdexcept>

namespace physim {

struct GraphsManager::Graph {
    std::string title;
    graph_modifier modifier;
    GraphMode mode = GraphMode::DEFAULT;
    int pad = 0;  // pads are numbered in addGraph order; addSeries shares its graph's pad
    std::vector<std::pair<double, double>> points;
    std::size_t skipped = 0;
};

// ROOT objects. The canvas is deleted before the graphs it shows; the pads do not own the graphs.
struct GraphsManager::Root {
    std::vector<std::unique_ptr<TGraph>> graphs;
    std::unique_ptr<TCanvas> canvas;  // live window; null headless
    std::vector<bool> padDrawn;       // live: a pad is drawn once it has points (ROOT rejects empty graphs)
    std::chrono::steady_clock::time_point lastRefresh{};

    ~Root() { canvas.reset(); }
};

namespace {

const char* drawOption(GraphMode mode, bool first) {
    if (mode == GraphMode::WITH_LINES) return first ? "APL" : "PL";
    return first ? "AP" : "P";
}

// Pads in a grid close to the canvas's aspect ratio.
std::pair<int, int> padGrid(int n) {
    const int cols = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
    const int rows = (n + cols - 1) / cols;
    return {cols, rows};
}

std::unique_ptr<TCanvas> makeCanvas(const void* owner, const char* purpose, int x, int y, int w, int h, int pads) {
    char name[96];  // unique per manager and purpose: ROOT finds (and replaces) canvases by name
    std::snprintf(name, sizeof name, "physim_graphs_%s_%p", purpose, owner);
    auto canvas = std::make_unique<TCanvas>(name, "physim graphs", x, y, w, h);
    const auto [cols, rows] = padGrid(pads);
    if (pads > 1) canvas->Divide(cols, rows);
    for (int p = 0; p < pads; ++p) {
        canvas->cd(p + 1);
        gPad->SetGrid();
    }
    return canvas;
}

}  // namespace

// Draws pad `pad` of `canvas`: the first graph with axes, the others over it, with a legend when there are
// several. Once per canvas: drawing again would add the graphs to the pad twice.
void GraphsManager::drawPad(TCanvas& canvas, int pad) const {
    canvas.cd(pad + 1);
    int series = 0;
    for (std::size_t i = 0; i < graphs_.size(); ++i) {
        if (graphs_[i].pad != pad) continue;
        root_->graphs[i]->Draw(drawOption(graphs_[i].mode, series == 0));
        ++series;
    }
    if (series > 1) {
        gPad->BuildLegend(0.65, 0.75, 0.95, 0.92);  // the pad owns the legend
        // The first graph (the simulated points, usually) again on top of the series drawn after it.
        for (std::size_t i = 0; i < graphs_.size(); ++i)
            if (graphs_[i].pad == pad) {
                root_->graphs[i]->Draw(drawOption(graphs_[i].mode, false));
                break;
            }
    }
    fitAxes(pad);
}

// The axes span every series on the pad (ROOT sizes them to the first graph alone).
void GraphsManager::fitAxes(int pad) const {
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    TGraph* first = nullptr;
    for (std::size_t i = 0; i < graphs_.size(); ++i) {
        if (graphs_[i].pad != pad) continue;
        if (!first) first = root_->graphs[i].get();
        for (const auto& [x, y] : graphs_[i].points) {
            xmin = std::min(xmin, x), xmax = std::max(xmax, x);
            ymin = std::min(ymin, y), ymax = std::max(ymax, y);
        }
    }
    if (!first || xmin > xmax) return;
    const double mx = 0.05 * std::max(xmax - xmin, 1e-9), my = 0.05 * std::max(ymax - ymin, 1e-9);
    first->GetXaxis()->SetLimits(xmin - mx, xmax + mx);
    first->SetMinimum(ymin - my);
    first->SetMaximum(ymax + my);
    if (gPad) gPad->Modified();
}

bool GraphsManager::padHasPoints(int pad) const {
    for (const Graph& g : graphs_)
        if (g.pad == pad && !g.points.empty()) return true;
    return false;
}

GraphsManager::GraphsManager() = default;
GraphsManager::~GraphsManager() = default;

void GraphsManager::setCanvasSize(int width, int height) {
    if (width <= 0 || height <= 0)
        throw std::invalid_argument("physim: canvas size must be positive, got " + std::to_string(width) + " x " +
                                    std::to_string(height));
    width_ = width;
    height_ = height;
    if (root_ && root_->canvas) root_->canvas->SetCanvasSize(width, height);
}

void GraphsManager::setCanvasPosition(int x, int y) {
    x_ = x;
    y_ = y;
    if (root_ && root_->canvas) root_->canvas->SetWindowPosition(x, y);
}

void GraphsManager::setLive(bool live, double refreshHz) {
    if (built_) throw std::logic_error("physim: GraphsManager::setLive must be called before build()");
    if (!(refreshHz > 0.0 && std::isfinite(refreshHz)))
        throw std::invalid_argument("physim: graph refresh rate must be > 0 Hz, got " + std::to_string(refreshHz));
    live_ = live;
    refreshHz_ = refreshHz;
}

int GraphsManager::addGraph(const std::string& title, graph_modifier modifier, GraphMode mode) {
    if (built_) throw std::logic_error("physim: addGraph(\"" + title + "\") after build()");
    graphs_.push_back(Graph{title, std::move(modifier), mode, padCount_++, {}, 0});
    return static_cast<int>(graphs_.size()) - 1;
}

int GraphsManager::addSeries(int onGraph, const std::string& label, graph_modifier modifier, GraphMode mode) {
    if (built_) throw std::logic_error("physim: addSeries(\"" + label + "\") after build()");
    const int pad = graph(onGraph).pad;
    graphs_.push_back(Graph{label, std::move(modifier), mode, pad, {}, 0});
    return static_cast<int>(graphs_.size()) - 1;
}

void GraphsManager::build() {
    if (built_) throw std::logic_error("physim: GraphsManager::build() called twice");
    built_ = true;
    if (graphs_.empty()) return;
    if (!live_) gROOT->SetBatch(kTRUE);  // no window, no display needed
    root_ = std::make_unique<Root>();
    static const Color_t seriesColors[] = {kBlack, kRed + 1, kBlue + 1, kGreen + 2, kMagenta + 1, kOrange + 7};
    std::vector<int> seriesOnPad(static_cast<std::size_t>(padCount_), 0);
    for (const Graph& g : graphs_) {
        auto tg = std::make_unique<TGraph>();
        tg->SetTitle(g.title.c_str());
        tg->SetMarkerStyle(20);
        tg->SetMarkerSize(0.5);
        const Color_t color = seriesColors[seriesOnPad[static_cast<std::size_t>(g.pad)]++ % 6];
        tg->SetMarkerColor(color);
        tg->SetLineColor(color);
        if (g.modifier) g.modifier(tg.get());
        root_->graphs.push_back(std::move(tg));
    }
    if (live_) {
        root_->canvas = makeCanvas(this, "live", x_, y_, width_, height_, padCount_);
        root_->padDrawn.assign(static_cast<std::size_t>(padCount_), false);
    }
}

const GraphsManager::Graph& GraphsManager::graph(int i) const {
    if (i < 0 || static_cast<std::size_t>(i) >= graphs_.size())
        throw std::out_of_range("physim: graph index " + std::to_string(i) + " is not in [0, " +
                                std::to_string(graphs_.size()) + ")");
    return graphs_[static_cast<std::size_t>(i)];
}

void GraphsManager::addPoint(int i, double x, double y) {
    if (!built_) throw std::logic_error("physim: addPoint before GraphsManager::build()");
    Graph& g = const_cast<Graph&>(graph(i));
    if (!std::isfinite(x) || !std::isfinite(y)) {
        if (g.skipped++ == 0)  // once per graph: a NaN every frame must not flood the terminal
            std::cerr << "physim: graph " << i << " (\"" << g.title << "\"): skipping a non-finite point (" << x
                      << ", " << y << "); skippedPoints(" << i << ") counts them\n";
        return;
    }
    g.points.emplace_back(x, y);
    TGraph& tg = *root_->graphs[static_cast<std::size_t>(i)];
    tg.SetPoint(tg.GetN(), x, y);
}

void GraphsManager::render() {
    if (!live_ || !root_ || !root_->canvas) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - root_->lastRefresh < std::chrono::duration<double>(1.0 / refreshHz_)) return;
    root_->lastRefresh = now;
    for (int p = 0; p < padCount_; ++p) {
        if (!padHasPoints(p)) continue;
        if (root_->padDrawn[static_cast<std::size_t>(p)]) {
            root_->canvas->cd(p + 1);
            fitAxes(p);  // to the points so far
        } else {
            drawPad(*root_->canvas, p);
            root_->padDrawn[static_cast<std::size_t>(p)] = true;
        }
    }
    root_->canvas->Update();
    gSystem->ProcessEvents();
}

void GraphsManager::reset() {
    for (Graph& g : graphs_) {
        g.points.clear();
        g.skipped = 0;
    }
    if (root_)
        for (auto& tg : root_->graphs) tg->Set(0);
}

void GraphsManager::setPoints(int i, const std::vector<std::pair<double, double>>& points) {
    if (!built_) throw std::logic_error("physim: setPoints before GraphsManager::build()");
    Graph& g = const_cast<Graph&>(graph(i));
    g.points.clear();
    g.skipped = 0;
    root_->graphs[static_cast<std::size_t>(i)]->Set(0);
    for (const auto& [x, y] : points) addPoint(i, x, y);
}

std::size_t GraphsManager::graphCount() const { return graphs_.size(); }
const std::string& GraphsManager::title(int i) const { return graph(i).title; }
const std::vector<std::pair<double, double>>& GraphsManager::points(int i) const { return graph(i).points; }
std::size_t GraphsManager::skippedPoints(int i) const { return graph(i).skipped; }

std::vector<std::string> GraphsManager::writeFiles(const std::string& directory) const {
    namespace fs = std::filesystem;
    fs::create_directories(directory);
    std::vector<std::string> written;
    for (std::size_t i = 0; i < graphs_.size(); ++i) {
        const fs::path path = fs::path(directory) / ("graph_" + std::to_string(i) + ".csv");
        std::ofstream out(path);
        if (!out) throw std::runtime_error("physim: cannot write " + path.string());
        out << "# " << graphs_[i].title << "\n" << "x,y\n" << std::setprecision(17);
        for (const auto& [x, y] : graphs_[i].points) out << x << ',' << y << '\n';
        written.push_back(path.string());
    }
    if (root_ && !root_->graphs.empty()) {
        const bool wasBatch = gROOT->IsBatch();
        gROOT->SetBatch(kTRUE);
        // A separate batch canvas, so a live window is left as it is.
        auto canvas = makeCanvas(this, "export", 0, 0, width_, height_, padCount_);
        for (int p = 0; p < padCount_; ++p)
            if (padHasPoints(p)) drawPad(*canvas, p);
        const fs::path png = fs::path(directory) / "graphs.png";
        const Int_t ignoreLevel = gErrorIgnoreLevel;
        gErrorIgnoreLevel = kWarning;  // no "file has been created" line on every run
        canvas->SaveAs(png.string().c_str());
        gErrorIgnoreLevel = ignoreLevel;
        canvas.reset();
        gROOT->SetBatch(wasBatch);
        written.push_back(png.string());

        // Every graph in one ROOT file, named graph_<i>, for analysis in ROOT itself.
        const fs::path rootFile = fs::path(directory) / "graphs.root";
        TFile file(rootFile.string().c_str(), "RECREATE");
        if (file.IsZombie()) throw std::runtime_error("physim: cannot write " + rootFile.string());
        for (std::size_t i = 0; i < root_->graphs.size(); ++i)
            root_->graphs[i]->Write(("graph_" + std::to_string(i)).c_str());
        file.Close();
        written.push_back(rootFile.string());
    }
    return written;
}

}  // namespace physim
