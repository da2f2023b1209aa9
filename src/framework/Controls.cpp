#include "Controls.hpp"

#include "physim/core/Collide.hpp"
#include "physim/core/Validate.hpp"
#include "physim/framework/Runner.hpp"
#include "physim/framework/Simulation.hpp"

#include <SFML/Window/Event.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace physim {
namespace {

constexpr double kZoomStep = 1.1;      // per wheel notch
constexpr double kPickPixels = 2.0;    // a click this close to a body grabs it

// The debug-draw switch a number key toggles; nullptr for other keys.
bool* debugSwitch(DebugDrawOptions& o, sf::Keyboard::Key key) {
    switch (key) {
        case sf::Keyboard::Num1: return &o.contacts;
        case sf::Keyboard::Num2: return &o.boxes;
        case sf::Keyboard::Num3: return &o.velocities;
        case sf::Keyboard::Num4: return &o.joints;
        case sf::Keyboard::Num5: return &o.centres;
        case sf::Keyboard::Num6: return &o.sleep;
        case sf::Keyboard::Num7: return &o.sensors;
        case sf::Keyboard::Num8: return &o.rays;
        default: return nullptr;
    }
}

// The topmost (last created) dynamic body within kPickPixels of `point`, if any.
std::optional<BodyId> bodyAt(const World& world, const Vec2& point, double pixelsPerMetre) {
    const Circle probe{Vec2::Zero(), kPickPixels / pixelsPerMetre};
    const Transform at{point, Rotation{}};
    const std::vector<BodyId> ids = world.bodies();
    for (auto it = ids.rbegin(); it != ids.rend(); ++it) {
        if (world.type(*it) != BodyType::Dynamic) continue;
        for (ShapeId s : world.shapes(*it))  // any of a compound body's shapes
            if (collide(probe, at, world.geometry(s), world.transform(*it)).pointCount > 0) return *it;
    }
    return std::nullopt;
}

}  // namespace

void Controls::setTimeScale(double scale) {
    requireInRange("time scale", scale, Runner::minTimeScale, Runner::maxTimeScale);
    timeScale_ = scale;
}

void Controls::slower() { timeScale_ = std::max(Runner::minTimeScale, timeScale_ / 2.0); }
void Controls::faster() { timeScale_ = std::min(Runner::maxTimeScale, timeScale_ * 2.0); }

bool Controls::takeSingleStep() { return std::exchange(singleStep_, false); }
bool Controls::takeFitRequest() { return std::exchange(fit_, false); }

void Controls::startDrag(Simulation& sim, const Vec2& point) {
    World& world = sim.world();
    const std::optional<BodyId> body = bodyAt(world, point, sim.view.pixelsPerMetre);
    if (!body) return;
    picked_ = body;
    MouseJointDef def;
    def.body = *body;
    def.target = point;
    def.localAnchor = world.transform(*body).applyInverse(point);
    def.maxForce = dragForcePerWeight * world.mass(*body) * std::max(world.settings().gravity.norm(), 9.81);
    def.hertz = dragHertz;
    def.dampingRatio = dragDampingRatio;
    drag_ = world.createMouseJoint(def);
    worldChanged_ = true;
}

void Controls::releaseDrag(Simulation& sim) {
    if (drag_ && sim.world().contains(*drag_)) {
        sim.world().destroyJoint(*drag_);
        worldChanged_ = true;
    }
    drag_.reset();
}

void Controls::forgetDrag() {
    drag_.reset();
    picked_.reset();
    panFrom_.reset();
}

