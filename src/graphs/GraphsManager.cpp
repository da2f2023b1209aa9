#include "physim/graphs/GraphsManager.hpp"

#include "PadPlot.hpp"
#include "PlotLayout.hpp"
#include "RootApplication.hpp"

#include <Buttons.h>
#include <TCanvas.h>
#include <TCanvasImp.h>
#include <TError.h>
#include <TFile.h>
#include <TGraph.h>
#include <TMemFile.h>
#include <TROOT.h>
#include <TSystem.h>
#include <TVirtualX.h>

#include <unistd.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <stdexcept>
#include <thread>

namespace physim {

graph_modifier lineInColour(int colour) {
    return [colour](TGraph* g) {
        g->SetLineColor(static_cast<Color_t>(colour));
        g->SetMarkerColor(static_cast<Color_t>(colour));
        g->SetMarkerStyle(1);
        g->SetLineWidth(2);
    };
}


struct GraphsManager::Graph {
    std::string label;
    graph_modifier modifier;
    GraphMode mode = GraphMode::DEFAULT;
    int pad = 0;  // pads are numbered in addGraph order; addSeries shares its graph's pad
    std::vector<std::pair<double, double>> points;
    std::size_t skipped = 0;
};

// ROOT objects. The canvas goes before the pads' objects it shows (the destructor's body runs first).
struct GraphsManager::Root {
    std::vector<std::unique_ptr<TGraph>> styles;  // one per series: its style (defaults, then the modifier)
    std::unique_ptr<TCanvas> canvas;              // the live window; null headless or once the user closed it
    std::vector<std::unique_ptr<PadPlot>> pads;   // the live canvas's pads
    std::chrono::steady_clock::time_point nextRefresh{};
    mutable std::thread warmup;  // prepareExport's: joined before ROOT is used again here

