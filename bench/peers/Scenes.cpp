#include "Scenes.hpp"

#include "support/Pyramid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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

Scene chainTerrainScene() {
    Scene s;
    s.name = "chain_terrain";
    // Ground: x in [-150, 150] in 1 200 pieces of 0.25 m (a dozen points per wavelength of the shortest sine), a
    // sum of sines of 19, 6.3 and 2.9 m (slopes up to 38 degrees, valleys about every 19 m, so the bodies spread
    // over the whole length), rising as a parabola past |x| = 135 to 11 m at the ends so nothing rolls off.
    constexpr int kPieces = 1200;
    constexpr double kLeft = -150.0, kPiece = 0.25;
    for (int i = 0; i <= kPieces; ++i) {
        const double x = kLeft + kPiece * i;
        const double rim = std::max(0.0, std::abs(x) - 135.0);
        const double y = 0.8 * std::sin(2.0 * M_PI * x / 19.0) + 0.3 * std::sin(2.0 * M_PI * x / 6.3 + 1.0) +
                         0.1 * std::sin(2.0 * M_PI * x / 2.9 + 2.0) + 0.05 * rim * rim;
        s.chain.push_back({x, y});
    }
    // Bodies: 4 rows of 150, 1.75 m apart, from 1.8 m up (the ground stays below 1.2 m there) and 1.3 m between
    // rows; circles (radius 0.25, 0.3 or 0.35 m) and horizontal capsules (radius 0.2 m, centres 0.6 m apart) in a
    // checkerboard: 300 of each.
    constexpr int kRows = 4, kColumns = 150;
    constexpr double kPitch = 1.75;
    for (int row = 0; row < kRows; ++row)
        for (int col = 0; col < kColumns; ++col) {
            ShapeSpec b;
            b.x = (col - 0.5 * (kColumns - 1)) * kPitch;
            b.y = 1.8 + 1.3 * row;
            if ((row + col) % 2 == 0) {
                b.radius = 0.25 + 0.05 * (col % 3);
            } else {
                b.radius = 0.2;
                b.halfLength = 0.3;
            }
            s.dynamics.push_back(b);
        }
    return s;
}

Scene jointGridScene() {
    constexpr int kSide = 100;
    constexpr int kFirstStatic = kSide / 2 - 3, kLastStatic = kSide / 2 + 3;  // top row: 7 static discs
    Scene s;
    s.name = "joint_grid";
    s.collisions = false;
    // Bodies column by column, each column top down (Box2D's order of creation); where each one went.
    std::vector<BodyRef> at(static_cast<std::size_t>(kSide * kSide));
    for (int k = 0; k < kSide; ++k)
        for (int i = 0; i < kSide; ++i) {
            ShapeSpec disc;
            disc.x = k;
            disc.y = -i;
            disc.radius = 0.4;
            const bool fixed = i == 0 && k >= kFirstStatic && k <= kLastStatic;
            std::vector<ShapeSpec>& list = fixed ? s.statics : s.dynamics;
            at[static_cast<std::size_t>(k * kSide + i)] = {fixed, list.size()};
            list.push_back(disc);
        }
    auto pin = [&](int k0, int i0, int k1, int i1) {
        const BodyRef a = at[static_cast<std::size_t>(k0 * kSide + i0)], b = at[static_cast<std::size_t>(k1 * kSide + i1)];
        if (a.isStatic && b.isStatic) return;
        s.pins.push_back({a, b, 0.5 * (k0 + k1), -0.5 * (i0 + i1)});
    };
    for (int k = 0; k < kSide; ++k)
        for (int i = 0; i < kSide; ++i) {
            if (i > 0) pin(k, i - 1, k, i);  // to the disc above
            if (k > 0) pin(k - 1, i, k, i);  // to the disc on the left
        }
    return s;
}

Scene smashScene() {
    Scene s;
    s.name = "smash";
    s.gravity = 0.0;
    s.sleep = true;
    ShapeSpec ram;
    ram.x = -20.0;
    ram.halfWidth = ram.halfHeight = 4.0;
    ram.vx = 40.0;
    ram.density = 8.0;
    s.dynamics.push_back(ram);
    constexpr int kColumns = 120, kRows = 80;
    constexpr double kSide = 0.4;
    for (int i = 0; i < kColumns; ++i)
        for (int j = 0; j < kRows; ++j) {
            ShapeSpec square;
            square.x = 30.0 + i * kSide;
            square.y = (j - 0.5 * kRows) * kSide;
            square.halfWidth = square.halfHeight = 0.5 * kSide;
            square.asleep = true;
            s.dynamics.push_back(square);
        }
    return s;
}

