#include "physim/graphs/TreeFile.hpp"

#include <TFile.h>
#include <TTree.h>

#include <filesystem>
#include <stdexcept>

namespace physim {
namespace {

bool isIdentifier(const std::string& s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    for (char c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
    return true;
}

}  // namespace

void writeTree(const std::string& path, const std::string& name, const std::vector<std::string>& branches,
               const std::vector<std::vector<double>>& rows) {
    if (!isIdentifier(name))
        throw std::invalid_argument("physim: writeTree: the tree's name '" + name + "' is not an identifier");
    for (const std::string& b : branches)
        if (!isIdentifier(b)) throw std::invalid_argument("physim: writeTree: branch '" + b + "' is not an identifier");
    for (std::size_t r = 0; r < rows.size(); ++r)
        if (rows[r].size() != branches.size())
            throw std::invalid_argument("physim: writeTree: row " + std::to_string(r) + " has " +
                                        std::to_string(rows[r].size()) + " values for " +
                                        std::to_string(branches.size()) + " branches");
    TFile file(path.c_str(), std::filesystem::exists(path) ? "UPDATE" : "RECREATE");
    if (file.IsZombie()) throw std::runtime_error("physim: cannot write " + path);
    std::vector<double> values(branches.size());
    {
        TTree tree(name.c_str(), name.c_str());  // owned by the file's directory while it is open
        for (std::size_t b = 0; b < branches.size(); ++b)
            tree.Branch(branches[b].c_str(), &values[b], (branches[b] + "/D").c_str());
        for (const std::vector<double>& row : rows) {
            values = row;
            tree.Fill();
        }
        tree.Write(nullptr, TObject::kOverwrite);
        tree.SetDirectory(nullptr);  // the file closes first: it must not delete the tree on the stack
    }
    file.Close();
}

}  // namespace physim
