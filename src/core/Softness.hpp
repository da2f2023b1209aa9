#pragma once
// Soft constraints: a row solved as an implicit spring-damper instead of rigidly (Catto's soft step), shared by the
// contact rows (ContactSolver.hpp) and the joint rows (joints/). Internal.

#include <algorithm>

namespace physim {

/// A soft constraint's coefficients for a substep h: a spring of `hertz` with `dampingRatio`, implicit in time.
struct Softness {
    double biasRate = 0.0;      // 1/s: velocity bias per metre of error
    double massScale = 1.0;
    double impulseScale = 0.0;
};

/// hertz <= 0: rigid. The spring is capped at a quarter of the substep rate, the stiffest the one-pass Gauss-Seidel
/// solve keeps stable: at a quarter a 40-box pyramid holds, at half its base shakes apart.
inline Softness makeSoftness(double hertz, double dampingRatio, double h) {
    if (hertz <= 0.0) return {};  // rigid
    constexpr double kMaxHertzPerSubstepRate = 0.25;
    const double omega = 2.0 * 3.14159265358979323846 * std::min(hertz, kMaxHertzPerSubstepRate * (1.0 / h));
    const double a1 = 2.0 * dampingRatio + h * omega;
    const double a2 = h * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

}  // namespace physim
