// Debug drawing rendered off screen (needs a display for the OpenGL context: run under Xvfb by
// tests/support/with-display.sh), checked pixel by pixel where each item must appear: a contact point's dot,
// a resting contact's ring, a bounding box's edge, a velocity arrow, a joint's line, a centre's cross, and the
// veil over a sleeping body (every shape of it, a segment as a line), over chain ground too; and each joint kind's
// marks.

#include <physim/core/World.hpp>
#include <physim/framework/DebugDraw.hpp>
#include "support/Scenes.hpp"

#include <SFML/Graphics/RenderTexture.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;

// Background white; the view maps the world origin to the texture's centre at 100 px/m.
struct Canvas {
    sf::RenderTexture texture;
    View view;
    sf::Image image;

    Canvas() { EXPECT_TRUE(texture.create(800, 600)); }
    void draw(const World& world, const DebugDrawOptions& options, const char* name) {
        texture.clear(sf::Color::White);
        drawDebug(texture, view, world, options);
        texture.display();
        image = texture.getTexture().copyToImage();
        if (const char* dir = std::getenv("PHYSIM_TEST_SHOTS"))
            image.saveToFile(std::string(dir) + "/" + name + ".png");
    }
    sf::Color at(const Vec2& world) const {
        const sf::Vector2f p = view.worldToPixels(texture.getSize()).transformPoint(float(world.x()), float(world.y()));
        return image.getPixel(static_cast<unsigned>(std::lround(p.x)), static_cast<unsigned>(std::lround(p.y)));
    }
};

bool reddish(sf::Color c) { return c.r > 150 && c.g < 120 && c.b < 120; }

BodyId ground(World& world) { return test::addStaticBox(world, {0.0, -2.25}, 3.5, 0.25); }  // top at y = -2

TEST(DebugDrawWindow, ContactsAwakeAndResting) {
    World world;
    ground(world);
    BodyDef box;
    box.shape = makeBox(0.5, 0.5);
    box.position = {-1.5, -1.5};
    box.allowSleep = false;  // stays awake: its contacts are the step's
    world.createBody(box);
    box.position = {1.5, -1.5};
    box.allowSleep = true;
    const BodyId sleeper = world.createBody(box);
    for (int i = 0; i < 120; ++i) world.step(kDt);
    world.step(kDt);
    ASSERT_FALSE(world.isAwake(sleeper));
    ASSERT_EQ(world.contacts().size(), 1u) << "only the awake box's contact is computed by the step";

    Canvas canvas;
    DebugDrawOptions options;
    options.contacts = true;
    canvas.draw(world, options, "debug_contacts");
    // Each box touches the ground at its two bottom corners, y = -2 (within the 5 mm slop: under a pixel).
    // (Sampled 2.5 px beside each point: the normal's 2 px line covers the point itself.)
    EXPECT_TRUE(reddish(canvas.at({-2.0 + 0.025, -2.0}))) << "awake contact point: a red dot";
    EXPECT_TRUE(reddish(canvas.at({-1.0 + 0.025, -2.0})));
    const sf::Color ring = canvas.at({1.0 + 0.03, -2.0});
    EXPECT_NE(ring, sf::Color::White) << "resting contact point: a ring";
    EXPECT_LT(ring.r - ring.g, 150) << "faded, not the awake red";
    // The normal points from the ground (A) up into the box: blue above the point, nothing below it.
    const sf::Color normal = canvas.at({-2.0, -2.0 + 0.2});
    EXPECT_GT(normal.b, 150);
    EXPECT_LT(normal.r, 120);
    EXPECT_EQ(canvas.at({-2.0, -2.0 - 0.2}), sf::Color::White);
}

