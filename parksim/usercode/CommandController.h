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

/// The tick line for `in`: "tick" and the kTickFields values, '\n'-terminated.
std::string tickLine(const ControllerInput& in);

/// The wheel speeds an answer line holds: two numbers separated by blanks ("0.5 -1e-3"; a
/// trailing '\r' allowed), or nothing. "nan" and "inf" parse (and are refused as commands).
std::optional<WheelSpeeds> parseWheelAnswer(std::string_view line);

class CommandController : public Controller {
 public:
  explicit CommandController(CommandControllerDef def);
  /// Ends the process (see the file comment).
  ~CommandController() override;

  void reset(const ControllerSetup& setup) override;
  WheelSpeeds command(const ControllerInput& input) override;

 private:
  std::string failure(const std::string& why) const;
  // Why the process stopped talking: its exit, waited for briefly, or that it closed a pipe.
  std::string ended();
  void end();

  CommandControllerDef def_;
  std::string shown_;  // the command, for messages
  std::unique_ptr<ChildProcess> process_;
  std::string request_;  // reused tick line
  std::string answer_;
};

/// The registry entry: name `command`, runs_user_code.
ControllerEntry commandControllerEntry();

}  // namespace parksim
