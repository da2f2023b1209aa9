#pragma once
// Drag: a body moving through a still fluid (air, water) is slowed by a force against its velocity.

namespace physim {

/// A body's drag, acting at its centre of mass against its velocity v (m/s) and turn w (rad/s):
///   F = -(linear + 1/2 fluidDensity dragCoefficient width |v|) v   (N)
///   torque = -angular w                                           (N m)
/// The quadratic part is the high-Reynolds-number law; `linear` is the slow, viscous (Stokes-like) law. The
/// world is a slab 1 m deep, so a fluid of density rho kg/m^3 has fluidDensity rho kg/m^2 (air: 1.2).
/// All zero (the default): no drag, and the body costs the drag stage nothing.
struct DragDef {
    double linear = 0.0;           ///< N s/m (kg/s), >= 0
    double dragCoefficient = 0.0;  ///< C_d, dimensionless, >= 0 (a long cylinder across the flow: about 1.2)
    double fluidDensity = 1.2;     ///< kg/m^2, >= 0 (air 1.2, water 1000 for the 1 m deep slab)
    /// m, >= 0: the width the body shows the flow. 0 takes the shape's mean width over all directions,
    /// perimeter / pi (Cauchy): a circle's diameter, 1.27 times a square's side.
    double width = 0.0;
    double angular = 0.0;          ///< N m s, >= 0: rotational drag
};

/// Throws std::invalid_argument naming the first negative or non-finite field.
void validate(const DragDef& drag);

/// True when the definition asks for no drag at all.
inline bool isNone(const DragDef& d) { return d.linear == 0.0 && d.dragCoefficient == 0.0 && d.angular == 0.0; }

}  // namespace physim
