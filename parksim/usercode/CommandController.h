#pragma once
// A controller that is a process in any language, speaking a line protocol on its standard
// input and output (issue 30's "any language"): registered as the controller `command`, its
// parameter `command` holding the command line (CommandLine.h, no shell).
//
//   parksim run worlds/head_in.yaml --controller-command 'python3 controller.py'
//
// The protocol, `parksim-controller/1` (docs/your-code.md has it whole, with an example):
// - reset() starts the process (one per episode) and sends one line, "reset " and a JSON
//   object: the format, the world (ProblemFile.h's worldJson), the plan's rows, the control
//   period and latency, whether poses are estimates, the tick line's field names, and the
//   controller's other parameters. The process answers "ready" within start_timeout_s.
// - command() sends one line per control tick, "tick" and the ControllerInput's 17 numbers
//   (kTickFields, shortest round-trip text); the process answers one line, "LEFT RIGHT", the
//   wheel speed commands in rad/s, within tick_timeout_s.
// - The run's limit on one command (ControllerSetup::time_limit_s, `--controller-timeout`)
//   replaces either timeout when it is shorter; messages name the limit that struck.
// - A car (the reset's "drive" is "car"; docs/cars.md): its tick lines carry kCarTickFields
//   after those, and the process may answer "speed V STEER" (m/s, rad) or "accel A STEER"
//   (m/s^2, rad) instead (CarCommand, sim/Controller.h); "LEFT RIGHT" still drives it, as its
//   rear wheels.
// - At the episode's end (the controller is destroyed) its standard input is closed; the
//   process should exit, and is killed with its process group kExitGraceS later.
// Anything else (an exit, a line that is not two numbers, a line longer than kMaxAnswerBytes,
// no answer in time) throws; the episode then ends with controller_error naming the process,
// the tick and the reason (sim/episode/Episode.cpp), and commands that are NaN or beyond the wheel
// speed limit are refused there too. Its standard error is kept (the last
// ChildProcess::kStderrTailBytes bytes) and its last line quoted in messages.

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "parksim/core/params/ParamMap.h"
#include "parksim/core/system/ChildProcess.h"
#include "parksim/sim/control/Controller.h"

namespace parksim {

/// The registered name of the command controller.
inline constexpr const char* kCommandController = "command";
/// The protocol's name and version: the reset message's "format".
inline constexpr const char* kControllerProtocol = "parksim-controller/1";
/// Longest answer line a process may send, bytes (docs/limits.md).
inline constexpr std::size_t kMaxAnswerBytes = 1024;
/// Time a process has to exit once its standard input is closed, s.
inline constexpr double kExitGraceS = 1.0;

/// The numbers of a tick line, in order, with their units (ControllerInput's fields).
inline constexpr std::array<const char*, 17> kTickFields = {"tick",
                                                            "t_s",
                                                            "x_m",
                                                            "y_m",
                                                            "theta_rad",
                                                            "encoder_left_rad",
                                                            "encoder_right_rad",
                                                            "wheel_left_radps",
                                                            "wheel_right_radps",
                                                            "ref_x_m",
                                                            "ref_y_m",
                                                            "ref_theta_rad",
                                                            "ref_v_mps",
                                                            "ref_omega_radps",
                                                            "ff_left_radps",
                                                            "ff_right_radps",
                                                            "plan_ended"};

struct CommandControllerDef {
  /// The command's words.
  std::vector<std::string> command;
  /// Wall time from the start of the process to its "ready", s.
  double start_timeout_s = 30.0;
  /// Wall time the process may take to answer one tick, s.
  double tick_timeout_s = 5.0;
  /// The controller's other parameters, handed to the process in the reset message's "params".
  ParamMap passed;
};

/// The Def of `params`: `command` (required), the time limits, and every other parameter passed
/// on. Throws Error naming the parameter.
CommandControllerDef commandControllerDef(const ParamMap& params);

/// The tick line for `in`: "tick" and the kTickFields values (and a car's kCarTickFields),
/// '\n'-terminated.
std::string tickLine(const ControllerInput& in, bool car = false);

/// The numbers a car's tick line carries after kTickFields (ControllerInput's car fields).
inline constexpr std::array<const char*, 3> kCarTickFields = {"steer_rad", "ref_steer_rad",
                                                              "commanded_speed_mps"};

/// The wheel speeds an answer line holds: two numbers separated by blanks ("0.5 -1e-3"; a
/// trailing '\r' allowed), or nothing. "nan" and "inf" parse (and are refused as commands).
std::optional<WheelSpeeds> parseWheelAnswer(std::string_view line);

/// The car command an answer line holds: "speed V STEER" or "accel A STEER" (blanks between,
/// a trailing '\r' allowed), or nothing.
std::optional<CarCommand> parseCarAnswer(std::string_view line);

class CommandController : public Controller {
 public:
  explicit CommandController(CommandControllerDef def);
  /// Ends the process (see the file comment).
  ~CommandController() override;

  void reset(const ControllerSetup& setup) override;
  WheelSpeeds command(const ControllerInput& input) override;
  /// A car: the process's answer as a car command, or its wheel speeds read as the rear
  /// wheels' (carCommandOfWheels).
  std::optional<CarCommand> carCommand(const ControllerInput& input) override;

 private:
  // Sends the tick line and returns the answer line; throws what command() documents, with
  // `expected` saying what a good answer is.
  const std::string& exchangeTick(const ControllerInput& input);
  // Throws that the last answer is not one of `expected`, ending the process.
  [[noreturn]] void refuse(const ControllerInput& input, const char* expected);
  std::string failure(const std::string& why) const;
  // Why the process stopped talking: its exit, waited for briefly, or that it closed a pipe.
  std::string ended();
  void end();

  CommandControllerDef def_;
  double run_limit_s_ = 0.0;  // the run's limit on one command (ControllerSetup), 0: none
  std::string shown_;         // the command, for messages
  RobotDef robot_;            // the scenario's, from the reset
  std::unique_ptr<ChildProcess> process_;
  std::string request_;  // reused tick line
  std::string answer_;
};

/// The registry entry: name `command`, runs_user_code.
ControllerEntry commandControllerEntry();

}  // namespace parksim