bool Controls::handleEvent(const sf::Event& event, Simulation& sim, sf::Vector2u windowSize) {
    switch (event.type) {
        case sf::Event::MouseButtonPressed: {
            const sf::Vector2i pixel(event.mouseButton.x, event.mouseButton.y);
            if (event.mouseButton.button == sf::Mouse::Left) {
                releaseDrag(sim);
                const Vec2 point = sim.view.toWorld(pixel, windowSize);
                const Measurement::Kind kind = tapeKey_         ? Measurement::Kind::Tape
                                               : protractorKey_ ? Measurement::Kind::Protractor
                                                                : Measurement::Kind::None;
                if (!measurement_.press(kind, point)) startDrag(sim, point);
            } else if (event.mouseButton.button == sf::Mouse::Right) {
                panFrom_ = pixel;
            }
            return true;
        }
        case sf::Event::MouseButtonReleased:
            if (event.mouseButton.button == sf::Mouse::Left) {
                releaseDrag(sim);
                measurement_.release(sim.view.toWorld({event.mouseButton.x, event.mouseButton.y}, windowSize));
            }
            if (event.mouseButton.button == sf::Mouse::Right) panFrom_.reset();
            return true;
        case sf::Event::MouseMoved: {
            const sf::Vector2i pixel(event.mouseMove.x, event.mouseMove.y);
            if (panFrom_) {
                sim.view.pan(pixel - *panFrom_);
                panFrom_ = pixel;
            }
            if (measurement_.kind() != Measurement::Kind::None) measurement_.move(sim.view.toWorld(pixel, windowSize));
            if (drag_) {
                if (sim.world().contains(*drag_)) {
                    sim.world().setMouseJointTarget(*drag_, sim.view.toWorld(pixel, windowSize));
                    dragMoved_ = true;
                } else
                    drag_.reset();  // the body went (the simulation removed it)
            }
            return true;
        }
        case sf::Event::MouseWheelScrolled:
            sim.view.zoomAt(std::pow(kZoomStep, event.mouseWheelScroll.delta),
                            {event.mouseWheelScroll.x, event.mouseWheelScroll.y}, windowSize);
            return true;
        case sf::Event::KeyPressed: {
            const sf::Keyboard::Key key = event.key.code;
            if (bool* option = debugSwitch(sim.debugDraw, key)) {
                *option = !*option;
            } else if (key == sf::Keyboard::O) {
                sim.paused = true;
                singleStep_ = true;
            } else if (key == sf::Keyboard::LBracket) {
                slower();
            } else if (key == sf::Keyboard::RBracket) {
                faster();
            } else if (key == sf::Keyboard::F) {
                fit_ = true;
            } else if (key == sf::Keyboard::Tab) {
                statsShown_ = !statsShown_;
            } else if (key == sf::Keyboard::W && event.key.shift) {
                stopwatch_.arm();
            } else if (key == sf::Keyboard::W) {
                stopwatch_.press(sim.time);
            } else if (key == sf::Keyboard::V) {
                arrowsShown_ = !arrowsShown_;
            } else if (key == sf::Keyboard::L) {
                trailsShown_ = !trailsShown_;
            } else if (key == sf::Keyboard::M) {
                tapeKey_ = true;
            } else if (key == sf::Keyboard::A) {
                protractorKey_ = true;
            } else {
                return false;
            }
            return true;
        }
        case sf::Event::KeyReleased:
            if (event.key.code == sf::Keyboard::M) tapeKey_ = false;
            else if (event.key.code == sf::Keyboard::A) protractorKey_ = false;
            else return false;
            return true;
        case sf::Event::LostFocus:  // the key's release goes to another window
            tapeKey_ = protractorKey_ = false;
            return false;
        default: return false;
    }
}

void Controls::resetInstruments() {
    stopwatch_ = Stopwatch();
    measurement_.clear();
}

std::string Controls::keysHelp() {
    return "Space restart   P pause   O step   Left/Right back/forward 1 s   Home start   B branch   [ ] slower/faster   F fit   "
           "Tab stats   W stopwatch (Shift+W: sensors)   M+drag tape   A+drag, click: angle   L trails   V arrows   "
           "1-8 contacts/boxes/velocities/joints/centres/sleep/sensors/rays   left drag: move a body   right drag: pan   "
           "wheel: zoom   Esc quit";
}

}  // namespace physim
