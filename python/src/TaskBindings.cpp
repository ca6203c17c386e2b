// The reinforcement-learning tasks (rl/ParkingTask.h, rl/TaskBatch.h) for parksim.ParkingEnv
// and parksim.VecParkingEnv (python/parksim/env.py, vector.py), which add Gymnasium's
// interface. Results come back as NumPy arrays built here; stepping releases the GIL.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "parksim/pipeline/EpisodeSettings.h"
#include "parksim/rl/ParkingTask.h"
#include "parksim/rl/TaskBatch.h"
#include "parksim/rl/TaskReward.h"
#include "python/src/Bindings.h"

namespace parksim::python {

namespace {

// The task definition from keyword options: `realism` ("world": the world's realism: section,
// the request's default; or a preset) resolved as run() resolves it, then ParkingTaskDef's
// fields (`model` a SimModelDef or dict).
ParkingTaskDef taskDefFrom(const WorldHandle& world, py::dict& options, const char* function) {
  EpisodeRequest request;
  request.world = world.world;
  if (options.contains("realism")) {
    const py::object realism = options.attr("pop")("realism");
    if (!realism.is_none()) request.realism = realism.cast<std::string>();
  }
  if (options.contains("model") && options["model"].is_none()) options.attr("pop")("model");
  ParkingTaskDef def = takeOptions(ParkingTaskDef{}, options);
  rejectUnknownOptions(options, function);
  def.realism = resolveSettings(request).execution.realism;
  return def;
}

using PoseRows = py::array_t<double, py::array::c_style | py::array::forcecast>;
using FlagRows = py::array_t<bool, py::array::c_style | py::array::forcecast>;

constexpr const char* kTransitionRewardsDoc =
    "The reward of n steps of the true pose from before[i] to after[i] (x, y, theta) towards "
    "goals[i], with or without a contact: the task's own (taskTransitionReward, "
    "rl/TaskReward.h), for the environments' compute_reward.";

// The reward of n transitions towards relabelled goals: one function for a task and a batch,
// so that ParkingEnv's and VecParkingEnv's compute_reward are the same.
py::array_t<double> transitionRewards(const ParkingTaskDef& def, const Scenario& scenario,
                                      const PoseRows& before, const PoseRows& after,
                                      const PoseRows& goals, const FlagRows& contact) {
  const py::ssize_t n = contact.size();
  for (const auto* a : {&before, &after, &goals}) {
    if (a->ndim() != 2 || a->shape(0) != n || a->shape(1) != 3) {
      throw py::value_error("transition_rewards: poses must be (n, 3) arrays for n = " +
                            std::to_string(n) + " contact flags");
    }
  }
  py::array_t<double> out(n);
  auto r = out.mutable_unchecked<1>();
  const auto b = before.unchecked<2>(), a = after.unchecked<2>(), g = goals.unchecked<2>();
  const auto c = contact.unchecked<1>();
  GoalRegion goal = scenario.goal;
  for (py::ssize_t i = 0; i < n; ++i) {
    goal.pose = {g(i, 0), g(i, 1), g(i, 2)};
    r(i) = taskTransitionReward(def, goal, scenario.lot, {b(i, 0), b(i, 1), b(i, 2)},
                                {a(i, 0), a(i, 1), a(i, 2)}, c(i));
  }
  return out;
}

py::array_t<float> observationArray(const TaskObservation& o) {
  py::array_t<float> out(static_cast<py::ssize_t>(o.size()));
  std::copy(o.begin(), o.end(), out.mutable_data());
  return out;
}

py::array_t<double> poseArray(const Pose2& p) {
  py::array_t<double> out(3);
  double* d = out.mutable_data();
  d[0] = p.x;
  d[1] = p.y;
  d[2] = p.theta;
  return out;
}

// The mask of obstacles in contact: a fixed-size array, so that vector environments stack it.
void contactMask(const std::vector<int>& contacts, bool* mask, std::size_t obstacles) {
  std::fill(mask, mask + obstacles, false);
  for (int i : contacts) mask[static_cast<std::size_t>(i)] = true;
}

py::dict infoDict(const TaskInfo& info, std::size_t obstacles) {
  py::dict d;
  d["pose"] = poseArray(info.pose);
  d["estimated_pose"] = poseArray(info.estimate);
  d["t"] = info.t_s;
  d["goal_pos_err_m"] = info.goal_pos_err_m;
  d["goal_heading_err_rad"] = info.goal_heading_err_rad;
  d["is_success"] = info.is_success;
  py::array_t<bool> mask(static_cast<py::ssize_t>(obstacles));
  contactMask(info.contacts, mask.mutable_data(), obstacles);
  d["contacts"] = mask;
  return d;
}

Pose2 startFrom(const py::handle& start) { return poseFrom(start); }

// What a refused action was, for the message: its kind of values or its shape.
std::string describeAction(const py::handle& action, const py::array& a) {
  if (!a) {
    // One line: a list of arrays has a repr of many lines; each run of white space is a space.
    std::string text;
    for (const char c : py::repr(action).cast<std::string>()) {
      const bool space = c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\v' || c == '\f';
      if (!space) {
        text += c;
      } else if (!text.empty() && text.back() != ' ') {
        text += ' ';
      }
    }
    if (text.size() > 60) text = text.substr(0, 57) + "...";
    return text;
  }
  switch (a.dtype().kind()) {
    case 'U':
    case 'S': return "strings";
    case 'c': return "complex numbers";
    case 'b': return "booleans";
    case 'O': return "Python objects";
    case 'i':
    case 'u':
    case 'f': break;
    default: return "values of dtype " + py::str(a.dtype()).cast<std::string>();
  }
  std::string shape;
  for (py::ssize_t i = 0; i < a.ndim(); ++i) shape += (i ? ", " : "") + std::to_string(a.shape(i));
  if (a.ndim() == 1) shape += ",";
  return "shape (" + shape + ")";
}

// Wheel speed fractions as float64, of shape (2,) (an action, rows < 0) or (rows, 2) (a
// batch's): real numbers only (integers or floats). Strings, complex numbers, booleans and
// objects, which NumPy would convert (dropping an imaginary part), are refused like a wrong
// shape, in one line: ValueError "action: expected two finite numbers (...), got <what it
// was>" ("actions: expected shape (n, 2) ..." for a batch). Non-finite values are the task's
// to refuse, in the same words.
py::array_t<double> wheelFractions(const py::handle& action, py::ssize_t rows) {
  py::array a;
  try {
    a = py::array::ensure(action);
  } catch (const py::error_already_set&) {
    // ensure() clears NumPy's error and returns null; some objects raise from __array__.
  }
  const bool shaped = a && (rows < 0 ? a.ndim() == 1 && a.shape(0) == 2
                                     : a.ndim() == 2 && a.shape(0) == rows && a.shape(1) == 2);
  const char kind = a ? a.dtype().kind() : '\0';
  if (!shaped || (kind != 'i' && kind != 'u' && kind != 'f')) {
    const std::string expected =
        rows < 0 ? std::string("action: ") + kTaskActionExpected
                 : "actions: expected shape (" + std::to_string(rows) +
                       ", 2) of finite numbers (a left, right wheel speed fraction pair per "
                       "environment)";
    throw py::value_error(expected + ", got " + describeAction(action, a));
  }
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
}

// An action as (left, right): exactly two real numbers, a sequence or an array of shape (2,).
TaskAction actionFrom(const py::handle& action) {
  const auto a = wheelFractions(action, -1);
  return {a.at(0), a.at(1)};
}

struct TaskHandle {
  std::shared_ptr<const Scenario> scenario;
  ParkingTask task;

