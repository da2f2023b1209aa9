#pragma once
// A test's own connection to the X server, looking at windows as another client (a window manager, xwininfo)
// does, from the test's own thread while the program under test draws. It speaks xcb, not Xlib: Xlib hands every
// error (a window gone between two requests) to one handler per process, and ROOT's runs its interpreter, which
// must not run on this thread beside ROOT's own work (docs/graphs.md). xcb returns a request's error with its
// reply. The xcb headers stay in XClient.cpp.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace physim::test {

struct XRect {
    int x = 0, y = 0, width = 0, height = 0;
};

class XClient {
public:
    using Window = std::uint32_t;  // an X window id (xcb_window_t)

    XClient();
    ~XClient();
    XClient(const XClient&) = delete;
    XClient& operator=(const XClient&) = delete;
    explicit operator bool() const { return connection_ != nullptr; }

    /// The first viewable window whose name contains `part`.
    std::optional<Window> find(const std::string& part);
    /// How many viewable windows have a name containing `part`.
    int count(const std::string& part);
    /// Position on the screen and size; all zero for a window that is gone.
    XRect geometry(Window w);
    /// The window's pixels, as the server holds them; empty for a window that is gone.
    std::string pixels(Window w);
    /// What a window manager sends when the user clicks the close button (WM_DELETE_WINDOW).
    void close(Window w);

private:
    /// Viewable windows under `w` (itself included) named with `part`, at most `limit`. A window that goes away
    /// meanwhile is skipped.
    std::vector<Window> matching(Window w, const std::string& part, std::size_t limit);

    void* connection_ = nullptr;  // xcb_connection_t*
    Window root_ = 0;
};

}  // namespace physim::test
