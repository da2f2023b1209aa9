#pragma once
// The true distance of a moving pair over t in [0, 1] by dense sampling, refined where it matters: the reference
// for the time-of-impact tests (TimeOfImpactTest.cpp on Geometry shapes, TimeOfImpactKindsTest.cpp on kernel
// shapes). No two points of the pair move apart or together faster than L = |motion_b - motion_a| + |turn_a| R_a +
// |turn_b| R_b (m per unit t, R: bounding radius), so between samples d0 and d1 at spacing h the distance stays
// above (d0 + d1 - L h) / 2. Intervals where that bound is below the tolerance are halved down to a spacing of
// tolerance / (10 L), where the bound is within tolerance / 20 of the samples. So the true minimum is at least
// min(tolerance, sampled minimum - tolerance / 20): the sampling's error bound is tolerance / 20. The walk goes in
// time order and stops at the first sample closer than half the tolerance (all the tests' checks need).

#include "physim/core/Math.hpp"
#include "physim/core/TimeOfImpact.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace physim::testing {

struct DenseSampling {
    double minimum = INFINITY;         ///< m, of the samples
    double firstBelowHalf = INFINITY;  ///< first sampled t with distance < tolerance / 2
    double firstOverlap = INFINITY;    ///< first sampled t with distance 0 (touching or overlapping)
};

/// L above, for shapes of bounding radii ra and rb on the sweeps sa and sb.
inline double closingSpeedBound(const Sweep& sa, double ra, const Sweep& sb, double rb) {
    return ((sb.p1 - sb.p0) - (sa.p1 - sa.p0)).norm() + std::abs(sa.a1 - sa.a0) * ra + std::abs(sb.a1 - sb.a0) * rb;
}

/// distanceAt(t): the pair's true distance (m, 0 when touching or overlapping) at t; speed: closingSpeedBound.
template <class DistanceAt>
DenseSampling sampleDistance(double speed, double tolerance, DistanceAt distanceAt) {
    const double finest = 0.1 * tolerance / std::max(speed, 1e-300);
    DenseSampling s;
    auto sample = [&](double t) {
        const double d = distanceAt(t);
        s.minimum = std::min(s.minimum, d);
        if (d < 0.5 * tolerance) s.firstBelowHalf = std::min(s.firstBelowHalf, t);
        if (d == 0.0) s.firstOverlap = std::min(s.firstOverlap, t);
        return d;
    };
    struct Interval {
        double t0, d0, t1, d1;
    };
    std::vector<Interval> stack;
    const int grid = 1000;
    double t0 = 0.0, d0 = sample(0.0);
    for (int k = 1; k <= grid && s.firstBelowHalf == INFINITY; ++k) {
        const double t1 = static_cast<double>(k) / grid, d1 = sample(t1);
        stack.push_back({t0, d0, t1, d1});
        while (!stack.empty() && s.firstBelowHalf == INFINITY) {
            const Interval i = stack.back();
            stack.pop_back();
            if (0.5 * (i.d0 + i.d1 - speed * (i.t1 - i.t0)) >= tolerance || i.t1 - i.t0 <= finest) continue;
            const double tm = 0.5 * (i.t0 + i.t1), dm = sample(tm);
            stack.push_back({tm, dm, i.t1, i.d1});  // the earlier half on top: time order
            stack.push_back({i.t0, i.d0, tm, dm});
        }
        t0 = t1;
        d0 = d1;
    }
    return s;
}

}  // namespace physim::testing
