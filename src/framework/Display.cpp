#include "Display.hpp"

#include <X11/Xlib.h>

#include <cstdlib>

namespace physim {

std::string displayProblem() {
    const char* name = std::getenv("DISPLAY");
    if (!name || !*name) return "no display to open a window on (DISPLAY is not set)";
    Display* display = XOpenDisplay(name);
    if (!display) return std::string("cannot open the display '") + name + "' (no X server answers there)";
    XCloseDisplay(display);
    return "";
}

}  // namespace physim
