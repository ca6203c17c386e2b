// The OMPL plugin (OmplApi.h): compiled alone into libparksim_ompl_plugin.so, which links libompl.

#include "parksim/planner/steering/OmplApi.h"

#include <array>
#include <string>

#include <ompl/base/PlannerStatus.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>

namespace {

namespace ob = ompl::base;

void* reedsSheppNew(double radius) { return new ob::ReedsSheppStateSpace(radius); }

void reedsSheppDelete(void* space) { delete static_cast<ob::ReedsSheppStateSpace*>(space); }

void reedsSheppPath(const void* opaque, const double from[3], const double to[3], int types[5],
                    double lengths[5], double* total) {
  const auto& space = *static_cast<const ob::ReedsSheppStateSpace*>(opaque);
  // allocState per call keeps this thread-safe: the space itself is only read.
  ob::State* a = space.allocState();
  ob::State* b = space.allocState();
  a->as<ob::SE2StateSpace::StateType>()->setXY(from[0], from[1]);
  a->as<ob::SE2StateSpace::StateType>()->setYaw(from[2]);
  b->as<ob::SE2StateSpace::StateType>()->setXY(to[0], to[1]);
  b->as<ob::SE2StateSpace::StateType>()->setYaw(to[2]);
  const ob::ReedsSheppStateSpace::ReedsSheppPath path = space.reedsShepp(a, b);
  space.freeState(a);
  space.freeState(b);
  for (int i = 0; i < 5; ++i) {
    types[i] = path.type_[i];
    lengths[i] = path.length_[i];
  }
  *total = path.length();
}

const char* statusName(int code) {
  static const std::array<std::string, ob::PlannerStatus::TYPE_COUNT> names = [] {
    std::array<std::string, ob::PlannerStatus::TYPE_COUNT> out;
    for (int i = 0; i < ob::PlannerStatus::TYPE_COUNT; ++i) {
      out[i] = ob::PlannerStatus(static_cast<ob::PlannerStatus::StatusType>(i)).asString();
    }
    return out;
  }();
  if (code < 0 || code >= ob::PlannerStatus::TYPE_COUNT) return nullptr;
  return names[code].c_str();
}

}  // namespace

extern "C" __attribute__((visibility("default"))) const ParksimOmplApi* parksim_ompl_api_v1() {
  static const ParksimOmplApi api{reedsSheppNew, reedsSheppDelete, reedsSheppPath, statusName};
  return &api;
}
