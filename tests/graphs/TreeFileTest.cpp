// writeTree: a table written as a ROOT TTree reads back value for value, beside what the file already held, and
// bad names and ragged rows are refused before the file is touched.

#include "physim/graphs/TreeFile.hpp"

#include <TFile.h>
#include <TGraph.h>
#include <TTree.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <stdexcept>

namespace physim {
namespace {

std::filesystem::path scratch(const char* name) {
    return std::filesystem::temp_directory_path() / ("physim_tree_" + std::string(name) + "_" +
                                                     std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
}

TEST(TreeFile, RowsReadBackBesideWhatTheFileHeld) {
    const std::filesystem::path path = scratch("rows.root");
    std::filesystem::remove(path);
    {
        TFile file(path.string().c_str(), "RECREATE");
        TGraph g(2);
        g.Write("graph_0");
    }
    const std::vector<std::vector<double>> rows{{0.0, 1.5, -2.0}, {0.025, 1e-300, 3.25}, {0.05, 7.0, 1e300}};
    writeTree(path.string(), "records", {"t", "kinetic_energy_3", "y_3"}, rows);
    writeTree(path.string(), "records", {"t", "kinetic_energy_3", "y_3"}, rows);  // replaces, does not add
    TFile file(path.string().c_str(), "READ");
    ASSERT_FALSE(file.IsZombie());
    const std::unique_ptr<TGraph> graph(file.Get<TGraph>("graph_0"));
    EXPECT_NE(graph, nullptr) << "what the file held stays";
    auto* tree = file.Get<TTree>("records");  // owned by the file
    ASSERT_NE(tree, nullptr);
    ASSERT_EQ(tree->GetEntries(), 3);
    double t = 0.0, e = 0.0, y = 0.0;
    tree->SetBranchAddress("t", &t);
    tree->SetBranchAddress("kinetic_energy_3", &e);
    tree->SetBranchAddress("y_3", &y);
    for (Long64_t i = 0; i < 3; ++i) {
        tree->GetEntry(i);
        EXPECT_EQ(t, rows[i][0]);  // doubles stored as doubles: bit for bit
        EXPECT_EQ(e, rows[i][1]);
        EXPECT_EQ(y, rows[i][2]);
    }
    std::filesystem::remove(path);
}

TEST(TreeFile, BadNamesAndRaggedRowsAreRefusedWithoutWriting) {
    const std::filesystem::path path = scratch("bad.root");
    std::filesystem::remove(path);
    EXPECT_THROW(writeTree(path.string(), "my records", {"t"}, {}), std::invalid_argument);
    EXPECT_THROW(writeTree(path.string(), "records", {"t", "3y"}, {}), std::invalid_argument);
    try {
        writeTree(path.string(), "records", {"t", "y"}, {{0.0, 1.0}, {0.5}});
        FAIL() << "a short row";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("row 1 has 1 values for 2"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace physim
