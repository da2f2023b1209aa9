// Uses the installed core alone; exits 0 when a dropped ball has fallen as physics says.
#include <physim/core/World.hpp>

#include <cmath>
#include <cstdio>

int main() {
    physim::World world;
    physim::BodyDef ball;
    ball.shape = physim::makeCircle(0.1);
    const physim::BodyId id = world.createBody(ball);
    const double dt = 1.0 / 40.0;
    for (int i = 0; i < 40; ++i) world.step(dt);
    // 1 s in 40 steps of 8 substeps (the default), semi-implicit Euler: y = -g h^2 n (n + 1) / 2 with
    // h = 1/320 s and n = 320 substeps.
    const double n = 40.0 * physim::WorldSettings{}.substeps;
    const double expected = -9.81 * (1.0 / (n * n)) * n * (n + 1) / 2;
    const double y = world.position(id).y();
    std::printf("y = %.6f, expected %.6f\n", y, expected);
    return std::abs(y - expected) < 1e-9 ? 0 : 1;
}
