// The transcription's warm start (sim/bullet/SolverWarmStart.h) converges steady driving that
// cold-started iterations leave unconverged. The transcription against Bullet's own solver:
// tests/sim/SolverPathsTest.cpp, which runs in every build.

#include <cstdio>

#include <gtest/gtest.h>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/sim/world/DynamicsWorld.h"
#include "tests/sim/SimTestSupport.h"

namespace parksim {
namespace {

// Warm starting (SolverWarmStart.h) against the converged answer: wheel speeds held from rest
// for 5 s, the default model (15 iterations at most, warm-started) ends within 0.04 mm (straight)
// and 0.09 mm (arc; most of it from the start, where the warm start has nothing to start from)
// of where 300 cold iterations per step end; 15 cold iterations end 0.46 and 1.38 mm away.
TEST(FastMultiBodySolver, WarmStartedStepsEndWhereConvergedStepsEnd) {
  const Scenario base = testing::emptyLot({0.5, 0.5, 0.3});
  auto drive = [&](const WheelSpeeds& wheels, int iterations, bool warm, double threshold) {
    Scenario s = base;
    s.physics.solver_iterations = iterations;
    SimModelDef model;
    model.warm_start = warm;
    model.solver_residual_threshold = threshold;
    DynamicsWorld world(s, s.start, model);
    world.setWheelTargets(wheels);
    for (int k = 0; k < 1200; ++k) world.step();
    return world.robot().pose;
  };
  for (const WheelSpeeds& wheels : {WheelSpeeds{5.0, 5.0}, WheelSpeeds{3.0, 6.0}}) {
    const Pose2 converged = drive(wheels, 300, false, 0.0);
    const Pose2 warm = drive(wheels, PhysicsDef{}.solver_iterations, true,
                             SimModelDef{}.solver_residual_threshold);
    const Pose2 cold = drive(wheels, PhysicsDef{}.solver_iterations, false,
                             SimModelDef{}.solver_residual_threshold);
    const double warm_err = positionDistance(warm, converged);
    const double cold_err = positionDistance(cold, converged);
    std::printf("wheels %.0f/%.0f: from the converged pose, warm %.4f mm, cold %.4f mm\n",
                wheels.left_radps, wheels.right_radps, warm_err * 1e3, cold_err * 1e3);
    EXPECT_LT(warm_err, 0.15e-3);
    EXPECT_GT(cold_err, 4.0 * warm_err);
  }
}

}  // namespace
}  // namespace parksim
