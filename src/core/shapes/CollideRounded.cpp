// Narrow phase for two rounded cores (RoundedCore.hpp): every pair of kinds but circle-circle and the radius-0
// polygon pairs. The separation is the distance between the cores minus both radii:
// - cores apart: the closest features (found over every vertex-edge pair: at most 8 x 8) give the normal: an edge's
//   own normal when a vertex faces its interior (then the other shape's edge most antiparallel to it is clipped to
//   that face for up to two points), the direction between two vertices otherwise (one point);
// - cores overlapping: separating axes over both cores' edge normals, then the incident edge clipped to the
//   reference face, as for two polygons (CollidePolygons.cpp).
// Separating axes alone would miss the gap between two collinear segments (their Minkowski difference has no
// area), so cores of at most 2 vertices are checked by their closest features unless they cross.

#include "Faces.hpp"
#include "RoundedCore.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace physim {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kFacingCosine = -0.9998;  // as CollidePolygons.cpp: faces within about 1.1 degrees of antiparallel

// The face of p whose line is farthest from q (face -1 when p has no edges).
FaceQuery facesOf(const RoundedCore& p, const RoundedCore& q) {
    if (p.count < 2) return {-1, -kInfinity};
    return maxSeparation(p, q);
}

Vec2 directionOr(const Vec2& v, const Vec2& fallback) {
    const double length = v.norm();  // coordinates are bounded (Validate.hpp): no overflow; an underflow falls back
    return length > 0.0 ? Vec2(v / length) : fallback;
}

int edgeCount(const RoundedCore& c) { return c.count == 1 ? 0 : c.count == 2 ? 1 : c.count; }

struct Closest {
    enum Kind { kVertexOnFaceOfA, kVertexOnFaceOfB, kVertices };
    double distance = kInfinity;
    Kind kind = kVertices;
    int face = 0;  // the face whose interior holds the closest point
    int vertexA = 0, vertexB = 0;
};

// Every vertex of q against every edge of p; pIsA says which of the pair p is.
void closestToEdges(const RoundedCore& p, const RoundedCore& q, bool pIsA, Closest& best) {
    for (int i = 0; i < edgeCount(p); ++i) {
        const Vec2& v1 = p.vertices[i];
        const Vec2& v2 = p.vertices[(i + 1) % p.count];
        const Vec2 e = v2 - v1;
        const double ee = e.squaredNorm();
        for (int j = 0; j < q.count; ++j) {
            const Vec2& w = q.vertices[j];
            const double u = (w - v1).dot(e);
            double d;
            int face = i, vertex = i;
            // The face's span includes its ends: where a vertex lies straight above another (aligned boxes) the
            // face and the two vertices are equally close, and the face gives the two-point manifold.
            const bool onFace = u >= 0.0 && u <= ee;
            if (onFace) {
                double s = p.normals[i].dot(w - v1);
                if (s < 0.0) {
                    // A 2-vertex core's other side; for a polygon the inner side of an edge is never the closest
                    // feature of a vertex outside it (the closest pair has the vertex on an outward normal).
                    if (p.count != 2) continue;
                    s = -s;
                    face = 1;
                }
                d = s;
            } else {
                vertex = u <= 0.0 ? i : (i + 1) % p.count;
                const Vec2 diff = w - p.vertices[vertex];
                d = diff.norm();
            }
            if (d < best.distance || (d == best.distance && onFace && best.kind == Closest::kVertices)) {
                best.distance = d;
                best.face = face;
                if (onFace) {
                    best.kind = pIsA ? Closest::kVertexOnFaceOfA : Closest::kVertexOnFaceOfB;
                    (pIsA ? best.vertexB : best.vertexA) = j;
                } else {
                    best.kind = Closest::kVertices;
                    best.vertexA = pIsA ? vertex : j;
                    best.vertexB = pIsA ? j : vertex;
                }
            }
        }
    }
}

Closest closest(const RoundedCore& a, const RoundedCore& b) {
    Closest best;
    if (a.count == 1 && b.count == 1) {
        const Vec2 d = b.vertices[0] - a.vertices[0];
        best.distance = d.norm();
        return best;
    }
    closestToEdges(a, b, true, best);
    closestToEdges(b, a, false, best);
    return best;
}

