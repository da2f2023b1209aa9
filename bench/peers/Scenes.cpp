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


// Box2D v3's benchmark scenes. Their grounds are single static bodies of many parts, as v3 builds them.

PartSpec polygonPart(std::vector<ChainPoint> points, const Material& m = {}, double radius = 0.0) {
    PartSpec p;
    p.points = std::move(points);
    p.radius = radius;
    p.material = m;
    return p;
}

PartSpec boxPart(double x, double y, double halfWidth, double halfHeight, const Material& m = {}) {
    return polygonPart({{x - halfWidth, y - halfHeight},
                        {x + halfWidth, y - halfHeight},
                        {x + halfWidth, y + halfHeight},
                        {x - halfWidth, y + halfHeight}},
                       m);
}

PartSpec capsulePart(double x1, double y1, double x2, double y2, double radius, const Material& m) {
    PartSpec p;
    p.kind = PartSpec::Kind::Capsule;
    p.points = {{x1, y1}, {x2, y2}};
    p.radius = radius;
    p.material = m;
    return p;
}

// A static ground of boxes 1 m apart: a floor at y = 0 of `floor` boxes of half-size (0.55, 0.5) centred on x = 0,
// and on each side a wall of `wall` boxes of half-size (0.5, 0.55) from y = 1 up, at x = +-halfSpan.
ShapeSpec boxedGround(int floor, int wall, double halfSpan) {
    ShapeSpec g;
    for (int i = 0; i < floor; ++i) g.parts.push_back(boxPart(-halfSpan + i, 0.0, 0.55, 0.5));
    for (double side : {-1.0, 1.0})
        for (int i = 0; i < wall; ++i) g.parts.push_back(boxPart(side * halfSpan, 1.0 + i, 0.5, 0.55));
    return g;
}

ShapeSpec shapeless(double x, double y) {
    ShapeSpec s;
    s.x = x;
    s.y = y;
    return s;
}

// A pin whose motor turns B against the static body A at `speed` (rad/s) within `torque` (N m).
PinSpec motorPin(std::size_t staticIndex, std::size_t dynamicIndex, double x, double y, double speed, double torque) {
    PinSpec p;
    p.a = {true, staticIndex};
    p.b = {false, dynamicIndex};
    p.x = x;
    p.y = y;
    p.enableMotor = true;
    p.motorSpeed = speed;
    p.maxMotorTorque = torque;
    return p;
}

constexpr double kDegree = M_PI / 180.0;
constexpr double kUnbounded = 3.4028234663852886e38;  // N m: FLT_MAX, v3's "no bound" (finite for both engines)


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
    ram.material.density = 8.0;
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

Scene compoundsScene() {
    Scene s;
    s.name = "compounds";
    s.sleep = true;
    ShapeSpec ground = boxedGround(81, 100, 40.0);
    PartSpec floor;  // far below, out of reach: v3 has it, so its broad phase carries it too
    floor.kind = PartSpec::Kind::Segment;
    floor.points = {{-800.0, -80.0}, {800.0, -80.0}};
    ground.parts.push_back(floor);
    s.statics.push_back(ground);
    // Two triangles meeting on the body's axis, a tent 2 m wide and 2 m tall; columns 2 m apart, rows 2.25 m,
    // each body 0.25 m off its column's axis, to the right and left in turn.
    Material m;
    m.friction = 0.5;
    const PartSpec left = polygonPart({{-1.0, 0.0}, {0.5, 1.0}, {0.0, 2.0}}, m);
    const PartSpec right = polygonPart({{1.0, 0.0}, {-0.5, 1.0}, {0.0, 2.0}}, m);
    constexpr int kColumns = 20, kRows = 150;
    double side = 0.25;
    for (int i = 0; i < kColumns; ++i)
        for (int j = 0; j < kRows; ++j) {
            ShapeSpec b;
            b.x = 2.0 * i - (kColumns - 1.0) + side;
            b.y = 2.25 * j + 0.575 + 5.0;
            b.parts = {left, right};
            s.dynamics.push_back(b);
            side = -side;
        }
    return s;
}

