// MuJoCo side by side with parksim (docs/simulation.md, "MuJoCo side by side"): one plan driven
// open loop at the world's time step in parksim (its default model) and in an equivalent MuJoCo
// model, alternately, in one process, so that the ratio of their CPU per simulated second is
// measured under the same load. Prints, per engine, the median and the fastest CPU time of its
// stepping loop per simulated second, and the final position error against the plan's last
// pose (parksim's final_pos_err_m), then the ratio of the medians; and parksim's model as it was
// before the speed work of issue 21 (parksim*), for that ratio in the same run.
//
//   bench_mujoco [--repetitions N] [--world FILE] [--plan FILE]
//
// Defaults: worlds/head_in.yaml and the study's plan
// (tests/sim/fixtures/head_in_study_trajectory.csv: rrt-goal-connect, move-to-pose, study timing,
// seed 1; 331 rows, 33 s), 9 repetitions.
//
// The MuJoCo model is built from the world's robot and physics, as parksim builds its own: a box
// chassis that is the footprint (no collisions: the plan touches nothing), two sphere wheels on
// hinges at +-half the wheel base, a frictionless sphere slider at the rear, the same masses,
// friction, time step and wheel torque limit; velocity actuators play the motors. Tuned for
// speed: Newton solver, few iterations, elliptic friction cone (MuJoCo's pyramidal cone turned
// the robot 1 % too fast in arcs), contacts stiffened to the time step (MuJoCo's default contact
// time constant let the wheels sink 0.3 mm and roll short), implicit integration for the stiff
// actuators.

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "parksim/results/episode/TrajectoryFile.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "parksim/sim/episode/Episode.h"
#include "parksim/sim/episode/ReferenceTrajectory.h"

