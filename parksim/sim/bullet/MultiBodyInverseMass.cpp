#include "parksim/sim/bullet/MultiBodyInverseMass.h"

#include <algorithm>
#include <cmath>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>

namespace parksim {

namespace {

// The world-to-base rotation, in double.
void worldToBase(const btMultiBody& body, double r[3][3]) {
  const btMatrix3x3 m(body.getWorldToBaseRot());
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) r[i][j] = double(m[i][j]);
  }
}

// out = T v (T = diag(R, R, 1)) for a vector of n entries.
void turn(const double r[3][3], const double* v, double* out, int n) {
  for (int block = 0; block < 6; block += 3) {
    for (int i = 0; i < 3; ++i) {
      double sum = 0.0;
      for (int j = 0; j < 3; ++j) sum += r[i][j] * v[block + j];
      out[block + i] = sum;
    }
  }
  for (int i = 6; i < n; ++i) out[i] = v[i];
}

// response = T^T L T jac, L column-major (`finite`: every entry is finite). kN: the size known
// at compile time (unrolled loops, arrays on the stack), or 0 for `size` with 2 `size` doubles
// of `scratch`.
template <int kN>
void product(int size, const double* local, bool finite, const double (&r)[3][3], double* scratch,
             const btScalar* jac, btScalar* response) {
  const int n = kN > 0 ? kN : size;
  // T J: the base's angular and linear parts turned into the base frame.
  double fixed[2 * (kN > 0 ? kN : 1)];
  double* in = kN > 0 ? fixed : scratch;
  double* out = in + n;
  for (int b = 0; b < 6; b += 3) {
    const double x = double(jac[b]), y = double(jac[b + 1]), z = double(jac[b + 2]);
    for (int i = 0; i < 3; ++i) in[b + i] = r[i][0] * x + r[i][1] * y + r[i][2] * z;
  }
  for (int i = 6; i < n; ++i) in[i] = double(jac[i]);
  // L is kept column by column: out += L[:, j] in[j] for each j runs over contiguous entries,
  // so the compiler can do it two at a time without reordering any sum. A column whose in[j]
  // is zero is skipped when L is finite: its products are zeros, and adding a zero leaves every
  // sum as it was (a sum that starts at +0 never becomes -0 under round-to-nearest, and
  // +0 + -0 is +0). Contact rows have one or two such entries (the other joints), motor rows
  // all but one.
  const double* column = local;
  for (int i = 0; i < n; ++i) out[i] = 0.0;
  for (int j = 0; j < n; ++j, column += n) {
    const double x = in[j];
    if (x == 0.0 && finite) continue;
    for (int i = 0; i < n; ++i) out[i] += column[i] * x;
  }
  // T^T: back to the world frame.
  for (int b = 0; b < 6; b += 3) {
    for (int i = 0; i < 3; ++i) {
      response[b + i] = btScalar(r[0][i] * out[b] + r[1][i] * out[b + 1] + r[2][i] * out[b + 2]);
    }
  }
  for (int i = 6; i < n; ++i) response[i] = btScalar(out[i]);
}

}  // namespace

void MultiBodyInverseMass::add(const btMultiBody* body) {
  if (covers(body)) return;
  Body entry;
  entry.body = body;
  entry.n = body->getNumDofs() + 6;
  bodies_.push_back(std::move(entry));
  last_ = nullptr;  // the vector may have moved
}

bool MultiBodyInverseMass::covers(const btMultiBody* body) const {
  for (const Body& b : bodies_) {
    if (b.body == body) return true;
  }
  return false;
}

MultiBodyInverseMass::Body* MultiBodyInverseMass::find(const btMultiBody* body) {
  for (Body& b : bodies_) {
    if (b.body == body) return &b;
  }
  return nullptr;
}

// L = T M^-1 T^T, with M^-1's columns Bullet's responses to unit impulses now.
void MultiBodyInverseMass::measure(btMultiBody& body, Body& entry, btMultiBodyJacobianData& data) {
  const int n = entry.n;
  std::vector<btScalar> unit(static_cast<std::size_t>(n), btScalar(0));
  std::vector<btScalar> response(static_cast<std::size_t>(n));
  std::vector<double> world(static_cast<std::size_t>(n * n));  // M^-1, row-major
  for (int k = 0; k < n; ++k) {
    unit[static_cast<std::size_t>(k)] = 1;
    body.calcAccelerationDeltasMultiDof(unit.data(), response.data(), data.scratch_r,
                                        data.scratch_v);
    unit[static_cast<std::size_t>(k)] = 0;
    for (int i = 0; i < n; ++i) {
      world[static_cast<std::size_t>(i * n + k)] = double(response[static_cast<std::size_t>(i)]);
    }
  }
  double r[3][3];
  worldToBase(body, r);
  // Columns first (M^-1 T^T: each row of M^-1 turned), then rows (T applied to each column).
  std::vector<double> row(static_cast<std::size_t>(n));
  std::vector<double> turned(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j)
      row[static_cast<std::size_t>(j)] = world[static_cast<std::size_t>(i * n + j)];
    turn(r, row.data(), turned.data(), n);
    for (int j = 0; j < n; ++j)
      world[static_cast<std::size_t>(i * n + j)] = turned[static_cast<std::size_t>(j)];
  }
  entry.local.assign(static_cast<std::size_t>(n * n), 0.0);  // column-major
  std::vector<double> column(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i)
      column[static_cast<std::size_t>(i)] = world[static_cast<std::size_t>(i * n + j)];
    turn(r, column.data(), turned.data(), n);
    for (int i = 0; i < n; ++i)
      entry.local[static_cast<std::size_t>(j * n + i)] = turned[static_cast<std::size_t>(i)];
  }
  entry.finite = std::all_of(entry.local.begin(), entry.local.end(),
                             [](double v) { return std::isfinite(v); });
}

void MultiBodyInverseMass::respond(btMultiBody& body, int index, btMultiBodyJacobianData& data) {
  Body* entry = last_ != nullptr && last_->body == &body ? last_ : find(&body);
  last_ = entry;
  if (entry->local.empty()) measure(body, *entry, data);
  const btQuaternion& q = body.getWorldToBaseRot();
  const double quaternion[4] = {double(q.x()), double(q.y()), double(q.z()), double(q.w())};
  if (quaternion[0] != entry->quaternion[0] || quaternion[1] != entry->quaternion[1] ||
      quaternion[2] != entry->quaternion[2] || quaternion[3] != entry->quaternion[3]) {
    for (int k = 0; k < 4; ++k) entry->quaternion[k] = quaternion[k];
    worldToBase(body, entry->rotation);
  }
  const btScalar* jac = &data.m_jacobians[index];
  btScalar* response = &data.m_deltaVelocitiesUnitImpulse[index];
  if (entry->n == kFixedSize) {
    product<kFixedSize>(entry->n, entry->local.data(), entry->finite, entry->rotation, nullptr, jac,
                        response);
  } else {
    scratch_.resize(static_cast<std::size_t>(2 * entry->n));
    product<0>(entry->n, entry->local.data(), entry->finite, entry->rotation, scratch_.data(), jac,
               response);
  }
}

}  // namespace parksim
