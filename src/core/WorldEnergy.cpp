// The World's energy API and the ledger's step bookkeeping (physim/core/EnergyLedger.hpp); the substeps' share is
// EnergyTally's.

#include "physim/core/World.hpp"

#include "WorldImpl.hpp"

namespace physim {

double World::kineticEnergy() const { return kineticEnergyOf(*impl_); }
double World::potentialEnergy() const { return potentialEnergyOf(*impl_); }

void World::setEnergyLedger(bool enabled) {
    impl_->requireNotStepping("setEnergyLedger");
    EnergyLedger& ledger = impl_->ledger;
    ledger = EnergyLedger{};
    ledger.enabled = enabled;
    if (!enabled) return;
    ledger.kinetic = kineticEnergy();
    ledger.potential = potentialEnergy();
    ledger.startKinetic = ledger.kinetic;
    ledger.startPotential = ledger.potential;
    ledger.start = ledger.energy();
}

const EnergyLedger& World::energyLedger() const { return impl_->ledger; }

void World::restoreEnergyLedger(const EnergyLedger& ledger) {
    impl_->requireNotStepping("restoreEnergyLedger");
    impl_->ledger = ledger;
}

double WorldImpl::ledgerEnergy() { return kineticEnergyOf(*this) + potentialEnergyOf(*this, &gravitationPotential); }

void WorldImpl::closeLedgerStep(double before, bool solved) {
    EnergyParts parts = solved ? solver.tally().stepParts() : EnergyParts{};
    ledger.kinetic = kineticEnergyOf(*this);
    ledger.potential = potentialEnergyOf(*this, &gravitationPotential);
    // What the measured parts leave of the measured change.
    parts.residue = (ledger.energy() - before) - parts.sum();
    ledger.step = parts;
    ledger.total += parts;
    ++ledger.steps;
}

}  // namespace physim
