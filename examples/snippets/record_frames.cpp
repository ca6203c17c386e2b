// Plans a world, drives the plan in the simulation and films it with FrameRecorder: the
// program behind docs/rendering.md's "Frames" example, built and run by the tests.
// Usage: record_frames WORLD OUT_DIR [FPS]

#include <cstdio>
#include <cstdlib>
#include <string>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/io/Error.h"
#include "parksim/pipeline/EpisodeFigures.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/renders/film/FrameRecorder.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "parksim/sim/episode/Episode.h"

int main(int argc, char** argv) {
  using namespace parksim;
  if (argc < 3) {
    std::fprintf(stderr, "usage: record_frames WORLD OUT_DIR [FPS]\n");
    return 2;
  }
  try {
    const Scenario scenario = loadScenario(argv[1]);
    const BulletCollisionWorld collision(scenario);
    const PlanResult plan = planScenario(scenario, collision, PlanSetup{});
    if (!plan.solved()) {
      std::fprintf(stderr, "record_frames: unsolved: %s\n", plan.message.c_str());
      return 1;
    }
    const std::string out_dir = argv[2];
    const double fps = argc > 3 ? std::strtod(argv[3], nullptr) : 30.0;
    // [docs:frame-recorder]
    FrameDef def;  // fps 30, 640x480, view top, out_dir "out", no video
    def.view = frameViewFromString("both");
    def.out_dir = out_dir;
    def.fps = fps;
    FrameRecorder rec(scenario, def);               // creates out_dir/frames
    rec.setPlan(plan.trajectory, plan.tree_edges);  // the tree is drawn only with def.show_tree
    const EpisodeObserver observer = [&rec](const EpisodeSample& sample) {
      rec.addFrame(frameInput(sample));  // pipeline/EpisodeFigures.h: sample -> frame input
    };
    runEpisode(scenario, plan.trajectory, ExecutionDef{}, observer, 1.0 / def.fps);
    const RecordingResult r = rec.finish();  // waits for the PNGs, runs ffmpeg if asked
    std::puts(r.message.c_str());            // "40 frames: out_dir/frames/000000.png ..."
    // [docs:end]
    return r.frames > 0 ? 0 : 1;
  } catch (const Error& e) {
    std::fprintf(stderr, "record_frames: %s\n", e.what());
    return 2;
  }
}
