#include "GraphsPlacement.hpp"

#include <algorithm>

namespace physim {

SideBySide placeBeside(int windowWidth, int windowHeight, int screenWidth, int screenHeight, int preferredWidth,
                       int minWidth) {
    SideBySide p;
    p.window.width = windowWidth, p.window.height = windowHeight;
    p.canvas.height = std::min(windowHeight, std::max(screenHeight, 1));
    p.window.y = p.canvas.y = std::max(0, (screenHeight - windowHeight) / 2);
    const int room = screenWidth - windowWidth;
    if (room >= preferredWidth) {
        p.canvas.width = preferredWidth;
        p.window.x = (room - preferredWidth) / 2;
        p.canvas.x = p.window.x + windowWidth;
    } else if (room >= minWidth) {
        p.canvas.width = room;
        p.window.x = 0;
        p.canvas.x = windowWidth;
    } else {
        p.canvas.width = std::min(preferredWidth, std::max(screenWidth, minWidth));
        p.window.x = std::max(0, (screenWidth - windowWidth) / 2);
        p.canvas.x = std::max(0, screenWidth - p.canvas.width);
    }
    return p;
}

}  // namespace physim