Scene junkyardScene() {
    Scene s;
    s.name = "junkyard";
    s.sleep = true;
    s.box2d24Skip = "once its kinematic pusher ploughs into the pile it takes over 0.5 s a step here: its continuous "
                    "pass rescans every contact for each time-of-impact event";
    s.statics.push_back(boxedGround(161, 50, 80.0));
    // A pentagon inscribed in a circle of 0.25 m, its corners at multiples of pi (sqrt 5 - 1) rad (v3's points).
    constexpr double kRadius = 0.25;
    std::vector<ChainPoint> corners;
    for (int i = 0; i < 5; ++i) {
        const double theta = M_PI * (std::sqrt(5.0) - 1.0) * i;
        corners.push_back({kRadius * std::cos(theta), kRadius * std::sin(theta)});
    }
    const PartSpec pentagon = polygonPart(corners);
    constexpr int kColumns = 200, kRows = 40;
    double side = -0.1;
    for (int i = 0; i < kColumns; ++i)
        for (int j = 0; j < kRows; ++j) {
            ShapeSpec b;
            b.x = 1.5 * (2.0 * i - kColumns) * kRadius + side;
            b.y = 4.0 * j * kRadius + 15.0;
            b.parts = {pentagon};
            s.dynamics.push_back(b);
            side = -side;
        }
    ShapeSpec pusher;
    pusher.parts = {boxPart(0.0, 4.0, 2.0, 4.0)};
    s.kinematics.push_back(pusher);
    s.sweeps.push_back({0, 60.0, 0.2});
    return s;
}

namespace {

// A ragdoll of 11 capsules standing with its feet at (x, y), after v3's human at scale 1: hip, torso, head, two
// legs of two bones (the lower one with a foot that touches only the ground), two arms of two bones. Each joint has
// limits, a friction of 0.05 N m times the bone's share (a motor held at speed 0) and a 5 Hz spring of damping
// ratio 0.5 towards the standing pose. Shapes: category 2, touching the ground (1) and other ragdolls (2) but
// never those of the same negative group.
void addRagdoll(Scene& s, double x, double y, int group) {
    Material flesh;
    flesh.friction = 0.2;
    flesh.category = 2;
    flesh.mask = 1 | 2;
    flesh.group = group;
    Material sole = flesh;
    sole.friction = 0.05;
    sole.mask = 1;
    constexpr double kJointFriction = 0.05;  // N m

    // A bone: a vertical capsule from y0 to y1 (body frame) of radius r, its body at height h above the feet.
    auto bone = [&](double h, double y0, double y1, double r, double damping) {
        ShapeSpec b;
        b.x = x;
        b.y = y + h;
        b.linearDamping = damping;
        b.parts = {capsulePart(0.0, y0, 0.0, y1, r, flesh)};
        s.dynamics.push_back(b);
        return s.dynamics.size() - 1;
    };
    // A joint between two of this ragdoll's bones at height h, limits in units of pi; frictionShare scales the
    // joint friction. Angles relative to the pose at creation.
    auto joint = [&](std::size_t a, std::size_t b, double h, double lower, double upper, double frictionShare,
                     double target = 0.0) {
        PinSpec p;
        p.a = {false, a};
        p.b = {false, b};
        p.x = x;
        p.y = y + h;
        p.enableLimit = true;
        p.lowerAngle = lower * M_PI;
        p.upperAngle = upper * M_PI;
        p.enableMotor = true;
        p.maxMotorTorque = frictionShare * kJointFriction;
        p.enableSpring = true;
        p.springHertz = 5.0;
        p.springDampingRatio = 0.5;
        p.springTargetAngle = target;
        s.pins.push_back(p);
    };
    const std::size_t hip = bone(0.95, -0.02, 0.02, 0.095, 0.0);
    const std::size_t torso = bone(1.2, -0.135, 0.135, 0.09, 0.0);
    joint(hip, torso, 1.0, -0.25, 0.0, 0.5);
    const std::size_t head = bone(1.475, -0.038, 0.039, 0.075, 0.1);
    joint(torso, head, 1.4, -0.3, 0.1, 0.25);
    const PartSpec foot = polygonPart({{-0.03, -0.185}, {0.11, -0.185}, {0.11, -0.16}, {-0.03, -0.14}}, sole, 0.015);
    for (int leg = 0; leg < 2; ++leg) {
        const std::size_t upper = bone(0.775, -0.125, 0.125, 0.06, 0.0);
        joint(hip, upper, 0.9, -0.05, 0.4, 1.0);
        const std::size_t lower = bone(0.475, -0.155, 0.125, 0.045, 0.0);
        s.dynamics[lower].parts.push_back(foot);
        joint(upper, lower, 0.625, -0.5, -0.02, 0.5);
    }
    for (int arm = 0; arm < 2; ++arm) {
        const std::size_t upper = bone(1.225, -0.125, 0.125, 0.035, 0.0);
        joint(torso, upper, 1.35, -0.1, 0.8, 0.5);
        const std::size_t lower = bone(0.975, -0.125, 0.125, 0.03, 0.1);
        // v3 measures the elbow from a frame turned 45 degrees: its limits -0.2 pi..0.3 pi and its spring's rest
        // at 0 there are 0.05 pi..0.55 pi and 45 degrees from the straight arm the ragdoll is made with.
        joint(upper, lower, 1.1, 0.05, 0.55, 0.1, 0.25 * M_PI);
    }
}

}  // namespace