TEST(DebugDrawWindow, BoxesVelocitiesJointsCentresAndSleep) {
    WorldSettings settings;
    settings.gravity = Vec2::Zero();
    World world(settings);
    BodyDef def;
    def.shape = makeBox(0.5, 0.5);
    def.angle = M_PI / 4;  // its box is wider than the shape: the corners of the box are empty space
    def.position = {-2.0, 1.0};
    world.createBody(def);
    def.angle = 0.0;
    def.position = {0.0, 1.0};
    def.velocity = {10.0, 0.0};  // arrow of 1 m (0.1 s of travel) to the right
    const BodyId mover = world.createBody(def);
    def.velocity = Vec2::Zero();
    def.position = {2.0, -1.0};
    const BodyId sleeper = world.createBody(def);
    world.setAwake(sleeper, false);
    def.type = BodyType::Static;
    def.position = {-2.0, -1.5};
    const BodyId anchor = world.createBody(def);
    DistanceJointDef rod;
    rod.bodyA = anchor;
    rod.bodyB = mover;
    const JointId joint = world.createDistanceJoint(rod);
    const auto [a, b] = world.jointAnchors(joint);

    Canvas canvas;
    DebugDrawOptions options;
    options.boxes = options.velocities = options.joints = options.centres = options.sleep = true;
    canvas.draw(world, options, "debug_items");
    const double h = 0.5 * std::sqrt(2.0);  // the rotated box's half-size
    const sf::Color box = canvas.at({-2.0 - h, 1.0 + 0.3});
    EXPECT_GT(box.r, 150) << "bounding box edge: magenta";
    EXPECT_GT(box.b, 150);
    EXPECT_LT(box.g, 80);
    const sf::Color arrow = canvas.at({0.5, 1.0});
    EXPECT_GT(arrow.g, 100) << "velocity arrow: green";
    EXPECT_LT(arrow.r, 80);
    EXPECT_EQ(canvas.at({0.0, 1.0 + 0.3}), sf::Color::White) << "nothing drawn inside the moving box";
    const sf::Color line = canvas.at(0.5 * (a + b));
    EXPECT_LT(line.r, 80) << "joint line: teal";
    EXPECT_GT(line.g, 90);
    EXPECT_GT(line.b, 90);
    EXPECT_LT(canvas.at({-2.0, 1.0 + 0.04}).r, 60) << "centre of mass: a dark cross";
    const sf::Color veil = canvas.at({2.2, -0.8});
    EXPECT_LT(veil.r, 255) << "the sleeping body is veiled";
    EXPECT_GT(veil.r, 200) << "lightly";
}

// Chain ground (a body with no first shape) and a sleeping compound body: a box and a segment sticking out of it.
// Every shape is veiled, the segment as a line (its outline is two points, which a filled polygon draws as
// nothing); the ground's bounding box is that of its chain.
TEST(DebugDrawWindow, ChainGroundAndCompoundSleeperSegmentAsLine) {
    World world;
    BodyDef groundDef;
    groundDef.type = BodyType::Static;
    groundDef.withShape = false;
    const BodyId chainGround = world.createBody(groundDef);
    ChainDef chain;
    chain.points = {{-3.0, -2.0}, {0.0, -2.0}, {3.0, -2.0}};
    world.createChain(chainGround, chain);
    BodyDef def;
    def.shape = makeBox(0.5, 0.5);
    def.position = {0.0, -1.5};
    const BodyId sleeper = world.createBody(def);
    ShapeDef stick;
    stick.geometry = makeSegment({0.5, 0.0}, {1.5, 0.0});  // body frame: from the box's right face outwards
    world.createShape(sleeper, stick);
    world.setAwake(sleeper, false);

    Canvas canvas;
    DebugDrawOptions options;
    options.boxes = options.contacts = options.centres = options.sleep = true;
    canvas.draw(world, options, "debug_chain_compound");
    const auto veiled = [](sf::Color c) { return c.r < 255 && c.r > 200; };  // lightly, as above
    EXPECT_TRUE(veiled(canvas.at({0.2, -1.7}))) << "the box, veiled";
    // The segment's 2 px line, on the pixel row of y = -1.5 or the one beside it.
    EXPECT_TRUE(veiled(canvas.at({1.2, -1.5})) || veiled(canvas.at({1.2, -1.51}))) << "the segment, a veiled line";
    EXPECT_EQ(canvas.at({1.2, -1.45}), sf::Color::White) << "a line, not a filled area";
    const sf::Color edge = canvas.at({-2.5, -2.0});  // the chain's box is flat: its edges lie on the chain
    EXPECT_GT(edge.r, 150);
    EXPECT_LT(edge.g, 60) << "the box colour (magenta) along the chain";
}

