// gallery: every example scene in one window, with a scene list, live parameters, run controls and debug
// drawing in a Dear ImGui panel. `--scene NAME` picks the first scene; every other option is the examples'.
// Headless, it runs the chosen scene as that example's own program would.

#include "Gallery.hpp"

#include <cstring>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    using physim::examples::scenes;
    std::string first = scenes().front().name;
    std::vector<const char*> args{argc > 0 ? argv[0] : "gallery"};
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--scene" || a.rfind("--scene=", 0) == 0) {
            if (a == "--scene" && i + 1 >= argc) {
                std::cerr << "gallery: --scene needs a value\n";
                return 2;
            }
            first = a == "--scene" ? argv[++i] : a.substr(std::strlen("--scene="));
        } else {
            if (a == "--help" || a == "-h") {
                std::cout << "gallery: --scene NAME starts with that scene, one of:";
                for (const auto& s : scenes()) std::cout << " " << s.name;
                std::cout << "\n\n";
            }
            args.push_back(argv[i]);
        }
    }
    std::size_t index = scenes().size();
    for (std::size_t i = 0; i < scenes().size(); ++i)
        if (scenes()[i].name == first) index = i;
    if (index == scenes().size()) {
        std::cerr << "gallery: --scene must name one of the examples (see --help), got '" << first << "'\n";
        return 2;
    }
    return physim::runMain(static_cast<int>(args.size()), args.data(), scenes()[index].make,
                           [index](physim::Runner& runner) {
                               runner.setPanel(std::make_unique<physim::examples::Gallery>(scenes(), index));
                           });
}
