#include "Scenes.hpp"

namespace physim::examples {

const std::vector<Scene>& scenes() {
    static const std::vector<Scene> all{
        {"falling_box", makeFallingBox}, {"test_scene", makeTestScene},       {"circles", makeCircles},
        {"gas", makeGas},                {"pendulum", makePendulum},          {"rope", makeRope},
        {"projectile", makeProjectile},  {"incline", makeIncline},            {"collisions", makeCollisions},
        {"newtons_cradle", makeNewtonsCradle}, {"pyramid", makePyramid},
        {"drag", makeDrag},              {"orbits", makeOrbits},              {"galaxy", makeGalaxy},
        {"ramp", makeRamp},              {"tipping", makeTipping},
        {"atwood", makeAtwood},          {"gears", makeGears},
        {"car", makeCar},
        {"one_way", makeOneWay},
        {"photogate", makePhotogate},
        {"conveyor", makeConveyor},
        {"double_pendulum", makeDoublePendulum},
    };
    return all;
}

}  // namespace physim::examples
