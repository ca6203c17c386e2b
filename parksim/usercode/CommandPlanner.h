#pragma once
// A planner that is a program in any language, run as a command (issue 30's "any language"):
// registered as the planner `command`, its parameter `command` holding the command line
// (CommandLine.h). Each solve() writes the problem (ProblemFile.h) to a fresh private directory,
// runs the command with {problem} and {out} replaced by the problem file's and an empty output
// directory's absolute paths, and reads the plan back from {out}/trajectory.csv, parksim's own
// plan format (results/TrajectoryFile.h, the file `parksim plan` writes).
//
//   parksim run worlds/head_in.yaml --planner-command 'python3 planner.py {problem} {out}'
//   parksim run worlds/head_in.yaml --planner command \
//       --planner-param command='python3 planner.py {problem} {out}' --planner-param timeout_s=60
//
// The answer:
// - exit status 0 and a trajectory.csv with rows: the plan (checked before it is driven,
//   planner/base/PlanCheck.h: it is user code, never trusted);
// - exit status 0 and a trajectory.csv with its header alone: "no plan", an unsolved result
//   (plan_failed), the last line of its standard error as the message;
// - anything else is the planner's failure, a UserCodeError (planner_error) naming the command
//   and the reason in one line: a non-zero exit or a signal, no trajectory.csv, a malformed one,
//   more than timeout_s of wall time, or than the run's limit on a user's planner
//   (PlanningProblem::time_limit_s, `--planner-timeout`) when that is shorter (the process group
//   is killed; the message names the limit).
// Its standard output and error are kept (the last ChildProcess::kStderrTailBytes bytes) and
// the last line quoted in messages. The private directory is removed afterwards.

#include <memory>
#include <string>
#include <vector>

#include "parksim/core/params/ParamMap.h"
#include "parksim/planner/base/Planner.h"

namespace parksim {

/// The registered name of the command planner.
inline constexpr const char* kCommandPlanner = "command";

struct CommandPlannerDef {
  /// The command's words, {problem} and {out} not yet replaced; one of them contains {out}.
  std::vector<std::string> command;
  /// Wall time the command may take, s; then its process group is killed (planner_error). The
  /// run's limit (PlanningProblem::time_limit_s) applies when it is shorter.
  double timeout_s = 600.0;
  /// The planner's other parameters, handed to the command in the problem file's "params".
  ParamMap passed;
};

/// The Def of `params`: `command` (required) split into words, `timeout_s`, and every other
/// parameter passed on. Throws Error naming the parameter: no command, a command without {out},
/// a program that is not found, a bad timeout_s.
CommandPlannerDef commandPlannerDef(const ParamMap& params);

class CommandPlanner : public Planner {
 public:
  explicit CommandPlanner(CommandPlannerDef def);
  PlanResult solve(const PlanningProblem& problem) override;

 private:
  CommandPlannerDef def_;
};

/// The registry entry: name `command`, runs_user_code.
PlannerEntry commandPlannerEntry();

}  // namespace parksim
