#pragma once
// What the polygon narrow phase (CollidePolygons.cpp) and the rounded cores' (CollideRounded.cpp) share, one rule
// each: the second shape placed in the first one's frame, the separating-axis face query, and the clipped points'
// feature ids. Internal.

#include "physim/core/Math.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace physim {

/// Places b's vertices and normals (its first `count`) in a's frame: xa^-1 xb applied to them. Working there keeps b's
/// vertices small numbers even far from the world origin. S holds `count`, `vertices` and `normals`.
/// xa^-1 xb: b's frame seen from a's.
inline Transform relativeTransform(const Transform& xa, const Transform& xb) {
    const Rotation q{xa.q.c * xb.q.c + xa.q.s * xb.q.s, xa.q.c * xb.q.s - xa.q.s * xb.q.c};  // qa^-1 qb
    return {xa.q.applyInverse(xb.p - xa.p), q};
}

template <class S>
void placeInFrameOf(S& local, const S& b, const Transform& xa, const Transform& xb) {
    const Transform relative = relativeTransform(xa, xb);
    for (int i = 0; i < b.count; ++i) {
        local.vertices[i] = relative.apply(b.vertices[i]);
        local.normals[i] = relative.q.apply(b.normals[i]);
    }
}

struct FaceQuery {
    int face = 0;
    double separation = -std::numeric_limits<double>::infinity();
};

/// The face of `p` whose supporting line is farthest from `q` (greatest separation). Its separation is
/// min over q's vertices of n_i . (w - v_i); the shapes (their cores) are disjoint when some face's separation is
/// > 0. P and Q hold `count`, `vertices` and, for P, `normals` (Polygon, RoundedCore).
template <class P, class Q>
FaceQuery maxSeparation(const P& p, const Q& q) {
    FaceQuery best;
    for (int i = 0; i < p.count; ++i) {
        double s = std::numeric_limits<double>::infinity();
        for (int j = 0; j < q.count; ++j) s = std::min(s, p.normals[i].dot(q.vertices[j] - p.vertices[i]));
        if (s > best.separation) best = {i, s};
    }
    return best;
}

/// Feature id of a clipped point: the vertex of the first shape and the vertex of the second shape it lies
/// between (the reference face's end and the incident edge's end on the same side of the clip). It does not say
/// which shape is the reference, so a reference face that swaps between two facing faces (a box on a box, tilted
/// by a hair one way or the other) keeps its ids, and with them the warm-start impulses.
inline std::uint32_t featureId(bool flip, int referenceVertex, int incidentVertex) {
    const int onA = flip ? incidentVertex : referenceVertex;
    const int onB = flip ? referenceVertex : incidentVertex;
    return static_cast<std::uint32_t>(onA) << 4 | static_cast<std::uint32_t>(onB);
}

}  // namespace physim
