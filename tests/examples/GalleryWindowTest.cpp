// The gallery in a real window (under Xvfb when there is no display), driven by synthesized SFML events as a
// user's mouse would: clicking each scene's entry switches to that scene and runs it; letting go of a slider
// restarts the scene with the new value; a click in the scene still grabs a body, a click on the panel does not.

#include "Gallery.hpp"
#include "RunnerAccess.hpp"  // src/framework: the runner's internals, to see the drag
#include "support/SfmlEvents.hpp"

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/Texture.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

namespace physim::examples {
namespace {

using test::mouseMove;

sf::Event mouseButton(sf::Event::EventType type, sf::Vector2i at) {
    return test::mouseButton(type, sf::Mouse::Left, at);
}

sf::Vector2i centreOf(const sf::FloatRect& r) {
    return {static_cast<int>(r.left + 0.5f * r.width), static_cast<int>(r.top + 0.5f * r.height)};
}

class GalleryWindow : public ::testing::Test {
protected:
    void SetUp() override {
        RunOptions options;
        options.hz = 60.0;
        options.headless = true;  // graphs stay off screen (no ROOT canvas per scene); the frames go to `window`
        runner = std::make_unique<Runner>(scenes().front().make, options);
        window.create(sf::VideoMode(1280, 720), "gallery test");
        auto panel = std::make_unique<Gallery>(scenes(), 0);
        gallery = panel.get();
        gallery->open(window);
        runner->setPanel(std::move(panel));
        runner->restart();
        frames(2);  // ImGui lays the panel out in its first frame
    }
    void TearDown() override { gallery->close(); }  // before the window goes

    void frames(int n) {
        for (int i = 0; i < n; ++i) runner->frame(1.0 / 60.0, &window);
    }
    // Press and release at `at`, a frame between each event, as a real click reaches the program.
    void click(sf::Vector2i at) {
        runner->handleEvent(mouseMove(at), &window);
        frames(1);
        runner->handleEvent(mouseButton(sf::Event::MouseButtonPressed, at), &window);
        frames(1);
        runner->handleEvent(mouseButton(sf::Event::MouseButtonReleased, at), &window);
        frames(2);
    }

