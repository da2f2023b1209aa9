// Prints the state hash of the determinism scene after 10^4 steps (support/Scenes.hpp): ctest runs it in two
// processes and compares the lines.
#include "support/Scenes.hpp"

#include <cstdio>

int main() {
    physim::World world(physim::test::awakeSettings());
    const std::vector<physim::BodyId> ids = physim::test::buildDeterminismScene(world);
    for (int i = 0; i < 10000; ++i) world.step(1.0 / 60.0);
    std::printf("%016llx\n", static_cast<unsigned long long>(physim::test::stateHash(world, ids)));
    return 0;
}