// Every joint kind drawn so its kind shows (DebugDrawOptions::joints), checked where each mark must be and where
// nothing must be. Nothing steps: the joints are as created. The view is 100 px/m, so 0.01 m is a pixel; samples
// sit on a mark's centre line (its lines are 2 px wide), and the empty ones at least 5 px from any mark.
TEST(DebugDrawWindow, JointKindsRevolutePrismaticWheelPulleyGearWeld) {
    WorldSettings settings;
    settings.gravity = Vec2::Zero();
    World world(settings);
    BodyDef groundDef;
    groundDef.type = BodyType::Static;
    groundDef.shape = makeBox(0.1, 0.1);
    groundDef.position = {0.0, -2.8};
    const BodyId ground = world.createBody(groundDef);
    BodyDef def;
    def.shape = makeCircle(0.1);
    const auto body = [&](const Vec2& at) {
        def.position = at;
        return world.createBody(def);
    };

    RevoluteJointDef pin;  // limits -45 and +90 degrees; A static at angle 0, so the rays point there
    pin.bodyA = ground;
    pin.bodyB = body({-3.0, 2.0});
    pin.anchor = {-3.0, 2.0};
    pin.enableLimit = true;
    pin.lowerAngle = -M_PI / 4;
    pin.upperAngle = M_PI / 2;
    world.createRevoluteJoint(pin);

    PrismaticJointDef slider;  // along x, limits -0.5 and 0.8 m
    slider.bodyA = ground;
    slider.bodyB = body({0.0, 2.0});
    slider.anchor = {0.0, 2.0};
    slider.enableLimit = true;
    slider.lowerTranslation = -0.5;
    slider.upperTranslation = 0.8;
    world.createPrismaticJoint(slider);

    WheelJointDef wheel;  // along y, no limits
    wheel.bodyA = ground;
    wheel.bodyB = body({3.0, 2.0});
    wheel.anchor = {3.0, 2.0};
    world.createWheelJoint(wheel);

    PulleyJointDef pulley;
    pulley.bodyA = body({-3.0, -2.5});
    pulley.bodyB = body({-1.0, -2.5});
    pulley.groundAnchorA = {-3.0, -1.0};
    pulley.groundAnchorB = {-1.0, -1.0};
    world.createPulleyJoint(pulley);

    RevoluteJointDef axle;  // two discs on axles, geared
    axle.bodyA = ground;
    axle.bodyB = body({1.5, -2.0});
    axle.anchor = {1.5, -2.0};
    const JointId axle1 = world.createRevoluteJoint(axle);
    axle.bodyB = body({3.0, -2.0});
    axle.anchor = {3.0, -2.0};
    const JointId axle2 = world.createRevoluteJoint(axle);
    GearJointDef gear;
    gear.joint1 = axle1;
    gear.joint2 = axle2;
    gear.ratio = 2.0;
    world.createGearJoint(gear);

    WeldJointDef weld;
    weld.bodyA = body({-0.5, 0.0});
    weld.bodyB = body({0.5, 0.0});
    weld.anchor = {0.0, 0.0};
    world.createWeldJoint(weld);

    Canvas canvas;
    DebugDrawOptions options;
    options.joints = true;
    canvas.draw(world, options, "debug_joint_kinds");
    const auto teal = [](sf::Color c) { return c.r < 80 && c.g > 90 && c.b > 90; };
    const auto at = [&](const Vec2& anchor, double angle, double metres) {
        return canvas.at(anchor + metres * Vec2(std::cos(angle), std::sin(angle)));
    };

    const Vec2 p(-3.0, 2.0);
    EXPECT_TRUE(teal(canvas.at(p + Vec2(-0.05, 0.0)))) << "revolute: a ring of 5 px around its anchor";
    EXPECT_EQ(canvas.at(p), sf::Color::White) << "revolute: a ring, not a dot";
    EXPECT_TRUE(teal(at(p, M_PI / 2, 0.15))) << "revolute: the upper limit's ray, straight up";
    EXPECT_TRUE(teal(at(p, -M_PI / 4, 0.15))) << "revolute: the lower limit's ray, down to the right";
    EXPECT_EQ(at(p, M_PI, 0.15), sf::Color::White) << "revolute: no ray to the left";

    const Vec2 s(0.0, 2.0);
    EXPECT_TRUE(teal(canvas.at(s + Vec2(0.6, 0.0)))) << "prismatic: its axis line, out to the upper limit";
    EXPECT_TRUE(teal(canvas.at(s + Vec2(0.8, 0.04)))) << "prismatic: the upper limit's tick across the axis";
    EXPECT_TRUE(teal(canvas.at(s + Vec2(-0.5, -0.04)))) << "prismatic: the lower limit's tick";
    EXPECT_EQ(canvas.at(s + Vec2(0.3, 0.05)), sf::Color::White) << "prismatic: no tick between the limits";
    EXPECT_EQ(canvas.at(s + Vec2(1.0, 0.0)), sf::Color::White) << "prismatic: the axis ends past the limit";

    const Vec2 w(3.0, 2.0);
    EXPECT_TRUE(teal(canvas.at(w + Vec2(0.0, 0.2)))) << "wheel: its axis, vertical, 25 px either side";
    EXPECT_TRUE(teal(canvas.at(w + Vec2(0.0, -0.2))));
    EXPECT_EQ(canvas.at(w + Vec2(0.2, 0.0)), sf::Color::White) << "wheel: nothing across its axis";

    EXPECT_TRUE(teal(canvas.at({-2.0, -1.0}))) << "pulley: the line between its ground anchors";
    EXPECT_TRUE(teal(canvas.at({-3.0, -1.75}))) << "pulley: A's rope";
    EXPECT_TRUE(teal(canvas.at({-1.0, -1.75}))) << "pulley: B's rope";
    EXPECT_EQ(canvas.at({-2.0, -1.75}), sf::Color::White) << "pulley: no line between its bodies";

    EXPECT_TRUE(teal(canvas.at({2.25, -2.0}))) << "gear: the line between its bodies' centres";

    EXPECT_TRUE(teal(canvas.at({0.05, 0.0}))) << "weld: a square of 10 px at its anchor";
    EXPECT_TRUE(teal(canvas.at({0.0, -0.05})));
    EXPECT_EQ(canvas.at({0.0, 0.0}), sf::Color::White) << "weld: a square, not a dot";
}

}  // namespace
}  // namespace physim

