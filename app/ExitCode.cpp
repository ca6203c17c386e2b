#include "app/Command.h"

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

}  // namespace parksim::app