Scene rainScene() {
    Scene s;
    s.name = "rain";
    s.sleep = true;
    constexpr int kRows = 5, kColumns = 40, kGroup = 5, kGridCount = 500;
    constexpr double kGrid = 0.5, kRowPitch = 45.0;
    // Five floors, 45 m apart, each of 501 boxes of 0.5 m side by side.
    ShapeSpec ground;
    for (int r = 0; r < kRows; ++r)
        for (int j = 0; j <= kGridCount; ++j)
            ground.parts.push_back(boxPart(-0.5 * kGridCount * kGrid + j * kGrid, r * kRowPitch, 0.5 * kGrid, 0.5 * kGrid));
    s.statics.push_back(ground);
    // A wave is a column: on each floor a group of 5 ragdolls 0.5 m apart, 40 m above it.
    const double span = kGridCount * kGrid, columnPitch = span / kColumns;
    for (int c = 0; c < kColumns; ++c) {
        WaveSpec w;
        w.firstBody = s.dynamics.size();
        w.firstPin = s.pins.size();
        for (int r = 0; r < kRows; ++r)
            for (int k = 0; k < kGroup; ++k)
                addRagdoll(s, -0.5 * span + columnPitch * (c + 0.5) + 0.5 * k, 40.0 + kRowPitch * r, -(k + 1));
        w.bodyCount = s.dynamics.size() - w.firstBody;
        w.pinCount = s.pins.size() - w.firstPin;
        s.waves.push_back(w);
    }
    s.wavePeriod = 8;
    return s;
}

Scene spinnerScene() {
    Scene s;
    s.name = "spinner";
    s.sleep = true;
    s.box2d24Skip = "it takes seconds a step here: its continuous pass rescans every contact for each time-of-impact "
                    "event, and without it (0.4 s a step) bodies leave the loop";
    // The ground: a loop of 360 points on a circle of 40 m about (0, 32). The bar is pinned to it, so the two never
    // collide (the bar's rounded ends reach 0.2 m past the loop's bottom).
    constexpr int kPoints = 360;
    PartSpec loop;
    loop.kind = PartSpec::Kind::Loop;
    loop.material.friction = 0.1;
    for (int i = 0; i < kPoints; ++i) {
        const double a = 2.0 * M_PI * i / kPoints;
        loop.points.push_back({40.0 * std::cos(a), 32.0 + 40.0 * std::sin(a)});
    }
    ShapeSpec ground;
    ground.parts = {loop};
    s.statics.push_back(ground);
    // The bar: 0.8 x 40 m rounded by 0.2 m, frictionless, pinned at its centre (0, 12).
    ShapeSpec bar;
    bar.y = 12.0;
    bar.allowSleep = false;
    Material smooth;
    smooth.friction = 0.0;
    PartSpec core = polygonPart({{-0.4, -20.0}, {0.4, -20.0}, {0.4, 20.0}, {-0.4, 20.0}}, smooth, 0.2);
    bar.parts = {core};
    s.dynamics.push_back(bar);
    s.pins.push_back(motorPin(0, 0, 0.0, 12.0, 5.0, kUnbounded));
    // Capsules (radius 0.25 m, centres 0.5 m apart), discs (radius 0.35 m) and squares (0.7 m) in turn, in rows of
    // 92 from (-23, 2), 0.5 m apart: neighbours start overlapping, and push apart in the first steps.
    Material m;
    m.density = 0.25;
    m.friction = 0.1;
    m.restitution = 0.1;
    constexpr int kBodies = 2 * 3038;
    double x = -23.0, y = 2.0;
    for (int i = 0; i < kBodies; ++i) {
        ShapeSpec b;
        b.x = x;
        b.y = y;
        b.material = m;
        if (i % 3 == 0) {
            b.radius = 0.25;
            b.halfLength = 0.25;
        } else if (i % 3 == 1) {
            b.radius = 0.35;
        } else {
            b.halfWidth = b.halfHeight = 0.35;
        }
        s.dynamics.push_back(b);
        x += 0.5;
        if (x >= 23.0) {
            x = -23.0;
            y += 0.5;
        }
    }
    return s;
}

