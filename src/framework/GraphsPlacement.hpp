#pragma once
// Where the live graphs window goes: beside the simulation window, not on top of it.

namespace physim {

struct ScreenRect {
    int x = 0, y = 0, width = 0, height = 0;
};

struct SideBySide {
    ScreenRect window;  ///< the simulation window, moved
    ScreenRect canvas;  ///< the graphs window
};

/// The graphs window at the simulation window's height, right of it. When both fit on the screen at the
/// graphs' preferred width, the pair is centred; else the graphs window takes the room left of the screen's
/// width (down to `minWidth`) with the simulation window at the left edge; on a screen narrower than that the
/// graphs window sits at the screen's right edge, over part of the simulation window.
SideBySide placeBeside(int windowWidth, int windowHeight, int screenWidth, int screenHeight,
                       int preferredWidth = 1000, int minWidth = 480);

}  // namespace physim
