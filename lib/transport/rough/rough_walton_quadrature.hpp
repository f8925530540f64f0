// Internal: the conditioned Gaussian of the Walton gas's pre-collisional velocities and the composite
// Gauss–Legendre rule over (u, |g_c,t|) (docs/theory.md §19.10, (19.23)), shared by rough_walton.cpp and
// rough_walton_cumulants.cpp and rough_walton_sonine.cpp, and the range check of the Walton parameters.
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace gkt::detail {

/// Throws std::invalid_argument naming the field unless d ∈ {2, 3}, α ∈ (0, 1], β0 ∈ [−1, 1], κ ∈ (0, 1], μ_f ≥ 0.
inline void check_walton_parameters(int d, double alpha, double beta0, double kappa, double friction) {
  if (d != 2 && d != 3) throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(d));
  if (!(alpha > 0 && alpha <= 1)) throw std::invalid_argument("alpha: must be a number in (0, 1]");
  if (!(beta0 >= -1 && beta0 <= 1)) throw std::invalid_argument("beta0: must be a number in [-1, 1]");
  if (!(kappa > 0 && kappa <= 1)) throw std::invalid_argument("moment_of_inertia: must be a number in (0, 1]");
  if (!(friction >= 0)) throw std::invalid_argument("friction: must be a number >= 0");
}

/// The Gaussian of the pre-collisional velocities X = (v1, v2, w1, w2) (velocities in units of
/// √(2T_t/m); variance 1/2 per translational and τ/2 per spin component) conditioned on the normal
/// relative velocity u and the tangential relative contact velocity g_c,t = (G, 0) (σ̂ = e0):
/// mean K y (y = (u, G, 0)) and covariance C. Variables: v1 (d), v2 (d), w1, w2 (3 each; 1 each for disks).
struct ConditionedGaussian {
  int d = 3, n = 12;
  std::array<std::array<double, 3>, 12> gain{};  // rows: variables; columns: y
  std::array<std::array<double, 12>, 12> cov{};
};

inline ConditionedGaussian condition(int d, double tau) {
  const int n = d == 3 ? 12 : 6, m = d;  // v1 (d), v2 (d), w1, w2 (3 each, or 1 each for disks)
  const int w1 = 2 * d, w2 = d == 3 ? 2 * d + 3 : 2 * d + 1;
  std::vector<double> prior(static_cast<std::size_t>(n), 0.5);
  for (int i = 2 * d; i < n; ++i) prior[static_cast<std::size_t>(i)] = tau / 2;
  // Constraint rows A (m × n): u = v1_0 − v2_0; g_c,t = v1_t − v2_t + ((w1 + w2) × σ̂)_t,
  // (w × e0) = (0, w_2, −w_1) for spheres, w ŷ for disks.
  std::vector<std::vector<double>> a(static_cast<std::size_t>(m), std::vector<double>(static_cast<std::size_t>(n), 0));
  for (int r = 0; r < m; ++r) {
    a[r][static_cast<std::size_t>(r)] = 1;
    a[r][static_cast<std::size_t>(d + r)] = -1;
  }
  if (d == 3) {
    a[1][static_cast<std::size_t>(w1 + 2)] = a[1][static_cast<std::size_t>(w2 + 2)] = 1;
    a[2][static_cast<std::size_t>(w1 + 1)] = a[2][static_cast<std::size_t>(w2 + 1)] = -1;
  } else {
    a[1][static_cast<std::size_t>(w1)] = a[1][static_cast<std::size_t>(w2)] = 1;
  }
  // S = A Σ Aᵀ (m × m), inverted by Gauss–Jordan (m ≤ 3).
  std::array<std::array<double, 3>, 3> sm{}, inv{};
  for (int r = 0; r < m; ++r)
    for (int c = 0; c < m; ++c) {
      double x = 0;
      for (int i = 0; i < n; ++i) x += a[r][i] * prior[i] * a[c][i];
      sm[r][c] = x;
      inv[r][c] = r == c ? 1 : 0;
    }
  for (int c = 0; c < m; ++c) {
    const double pivot = sm[c][c];
    for (int k = 0; k < m; ++k) {
      sm[c][k] /= pivot;
      inv[c][k] /= pivot;
    }
    for (int r = 0; r < m; ++r) {
      if (r == c) continue;
      const double f = sm[r][c];
      for (int k = 0; k < m; ++k) {
        sm[r][k] -= f * sm[c][k];
        inv[r][k] -= f * inv[c][k];
      }
    }
  }
  ConditionedGaussian g;
  g.d = d;
  // K = Σ Aᵀ S⁻¹; C = Σ − K A Σ.
  g.n = n;
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < m; ++c) {
      double x = 0;
      for (int r = 0; r < m; ++r) x += prior[i] * a[r][i] * inv[r][c];
      g.gain[i][c] = x;
    }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double x = 0;
      for (int r = 0; r < m; ++r) x += g.gain[i][r] * a[r][j] * prior[j];
      g.cov[i][j] = (i == j ? prior[i] : 0) - x;
    }
  return g;
}

/// Visits the nodes of the composite 8-point Gauss–Legendre rule on [lo, hi] with `panels` panels: f(node, weight),
/// weight = w_i h/2 (h the panel width), per panel the four nodes left of its midpoint, then the four right of it.
template <class F>
void for_each_gauss_legendre_node(double lo, double hi, int panels, const F& f) {
  static constexpr std::array<double, 4> x{0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                           0.9602898564975363};
  static constexpr std::array<double, 4> w{0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                           0.1012285362903763};
  if (!(hi > lo)) return;
  const double h = (hi - lo) / panels;
  for (int p = 0; p < panels; ++p) {
    const double mid = lo + (p + 0.5) * h;
    for (std::size_t i = 0; i < 8; ++i) f(mid + (i < 4 ? -1 : 1) * x[i % 4] * h / 2, w[i % 4] * h / 2);
  }
}

/// Composite 8-point Gauss–Legendre rule on [lo, hi] with `panels` panels, for f returning N values.
template <std::size_t N, class F>
std::array<double, N> gauss_legendre(double lo, double hi, int panels, const F& f) {
  static constexpr std::array<double, 4> x{0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                           0.9602898564975363};
  static constexpr std::array<double, 4> w{0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                           0.1012285362903763};
  std::array<double, N> sum{};
  if (!(hi > lo)) return sum;
  const double h = (hi - lo) / panels;
  for (int p = 0; p < panels; ++p) {
    const double mid = lo + (p + 0.5) * h;
    for (std::size_t i = 0; i < 4; ++i) {
      const std::array<double, N> a = f(mid - x[i] * h / 2), b = f(mid + x[i] * h / 2);
      for (std::size_t k = 0; k < N; ++k) sum[k] += w[i] * (a[k] + b[k]);
    }
  }
  for (auto& v : sum) v *= h / 2;
  return sum;
}

}  // namespace gkt::detail