Scene carsScene() {
    Scene s;
    s.name = "cars";
    // Ground: x in [-150, 150] in 1 200 pieces of 0.25 m, rolling hills (sines of 23, 7.7 and 3.1 m, slopes up to
    // 15 degrees: the rear-driven cars climb them within the tyres' friction), rising as a parabola past
    // |x| = 135 to 22.5 m at the ends, too steep for a car to climb out.
    constexpr int kPieces = 1200;
    constexpr double kLeft = -150.0, kPiece = 0.25;
    for (int i = 0; i <= kPieces; ++i) {
        const double x = kLeft + kPiece * i;
        const double rim = std::max(0.0, std::abs(x) - 135.0);
        const double y = 0.4 * std::sin(2.0 * M_PI * x / 23.0) + 0.12 * std::sin(2.0 * M_PI * x / 7.7 + 1.0) +
                         0.03 * std::sin(2.0 * M_PI * x / 3.1 + 2.0) + 0.1 * rim * rim;
        s.chain.push_back({x, y});
    }
    // Cars, 4.3 m apart from x = -130, each dropped with its wheels 0.1 m above the highest ground under it. A car:
    // chassis of half-size (1.25, 0.25) (1.25 kg), wheels of radius 0.4 m (0.50 kg) whose centres hang 0.5 m below
    // the chassis's centre and 0.9 m to either side (they overlap the chassis: joined bodies do not collide).
    constexpr int kCars = 60;
    constexpr double kSpacing = 4.3, kFirst = -130.0;
    constexpr double kHalfWidth = 1.25, kHalfHeight = 0.25, kWheelRadius = 0.4, kAxleX = 0.9, kAxleDrop = 0.5;
    for (int c = 0; c < kCars; ++c) {
        const double x = kFirst + kSpacing * c;
        double ground = -std::numeric_limits<double>::infinity();
        for (double u = x - kHalfWidth - 0.2; u <= x + kHalfWidth + 0.2; u += 0.05)
            ground = std::max(ground, chainHeightAt(s, u));
        const double y = ground + 0.1 + kWheelRadius + kAxleDrop;
        s.cars.push_back(s.dynamics.size());
        const std::size_t chassis = s.dynamics.size();
        s.dynamics.push_back(box(x, y, kHalfWidth, kHalfHeight));
        for (double side : {-1.0, 1.0}) {  // rear (left) then front
            ShapeSpec wheel;
            wheel.x = x + side * kAxleX;
            wheel.y = y - kAxleDrop;
            wheel.radius = kWheelRadius;
            WheelSpec j;
            j.chassis = chassis;
            j.wheel = s.dynamics.size();
            j.x = wheel.x;
            j.y = wheel.y;
            j.hertz = 4.0;
            j.dampingRatio = 0.7;
            j.enableMotor = side < 0.0;  // rear-wheel drive, rolling to the right (clockwise: negative)
            j.motorSpeed = j.enableMotor ? -10.0 : 0.0;
            j.maxMotorTorque = j.enableMotor ? 4.0 : 0.0;
            s.wheels.push_back(j);
            s.dynamics.push_back(wheel);
        }
    }
    return s;
}

double chainHeightAt(const Scene& scene, double x) {
    const std::vector<ChainPoint>& c = scene.chain;
    if (c.size() < 2 || !(x >= c.front().x && x <= c.back().x)) return std::numeric_limits<double>::quiet_NaN();
    const auto right = std::lower_bound(c.begin() + 1, c.end() - 1, x,
                                        [](const ChainPoint& p, double value) { return p.x < value; });
    const ChainPoint& a = *(right - 1);
    const ChainPoint& b = *right;
    return a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
}

CapsuleMass capsuleMass(double radius, double halfLength) {
    // A 2L x 2r rectangle and two half discs at x = +-L, each half disc's centroid 4 r / (3 pi) beyond its flat side.
    const double r = radius, L = halfLength;
    const double rectangle = 4.0 * L * r * (L * L + r * r) / 3.0;
    const double halfDiscs = M_PI * r * r * r * r / 2.0 + M_PI * r * r * L * L + 8.0 * L * r * r * r / 3.0;
    return {4.0 * L * r + M_PI * r * r, rectangle + halfDiscs};
}

Scene makeScene(const std::string& name) {
    if (name == "large_pyramid") return pyramidScene(name, 100);
    if (name == "circles1000") return circlesScene();
    if (name == "many_pyramids") return pyramidGridScene(name, 19);
    if (name == "chain_terrain") return chainTerrainScene();
    if (name == "joint_grid") return jointGridScene();
    if (name == "cars") return carsScene();
    if (name == "smash") return smashScene();
    const int base = numberAfter("pyramid", name);
    if (base >= 1 && base <= 400) return pyramidScene(name, base);
    const int rows = numberAfter("pyramid_grid", name);
    if (rows >= 1 && rows <= 100) return pyramidGridScene(name, rows);
    throw std::invalid_argument("unknown scene '" + name +
                                "' (large_pyramid, pyramid<N> with N in 1..400, circles1000, many_pyramids, "
                                "pyramid_grid<R> with R in 1..100, chain_terrain, joint_grid, cars, smash, scaling, all)");
}

std::vector<std::string> defaultScenes() {
    return {"large_pyramid", "pyramid20",     "pyramid40",  "circles1000",
            "many_pyramids", "chain_terrain", "joint_grid", "cars"};
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