  py::tuple resetResult(const TaskStep& s) const {
    return py::make_tuple(observationArray(s.observation),
                          infoDict(s.info, scenario->obstacles.size()));
  }
  py::tuple stepResult(const TaskStep& s) const {
    return py::make_tuple(observationArray(s.observation), s.reward, s.terminated, s.truncated,
                          infoDict(s.info, scenario->obstacles.size()));
  }
};

void bindTask(py::module_& m) {
  py::class_<TaskHandle>(m, "_ParkingTask",
                         "One parking task (rl/ParkingTask.h); parksim.ParkingEnv wraps it.")
      .def(py::init([](const WorldHandle& world, const py::kwargs& kwargs) {
             py::dict options = optionsDict(kwargs);
             const ParkingTaskDef def = taskDefFrom(world, options, "ParkingEnv");
             return std::make_unique<TaskHandle>(
                 TaskHandle{world.scenario, ParkingTask(*world.scenario, def)});
           }),
           py::arg("world"))
      .def("seed", [](TaskHandle& h, std::uint64_t seed) { h.task.seed(seed); })
      .def_property(
          "seed_state",
          [](const TaskHandle& h) {
            const TaskSeed s = h.task.seedState();
            return py::make_tuple(s.seed, s.episode);
          },
          [](TaskHandle& h, const std::pair<std::uint64_t, std::uint64_t>& s) {
            h.task.setSeedState({s.first, s.second});
          })
      .def("reset",
           [](TaskHandle& h) {
             {
               py::gil_scoped_release release;
               h.task.reset();
             }
             return h.resetResult(h.task.last());
           })
      .def(
          "reset_at",
          [](TaskHandle& h, const py::handle& start, std::uint64_t noise_seed) {
            const Pose2 pose = startFrom(start);
            {
              py::gil_scoped_release release;
              h.task.resetAt(pose, noise_seed);
            }
            return h.resetResult(h.task.last());
          },
          py::arg("start"), py::arg("noise_seed") = 0)
      .def("step",
           [](TaskHandle& h, const py::handle& action) {
             const TaskAction a = actionFrom(action);
             {
               py::gil_scoped_release release;
               h.task.step(a);
             }
             return h.stepResult(h.task.last());
           })
      .def_property_readonly("running", [](const TaskHandle& h) { return h.task.running(); })
      .def_property_readonly("steps", [](const TaskHandle& h) { return h.task.steps(); })
      .def_property_readonly("episode",
                             [](const TaskHandle& h) {
                               return py::make_tuple(poseTuple(h.task.episodeStart()),
                                                     h.task.episodeNoiseSeed());
                             })
      .def_property_readonly("control_period_s",
                             [](const TaskHandle& h) { return h.task.controlPeriod(); })
      .def_property_readonly("definition", [](const TaskHandle& h) { return h.task.def(); })
      .def_property_readonly(
          "observation_low",
          [](const TaskHandle& h) { return observationArray(h.task.observationLow()); })
      .def_property_readonly(
          "observation_high",
          [](const TaskHandle& h) { return observationArray(h.task.observationHigh()); })
      .def_property_readonly("pose",
                             [](const TaskHandle& h) { return poseArray(h.task.last().info.pose); })
      .def_property_readonly("contacts",
                             [](const TaskHandle& h) { return h.task.last().info.contacts; })
      .def("obstacle_poses", [](const TaskHandle& h) { return posesArray(h.task.obstaclePoses()); })
      .def(
          "transition_rewards",
          [](const TaskHandle& h, const PoseRows& before, const PoseRows& after,
             const PoseRows& goals, const FlagRows& contact) {
            return transitionRewards(h.task.def(), *h.scenario, before, after, goals, contact);
          },
          py::arg("before"), py::arg("after"), py::arg("goals"), py::arg("contact"),
          kTransitionRewardsDoc);
}

// A batch's results as Gymnasium's vector API returns them: observations (n, d) float32,
// rewards (n,), terminated and truncated (n,) bool, and infos as a dict of arrays with a
// "_key" mask per key (every task reports every key).
struct BatchArrays {
  explicit BatchArrays(std::size_t n, std::size_t obstacles)
      : count(static_cast<py::ssize_t>(n)),
        obs({count, static_cast<py::ssize_t>(kTaskObservationSize)}),
        reward(count),
        terminated(count),
        truncated(count),
        pose({count, py::ssize_t{3}}),
        estimate({count, py::ssize_t{3}}),
        t(count),
        goal_pos(count),
        goal_heading(count),
        success(count),
        contacts({count, static_cast<py::ssize_t>(obstacles)}),
        obstacle_count(obstacles) {}

