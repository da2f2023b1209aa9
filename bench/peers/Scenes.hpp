#pragma once
// The scenes peer_bench runs, as plain data that each engine turns into its own bodies, so every engine is
// handed the same bodies at the same places. Units: m, kg/m^2, s.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace peers {

// Shared by every scene and engine (docs/performance.md, section "Peers").
constexpr double kGravity = -10.0;     // m/s^2, along y
constexpr double kTimeStep = 1.0 / 60.0;
constexpr double kFriction = 0.6;      // physim's static and dynamic coefficients both, Box2D's one
constexpr double kDensity = 1.0;

/// A point of a static ground chain or loop, m.
struct ChainPoint {
    double x = 0.0;
    double y = 0.0;
};

/// What a shape is made of and what it may touch.
struct Material {
    double density = kDensity;     ///< kg/m^2
    double friction = kFriction;   ///< physim's static and dynamic coefficients both, Box2D's one
    double restitution = 0.0;
    /// Box2D's collision filter, physim's alike: category and mask bits, and a group (a shared negative group
    /// never collides).
    std::uint64_t category = 1, mask = ~std::uint64_t{0};
    int group = 0;
};

/// One shape of a body made of several (ShapeSpec::parts), in the body's frame, m.
struct PartSpec {
    enum class Kind { Polygon, Circle, Capsule, Segment, Loop };
    Kind kind = Kind::Polygon;
    /// Polygon: its corners (convex, any order); Circle: its centre; Capsule and Segment: their two ends; Loop (a
    /// static body's closed chain): its points, counter-clockwise (it holds bodies inside).
    std::vector<ChainPoint> points;
    double radius = 0.0;  ///< Circle and Capsule: the radius; Polygon: how far it is rounded (0: sharp corners)
    Material material;
};

/// A body. Its shape: with `parts`, those; else an axis-aligned box (halfWidth, halfHeight > 0); with radius > 0 a
/// circle; with radius and halfLength > 0 a horizontal capsule (centres at x - halfLength and x + halfLength); with
/// none of these, no shape (a static anchor for a pin). Its origin at (x, y).
struct ShapeSpec {
    double x = 0.0;
    double y = 0.0;
    double halfWidth = 0.0;
    double halfHeight = 0.0;
    double radius = 0.0;
    double halfLength = 0.0;
    double vx = 0.0, vy = 0.0;       ///< starting velocity, m/s (dynamic and kinematic bodies)
    double angularVelocity = 0.0;    ///< rad/s, counter-clockwise (dynamic and kinematic bodies)
    double linearDamping = 0.0;      ///< 1/s: dv/dt = -linearDamping v (Box2D's)
    Material material;               ///< of the one shape (parts carry their own)
    bool asleep = false;             ///< a dynamic body created asleep (scenes with `sleep` on)
    bool allowSleep = true;          ///< false: never sleeps
    std::vector<PartSpec> parts;

    bool isCompound() const { return !parts.empty(); }
    bool isCircle() const { return !isCompound() && radius > 0.0 && halfLength == 0.0; }
    bool isCapsule() const { return !isCompound() && radius > 0.0 && halfLength > 0.0; }
    bool isShapeless() const { return !isCompound() && radius == 0.0 && halfWidth == 0.0 && halfHeight == 0.0; }
};

/// A body of a scene: scene.statics[index] or scene.dynamics[index].
struct BodyRef {
    bool isStatic = false;
    std::size_t index = 0;
};

/// A revolute joint (a pin) between two of the scene's bodies at a world point (x, y), m; never two static ones
/// (physim refuses such a joint, Box2D ignores it: scenes leave it out for both).
/// Angles are B's relative to A's less their value at creation.
struct PinSpec {
    BodyRef a, b;
    double x = 0.0;
    double y = 0.0;
    bool enableLimit = false;
    double lowerAngle = 0.0, upperAngle = 0.0;  ///< rad
    bool enableMotor = false;
    double motorSpeed = 0.0;                    ///< rad/s of B relative to A
    double maxMotorTorque = 0.0;                ///< N m (with speed 0: the joint's friction)
    /// A rotary spring towards springTargetAngle, of springHertz for the joint's effective inertia.
    bool enableSpring = false;
    double springHertz = 0.0, springDampingRatio = 0.0, springTargetAngle = 0.0;
};

