#pragma once
// The separating-axis face query and the clipped points' feature ids: one rule for the polygon narrow phase
// (CollidePolygons.cpp) and the rounded cores' (CollideRounded.cpp). Internal.

#include <algorithm>
#include <cstdint>
#include <limits>

namespace physim {

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
