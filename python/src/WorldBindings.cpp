// parksim.World (an immutable Scenario), loading it, and the questions asked of a lot without
// simulating it: footprint collisions and C-space slices.

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/io/InputFile.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/renders/plots/CSpace.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "parksim/scenario/world/World.h"
#include "python/src/Bindings.h"

namespace parksim::python {

namespace {

py::array corners(const OrientedBox& box) {
  py::array_t<double> out({4, 2});
  auto r = out.mutable_unchecked<2>();
  const auto c = box.corners();
  for (py::ssize_t i = 0; i < 4; ++i) {
    r(i, 0) = c[static_cast<std::size_t>(i)].x();
    r(i, 1) = c[static_cast<std::size_t>(i)].y();
  }
  return out;
}

py::array polygon(const std::vector<Eigen::Vector2d>& points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t{2}});
  auto r = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i) {
    r(static_cast<py::ssize_t>(i), 0) = points[i].x();
    r(static_cast<py::ssize_t>(i), 1) = points[i].y();
  }
  return out;
}

const char* shapeName(ObstacleShape shape) {
  switch (shape) {
    case ObstacleShape::kBox: return "box";
    case ObstacleShape::kCircle: return "circle";
    case ObstacleShape::kPolygon: return "polygon";
    case ObstacleShape::kCompound: return "compound";
  }
  return "box";
}

py::dict obstacleDict(const Obstacle& o) {
  py::dict d;
  d["name"] = o.name;
  d["kind"] = toString(o.kind);
  d["shape"] = shapeName(o.shape);
  // Boxes: the box; circles, polygons and compounds: their axis-aligned bounding rectangle.
  d["center"] = py::make_tuple(o.box.center.x(), o.box.center.y());
  d["size"] = py::make_tuple(2.0 * o.box.half_extents.x(), 2.0 * o.box.half_extents.y());
  d["yaw"] = o.box.yaw;
  d["height"] = o.height_m;
  d["corners"] = corners(o.box);
  if (o.shape == ObstacleShape::kCircle) d["radius"] = o.radius_m;
  if (o.shape == ObstacleShape::kPolygon) d["vertices"] = polygon(o.vertices);
  if (o.shape == ObstacleShape::kCompound) {
    // Its convex parts (their union is the obstacle) and its outline rings (outlines
    // counter-clockwise, holes clockwise; none for a map's cells).
    py::list parts;
    for (const auto& part : o.compound->parts) parts.append(polygon(part));
    py::list rings;
    for (const auto& ring : o.compound->rings) rings.append(polygon(ring));
    d["parts"] = parts;
    d["rings"] = rings;
  }
  return d;
}

// What the readers ignored (World::warnings), as Python warnings: the command line prints them
// as "warning: " lines.
void warnAbout(const World& world) {
  for (const std::string& line : world.warnings) {
    if (PyErr_WarnEx(PyExc_UserWarning, line.c_str(), 1) != 0) throw py::error_already_set();
  }
}

WorldHandle parsedWorld(const std::string& text, const std::string& source_name) {
  auto world = std::make_shared<const World>(parseWorld(text, source_name));
  warnAbout(*world);
  return WorldHandle(std::move(world), text, source_name);
}

// The footprint checker with its world kept alive (it copies what it needs, but a World
// argument is what users hold).
struct CollisionChecker {
  std::shared_ptr<const Scenario> scenario;
  BulletCollisionWorld collision;
  explicit CollisionChecker(const WorldHandle& w) : scenario(w.scenario), collision(*w.scenario) {}
};

}  // namespace

