// One pad drawn by ROOT (batch canvas): what is on it after drawing, read back from the pad itself.

#include "PadPlot.hpp"

#include <TAxis.h>
#include <TCanvas.h>
#include <TGraph.h>
#include <TH1F.h>
#include <TLegend.h>
#include <TList.h>
#include <TROOT.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace physim {
namespace {

struct Drawn {
    std::vector<TGraph*> graphs;  // in drawing order
    TH1F* frame = nullptr;
    TLegend* legend = nullptr;
};

Drawn contents(TVirtualPad& pad) {
    Drawn d;
    TIter next(pad.GetListOfPrimitives());
    while (TObject* o = next()) {
        if (auto* g = dynamic_cast<TGraph*>(o)) d.graphs.push_back(g);
        else if (auto* h = dynamic_cast<TH1F*>(o)) d.frame = h;
        else if (auto* l = dynamic_cast<TLegend*>(o)) d.legend = l;
    }
    return d;
}

class PadPlotTest : public testing::Test {
protected:
    void SetUp() override {
        gROOT->SetBatch(kTRUE);
        canvas_ = std::make_unique<TCanvas>("pad_plot_test", "", 600, 400);
        marker_.SetMarkerStyle(21);
        curve_.SetLineWidth(4);
    }
    std::unique_ptr<TCanvas> canvas_;
    TGraph marker_, curve_;  // styles
};

TEST_F(PadPlotTest, LongSeriesAreThinnedMarkersOverCurvesAndEveryOneNamed) {
    std::vector<plot::Point> simulated, analytic;
    for (int i = 0; i < 24000; ++i) {
        const double t = 0.025 * i;
        simulated.emplace_back(t, std::abs(std::cos(t)) * 5);
        analytic.emplace_back(t, std::abs(std::cos(t)) * 5);
    }
    PadPlot plot;
    plot.draw(*canvas_, "Height;time (s);y (m)",
              {{&simulated, GraphMode::DEFAULT, &marker_, "simulated"}, {&analytic, GraphMode::CURVE, &curve_, "analytic"}},
              false);
    const Drawn d = contents(*canvas_);
    ASSERT_EQ(d.graphs.size(), 2u);
    EXPECT_STREQ(d.graphs[0]->GetTitle(), "analytic") << "the curve is drawn first, under the markers";
    EXPECT_STREQ(d.graphs[1]->GetTitle(), "simulated");
    // 600 px wide: at most one marker per 8 px, two line points per pixel column.
    EXPECT_LE(d.graphs[1]->GetN(), 600 / 8);
    EXPECT_LE(d.graphs[0]->GetN(), 2 * 600 + 2);
    EXPECT_EQ(d.graphs[1]->GetMarkerStyle(), 21) << "the series' style is kept";
    ASSERT_NE(d.legend, nullptr);
    ASSERT_EQ(d.legend->GetListOfPrimitives()->GetSize(), 2);
    ASSERT_NE(d.frame, nullptr);
    EXPECT_STREQ(d.frame->GetYaxis()->GetTitle(), "y (m)");
}

TEST_F(PadPlotTest, TheLegendCoversNoDataAndTheYTitleFits) {
    // Data filling the whole pad but for the top: the legend must end up above it.
    std::vector<plot::Point> pts;
    for (int i = 0; i <= 400; ++i) pts.emplace_back(i, 1000.0 + 500.0 * std::sin(i * 0.3));
    PadPlot plot;
    plot.draw(*canvas_, "Noisy;x (m);signal with a long name (kg m^2/s)", {{&pts, GraphMode::DEFAULT, &marker_, "simulated"}},
              false);
    canvas_->Update();
    const Drawn d = contents(*canvas_);
    ASSERT_NE(d.legend, nullptr);
    ASSERT_EQ(d.graphs.size(), 1u);
    const TGraph& g = *d.graphs[0];
    const double ymin = d.frame->GetMinimum(), ymax = d.frame->GetMaximum();
    const double xmin = d.frame->GetXaxis()->GetXmin(), xmax = d.frame->GetXaxis()->GetXmax();
    const double l = canvas_->GetLeftMargin(), r = canvas_->GetRightMargin(), b = canvas_->GetBottomMargin(),
                 t = canvas_->GetTopMargin();
    for (int i = 0; i < g.GetN(); ++i) {
        const double nx = l + (g.GetPointX(i) - xmin) / (xmax - xmin) * (1 - l - r);
        const double ny = b + (g.GetPointY(i) - ymin) / (ymax - ymin) * (1 - b - t);
        const bool inside = nx >= d.legend->GetX1NDC() && nx <= d.legend->GetX2NDC() && ny >= d.legend->GetY1NDC() &&
                            ny <= d.legend->GetY2NDC();
        EXPECT_FALSE(inside) << "point " << i << " under the legend";
    }
    // The y title's centre (ROOT: 1.5625 title sizes per unit of offset from the axis, measured) lies inside the
    // pad, with half the title's height to spare: it is not clipped.
    const TAxis& y = *d.frame->GetYaxis();
    const double centrePx = 1.5625 * y.GetTitleSize() * y.GetTitleOffset();
    EXPECT_GT(l * 596 - centrePx, 0.5 * y.GetTitleSize());
}

TEST_F(PadPlotTest, AConservedQuantityIsShownAsItsRelativeChange) {
    std::vector<plot::Point> momentum, conserved;
    for (int i = 0; i < 100; ++i) {
        momentum.emplace_back(i, 2.0 * (1 + 1e-9 * std::sin(i)));
        conserved.emplace_back(i, 2.0);
    }
    PadPlot plot;
    plot.draw(*canvas_, "Momentum;time (s);p (kg m/s)",
              {{&momentum, GraphMode::DEFAULT, &marker_, "simulated"}, {&conserved, GraphMode::CURVE, &curve_, "conserved"}},
              false);
    const Drawn d = contents(*canvas_);
    EXPECT_EQ(std::string(d.frame->GetYaxis()->GetTitle()), "#Delta(p) / start,  start = 2 kg m/s");
    EXPECT_LT(d.frame->GetMaximum(), 1e-8) << "relative units around 0, not 10-digit labels around 2";
    EXPECT_GT(d.frame->GetMaximum(), 1e-9);
}

TEST_F(PadPlotTest, EmptySeriesAreNotDrawn) {
    std::vector<plot::Point> none, some{{0, 1}, {1, 2}};
    PadPlot plot;
    testing::internal::CaptureStderr();
    plot.draw(*canvas_, "t;x;y", {{&none, GraphMode::DEFAULT, &marker_, "measured"}, {&some, GraphMode::CURVE, &curve_, "exact"}},
              false);
    canvas_->Update();
    plot.draw(*canvas_, "t;x;y", {{&none, GraphMode::DEFAULT, &marker_, "measured"}, {&none, GraphMode::CURVE, &curve_, "exact"}},
              false);
    canvas_->Update();
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(err.find("illegal number of points"), std::string::npos) << err;
    EXPECT_TRUE(contents(*canvas_).graphs.empty());
}

TEST_F(PadPlotTest, ALiveZoomStaysAcrossRefreshes) {
    std::vector<plot::Point> pts;
    for (int i = 0; i < 1000; ++i) pts.emplace_back(i, i * 0.5);
    PadPlot plot;
    plot.draw(*canvas_, "t;x;y", {{&pts, GraphMode::WITH_LINES, &marker_, "simulated"}}, true);
    TH1F* frame = contents(*canvas_).frame;
    ASSERT_NE(frame, nullptr);
    frame->GetXaxis()->SetRangeUser(100, 200);  // what dragging along the x axis does
    frame->SetMinimum(50);
    frame->SetMaximum(60);
    for (int i = 1000; i < 1100; ++i) pts.emplace_back(i, i * 0.5);
    plot.draw(*canvas_, "t;x;y", {{&pts, GraphMode::WITH_LINES, &marker_, "simulated"}}, true);
    TAxis& x = *frame->GetXaxis();
    EXPECT_NEAR(x.GetBinLowEdge(x.GetFirst()), 100, 2);
    EXPECT_NEAR(x.GetBinUpEdge(x.GetLast()), 200, 2);
    EXPECT_EQ(frame->GetMinimum(), 50);
    EXPECT_EQ(frame->GetMaximum(), 60);
    for (TGraph* g : contents(*canvas_).graphs)
        for (int i = 0; i < g->GetN(); ++i) EXPECT_LT(g->GetPointX(i), 205) << "thinned within the zoom";
    frame->SetMinimum();  // y unzoomed: it follows the points in the zoomed x range, y = x / 2
    frame->SetMaximum();
    plot.draw(*canvas_, "t;x;y", {{&pts, GraphMode::WITH_LINES, &marker_, "simulated"}}, true);
    EXPECT_NEAR(frame->GetMinimum(), 45, 3);
    EXPECT_NEAR(frame->GetMaximum(), 105, 3);
    x.UnZoom();  // and back: the range follows the data again
    plot.draw(*canvas_, "t;x;y", {{&pts, GraphMode::WITH_LINES, &marker_, "simulated"}}, true);
    EXPECT_GT(x.GetXmax(), 1099);
}

}  // namespace
}  // namespace physim