/// A kinematic body swept along x (Box2D v3's junkyard pusher): before the world's step n (n steps taken) it is
/// given the velocity that takes it in one step to x = amplitude sin(rate n kTimeStep), as v3's
/// b2Body_SetTargetTransform does.
struct SweepSpec {
    std::size_t kinematic = 0;  ///< index into scene.kinematics
    double amplitude = 0.0;     ///< m
    double rate = 0.0;          ///< rad/s
};

/// Bodies and pins that come and go together (Box2D v3's rain): scene.dynamics [firstBody, firstBody + bodyCount)
/// and scene.pins [firstPin, firstPin + pinCount), which join only bodies of the wave.
struct WaveSpec {
    std::size_t firstBody = 0, bodyCount = 0;
    std::size_t firstPin = 0, pinCount = 0;
};

/// A wheel joint: `wheel` turns freely about its centre, which slides along the world axis (axisX, axisY) (unit)
/// through (x, y) fixed in `chassis`, held by a suspension spring of `hertz` (for the effective mass along the axis at
/// creation) and `dampingRatio`; with a motor, it is driven at motorSpeed (rad/s of the wheel relative to the chassis)
/// within maxMotorTorque (N m).
struct WheelSpec {
    std::size_t chassis = 0, wheel = 0;  ///< indices into scene.dynamics
    double x = 0.0, y = 0.0;
    double axisX = 0.0, axisY = 1.0;
    double hertz = 0.0, dampingRatio = 0.0;
    bool enableMotor = false;
    double motorSpeed = 0.0, maxMotorTorque = 0.0;
};

struct Scene {
    std::string name;
    std::vector<ShapeSpec> statics;
    std::vector<ShapeSpec> dynamics;
    /// A static open chain listed left to right with x increasing, solid below (physim's ChainDef order; Box2D
    /// takes it reversed); empty for scenes without one. Its scenes report how far each body sits above it.
    std::vector<ChainPoint> chain;
    /// Indices into `dynamics` of the top box of each pyramid; empty for scenes without a stack, which then
    /// report no drop, drift or sideways figures.
    std::vector<std::size_t> tops;
    /// Rows of base-10 pyramids: their step times enter the fit of step time against body count.
    bool pyramidGrid = false;
    /// Pins between bodies; scenes with some report their lowest dynamic body's height at the end (stiffness).
    std::vector<PinSpec> pins;
    /// false: no body touches another (no shape collides), as in a scene that measures joints alone.
    bool collisions = true;
    /// Wheel joints; and the index into `dynamics` of each car's chassis, for scenes whose cars report how far they
    /// drove and how many stayed upright at the end.
    std::vector<WheelSpec> wheels;
    std::vector<std::size_t> cars;
    /// Gravity along y (m/s^2), and whether bodies may sleep: the scenes run with kGravity and sleep off, but for
    /// smash (zero gravity, a grid created asleep).
    double gravity = kGravity;
    bool sleep = false;
    /// Kinematic bodies: they move at their starting velocity, pushed by nothing, unless a sweep steers them.
    std::vector<ShapeSpec> kinematics;
    std::vector<SweepSpec> sweeps;
    /// Waves, in order: they hold the last of `dynamics` and of `pins`, which are not made at the start. Before the
    /// world's step n (n steps taken), when n is a multiple of wavePeriod, wave (n / wavePeriod) mod waves.size()
    /// goes, if it is in the world, and is made afresh where its bodies started.
    std::vector<WaveSpec> waves;
    int wavePeriod = 0;
    /// Why Box2D 2.4.1 does not run this scene; empty: it does.
    std::string box2d24Skip;

    /// The wave due before the world's step n, or -1.
    long waveBefore(long n) const {
        if (waves.empty() || wavePeriod <= 0 || n % wavePeriod != 0) return -1;
        return (n / wavePeriod) % static_cast<long>(waves.size());
    }
    /// The first dynamic body and pin that belong to a wave (dynamics.size() and pins.size() without waves).
    std::size_t firstWaveBody() const { return waves.empty() ? dynamics.size() : waves.front().firstBody; }
    std::size_t firstWavePin() const { return waves.empty() ? pins.size() : waves.front().firstPin; }
};

/// The pyramid of base `base` (base * (base + 1) / 2 boxes of half-size 0.5) standing on the ground at
/// height originY, centred on originX, without its ground.
void addPyramid(Scene& scene, int base, double originX, double originY);

