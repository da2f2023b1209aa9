// Narrow phase for two convex polygons: separating axes (SAT) over both polygons' face normals, then a
// contact manifold from clipping the incident edge against the reference face.

#include "Faces.hpp"
#include "PolygonKind.hpp"

#include <algorithm>
#include <limits>

namespace physim {
namespace {

// Faces count as facing each other (a resting stack) when their normals are within about 1.1 degrees of
// antiparallel; only then is the reference-face tolerance applied.
constexpr double kFacingCosine = -0.9998;

}  // namespace

NarrowResult collidePolygons(const Polygon& a, const Transform& xa, const Polygon& b, const Transform& xb,
                             double margin) {
    Polygon local = b;
    placeInFrameOf(local, b, xa, xb);

    NarrowResult r;
    const FaceQuery onA = maxSeparation(a, local);
    const FaceQuery onB = maxSeparation(local, a);
    r.separation = std::max(onA.separation, onB.separation);
    if (r.separation > margin) return r;

    // The reference face is the face of least overlap (the minimum translation); a's face wins a near tie
    // between facing faces so the choice, and so the feature ids, do not flicker.
    const bool facing = a.normals[onA.face].dot(local.normals[onB.face]) < kFacingCosine;
    const bool flip = facing ? onB.separation > onA.separation + kReferenceFaceTolerance
                             : onB.separation > onA.separation;
    const Polygon& ref = flip ? local : a;
    const Polygon& inc = flip ? a : local;
    const int i1 = flip ? onB.face : onA.face;
    r.separation = flip ? onB.separation : onA.separation;

    const Vec2 n = ref.normals[i1];
    const Vec2 t = perp(n);  // direction of the reference edge (counter-clockwise polygon)
    const Vec2& v11 = ref.vertices[i1];
    const double faceLength = t.dot(ref.vertices[(i1 + 1) % ref.count] - v11);

    // Incident edge: the edge of the other polygon most antiparallel to the reference normal. It holds the
    // other polygon's deepest vertex, and runs along -t.
    int i2 = 0;
    double mostAntiparallel = std::numeric_limits<double>::infinity();
    for (int j = 0; j < inc.count; ++j) {
        const double d = n.dot(inc.normals[j]);
        if (d < mostAntiparallel) {
            mostAntiparallel = d;
            i2 = j;
        }
    }
    const Vec2& v21 = inc.vertices[i2];
    const Vec2& v22 = inc.vertices[(i2 + 1) % inc.count];

    // Clip the incident edge to the reference face's side planes (0 <= t . (x - v11) <= faceLength). Positions
    // along t: v22 is the lower end, v21 the upper. The two ranges overlap for the least-overlap face; a guard
    // keeps a single vertex if tolerances ever make them miss.
    const double lower = t.dot(v22 - v11), upper = t.dot(v21 - v11);
    const double span = upper - lower;  // > 0: the incident edge is within 60 degrees of antiparallel
    Vec2 clipped[2];
    int ends[2] = {0, 1};
    int candidates = 2;
    const double from = std::max(lower, 0.0), to = std::min(upper, faceLength);
    if (span > 0.0 && from <= to) {
        clipped[0] = v22 + ((from - lower) / span) * (v21 - v22);
        clipped[1] = v22 + ((to - lower) / span) * (v21 - v22);
    } else {
        const bool lowerDeeper = n.dot(v22 - v11) <= n.dot(v21 - v11);
        clipped[0] = lowerDeeper ? v22 : v21;
        ends[0] = lowerDeeper ? 0 : 1;
        candidates = 1;
    }

    // Keep the points on or below the reference face, or within kSpeculativeMargin (or the caller's margin) above
    // it: a tilted incident edge touches with one end only (vertex against face). Each point goes midway between
    // the two surfaces.
    const double keep = std::max(margin, kSpeculativeMargin);
    Manifold& m = r.manifold;
    m.normal = xa.q.apply(flip ? Vec2(-n) : n);
    double separations[2];
    int deepest = 0;
    for (int k = 0; k < candidates; ++k) {
        separations[k] = n.dot(clipped[k] - v11);
        if (separations[k] < separations[deepest]) deepest = k;
    }
    for (int k = 0; k < candidates; ++k) {
        if (separations[k] > keep) continue;
        ContactPoint& cp = m.points[m.pointCount++];
        cp.point = xa.apply(clipped[k] - 0.5 * separations[k] * n);
        cp.separation = separations[k];
        cp.id = featureId(flip, ends[k] == 0 ? i1 : (i1 + 1) % ref.count, ends[k] == 0 ? (i2 + 1) % inc.count : i2);
    }
    if (m.pointCount == 0) {  // within the margin along every axis but the clipped edge ends above the face
        ContactPoint& cp = m.points[m.pointCount++];
        cp.point = xa.apply(clipped[deepest] - 0.5 * separations[deepest] * n);
        cp.separation = std::min(separations[deepest], std::max(r.separation, 0.0));
        cp.id = featureId(flip, ends[deepest] == 0 ? i1 : (i1 + 1) % ref.count,
                          ends[deepest] == 0 ? (i2 + 1) % inc.count : i2);
    }
    return r;
}

}  // namespace physim
