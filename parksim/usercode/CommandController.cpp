#include "parksim/usercode/CommandController.h"

#include <charconv>
#include <chrono>
#include <stdexcept>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/io/Text.h"
#include "parksim/usercode/CommandLine.h"
#include "parksim/usercode/ProblemFile.h"

namespace parksim {

namespace {

void bindCommandController(CommandControllerDef& def, ParamSet& params) {
  params.add("start_timeout_s", &def.start_timeout_s,
             "wall time from starting the process to its 'ready', s", 0.001, 3600.0);
  params.add("tick_timeout_s", &def.tick_timeout_s,
             "wall time the process may take to answer one tick, s", 0.001, 3600.0);
}

ChildProcess::Clock::time_point after(double seconds) {
  return ChildProcess::Clock::now() + std::chrono::duration_cast<ChildProcess::Clock::duration>(
                                          std::chrono::duration<double>(seconds));
}

// The columns of the plan's rows in the reset message: trajectory.csv's (TrajectoryFile.h),
// and a car's steering angle.
nlohmann::json planJson(const Trajectory& plan, bool car) {
  nlohmann::json rows = nlohmann::json::array();
  for (const TrajectoryPoint& p : plan.points) {
    rows.push_back(
        {p.t_s, p.pose.x, p.pose.y, p.pose.theta, p.wheels.left_radps, p.wheels.right_radps});
    if (car) rows.back().push_back(p.steer_rad);
  }
  nlohmann::json columns = {"t", "x", "y", "theta", "omega_left", "omega_right"};
  if (car) columns.push_back("steer_rad");
  return {{"columns", std::move(columns)}, {"rows", std::move(rows)}};
}

std::string resetLine(const ControllerSetup& setup, const ParamMap& passed) {
  nlohmann::json params = nlohmann::json::object();
  for (const auto& [name, value] : passed) params[name] = value;
  const bool car = setup.scenario.robot.isCar();
  nlohmann::json fields = kTickFields;
  if (car) {
    for (const char* name : kCarTickFields) fields.push_back(name);
  }
  const nlohmann::json message = {
      {"format", kControllerProtocol},
      {"world", worldJson(setup.scenario)},
      {"drive", car ? "car" : "differential"},
      {"plan", planJson(setup.plan, car)},
      {"period_s", setup.period_s},
      {"latency_s", setup.latency_s},
      {"estimated_pose", setup.estimated_pose},
      {"tick_fields", std::move(fields)},
      {"params", std::move(params)},
  };
  // One line: JSON escapes the newlines of strings; text that is not UTF-8 (a name from a world
  // file) is replaced rather than refused.
  return "reset " + message.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

// A wait's limit: a timeout parameter's, or the run's limit on one command of a user's
// controller (ControllerSetup::time_limit_s) when that is shorter, and how messages name it.
struct WaitLimit {
  double s = 0.0;
  std::string text;  // "tick_timeout_s = 5 s", "the controller time limit of 2 s"
};

WaitLimit waitLimit(const char* param, double param_s, double run_s) {
  if (run_s > 0.0 && run_s < param_s) {
    return {run_s, "the controller time limit of " + formatGeneral(run_s) + " s"};
  }
  return {param_s, std::string(param) + " = " + formatGeneral(param_s) + " s"};
}

// Time a process whose output ended has to become an exit status, s.
constexpr double kClosedGraceS = 0.2;

bool isBlank(char c) { return c == ' ' || c == '\t'; }

// Two numbers separated by blanks, and nothing else but blanks.
bool parseTwoNumbers(std::string_view line, double (&values)[2]) {
  std::size_t i = 0;
  for (double& v : values) {
    while (i < line.size() && isBlank(line[i])) ++i;
    const char* first = line.data() + i;
    const char* last = line.data() + line.size();
    // from_chars takes no leading '+'; a number written with one is still a number.
    if (first != last && *first == '+') ++first;
    const auto [end, ec] = std::from_chars(first, last, v);
    if (ec != std::errc() || end == first || (end != last && !isBlank(*end))) return false;
    i = static_cast<std::size_t>(end - line.data());
  }
  while (i < line.size() && isBlank(line[i])) ++i;
  return i == line.size();
}

}  // namespace

CommandControllerDef commandControllerDef(const ParamMap& params) {
  const std::string owner = std::string("controller ") + kCommandController;
  CommandControllerDef def;
  def.command = commandParam(params, owner, "");
  ParamSet known(owner);
  bindCommandController(def, known);
  def.passed = applyKnownParams(params, known);
  return def;
}

std::string tickLine(const ControllerInput& in, bool car) {
  std::string line = "tick " + std::to_string(in.tick);
  for (const double v :
       {in.t_s, in.pose.x, in.pose.y, in.pose.theta, in.encoders_rad.left_radps,
        in.encoders_rad.right_radps, in.wheel_speeds_radps.left_radps,
        in.wheel_speeds_radps.right_radps, in.reference.x, in.reference.y, in.reference.theta,
        in.reference_twist.v_mps, in.reference_twist.omega_radps, in.feedforward.left_radps,
        in.feedforward.right_radps}) {
    line += ' ';
    appendShortest(line, v);
  }
  line += in.plan_ended ? " 1" : " 0";
  if (car) {
    for (const double v : {in.steer_rad, in.reference_steer_rad, in.commanded_speed_mps}) {
      line += ' ';
      appendShortest(line, v);
    }
  }
  line += '\n';
  return line;
}

std::optional<WheelSpeeds> parseWheelAnswer(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  double values[2] = {0.0, 0.0};
  if (!parseTwoNumbers(line, values)) return std::nullopt;
  return WheelSpeeds{values[0], values[1]};
}

std::optional<CarCommand> parseCarAnswer(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  std::size_t i = 0;
  while (i < line.size() && isBlank(line[i])) ++i;
  line.remove_prefix(i);
  CarCommand out;
  if (line.size() < 6 || !isBlank(line[5])) return std::nullopt;
  if (line.substr(0, 5) == "speed") {
    out.mode = CarCommand::Mode::kSpeed;
  } else if (line.substr(0, 5) == "accel") {
    out.mode = CarCommand::Mode::kAcceleration;
  } else {
    return std::nullopt;
  }
  double values[2] = {0.0, 0.0};
  if (!parseTwoNumbers(line.substr(6), values)) return std::nullopt;
  (out.mode == CarCommand::Mode::kSpeed ? out.speed_mps : out.accel_mps2) = values[0];
  out.steer_rad = values[1];
  return out;
}

CommandController::CommandController(CommandControllerDef def)
    : def_(std::move(def)), shown_(shownCommand(def_.command)) {}

CommandController::~CommandController() { end(); }

std::string CommandController::failure(const std::string& why) const {
  std::string text = "process `" + shown_ + "` " + why;
  if (process_) {
    const std::string last = process_->lastErrorLine();
    if (!last.empty()) text += " (stderr: " + last + ")";
  }
  return text;
}

std::string CommandController::ended() {
  // Its output ends a moment before its exit can be waited for.
  if (process_->waitUntil(after(kClosedGraceS))) return process_->exit()->text();
  process_->kill();
  return "closed its standard input or output";
}

void CommandController::end() {
  if (!process_) return;
  process_->closeStdin();
  if (!process_->waitUntil(after(kExitGraceS))) process_->kill();
  process_.reset();
}

void CommandController::reset(const ControllerSetup& setup) {
  end();
  robot_ = setup.scenario.robot;
  run_limit_s_ = setup.time_limit_s;
  const WaitLimit limit = waitLimit("start_timeout_s", def_.start_timeout_s, run_limit_s_);
  const auto deadline = after(limit.s);
  try {
    process_ = std::make_unique<ChildProcess>(ChildProcessDef{def_.command, true, true});
  } catch (const Error& e) {
    throw UserCodeError(UserCodeError::Component::kController,
                        "process `" + shown_ + "` could not be started: " + e.what());
  }
  const ChildProcess::LineStatus status =
      process_->exchange(resetLine(setup, def_.passed), answer_, deadline, kMaxAnswerBytes);
  std::string why;
  switch (status) {
    case ChildProcess::LineStatus::kLine:
      if (answer_ == "ready" || answer_ == "ready\r") return;
      why = "answered '" + escapeTextShortened(answer_, 60) + "' to reset, not 'ready'";
      break;
    case ChildProcess::LineStatus::kTimeout: why = "was not ready within " + limit.text; break;
    case ChildProcess::LineStatus::kClosed: why = "ended before it was ready: " + ended(); break;
    case ChildProcess::LineStatus::kTooLong:
      why = "answered reset with a line longer than " + std::to_string(kMaxAnswerBytes) + " bytes";
      break;
  }
  process_->kill();
  throw UserCodeError(UserCodeError::Component::kController, failure(why));
}

const std::string& CommandController::exchangeTick(const ControllerInput& input) {
  if (!process_) {
    throw UserCodeError(UserCodeError::Component::kController,
                        "process `" + shown_ + "` was asked for a command before its reset");
  }
  const WaitLimit limit = waitLimit("tick_timeout_s", def_.tick_timeout_s, run_limit_s_);
  const auto deadline = after(limit.s);
  const std::string at = " at tick " + std::to_string(input.tick);
  if (process_->pendingOutput() > 0) {
    process_->kill();
    throw UserCodeError(
        UserCodeError::Component::kController,
        failure("wrote more than one line per request, before tick " + std::to_string(input.tick)));
  }
  request_ = tickLine(input, robot_.isCar());
  std::string why;
  switch (process_->exchange(request_, answer_, deadline, kMaxAnswerBytes)) {
    case ChildProcess::LineStatus::kLine: return answer_;
    case ChildProcess::LineStatus::kTimeout:
      why = "gave no answer" + at + " within " + limit.text;
      break;
    case ChildProcess::LineStatus::kClosed: why = ended() + at; break;
    case ChildProcess::LineStatus::kTooLong:
      why = "answered" + at + " with a line longer than " + std::to_string(kMaxAnswerBytes) +
            " bytes";
      break;
  }
  process_->kill();
  throw UserCodeError(UserCodeError::Component::kController, failure(why));
}

void CommandController::refuse(const ControllerInput& input, const char* expected) {
  const std::string why = "answered '" + escapeTextShortened(answer_, 60) + "' at tick " +
                          std::to_string(input.tick) + ": expected " + expected;
  process_->kill();
  throw UserCodeError(UserCodeError::Component::kController, failure(why));
}

WheelSpeeds CommandController::command(const ControllerInput& input) {
  const std::string& answer = exchangeTick(input);
  if (std::optional<WheelSpeeds> w = parseWheelAnswer(answer)) return *w;
  refuse(input, "'LEFT RIGHT', two numbers in rad/s");
}

std::optional<CarCommand> CommandController::carCommand(const ControllerInput& input) {
  const std::string& answer = exchangeTick(input);
  if (std::optional<CarCommand> c = parseCarAnswer(answer)) return c;
  if (std::optional<WheelSpeeds> w = parseWheelAnswer(answer)) {
    return carCommandOfWheels(*w, robot_, input.steer_rad);
  }
  refuse(input, "'speed V STEER' (m/s, rad), 'accel A STEER' (m/s^2, rad) or 'LEFT RIGHT'");
}

ControllerEntry commandControllerEntry() {
  ControllerInfo info;
  info.name = kCommandController;
  info.description =
      "a process in any language: one line per control tick on its stdin, 'LEFT RIGHT' back "
      "(docs/your-code.md)";
  info.runs_user_code = true;
  info.own_process = true;
  CommandControllerDef defaults;
  ParamSet known(std::string("controller ") + kCommandController);
  bindCommandController(defaults, known);
  info.params = commandParamInfos(
      "the command line to run, without a shell; other parameters go to the process in its "
      "reset message",
      known);
  return {std::move(info), [](const ParamMap& params) -> std::unique_ptr<Controller> {
            return std::make_unique<CommandController>(commandControllerDef(params));
          }};
}

}  // namespace parksim
