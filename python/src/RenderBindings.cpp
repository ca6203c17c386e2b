// Images from Python: a frame of the lot (optionally with a robot, a plan, an episode instant),
// the study's figures, PNG encoding, and FrameRecorder for films. Images are H x W x 3 uint8
// arrays. Each thread keeps one renderer (an off-screen GL context is bound to a thread).

#include <algorithm>
#include <optional>

#include <pybind11/stl.h>

#include "parksim/core/io/Error.h"
#include "parksim/pipeline/EpisodeFigures.h"
#include "parksim/renders/film/FrameRecorder.h"
#include "parksim/renders/gl/Renderer.h"
#include "parksim/renders/image/PngEncoder.h"
#include "parksim/renders/plots/Figures.h"
#include "parksim/renders/scene/SceneBuilder.h"
#include "python/src/Bindings.h"
#include "python/src/Conversions.h"

namespace parksim::python {

namespace {

// Made on first use in each thread, kept for the thread's life: creating a context costs far
// more than a frame.
Renderer& threadRenderer(int width_px, int height_px, int msaa_samples) {
  thread_local std::unique_ptr<Renderer> renderer;
  thread_local int samples = -1;
  if (!renderer || samples != msaa_samples) {
    RenderDef def;
    def.width_px = width_px;
    def.height_px = height_px;
    def.msaa_samples = msaa_samples;
    renderer = std::make_unique<Renderer>(def);
    samples = msaa_samples;
  }
  renderer->setSize(width_px, height_px);
  return *renderer;
}

py::array imageArray(const RgbImage& image) {
  py::array_t<std::uint8_t> out({image.height, image.width, 3});
  std::copy(image.pixels.begin(), image.pixels.end(), out.mutable_data());
  return out;
}

RgbImage imageFrom(const py::handle& array) {
  const auto a =
      py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!a || a.ndim() != 3 || a.shape(2) != 3) {
    throw py::value_error("an image is an H x W x 3 uint8 array");
  }
  RgbImage image(static_cast<int>(a.shape(1)), static_cast<int>(a.shape(0)));
  std::copy(a.data(), a.data() + a.size(), image.pixels.begin());
  return image;
}

std::vector<Pose2> posesFrom(const py::handle& value) {
  std::vector<Pose2> poses;
  if (value.is_none()) return poses;
  const py::array array = py::array::ensure(value);
  if (array && !array.dtype().attr("names").is_none()) {  // structured: x, y, theta fields
    const auto x = py::array_t<double, py::array::forcecast>(value[py::str("x")]);
    const auto y = py::array_t<double, py::array::forcecast>(value[py::str("y")]);
    const auto theta = py::array_t<double, py::array::forcecast>(value[py::str("theta")]);
    for (py::ssize_t i = 0; i < x.size(); ++i) poses.push_back({x.at(i), y.at(i), theta.at(i)});
    return poses;
  }
  for (const py::handle pose : value) poses.push_back(poseFrom(pose));
  return poses;
}

CameraDef viewCamera(const std::string& view) {
  if (view == "top") return CameraDef{};
  if (view == "3d") return FrameDef{}.camera_3d;
  throw py::value_error("view must be 'top' or '3d', got '" + view + "'");
}

RgbImage renderScene(const Scene& scene, const CameraDef& camera, int width_px, int height_px,
                     int msaa_samples) {
  if (width_px < 1 || height_px < 1 || width_px > 8192 || height_px > 8192) {
    throw Error("render: size must be between 1x1 and 8192x8192");
  }
  RgbImage image;
  threadRenderer(width_px, height_px, msaa_samples).render(scene, camera, image);
  return image;
}

PlanFigure planFigureFrom(const py::handle& plan) {
  PlanFigure figure;
  figure.name = "plan";
  if (py::isinstance<PlanOutcome>(plan)) {
    const PlanOutcome& p = plan.cast<const PlanOutcome&>();
    figure.name = p.setup.planner;
    figure.caption = std::string(p.setup.planner) + ", seed " +
                     std::to_string(p.setup.search.seed) + ": " + p.message();
    if (p.result) {
      figure.trajectory = p.result->trajectory;
      figure.waypoints = p.result->waypoints;
      figure.tree_edges = p.result->tree_edges;
    }
  } else {
    figure.trajectory = trajectoryFrom(plan);
  }
  return figure;
}

// The tracking error of an executed array (columns t, pos_err, heading_err).
TrackingSeries seriesFrom(const py::handle& executed) {
  TrackingSeries s;
  for (const char* field : {"t", "pos_err", "heading_err"}) {
    const auto column = py::array_t<double, py::array::forcecast>(executed[py::str(field)]);
    std::vector<double>& out = field[0] == 't'   ? s.t_s
                               : field[0] == 'p' ? s.position_error_m
                                                 : s.heading_error_rad;
    out.assign(column.data(), column.data() + column.size());
  }
  return s;
}

void bindImages(py::module_& m) {
  m.def(
      "_render_frame",
      [](const WorldHandle& world, const py::object& pose, const py::object& plan,
         const py::object& reference, const py::object& obstacle_poses,
         const std::vector<int>& contacts, const py::object& executed, const py::object& overlay,
         int width, int height, const std::string& view, int msaa) {
        const Scenario& scenario = *world.scenario;
        std::vector<Pose2> planned;
        if (!plan.is_none()) planned = samplePath(trajectoryFrom(plan), scenario.robot);
        const std::vector<Pose2> obstacles = posesFrom(obstacle_poses);
        const std::vector<Pose2> driven = posesFrom(executed);
        ViewState state;
        if (!pose.is_none()) state.robot = poseFrom(pose);
        if (!reference.is_none()) state.reference = poseFrom(reference);
        state.obstacle_poses = obstacles;
        state.contacts = contacts;
        state.planned_path = planned;
        state.executed_path = driven;
        if (!overlay.is_none()) {
          const py::dict o = overlay.cast<py::dict>();
          state.overlay =
              Overlay{o.contains("title") ? o["title"].cast<std::string>() : "",
                      o.contains("t") ? o["t"].cast<double>() : 0.0,
                      o.contains("pos_err") ? o["pos_err"].cast<double>() : 0.0,
                      o.contains("heading_err") ? o["heading_err"].cast<double>() : 0.0};
        }
        const CameraDef camera = viewCamera(view);
        RgbImage image;
        {
          py::gil_scoped_release release;
          const SceneStyle style =
              SceneStyle{}.scaled(styleScaleFor(height)).forRobot(scenario.robot);
          image = renderScene(buildScene(scenario, state, style), camera, width, height, msaa);
        }
        return imageArray(image);
      },
      py::arg("world"), py::arg("pose"), py::arg("plan"), py::arg("reference"),
      py::arg("obstacle_poses"), py::arg("contacts"), py::arg("executed"), py::arg("overlay"),
      py::arg("width"), py::arg("height"), py::arg("view"), py::arg("msaa"));

  m.def(
      "render_figure",
      [](const WorldHandle& world, const std::string& name, const py::object& plan,
         const py::object& executed, double heading, int width, int height, int msaa) {
        const Scenario& scenario = *world.scenario;
        if (name != "lot_map" && name != "cspace_slice" && name != "cspace_stack" &&
            name != "plan" && name != "lot_3d" && name != "tracking_error") {
          throw py::value_error(
              "figure must be lot_map, cspace_slice, cspace_stack, plan, lot_3d "
              "or tracking_error, got '" +
              name + "'");
        }
        std::optional<PlanFigure> plan_figure;
        if (!plan.is_none()) plan_figure = planFigureFrom(plan);
        std::optional<TrackingSeries> series;
        if (name == "tracking_error") {
          if (executed.is_none()) throw py::value_error("tracking_error needs executed=");
          series = seriesFrom(executed);
        }
        if (name == "plan" && !plan_figure) throw py::value_error("the plan figure needs plan=");
        FigureDef def;
        def.width_px = width;
        def.height_px = height;
        RgbImage image;
        py::gil_scoped_release release;
        const SceneStyle style = def.style.scaled(styleScaleFor(height)).forRobot(scenario.robot);
        if (name == "lot_map") {
          image = renderScene(buildLotMapFigure(scenario, style), figureCamera(name), width, height,
                              msaa);
        } else if (name == "cspace_slice") {
          image = renderScene(buildCSpaceSliceFigure(scenario, heading, style), figureCamera(name),
                              width, height, msaa);
        } else if (name == "cspace_stack") {
          image = renderScene(buildCSpaceStackFigure(scenario, def.cspace_slices, style),
                              figureCamera(name), width, height, msaa);
        } else if (name == "plan") {
          image = renderScene(buildPlanFigure(scenario, *plan_figure, def, style),
                              figureCamera("plan_" + plan_figure->name), width, height, msaa);
        } else if (name == "lot_3d") {
          image =
              renderScene(buildLot3dFigure(scenario, plan_figure ? &*plan_figure : nullptr, style),
                          figureCamera(name), width, height, msaa);
        } else if (name == "tracking_error") {
          CameraDef camera;
          camera.fill = 1.0;
          image = renderScene(
              buildTrackingPlot(*series, "Tracking error: " + scenario.name, width, height, style),
              camera, width, height, msaa);
        }
        py::gil_scoped_acquire acquire;
        return imageArray(image);
      },
      py::arg("world"), py::arg("name"), py::arg("plan") = py::none(),
      py::arg("executed") = py::none(), py::arg("heading") = degToRad(-60.0),
      py::arg("width") = 1200, py::arg("height") = 800, py::arg("msaa") = 4,
      R"(One of the study's figures as an H x W x 3 uint8 array: lot_map, cspace_slice (at
heading, rad), cspace_stack, plan (plan=PlanResult or trajectory), lot_3d (plan optional),
tracking_error (executed=RunResult.executed or Episode.executed).)");