void bindWorld(py::module_& m) {
  py::class_<WorldHandle>(
      m, "World",
      "A parking problem read from a world file (immutable): lot, obstacles, robot, "
      "start, goal, physics. Made by parksim.load_world().")
      .def_property_readonly("name", [](const WorldHandle& w) { return w.scenario->name; })
      .def_property_readonly("source_path",
                             [](const WorldHandle& w) { return w.scenario->source_path; })
      .def_property_readonly("lot",
                             [](const WorldHandle& w) {
                               const LotBounds& b = w.scenario->lot;
                               py::dict d;
                               d["x_min"] = b.x_min_m;
                               d["y_min"] = b.y_min_m;
                               d["x_max"] = b.x_max_m;
                               d["y_max"] = b.y_max_m;
                               return d;
                             })
      .def_property_readonly(
          "obstacles",
          [](const WorldHandle& w) {
            py::list l;
            for (const Obstacle& o : w.scenario->obstacles) {
              l.append(obstacleDict(o));
            }
            return l;
          },
          "One dict per obstacle: name, kind, center, size, yaw, height, "
          "corners (4 x 2 array), m and rad.")
      .def_property_readonly("robot", [](const WorldHandle& w) { return w.scenario->robot; })
      .def_property_readonly("start",
                             [](const WorldHandle& w) { return poseTuple(w.scenario->start); })
      .def_property_readonly("goal",
                             [](const WorldHandle& w) {
                               const GoalRegion& g = w.scenario->goal;
                               py::dict d;
                               d["pose"] = poseTuple(g.pose);
                               d["position_tolerance_m"] = g.position_tolerance_m;
                               d["heading_tolerance_rad"] = g.heading_tolerance_rad;
                               d["either_heading"] = g.either_heading;
                               return d;
                             })
      .def_property_readonly(
          "realism",
          [](const WorldHandle& w) -> py::object {
            if (!w.world->sections.has_realism) return py::none();
            return py::str(w.world->sections.realism.name);
          },
          "The realism: section's preset name (None: the ideal robot).")
      .def_property_readonly("time_step_s",
                             [](const WorldHandle& w) { return w.scenario->physics.time_step_s; })
      .def(
          "footprint",
          [](const WorldHandle& w, const py::handle& pose, double margin_m) {
            return corners(footprintAt(w.scenario->robot, poseFrom(pose), margin_m));
          },
          py::arg("pose"), py::arg("margin_m") = 0.0,
          "Corners (4 x 2 array, m) of the robot's footprint at pose (x, y, theta).")
      // Pickled as its text and name, and read again: a World crosses to another process
      // (multiprocessing, Gymnasium's AsyncVectorEnv) without the file. It is immutable, so a
      // copy may share it.
      .def(py::pickle(
          [](const WorldHandle& w) { return py::make_tuple(w.source_text, w.source_name); },
          [](const py::tuple& state) {
            if (state.size() != 2) throw py::value_error("World: bad pickled state");
            return parsedWorld(state[0].cast<std::string>(), state[1].cast<std::string>());
          }))
      .def("__copy__", [](const WorldHandle& w) { return w; })
      .def(
          "__deepcopy__", [](const WorldHandle& w, const py::handle&) { return w; },
          py::arg("memo"))
      .def("__repr__", [](const WorldHandle& w) {
        return "<parksim.World '" + w.scenario->name + "' from " + w.scenario->source_path + ": " +
               std::to_string(w.scenario->obstacles.size()) + " obstacles>";
      });

  m.def(
      "_load_world",
      [](const std::string& path) {
        auto world = std::make_shared<const World>(loadWorld(path));
        warnAbout(*world);
        // Read again for pickling, after the loader's checks and messages.
        return WorldHandle(std::move(world), readInputFile(path, kMaxWorldFileBytes, "world file"),
                           path);
      },
      py::arg("path"));
  m.def("_parse_world", &parsedWorld, py::arg("text"), py::arg("source_name"));

  py::class_<CollisionChecker>(m, "CollisionChecker",
                               "Footprint queries against a world's obstacles (the planner's "
                               "collision checker). Not thread-safe: one per thread.")
      .def(py::init<const WorldHandle&>(), py::arg("world"))
      .def(
          "is_free",
          [](const CollisionChecker& c, const py::handle& pose, double margin_m) {
            return c.collision.isFree(poseFrom(pose), margin_m);
          },
          py::arg("pose"), py::arg("margin_m") = 0.0,
          "True when the footprint at pose, grown by margin_m, overlaps no obstacle.")
      .def(
          "overlapping",
          [](const CollisionChecker& c, const py::handle& pose, double margin_m) {
            return c.collision.overlapping(poseFrom(pose), margin_m);
          },
          py::arg("pose"), py::arg("margin_m") = 0.0, "Names of the obstacles it overlaps.")
      .def(
          "clearance",
          [](const CollisionChecker& c, const py::handle& pose) {
            return c.collision.clearance(poseFrom(pose));
          },
          py::arg("pose"), "Distance from the footprint to the nearest obstacle, m.");

  m.def(
      "cspace_slice",
      [](const WorldHandle& w, double theta_rad) {
        py::list out;
        for (const Obstacle& o : w.scenario->obstacles) {
          out.append(polygon(cspaceSlice(o, w.scenario->robot, theta_rad)));
        }
        return out;
      },
      py::arg("world"), py::arg("theta"),
      "The C-space obstacles at heading theta (rad): one counter-clockwise convex polygon (N x 2 "
      "array, m) per obstacle, in scenario order. The reference point collides exactly inside "
      "them.");
}

}  // namespace parksim::python
