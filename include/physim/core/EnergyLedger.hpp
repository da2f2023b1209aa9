#pragma once
// Where a world's energy went (World::setEnergyLedger): each step's change of kinetic plus potential energy, split
// by cause. All in joules. The parts of a step always sum to that step's measured change, to rounding: `residue` is
// defined as what the other parts leave, the integrator's own share (docs/guide.md, "Measuring a run").
//
// How each part is measured, substep by substep (a substep changes a body's velocity from v_start to v_end and moves
// it with v_move, the velocity the solve leaves):
//   work      user forces and torques, force callbacks, motors (revolute, wheel, prismatic) and kinematic bodies
//             pushing through contacts: impulse . (v_start + v_end) / 2
//   drag      air drag's impulse . (v_start + v_end) / 2 (negative)
//   friction  each contact's friction impulse . its slip velocity at v_move: force times the distance slid
//             (negative; positive where a conveyor's surface speed drives a body)
//   impacts   the normal impulses (bounces included) of the contact points that approached faster than
//             WorldSettings::restitutionThreshold at the substep's start, . the mean velocity: exactly their share
//             of the kinetic energy's change, so a bounce with restitution e from normal speed v loses
//             (1 - e^2) m v^2 / 2
//   soft      the other contact points' normal impulses . the mean velocity (a soft contact pushing out an overlap,
//             a resting one: nothing), and spring joints' damping
//   residue   the rest: semi-implicit Euler's own share (gravity, springs and gravitation change the velocities at
//             the substep's start, their potentials follow the move), friction's share of the velocity change
//             beyond the distance slid, the continuous stage's put-backs, and the joints' rows: an ideal joint does
//             no work, so what the method's joint rows do to the energy (a pendulum's swing of a few 1e-3 of its
//             energy at 40 Hz; WorldSettings::jointArcs keeps it from drifting) is the method's, limits' and joint
//             springs' included.
// Potential energy: gravity (-m g . x for every dynamic body that feels it), spring joints ((k/2) stretch^2) and
// gravitation between attracting bodies (-G m1 m2 / sqrt(r^2 + softening^2), summed over all pairs: O(n^2) per
// step while the ledger is on). Kinetic energy: every dynamic body's, translation and rotation.

namespace physim {

/// One step's changes, or the running totals since the ledger was switched on (J; positive: energy gained).
struct EnergyParts {
    double work = 0.0;      ///< user forces and torques, force callbacks, motors, kinematic bodies
    double drag = 0.0;      ///< air drag
    double friction = 0.0;  ///< sliding friction
    double impacts = 0.0;   ///< energy lost in bounces (restitution < 1)
    double soft = 0.0;      ///< stored and released by soft contacts and joints
    double residue = 0.0;   ///< the method's numerical share: what the others leave of the measured change

    double sum() const { return work + drag + friction + impacts + soft + residue; }
    EnergyParts& operator+=(const EnergyParts& o) {
        work += o.work, drag += o.drag, friction += o.friction, impacts += o.impacts, soft += o.soft;
        residue += o.residue;
        return *this;
    }
};

/// World::energyLedger(): the energies now and where they went.
struct EnergyLedger {
    bool enabled = false;
    double kinetic = 0.0;    ///< J, all bodies, now (after the last step)
    double potential = 0.0;  ///< J, gravity + spring joints + gravitation, now
    double start = 0.0;      ///< J, kinetic + potential when the ledger was switched on (or restarted)
    double startKinetic = 0.0;    ///< J, its kinetic share then
    double startPotential = 0.0;  ///< J, its potential share then
    int steps = 0;           ///< steps measured since then
    EnergyParts step;        ///< the last step's parts: sum() == its change of kinetic + potential, to rounding
    EnergyParts total;       ///< summed over the measured steps

    double energy() const { return kinetic + potential; }
};

}  // namespace physim
