#include "ImGuiSfml.hpp"

#include <imgui.h>
#include <backends/imgui_impl_opengl2.h>

#include <SFML/Graphics/RenderWindow.hpp>

#include <algorithm>
#include <cfloat>
#include <filesystem>
#include <stdexcept>
#include <utility>

namespace physim::examples {
namespace {

const char* const kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// ImGui 1.86 reads keys from io.KeysDown[], indexed by the application's own codes: SFML's.
void mapKeys(ImGuiIO& io) {
    const std::pair<ImGuiKey_, sf::Keyboard::Key> keys[] = {
        {ImGuiKey_Tab, sf::Keyboard::Tab},         {ImGuiKey_LeftArrow, sf::Keyboard::Left},
        {ImGuiKey_RightArrow, sf::Keyboard::Right}, {ImGuiKey_UpArrow, sf::Keyboard::Up},
        {ImGuiKey_DownArrow, sf::Keyboard::Down},   {ImGuiKey_PageUp, sf::Keyboard::PageUp},
        {ImGuiKey_PageDown, sf::Keyboard::PageDown}, {ImGuiKey_Home, sf::Keyboard::Home},
        {ImGuiKey_End, sf::Keyboard::End},         {ImGuiKey_Insert, sf::Keyboard::Insert},
        {ImGuiKey_Delete, sf::Keyboard::Delete},   {ImGuiKey_Backspace, sf::Keyboard::BackSpace},
        {ImGuiKey_Space, sf::Keyboard::Space},     {ImGuiKey_Enter, sf::Keyboard::Enter},
        {ImGuiKey_Escape, sf::Keyboard::Escape},   {ImGuiKey_KeyPadEnter, sf::Keyboard::Enter},
        {ImGuiKey_A, sf::Keyboard::A},             {ImGuiKey_C, sf::Keyboard::C},
        {ImGuiKey_V, sf::Keyboard::V},             {ImGuiKey_X, sf::Keyboard::X},
        {ImGuiKey_Y, sf::Keyboard::Y},             {ImGuiKey_Z, sf::Keyboard::Z},
    };
    for (const auto& [imgui, sfml] : keys) io.KeyMap[imgui] = sfml;
}

int mouseButton(sf::Mouse::Button b) {
    switch (b) {
        case sf::Mouse::Left: return 0;
        case sf::Mouse::Right: return 1;
        case sf::Mouse::Middle: return 2;
        default: return -1;
    }
}

}  // namespace

ImGuiSfml::ImGuiSfml(sf::RenderWindow& window) : window_(window) {
    if (ImGui::GetCurrentContext())
        throw std::logic_error("physim: one ImGuiSfml at a time (ImGui's context is global)");
    if (!window_.setActive(true))  // before anything is made that would need undoing
        throw std::runtime_error("physim: the window's OpenGL context cannot be made current");
    IMGUI_CHECKVERSION();
    context_ = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini written into the working directory
    io.BackendPlatformName = "physim_imgui_sfml";
    mapKeys(io);
    if (std::filesystem::exists(kFont)) io.Fonts->AddFontFromFileTTF(kFont, 15.0f);
    ImGui::StyleColorsLight();
    ImGui_ImplOpenGL2_Init();
}

ImGuiSfml::~ImGuiSfml() {
    (void)window_.setActive(true);
    ImGui_ImplOpenGL2_Shutdown();
    ImGui::DestroyContext(context_);
}

bool ImGuiSfml::processEvent(const sf::Event& event) {
    ImGuiIO& io = ImGui::GetIO();
    switch (event.type) {
        case sf::Event::MouseMoved:
            io.MousePos = ImVec2(static_cast<float>(event.mouseMove.x), static_cast<float>(event.mouseMove.y));
            return false;
        case sf::Event::MouseButtonPressed:
        case sf::Event::MouseButtonReleased: {
            io.MousePos = ImVec2(static_cast<float>(event.mouseButton.x), static_cast<float>(event.mouseButton.y));
            const int b = mouseButton(event.mouseButton.button);
            if (b >= 0) {
                const bool press = event.type == sf::Event::MouseButtonPressed;
                // ImGui 1.86 samples MouseDown once per frame: a release before any frame saw the press is
                // held back one frame, or the click would be lost.
                if (!press && unseenPress_[b]) releaseLater_[b] = true;
                else io.MouseDown[b] = press;
                unseenPress_[b] = press;
            }
            // ImGui wants the mouse when it is over a panel, and until the release of a press made there (a
            // press made in the scene stays the scene's).
            return io.WantCaptureMouse;
        }
        case sf::Event::MouseWheelScrolled:
            if (event.mouseWheelScroll.wheel == sf::Mouse::VerticalWheel) io.MouseWheel += event.mouseWheelScroll.delta;
            else io.MouseWheelH += event.mouseWheelScroll.delta;
            return io.WantCaptureMouse;
        case sf::Event::MouseLeft:
            io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
            return false;
        case sf::Event::KeyPressed:
        case sf::Event::KeyReleased: {
            const bool down = event.type == sf::Event::KeyPressed;
            const int key = static_cast<int>(event.key.code);  // sf::Keyboard::Unknown is -1
            if (key >= 0 && key < static_cast<int>(IM_ARRAYSIZE(io.KeysDown))) io.KeysDown[key] = down;
            io.KeyCtrl = event.key.control;
            io.KeyShift = event.key.shift;
            io.KeyAlt = event.key.alt;
            io.KeySuper = event.key.system;
            return io.WantCaptureKeyboard;
        }
        case sf::Event::TextEntered:
            if (event.text.unicode >= 32 && event.text.unicode != 127) io.AddInputCharacter(event.text.unicode);
            return io.WantTextInput;
        case sf::Event::LostFocus:
            std::fill(std::begin(io.KeysDown), std::end(io.KeysDown), false);
            std::fill(std::begin(io.MouseDown), std::end(io.MouseDown), false);
            return false;
        default: return false;
    }
}

void ImGuiSfml::newFrame(double seconds) {
    ImGuiIO& io = ImGui::GetIO();
    const sf::Vector2u size = window_.getSize();
    io.DisplaySize = ImVec2(static_cast<float>(size.x), static_cast<float>(size.y));
    io.DeltaTime = static_cast<float>(std::max(seconds, 1e-4));  // ImGui asserts > 0
    ImGui_ImplOpenGL2_NewFrame();
    ImGui::NewFrame();
    for (int b = 0; b < 3; ++b) {
        unseenPress_[b] = false;
        if (std::exchange(releaseLater_[b], false)) io.MouseDown[b] = false;  // the next frame sees the release
    }
}

void ImGuiSfml::render() {
    ImGui::Render();
    // ImGui's backend saves and restores the OpenGL state it touches; SFML's own cache of that state is
    // pushed and popped around it so SFML's next draws start from what they expect.
    window_.pushGLStates();
    ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
    window_.popGLStates();
}

}  // namespace physim::examples
