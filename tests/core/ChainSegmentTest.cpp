// Chain pieces at the geometry level: one-sided, and smooth across joints through their ghost points. The
// expected normals are the pieces' own face normals, computed here from the points; 1e-12 allows the rounding of
// normalising them. Where a vertex of the shape sits right above a joint (the loops' x accumulate rounding), the
// joint's vertex and the shape's meet and their direction is straight up to 1e-12 rad: kStraightUp allows that.

#include "physim/core/Collide.hpp"
#include "Manifolds.hpp"
#include "shapes/ChainSegmentKind.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace physim {
namespace {

constexpr double kTol = 1e-12;
constexpr double kStraightUp = 1e-9;

// The pieces of the open chain through `points`: each piece's ghosts are its neighbours' far points, or its own end
// point at the chain's ends.
std::vector<ChainSegment> openChain(const std::vector<Vec2>& points) {
    std::vector<ChainSegment> pieces;
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
        pieces.push_back({i == 0 ? points[i] : points[i - 1], makeSegment(points[i], points[i + 1]),
                          i + 2 < points.size() ? points[i + 2] : points[i + 1]});
    return pieces;
}

Vec2 leftNormal(const ChainSegment& c) {
    const Vec2 e = (c.segment.point2 - c.segment.point1).normalized();
    return {-e.y(), e.x()};
}

// The bodies that slide: the lowest point of each is `depth` below its origin's height minus its half height.
struct Slider {
    const char* name;
    Geometry shape;
    double halfHeight;  // origin to lowest point, unrotated
};

std::vector<Slider> sliders() {
    return {{"box", makeBox(0.4, 0.3), 0.3},
            {"circle", makeCircle(0.3), 0.3},
            {"capsule", makeCapsule({-0.4, 0.0}, {0.4, 0.0}, 0.2), 0.2},
            {"rounded box", makeRoundedBox(0.3, 0.2, 0.1), 0.3}};
}

TEST(ChainSegment, ShapesSlidingOnAFlatChainGetOnlyTheFaceNormal) {
    const std::vector<ChainSegment> chain = openChain({{-3, 0}, {-1, 0}, {1, 0}, {3, 0}});
    int sideways = 0;  // the same pieces as plain two-sided segments, for contrast
    for (const Slider& s : sliders()) {
        for (double x = -2.5; x <= 2.5; x += 1e-3) {
            const Transform xf{{x, s.halfHeight - 0.01}, Rotation::fromAngle(0.0)};
            SCOPED_TRACE(std::string(s.name) + " at x = " + std::to_string(x));
            int points = 0;
            for (const ChainSegment& piece : chain) {
                const Manifold m = collide(piece, Transform{}, s.shape, xf);
                points += m.pointCount;
                if (m.pointCount > 0) {
                    EXPECT_LT((m.normal - Vec2(0.0, 1.0)).norm(), kStraightUp);
                }
                for (int i = 0; i < m.pointCount; ++i) {
                    // Each point within the piece's span (the neighbour answers beyond it) and 0.01 m deep.
                    EXPECT_GE(m.points[i].point.x(), piece.segment.point1.x() - kTol);
                    EXPECT_LE(m.points[i].point.x(), piece.segment.point2.x() + kTol);
                    EXPECT_NEAR(m.points[i].separation, -0.01, 1e-9);
                }
                const Manifold plain = collide(piece.segment, Transform{}, s.shape, xf);
                if (plain.pointCount > 0 && (plain.normal - Vec2(0.0, 1.0)).norm() > 1e-6) ++sideways;
            }
            EXPECT_GT(points, 0) << "the chain holds the shape everywhere";
        }
    }
    EXPECT_GT(sideways, 0) << "two-sided segments do catch a corner at the joints: the ghosts are what smooths them";
}

TEST(ChainSegment, TiltedBoxCrossingJointsGetsOnlyTheFaceNormal) {
    const std::vector<ChainSegment> chain = openChain({{-3, 0}, {-1, 0}, {1, 0}, {3, 0}});
    const Polygon box = makeBox(0.4, 0.3);
    for (double angle : {-0.2, 0.05, 0.3}) {
        // The lowest corner 0.01 below the chain.
        const Rotation q = Rotation::fromAngle(angle);
        double lowest = 0.0;
        for (int i = 0; i < box.count; ++i) lowest = std::min(lowest, q.apply(box.vertices[i]).y());
        for (double x = -2.5; x <= 2.5; x += 1e-3) {
            const Transform xf{{x, -lowest - 0.01}, q};
            for (const ChainSegment& piece : chain) {
                const Manifold m = collide(piece, Transform{}, box, xf);
                if (m.pointCount > 0) {
                    EXPECT_LT((m.normal - Vec2(0.0, 1.0)).norm(), kStraightUp) << "x = " << x;
                }
            }
        }
    }
}

TEST(ChainSegment, NothingFromBehind) {
    const std::vector<ChainSegment> chain = openChain({{-3, 0}, {-1, 0}, {1, 0}, {3, 0}});
    for (const Slider& s : sliders())
        for (double x = -2.5; x <= 2.5; x += 1e-2)
            for (double y : {-0.05, -0.2, -s.halfHeight + 0.01})  // centre below the chain, overlapping it
                for (const ChainSegment& piece : chain)
                    EXPECT_EQ(collide(piece, Transform{}, s.shape, Transform{{x, y}, Rotation{}}).pointCount, 0)
                        << s.name << " at (" << x << ", " << y << ")";
}

// Order of the shapes: the same contact with the normal reversed.
TEST(ChainSegment, EitherOrderGivesTheSameContact) {
    const ChainSegment piece = openChain({{-3, 0}, {-1, 0}, {1, 0}, {3, 0}})[1];
    const Transform xf{{0.3, 0.29}, Rotation::fromAngle(0.1)};
    const Manifold ab = collide(piece, Transform{}, makeCircle(0.3), xf);
    const Manifold ba = collide(makeCircle(0.3), xf, piece, Transform{});
    ASSERT_EQ(ab.pointCount, 1);
    ASSERT_EQ(ba.pointCount, 1);
    EXPECT_LT((ab.normal + ba.normal).norm(), kTol);
    EXPECT_LT((ab.points[0].point - ba.points[0].point).norm(), kTol);
}

// A hilltop: the corner's own normals (between the two pieces' face normals) stand on both pieces; beyond a piece's
// normal only that piece's face answers.
TEST(ChainSegment, ConvexCornerKeepsOnlyTheNormalsBetweenThePieces) {
    const std::vector<ChainSegment> hill = openChain({{-4, -1}, {-2, -0.5}, {0, 0}, {2, -0.5}, {4, -1}});
    const ChainSegment& left = hill[1];
    const ChainSegment& right = hill[2];
    const Circle ball = makeCircle(0.3);
    // Straight above the apex: both pieces see the corner, normal straight up (inside the cone).
    for (const ChainSegment* piece : {&left, &right}) {
        const Manifold m = collide(*piece, Transform{}, ball, Transform{{0.0, 0.29}, Rotation{}});
        ASSERT_EQ(m.pointCount, 1);
        EXPECT_LT((m.normal - Vec2(0.0, 1.0)).norm(), kTol);
    }
    // Up and to the left: the left piece's face; the right piece would see its corner at 135 degrees, beyond the
    // left piece's normal (104 degrees): it drops it.
    const Transform upLeft{{-0.2, 0.2}, Rotation{}};
    const Manifold onLeft = collide(left, Transform{}, ball, upLeft);
    ASSERT_EQ(onLeft.pointCount, 1);
    EXPECT_LT((onLeft.normal - leftNormal(left)).norm(), kTol);
    EXPECT_EQ(collide(right, Transform{}, ball, upLeft).pointCount, 0);
    EXPECT_EQ(collide(right.segment, Transform{}, ball, upLeft).pointCount, 1) << "a plain segment keeps the corner";
}

// A valley: a ball resting in it touches both faces, each with its own normal, never the corner.
TEST(ChainSegment, ConcaveJointGivesEachPieceItsFaceNormal) {
    const std::vector<ChainSegment> valley = openChain({{-4, 1}, {-2, 0.5}, {0, 0}, {2, 0.5}, {4, 1}});
    const Circle ball = makeCircle(0.35);
    for (const double x : {0.0, 0.02, -0.05}) {
        for (int i = 1; i <= 2; ++i) {
            const Manifold m = collide(valley[i], Transform{}, ball, Transform{{x, 0.3}, Rotation{}});
            ASSERT_EQ(m.pointCount, 1) << "piece " << i << " x " << x;
            EXPECT_LT((m.normal - leftNormal(valley[i])).norm(), kTol);
        }
    }
    // A box sitting across the valley's bottom: face normals only.
    const Polygon box = makeBox(0.5, 0.2);
    for (double x = -0.6; x <= 0.6; x += 1e-3)
        for (int i = 1; i <= 2; ++i) {
            const Manifold m = collide(valley[i], Transform{}, box, Transform{{x, 0.3}, Rotation{}});
            if (m.pointCount > 0) {
                EXPECT_LT((m.normal - leftNormal(valley[i])).norm(), kTol) << "x " << x;
            }
        }
}

// A piece whose ghosts are its own end points (both ends open) is its segment made one-sided: wherever the segment's
// normal leans out of the piece's front and the shape's centre is in front, the two manifolds are the same (to
// 1e-12: a capsule, a later kind than the segment, is the first shape of the segment's routine, so the arithmetic
// differs; so do the ids, which name the first shape's vertex first).
TEST(ChainSegment, OpenEndedPieceIsItsOneSidedSegment) {
    std::mt19937_64 rng(4);
    auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    const Segment segment = makeSegment({-1.0, 0.2}, {1.2, -0.1});
    const ChainSegment piece{segment.point1, segment, segment.point2};
    const Vec2 face = leftNormal(piece);
    int compared = 0;
    for (int k = 0; k < 4000; ++k) {
        const Geometry shapes[] = {makeCircle(uniform(0.1, 0.8)), makeBox(uniform(0.1, 0.8), uniform(0.1, 0.8)),
                                   makeCapsule({-0.5, 0.0}, {0.5, 0.0}, uniform(0.05, 0.5)),
                                   makeRoundedBox(uniform(0.1, 0.5), uniform(0.1, 0.5), uniform(0.05, 0.3))};
        const Geometry& shape = shapes[k % 4];
        const Transform xf{{uniform(-2.0, 2.0), uniform(-1.0, 1.0)}, Rotation::fromAngle(uniform(-M_PI, M_PI))};
        const Manifold plain = collide(segment, Transform{}, shape, xf);
        const Manifold chained = collide(piece, Transform{}, shape, xf);
        const Vec2 centre = xf.apply(computeMassProperties(shape).centroid);
        if (face.dot(centre - segment.point1) < 0.0) {
            EXPECT_EQ(chained.pointCount, 0);
            continue;
        }
        if (plain.pointCount == 0 || plain.normal.dot(face) <= 0.0) continue;
        ++compared;
        ASSERT_EQ(chained.pointCount, plain.pointCount);
        EXPECT_LT((chained.normal - plain.normal).norm(), kTol);
        for (int i = 0; i < plain.pointCount; ++i) {
            double nearest = std::numeric_limits<double>::infinity();
            for (int j = 0; j < plain.pointCount; ++j)
                nearest = std::min(nearest, (chained.points[i].point - plain.points[j].point).norm());
            EXPECT_LT(nearest, kTol);
            if (k % 4 != 2) {
                EXPECT_EQ(chained.points[i].id, plain.points[i].id);
            }
        }
    }
    EXPECT_GT(compared, 200);
}

// Random joints (turning -60 to 60 degrees) and random shapes near them, far from the chain's open ends: at a flat or
// concave joint every normal is the piece's face normal; at a convex one it is that or lies between the two pieces'
// normals (the corner's own); a shape whose centre is behind a piece gets nothing from it.
TEST(ChainSegment, RandomJointsGiveOnlyFaceOrCornerNormals) {
    std::mt19937_64 rng(52);
    auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    int contacts = 0, cornerNormals = 0;
    for (int k = 0; k < 20000; ++k) {
        const double heading = uniform(-M_PI, M_PI), turn = uniform(-M_PI / 3, M_PI / 3);
        const Vec2 joint(uniform(-1.0, 1.0), uniform(-1.0, 1.0));
        const Vec2 d1(std::cos(heading), std::sin(heading)), d2(std::cos(heading + turn), std::sin(heading + turn));
        const std::vector<ChainSegment> chain = openChain({joint - 3.0 * d1, joint, joint + 3.0 * d2});
        const Vec2 n1 = leftNormal(chain[0]), n2 = leftNormal(chain[1]);
        const bool convex = turn < 0.0;
        const Geometry shapes[] = {makeCircle(uniform(0.05, 0.5)), makeBox(uniform(0.05, 0.5), uniform(0.05, 0.5)),
                                   makeCapsule({-0.3, 0.0}, {0.3, 0.0}, uniform(0.05, 0.3)),
                                   makeRoundedBox(uniform(0.05, 0.3), uniform(0.05, 0.3), uniform(0.02, 0.2))};
        const Geometry& shape = shapes[k % 4];
        const Transform xf{joint + Vec2(uniform(-0.6, 0.6), uniform(-0.6, 0.6)),
                           Rotation::fromAngle(uniform(-M_PI, M_PI))};
        const Vec2 centre = xf.apply(computeMassProperties(shape).centroid);
        for (int i = 0; i < 2; ++i) {
            const Manifold m = collide(chain[i], Transform{}, shape, xf);
            const Vec2 face = i == 0 ? n1 : n2;
            SCOPED_TRACE("draw " + std::to_string(k) + ", piece " + std::to_string(i));
            if (face.dot(centre - chain[i].segment.point1) < 0.0) {
                EXPECT_EQ(m.pointCount, 0);
                continue;
            }
            if (m.pointCount == 0) continue;
            ++contacts;
            ASSERT_NEAR(m.normal.norm(), 1.0, 1e-12);
            if ((m.normal - face).norm() < 1e-9) continue;
            ++cornerNormals;
            EXPECT_TRUE(convex) << "turn " << turn << ": only a convex joint has a corner";
            // Between n1 and n2 (n2 is clockwise of n1 at a convex joint), to rounding.
            EXPECT_LE(cross(n1, m.normal), 1e-12);
            EXPECT_GE(cross(n2, m.normal), -1e-12);
        }
    }
    EXPECT_GT(contacts, 5000);
    EXPECT_GT(cornerNormals, 100);
}

// Two pieces 0.1 to 1 m long meeting at a joint within 1 m of the origin and turning there by -60 to 60 degrees,
// drawn from `uniform`; draw k % 10 == 0 has an open end at the joint (a real corner).
struct RandomJoint {
    std::vector<ChainSegment> chain;
    Vec2 joint;
    double turn;
};
template <class Uniform>
RandomJoint randomJoint(Uniform& uniform, int k) {
    const double heading = uniform(-M_PI, M_PI), turn = uniform(-M_PI / 3, M_PI / 3);
    const Vec2 joint(uniform(-1.0, 1.0), uniform(-1.0, 1.0));
    const Vec2 d1(std::cos(heading), std::sin(heading)), d2(std::cos(heading + turn), std::sin(heading + turn));
    const double length = uniform(0.1, 1.0);
    std::vector<ChainSegment> chain = openChain({joint - length * d1, joint, joint + length * d2});
    if (k % 10 == 0) chain[1].ghost1 = chain[1].segment.point1;
    return {chain, joint, turn};
}

// An empty answer's StaysEmpty is a promise the narrow phase acts on (it skips the routine while the promise
// holds): the routine must answer empty again at any pose and margin within it. Random joints (as above), circles
// and boxes off their bodies' origins, random margins; each empty answer with a promise is asked again after a
// random move of the body about a random centre of mass: a shift and a turn whose bound (shift + turn x the arm
// from that centre to the promise's point, as the narrow phase measures it) spends up to all of the allowance.
// No tolerance: a single contact found inside the promise fails. The draws also show the promise is worth
// keeping: most empty answers near a joint carry one.
TEST(ChainSegment, AnEmptyAnswerStaysEmptyWithinItsPromise) {
    std::mt19937_64 rng(54);
    auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    int empties = 0, promised = 0, anyMargin = 0, checked = 0;
    for (int k = 0; k < 40000; ++k) {
        const RandomJoint drawn = randomJoint(uniform, k);
        const std::vector<ChainSegment>& chain = drawn.chain;
        const Vec2& joint = drawn.joint;
        const Vec2 off(uniform(-0.3, 0.3), uniform(-0.3, 0.3));
        const Geometry shape = k % 2 == 0 ? Geometry{makeCircle(uniform(0.05, 0.5), off)}
                                          : Geometry{makeBox(uniform(0.05, 0.5), uniform(0.05, 0.5), off,
                                                             uniform(-M_PI, M_PI))};
        const Vec2 centreOfMass(uniform(-0.3, 0.3), uniform(-0.3, 0.3));  // body-local
        const Transform xa{{uniform(-5.0, 5.0), uniform(-5.0, 5.0)}, Rotation::fromAngle(uniform(-M_PI, M_PI))};
        const Transform xb{xa.apply(joint + Vec2(uniform(-1.2, 1.2), uniform(-1.2, 1.2))),
                           Rotation::fromAngle(uniform(-M_PI, M_PI))};
        const double margin = uniform(0.0, 0.2);
        for (int i = 0; i < 2; ++i) {
            const NarrowResult r = collideGeometries(chain[i], xa, shape, xb, margin);
            if (r.manifold.pointCount > 0) continue;
            ++empties;
            const StaysEmpty& p = r.empty;
            if (!(p.distance > 0.0)) continue;
            ++promised;
            anyMargin += p.anyMargin;
            const double later = p.anyMargin ? uniform(0.0, 0.3) : uniform(0.0, p.distance);
            const double budget = p.anyMargin ? p.distance : p.distance - std::max(later, kSpeculativeMargin);
            if (!(budget > 0.0)) continue;
            const double arm = (p.about - centreOfMass).norm();
            const double spend = (k % 7 == 0 ? 0.999999 : uniform(0.0, 1.0)) * budget, share = uniform(0.0, 1.0);
            const double shiftAngle = uniform(-M_PI, M_PI);
            const Vec2 shift = share * spend * Vec2(std::cos(shiftAngle), std::sin(shiftAngle));
            const double dTheta = arm > 0.0 ? (1.0 - share) * spend / arm * (uniform(0.0, 1.0) < 0.5 ? -1 : 1) : 0.0;
            const Rotation q2 = Rotation::fromAngle(xb.q.angle() + dTheta);
            const Transform xb2{xb.apply(centreOfMass) + shift - q2.apply(centreOfMass), q2};
            SCOPED_TRACE("draw " + std::to_string(k) + ", piece " + std::to_string(i));
            EXPECT_EQ(collideGeometries(chain[i], xa, shape, xb2, later).manifold.pointCount, 0);
            ++checked;
        }
    }
    EXPECT_GT(checked, 20000);
    EXPECT_GT(anyMargin, 5000);
    EXPECT_GT(promised, empties / 2);
}

TEST(ChainSegment, FrontOffsetIsTheShapeCentresSignedDistanceFromThePiecesLine) {
    // What the Continuous stage asks of a piece (whether a body stays in front of it): the signed distance of the
    // shape's centre from the piece's line, here from world points by the cross product. Random poses within 10 m;
    // 1e-12 m per metre of scale is the rounding of two transforms.
    std::mt19937 rng(52);
    std::uniform_real_distribution<double> coord(-5.0, 5.0), angle(-3.2, 3.2);
    const ChainSegment piece{{-2.0, -0.5}, makeSegment({-1.0, 0.0}, {1.0, 0.2}), {2.0, 0.6}};
    const Geometry shapes[] = {makeCircle(0.3, {0.1, -0.2}), makeBox(0.4, 0.2, {0.3, 0.1}, 0.5),
                               makeCapsule({-0.2, 0.0}, {0.4, 0.3}, 0.1)};
    const Vec2 centres[] = {{0.1, -0.2}, {0.3, 0.1}, {0.1, 0.15}};  // each shape's centre, body-local
    for (int trial = 0; trial < 200; ++trial) {
        const Transform xa{{coord(rng), coord(rng)}, Rotation::fromAngle(angle(rng))};
        const Transform xb{{coord(rng), coord(rng)}, Rotation::fromAngle(angle(rng))};
        const Vec2 p1 = xa.apply(piece.segment.point1), p2 = xa.apply(piece.segment.point2);
        for (int k = 0; k < 3; ++k) {
            const Vec2 c = xb.apply(centres[k]);
            const double expected = cross(p2 - p1, c - p1) / (p2 - p1).norm();
            EXPECT_NEAR(frontOffset(piece, xa, shapes[k], xb), expected, 1e-11) << trial << " " << k;
        }
    }
    EXPECT_TRUE(std::isinf(frontOffset(piece, {}, Geometry{piece}, {})));
}

TEST(ChainSegment, PointsKeptRightUpToTheMarginNearAndFarFromTheOrigin) {
    // The narrow phase rejects most pieces before any manifold work (clearlyApart, then apart): a circle whose gap
    // to the piece is 1e-7 m under the kept margin must still get its point, and 1e-7 m over it none, in front of
    // the piece's span and past either (open) end, and with the pair 1e6 m from the origin. 1e-7 m is far above the
    // rounding of these distances (1e-10 m at 1e6 m) and far below the rejections' slack would need to be wrong by.
    // A box (its bounding circle is only a bound) keeps its point under the margin too.
    constexpr double kMargin = 0.004, kStep = 1e-7, kRadius = 0.3;
    for (double far : {0.0, 1e6}) {
        const Vec2 shift(far, -far);
        const Vec2 end1 = shift + Vec2(-1.0, 0.0), end2 = shift + Vec2(1.0, 0.2);
        const ChainSegment piece{end1, makeSegment(end1, end2), end2};  // open ends: real corners
        const Vec2 p1 = piece.segment.point1, p2 = piece.segment.point2;
        const Vec2 up = leftNormal(piece);
        const Vec2 out1 = (up - (p2 - p1).normalized()).normalized();  // past point1, up and outwards
        const Vec2 out2 = (up + (p2 - p1).normalized()).normalized();
        const std::pair<Vec2, Vec2> nearest[] = {{p1 + 0.3 * (p2 - p1), up}, {p1, out1}, {p2, out2}};
        for (const auto& [point, direction] : nearest)
            for (double angle : {0.0, 0.7, -2.1}) {
                for (int side : {-1, 1}) {
                    const double gap = kMargin + side * kStep;
                    const Transform xb{
                        point + (kRadius + gap) * direction - Rotation::fromAngle(angle).apply({0.05, 0.0}),
                        Rotation::fromAngle(angle)};
                    const NarrowResult r =
                        collideChainSegment(piece, Transform{}, coreOf(makeCircle(kRadius, {0.05, 0.0})), xb, kMargin);
                    EXPECT_EQ(r.manifold.pointCount, side < 0 ? 1 : 0)
                        << "far " << far << " angle " << angle << " gap " << gap;
                }
                // A box resting flat above the middle of the span, its bottom face kMargin - kStep above the piece.
                const double tilt = std::atan2(p2.y() - p1.y(), p2.x() - p1.x());
                const Transform xb{p1 + 0.5 * (p2 - p1) + (0.2 + kMargin - kStep) * up, Rotation::fromAngle(tilt)};
                EXPECT_GT(
                    collideChainSegment(piece, Transform{}, coreOf(makeBox(0.4, 0.2)), xb, kMargin).manifold.pointCount,
                    0)
                    << "far " << far;
            }
    }
}

TEST(ChainSegment, GroundAgainstGroundHasNoContact) {
    const ChainSegment piece = openChain({{-3, 0}, {-1, 0}, {1, 0}})[0];
    EXPECT_EQ(collide(piece, Transform{}, piece, Transform{}).pointCount, 0);
    EXPECT_EQ(collide(piece, Transform{}, makeSegment({-2, -1}, {-2, 1}), Transform{}).pointCount, 0);
    EXPECT_EQ(collide(makeSegment({-2, -1}, {-2, 1}), Transform{}, piece, Transform{}).pointCount, 0);
}

// A circle's chain collision skips the routine where the circle lies clearly beyond an end of the piece and the
// neighbour answers (circleLeftToNeighbour): there the routine must give no contact. Random joints turning -60 to
// 60 degrees (some chains open-ended), random circles near the joint, random piece transforms and margins: every
// skipped case is checked against collideChainSegment, and the collision with the skip gives the routine's
// manifold bit for bit in every case (the skip returns only where the routine finds nothing).
TEST(ChainSegment, CircleShortcutGivesTheRoutinesAnswer) {
    std::mt19937_64 rng(53);
    auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    int skipped = 0, skippedAtConvex = 0, contacts = 0;
    for (int k = 0; k < 40000; ++k) {
        const RandomJoint drawn = randomJoint(uniform, k);
        const std::vector<ChainSegment>& chain = drawn.chain;
        const Vec2& joint = drawn.joint;
        const double turn = drawn.turn;
        const Circle circle = makeCircle(uniform(0.05, 0.5));
        const Transform xa{{uniform(-5.0, 5.0), uniform(-5.0, 5.0)}, Rotation::fromAngle(uniform(-M_PI, M_PI))};
        const Transform xb{xa.apply(joint + Vec2(uniform(-0.8, 0.8), uniform(-0.8, 0.8))),
                           Rotation::fromAngle(uniform(-M_PI, M_PI))};
        const double margin = uniform(0.0, 0.2);
        for (int i = 0; i < 2; ++i) {
            SCOPED_TRACE("draw " + std::to_string(k) + ", piece " + std::to_string(i));
            const NarrowResult full = collideChainSegment(chain[i], xa, coreOf(circle), xb, margin);
            const NarrowResult got = collideGeometries(chain[i], xa, circle, xb, margin);
            if (circleLeftToNeighbour(chain[i], xa, circle, xb) >= 0.0) {
                ++skipped;
                if (turn < 0.0) ++skippedAtConvex;
                EXPECT_EQ(full.manifold.pointCount, 0);
            }
            contacts += full.manifold.pointCount > 0;
            ASSERT_EQ(got.manifold.pointCount, full.manifold.pointCount);
            for (int p = 0; p < full.manifold.pointCount; ++p) {
                EXPECT_EQ(got.manifold.normal, full.manifold.normal);
                EXPECT_EQ(got.manifold.points[p].point, full.manifold.points[p].point);
                EXPECT_EQ(got.manifold.points[p].separation, full.manifold.points[p].separation);
                EXPECT_EQ(got.manifold.points[p].id, full.manifold.points[p].id);
            }
        }
    }
    // The draws reach every branch: skips at convex and other joints, and contacts the routine keeps.
    EXPECT_GT(skipped, 5000);
    EXPECT_GT(skippedAtConvex, 1000);
    EXPECT_GT(contacts, 5000);
}

}  // namespace
}  // namespace physim
