#pragma once
// Angle helpers. parksim works in radians everywhere; degrees appear only in files and on screen.

#include <cmath>
#include <numbers>

namespace parksim {

inline constexpr double kPi = std::numbers::pi;

constexpr double degToRad(double deg) { return deg * kPi / 180.0; }
constexpr double radToDeg(double rad) { return rad * 180.0 / kPi; }

/// Wraps an angle to [-pi, pi).
inline double wrapAngle(double a) {
  double w = std::fmod(a + kPi, 2.0 * kPi);
  if (w < 0.0) w += 2.0 * kPi;
  return w - kPi;
}

/// Signed smallest difference a - b, in [-pi, pi).
inline double angleDiff(double a, double b) { return wrapAngle(a - b); }

}  // namespace parksim
