#pragma once
// A motion validator that keeps a path clear enough for any later check. MotionValidator
// accepts a path when its footprint, grown by half the resolution, is free at poses at most the
// resolution of footprint travel apart: between two such poses the path is free, but may pass an
// obstacle closer than half the resolution. A path made again from the same geometry (a car's
// plan along its search's pieces, CarPlanAlong.h, whose rows fall elsewhere) is then checked at
// other poses, and can fail there. This one checks the footprint grown by the whole resolution
// at the same spacing, and keeps the reference point half a resolution further inside the lot,
// so a path it accepts keeps half a resolution everywhere: MotionValidator accepts it however it
// is sampled. The poses it is told to spare (a plan's start and goal, which the world only keeps
// half a resolution clear) are checked as MotionValidator checks them.

#include <vector>

#include "parksim/core/model/FootprintChecker.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/planner/motion/MotionValidator.h"

namespace parksim {

class ClearanceValidator {
 public:
  /// `checker`, `robot`, `lot` and `def` as MotionValidator's; `spared` poses keep its margin.
  /// Keeps references to `checker` only.
  ClearanceValidator(const FootprintChecker& checker, const RobotDef& robot, const LotBounds& lot,
                     const MotionValidatorDef& def, std::vector<Pose2> spared);
  ClearanceValidator(const ClearanceValidator&) = delete;
  ClearanceValidator& operator=(const ClearanceValidator&) = delete;

  /// The validator to search with.
  const MotionValidator& validator() const { return validator_; }

 private:
  // The footprint checker with the extra margin, except at the spared poses.
  class Grown final : public FootprintChecker {
   public:
    Grown(const FootprintChecker& inner, double extra_m, std::vector<Pose2> spared)
        : inner_(inner), extra_m_(extra_m), spared_(std::move(spared)) {}
    bool isFree(const Pose2& pose, double margin_m) const override;
    std::vector<std::string> overlapping(const Pose2& pose, double margin_m) const override {
      return inner_.overlapping(pose, margin_m);
    }

   private:
    const FootprintChecker& inner_;
    double extra_m_;
    std::vector<Pose2> spared_;
  };

  Grown grown_;
  MotionValidator validator_;
};

}  // namespace parksim
