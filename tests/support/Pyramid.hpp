#pragma once
// The pyramid of square boxes that the tests, the benches and the peer comparison all build. One layout, so that
// "a base-40 pyramid" names the same boxes everywhere. Header-only and free of engine types, so an adapter for
// another engine can place the same boxes.

namespace physim::scenes {

/// Calls place(x, y) with the centre (m) of each box of a pyramid of boxes of side `side` (m), `base` boxes in its
/// bottom row, which rests on y = floorY and is centred on x = centerX. Boxes touch their neighbours. The order is
/// row by row from the bottom, left to right, so the single top box comes last.
template <class Place>
void forEachPyramidBox(int base, double side, double centerX, double floorY, Place&& place) {
    for (int row = 0; row < base; ++row)
        for (int i = 0; i < base - row; ++i)
            place(centerX + side * (i - 0.5 * (base - row - 1)), floorY + side * (0.5 + row));
}

}  // namespace physim::scenes
