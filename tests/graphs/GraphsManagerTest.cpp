// GraphsManager headless: what is written is what was added; bad calls get clear errors.

#include <physim/graphs/GraphsManager.hpp>

#include <TAxis.h>
#include <TFile.h>
#include <TGraph.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

namespace physim {
namespace {

std::vector<std::string> lines(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> out;
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
}

TEST(GraphsManager, EachGraphIsItsOwnAndFilesMatchThePoints) {
    GraphsManager gm;
    gm.addGraph("Speed;t (s);v (m/s)");
    gm.addGraph("Height;t (s);y (m)", {}, GraphMode::WITH_LINES);
    gm.build();
    for (int i = 0; i < 5; ++i) gm.addPoint(0, i, 2.0 * i);
    gm.addPoint(1, 0.5, -1.25);
    EXPECT_EQ(gm.points(0).size(), 5u);
    EXPECT_EQ(gm.points(1).size(), 1u) << "graphs must not alias each other";

    const auto dir = std::filesystem::temp_directory_path() / "physim_graphs_test";
    std::filesystem::remove_all(dir);
    const auto written = gm.writeFiles(dir.string());
    ASSERT_EQ(written.size(), 4u);
    const auto g0 = lines((dir / "graph_0.csv").string());
    ASSERT_EQ(g0.size(), 3u + 5u);
    EXPECT_EQ(g0[0], "# Speed;t (s);v (m/s)");
    EXPECT_EQ(g0[1], "# series: simulated");
    EXPECT_EQ(g0[2], "x,y");
    EXPECT_EQ(g0[5], "2,4");
    const auto g1 = lines((dir / "graph_1.csv").string());
    ASSERT_EQ(g1.size(), 4u);
    EXPECT_EQ(g1[3], "0.5,-1.25");
    EXPECT_GT(std::filesystem::file_size(dir / "graphs.png"), 1000u) << "a PNG drawn in ROOT's batch mode";
    {
        TFile file((dir / "graphs.root").string().c_str(), "READ");
        ASSERT_FALSE(file.IsZombie());
        // Objects read from a file belong to the caller (ROOT's convention for non-histograms).
        const std::unique_ptr<TGraph> g0root(file.Get<TGraph>("graph_0"));
        const std::unique_ptr<TGraph> g1root(file.Get<TGraph>("graph_1"));
        ASSERT_NE(g0root, nullptr);
        ASSERT_NE(g1root, nullptr);
        EXPECT_EQ(g0root->GetN(), 5);
        EXPECT_EQ(g0root->GetPointY(3), 6.0);
        EXPECT_EQ(g1root->GetN(), 1);
    }
    std::filesystem::remove_all(dir);
}

TEST(GraphsManager, NonFinitePointsAreSkippedAndCounted) {
    GraphsManager gm;
    gm.addGraph("g");
    gm.build();
    testing::internal::CaptureStderr();
    gm.addPoint(0, 1.0, NAN);
    gm.addPoint(0, INFINITY, 1.0);
    const std::string warning = testing::internal::GetCapturedStderr();
    EXPECT_NE(warning.find("non-finite"), std::string::npos) << warning;
    EXPECT_EQ(warning.find("non-finite"), warning.rfind("non-finite")) << "warned once, not per point";
    gm.addPoint(0, 1.0, 1.0);
    EXPECT_EQ(gm.points(0).size(), 1u);
    EXPECT_EQ(gm.skippedPoints(0), 2u);
    gm.setPoints(0, {{1.0, 2.0}, {NAN, 0.0}, {3.0, 4.0}});
    EXPECT_EQ(gm.points(0), (std::vector<std::pair<double, double>>{{1.0, 2.0}, {3.0, 4.0}}));
    EXPECT_EQ(gm.skippedPoints(0), 1u) << "replacing starts the count again";
    gm.reset();
    EXPECT_TRUE(gm.points(0).empty());
    EXPECT_EQ(gm.graphCount(), 1u);
}

TEST(GraphsManager, MisuseGetsClearErrors) {
    GraphsManager gm;
    gm.addGraph("g");
    EXPECT_THROW(gm.addPoint(0, 1.0, 1.0), std::logic_error) << "before build";
    gm.build();
    EXPECT_THROW(gm.addPoint(1, 1.0, 1.0), std::out_of_range);
    EXPECT_THROW(gm.addPoint(-1, 1.0, 1.0), std::out_of_range);
    EXPECT_THROW(gm.addGraph("late"), std::logic_error);
    EXPECT_THROW(gm.build(), std::logic_error);
    EXPECT_THROW(gm.setCanvasSize(0, 100), std::invalid_argument);
    gm.render();  // headless: nothing to refresh, no crash
}

TEST(GraphsManager, ModifierStylesTheGraph) {
    GraphsManager gm;
    int calls = 0;
    gm.addGraph("g", [&calls](TGraph* g) {
        ASSERT_NE(g, nullptr);
        ++calls;
    });
    gm.build();
    EXPECT_EQ(calls, 1);
}

}  // namespace
}  // namespace physim

