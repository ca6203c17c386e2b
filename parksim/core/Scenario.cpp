#include "parksim/core/Scenario.h"

namespace parksim {

const char* toString(ObstacleKind kind) {
  switch (kind) {
    case ObstacleKind::kWall: return "wall";
    case ObstacleKind::kCurb: return "curb";
    case ObstacleKind::kIsland: return "island";
    case ObstacleKind::kBox: return "box";
    case ObstacleKind::kParkedRobot: return "parked_robot";
  }
  return "box";
}

}  // namespace parksim
