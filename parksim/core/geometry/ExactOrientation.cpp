#include "parksim/core/geometry/ExactOrientation.h"

#include <array>
#include <cmath>
#include <cstddef>

namespace parksim {

namespace {

// a + b as hi + lo exactly (Knuth's two-sum).
void twoSum(double a, double b, double& hi, double& lo) {
  hi = a + b;
  const double bv = hi - a;
  lo = (a - (hi - bv)) + (b - bv);
}

// a * b as hi + lo exactly (the fused multiply-add keeps the product's low half).
void twoProduct(double a, double b, double& hi, double& lo) {
  hi = a * b;
  lo = std::fma(a, b, -hi);
}

// Adds `b` to the nonoverlapping expansion e[0..n) (smallest first), exactly; returns the new
// length (zero components are dropped).
std::size_t growExpansion(double* e, std::size_t n, double b) {
  double q = b;
  std::size_t out = 0;
  for (std::size_t i = 0; i < n; ++i) {
    double hi = 0.0;
    double lo = 0.0;
    twoSum(q, e[i], hi, lo);
    if (lo != 0.0) e[out++] = lo;
    q = hi;
  }
  if (q != 0.0) e[out++] = q;
  return out;
}

}  // namespace

int orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const double left = (b.x() - a.x()) * (c.y() - a.y());
  const double right = (b.y() - a.y()) * (c.x() - a.x());
  const double det = left - right;
  // Shewchuk's error bound of the plain evaluation: outside it the sign is certain.
  const double bound = 3.3306690738754716e-16 * (std::abs(left) + std::abs(right));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  // Exact: each difference is a two-term expansion, so the determinant is a sum of 16
  // products of two doubles, each split exactly into two, accumulated without rounding.
  double bx_hi = 0.0, bx_lo = 0.0, by_hi = 0.0, by_lo = 0.0;
  double cx_hi = 0.0, cx_lo = 0.0, cy_hi = 0.0, cy_lo = 0.0;
  twoSum(b.x(), -a.x(), bx_hi, bx_lo);
  twoSum(b.y(), -a.y(), by_hi, by_lo);
  twoSum(c.x(), -a.x(), cx_hi, cx_lo);
  twoSum(c.y(), -a.y(), cy_hi, cy_lo);
  const std::array<double, 2> bx{bx_hi, bx_lo};
  const std::array<double, 2> by{by_hi, by_lo};
  const std::array<double, 2> cx{cx_hi, cx_lo};
  const std::array<double, 2> cy{cy_hi, cy_lo};
  std::array<double, 40> e{};
  std::size_t n = 0;
  for (const double u : bx) {
    for (const double v : cy) {
      double hi = 0.0;
      double lo = 0.0;
      twoProduct(u, v, hi, lo);
      n = growExpansion(e.data(), n, lo);
      n = growExpansion(e.data(), n, hi);
    }
  }
  for (const double u : by) {
    for (const double v : cx) {
      double hi = 0.0;
      double lo = 0.0;
      twoProduct(u, v, hi, lo);
      n = growExpansion(e.data(), n, -lo);
      n = growExpansion(e.data(), n, -hi);
    }
  }
  // The largest component of a nonoverlapping expansion carries its sign.
  if (n == 0) return 0;
  return e[n - 1] > 0.0 ? 1 : -1;
}

}  // namespace parksim
