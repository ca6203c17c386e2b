#include "parksim/pipeline/EpisodeRequest.h"

#include "parksim/core/io/Error.h"

namespace parksim {

TrackingTolerance ToleranceOverrides::appliedTo(TrackingTolerance base) const {
  if (max_pos_err_m) base.max_pos_err_m = *max_pos_err_m;
  if (goal_pos_err_m) base.goal_pos_err_m = *goal_pos_err_m;
  if (goal_heading_err_deg) base.goal_heading_err_deg = *goal_heading_err_deg;
  if (max_contacts) base.max_contacts = *max_contacts;
  if (max_parked_displacement_m) base.max_parked_displacement_m = *max_parked_displacement_m;
  return base;
}

const char* toString(FilesPolicy policy) {
  switch (policy) {
    case FilesPolicy::kNone: return "none";
    case FilesPolicy::kFailures: return "failures";
    case FilesPolicy::kAll: return "all";
  }
  return "?";
}

FilesPolicy filesPolicyFromString(const std::string& name) {
  for (FilesPolicy p : {FilesPolicy::kNone, FilesPolicy::kFailures, FilesPolicy::kAll}) {
    if (name == toString(p)) return p;
  }
  throw Error("must be none, failures or all, got '" + name + "'");
}

}  // namespace parksim
