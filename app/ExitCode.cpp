#include "app/Command.h"

#include <cstdio>
#include <string>

#include "parksim/cli/TerminalText.h"
#include "parksim/usercode/UserCodeIsolation.h"

namespace parksim::app {

int exitCodeFor(EpisodeStatus status) {
  switch (status) {
    case EpisodeStatus::kMet: return kExitOk;
    case EpisodeStatus::kPlanFailed: return kExitUnsolved;
    case EpisodeStatus::kPlanInvalid: return kExitPlanInvalid;
    case EpisodeStatus::kPlannerError:
    case EpisodeStatus::kControllerError: return kExitUserCodeFailed;
    case EpisodeStatus::kContact:
    case EpisodeStatus::kGoalMissed:
    case EpisodeStatus::kToleranceMissed: return kExitToleranceNotMet;
  }
  return kExitInternal;
}

std::string verdictLine(const Verdict& verdict) {
  switch (verdict.status) {
    case EpisodeStatus::kPlanInvalid:
    case EpisodeStatus::kPlannerError:
    case EpisodeStatus::kControllerError:
      return std::string(toString(verdict.status)) + ": " + verdict.reason;
    default: return verdict.reason;
  }
}

std::optional<int> runWatched(const char* program, bool isolate, const UserCodeLimits& limits,
                              const std::function<int(UserCodeWatch*)>& body) {
  if (!isolate) return body(nullptr);
  try {
    const std::string code =
        runIsolated([&](UserCodeWatch& watch) { return std::to_string(body(&watch)); }, limits);
    return std::stoi(code);
  } catch (const UserCodeError& e) {
    std::fprintf(stderr, "%s: %s\n", program,
                 cli::printable(verdictLine(userCodeVerdict(e))).c_str());
    return std::nullopt;
  }
}

}  // namespace parksim::app