// Two 2-vertex cores whose segments cross at a point inside both.
bool properlyCross(const RoundedCore& a, const RoundedCore& b) {
    if (a.count != 2 || b.count != 2) return false;
    const Vec2 ea = a.vertices[1] - a.vertices[0], eb = b.vertices[1] - b.vertices[0];
    const double d1 = cross(ea, b.vertices[0] - a.vertices[0]), d2 = cross(ea, b.vertices[1] - a.vertices[0]);
    const double d3 = cross(eb, a.vertices[0] - b.vertices[0]), d4 = cross(eb, a.vertices[1] - b.vertices[0]);
    return ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0));
}

// The manifold with ref's face i1 as the reference (flip: ref is b, so the normal is reversed to run from a to b).
// inc's edge most antiparallel to the face's normal (or its one vertex) is clipped to the face's span. Each point
// lies midway between the surfaces. `separation` is the pair's; inSpanOnly drops what lies outside the span and
// takes the separation from the points (a chain piece's face, ChainSegmentKind.cpp).
LocalManifold clip(const RoundedCore& ref, int i1, const RoundedCore& inc, bool flip, double separation,
                   double margin, bool inSpanOnly) {
    const Vec2 n = ref.normals[i1];
    const Vec2 t = perp(n);
    const int i1Next = (i1 + 1) % ref.count;
    const Vec2& v11 = ref.vertices[i1];
    const double faceLength = t.dot(ref.vertices[i1Next] - v11);
    const double radii = ref.radius + inc.radius;

    Vec2 clipped[2];
    int refVertex[2] = {i1, i1Next}, incVertex[2] = {0, 0};
    int candidates = 0;
    if (inc.count == 1) {
        clipped[0] = inc.vertices[0];
        const double along = t.dot(clipped[0] - v11);
        candidates = !inSpanOnly || (along >= 0.0 && along <= faceLength) ? 1 : 0;
    } else {
        int i2 = 0;
        double mostAntiparallel = kInfinity;
        for (int j = 0; j < inc.count; ++j) {
            const double d = n.dot(inc.normals[j]);
            if (d < mostAntiparallel) {
                mostAntiparallel = d;
                i2 = j;
            }
        }
        const int i2Next = (i2 + 1) % inc.count;
        const Vec2& v21 = inc.vertices[i2];
        const Vec2& v22 = inc.vertices[i2Next];
        const double lower = t.dot(v22 - v11), upper = t.dot(v21 - v11);
        const double span = upper - lower;
        const double from = std::max(lower, 0.0), to = std::min(upper, faceLength);
        if (span > 0.0 && from <= to) {
            clipped[0] = v22 + ((from - lower) / span) * (v21 - v22);
            clipped[1] = v22 + ((to - lower) / span) * (v21 - v22);
            incVertex[0] = i2Next;
            incVertex[1] = i2;
            candidates = 2;
        } else if (!(inSpanOnly && span > 0.0)) {
            const bool lowerDeeper = n.dot(v22 - v11) <= n.dot(v21 - v11);
            clipped[0] = lowerDeeper ? v22 : v21;
            incVertex[0] = lowerDeeper ? i2Next : i2;
            refVertex[0] = lowerDeeper ? i1 : i1Next;
            const double along = t.dot(clipped[0] - v11);
            candidates = !inSpanOnly || (along >= 0.0 && along <= faceLength) ? 1 : 0;
        }
    }

    LocalManifold m;
    double separations[2] = {kInfinity, kInfinity};
    int deepest = 0;
    for (int k = 0; k < candidates; ++k) {
        separations[k] = n.dot(clipped[k] - v11) - radii;
        if (separations[k] < separations[deepest]) deepest = k;
    }
    if (candidates == 0) return m;
    if (inSpanOnly) {
        separation = separations[deepest];
        if (separation > margin) {
            m.separation = separation;
            return m;
        }
    }
    m.separation = separation;
    m.normal = flip ? Vec2(-n) : n;
    // Midway between the reference surface (the point's projection on the face, pushed out by ref.radius) and the
    // incident surface (the point pulled in by inc.radius).
    auto add = [&](int k, double s) {
        const int slot = m.pointCount++;
        m.points[slot] = midwayPoint(clipped[k], n, ref.radius, inc.radius, radii, separations[k]);
        m.separations[slot] = s;
        m.ids[slot] = featureId(flip, refVertex[k], incVertex[k]);
    };
    const double keep = std::max(margin, kSpeculativeMargin);
    for (int k = 0; k < candidates; ++k)
        if (separations[k] <= keep) add(k, separations[k]);
    if (m.pointCount == 0) add(deepest, deepestSeparation(separations[deepest], separation));
    return m;
}

}  // namespace

RoundedCore coreOf(const Circle& c) {
    RoundedCore k;
    k.vertices[0] = c.center;
    k.normals[0] = Vec2::Zero();  // a point has no edge
    k.count = 1;
    k.radius = c.radius;
    return k;
}