namespace physim {
namespace {

bool orange(sf::Color c) { return c.r > 200 && c.g > 80 && c.g < 160 && c.b < 60; }

// A ray (RayCast drawing): orange up to its hit, the hit point's dot there, a blue normal, faint beyond.
TEST(DebugDrawWindow, RayCastHitPointAndNormal) {
    World world;
    BodyDef def;
    def.type = BodyType::Static;
    def.position = {1.0, 0.0};
    def.shape = makeCircle(0.5);
    world.createBody(def);
    const Vec2 origin(-3.0, 0.0), translation(6.0, 0.0);
    const std::vector<DebugRay> rays{{origin, translation, world.castRayClosest(origin, translation)}};
    ASSERT_TRUE(rays[0].hit);
    Canvas canvas;
    DebugDrawOptions options;
    options.rays = true;
    canvas.texture.clear(sf::Color::White);
    drawDebug(canvas.texture, canvas.view, world, options, rays);
    canvas.texture.display();
    canvas.image = canvas.texture.getTexture().copyToImage();
    EXPECT_TRUE(orange(canvas.at({-2.0, 0.0}))) << "the ray before its hit";
    EXPECT_TRUE(orange(canvas.at({0.5, 0.04}))) << "the hit point's dot (4 px above the line)";
    const sf::Color beyond = canvas.at({2.5, 0.0});
    EXPECT_FALSE(orange(beyond));
    EXPECT_LT(beyond.b, 255) << "the ray past its hit, faint";
    const sf::Color normal = canvas.at({0.2, 0.0});  // the normal points back along -x from the hit at x = 0.5
    EXPECT_GT(normal.b, 150);
    EXPECT_LT(normal.r, 120);
}

}  // namespace
}  // namespace physim
