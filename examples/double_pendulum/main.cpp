// The double_pendulum program: the scene in DoublePendulum.cpp, in a window or --headless (--help lists the options).
#include "Scenes.hpp"

int main(int argc, char** argv) { return physim::runMain(argc, argv, physim::examples::makeDoublePendulum); }
