#pragma once
// One pad of the graphs canvas drawn with ROOT: axes, every series (thinned for drawing), a legend. The same
// drawing serves the live window (redrawn at each refresh, keeping a zoom the user made with the mouse) and
// the exported PNG.

#include "PlotLayout.hpp"
#include "physim/graphs/GraphsManager.hpp"

#include <memory>
#include <string>
#include <vector>

class TGraph;
class TH1F;
class TLatex;
class TLegend;
class TVirtualPad;

namespace physim {

/// A series as the pad sees it: its points (all of them), how it is drawn, its style and its legend label.
struct PadSeries {
    const std::vector<plot::Point>* points = nullptr;
    GraphMode mode = GraphMode::DEFAULT;
    const TGraph* style = nullptr;  ///< colours, markers and widths (our defaults, then the user's modifier)
    std::string label;
};

class PadPlot {
public:
    PadPlot();
    ~PadPlot();
    PadPlot(const PadPlot&) = delete;
    PadPlot& operator=(const PadPlot&) = delete;

    /// Draws `series` on `pad` (cleared first) under `title` ("title;x label;y label"). `live`: an axis range
    /// the user set with the mouse since the last call is kept, and thinning follows it.
    void draw(TVirtualPad& pad, const std::string& title, const std::vector<PadSeries>& series, bool live);

private:
    struct Range {
        double xlo = 0, xhi = 1, ylo = 0, yhi = 1;
    };

    std::unique_ptr<TH1F> frame_;                   // the axes, grid and title; no contents
    std::vector<std::unique_ptr<TGraph>> shown_;   // thinned, transformed copies that the pad draws
    std::unique_ptr<TLegend> legend_;
    std::unique_ptr<TLatex> title_;                // the pad's title, above the frame
    Range set_;                                     // the ranges this class last gave the frame
    bool drawn_ = false;
    plot::Corner corner_ = plot::Corner::TOP_RIGHT;
};

}  // namespace physim
