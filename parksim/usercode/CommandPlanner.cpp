#include "parksim/usercode/CommandPlanner.h"

#include <stdlib.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <system_error>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/InputFile.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/system/ChildProcess.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/planner/motion/PathCost.h"
#include "parksim/results/episode/JsonFile.h"
#include "parksim/results/episode/TrajectoryFile.h"
#include "parksim/usercode/CommandLine.h"
#include "parksim/usercode/ProblemFile.h"

namespace parksim {

namespace {

namespace fs = std::filesystem;

// The command's own parameters; the Def's initializers are their defaults.
void bindCommandPlanner(CommandPlannerDef& def, ParamSet& params) {
  params.add("timeout_s", &def.timeout_s,
             "wall time the command may take, s; then it is killed with its process group "
             "(planner_error)",
             0.001, 86400.0);
}

// A private directory for one solve: {problem} and {out} live in it. Removed with everything in
// it when the solve ends, however it ends.
class ScratchDirectory {
 public:
  ScratchDirectory() {
    std::error_code ec;
    fs::path base = fs::temp_directory_path(ec);
    if (ec) base = "/tmp";
    std::string name = (base / "parksim-plan-XXXXXX").string();
    if (::mkdtemp(name.data()) == nullptr) {
      throw EnvironmentError("planner command: cannot make a directory in " + base.string() +
                             " for the problem file (set TMPDIR to a writable directory)");
    }
    path_ = name;
  }
  ~ScratchDirectory() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// How often a running command is looked at for the search's cancel flag.
constexpr auto kCancelPoll = std::chrono::milliseconds(50);

}  // namespace

CommandPlannerDef commandPlannerDef(const ParamMap& params) {
  const std::string owner = std::string("planner ") + kCommandPlanner;
  CommandPlannerDef def;
  def.command = commandParam(params, owner, "{out}");
  ParamSet known(owner);
  bindCommandPlanner(def, known);
  def.passed = applyKnownParams(params, known);
  return def;
}

CommandPlanner::CommandPlanner(CommandPlannerDef def) : def_(std::move(def)) {}

PlanResult CommandPlanner::solve(const PlanningProblem& problem) {
  const auto start = ChildProcess::Clock::now();
  const std::string shown = shownCommand(def_.command);
  const auto failed = [&](const std::string& why, const ChildProcess* child) {
    std::string text = std::string("planner ") + kCommandPlanner + " `" + shown + "` " + why;
    if (child != nullptr) {
      const std::string last = child->lastErrorLine();
      if (!last.empty()) text += " (stderr: " + last + ")";
    }
    return UserCodeError(UserCodeError::Component::kPlanner, text);
  };

  const ScratchDirectory scratch;
  const fs::path problem_path = scratch.path() / "problem.json";
  const fs::path out_dir = scratch.path() / "out";
  writeJsonFile(problem_path.string(), problemJson(problem, def_.passed));
  fs::create_directory(out_dir);
  const std::vector<std::string> argv = substitutePlaceholders(
      def_.command, {{"problem", problem_path.string()}, {"out", out_dir.string()}});

  std::optional<ChildProcess> child;
  try {
    child.emplace(ChildProcessDef{argv, false, false});
  } catch (const Error& e) {
    throw failed(std::string("could not be started: ") + e.what(), nullptr);
  }
  // The shorter of its own timeout_s and the run's limit on a user's planner, named as such.
  const bool run_limit = problem.time_limit_s > 0.0 && problem.time_limit_s < def_.timeout_s;
  const double limit_s = run_limit ? problem.time_limit_s : def_.timeout_s;
  const std::string limit_text = run_limit ? "the planner time limit of " + formatGeneral(limit_s)
                                           : "timeout_s = " + formatGeneral(limit_s);
  const auto deadline = start + std::chrono::duration_cast<ChildProcess::Clock::duration>(
                                    std::chrono::duration<double>(limit_s));
  std::optional<ChildExit> exit;
  while (!exit) {
    if (problem.search().cancelled()) {
      child->kill();
      PlanResult cancelled;
      cancelled.status = PlanStatus::kCancelled;
      cancelled.message = "cancelled while the command ran";
      return cancelled;
    }
    const auto now = ChildProcess::Clock::now();
    if (now >= deadline) {
      child->kill();
      throw failed("gave no answer within " + limit_text + " s and was killed", &*child);
    }
    exit = child->waitUntil(std::min(deadline, now + kCancelPoll));
  }
  if (!exit->success()) throw failed(exit->text(), &*child);

  // The answer: what is not there, not a regular file, too large or not a plan is its fault.
  const fs::path answer = out_dir / "trajectory.csv";
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(answer, ec))) {
    throw failed("exited with status 0 but wrote no {out}/trajectory.csv", &*child);
  }
  Trajectory trajectory;
  try {
    const std::string text = readInputFile(answer.string(), PlanFileLimits::kMaxBytes, "plan file");
    trajectory = parseTrajectoryCsvRows(text, "{out}/trajectory.csv", problem.scenario.robot);
  } catch (const Error& e) {
    std::string why = e.what();
    // The scratch directory's path means nothing to the user.
    if (why.rfind(answer.string(), 0) == 0)
      why = "{out}/trajectory.csv" + why.substr(answer.string().size());
    throw failed("wrote a bad plan: " + why, &*child);
  }

  PlanResult result;
  result.stats.times.total_s =
      std::chrono::duration<double>(ChildProcess::Clock::now() - start).count();
  if (trajectory.empty()) {
    // A header without rows: the command's "no plan".
    const std::string last = child->lastErrorLine();
    result.status = PlanStatus::kIterationLimit;
    result.message = "the command found no plan" + (last.empty() ? std::string() : ": " + last);
    return result;
  }
  const SearchDef& search = problem.search();
  result.status = PlanStatus::kSolved;
  result.cost = trajectoryCost(trajectory, problem.scenario.robot,
                               {search.reverse_penalty, search.cusp_penalty_m});
  result.cost_history.push_back({result.stats.times.total_s, 0, result.cost});
  result.stats.first_solution_s = result.stats.times.total_s;
  result.stats.first_solution_iteration = 0;
  result.message =
      "planned by `" + shown + "` in " + formatFixed(result.stats.times.total_s, 3) + " s";
  result.trajectory = std::move(trajectory);
  return result;
}

PlannerEntry commandPlannerEntry() {
  PlannerInfo info;
  info.name = kCommandPlanner;
  info.description =
      "a program in any language: reads the problem file {problem}, writes "
      "{out}/trajectory.csv (docs/your-code.md)";
  info.runs_user_code = true;
  info.own_process = true;
  CommandPlannerDef defaults;
  ParamSet known(std::string("planner ") + kCommandPlanner);
  bindCommandPlanner(defaults, known);
  info.params = commandParamInfos(
      "the command line to run, without a shell; {problem} and {out} are replaced by the "
      "problem file and the directory for trajectory.csv; other parameters go to the program "
      "in the problem file",
      known);
  return {std::move(info), [](const ParamMap& params) -> std::unique_ptr<Planner> {
            return std::make_unique<CommandPlanner>(commandPlannerDef(params));
          }};
}

}  // namespace parksim