namespace parksim {
namespace {

struct Run {
  double cpu_s = 0.0;  // CPU time of the stepping loop
  double sim_s = 0.0;
  long steps = 0;
  double final_err_m = 0.0;
};

double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

Run runParksim(const Scenario& scenario, const Trajectory& plan, const SimModelDef& model) {
  ExecutionDef def;
  def.tracking = TrackingMode::kOpen;
  Episode episode(scenario, plan, def, model);
  const double start = cpuSeconds();
  while (!episode.finished()) episode.step();
  Run run;
  run.cpu_s = cpuSeconds() - start;
  const EpisodeMetrics m = episode.metrics();
  run.sim_s = m.sim_time_s;
  run.steps = m.steps;
  run.final_err_m = m.final_pos_err_m;
  return run;
}

// MuJoCo's settings, tuned for speed on the study plan at the world's time step: 4 Newton
// iterations (2 let the robot tip over, 10 changed nothing); docs/simulation.md lists what was
// tried.
struct MujocoDef {
  int iterations = 4;
  double tolerance = 1e-8;
  /// Velocity actuator gain, N m s. Chosen by the final error on the study plan at 1/240 s:
  /// 0.005 gave 32 mm, 0.006 19 mm, 0.007 16 mm, 0.008 26 mm; stiffer drives pitched the robot
  /// at the plan's wheel-speed steps (0.1: 0.4 m), softer ones lagged in arcs.
  double kv = 0.007;
};

std::string mujocoXml(const Scenario& s, const MujocoDef& def) {
  const RobotDef& r = s.robot;
  const PhysicsDef& p = s.physics;
  const SimModelDef model;
  const Pose2& start = s.start;
  const double radius = r.wheel_radius_m;
  const double half_height = 0.5 * (r.height_m - r.ground_clearance_m);
  const double rear_edge = r.front_overhang_m - r.length_m;
  // Contacts stiffened to twice the time step (the stiffest MuJoCo integrates stably).
  const double contact_time = 2.0 * p.time_step_s;
  char xml[4096];
  std::snprintf(xml, sizeof xml,
                R"(<mujoco model="parksim robot">
  <option timestep="%.17g" gravity="0 0 %.17g" integrator="implicit" solver="Newton"
          iterations="%d" tolerance="%g" cone="elliptic"/>
  <default><geom solref="%.17g 1"/></default>
  <worldbody>
    <geom name="ground" type="plane" size="50 50 0.1" friction="%.17g 0 0"/>
    <body name="robot" pos="%.17g %.17g %.17g" quat="%.17g 0 0 %.17g">
      <freejoint/>
      <geom name="chassis" type="box" size="%.17g %.17g %.17g" pos="%.17g 0 %.17g" mass="%.17g"
            contype="0" conaffinity="0"/>
      <geom name="slider" type="sphere" size="%.17g" pos="%.17g 0 %.17g" mass="%.17g" condim="1"
            priority="1" friction="%.17g 0 0"/>
      <body name="left" pos="0 %.17g 0">
        <joint name="left" type="hinge" axis="0 1 0"/>
        <geom type="sphere" size="%.17g" mass="%.17g" friction="%.17g 0 0"/>
      </body>
      <body name="right" pos="0 %.17g 0">
        <joint name="right" type="hinge" axis="0 1 0"/>
        <geom type="sphere" size="%.17g" mass="%.17g" friction="%.17g 0 0"/>
      </body>
    </body>
  </worldbody>
  <actuator>
    <velocity joint="left" kv="%.17g" forcelimited="true" forcerange="%.17g %.17g"/>
    <velocity joint="right" kv="%.17g" forcelimited="true" forcerange="%.17g %.17g"/>
  </actuator>
</mujoco>)",
                p.time_step_s, -p.gravity_mps2, def.iterations, def.tolerance, contact_time,
                p.ground_friction, start.x, start.y, radius, std::cos(0.5 * start.theta),
                std::sin(0.5 * start.theta), 0.5 * r.length_m, 0.5 * r.width_m, half_height,
                r.footprintCenterOffset(), r.ground_clearance_m + half_height - radius,
                p.chassis_mass_kg, model.support_radius_m, rear_edge + model.support_inset_m,
                model.support_radius_m - radius, model.support_mass_kg, p.support_friction,
                0.5 * r.wheel_base_m, radius, p.wheel_mass_kg, p.wheel_friction,
                -0.5 * r.wheel_base_m, radius, p.wheel_mass_kg, p.wheel_friction, def.kv,
                -p.max_wheel_torque_nm, p.max_wheel_torque_nm, def.kv, -p.max_wheel_torque_nm,
                p.max_wheel_torque_nm);
  return xml;
}

mjModel* loadMujoco(const Scenario& s, const MujocoDef& def) {
  const std::string xml = mujocoXml(s, def);
  char error[1000] = "";
  // MuJoCo 2.2 reads models from files or its virtual file system; the latter keeps the bench
  // free of temporary files.
  auto vfs = std::make_unique<mjVFS>();  // ~2 MB: not on the stack
  mj_defaultVFS(vfs.get());
  mj_makeEmptyFileVFS(vfs.get(), "robot.xml", static_cast<int>(xml.size()));
  const int file = mj_findFileVFS(vfs.get(), "robot.xml");
  std::copy(xml.begin(), xml.end(), static_cast<char*>(vfs->filedata[file]));
  mjModel* m = mj_loadXML("robot.xml", vfs.get(), error, sizeof error);
  mj_deleteVFS(vfs.get());
  if (m == nullptr) throw std::runtime_error(std::string("MuJoCo model: ") + error);
  return m;
}

// The plan's wheel speeds held per control period, the period chosen by the step's midpoint
// (ReferenceTrajectory, as parksim's open loop reads them), then zero until the robot rests
// (ExecutionDef's rule) or the stop time runs out.
Run runMujoco(const mjModel* m, const ReferenceTrajectory& reference) {
  const Trajectory& plan = reference.plan();
  mjData* d = mj_makeData(m);
  const ExecutionDef rules;
  const double dt = m->opt.timestep;
  const double t0 = plan.points.front().t_s;
  const double duration = plan.duration();
  const long rest_steps = std::lround(std::ceil(rules.rest_hold_s / dt - 1e-9));
  long k = 0;
  long resting = 0;
  const double start = cpuSeconds();
  for (;;) {
    const WheelSpeeds wheels = reference.wheelsAt(t0 + (static_cast<double>(k) + 0.5) * dt);
    d->ctrl[0] = wheels.left_radps;
    d->ctrl[1] = wheels.right_radps;
    mj_step(m, d);
    ++k;
    const double t = static_cast<double>(k) * dt;
    if (t < duration) continue;
    // Free joint: linear velocity qvel[0..2], angular qvel[3..5] (world frame).
    const bool rest = std::hypot(d->qvel[0], d->qvel[1]) < rules.rest_speed_mps &&
                      std::abs(d->qvel[5]) < rules.rest_yaw_rate_radps;
    resting = rest ? resting + 1 : 0;
    if (resting >= rest_steps || t >= duration + rules.max_stop_time_s) break;
  }
  Run run;
  run.cpu_s = cpuSeconds() - start;
  run.steps = k;
  run.sim_s = static_cast<double>(k) * dt;
  const Pose2& goal = plan.points.back().pose;
  run.final_err_m = std::hypot(d->qpos[0] - goal.x, d->qpos[1] - goal.y);
  mj_deleteData(d);
  return run;
}

struct Summary {
  double median_ms_per_s = 0.0;
  double best_ms_per_s = 0.0;
  Run last;
};

Summary summarize(const std::vector<Run>& runs) {
  std::vector<double> per_s;
  for (const Run& r : runs) per_s.push_back(1e3 * r.cpu_s / r.sim_s);
  std::sort(per_s.begin(), per_s.end());
  return {per_s[per_s.size() / 2], per_s.front(), runs.back()};
}

void print(const char* engine, const Summary& s) {
  std::printf("%-10s %8.3f %8.3f %10.2f %8.2f %7ld\n", engine, s.median_ms_per_s, s.best_ms_per_s,
              1e3 * s.last.final_err_m, s.last.sim_s, s.last.steps);
}

int run(int argc, char** argv) {
  std::string world = std::string(PARKSIM_SOURCE_DIR) + "/worlds/head_in.yaml";
  std::string plan_file =
      std::string(PARKSIM_SOURCE_DIR) + "/tests/sim/fixtures/head_in_study_trajectory.csv";
  int repetitions = 9;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 < argc && arg == "--repetitions") {
      repetitions = std::max(1, std::atoi(argv[++i]));
    } else if (i + 1 < argc && arg == "--world") {
      world = argv[++i];
    } else if (i + 1 < argc && arg == "--plan") {
      plan_file = argv[++i];
    } else {
      std::fprintf(stderr, "usage: bench_mujoco [--repetitions N] [--world FILE] [--plan FILE]\n");
      return 2;
    }
  }
  const Scenario scenario = loadScenario(world);
  const Trajectory plan = readTrajectoryCsv(plan_file);
  const MujocoDef def;
  mjModel* model = loadMujoco(scenario, def);
  // parksim's model before the speed work of issue 21, for the ratio in the same run: Bullet's
  // own row setup and GJK contacts (kExact), 50 cold-started iterations.
  Scenario before = scenario;
  before.physics.solver_iterations = 50;
  SimModelDef before_model;
  before_model.solver = SolverKernel::kExact;
  before_model.warm_start = false;
  // One run of each first (caches, lazy set-up), then alternately.
  runParksim(scenario, plan, SimModelDef{});
  runParksim(before, plan, before_model);
  const ReferenceTrajectory reference(plan, scenario.robot);
  runMujoco(model, reference);
  std::vector<Run> parksim;
  std::vector<Run> parksim_before;
  std::vector<Run> mujoco;
  for (int i = 0; i < repetitions; ++i) {
    parksim.push_back(runParksim(scenario, plan, SimModelDef{}));
    parksim_before.push_back(runParksim(before, plan, before_model));
    mujoco.push_back(runMujoco(model, reference));
  }
  mj_deleteModel(model);
  const Summary p = summarize(parksim);
  const Summary b = summarize(parksim_before);
  const Summary j = summarize(mujoco);
  std::printf("plan %s (%.2f s) on %s, open loop, %d repetitions, MuJoCo %s\n", plan_file.c_str(),
              plan.duration(), world.c_str(), repetitions, mj_versionString());
  std::printf("engine     CPU ms per simulated s   final error  sim time  steps\n");
  std::printf("           median     best         mm           s\n");
  print("parksim", p);
  print("MuJoCo", j);
  print("parksim*", b);
  std::printf("parksim / MuJoCo CPU per simulated second (medians): %.2f\n",
              p.median_ms_per_s / j.median_ms_per_s);
  std::printf(
      "parksim* (as before issue 21: Bullet's rows and contacts, 50 cold iterations) / "
      "MuJoCo: %.2f\n",
      b.median_ms_per_s / j.median_ms_per_s);
  return 0;
}

}  // namespace
}  // namespace parksim

int main(int argc, char** argv) {
  try {
    return parksim::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_mujoco: %s\n", e.what());
    return 1;
  }
}