RoundedCore coreOf(const Polygon& p) {
    RoundedCore k;
    k.vertices = p.vertices;
    k.normals = p.normals;
    k.count = p.count;
    k.radius = p.radius;
    return k;
}

RoundedCore coreOf(const Vec2& p1, const Vec2& p2, double radius) {
    RoundedCore k;
    const Vec2 e = p2 - p1;
    k.vertices[0] = p1;
    k.vertices[1] = p2;
    k.normals[0] = Vec2(e.y(), -e.x()) / e.norm();
    k.normals[1] = -k.normals[0];
    k.count = 2;
    k.radius = radius;
    return k;
}

RoundedCore coreOf(const Segment& s) { return coreOf(s.point1, s.point2, 0.0); }

RoundedCore coreOf(const Capsule& c) { return coreOf(c.center1, c.center2, c.radius); }

RoundedCore relativeCore(const RoundedCore& b, const Transform& xa, const Transform& xb) {
    RoundedCore local;
    local.count = b.count;
    local.radius = b.radius;
    placeInFrameOf(local, b, xa, xb);
    return local;
}

LocalManifold collideCores(const RoundedCore& a, const RoundedCore& b, double margin) {
    const double radii = a.radius + b.radius;
    const FaceQuery onA = facesOf(a, b);
    const FaceQuery onB = facesOf(b, a);
    const double sat = std::max(onA.separation, onB.separation);  // a lower bound of the cores' distance
    LocalManifold m;
    if (sat - radii > margin) {
        m.separation = sat - radii;
        return m;
    }

    if (sat > 0.0 || (a.count <= 2 && b.count <= 2 && !properlyCross(a, b))) {
        const Closest c = closest(a, b);
        if (c.distance > 0.0) {
            const double s = c.distance - radii;
            if (s > margin) {
                m.separation = s;
                return m;
            }
            if (c.kind == Closest::kVertexOnFaceOfA) return clip(a, c.face, b, false, s, margin, false);
            if (c.kind == Closest::kVertexOnFaceOfB) return clip(b, c.face, a, true, s, margin, false);
            const Vec2& pa = a.vertices[c.vertexA];
            m.normal = directionOr(b.vertices[c.vertexB] - pa, Vec2(0.0, 1.0));
            m.separation = s;
            m.pointCount = 1;
            m.points[0] = pa + (a.radius + 0.5 * s) * m.normal;
            m.separations[0] = s;
            m.ids[0] = featureId(false, c.vertexA, c.vertexB);
            return m;
        }
    }

    if (onA.face < 0 && onB.face < 0) {  // two coincident points: every direction needs the same push
        m.normal = Vec2(0.0, 1.0);
        m.separation = -radii;
        m.pointCount = 1;
        m.points[0] = a.vertices[0] + (a.radius + 0.5 * m.separation) * m.normal;
        m.separations[0] = m.separation;
        return m;
    }
    // The reference face is the face of least overlap; a's face wins a near tie between facing faces (see
    // kReferenceFaceTolerance) so the feature ids do not flicker.
    const bool facing = onA.face >= 0 && onB.face >= 0 &&
                        a.normals[onA.face].dot(b.normals[onB.face]) < kFacingCosine;
    const bool flip = facing ? onB.separation > onA.separation + kReferenceFaceTolerance
                             : onB.separation > onA.separation;
    if (flip) return clip(b, onB.face, a, true, onB.separation - radii, margin, false);
    return clip(a, onA.face, b, false, onA.separation - radii, margin, false);
}

LocalManifold collideWithFace(const RoundedCore& a, int face, const RoundedCore& b, double margin) {
    return clip(a, face, b, false, 0.0, margin, true);
}

NarrowResult placed(const LocalManifold& m, const Transform& xa) {
    NarrowResult r;
    r.separation = m.separation;
    if (m.pointCount == 0) return r;
    r.manifold.normal = xa.q.apply(m.normal);
    r.manifold.pointCount = m.pointCount;
    for (int k = 0; k < m.pointCount; ++k) {
        ContactPoint& cp = r.manifold.points[k];
        cp.point = xa.apply(m.points[k]);
        cp.separation = m.separations[k];
        cp.id = m.ids[k];
    }
    return r;
}

NarrowResult collideRounded(const RoundedCore& a, const Transform& xa, const RoundedCore& b, const Transform& xb,
                            double margin) {
    return placed(collideCores(a, relativeCore(b, xa, xb), margin), xa);
}

}  // namespace physim
