// Uses each installed layer once; exits 0 when a dropped ball has fallen as physics says.
#include <physim/core/CircleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Simulation.hpp>

#include <cmath>
#include <cstdio>

int main() {
    physim::Simulation sim;
    auto& ball = sim.spawn<physim::Object>(physim::Mesh::CircleMesh(0.1, sf::Color::Red), physim::CircleShape(0.1));
    sim.graphsManager.addGraph("y");
    sim.graphsManager.build();
    for (int i = 0; i < 40; ++i) {
        sim.fixedStep();
        sim.graphsManager.addPoint(0, sim.time, ball.getPosition().y());
    }
    // 1 s at 40 Hz, 8 substeps each (the default), semi-implicit Euler: y = -g h^2 n (n + 1) / 2 with
    // h = 1/320 s and n = 320 substeps.
    const double n = 40.0 * physim::WorldSettings{}.substeps;
    const double expected = -9.81 * (1.0 / (n * n)) * n * (n + 1) / 2;
    std::printf("y = %.6f, expected %.6f\n", ball.getPosition().y(), expected);
    return std::abs(ball.getPosition().y() - expected) < 1e-9 ? 0 : 1;
}