  py::tuple names(kFigureNames.size());
  for (std::size_t i = 0; i < kFigureNames.size(); ++i) names[i] = py::str(kFigureNames[i]);
  m.attr("FIGURE_NAMES") = names;
}

void bindFigures(py::module_& m) {
  m.def(
      "write_figures",
      [](const WorldHandle& world, const std::string& out_dir, const std::string& figures,
         const py::object& plans, const py::object& executed, const py::object& steer_target,
         double heading, int slices, int width, int height, int msaa,
         const std::string& gl_backend) {
        const Scenario& scenario = *world.scenario;
        if (width < 1 || height < 1 || width > 8192 || height > 8192) {
          throw Error("write_figures: size must be between 1x1 and 8192x8192");
        }
        FigureDef def;
        def.figures = FigureSelection::parse(figures);
        def.width_px = width;
        def.height_px = height;
        def.msaa_samples = msaa;
        def.cspace_heading_rad = heading;
        def.cspace_slices = std::clamp(slices, 1, 720);
        def.context.backend = contextBackendFromString(gl_backend);
        FigureInputs inputs;
        // The same figure inputs as `parksim render` (pipeline/EpisodeFigures.h): captions,
        // steering.
        auto add = [&](const py::handle& p) {
          if (py::isinstance<PlanOutcome>(p)) {
            const PlanOutcome& outcome = p.cast<const PlanOutcome&>();
            if (!outcome.result) {
              throw Error("write_figures: a plan whose planner failed has nothing to draw (" +
                          outcome.status() + ": " + outcome.message() + ")");
            }
            inputs.plans.push_back(planFigure(scenario, outcome.setup, *outcome.result));
          } else {
            inputs.plans.push_back(planFigureFrom(p));
          }
        };
        if (py::isinstance<py::list>(plans) || py::isinstance<py::tuple>(plans)) {
          for (const py::handle p : plans) add(p);
        } else if (!plans.is_none()) {
          add(plans);
        }
        if (!executed.is_none()) inputs.tracking = seriesFrom(executed);
        std::optional<Pose2> target;
        if (!steer_target.is_none()) target = poseFrom(steer_target);
        inputs.steering = steeringExample(scenario, target);
        py::gil_scoped_release release;
        return writeFigures(scenario, inputs, def, out_dir);
      },
      py::arg("world"), py::arg("out_dir"), py::arg("figures") = "all",
      py::arg("plans") = py::none(), py::arg("executed") = py::none(),
      py::arg("steer_target") = py::none(), py::arg("heading") = degToRad(-60.0),
      py::arg("slices") = 36, py::arg("width") = 1200, py::arg("height") = 800, py::arg("msaa") = 4,
      py::arg("gl_backend") = "auto",
      R"(Writes the study's figures as `parksim render` does, into out_dir (created), and returns
the paths written. figures: "all", "none" or a comma-separated list of FIGURE_NAMES ("plan":
one plan_<name>.png per plan); plans: a PlanResult, a trajectory, or a list of them;
executed: RunResult.executed or Episode.executed (adds tracking_error); steer_target: the
steering figure's target (x, y, theta); heading: the C-space slice's heading, rad;
gl_backend: "auto" (PARKSIM_GL_BACKEND, else egl, then osmesa), "egl" or "osmesa". A figure
whose input is missing is skipped; an unknown name raises parksim.Error.)");

  m.def(
      "encode_png",
      [](const py::handle& image) {
        const RgbImage rgb = imageFrom(image);
        std::vector<unsigned char> bytes;
        {
          py::gil_scoped_release release;
          bytes = encodePng(rgb);
        }
        return py::bytes(reinterpret_cast<const char*>(bytes.data()), bytes.size());
      },
      py::arg("image"), "PNG file bytes of an H x W x 3 uint8 image.");
  m.def(
      "write_png",
      [](const std::string& path, const py::handle& image) { writePng(path, imageFrom(image)); },
      py::arg("path"), py::arg("image"), "Writes an H x W x 3 uint8 image as PNG (atomically).");
  m.def(
      "read_png", [](const std::string& path) { return imageArray(readPng(path)); },
      py::arg("path"), "A PNG file as an H x W x 3 uint8 array.");
}

