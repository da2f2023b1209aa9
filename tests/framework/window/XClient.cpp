#include "XClient.hpp"

#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <cstring>

namespace physim::test {
namespace {

Display* dpy(void* d) { return static_cast<Display*>(d); }

}  // namespace

XClient::XClient() : display_(XOpenDisplay(nullptr)) {}

XClient::~XClient() {
    if (display_) XCloseDisplay(dpy(display_));
}

std::optional<XClient::Window> XClient::find(const std::string& part) {
    const auto found = matching(DefaultRootWindow(dpy(display_)), part, 1);
    return found.empty() ? std::nullopt : std::optional<Window>(found.front());
}

int XClient::count(const std::string& part) {
    return static_cast<int>(matching(DefaultRootWindow(dpy(display_)), part, 1000).size());
}

std::vector<XClient::Window> XClient::matching(Window w, const std::string& part, std::size_t limit) {
    std::vector<Window> found;
    char* name = nullptr;
    if (XFetchName(dpy(display_), w, &name) && name) {
        const bool match = std::strstr(name, part.c_str()) != nullptr;
        XFree(name);
        XWindowAttributes a{};
        if (match && XGetWindowAttributes(dpy(display_), w, &a) && a.map_state == IsViewable) found.push_back(w);
    }
    ::Window root = 0, parent = 0, *children = nullptr;
    unsigned n = 0;
    if (!XQueryTree(dpy(display_), w, &root, &parent, &children, &n)) return found;
    for (unsigned i = 0; i < n && found.size() < limit; ++i)
        for (Window c : matching(children[i], part, limit - found.size())) found.push_back(c);
    if (children) XFree(children);
    return found;
}

XRect XClient::geometry(Window w) {
    XWindowAttributes a{};
    XGetWindowAttributes(dpy(display_), w, &a);
    int x = 0, y = 0;
    ::Window child = 0;
    XTranslateCoordinates(dpy(display_), w, DefaultRootWindow(dpy(display_)), 0, 0, &x, &y, &child);
    return {x, y, a.width, a.height};
}

std::string XClient::pixels(Window w) {
    const XRect g = geometry(w);
    XImage* image = XGetImage(dpy(display_), w, 0, 0, static_cast<unsigned>(g.width), static_cast<unsigned>(g.height),
                              AllPlanes, ZPixmap);
    if (!image) return {};
    std::string bytes(image->data,
                      static_cast<std::size_t>(image->bytes_per_line) * static_cast<std::size_t>(image->height));
    XDestroyImage(image);
    return bytes;
}

void XClient::close(Window w) {
    XEvent e{};
    e.xclient.type = ClientMessage;
    e.xclient.window = w;
    e.xclient.message_type = XInternAtom(dpy(display_), "WM_PROTOCOLS", False);
    e.xclient.format = 32;
    e.xclient.data.l[0] = static_cast<long>(XInternAtom(dpy(display_), "WM_DELETE_WINDOW", False));
    e.xclient.data.l[1] = CurrentTime;
    XSendEvent(dpy(display_), w, False, NoEventMask, &e);
    XFlush(dpy(display_));
}

}  // namespace physim::test