  void fill(const std::vector<TaskStep>& steps) {
    float* o = obs.mutable_data();
    double* p = pose.mutable_data();
    double* e = estimate.mutable_data();
    bool* c = contacts.mutable_data();
    for (std::size_t i = 0; i < steps.size(); ++i) {
      const TaskStep& s = steps[i];
      const auto k = static_cast<py::ssize_t>(i);
      std::copy(s.observation.begin(), s.observation.end(), o + i * kTaskObservationSize);
      reward.mutable_at(k) = s.reward;
      terminated.mutable_at(k) = s.terminated;
      truncated.mutable_at(k) = s.truncated;
      const Pose2 poses[2] = {s.info.pose, s.info.estimate};
      double* rows[2] = {p + 3 * i, e + 3 * i};
      for (int j = 0; j < 2; ++j) {
        rows[j][0] = poses[j].x;
        rows[j][1] = poses[j].y;
        rows[j][2] = poses[j].theta;
      }
      t.mutable_at(k) = s.info.t_s;
      goal_pos.mutable_at(k) = s.info.goal_pos_err_m;
      goal_heading.mutable_at(k) = s.info.goal_heading_err_rad;
      success.mutable_at(k) = s.info.is_success;
      contactMask(s.info.contacts, c + i * obstacle_count, obstacle_count);
    }
  }

