#include "Display.hpp"

#include <X11/Xlib.h>

#include <cstdlib>

namespace physim {

DisplayConnection::DisplayConnection() {
    const char* name = std::getenv("DISPLAY");
    if (!name || !*name) {
        problem_ = "no display to open a window on (DISPLAY is not set)";
        return;
    }
    display_ = XOpenDisplay(name);
    if (!display_) problem_ = std::string("cannot open the display '") + name + "' (no X server answers there)";
}

DisplayConnection::~DisplayConnection() {
    if (display_) XCloseDisplay(display_);
}

}  // namespace physim
