// A chain's pieces from its points: each piece knows its neighbours (its ghosts), so the narrow phase can smooth
// the joints (ChainSegmentKind.cpp).

#include "SegmentKind.hpp"

#include <stdexcept>
#include <string>

namespace physim {

std::vector<ChainSegment> makeChain(const std::vector<Vec2>& points, bool loop) {
    const std::size_t n = points.size();
    const std::size_t least = loop ? 3 : 2;
    if (n < least)
        throw std::invalid_argument("physim: a " + std::string(loop ? "loop" : "chain") + " needs at least " +
                                    std::to_string(least) + " points, got " + std::to_string(n));
    const std::size_t pieces = loop ? n : n - 1;
    std::vector<ChainSegment> chain;
    chain.reserve(pieces);
    for (std::size_t i = 0; i < pieces; ++i) {
        const std::size_t j = (i + 1) % n;
        const std::string name = "chain piece " + std::to_string(i);
        const std::string first = "point " + std::to_string(i), second = "point " + std::to_string(j);
        requireTwoPoints(name.c_str(), first.c_str(), points[i], second.c_str(), points[j]);
        ChainSegment piece;
        piece.segment = Segment{points[i], points[j]};
        piece.ghost1 = loop || i > 0 ? points[(i + n - 1) % n] : points[i];
        piece.ghost2 = loop || j + 1 < n ? points[(j + 1) % n] : points[j];
        chain.push_back(piece);
    }
    return chain;
}

}  // namespace physim