Scene tumblerScene() {
    Scene s;
    s.name = "tumbler";
    s.sleep = true;
    s.statics.push_back(shapeless(0.0, 0.0));
    // The drum: four walls 1 m thick around a 20 m square, density 50, about (0, 10).
    ShapeSpec drum;
    drum.y = 10.0;
    Material heavy;
    heavy.density = 50.0;
    drum.parts = {boxPart(10.0, 0.0, 0.5, 10.0, heavy), boxPart(-10.0, 0.0, 0.5, 10.0, heavy),
                  boxPart(0.0, 10.0, 10.0, 0.5, heavy), boxPart(0.0, -10.0, 10.0, 0.5, heavy)};
    s.dynamics.push_back(drum);
    s.pins.push_back(motorPin(0, 0, 0.0, 10.0, 25.0 * kDegree, 1e8));
    constexpr int kGrid = 45;
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j)
            s.dynamics.push_back(box(-0.2 * kGrid + 0.4 * j, -0.2 * kGrid + 10.0 + 0.4 * i, 0.125, 0.125));
    return s;
}

Scene washerScene() {
    Scene s;
    s.name = "washer";
    s.sleep = true;
    s.box2d24Skip = "it takes 2 to 20 s a step here: each new pair walks the drum's contact list (thousands), and "
                    "its continuous pass rescans every contact for each time-of-impact event";
    // The drum, kinematic, about (0, 10): a ring from 16 to 18 m of 36 pieces of 10 degrees, each reaching 1 degree
    // into both neighbours (no seams), and four paddles from 14 to 16 m, every 90 degrees. It drifts by (1, -2) mm/s
    // as v3's does.
    ShapeSpec drum;
    drum.y = 10.0;
    drum.vx = 0.001;
    drum.vy = -0.002;
    drum.angularVelocity = 25.0 * kDegree;
    constexpr double kR0 = 14.0, kR1 = 16.0, kR2 = 18.0, kPiece = M_PI / 18.0, kGap = 0.1 * kPiece;
    auto at = [](double r, double a) { return ChainPoint{r * std::cos(a), r * std::sin(a)}; };
    for (int i = 0; i < 36; ++i) {
        const double a1 = i * kPiece, a2 = (i + 1) * kPiece;
        drum.parts.push_back(polygonPart({at(kR1, a1 - kGap), at(kR2, a1 - kGap), at(kR1, a2 + kGap), at(kR2, a2 + kGap)}));
        if (i % 9 == 0) drum.parts.push_back(polygonPart({at(kR0, a1), at(kR1, a1), at(kR0, a2), at(kR1, a2)}));
    }
    s.kinematics.push_back(drum);
    constexpr int kGrid = 90;
    constexpr double kHalf = 0.1;
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j)
            s.dynamics.push_back(box(-1.1 * kHalf * kGrid + 2.1 * kHalf * j, -1.1 * kHalf * kGrid + 10.0 + 2.1 * kHalf * i,
                                     kHalf, kHalf));
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
    if (name == "compounds") return compoundsScene();
    if (name == "junkyard") return junkyardScene();
    if (name == "rain") return rainScene();
    if (name == "spinner") return spinnerScene();
    if (name == "tumbler") return tumblerScene();
    if (name == "washer") return washerScene();
    const int base = numberAfter("pyramid", name);
    if (base >= 1 && base <= 400) return pyramidScene(name, base);
    const int rows = numberAfter("pyramid_grid", name);
    if (rows >= 1 && rows <= 100) return pyramidGridScene(name, rows);
    throw std::invalid_argument("unknown scene '" + name +
                                "' (large_pyramid, pyramid<N> with N in 1..400, circles1000, many_pyramids, "
                                "pyramid_grid<R> with R in 1..100, chain_terrain, joint_grid, cars, smash, compounds, "
                                "junkyard, rain, spinner, tumbler, washer, scaling, box2d, all)");
}

std::vector<std::string> defaultScenes() {
    return {"large_pyramid", "pyramid20",     "pyramid40",  "circles1000",
            "many_pyramids", "chain_terrain", "joint_grid", "cars"};
}

std::vector<std::string> scalingScenes() {
    // 1 100, 2 200, 5 500, 11 000 and 20 900 boxes: about evenly spaced in log(bodies).
    return {"pyramid_grid1", "pyramid_grid2", "pyramid_grid5", "pyramid_grid10", "many_pyramids"};
}

std::vector<std::string> box2dScenes() {
    // Box2D v3's benchmark program's scenes, in its order.
    return {"compounds",     "joint_grid", "junkyard", "large_pyramid", "many_pyramids",
            "rain",          "smash",      "spinner",  "tumbler",       "washer"};
}

std::vector<std::string> expandSceneList(const std::vector<std::string>& names) {
    std::vector<std::string> out;
    auto add = [&](const std::string& n) {
        if (std::find(out.begin(), out.end(), n) == out.end()) out.push_back(n);
    };
    for (const std::string& n : names) {
        if (n == "box2d") {
            for (const std::string& d : box2dScenes()) add(d);
        } else if (n == "all" || n == "scaling") {
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