/// `pyramid<N>` (large_pyramid is pyramid100): one pyramid on a static ground box of half-size (100, 1).
Scene pyramidScene(const std::string& name, int base);
/// 1000 circles of radius 0.25 dropped into a closed box.
Scene circlesScene();
/// `rows` rows of 20 base-10 pyramids (55 boxes each), each row on its own static ground box;
/// many_pyramids is 19 rows: 20 900 boxes.
Scene pyramidGridScene(const std::string& name, int rows);

/// chain_terrain: 600 circles and capsules, half of each, dropped in four rows onto a bumpy chain of 1 200 pieces
/// (0.25 m each, a sum of three sines, steep at both ends), where they roll into its valleys.
Scene chainTerrainScene();

/// smash, Box2D v3's benchmark of that name: no gravity, sleep on; an 8 m box of density 8 at (-20, 0) moving at
/// 40 m/s along x into a grid of 120 x 80 squares of 0.4 m, created asleep, 0.4 m apart from x = 30, centred on y = 0.
Scene smashScene();
/// joint_grid, Box2D's benchmark of that name: 100 x 100 discs (radius 0.4 m) 1 m apart, column k at x = k, row i
/// at y = -i, each pinned to the disc below and the disc to its right halfway between them; the discs of row 0 in
/// columns 47 to 53 are static, and the grid hangs from them. No collisions. Box2D's six pins between two of those
/// static discs are left out.
Scene jointGridScene();

/// cars: 60 cars (a 2.5 x 0.5 m chassis on two wheels of radius 0.4 m, each on a wheel joint with a vertical
/// suspension spring of 4 Hz, damping ratio 0.7; a motor on the rear wheel of 8 N m at -12 rad/s, to the right)
/// dropped 4.3 m apart onto a rolling chain of 1 200 pieces of 0.25 m (slopes up to 15 degrees, walls at the ends).
Scene carsScene();

/// Box2D v3's benchmark scenes of those names (its shared/benchmarks.c), each with v3's gravity, sleep on (v3's
/// default), and its sizes, counts, densities, frictions and speeds:
/// compounds: 3 000 bodies of two triangles each (friction 0.5) dropped in 20 columns into an 80 m wide box of
/// static boxes, with a floor segment far below.
Scene compoundsScene();
/// junkyard: 8 000 pentagons (radius 0.25 m) in 200 columns of 40 dropped into a 160 m wide box, and a 4 x 8 m
/// kinematic pusher swept along the floor by x = 60 sin(0.2 t) m.
Scene junkyardScene();
/// rain: every 8 steps a column of 25 ragdolls (5 rows, 45 m apart, of 5 side by side) falls from 40 m onto one of
/// 5 floors of boxes; after 40 columns (11 000 bodies), the oldest column goes and falls again.
Scene rainScene();
/// spinner: 6 076 capsules, discs and squares (density 0.25, friction 0.1, restitution 0.1) in a 40 m loop chain,
/// stirred by a 40 m bar turned at 5 rad/s by a motor of unbounded torque.
Scene spinnerScene();
/// tumbler: 2 025 boxes of 0.25 m in a 20 m box of four walls (density 50) turned at 25 degrees/s by a motor.
Scene tumblerScene();
/// washer: 8 100 squares of 0.2 m in a kinematic drum (radius 16 to 18 m, four paddles) turning at 25 degrees/s.
Scene washerScene();

/// The height of the scene's chain at x (m), linear between its points; NaN outside it or without a chain.
double chainHeightAt(const Scene& scene, double x);

/// Mass properties per unit density of a ShapeSpec capsule: area (m^2) and second moment about its centre (m^4),
/// for an engine that has no capsule and stands in a shape of other mass.
struct CapsuleMass {
    double area = 0.0;
    double secondMoment = 0.0;
};
CapsuleMass capsuleMass(double radius, double halfLength);

/// The scene called `name`: large_pyramid, pyramid<N> (N in 1..400), circles1000, many_pyramids,
/// pyramid_grid<R> (R in 1..100 rows), chain_terrain, joint_grid, cars, smash, compounds, junkyard, rain,
/// spinner, tumbler or washer. Throws std::invalid_argument naming an
/// unknown one.
Scene makeScene(const std::string& name);

/// What `--scenes` accepts besides scene names: `all` (the default scenes and the scaling set), `scaling`: grids
/// of 1 100 to 20 900 boxes, for the fit of step time against body count, and `box2d`: Box2D v3's benchmark set.
std::vector<std::string> expandSceneList(const std::vector<std::string>& names);
std::vector<std::string> defaultScenes();
std::vector<std::string> scalingScenes();
std::vector<std::string> box2dScenes();

}  // namespace peers
