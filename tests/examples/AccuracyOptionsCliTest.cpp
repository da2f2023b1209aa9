// Every example takes the accuracy study's knobs (--substeps, --iterations, --ccd, --precision), lists them in
// --help, refuses a bad value with exit code 2 naming it, and runs with them.

#include "RunProgram.hpp"

#include <gtest/gtest.h>

namespace {

using physim::test::runProgram;

const char* const kExamples[] = {PHYSIM_FALLING_BOX, PHYSIM_PROJECTILE, PHYSIM_TEST_SCENE, PHYSIM_GAS,
                                 PHYSIM_PENDULUM,    PHYSIM_ROPE,       PHYSIM_CIRCLES,    PHYSIM_INCLINE,
                                 PHYSIM_COLLISIONS,  PHYSIM_NEWTONS_CRADLE, PHYSIM_PYRAMID, PHYSIM_DRAG,
                                 PHYSIM_ORBITS,      PHYSIM_GALAXY};

TEST(AccuracyOptionsCli, EveryExampleListsRefusesAndRunsThem) {
    for (const char* program : kExamples) {
        SCOPED_TRACE(program);
        const auto help = runProgram(program, "--help");
        EXPECT_EQ(help.exitCode, 0);
        for (const char* flag : {"--substeps", "--iterations", "--ccd", "--precision"})
            EXPECT_NE(help.output.find(flag), std::string::npos) << flag;
        for (const char* bad : {"--ccd bogus", "--substeps 0", "--iterations -2", "--precision 2"}) {
            const auto r = runProgram(program, std::string("--headless --quiet ") + bad);
            EXPECT_EQ(r.exitCode, 2) << bad << "\n" << r.output;
            const std::string value = std::string(bad).substr(std::string(bad).find(' ') + 1);
            EXPECT_NE(r.output.find(value), std::string::npos) << bad << "\n" << r.output;
        }
        const auto run = runProgram(program, "--headless --quiet --seconds 0.1 --substeps 2 --iterations 2 "
                                             "--ccd sampled --precision 0.5");
        EXPECT_EQ(run.exitCode, 0) << run.output;
    }
}

}  // namespace
