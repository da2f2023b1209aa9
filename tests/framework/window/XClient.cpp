#include "XClient.hpp"

#include <xcb/xcb.h>

#include <cstdlib>
#include <cstring>
#include <memory>

namespace physim::test {
namespace {

xcb_connection_t* connection(void* c) { return static_cast<xcb_connection_t*>(c); }

struct Free {
    void operator()(void* p) const { std::free(p); }
};
template <class T>
using Reply = std::unique_ptr<T, Free>;

// A request's reply, or null when the server answered with an error (which is freed here, never handled).
template <class T, class Cookie, class Get>
Reply<T> reply(xcb_connection_t* c, Get get, Cookie cookie) {
    xcb_generic_error_t* error = nullptr;
    Reply<T> r(get(c, cookie, &error));
    std::free(error);
    return r;
}

xcb_atom_t atom(xcb_connection_t* c, const char* name) {
    const auto r = reply<xcb_intern_atom_reply_t>(
        c, xcb_intern_atom_reply, xcb_intern_atom(c, 0, static_cast<std::uint16_t>(std::strlen(name)), name));
    return r ? r->atom : xcb_atom_t{XCB_ATOM_NONE};
}

}  // namespace

XClient::XClient() {
    int screen = 0;
    xcb_connection_t* c = xcb_connect(nullptr, &screen);
    if (xcb_connection_has_error(c)) {
        xcb_disconnect(c);  // a failed connection is still an object to free
        return;
    }
    xcb_screen_iterator_t it = xcb_setup_roots_iterator(xcb_get_setup(c));
    for (int i = 0; i < screen && it.rem > 0; ++i) xcb_screen_next(&it);
    root_ = it.data->root;
    connection_ = c;
}

XClient::~XClient() {
    if (connection_) xcb_disconnect(connection(connection_));
}

std::optional<XClient::Window> XClient::find(const std::string& part) {
    const auto found = matching(root_, part, 1);
    return found.empty() ? std::nullopt : std::optional<Window>(found.front());
}

int XClient::count(const std::string& part) { return static_cast<int>(matching(root_, part, 1000).size()); }

std::vector<XClient::Window> XClient::matching(Window w, const std::string& part, std::size_t limit) {
    xcb_connection_t* const c = connection(connection_);
    // The three questions about w go out together: one round trip.
    const auto nameCookie = xcb_get_property(c, 0, w, XCB_ATOM_WM_NAME, XCB_GET_PROPERTY_TYPE_ANY, 0, 1024);
    const auto stateCookie = xcb_get_window_attributes(c, w);
    const auto treeCookie = xcb_query_tree(c, w);
    const auto name = reply<xcb_get_property_reply_t>(c, xcb_get_property_reply, nameCookie);
    const auto state = reply<xcb_get_window_attributes_reply_t>(c, xcb_get_window_attributes_reply, stateCookie);
    const auto tree = reply<xcb_query_tree_reply_t>(c, xcb_query_tree_reply, treeCookie);
    std::vector<Window> found;
    if (name && state && state->map_state == XCB_MAP_STATE_VIEWABLE) {
        const std::string title(static_cast<const char*>(xcb_get_property_value(name.get())),
                                static_cast<std::size_t>(xcb_get_property_value_length(name.get())));
        if (title.find(part) != std::string::npos) found.push_back(w);
    }
    if (!tree) return found;
    const xcb_window_t* children = xcb_query_tree_children(tree.get());
    const int n = xcb_query_tree_children_length(tree.get());
    for (int i = 0; i < n && found.size() < limit; ++i)
        for (Window child : matching(children[i], part, limit - found.size())) found.push_back(child);
    return found;
}

XRect XClient::geometry(Window w) {
    xcb_connection_t* const c = connection(connection_);
    const auto sizeCookie = xcb_get_geometry(c, w);
    const auto placeCookie = xcb_translate_coordinates(c, w, root_, 0, 0);
    const auto size = reply<xcb_get_geometry_reply_t>(c, xcb_get_geometry_reply, sizeCookie);
    const auto place = reply<xcb_translate_coordinates_reply_t>(c, xcb_translate_coordinates_reply, placeCookie);
    if (!size || !place) return {};
    return {place->dst_x, place->dst_y, size->width, size->height};
}

std::string XClient::pixels(Window w) {
    const XRect g = geometry(w);
    if (g.width <= 0 || g.height <= 0) return {};
    xcb_connection_t* const c = connection(connection_);
    const auto image = reply<xcb_get_image_reply_t>(
        c, xcb_get_image_reply,
        xcb_get_image(c, XCB_IMAGE_FORMAT_Z_PIXMAP, w, 0, 0, static_cast<std::uint16_t>(g.width),
                      static_cast<std::uint16_t>(g.height), ~0u));
    if (!image) return {};
    return std::string(reinterpret_cast<const char*>(xcb_get_image_data(image.get())),
                       static_cast<std::size_t>(xcb_get_image_data_length(image.get())));
}

void XClient::close(Window w) {
    xcb_connection_t* const c = connection(connection_);
    xcb_client_message_event_t e{};
    e.response_type = XCB_CLIENT_MESSAGE;
    e.format = 32;
    e.window = w;
    e.type = atom(c, "WM_PROTOCOLS");
    e.data.data32[0] = atom(c, "WM_DELETE_WINDOW");
    e.data.data32[1] = XCB_CURRENT_TIME;
    static_assert(sizeof e == 32, "xcb_send_event sends 32 bytes");
    xcb_send_event(c, 0, w, XCB_EVENT_MASK_NO_EVENT, reinterpret_cast<const char*>(&e));
    xcb_flush(c);
}

}  // namespace physim::test
