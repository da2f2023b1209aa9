#pragma once
// The paper's GraphsManager (section 6): named graphs of (x, y) points, drawn with CERN ROOT on pads of one
// canvas. ROOT stays out of this header (TGraph is only forward-declared), so including it costs nothing.
//
// Use: addGraph(...) for each graph, build(), then addPoint(i, x, y) as the simulation runs. In a window
// session render() refreshes a live ROOT canvas; headless, writeFiles(dir) saves CSV and PNG.

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

class TCanvas;
class TGraph;

namespace physim {

enum class GraphMode { DEFAULT, WITH_LINES };

/// Styles a graph after it is created (colours, markers, axis titles), as in the paper.
using graph_modifier = std::function<void(TGraph*)>;

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

    /// Adds a graph before build(). Axis labels (with units) go in the title as "title;x label;y label",
    /// ROOT's convention. Returns its index for addPoint. Throws std::logic_error after build().
    int addGraph(const std::string& title, graph_modifier modifier = {}, GraphMode mode = GraphMode::DEFAULT);
    /// Adds a series drawn on the same pad as graph `onGraph` (an analytic curve over the simulated points,
    /// say), with a legend entry `label`. Returns its index for addPoint. Before build() only.
    int addSeries(int onGraph, const std::string& label, graph_modifier modifier = {},
                  GraphMode mode = GraphMode::WITH_LINES);
    /// Creates one ROOT graph per addGraph/addSeries call (each its own object) laid out on pads of one canvas.
    void build();
    /// Appends a point to graph `i` (0-based, in addGraph/addSeries order). Non-finite points are skipped, counted
    /// and warned about on stderr (once per graph).
    /// Throws std::out_of_range for an unknown index, std::logic_error before build().
    void addPoint(int i, double x, double y);
    /// Live mode: refreshes the canvas, at most `refreshHz` times a second. Headless: does nothing.
    void render();
    /// Removes every point from every graph; the graphs stay.
    void reset();
    /// Replaces graph `i`'s points (a histogram recomputed each frame, say). Non-finite points are skipped and
    /// counted as in addPoint.
    void setPoints(int i, const std::vector<std::pair<double, double>>& points);

    /// Live mode opens a ROOT canvas window at build(); call before build(). Default: off (headless).
    void setLive(bool live, double refreshHz = 10.0);
    bool built() const { return built_; }
    std::size_t graphCount() const;
    const std::string& title(int i) const;
    const std::vector<std::pair<double, double>>& points(int i) const;
    std::size_t skippedPoints(int i) const;

    /// Writes graph_<i>.csv for each graph ("x,y" header; title in a comment line), graphs.png with every pad,
    /// and graphs.root holding each TGraph as graph_<i>. Returns the paths written. Creates `directory`.
    std::vector<std::string> writeFiles(const std::string& directory) const;

private:
    struct Graph;
    struct Root;  // ROOT objects (canvas, graphs): only in the .cpp

    const Graph& graph(int i) const;
    void drawPad(TCanvas& canvas, int pad) const;
    void fitAxes(int pad) const;
    bool padHasPoints(int pad) const;

    std::vector<Graph> graphs_;
    std::unique_ptr<Root> root_;
    int padCount_ = 0;
    int width_ = 1200, height_ = 700, x_ = 0, y_ = 0;
    bool built_ = false;
    bool live_ = false;
    double refreshHz_ = 10.0;
};

}  // namespace physim
