#pragma once
// Every example's scene, made by a factory so that its own program (examples/<name>/main.cpp) and the gallery
// (examples/gallery) run the same simulation.

#include <physim/framework/Runner.hpp>

#include <memory>
#include <string>
#include <vector>

namespace physim::examples {

std::unique_ptr<Simulation> makeFallingBox();
std::unique_ptr<Simulation> makeTestScene();
std::unique_ptr<Simulation> makeCircles();
std::unique_ptr<Simulation> makeGas();
std::unique_ptr<Simulation> makePendulum();
std::unique_ptr<Simulation> makeRope();
std::unique_ptr<Simulation> makeProjectile();
std::unique_ptr<Simulation> makeIncline();
std::unique_ptr<Simulation> makeCollisions();
std::unique_ptr<Simulation> makeNewtonsCradle();
std::unique_ptr<Simulation> makePyramid();
std::unique_ptr<Simulation> makeDrag();
std::unique_ptr<Simulation> makeOrbits();
std::unique_ptr<Simulation> makeGalaxy();
std::unique_ptr<Simulation> makeRamp();
std::unique_ptr<Simulation> makeTipping();
std::unique_ptr<Simulation> makeAtwood();
std::unique_ptr<Simulation> makeGears();
std::unique_ptr<Simulation> makeCar();
std::unique_ptr<Simulation> makeOneWay();
std::unique_ptr<Simulation> makePhotogate();
std::unique_ptr<Simulation> makeConveyor();
std::unique_ptr<Simulation> makeDoublePendulum();

struct Scene {
    std::string name;  ///< the example's program name
    SimulationFactory make;
};

/// Every scene, in the gallery's order.
const std::vector<Scene>& scenes();

}  // namespace physim::examples