  py::dict infos() const {
    py::dict d;
    // Every key holds a value for every sub-environment: one all-true mask, read-only so that
    // the seven "_key" entries can share it.
    py::array_t<bool> mask(count);
    std::fill(mask.mutable_data(), mask.mutable_data() + count, true);
    mask.attr("setflags")(py::arg("write") = false);
    const auto add = [&d, &mask](const char* key, const py::array& value) {
      d[key] = value;
      d[(std::string("_") + key).c_str()] = mask;
    };
    add("pose", pose);
    add("estimated_pose", estimate);
    add("t", t);
    add("goal_pos_err_m", goal_pos);
    add("goal_heading_err_rad", goal_heading);
    add("is_success", success);
    add("contacts", contacts);
    return d;
  }

  py::ssize_t count;
  py::array_t<float> obs;
  py::array_t<double> reward;
  py::array_t<bool> terminated;
  py::array_t<bool> truncated;
  py::array_t<double> pose;
  py::array_t<double> estimate;
  py::array_t<double> t;
  py::array_t<double> goal_pos;
  py::array_t<double> goal_heading;
  py::array_t<bool> success;
  py::array_t<bool> contacts;
  std::size_t obstacle_count;
};

struct BatchHandle {
  std::shared_ptr<const Scenario> scenario;
  std::unique_ptr<TaskBatch> batch;
  std::vector<TaskAction> actions;  // scratch, one per task
};

std::vector<std::optional<std::uint64_t>> seedsFrom(const py::object& seeds, std::size_t n) {
  std::vector<std::optional<std::uint64_t>> out;
  if (seeds.is_none()) return out;
  for (const py::handle s : seeds) {
    out.push_back(s.is_none() ? std::nullopt : std::optional(s.cast<std::uint64_t>()));
  }
  if (out.size() != n) {
    throw py::value_error("reset: " + std::to_string(out.size()) + " seeds for " +
                          std::to_string(n) + " environments");
  }
  return out;
}

void bindBatch(py::module_& m) {
  py::class_<BatchHandle>(m, "_TaskBatch",
                          "Parking tasks stepped together in threads (rl/TaskBatch.h); "
                          "parksim.VecParkingEnv wraps it.")
      .def(py::init([](const WorldHandle& world, std::size_t n, int threads, double spin_s,
                       bool same_step, const py::kwargs& kwargs) {
             py::dict options = optionsDict(kwargs);
             const ParkingTaskDef def = taskDefFrom(world, options, "VecParkingEnv");
             TaskBatchDef batch_def;
             batch_def.threads = threads;
             batch_def.spin_s = spin_s;
             batch_def.autoreset = same_step ? TaskAutoreset::kSameStep : TaskAutoreset::kNextStep;
             auto h = std::make_unique<BatchHandle>();
             h->scenario = world.scenario;
             h->batch = std::make_unique<TaskBatch>(*world.scenario, def, n, batch_def);
             h->actions.resize(n);
             return h;
           }),
           py::arg("world"), py::arg("num_envs"), py::arg("threads") = 0,
           py::arg("spin_s") = TaskBatchDef{}.spin_s, py::arg("same_step") = false)
      .def_property_readonly("num_envs", [](const BatchHandle& h) { return h.batch->size(); })
      .def_property_readonly("threads", [](const BatchHandle& h) { return h.batch->threads(); })
      .def_property_readonly("control_period_s",
                             [](const BatchHandle& h) { return h.batch->task(0).controlPeriod(); })
      .def_property_readonly("definition",
                             [](const BatchHandle& h) { return h.batch->task(0).def(); })
      .def_property_readonly(
          "observation_low",
          [](const BatchHandle& h) { return observationArray(h.batch->task(0).observationLow()); })
      .def_property_readonly(
          "observation_high",
          [](const BatchHandle& h) { return observationArray(h.batch->task(0).observationHigh()); })
      .def(
          "reset",
          [](BatchHandle& h, const py::object& seeds) {
            const auto s = seedsFrom(seeds, h.batch->size());
            {
              py::gil_scoped_release release;
              h.batch->reset(s);
            }
            BatchArrays out(h.batch->size(), h.scenario->obstacles.size());
            out.fill(h.batch->last());
            return py::make_tuple(out.obs, out.infos());
          },
          py::arg("seeds") = py::none(),
          "Seeds sub-environment i with seeds[i] where not None, then resets all.")
      .def("step",
           [](BatchHandle& h, const py::handle& actions) {
             const auto n = static_cast<py::ssize_t>(h.batch->size());
             const auto a = wheelFractions(actions, n);
             const double* d = a.data();
             for (std::size_t i = 0; i < h.actions.size(); ++i) {
               h.actions[i] = {d[2 * i], d[2 * i + 1]};
             }
             {
               py::gil_scoped_release release;
               h.batch->step(h.actions);
             }
             BatchArrays out(h.batch->size(), h.scenario->obstacles.size());
             out.fill(h.batch->last());
             return py::make_tuple(out.obs, out.reward, out.terminated, out.truncated, out.infos());
           })
      .def(
          "started",
          [](const BatchHandle& h) {
            if (h.batch->autoreset() != TaskAutoreset::kSameStep) {
              throw py::value_error("started: the batch was made with same_step=False");
            }
            BatchArrays out(h.batch->size(), h.scenario->obstacles.size());
            out.fill(h.batch->started());
            return py::make_tuple(out.obs, out.infos());
          },
          "same_step batches: (observations, infos) each task continues from: the new "
          "episode's first where the last step ended one, else the step's.")
      .def("seed_state",
           [](const BatchHandle& h, std::size_t i) {
             const TaskSeed s = h.batch->task(i).seedState();
             return py::make_tuple(s.seed, s.episode);
           })
      .def("obstacle_poses",
           [](const BatchHandle& h, std::size_t i) {
             return posesArray(h.batch->task(i).obstaclePoses());
           })
      .def("pose", [](const BatchHandle& h,
                      std::size_t i) { return poseArray(h.batch->task(i).last().info.pose); })
      .def("contacts", [](const BatchHandle& h,
                          std::size_t i) { return h.batch->task(i).last().info.contacts; })
      .def(
          "transition_rewards",
          [](const BatchHandle& h, const PoseRows& before, const PoseRows& after,
             const PoseRows& goals, const FlagRows& contact) {
            return transitionRewards(h.batch->task(0).def(), *h.scenario, before, after, goals,
                                     contact);
          },
          py::arg("before"), py::arg("after"), py::arg("goals"), py::arg("contact"),
          kTransitionRewardsDoc);
}

}  // namespace

void bindTasks(py::module_& m) {
  bindTask(m);
  bindBatch(m);
}

}  // namespace parksim::python