    sf::RenderWindow window;
    std::unique_ptr<Runner> runner;
    Gallery* gallery = nullptr;  // owned by the runner
};

TEST_F(GalleryWindow, ClickingEachSceneSwitchesToItAndRunsIt) {
    for (std::size_t i = scenes().size(); i-- > 0;) {  // last first: every entry, away from the start scene
        const std::string& name = scenes()[i].name;
        const std::optional<sf::FloatRect> entry = gallery->itemRect(name);
        ASSERT_TRUE(entry.has_value()) << name << " is in the list";
        click(centreOf(*entry));
        EXPECT_EQ(gallery->current(), i) << name;
        const std::unique_ptr<Simulation> fresh = scenes()[i].make();
        EXPECT_EQ(runner->simulation().title(), fresh->title()) << "the runner shows " << name;
        const double t = runner->simulation().time;
        frames(3);
        EXPECT_GT(runner->simulation().time, t) << name << " runs";
        // The scene is fitted right of the panel.
        EXPECT_GE(runner->sceneArea().left, Gallery::panelWidth);
        const std::optional<Aabb> bounds = runner->simulation().viewBounds();
        ASSERT_TRUE(bounds.has_value());
        const sf::Vector2f centre = runner->simulation().view.worldToPixels(window.getSize())
                                        .transformPoint(float(bounds->center().x()), float(bounds->center().y()));
        EXPECT_GT(centre.x, Gallery::panelWidth) << name << "'s subject is not under the panel";
    }
    if (const char* dir = std::getenv("PHYSIM_TEST_SHOTS")) {  // for looking at it: the last frame shown
        sf::Texture texture;
        texture.create(window.getSize().x, window.getSize().y);
        texture.update(window);
        texture.copyToImage().saveToFile(std::string(dir) + "/gallery_test.png");
    }
}

// The pyramid's base slider dragged to its left end and let go: the scene is made again with one box.
TEST_F(GalleryWindow, LettingGoOfASliderRestartsWithTheValue) {
    click(centreOf(*gallery->itemRect("pyramid")));
    ASSERT_EQ(runner->simulation().parameters.getInt("base"), 20);
    const std::optional<sf::FloatRect> slider = gallery->itemRect("base");
    ASSERT_TRUE(slider.has_value());
    const sf::Vector2i grab = centreOf(*slider), leftEnd(static_cast<int>(slider->left) - 20, grab.y);
    runner->handleEvent(mouseMove(grab), &window);
    frames(1);
    runner->handleEvent(mouseButton(sf::Event::MouseButtonPressed, grab), &window);
    frames(1);
    runner->handleEvent(mouseMove(leftEnd), &window);
    frames(1);
    EXPECT_EQ(runner->simulation().parameters.getInt("base"), 20) << "not applied while held";
    runner->handleEvent(mouseButton(sf::Event::MouseButtonReleased, leftEnd), &window);
    frames(2);
    EXPECT_EQ(runner->simulation().parameters.getInt("base"), 1);
    EXPECT_EQ(runner->simulation().world().bodyCount(), 2u) << "the ground and one box";
}

// Mouse presses over the panel are the panel's; in the scene they are the controls' (a drag grabs a body).
TEST_F(GalleryWindow, ThePanelTakesItsClicksTheSceneKeepsItsOwn) {
    click(centreOf(*gallery->itemRect("falling_box")));
    Simulation& sim = runner->simulation();
    const Vec2 box = sim.world().position(sim.world().bodies().back());
    const sf::Vector2f px = sim.view.worldToPixels(window.getSize()).transformPoint(float(box.x()), float(box.y()));
    const sf::Vector2i onBox(static_cast<int>(px.x), static_cast<int>(px.y));
    runner->handleEvent(mouseMove(onBox), &window);
    frames(1);
    runner->handleEvent(mouseButton(sf::Event::MouseButtonPressed, onBox), &window);
    EXPECT_TRUE(RunnerAccess::controls(*runner).dragJoint().has_value()) << "a press on the box grabs it";
    runner->handleEvent(mouseButton(sf::Event::MouseButtonReleased, onBox), &window);
    EXPECT_FALSE(RunnerAccess::controls(*runner).dragJoint().has_value());

    const sf::Vector2i onPanel(40, 700);
    runner->handleEvent(mouseMove(onPanel), &window);
    frames(2);
    runner->handleEvent(mouseButton(sf::Event::MouseButtonPressed, onPanel), &window);
    EXPECT_FALSE(RunnerAccess::controls(*runner).dragJoint().has_value());
    runner->handleEvent(mouseButton(sf::Event::MouseButtonReleased, onPanel), &window);
}

// Every scene shows its energy bars (World::energyLedger) in a box at the scene's lower right, inside the window,
// drawn: some pixel of a bar's colour where a bar has any length. The bars balance: kinetic + potential's change +
// dissipated - residue - work is the start's kinetic energy, to rounding (1e-9 of the largest bar).
TEST_F(GalleryWindow, ShowsEnergyBarsForEveryScene) {
    for (const Scene& scene : scenes()) {
        const std::string name = scene.name;
        click(centreOf(*gallery->itemRect(name)));
        frames(10);
        const EnergyLedger& e = runner->simulation().world().energyLedger();
        ASSERT_TRUE(e.enabled) << name;
        const std::optional<sf::FloatRect> box = gallery->itemRect("energy");
        ASSERT_TRUE(box.has_value()) << name;
        EXPECT_GE(box->left, 0.f);
        EXPECT_LE(box->left + box->width, static_cast<float>(window.getSize().x)) << name;
        EXPECT_LE(box->top + box->height, static_cast<float>(window.getSize().y)) << name;
        const double dissipated = -(e.total.friction + e.total.impacts + e.total.drag + e.total.soft);
        const double potential = e.potential - e.startPotential;
        const double largest = std::max({std::abs(e.kinetic), std::abs(potential), std::abs(dissipated),
                                         std::abs(e.total.residue), std::abs(e.total.work), 1e-300});
        EXPECT_NEAR(e.kinetic + potential + dissipated - e.total.residue - e.total.work, e.startKinetic,
                    1e-9 * std::max(largest, e.startKinetic))
            << name;
        sf::Texture texture;
        ASSERT_TRUE(texture.create(window.getSize().x, window.getSize().y));
        texture.update(window);
        const sf::Image image = texture.copyToImage();
        int barPixels = 0;
        const sf::Color colours[] = {{60, 160, 60}, {60, 110, 200}, {200, 90, 40}, {150, 150, 150}, {170, 60, 170}};
        for (unsigned y = static_cast<unsigned>(box->top); y < static_cast<unsigned>(box->top + box->height); ++y)
            for (unsigned x = static_cast<unsigned>(box->left); x < static_cast<unsigned>(box->left + box->width); ++x)
                for (const sf::Color& c : colours) barPixels += image.getPixel(x, y) == c;
        EXPECT_GT(barPixels, 0) << name << ": no bar drawn (largest " << largest << " J)";
    }
}

}  // namespace
}  // namespace physim::examples
