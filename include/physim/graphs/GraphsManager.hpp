#pragma once
// The paper's GraphsManager (section 6): named graphs of (x, y) points, drawn with CERN ROOT on pads of one
// canvas. ROOT stays out of this header (TGraph is only forward-declared), so including it costs nothing.
//
// Use: addGraph(...) for each pad's simulated data, addSeries(...) for what is drawn with it (an analytic
// answer, say), build(), then addPoint(i, x, y) as the simulation runs. Live (a window session) render() shows
// the pads in their own ROOT window and refreshes it; writeFiles(dir) saves CSV, PNG and a .root file.
//
// How a pad is drawn: markers (DEFAULT, WITH_LINES) over smooth lines (CURVE), every series named in a legend
// placed where it covers no data; margins fitted to the tick labels; a pad whose values all lie within 0.1% of
// the start shown as the relative change from the start; long series thinned for drawing only (every point
// stays in the CSV and .root files).

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

class TCanvas;
class TGraph;

namespace physim {

class PadPlot;  // one pad's ROOT drawing (src/graphs)

enum class GraphMode {
    DEFAULT,     ///< markers: simulated or measured data
    WITH_LINES,  ///< markers on a line through every point: densely sampled simulated data
    CURVE,       ///< a line without markers, drawn under the markers: an analytic answer, a reference value
};

/// Styles a graph after it is created (colours, markers, axis titles), as in the paper.
using graph_modifier = std::function<void(TGraph*)>;

/// A modifier for a line without markers, width 2, in ROOT colour index `colour` (600 blue, 632 red, 416 green,
/// 616 magenta, 800 orange, 920 grey; plus 1 or 2 for darker shades), for code that does not include ROOT.
graph_modifier lineInColour(int colour);

class GraphsManager {
public:
    GraphsManager();
    ~GraphsManager();
    GraphsManager(const GraphsManager&) = delete;
    GraphsManager& operator=(const GraphsManager&) = delete;

    /// Canvas size and screen position in pixels. Accepts sf::Vector2i or anything with .x and .y.
    void setCanvasSize(int width, int height);
    void setCanvasPosition(int x, int y);
    template <class V>
    void setCanvasSize(const V& size) { setCanvasSize(static_cast<int>(size.x), static_cast<int>(size.y)); }
    template <class V>
    void setCanvasPosition(const V& pos) { setCanvasPosition(static_cast<int>(pos.x), static_cast<int>(pos.y)); }

    /// The legend label of a graph added without one.
    static constexpr const char* kDefaultLabel = "simulated";

    /// Adds a graph (a pad of its own) before build(). Axis labels (with units) go in the title as
    /// "title;x label;y label", ROOT's convention; `label` names its points in the legend. The modifier styles
    /// the ROOT graph after physim's defaults (colours, markers, widths). Returns its index for addPoint.
    /// Throws std::logic_error after build().
    int addGraph(const std::string& title, graph_modifier modifier = {}, GraphMode mode = GraphMode::DEFAULT);
    int addGraph(const std::string& title, const std::string& label, graph_modifier modifier = {},
                 GraphMode mode = GraphMode::DEFAULT);
    /// Adds a series drawn on the same pad as graph `onGraph`, named `label` in the legend: by default a curve
    /// (an analytic answer) under the pad's markers. Returns its index for addPoint. Before build() only.
    int addSeries(int onGraph, const std::string& label, graph_modifier modifier = {},
                  GraphMode mode = GraphMode::CURVE);
    /// Creates one ROOT graph per addGraph/addSeries call (each its own object) laid out on pads of one canvas.
    void build();
    /// Appends a point to graph `i` (0-based, in addGraph/addSeries order). Non-finite points are skipped, counted
    /// and warned about on stderr (once per graph).
    /// Throws std::out_of_range for an unknown index, std::logic_error before build().
    void addPoint(int i, double x, double y);
    /// Live mode: lets ROOT handle the window's events (zoom, the value under the mouse, closing), and redraws
    /// the pads at most `refreshHz` times a second and at most a fifth of the time (a slow refresh waits
    /// longer), never while a mouse button is held in the window. Headless: does nothing.
    void render();
    /// Removes every point from every graph; the graphs stay.
    void reset();
    /// Replaces graph `i`'s points (a histogram recomputed each frame, say). Non-finite points are skipped and
    /// counted as in addPoint.
    void setPoints(int i, const std::vector<std::pair<double, double>>& points);

    /// Live mode opens the canvas as its own window at build() (making ROOT's application object if the program
    /// has none) and render() refreshes it; call before build(). Default: off (headless). With no display to
    /// open a window on, live mode says so once on stderr and stays headless.
    void setLive(bool live, double refreshHz = 10.0);
    /// The live window's title (default "physim graphs").
    void setCanvasTitle(const std::string& title);
    /// True while the live window is open: false headless, and once the user has closed it (the graphs still
    /// collect points and writeFiles still writes them).
    bool canvasOpen() const;
    bool built() const { return built_; }
    std::size_t graphCount() const;
    /// The title of graph i's pad ("title;x label;y label"); a series shares its graph's.
    const std::string& title(int i) const;
    /// Graph i's legend label.
    const std::string& label(int i) const;
    const std::vector<std::pair<double, double>>& points(int i) const;
    std::size_t skippedPoints(int i) const;

    /// Writes `graph_<i>.csv` for each graph (two comment lines, the pad's title and the series' label, then an
    /// "x,y" header and every point), graphs.png with every pad, and graphs.root holding each series as a TGraph
    /// named `graph_<i>`. Files of these names from an earlier run are removed first. Creates `directory`.
    /// Returns the paths written.
    std::vector<std::string> writeFiles(const std::string& directory) const;

    /// Headless, after build(), in a run that will end with writeFiles: starts ROOT's one-time work (its
    /// interpreter, painters, image and file formats: most of a first export's cost) on a second thread while
    /// the simulation runs, so the export at the end costs little more than its own drawing and writing.
    /// Meanwhile the manager does not use ROOT (points go to plain vectors) and writeFiles, render and the
    /// destructor wait for the thread; a simulation that calls ROOT itself during the run should not ask for
    /// this. Does nothing live, before build() or without graphs.
    void prepareExport();

private:
    struct Graph;
    struct Root;  // ROOT objects (style graphs, live canvas and its pads): only in the .cpp

    const Graph& graph(int i) const;
    Graph& graph(int i);
    void drawPads(TCanvas& canvas, bool live, std::vector<std::unique_ptr<PadPlot>>& pads) const;

    std::vector<Graph> graphs_;
    std::unique_ptr<Root> root_;
    std::vector<std::string> padTitles_;
    int width_ = 1200, height_ = 700, x_ = 0, y_ = 0;
    std::string canvasTitle_ = "physim graphs";
    bool built_ = false;
    bool live_ = false;
    double refreshHz_ = 10.0;
};

}  // namespace physim
