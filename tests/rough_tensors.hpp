// Test helper: 3 × 3 tensors in components for the rough trial families written out by hand (the chiral and full-space
// tests compare the engine's elements with Monte Carlo averages of these): symmetric outer products, traceless parts in
// d dimensions, scaling and the double contraction A:B.
#pragma once

#include <array>

#include "rough_monte_carlo.hpp"

namespace gkt::test {

using M3 = std::array<Vec3, 3>;

/// Returns s (ab)_sym = (s/2)(ab + ba).
inline M3 sym(const Vec3& a, const Vec3& b, double s = 1) {
  M3 m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = 0.5 * s * (a[i] * b[j] + a[j] * b[i]);
  return m;
}
/// Returns m − (tr m / d) 1 on the first d axes (disks: the plane).
inline M3 traceless(M3 m, int d) {
  const double t = m[0][0] + m[1][1] + m[2][2];
  for (int i = 0; i < d; ++i) m[i][i] -= t / d;
  return m;
}
/// Returns s m.
inline M3 scaled(M3 m, double s) {
  for (auto& row : m)
    for (double& e : row) e *= s;
  return m;
}
/// Returns s v.
inline Vec3 scaled(Vec3 v, double s) {
  for (double& e : v) e *= s;
  return v;
}
/// Returns A:B = Σ_ij A_ij B_ij.
inline double contract(const M3& a, const M3& b) {
  double s = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s += a[i][j] * b[i][j];
  return s;
}

}  // namespace gkt::test
