#include "PadPlot.hpp"

#include <TAxis.h>
#include <TGraph.h>
#include <TH1F.h>
#include <TLatex.h>
#include <TLegend.h>
#include <TVirtualPad.h>

#include <algorithm>
#include <cmath>

namespace physim {
namespace {

// Text in pixels (ROOT fonts with precision 3: 43 is Helvetica), so every pad reads the same at any size.
constexpr int kFont = 43;
constexpr double kLabelPx = 13, kAxisTitlePx = 15, kPadTitlePx = 16, kLegendPx = 13;
// ROOT puts a vertical axis title's centre 1.5625 * (title size) * (title offset) pixels from the axis
// (measured on the ROOT 6.40 wheel), a horizontal one's about that plus 2 pixels.
constexpr double kTitleOffsetPx = 1.5625;
constexpr double kLabelOffsetPx = 5, kGapPx = 7, kEdgePx = 6;
// Above the frame: the pad's title, and under it the power of ten ROOT may move to the top of the y axis.
constexpr double kTopPx = 40, kRightPx = 14;
constexpr double kLegendRowPx = 18, kLegendSymbolPx = 30, kLegendInsetPx = 8;
// Markers, at most one per so many pixels of the frame's width: about a marker's width for a series of
// markers (a curve under them still shows between), sparser on a line (the line carries the shape). A line
// keeps two points per pixel column.
constexpr double kMarkerEveryPx = 8, kMarkerOnLineEveryPx = 12;
constexpr double kMarkerRadiusPx = 6;
// A relative plot spans at least this much (of the start value): a series kept exactly shows as a flat line
// at 0 rather than as magnified rounding noise.
constexpr double kRelativeMinSpan = 1e-12;

bool hasMarkers(GraphMode m) { return m != GraphMode::CURVE; }
bool hasLine(GraphMode m) { return m != GraphMode::DEFAULT; }

// "title;x label;y label" split into its three parts.
struct Titles {
    std::string title, x, y;
};
Titles splitTitle(const std::string& t) {
    Titles out;
    const auto a = t.find(';');
    out.title = t.substr(0, a);
    if (a == std::string::npos) return out;
    const auto b = t.find(';', a + 1);
    out.x = t.substr(a + 1, b == std::string::npos ? std::string::npos : b - a - 1);
    if (b != std::string::npos) out.y = t.substr(b + 1);
    return out;
}

void styleAxis(TAxis& axis) {
    axis.SetLabelFont(kFont);
    axis.SetLabelSize(kLabelPx);
    axis.SetTitleFont(kFont);
    axis.SetTitleSize(kAxisTitlePx);
    axis.SetMaxDigits(5);
    axis.CenterTitle();
}

}  // namespace

PadPlot::PadPlot() = default;
PadPlot::~PadPlot() = default;

void PadPlot::draw(TVirtualPad& pad, const std::string& title, const std::vector<PadSeries>& series, bool live) {
    pad.cd();
    const double padW = std::max(1.0, pad.GetWw() * pad.GetAbsWNDC());
    const double padH = std::max(1.0, pad.GetWh() * pad.GetAbsHNDC());

    // Extents of every series, and the start: the first point of the first simulated series.
    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    double start = NAN;
    for (const PadSeries& s : series) {
        for (const auto& [x, y] : *s.points) {
            xlo = std::min(xlo, x), xhi = std::max(xhi, x);
            ylo = std::min(ylo, y), yhi = std::max(yhi, y);
        }
        if (!s.points->empty() && hasMarkers(s.mode) && std::isnan(start)) start = s.points->front().second;
    }
    const bool any = xlo <= xhi;
    if (any && std::isnan(start))
        for (const PadSeries& s : series)
            if (!s.points->empty()) {
                start = s.points->front().second;
                break;
            }

    // A range the user chose with the mouse since the last refresh stays.
    bool userX = false, userY = false;
    if (live && drawn_) {
        userX = frame_->GetXaxis()->TestBit(TAxis::kAxisRange);
        const double mn = frame_->GetMinimumStored(), mx = frame_->GetMaximumStored();
        userY = mn != -1111 && mx != -1111 && (mn != set_.ylo || mx != set_.yhi);
    }

    const plot::YTransform yt = any ? plot::chooseYTransform(start, ylo, yhi) : plot::YTransform{};
    Range r;
    if (any) {
        const double xspan = xhi > xlo ? xhi - xlo : std::max(1.0, std::abs(xlo));
        r.xlo = xlo - 0.02 * xspan, r.xhi = xhi + 0.02 * xspan;
        std::tie(r.ylo, r.yhi) =
            plot::paddedRange(yt.apply(ylo), yt.apply(yhi), yt.relative ? kRelativeMinSpan : 0.0);
    }
    if (userX) {
        // The y range follows the points in the x range zoomed to.
        const TAxis& ax = *frame_->GetXaxis();
        r.xlo = ax.GetBinLowEdge(ax.GetFirst()), r.xhi = ax.GetBinUpEdge(ax.GetLast());
        double vlo = INFINITY, vhi = -INFINITY;
        for (const PadSeries& s : series)
            for (const auto& [x, y] : *s.points)
                if (x >= r.xlo && x <= r.xhi) vlo = std::min(vlo, y), vhi = std::max(vhi, y);
        if (vlo <= vhi)
            std::tie(r.ylo, r.yhi) =
                plot::paddedRange(yt.apply(vlo), yt.apply(vhi), yt.relative ? kRelativeMinSpan : 0.0);
    }
    if (userY) r.ylo = frame_->GetMinimumStored(), r.yhi = frame_->GetMaximumStored();

    // Margins from what they hold: the widest y tick label and the axis titles.
    // Plus half a digit: the estimate of ROOT's labels and of their font's widths is close, not exact.
    const double labelW = plot::textWidthPx(plot::widestTickLabel(r.ylo, r.yhi), kLabelPx) + 0.3 * kLabelPx;
    const double yTitleCentre = kLabelOffsetPx + labelW + kGapPx + kAxisTitlePx / 2;
    const double left = (yTitleCentre + kAxisTitlePx / 2 + kEdgePx) / padW;
    const double xTitleCentre = kLabelOffsetPx + kLabelPx + kGapPx + kAxisTitlePx / 2;
    const double bottom = (xTitleCentre + kAxisTitlePx / 2 + kEdgePx) / padH;
    const double top = kTopPx / padH, right = kRightPx / padW;
    pad.SetMargin(left, right, bottom, top);
    const double frameW = padW * (1 - left - right), frameH = padH * (1 - top - bottom);

    // The points drawn: in the visible x range, transformed, thinned. Lines first so markers lie on top.
    std::vector<std::vector<plot::Point>> lines, markers;
    std::vector<const PadSeries*> lineOf, markerOf;
    for (const PadSeries& s : series) {
        std::vector<plot::Point> pts;
        pts.reserve(s.points->size());
        const auto& all = *s.points;
        for (std::size_t i = 0; i < all.size(); ++i) {
            const bool inside = all[i].first >= r.xlo && all[i].first <= r.xhi;
            const bool nextInside = i + 1 < all.size() && all[i + 1].first >= r.xlo && all[i + 1].first <= r.xhi;
            const bool prevInside = i > 0 && all[i - 1].first >= r.xlo && all[i - 1].first <= r.xhi;
            // Neighbours just outside keep a line running to the frame's edge.
            if (!userX || inside || (hasLine(s.mode) && (nextInside || prevInside)))
                pts.emplace_back(all[i].first, yt.apply(all[i].second));
        }
        if (pts.empty()) continue;
        if (hasLine(s.mode)) {
            lines.push_back(plot::thinLine(pts, static_cast<std::size_t>(std::max(1.0, frameW))));
            lineOf.push_back(&s);
        }
        if (hasMarkers(s.mode)) {
            const double every = s.mode == GraphMode::WITH_LINES ? kMarkerOnLineEveryPx : kMarkerEveryPx;
            markers.push_back(plot::thinMarkers(pts, static_cast<std::size_t>(std::max(3.0, frameW / every))));
            markerOf.push_back(&s);
        }
    }

    // Legend: one row per series that has points, in the order they were added; in a corner free of data,
    // else above the data with the y range raised to make room.
    std::vector<const PadSeries*> entries;
    for (const PadSeries& s : series)
        if (!s.points->empty()) entries.push_back(&s);
    double legendW = 0.0;
    for (const PadSeries* s : entries) legendW = std::max(legendW, plot::textWidthPx(s->label, kLegendPx));
    legendW += kLegendSymbolPx + 10;
    const double legendH = kLegendRowPx * static_cast<double>(entries.size()) + 6;
    const plot::Box frameBox{left, bottom, 1 - right, 1 - top};
    auto toNdc = [&](const plot::Point& p) {
        return plot::Point{left + (p.first - r.xlo) / (r.xhi - r.xlo) * (1 - left - right),
                           bottom + (p.second - r.ylo) / (r.yhi - r.ylo) * (1 - top - bottom)};
    };
    if (!entries.empty()) {
        plot::Obstacles obstacles;
        obstacles.markerRadius = kMarkerRadiusPx / std::min(padW, padH);
        for (const auto& m : markers)
            for (const auto& p : m) obstacles.markers.push_back(toNdc(p));
        for (const auto& l : lines) {
            obstacles.lines.emplace_back();
            for (const auto& p : l) obstacles.lines.back().push_back(toNdc(p));
        }
        plot::Corner chosen = corner_;
        if (plot::freeCorner(frameBox, legendW / padW, legendH / padH, kLegendInsetPx / padW, kLegendInsetPx / padH,
                             obstacles, corner_, chosen)) {
            corner_ = chosen;
        } else if (!userY) {
            // Raise the top so the data stays below the legend's bottom edge.
            const double room = legendH + 2 * kLegendInsetPx;
            r.yhi = r.ylo + (r.yhi - r.ylo) * frameH / std::max(frameH - room, 0.3 * frameH);
            corner_ = plot::Corner::TOP_RIGHT;
        }
    }

    // The frame: axes, grid, no contents. Its title is ours (a TLatex), so no global style is touched.
    if (!frame_) {
        frame_ = std::make_unique<TH1F>("", "", 1000, 0.0, 1.0);
        frame_->SetDirectory(nullptr);
        frame_->SetStats(false);
        frame_->SetBit(TH1::kNoTitle);
        styleAxis(*frame_->GetXaxis());
        styleAxis(*frame_->GetYaxis());
    }
    const Titles titles = splitTitle(title);
    frame_->GetXaxis()->SetTitle(titles.x.c_str());
    frame_->GetYaxis()->SetTitle(yt.relative ? plot::relativeTitle(titles.y, yt.origin).c_str() : titles.y.c_str());
    frame_->GetYaxis()->SetTitleOffset(static_cast<float>(yTitleCentre / (kTitleOffsetPx * kAxisTitlePx)));
    frame_->GetXaxis()->SetTitleOffset(static_cast<float>((xTitleCentre - 2) / (kTitleOffsetPx * kAxisTitlePx)));
    if (!userX) frame_->GetXaxis()->SetLimits(r.xlo, r.xhi);
    if (!userY) {
        frame_->SetMinimum(r.ylo);
        frame_->SetMaximum(r.yhi);
    }
    set_ = r;

    pad.Clear();
    pad.SetGrid();
    frame_->Draw("AXIS");
    frame_->Draw("AXIG SAME");  // the grid, under the series

    shown_.resize(lines.size() + markers.size());
    std::vector<TGraph*> markerGraph(series.size(), nullptr), lineGraph(series.size(), nullptr);
    std::size_t k = 0;
    auto show = [&](const std::vector<plot::Point>& pts, const PadSeries& s, const char* option) {
        auto& g = shown_[k++];
        if (!g) g = std::make_unique<TGraph>();
        g->Set(static_cast<int>(pts.size()));
        for (std::size_t i = 0; i < pts.size(); ++i) g->SetPoint(static_cast<int>(i), pts[i].first, pts[i].second);
        s.style->TAttLine::Copy(*g);
        s.style->TAttMarker::Copy(*g);
        s.style->TAttFill::Copy(*g);
        g->SetTitle(s.label.c_str());
        g->Draw(option);
        return g.get();
    };
    for (std::size_t i = 0; i < lines.size(); ++i)
        lineGraph[static_cast<std::size_t>(lineOf[i] - series.data())] = show(lines[i], *lineOf[i], "L");
    for (std::size_t i = 0; i < markers.size(); ++i)
        markerGraph[static_cast<std::size_t>(markerOf[i] - series.data())] = show(markers[i], *markerOf[i], "P");

    if (!title_) {
        title_ = std::make_unique<TLatex>();
        title_->SetNDC();
        title_->SetTextFont(kFont);
        title_->SetTextSize(kPadTitlePx);
        title_->SetTextAlign(22);
    }
    title_->SetText(0.5 * (left + 1 - right), 1 - (kPadTitlePx / 2 + 5) / padH, titles.title.c_str());
    title_->Draw();

    legend_.reset();
    if (!entries.empty()) {
        const plot::Box b = plot::cornerBox(frameBox, corner_, legendW / padW, legendH / padH, kLegendInsetPx / padW,
                                            kLegendInsetPx / padH);
        legend_ = std::make_unique<TLegend>(b.x1, b.y1, b.x2, b.y2);
        legend_->SetTextFont(kFont);
        legend_->SetTextSize(kLegendPx);
        legend_->SetBorderSize(0);
        legend_->SetFillColor(0);
        legend_->SetFillStyle(1001);
        legend_->SetMargin(static_cast<float>(kLegendSymbolPx / legendW));
        for (const PadSeries* s : entries) {
            const auto i = static_cast<std::size_t>(s - series.data());
            const char* option = s->mode == GraphMode::DEFAULT ? "P" : s->mode == GraphMode::CURVE ? "L" : "LP";
            TGraph* g = markerGraph[i] ? markerGraph[i] : lineGraph[i];
            if (g) legend_->AddEntry(g, s->label.c_str(), option);
        }
        legend_->Draw();
    }
    pad.Modified();
    drawn_ = true;
}

}  // namespace physim
