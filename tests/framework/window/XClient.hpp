#pragma once
// A test's own connection to the X server, looking at windows as another client (a window manager, xwininfo)
// does. Xlib stays in XClient.cpp: its macros (None, Status, ...) clash with GoogleTest.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace physim::test {

struct XRect {
    int x = 0, y = 0, width = 0, height = 0;
};

class XClient {
public:
    using Window = unsigned long;  // Xlib's XID

    XClient();
    ~XClient();
    XClient(const XClient&) = delete;
    XClient& operator=(const XClient&) = delete;
    explicit operator bool() const { return display_ != nullptr; }

    /// The first viewable window whose name contains `part`.
    std::optional<Window> find(const std::string& part);
    /// How many viewable windows have a name containing `part`.
    int count(const std::string& part);
    /// Position on the screen and size.
    XRect geometry(Window w);
    /// The window's pixels, as the server holds them.
    std::string pixels(Window w);
    /// What a window manager sends when the user clicks the close button (WM_DELETE_WINDOW).
    void close(Window w);

private:
    /// Viewable windows under `w` (itself included) named with `part`, at most `limit`.
    std::vector<Window> matching(Window w, const std::string& part, std::size_t limit);

    void* display_;  // Display*
};

}  // namespace physim::test
