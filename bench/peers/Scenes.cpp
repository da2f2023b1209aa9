#include "Scenes.hpp"

#include "support/Pyramid.hpp"

#include <algorithm>
#include <stdexcept>

namespace peers {

namespace {

constexpr double kBoxHalf = 0.5;  // the pyramids' boxes, m (the issue's `a`)

ShapeSpec box(double x, double y, double halfWidth, double halfHeight) {
    ShapeSpec s;
    s.x = x;
    s.y = y;
    s.halfWidth = halfWidth;
    s.halfHeight = halfHeight;
    return s;
}

// "<prefix><N>" -> N (up to 3 digits), or 0 when the name is not of that form.
int numberAfter(const std::string& prefix, const std::string& name) {
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) return 0;
    const std::string digits = name.substr(prefix.size());
    if (digits.size() > 3 || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return 0;
    return std::stoi(digits);
}

}  // namespace

void addPyramid(Scene& scene, int base, double originX, double originY) {
    physim::scenes::forEachPyramidBox(base, 2.0 * kBoxHalf, originX, originY, [&](double x, double y) {
        scene.dynamics.push_back(box(x, y, kBoxHalf, kBoxHalf));
    });
    scene.tops.push_back(scene.dynamics.size() - 1);  // the top box comes last
}

Scene pyramidScene(const std::string& name, int base) {
    Scene s;
    s.name = name;
    s.statics.push_back(box(0.0, -1.0, 100.0, 1.0));
    addPyramid(s, base, 0.0, 0.0);
    return s;
}

Scene circlesScene() {
    Scene s;
    s.name = "circles1000";
    // Inside: x in [-10, 10], y in [0, 25]; walls 1 m thick.
    s.statics = {box(0.0, -0.5, 11.0, 0.5), box(0.0, 25.5, 11.0, 0.5), box(-10.5, 12.5, 0.5, 12.5),
                 box(10.5, 12.5, 0.5, 12.5)};
    // Rows of 30, 0.6 m apart (0.1 m gaps), odd rows shifted half a pitch so they settle into the gaps below.
    constexpr int kPerRow = 30;
    constexpr double kPitch = 0.6;
    for (int k = 0; k < 1000; ++k) {
        const int row = k / kPerRow;
        ShapeSpec c;
        c.x = -9.0 + kPitch * (k % kPerRow) + 0.5 * kPitch * (row % 2);
        c.y = 1.0 + kPitch * row;
        c.radius = 0.25;
        s.dynamics.push_back(c);
    }
    return s;
}

Scene pyramidGridScene(const std::string& name, int rows) {
    constexpr int kBase = 10, kColumns = 20;
    constexpr double kColumnPitch = 12.0;  // m: 10 m pyramids, 2 m apart
    constexpr double kRowPitch = 13.0;     // m: 10 m tall, on a 2 m thick ground, 1 m of air above
    Scene s;
    s.name = name;
    s.pyramidGrid = true;
    for (int r = 0; r < rows; ++r) {
        const double groundTop = r * kRowPitch;
        s.statics.push_back(box(0.0, groundTop - 1.0, 0.5 * kColumns * kColumnPitch, 1.0));
        for (int c = 0; c < kColumns; ++c)
            addPyramid(s, kBase, (c - 0.5 * (kColumns - 1)) * kColumnPitch, groundTop);
    }
    return s;
}

Scene makeScene(const std::string& name) {
    if (name == "large_pyramid") return pyramidScene(name, 100);
    if (name == "circles1000") return circlesScene();
    if (name == "many_pyramids") return pyramidGridScene(name, 19);
    const int base = numberAfter("pyramid", name);
    if (base >= 1 && base <= 400) return pyramidScene(name, base);
    const int rows = numberAfter("pyramid_grid", name);
    if (rows >= 1 && rows <= 100) return pyramidGridScene(name, rows);
    throw std::invalid_argument("unknown scene '" + name +
                                "' (large_pyramid, pyramid<N> with N in 1..400, circles1000, many_pyramids, "
                                "pyramid_grid<R> with R in 1..100, scaling, all)");
}

std::vector<std::string> defaultScenes() {
    return {"large_pyramid", "pyramid20", "pyramid40", "circles1000", "many_pyramids"};
}

std::vector<std::string> scalingScenes() {
    // 1 100, 2 200, 5 500, 11 000 and 20 900 boxes: about evenly spaced in log(bodies).
    return {"pyramid_grid1", "pyramid_grid2", "pyramid_grid5", "pyramid_grid10", "many_pyramids"};
}

std::vector<std::string> expandSceneList(const std::vector<std::string>& names) {
    std::vector<std::string> out;
    auto add = [&](const std::string& n) {
        if (std::find(out.begin(), out.end(), n) == out.end()) out.push_back(n);
    };
    for (const std::string& n : names) {
        if (n == "all" || n == "scaling") {
            if (n == "all")
                for (const std::string& d : defaultScenes()) add(d);
            for (const std::string& d : scalingScenes()) add(d);
        } else {
            makeScene(n);  // throws for an unknown name before any run starts
            add(n);
        }
    }
    return out;
}

}  // namespace peers