namespace physim {
namespace {

TEST(GraphsManager, SeriesShareTheirGraphsPadButNotTheirPoints) {
    GraphsManager gm;
    gm.addGraph("Height;t (s);y (m)");
    gm.addGraph("Speed;t (s);v (m/s)");
    const int analytic = gm.addSeries(0, "analytic");
    EXPECT_EQ(analytic, 2);
    EXPECT_THROW(gm.addSeries(7, "x"), std::out_of_range);
    gm.build();
    for (int i = 0; i <= 10; ++i) {
        gm.addPoint(0, 0.1 * i, 1.0 - 0.05 * i * i);
        gm.addPoint(analytic, 0.1 * i, 1.0 - 0.049 * i * i);
    }
    EXPECT_EQ(gm.points(0).size(), 11u);
    EXPECT_EQ(gm.points(analytic).size(), 11u);
    EXPECT_TRUE(gm.points(1).empty());
    const auto dir = std::filesystem::temp_directory_path() / "physim_graphs_series_test";
    std::filesystem::remove_all(dir);
    const auto written = gm.writeFiles(dir.string());  // graph 1 has no points: its pad stays empty
    EXPECT_EQ(lines((dir / "graph_2.csv").string())[0], "# Height;t (s);y (m)") << "the pad's title";
    EXPECT_EQ(lines((dir / "graph_2.csv").string())[1], "# series: analytic");
    EXPECT_GT(std::filesystem::file_size(dir / "graphs.png"), 1000u);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace physim

namespace physim {
namespace {

TEST(GraphsManager, EverySeriesHasALabel) {
    GraphsManager gm;
    const int a = gm.addGraph("Height;t (s);y (m)");
    const int b = gm.addGraph("Period;amplitude (deg);T (s)", "measured");
    const int c = gm.addSeries(b, "exact");
    EXPECT_EQ(gm.label(a), "simulated") << "the default for simulated data";
    EXPECT_EQ(gm.label(b), "measured");
    EXPECT_EQ(gm.label(c), "exact");
    EXPECT_EQ(gm.title(c), "Period;amplitude (deg);T (s)") << "a series shares its graph's pad and title";
}

TEST(GraphsManager, FilesHoldEveryPointAndOnlyThisRunsGraphs) {
    const auto dir = std::filesystem::temp_directory_path() / "physim_graphs_files_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    for (const char* stale : {"graph_0.csv", "graph_7.csv", "graph_12.csv"}) std::ofstream(dir / stale) << "old\n";
    std::ofstream(dir / "notes.txt") << "the user's\n";

    GraphsManager gm;
    const int energy = gm.addGraph("Energy;time (s);E (J)", {}, GraphMode::WITH_LINES);
    gm.addSeries(energy, "initial");
    gm.build();
    gm.prepareExport();  // ROOT starts on its own thread while the points come in, as in a headless run
    for (int i = 0; i < 24000; ++i) {  // 600 s at 40 Hz: thinned for drawing, not in the files
        gm.addPoint(0, 0.025 * i, 100.0 - 1e-3 * i);
        gm.addPoint(1, 0.025 * i, 100.0);
    }
    const auto written = gm.writeFiles(dir.string());
    EXPECT_EQ(written.size(), 4u);
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"graph_0.csv", "graph_1.csv", "graphs.png", "graphs.root", "notes.txt"}))
        << "earlier graph_<i>.csv gone, other files left alone";
    EXPECT_EQ(lines((dir / "graph_0.csv").string()).size(), 3u + 24000u);
    TFile file((dir / "graphs.root").string().c_str(), "READ");
    const std::unique_ptr<TGraph> g0(file.Get<TGraph>("graph_0"));
    ASSERT_NE(g0, nullptr);
    EXPECT_EQ(g0->GetN(), 24000);
    EXPECT_STREQ(g0->GetTitle(), "Energy: simulated");
    EXPECT_STREQ(g0->GetXaxis()->GetTitle(), "time (s)") << "ROOT's title convention: drawn, it has its axis titles";
    EXPECT_STREQ(g0->GetYaxis()->GetTitle(), "E (J)");
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace physim