void bindFrameRecorder(py::module_& m) {
  py::class_<FrameRecorder>(m, "FrameRecorder",
                            "Films an episode into OUT/frames/*.png, and episode.mp4 / .gif with "
                            "ffmpeg (renders/film/FrameRecorder.h). Options: FrameDef fields.")
      .def(py::init([](const WorldHandle& world, const py::kwargs& kwargs) {
             py::dict options = optionsDict(kwargs);
             const FrameDef def = takeOptions(FrameDef{}, options);
             rejectUnknownOptions(options, "FrameRecorder");
             py::gil_scoped_release release;
             return std::make_unique<FrameRecorder>(*world.scenario, def);
           }),
           py::arg("world"))
      .def(
          "set_plan",
          [](FrameRecorder& r, const py::handle& plan) {
            const Trajectory trajectory = trajectoryFrom(plan);
            py::gil_scoped_release release;  // waits while the drawing thread's queue is full
            r.setPlan(trajectory);
          },
          py::arg("plan"))
      .def(
          "add_frame",
          [](FrameRecorder& r, double t, const py::handle& pose, const py::object& reference,
             const py::object& obstacle_poses, const std::vector<int>& contacts, double pos_err,
             double heading_err) {
            FrameInput in;
            in.t_s = t;
            in.pose = poseFrom(pose);
            if (!reference.is_none()) in.reference = poseFrom(reference);
            in.obstacle_poses = posesFrom(obstacle_poses);
            in.contacts = contacts;
            in.position_error_m = pos_err;
            in.heading_error_rad = heading_err;
            py::gil_scoped_release release;
            return r.addFrame(in);
          },
          py::arg("t"), py::arg("pose"), py::arg("reference") = py::none(),
          py::arg("obstacle_poses") = py::none(), py::arg("contacts") = std::vector<int>{},
          py::arg("pos_err") = 0.0, py::arg("heading_err") = 0.0,
          "Takes one sample (frames are due every 1/fps of t); returns the frames due from it, "
          "which the recorder's drawing thread draws.")
      .def(
          "finish",
          [](FrameRecorder& r) {
            RecordingResult result;
            {
              py::gil_scoped_release release;
              result = r.finish();
            }
            py::dict d;
            d["frames"] = result.frames;
            d["frames_dir"] = result.frames_dir;
            d["video"] = result.video.path;
            d["gif"] = result.gif.path;
            d["message"] = result.message;
            return d;
          },
          "Writes the last frame, waits for the files, runs ffmpeg if asked; returns a dict.")
      .def_property_readonly("frames", &FrameRecorder::frames);
}

}  // namespace

void bindRender(py::module_& m) {
  bindImages(m);
  bindFigures(m);
  bindFrameRecorder(m);
}

}  // namespace parksim::python
