// The car program: the scene in Car.cpp, in a window or --headless (--help lists the options).
#include "Scenes.hpp"

int main(int argc, char** argv) { return physim::runMain(argc, argv, physim::examples::makeCar); }