    void waitForWarmup() const {
        if (warmup.joinable()) warmup.join();
    }
    ~Root() {
        waitForWarmup();
        if (canvas) {
            canvas.reset();
            gSystem->ProcessEvents();  // the window goes now, not at the next event (a restart makes a new one)
        }
    }
};

namespace {

// Defaults, before the user's modifier: markers in strong colours and polygon shapes (ROOT's image export draws
// circles point by point, about 1 ms each); curves as wide pale lines that the markers sit on.
struct MarkerStyle {
    Color_t color;
    Style_t marker;
    Size_t size;
};
constexpr MarkerStyle kMarkerStyles[] = {{kBlue + 1, 21, 1.0f},     {kRed + 1, 33, 1.5f},    {kGreen + 3, 22, 1.2f},
                                         {kMagenta + 2, 23, 1.2f}, {kOrange + 7, 34, 1.2f}, {kCyan + 3, 29, 1.5f},
                                         {kBlack, 47, 1.2f}};
struct LineStyle {
    Color_t color;
    Style_t style;
    Width_t width;
};
constexpr LineStyle kCurveStyles[] = {{kOrange - 3, 1, 3}, {kGray + 1, 2, 3}, {kAzure - 4, 1, 3},
                                      {kPink - 4, 7, 3},   {kSpring - 5, 1, 3}};

std::unique_ptr<TCanvas> makeCanvas(const void* owner, const char* purpose, const std::string& title, int x, int y,
                                    int w, int h, int pads) {
    char name[96];  // unique per manager and purpose: ROOT finds (and replaces) canvases by name
    std::snprintf(name, sizeof name, "physim_graphs_%s_%p", purpose, owner);
    auto canvas = std::make_unique<TCanvas>(name, title.c_str(), x, y, w, h);
    const auto [cols, rows] = plot::padGrid(pads, w, h);
    if (pads > 1) canvas->Divide(cols, rows, 0.005f, 0.005f);
    return canvas;
}

// ROOT's one-time work for an export, on throwaway objects: a pad with every kind of series, legend and title,
// saved as PNG (painter and image plugins, fonts), and a graph written to a file in memory (streamer infos,
// compression). Failures are left to the real export to report. Names are the manager's own: ROOT replaces a
// canvas of the same name.
void warmUpExport(const void* owner) {
    try {
        ROOT::EnableThreadSafety();  // ROOT's own locks, should the simulation call ROOT meanwhile
        gROOT->SetBatch(kTRUE);
        const Int_t ignoreLevel = gErrorIgnoreLevel;
        gErrorIgnoreLevel = kWarning;
        {
            char name[96];
            std::snprintf(name, sizeof name, "physim_graphs_warmup_%p", owner);
            TCanvas canvas(name, "", 240, 180);
            TGraph markers, curve;
            markers.SetMarkerStyle(21);
            const std::vector<plot::Point> a{{0, 1}, {1, 1.0000001}, {2, 1}}, b{{0, 0}, {1, 1}, {2, 4}};
            PadPlot pad;
            pad.draw(canvas, "t;x (s);y (m)",
                     {{&a, GraphMode::WITH_LINES, &markers, "a"}, {&b, GraphMode::CURVE, &curve, "b"}}, false);
            const std::string png = (std::filesystem::temp_directory_path() /
                                     (std::string(name) + "_" + std::to_string(::getpid()) + ".png"))
                                        .string();
            canvas.SaveAs(png.c_str());
            std::error_code ec;
            std::filesystem::remove(png, ec);
        }
        TMemFile file("physim-warmup.root", "RECREATE");
        TGraph g(2);
        g.SetTitle("t: a;x;y");
        g.Write("g");
        file.Close();
        gErrorIgnoreLevel = ignoreLevel;
    } catch (...) {
    }
}

// "x,y\n" with the shortest decimal form that reads back as the same doubles (exact, and several times faster
// than an ostream at 17 digits).
void appendRow(std::string& out, double x, double y) {
    char buf[64];
    char* end = std::to_chars(buf, buf + 30, x).ptr;
    *end++ = ',';
    end = std::to_chars(end, buf + 62, y).ptr;
    *end++ = '\n';
    out.append(buf, end);
}

// A refresh waits at least this many times as long as the last one took.
constexpr int kBusyFactor = 5;

// One line on stderr per process: a program restarting its simulation must not repeat it.
void warnNoDisplayOnce() {
    static const bool warned = [] {
        std::cerr << "physim: no display for the live graphs window; the graphs are kept for --out only\n";
        return true;
    }();
    (void)warned;
}

}  // namespace

GraphsManager::GraphsManager() = default;
GraphsManager::~GraphsManager() = default;

void GraphsManager::setCanvasSize(int width, int height) {
    if (width <= 0 || height <= 0 || width > 1 << 15 || height > 1 << 15)
        throw std::invalid_argument("physim: canvas size must be in [1, 32768] pixels, got " + std::to_string(width) +
                                    " x " + std::to_string(height));
    width_ = width;
    height_ = height;
    if (root_ && root_->canvas) root_->canvas->SetWindowSize(static_cast<UInt_t>(width), static_cast<UInt_t>(height));
}

void GraphsManager::setCanvasPosition(int x, int y) {
    x_ = x;
    y_ = y;
    if (root_ && root_->canvas) root_->canvas->SetWindowPosition(x, y);
}

void GraphsManager::setCanvasTitle(const std::string& title) {
    canvasTitle_ = title;
    if (root_ && root_->canvas) root_->canvas->SetTitle(title.c_str());
}

void GraphsManager::setLive(bool live, double refreshHz) {
    if (built_) throw std::logic_error("physim: GraphsManager::setLive must be called before build()");
    if (!(refreshHz > 0.0 && std::isfinite(refreshHz)))
        throw std::invalid_argument("physim: graph refresh rate must be > 0 Hz, got " + std::to_string(refreshHz));
    live_ = live;
    refreshHz_ = refreshHz;
}

bool GraphsManager::canvasOpen() const { return root_ && root_->canvas; }

int GraphsManager::addGraph(const std::string& title, graph_modifier modifier, GraphMode mode) {
    return addGraph(title, kDefaultLabel, std::move(modifier), mode);
}

int GraphsManager::addGraph(const std::string& title, const std::string& label, graph_modifier modifier,
                            GraphMode mode) {
    if (built_) throw std::logic_error("physim: addGraph(\"" + title + "\") after build()");
    padTitles_.push_back(title);
    graphs_.push_back(Graph{label, std::move(modifier), mode, static_cast<int>(padTitles_.size()) - 1, {}, 0});
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
    if (live_ && !ensureRootApplication()) {
        warnNoDisplayOnce();
        live_ = false;
    }
    root_ = std::make_unique<Root>();
    std::vector<int> markersOnPad(padTitles_.size(), 0), curvesOnPad(padTitles_.size(), 0);
    for (const Graph& g : graphs_) {
        auto tg = std::make_unique<TGraph>();
        tg->SetTitle(padTitles_[static_cast<std::size_t>(g.pad)].c_str());
        if (g.mode == GraphMode::CURVE) {
            const LineStyle& s = kCurveStyles[curvesOnPad[static_cast<std::size_t>(g.pad)]++ % std::size(kCurveStyles)];
            tg->SetLineColor(s.color);
            tg->SetLineStyle(s.style);
            tg->SetLineWidth(s.width);
            tg->SetMarkerStyle(1);
        } else {
            const MarkerStyle& s =
                kMarkerStyles[markersOnPad[static_cast<std::size_t>(g.pad)]++ % std::size(kMarkerStyles)];
            tg->SetMarkerColor(s.color);
            tg->SetMarkerStyle(s.marker);
            tg->SetMarkerSize(s.size);
            tg->SetLineColor(s.color);
            tg->SetLineWidth(1);
        }
        if (g.modifier) g.modifier(tg.get());
        root_->styles.push_back(std::move(tg));
    }
    if (live_) {
        const int pads = static_cast<int>(padTitles_.size());
        root_->canvas = makeCanvas(this, "live", canvasTitle_, x_, y_, width_, height_, pads);
        root_->canvas->ToggleEventStatus();  // a status bar: the value under the mouse, as ROOT shows it
        root_->pads.resize(padTitles_.size());
        drawPads(*root_->canvas, true, root_->pads);  // titled, empty pads from the first frame
        root_->canvas->Update();
    }
}

const GraphsManager::Graph& GraphsManager::graph(int i) const {
    if (i < 0 || static_cast<std::size_t>(i) >= graphs_.size())
        throw std::out_of_range("physim: graph index " + std::to_string(i) + " is not in [0, " +
                                std::to_string(graphs_.size()) + ")");
    return graphs_[static_cast<std::size_t>(i)];
}

GraphsManager::Graph& GraphsManager::graph(int i) {
    return const_cast<Graph&>(static_cast<const GraphsManager&>(*this).graph(i));
}

void GraphsManager::addPoint(int i, double x, double y) {
    if (!built_) throw std::logic_error("physim: addPoint before GraphsManager::build()");
    Graph& g = graph(i);
    if (!std::isfinite(x) || !std::isfinite(y)) {
        if (g.skipped++ == 0)  // once per graph: a NaN every frame must not flood the terminal
            std::cerr << "physim: graph " << i << " (\"" << g.label << "\"): skipping a non-finite point (" << x
                      << ", " << y << "); skippedPoints(" << i << ") counts them\n";
        return;
    }
    g.points.emplace_back(x, y);
}

void GraphsManager::drawPads(TCanvas& canvas, bool live, std::vector<std::unique_ptr<PadPlot>>& pads) const {
    for (std::size_t p = 0; p < padTitles_.size(); ++p) {
        std::vector<PadSeries> series;
        for (std::size_t i = 0; i < graphs_.size(); ++i)
            if (graphs_[i].pad == static_cast<int>(p))
                series.push_back({&graphs_[i].points, graphs_[i].mode, root_->styles[i].get(), graphs_[i].label});
        TVirtualPad* pad = padTitles_.size() > 1 ? canvas.cd(static_cast<int>(p) + 1) : canvas.cd();
        if (!pad) continue;
        if (!pads[p]) pads[p] = std::make_unique<PadPlot>();
        pads[p]->draw(*pad, padTitles_[p], series, live);
    }
}

void GraphsManager::render() {
    if (!live_ || !root_ || !root_->canvas) return;  // (live: no warm-up thread)
    // Every frame: ROOT's own interaction (zoom an axis, the value under the mouse, closing) stays responsive.
    gSystem->ProcessEvents();
    if (!root_->canvas->GetCanvasImp()) {
        // The user closed the window. ROOT has cleared the canvas; the simulation and the data go on.
        root_->canvas.reset();
        root_->pads.clear();
        std::cerr << "physim: graphs window closed; the simulation goes on (--out still writes the graphs)\n";
        return;
    }
    // Not while a mouse button is held in the window: redrawing mid-drag would undo the zoom being drawn.
    switch (root_->canvas->GetEvent()) {
        case kButton1Down: case kButton2Down: case kButton3Down:
        case kButton1Motion: case kButton2Motion: case kButton3Motion: return;
        default: break;
    }
    using Clock = std::chrono::steady_clock;
    const auto now = Clock::now();
    if (now < root_->nextRefresh) return;
    drawPads(*root_->canvas, true, root_->pads);
    root_->canvas->Modified();
    root_->canvas->Update();
    // At most refreshHz times a second, and at most a fifth of the time: on a slow machine (or X server) the
    // graphs refresh less often rather than slow the simulation's frames.
    const auto took = Clock::now() - now;
    root_->nextRefresh = now + std::max(std::chrono::duration_cast<Clock::duration>(
                                            std::chrono::duration<double>(1.0 / refreshHz_)),
                                        kBusyFactor * took);
}

void GraphsManager::reset() {
    for (Graph& g : graphs_) {
        g.points.clear();
        g.skipped = 0;
    }
}

void GraphsManager::setPoints(int i, const std::vector<std::pair<double, double>>& points) {
    if (!built_) throw std::logic_error("physim: setPoints before GraphsManager::build()");
    Graph& g = graph(i);
    g.points.clear();
    g.skipped = 0;
    for (const auto& [x, y] : points) addPoint(i, x, y);
}

std::size_t GraphsManager::graphCount() const { return graphs_.size(); }
const std::string& GraphsManager::title(int i) const { return padTitles_[static_cast<std::size_t>(graph(i).pad)]; }
const std::string& GraphsManager::label(int i) const { return graph(i).label; }
const std::vector<std::pair<double, double>>& GraphsManager::points(int i) const { return graph(i).points; }
std::size_t GraphsManager::skippedPoints(int i) const { return graph(i).skipped; }

void GraphsManager::prepareExport() {
    if (live_ || !root_ || root_->warmup.joinable()) return;
    root_->warmup = std::thread(warmUpExport, static_cast<const void*>(this));
}

std::vector<std::string> GraphsManager::writeFiles(const std::string& directory) const {
    namespace fs = std::filesystem;
    fs::create_directories(directory);
    // Files of an earlier run (more graphs, or graphs where this run has none) would read as this run's.
    static const std::regex ours(R"(graph_[0-9]+\.csv|graphs\.png|graphs\.root)");
    for (const auto& entry : fs::directory_iterator(directory))
        if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), ours))
            fs::remove(entry.path());

    std::vector<std::string> written;
    for (std::size_t i = 0; i < graphs_.size(); ++i) {
        const fs::path path = fs::path(directory) / ("graph_" + std::to_string(i) + ".csv");
        std::string text = "# " + padTitles_[static_cast<std::size_t>(graphs_[i].pad)] + "\n# series: " +
                           graphs_[i].label + "\nx,y\n";
        text.reserve(text.size() + 40 * graphs_[i].points.size());
        for (const auto& [x, y] : graphs_[i].points) appendRow(text, x, y);
        std::ofstream out(path, std::ios::binary);
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        if (!out) throw std::runtime_error("physim: cannot write " + path.string());
        written.push_back(path.string());
    }
    if (!root_) return written;

    root_->waitForWarmup();  // the CSV files above needed no ROOT: written while it finished starting
    // A canvas of its own, off screen, so a live window is left as it is. With an application object ROOT
    // draws through X11 (gVirtualX): batch mode alone is not enough, its batch drawing interface goes in too.
    const bool wasBatch = gROOT->IsBatch();
    TVirtualX* const screen = gVirtualX;
    gROOT->SetBatch(kTRUE);
    if (gGXBatch) gVirtualX = gGXBatch;
    {
        auto canvas = makeCanvas(this, "export", canvasTitle_, 0, 0, width_, height_,
                                 static_cast<int>(padTitles_.size()));
        std::vector<std::unique_ptr<PadPlot>> pads(padTitles_.size());
        drawPads(*canvas, false, pads);
        const fs::path png = fs::path(directory) / "graphs.png";
        const Int_t ignoreLevel = gErrorIgnoreLevel;
        gErrorIgnoreLevel = kWarning;  // no "file has been created" line on every run
        canvas->SaveAs(png.string().c_str());
        gErrorIgnoreLevel = ignoreLevel;
        canvas.reset();  // before the pads' objects
        written.push_back(png.string());
    }
    gVirtualX = screen;
    gROOT->SetBatch(wasBatch);

    // Every series, every point, in one ROOT file (graph_<i>), titled "title: label;x label;y label".
    const fs::path rootFile = fs::path(directory) / "graphs.root";
    TFile file(rootFile.string().c_str(), "RECREATE");
    if (file.IsZombie()) throw std::runtime_error("physim: cannot write " + rootFile.string());
    for (std::size_t i = 0; i < graphs_.size(); ++i) {
        const auto& pts = graphs_[i].points;
        TGraph g(static_cast<int>(pts.size()));
        for (std::size_t k = 0; k < pts.size(); ++k) g.SetPoint(static_cast<int>(k), pts[k].first, pts[k].second);
        const TGraph& style = *root_->styles[i];
        style.TAttLine::Copy(g);
        style.TAttMarker::Copy(g);
        style.TAttFill::Copy(g);
        std::string title = padTitles_[static_cast<std::size_t>(graphs_[i].pad)];
        const auto semicolon = title.find(';');
        title.insert(semicolon == std::string::npos ? title.size() : semicolon, ": " + graphs_[i].label);
        g.SetTitle(title.c_str());
        g.Write(("graph_" + std::to_string(i)).c_str());
    }
    file.Close();
    written.push_back(rootFile.string());
    return written;
}

}  // namespace physim
