#pragma once
// Dear ImGui on an SFML window. Debian's libimgui-dev (1.86) has renderer backends but no SFML platform
// backend, so this adapter feeds ImGui's IO from SFML events (mouse, wheel, keys, text) and the window's size,
// and renders with ImGui's OpenGL 2 backend on the window's own OpenGL context.
//
// ImGui keeps its current context in one process-wide pointer: one ImGuiSfml at a time (the constructor
// refuses a second).

#include <SFML/Window/Event.hpp>

struct ImGuiContext;

namespace sf {
class RenderWindow;
}

namespace physim::examples {

class ImGuiSfml {
public:
    explicit ImGuiSfml(sf::RenderWindow& window);
    ~ImGuiSfml();
    ImGuiSfml(const ImGuiSfml&) = delete;
    ImGuiSfml& operator=(const ImGuiSfml&) = delete;

    /// Feeds one event. True when ImGui takes it: a click or wheel over a panel, a key while a text field has
    /// focus. Mouse motion is never taken (a drag that started in the scene goes on over a panel).
    bool processEvent(const sf::Event& event);
    /// Starts a frame of `seconds` since the last one; build the panels with ImGui:: calls after it.
    void newFrame(double seconds);
    /// Draws the frame's panels over what the window holds (before display()).
    void render();

private:
    sf::RenderWindow& window_;
    ImGuiContext* context_ = nullptr;
    bool unseenPress_[3] = {};   // pressed since the last frame began (left, right, middle)
    bool releaseLater_[3] = {};  // released before a frame saw the press: release at the next frame
};

}  // namespace physim::examples
