// GDH's published first Sonine approximation of a dilute or dense (Enskog) mixture in closed form
// (docs/theory.md §17.10). Units of theory.md (16.11): n = m̄ = σ̄ = 1, velocities in √(2T/m̄) (T = 1/2),
// θ_k = m_k/γ_k; dense, lengths along a gradient in mean free paths (theory.md (18.3)).
#include "gkt/transport/mixture/published_first_sonine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "gkt/transport/common/pair_correlation.hpp"
#include "gkt/transport/common/reference_gas.hpp"
#include "transport/mixture/dense_cell_closures.hpp"

namespace gkt {

namespace {

constexpr int kMax = 4;
using Vec = std::array<double, kMax>;
using Mat = std::array<double, kMax * kMax>;  // row i, column k at i·4 + k

/// Solves m x = b (s ≤ 4 unknowns) by Gaussian elimination with partial pivoting; m and b are consumed.
template <int S>
Vec solve(Mat m, Vec b) {
  for (int c = 0; c < S; ++c) {
    int pivot = c;
    for (int r = c + 1; r < S; ++r)
      if (std::abs(m[r * kMax + c]) > std::abs(m[pivot * kMax + c])) pivot = r;
    if (pivot != c) {
      for (int k = 0; k < S; ++k) std::swap(m[c * kMax + k], m[pivot * kMax + k]);
      std::swap(b[c], b[pivot]);
    }
    for (int r = c + 1; r < S; ++r) {
      const double f = m[r * kMax + c] / m[c * kMax + c];
      for (int k = c; k < S; ++k) m[r * kMax + k] -= f * m[c * kMax + k];
      b[r] -= f * b[c];
    }
  }
  Vec x{};
  for (int r = S - 1; r >= 0; --r) {
    double v = b[r];
    for (int k = r + 1; k < S; ++k) v -= m[r * kMax + k] * x[k];
    x[r] = v / m[r * kMax + r];
  }
  return x;
}

/// LU factors (partial pivoting) of the s × s block of one matrix, reused for every right-hand side of a mode.
template <int S>
class Lu {
 public:
  explicit Lu(const Mat& m) {
    for (int i = 0; i < S; ++i)
      for (int k = 0; k < S; ++k) lu_[i * S + k] = m[i * kMax + k];
    for (int c = 0; c < S; ++c) {
      int pivot = c;
      for (int r = c + 1; r < S; ++r)
        if (std::abs(lu_[r * S + c]) > std::abs(lu_[pivot * S + c])) pivot = r;
      pivot_[c] = pivot;
      // Columns ≥ c only: the multipliers of earlier columns stay with the rows they were computed
      // for, so solve() can replay swap and elimination column by column (swapping them too would
      // need every swap applied to b first).
      if (pivot != c)
        for (int k = c; k < S; ++k) std::swap(lu_[c * S + k], lu_[pivot * S + k]);
      for (int r = c + 1; r < S; ++r) {
        const double f = lu_[r * S + c] /= lu_[c * S + c];
        for (int k = c + 1; k < S; ++k) lu_[r * S + k] -= f * lu_[c * S + k];
      }
    }
  }
  /// Returns x with m x = b.
  [[nodiscard]] Vec solve(Vec b) const {
    for (int c = 0; c < S; ++c) {
      std::swap(b[c], b[pivot_[c]]);
      for (int r = c + 1; r < S; ++r) b[r] -= lu_[r * S + c] * b[c];
    }
    Vec x{};
    for (int r = S - 1; r >= 0; --r) {
      double v = b[r];
      for (int k = r + 1; k < S; ++k) v -= lu_[r * S + k] * x[k];
      x[r] = v / lu_[r * S + r];
    }
    return x;
  }

 private:
  std::array<double, S * S> lu_;  // the s × s block alone (row i, column k at i·s + k): a 4 × 4 copy per
                                  // factorisation cost a tenth of the binary’s modes
  std::array<int, S> pivot_{};
};

/// The state in the units of (16.11) and its Maxwellian HCS. The arrays are not zeroed (a call writes
/// the entries of its s species and pairs before reading them; zeroing them all cost 5 % of a binary call).
struct Reduced {
  int d = 3, s = 2, major = 0;  // major: the first most abundant species (its S_0 row carries momentum, (17.7))
  Vec m, x, gamma, theta, root_theta, inverse_m;
  // After the HCS, shared by every pair function: 1/θ_k, 1/√θ_k; per pair √(θ_i + θ_j), its inverse and
  // w_ij = √(1/θ_i + 1/θ_j) = √(θ_i + θ_j)/(√θ_i √θ_j) (one square root and one division per unordered pair).
  Vec inverse_theta, inverse_root_theta;
  Mat root_sum, inverse_root_sum, speed;
  Mat area, alpha, mu_a;  // (σ_ij/σ̄)^{d−1} χ_ij (χ = 1 dilute), α_ij and μ_ji(1 + α_ij)
  Mat jacobian;           // ∂ζ_i/∂γ_k at the HCS
  double c_d = 0, zeta = 0;
  ReferenceGas ref{};
  // Dense gas (theory.md §18): σ_ij/σ̄, the transfer length L_ij = nσ̄^d σ_ij/σ̄ (18.3), χ_ij and the closures
  // (filled in place, only when dense).
  bool dense = false;
  Mat sigma, length;
  std::optional<detail::DenseCellClosures> closures;
};

/// ζ_i = −(2c_d/d) Σ_l x_l σ_il^{d−1} w_il E_il (16.11) and its Jacobian ∂ζ_i/∂γ_k at i·4 + k, with the pair
/// energy change (16.3) E_il = −2μ_li(1+α)[1 − ½μ_li(1+α)(1 + θ_i/θ_l)], w_il = √(1/θ_i + 1/θ_l), 1/θ_k = γ_k/m_k.
template <int S>
void partial_cooling(const Reduced& r, const Vec& gamma, Vec& zeta, Mat& jacobian) {
  const double f = -2 * r.c_d / r.d;
  Vec over{}, theta{}, inverse_gamma{};  // 1/θ_k = γ_k/m_k, θ_k, 1/γ_k
  for (int k = 0; k < S; ++k) {
    over[k] = gamma[k] * r.inverse_m[k];
    theta[k] = 1 / over[k];
    inverse_gamma[k] = r.inverse_m[k] * theta[k];
  }
  Mat w{}, inverse_w{};  // w_il = w_li, one square root and one division per unordered pair
  for (int i = 0; i < S; ++i)
    for (int l = i; l < S; ++l) {
      w[i * kMax + l] = w[l * kMax + i] = std::sqrt(over[i] + over[l]);
      inverse_w[i * kMax + l] = inverse_w[l * kMax + i] = 1 / w[i * kMax + l];
    }
  for (int i = 0; i < S; ++i) {  // only the s × s block is used
    zeta[i] = 0;
    for (int k = 0; k < S; ++k) jacobian[i * kMax + k] = 0;
  }
  for (int i = 0; i < S; ++i)
    for (int l = 0; l < S; ++l) {
      const double ma = r.mu_a[i * kMax + l], ratio = over[l] * theta[i];  // θ_i/θ_l
      const double e = -2 * ma * (1 - 0.5 * ma * (1 + ratio)), wil = w[i * kMax + l];
      const double k = f * r.x[l] * r.area[i * kMax + l];
      zeta[i] += k * wil * e;
      // ∂w/∂γ_i = 1/(2m_i w), ∂E/∂(θ_i/θ_l) = μ_li²(1+α)², ∂(θ_i/θ_l)/∂γ_i = −(θ_i/θ_l)/γ_i; the same
      // with l (for l = i they add).
      const double half_e = 0.5 * e * inverse_w[i * kMax + l], de = wil * ma * ma * ratio;
      jacobian[i * kMax + i] += k * (half_e * r.inverse_m[i] - de * inverse_gamma[i]);
      jacobian[i * kMax + l] += k * (half_e * r.inverse_m[l] + de * inverse_gamma[l]);
    }
}

/// The binary's Maxwellian HCS, returns γ. ζ_i(λγ) = √λ ζ_i(γ) ((16.11): w_il ∝ √γ, E_il (16.3) depends on
/// θ_1/θ_2 only), so ζ_1 = ζ_2 fixes τ = γ_1/γ_2 alone, then Σ x_i γ_i = 1. In u = ln τ the scalar
/// v(u) = (ζ_1 − ζ_2)/(−2c_d/d) at γ = (τ, 1) falls from +∞ to −∞, so Newton from equipartition is kept
/// inside the bracket of the signs seen (bisection in ln τ where it leaves it); each step costs two square
/// roots and one division, against the s-species Jacobian of partial_cooling.
Vec binary_cooling_state(const Reduced& r) {
  const double q = r.m[0] * r.inverse_m[1];  // θ_1/θ_2 = q/τ (θ_k = m_k/γ_k)
  const double a12 = r.mu_a[1], a21 = r.mu_a[kMax], a11 = r.mu_a[0], a22 = r.mu_a[kMax + 1];
  // x_l σ_il^{d−1} χ_il of the cross terms; the self terms x_i σ_ii^{d−1} χ_ii w_ii E_ii with E_ii = −2a_ii(1 − a_ii)
  // and w_11 = √τ √(2/m_1), w_22 = √(2/m_2) (16.3)
  const double c12 = r.x[1] * r.area[1], c21 = r.x[0] * r.area[kMax];
  const double c11 = r.x[0] * r.area[0] * -2 * a11 * (1 - a11) * std::sqrt(2 * r.inverse_m[0]);
  const double c22 = r.x[1] * r.area[kMax + 1] * -2 * a22 * (1 - a22) * std::sqrt(2 * r.inverse_m[1]);
  double tau = 1, lo = 0, hi = std::numeric_limits<double>::infinity();  // bracket in τ
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double root = std::sqrt(tau), w12 = std::sqrt(tau * r.inverse_m[0] + r.inverse_m[1]);
    const double rho = q / tau, over_rho = tau / q;  // θ_1/θ_2, θ_2/θ_1
    const double e12 = -2 * a12 * (1 - 0.5 * a12 * (1 + rho)), e21 = -2 * a21 * (1 - 0.5 * a21 * (1 + over_rho));
    const double v = c11 * root + w12 * (c12 * e12 - c21 * e21) - c22;
    // dv/du: dw_11/du = w_11/2, dw_12/du = τ/(2m_1 w_12), dE_12/du = −a_12² θ_1/θ_2, dE_21/du = a_21² θ_2/θ_1
    const double slope = 0.5 * c11 * root + 0.5 * tau * r.inverse_m[0] / w12 * (c12 * e12 - c21 * e21) -
                         w12 * (c12 * a12 * a12 * rho + c21 * a21 * a21 * over_rho);
    if (v > 0)
      lo = tau;  // v falls with τ: the root lies above
    else
      hi = tau;
    const double du = std::clamp(-v / slope, -5.0, 5.0);
    // τ e^{δ}; near the root 1 + δ + δ²/2 suffices (u → τ only has to be right to first order)
    double next = tau * (std::abs(du) < 1e-2 ? 1 + du * (1 + 0.5 * du) : std::exp(du));
    // Quadratic convergence: a Newton step below 1e-8 leaves an error of order 1e-16 in u (taken even where
    // round-off puts it on an end of the bracket).
    if (std::abs(du) < 1e-8) {
      const double per_sum = 1 / (r.x[0] * next + r.x[1]);
      Vec gamma{};
      gamma[0] = next * per_sum;
      gamma[1] = per_sum;
      return gamma;
    }
    if (!(std::isfinite(next) && next > lo &&
          next < hi))  // bisection in ln τ, or a factor e out of a one-sided bracket
      next = lo > 0 && std::isfinite(hi) ? std::sqrt(lo * hi) : (lo > 0 ? lo * std::numbers::e : hi / std::numbers::e);
    tau = next;
  }
  throw std::invalid_argument("temperature_ratio: the Maxwellian HCS did not converge (binary ratio)");
}

/// The Maxwellian HCS (theory.md §16.2): ζ_i equal and Σ x_i γ_i = 1, by damped Newton from equipartition
/// (the binary by its scalar equation for γ_1/γ_2).
template <int S>
void cooling_state(Reduced& r) {
  Vec gamma{}, zeta{};
  Mat jac{};
  if constexpr (S == 2) {
    gamma = binary_cooling_state(r);
    partial_cooling<S>(r, gamma, zeta, jac);
  } else {
    Vec scale{};
    for (int i = 0; i < S; ++i) gamma[i] = 1;
    // Each equal-rate row is divided by the size of its gain and loss terms at equipartition,
    // (2c_d/d) Σ_l x_l σ_il^{d−1} w_il 2μ_li(1+α_il) (> 0 also where ζ = 0, α = 1), held fixed.
    const int last = S - 1;
    for (int i = 0; i < S; ++i)
      for (int l = 0; l < S; ++l)  // w_il = √(1/m_i + 1/m_l) at γ = 1
        scale[i] += 4 * r.c_d / r.d * r.x[l] * r.area[i * kMax + l] * std::sqrt(r.inverse_m[i] + r.inverse_m[l]) *
                    r.mu_a[i * kMax + l];
    for (int i = 0; i < last; ++i) scale[i] = 1 / (scale[i] + scale[last]);  // held as its reciprocal
    auto residual = [&](const Vec& g, Vec& res, Mat& j) {
      partial_cooling<S>(r, g, zeta, j);
      double norm = 0, sum = 0;
      for (int i = 0; i < last; ++i) res[i] = (zeta[i] - zeta[last]) * scale[i];
      for (int i = 0; i < S; ++i) sum += r.x[i] * g[i];
      res[last] = sum - 1;
      for (int i = 0; i < S; ++i) norm += res[i] * res[i];
      return norm;
    };
    Vec res{}, trial_res{};
    Mat m{}, trial_jac{};  // Newton matrix and the trial point's Jacobian, reused by every iteration
    double norm = residual(gamma, res, jac);
    // Quadratic convergence: once |res| < 1e-11 the next full step reaches round-off; no search beyond it.
    for (int iteration = 0; iteration < 200 && norm > 1e-30; ++iteration) {
      const bool last_step = norm < 1e-22;
      // Newton in ln γ keeps every γ > 0: Σ_k J_ik γ_k du_k = −res_i.
      for (int i = 0; i < S; ++i)
        for (int k = 0; k < S; ++k)
          m[i * kMax + k] = gamma[k] * (i < last ? (jac[i * kMax + k] - jac[last * kMax + k]) * scale[i] : r.x[k]);
      Vec rhs{};
      for (int i = 0; i < S; ++i) rhs[i] = -res[i];
      const Vec du = solve<S>(m, rhs);
      double step = 1;
      for (int halving = 0; halving < (last_step ? 1 : 40); ++halving, step /= 2) {
        Vec trial = gamma;
        // γ_k e^{δ}; near the root 1 + δ + δ²/2 suffices (the map u → γ only has to be right to first order).
        for (int k = 0; k < S; ++k) {
          const double delta = std::clamp(step * du[k], -5.0, 5.0);
          trial[k] = gamma[k] * (std::abs(delta) < 1e-2 ? 1 + delta * (1 + 0.5 * delta) : std::exp(delta));
        }
        const double trial_norm = residual(trial, trial_res, trial_jac);
        if (std::isfinite(trial_norm) && trial_norm < norm) {
          gamma = trial, res = trial_res, jac = trial_jac, norm = trial_norm;
          break;
        }
      }
      if (step < 1e-11 || last_step) break;
    }
    if (!(norm < 1e-22))
      throw std::invalid_argument(std::string("temperature_ratio: the Maxwellian HCS did not converge (residual ")
                                      .append(std::to_string(std::sqrt(norm)))
                                      .append(")"));
  }
  r.jacobian = jac;  // zeta and jac belong to the accepted γ
  r.gamma = gamma;
  for (int k = 0; k < S; ++k) {
    r.theta[k] = r.m[k] / gamma[k];
    r.root_theta[k] = std::sqrt(r.theta[k]);
    r.inverse_root_theta[k] = 1 / r.root_theta[k];
    r.inverse_theta[k] = gamma[k] * r.inverse_m[k];
  }
  for (int i = 0; i < S; ++i)
    for (int j = i; j < S; ++j) {
      const double root = std::sqrt(r.theta[i] + r.theta[j]), inverse = 1 / root;
      r.root_sum[i * kMax + j] = r.root_sum[j * kMax + i] = root;
      r.inverse_root_sum[i * kMax + j] = r.inverse_root_sum[j * kMax + i] = inverse;
      r.speed[i * kMax + j] = r.speed[j * kMax + i] = root * r.inverse_root_theta[i] * r.inverse_root_theta[j];
    }
  r.zeta = zeta[S - 1];
}

/// n ∂ln γ_i/∂n_j at i·4 + j and ∂ζ/∂n_j (theory.md §16.6): differentiate ζ_i − ζ_s = 0 and Σ_k n_k γ_k = n.
struct Sensitivity {
  Mat log_gamma{};
  Vec zeta{};
};
template <int S>
Sensitivity cooling_sensitivity(const Reduced& r) {
  const Mat& jac = r.jacobian;
  const int last = S - 1;
  Mat m{};
  for (int i = 0; i < S; ++i)
    for (int k = 0; k < S; ++k) m[i * kMax + k] = i < last ? jac[i * kMax + k] - jac[last * kMax + k] : r.x[k];
  const Lu<S> lu(m);  // one factorisation for the s right-hand sides
  Sensitivity out;
  const double f = -2 * r.c_d / r.d;
  // w_il E_il at the HCS, the pair energy change (16.3) E_il = −2μ_li(1+α)[1 − ½μ_li(1+α)(1 + θ_i/θ_l)]
  Mat rate{};
  for (int i = 0; i < S; ++i)
    for (int l = 0; l < S; ++l) {
      const double ma = r.mu_a[i * kMax + l];
      rate[i * kMax + l] = r.speed[i * kMax + l] * -2 * ma * (1 - 0.5 * ma * (1 + r.theta[i] * r.inverse_theta[l]));
    }
  for (int j = 0; j < S; ++j) {
    Vec explicit_part{}, rhs{};  // ∂ζ_i/∂n_j at fixed γ
    for (int i = 0; i < S; ++i) {
      explicit_part[i] = f * r.area[i * kMax + j] * rate[i * kMax + j];
      if (r.dense)  // χ_il moves with n_j (18.1)
        for (int l = 0; l < S; ++l)
          explicit_part[i] += f * r.x[l] * r.area[i * kMax + l] *
                              r.closures->log_chi_derivative[(i * kMax + l) * kMax + j] * rate[i * kMax + l];
    }
    for (int i = 0; i < last; ++i) rhs[i] = -(explicit_part[i] - explicit_part[last]);
    rhs[last] = 1 - r.gamma[j];
    const Vec dgamma = lu.solve(rhs);
    double dz = explicit_part[last];
    for (int k = 0; k < S; ++k) {
      out.log_gamma[k * kMax + j] = dgamma[k] / r.gamma[k];
      dz += jac[last * kMax + k] * dgamma[k];
    }
    out.zeta[j] = dz;
  }
  return out;
}

/// The first-Sonine collision integrals of the pair (i, j) with Maxwellians at θ_i, θ_j (derived in
/// theory.md §17.10, (17.16)–(17.17)), each divided by R = c_d w_ij μ_ji (1 + α_ij):
/// self_pq = ∫∫ f̂_i f̂_j c_1S_q(c_1²)·Δ[c_1S_p(c_1²)], other_pq the same with c_2S_q(c_2²) (c_k = √θ_k v_k),
/// Δψ = ∫dσ̂ Θ(σ̂·g)(σ̂·g)[ψ(v_1') − ψ(v_1)]; shear_* likewise with Y_2(c) = cc − c²I/d.
struct PairIntegrals {
  double rate;  // R (without σ_ij^{d−1})
  double self00, other00, self10, other10, self11, other11, shear_self, shear_other;
};
template <int D>
PairIntegrals pair_integrals(const Reduced& r, int i, int j) {
  // t = θ_i/θ_j, k = μ_ji(1 + α_ij)(1 + t); with u = 1 + t the integrals are polynomials in k and t over u, u².
  // 1/u = θ_j/(θ_i + θ_j): no division per pair.
  const int P = i * kMax + j;
  constexpr double d = D;  // the d-dependent coefficients fold at compile time
  const double t = r.theta[i] * r.inverse_theta[j], ma = r.mu_a[P];
  const double u = 1 + t, v = r.theta[j] * r.inverse_root_sum[P] * r.inverse_root_sum[P], k = ma * u,
               st = r.root_theta[i] * r.inverse_root_theta[j];
  PairIntegrals p{};
  p.rate = r.c_d * r.speed[P] * ma;
  p.self00 = -1;                                                                                  // (17.16)
  p.other00 = st;                                                                                 // (17.16)
  p.self10 = (2 * k * k - 0.5 * k * ((d + 2) * t + d + 11) + (d + 2) * t + (2 * d + 7) / 2) * v;  // (17.16)
  p.other10 = st * (-2 * k * k + 4.5 * k - 1.5) * v;                                              // (17.16)
  p.self11 = (-3 * k * k + 0.75 * k * ((d + 8) * t + d + 11) - 1.5 * (d + 2) * t * t - (7 * d + 20) / 2 * t -
              (8 * d + 25) / 4) *
             v * v;                                            // (17.16)
  p.other11 = 3 * t * st * (k * k - 0.75 * k - 0.25) * v * v;  // (17.16)
  if constexpr (D == 3) {                                      // (17.17)
    p.shear_self = (k - 10 * t / 3 - 4) * v;
    p.shear_other = t * (k - 2.0 / 3) * v;
  } else {
    p.shear_self = (0.75 * k - 2 * t - 2.5) * v;
    p.shear_other = t * (0.75 * k - 0.5) * v;
  }
  return p;
}

/// The linearised operator (17.4) of the published truncation: the S_0–S_0 block l00 (mass flux), the
/// S_1–S_0 block l10 that feeds the mass flux into the heat flux, the S_1–S_1 block l11, and the shear block.
struct Operator {
  Mat l00, l10, l11, shear;  // only the s × s blocks are written and read
};
template <int S>
Operator first_sonine_operator(const Reduced& r) {
  Operator op;
  for (int i = 0; i < S; ++i)
    for (int j = 0; j < S; ++j)
      op.l00[i * kMax + j] = op.l10[i * kMax + j] = op.l11[i * kMax + j] = op.shear[i * kMax + j] = 0;
  for (int i = 0; i < S; ++i)
    for (int j = 0; j < S; ++j) {
      const PairIntegrals p = r.d == 3 ? pair_integrals<3>(r, i, j) : pair_integrals<2>(r, i, j);
      const double rate = r.area[i * kMax + j] * p.rate;
      const double self = rate * r.x[j], other = rate * r.x[i];
      // −Σ_j [x_j ∫ψ_i J_ij[X_i, f_j] + x_i ∫ψ_i J_ij[f_i, X_j]] (17.4)
      op.l00[i * kMax + i] -= self * p.self00;
      op.l00[i * kMax + j] -= other * p.other00;
      op.l10[i * kMax + i] -= self * p.self10;
      op.l10[i * kMax + j] -= other * p.other10;
      op.l11[i * kMax + i] -= self * p.self11;
      op.l11[i * kMax + j] -= other * p.other11;
      op.shear[i * kMax + i] -= self * p.shear_self;
      op.shear[i * kMax + j] -= other * p.shear_other;
    }
  return op;
}

/// One vector mode (𝒜, ℬ^j or the force mode), factored once for all its sources: the mass-flux system
/// alone, then the heat flux with it fed in. shift0/shift10/shift11 are the ζ pieces of the mode
/// (ζ(D − ½M), ζD or ζ(D + M) at order 1).
struct VectorSolution {
  Vec s0{}, s1{};  // φ̃_i0, φ̃_i1
};
template <int S>
class VectorMode {
 public:
  VectorMode(const Reduced& r, const Operator& op, double shift0, double shift10, double shift11)
      : op_(op),
        major_(r.major),
        shift10_(shift10),
        mass_(mass_matrix(r, op, shift0)),
        heat_(heat_matrix(op, shift11)) {}
  /// Returns the solution for the S_0 and S_1 sources (the major species' S_0 source is replaced by 0).
  [[nodiscard]] VectorSolution solve(Vec source0, const Vec& source1) const {
    VectorSolution out;
    source0[major_] = 0;
    out.s0 = mass_.solve(source0);
    Vec c = source1;
    for (int i = 0; i < S; ++i) {
      c[i] -= shift10_ * out.s0[i];
      for (int k = 0; k < S; ++k) c[i] -= op_.l10[i * kMax + k] * out.s0[k];
    }
    out.s1 = heat_.solve(c);
    return out;
  }

 private:
  // The s × s blocks alone are read: the rest of the operator's arrays is never written.
  static Lu<S> mass_matrix(const Reduced& r, const Operator& op, double shift0) {
    Mat m;
    for (int i = 0; i < S; ++i)
      for (int k = 0; k < S; ++k) m[i * kMax + k] = op.l00[i * kMax + k] + (i == k ? shift0 : 0.0);
    // Σ_k m_k ∫V X_k = 0 replaces the most abundant species' row (17.7).
    for (int k = 0; k < S; ++k) m[r.major * kMax + k] = r.m[k] * r.inverse_root_theta[k];
    return Lu<S>(m);
  }
  static Lu<S> heat_matrix(const Operator& op, double shift11) {
    Mat h;
    for (int i = 0; i < S; ++i)
      for (int k = 0; k < S; ++k) h[i * kMax + k] = op.l11[i * kMax + k] + (i == k ? shift11 : 0.0);
    return Lu<S>(h);
  }
  const Operator& op_;
  int major_;
  double shift10_;
  Lu<S> mass_, heat_;
};

/// The order-1 collisional-transfer averages of the pair (i, j) about Maxwellians at θ_i, θ_j, in the
/// notation of PairTransferMoments (mixture_collisional_transfer.hpp): Gaussian integrals in the
/// centre-of-mass and relative velocities with σ̂ along the first axis, done once by computer algebra
/// (theory.md (17.26)–(17.27)). They depend on the pair through θ_i, θ_j, m_i and k = μ_ji(1 + α_ij) only.
struct PairTransfer {
  double density0, density1, temperature0, temperature1;  // source_density[p], source_temperature[p]
  double shear_source, shear_partner, shear_self;         // source_shear[0], shear_flux_partner[0], _self[0]
  double heat_partner0, heat_partner1, heat_self0, heat_self1;
  double energy, energy_self, energy_partner, cooling_gradient;  // shear_gradient = −4 for every pair
};
template <int D>
PairTransfer pair_transfer(const Reduced& r, int i, int j) {
  // Every division of the printed forms is by √θ_i, √θ_j, θ_i, θ_j or √(θ_i+θ_j), shared from Reduced.
  const int P = i * kMax + j;
  constexpr double d = D;  // the d-dependent coefficients fold at compile time
  const double ti = r.theta[i], tj = r.theta[j], k = r.mu_a[P], mi = r.m[i];
  const double sum = ti + tj, root = r.root_sum[P], rti = r.root_theta[i], rtj = r.root_theta[j];
  const double iti = r.inverse_theta[i], itj = r.inverse_theta[j], irti = r.inverse_root_theta[i],
               irtj = r.inverse_root_theta[j], irs = r.inverse_root_sum[P];
  const double sp = std::sqrt(std::numbers::pi), ks = k * sum, over = sp * irtj * irs;  // √π/√(θ_j(θ_i+θ_j))
  PairTransfer t{};
  t.density0 = -0.5 * k * sp * root * irtj;                                         // (17.26)
  t.temperature0 = -0.5 * k * ti * over;                                            // (17.26)
  t.density1 = 0.75 * k * (ks - 2 * tj) * (ks - tj) * over * itj;                   // (17.26)
  t.temperature1 = 0.75 * k * k * ti * (2 * ks - 3 * tj) * over * itj;              // (17.26)
  t.shear_source = -(d - 1) / (4 * d) * k * rti * (3 * ks - 4 * tj) * over * irtj;  // (17.26)
  t.shear_partner = (d - 1) / (2 * d) * rti * over;                                 // (17.27)
  t.shear_self = (d - 1) / (2 * d) * sp * rtj * irti * irs;                         // (17.27)
  t.heat_partner0 = -k * mi * (3 * ks - 4 * tj) * over * irti * irtj / 8;           // (17.27)
  t.heat_partner1 = 3 * k * k * mi * rti * over * irtj / 8;                         // (17.27)
  t.heat_self0 = k * mi * (3 * ks - 2 * ti - 6 * tj) * over * iti / 8;              // (17.27)
  t.heat_self1 = -3 * k * mi * tj * (k - 2) * over * iti / 8;                       // (17.27)
  const double e = k * mi * iti * itj * irs * irs / 4, ti2 = ti * ti, tt = ti * tj, tj2 = tj * tj;
  t.energy = 2 * e * sum * (ks - 2 * tj);  // (17.27)
  t.energy_self = e * (k * (d * ti2 + (2 * d + 3) * tt + (d + 3) * tj2) - (2 * d + 4) * tt - (2 * d + 6) * tj2);
  t.energy_partner = e * (k * ((d + 3) * ti2 + (2 * d + 3) * tt + d * tj2) - (2 * d + 2) * tt - 2 * d * tj2);
  t.cooling_gradient = -1.5 * sp * root * irti * irtj;  // (17.27)
  return t;
}

/// Returns "<base>[i]: <what>" (built by appending: GCC 12 misreports "a" + std::string as overlapping).
std::string field(const char* base, int i, const char* what) {
  return std::string(base).append("[").append(std::to_string(i)).append("]: ").append(what);
}

Reduced reduce(const MixtureCell& cell) {
  if (cell.dimension != 2 && cell.dimension != 3)
    throw std::invalid_argument(std::string("dimension: must be 2 or 3, got ").append(std::to_string(cell.dimension)));
  if (cell.species < 2 || cell.species > kMax)
    throw std::invalid_argument(std::string("species: must be 2 to 4, got ").append(std::to_string(cell.species)));
  Reduced r;
  r.d = cell.dimension;
  r.s = cell.species;
  double mean_mass = 0, mean_diameter = 0, total = 0;
  for (int i = 0; i < r.s; ++i) {
    if (!(cell.mass[i] > 0) || !std::isfinite(cell.mass[i]))
      throw std::invalid_argument(field("mass", i, "must be finite and > 0"));
    if (!(cell.diameter[i] > 0) || !std::isfinite(cell.diameter[i]))
      throw std::invalid_argument(field("diameter", i, "must be finite and > 0"));
    if (!(cell.fraction[i] >= 0 && cell.fraction[i] <= 1))
      throw std::invalid_argument(field("fraction", i, "must be in [0, 1]"));
    for (int j = 0; j < r.s; ++j) {
      const double a = cell.restitution[i * kMax + j];
      if (!(a > 0 && a <= 1) || a != cell.restitution[j * kMax + i])
        throw std::invalid_argument(
            field("restitution", i * kMax + j, "alpha_ij at i*4 + j must be in (0, 1] and symmetric"));
    }
    mean_mass += cell.fraction[i] * cell.mass[i];
    mean_diameter += cell.fraction[i] * cell.diameter[i];
    total += cell.fraction[i];
  }
  if (std::abs(total - 1) > 1e-12) throw std::invalid_argument("fraction: the mole fractions must sum to 1");
  static const std::array<double, 2> phi_max{max_packing_fraction(2).to_double(), max_packing_fraction(3).to_double()};
  const double phi_limit = phi_max[static_cast<std::size_t>(r.d - 2)];
  if (!(cell.packing_fraction >= 0 && cell.packing_fraction < phi_limit))
    throw std::invalid_argument(std::string("packing_fraction: must be in [0, ")
                                    .append(std::to_string(phi_limit))
                                    .append(") for this dimension"));
  r.dense = cell.packing_fraction > 0;
  if (r.dense) {
    detail::DenseCellGeometry g;
    g.d = r.d;
    g.s = r.s;
    g.packing_fraction = cell.packing_fraction;
    for (int i = 0; i < r.s; ++i) {
      g.sigma[i] = cell.diameter[i] / mean_diameter;
      g.fraction[i] = cell.fraction[i];
    }
    detail::dense_cell_closures(g, r.closures.emplace());
  }
  for (int i = 0; i < r.s; ++i) {
    r.m[i] = cell.mass[i] / mean_mass;
    r.inverse_m[i] = mean_mass / cell.mass[i];
    r.x[i] = cell.fraction[i];
    if (r.x[i] > r.x[r.major]) r.major = i;
    for (int j = 0; j < r.s; ++j) {
      const double sigma = 0.5 * (cell.diameter[i] + cell.diameter[j]) / mean_diameter;
      r.area[i * kMax + j] = (r.d == 3 ? sigma * sigma : sigma) * (r.dense ? r.closures->chi[i * kMax + j] : 1.0);
      r.sigma[i * kMax + j] = sigma;
      r.length[i * kMax + j] = r.dense ? r.closures->density * sigma : 0.0;
      r.mu_a[i * kMax + j] = cell.mass[j] / (cell.mass[i] + cell.mass[j]) * (1 + cell.restitution[i * kMax + j]);
      r.alpha[i * kMax + j] = cell.restitution[i * kMax + j];
    }
  }
  // c_d and the reference gas per dimension, computed once (tgamma and pow are the slow part of a call).
  static const std::array<double, 2> c_d{geometric_factor(2), geometric_factor(3)};
  static const std::array<ReferenceGas, 2> ref{unit_reference_gas(2), unit_reference_gas(3)};
  r.c_d = c_d[static_cast<std::size_t>(r.d - 2)];
  r.ref = ref[static_cast<std::size_t>(r.d - 2)];
  return r;
}

template <int S>
PublishedFirstSonine first_sonine(Reduced& r) {
  cooling_state<S>(r);
  const Sensitivity sens = cooling_sensitivity<S>(r);
  const Operator op = first_sonine_operator<S>(r);
  const double d = r.d, z = r.zeta;
  // Maxwell averages of the order-1 pieces (galerkin_pieces): M(0,0) = d/2, M(1,1) = F_0 = −F_1 =
  // d(d+2)/4; D(0,0) = −d/4, D(1,0) = d(d+2)/4, D(1,1) = −3d(d+2)/8; shear D = −(d−1)(d+2)/8.
  const double m00 = d / 2, m11 = d * (d + 2) / 4, d00 = -d / 4, d10 = m11, d11 = -3 * m11 / 2;
  const double temperature = 0.5;
  // Reciprocals of the reductions and of the d-dependent denominators, taken once per call.
  const double per_diffusion = 1 / r.ref.self_diffusion, per_conductivity = 1 / r.ref.conductivity,
               per_viscosity = 1 / r.ref.viscosity, per_d = 1 / d, per_d2 = 1 / (d + 2);
  PublishedFirstSonine out;
  out.cooling_rate = z / r.ref.collision_frequency;
  for (int i = 0; i < S; ++i) {
    out.temperature_ratio[i] = r.gamma[i];
    out.pressure_derivative[i] = 1;
  }

  // Dense gas: the pair averages (17.26)–(17.27), the rate R_ij = σ_ij^{d−1} χ_ij c_d w_ij, p* and
  // P_ℓ = ∂p/∂n_ℓ/T (18.2).
  std::array<PairTransfer, kMax * kMax> transfer;  // the s² pairs written below before any read
  Mat rate{};
  if (r.dense) {
    const double b2 = r.d == 3 ? 2 * std::numbers::pi / 3 : std::numbers::pi / 2;  // π^{(d−1)/2}Γ(3/2)/Γ(d/2+1)
    for (int i = 0; i < S; ++i)
      for (int j = 0; j < S; ++j) {
        const int P = i * kMax + j;
        transfer[P] = r.d == 3 ? pair_transfer<3>(r, i, j) : pair_transfer<2>(r, i, j);
        rate[P] = r.area[P] * r.c_d * r.speed[P];
        const double sd = r.d == 3 ? r.sigma[P] * r.sigma[P] * r.sigma[P] : r.sigma[P] * r.sigma[P];
        const double w = r.closures->density * b2 * r.mu_a[P] * sd * r.closures->chi[P] * r.gamma[i];
        out.pressure += w * r.x[i] * r.x[j];
        for (int l = 0; l < S; ++l)
          out.pressure_derivative[l] +=
              w * ((i == l ? r.x[j] : 0.0) + (j == l ? r.x[i] : 0.0) +
                   r.x[i] * r.x[j] * (r.closures->log_chi_derivative[P * kMax + l] + sens.log_gamma[i * kMax + l]));
      }
  }
  // The collisional heat flux (18.9) of a vector-mode solution, f0 f^(1) part:
  // −(1/(2d)) Σ_ij L R [x_i ⟨⟨(σ̂·c2)ΔE_1 X_j⟩⟩ + x_j ⟨⟨(σ̂·c1)ΔE_1 X_i⟩⟩].
  // It is linear in the solution: Σ_k (h0_k φ̃_k0 + h1_k φ̃_k1) with the weights gathered once from the pairs.
  Vec h0{}, h1{};
  if (r.dense)
    for (int i = 0; i < S; ++i)
      for (int j = 0; j < S; ++j) {
        const int P = i * kMax + j;
        const PairTransfer& t = transfer[P];
        const double c = -r.length[P] * rate[P] * 0.5 * per_d;
        h0[j] += c * r.x[i] * t.heat_partner0;
        h1[j] += c * r.x[i] * t.heat_partner1;
        h0[i] += c * r.x[j] * t.heat_self0;
        h1[i] += c * r.x[j] * t.heat_self1;
      }
  auto collisional_heat = [&](const VectorSolution& v) {
    double q = 0;
    for (int k = 0; k < S; ++k) q += h0[k] * v.s0[k] + h1[k] * v.s1[k];
    return q;
  };
  auto gradient_heat = [&](int P) { return -r.length[P] * r.length[P] * rate[P] * 0.25 * per_d; };

  // 𝒜 (∇ln T), sources (17.5), (18.4): −x_i θ_i^{−1/2}[(1 − θ_i p*) M(p,0) − M(p,1)] + Σ_j L R x_i x_j ⟨⟨…(X2 − d/2)⟩⟩.
  Vec a0{}, a1{};
  for (int i = 0; i < S; ++i) {
    a0[i] = -r.x[i] * r.inverse_root_theta[i] * (1 - r.theta[i] * out.pressure) * m00;
    a1[i] = r.x[i] * r.inverse_root_theta[i] * m11;
    if (r.dense)
      for (int j = 0; j < S; ++j) {
        const int P = i * kMax + j;
        const double f = r.length[P] * rate[P] * r.x[i] * r.x[j];
        a0[i] += f * transfer[P].temperature0;
        a1[i] += f * transfer[P].temperature1;
      }
  }
  const VectorSolution heat = VectorMode<S>(r, op, z * (d00 - m00 / 2), z * d10, z * (d11 - m11 / 2)).solve(a0, a1);
  const VectorMode<S> density_mode(r, op, z * d00, z * d10, z * d11),
      force_mode(r, op, z * (d00 + m00), z * d10, z * (d11 + m11));
  // Number flux ∫V·X_i/d = φ̃_i0/(2√θ_i); kinetic heat flux ∫½m_iV²V·X_i/d = (m_i/(2d))θ_i^{−3/2}(F_0φ̃_i0 + F_1φ̃_i1)
  // (17.9)–(17.10).
  Vec heat_weight{};  // (m_i/(2d)) θ_i^{−3/2} F_0
  for (int i = 0; i < S; ++i)
    heat_weight[i] = r.m[i] * 0.5 * per_d * r.inverse_theta[i] * r.inverse_root_theta[i] * m11;
  auto number_flux = [&](const VectorSolution& v, int i) { return v.s0[i] * 0.5 * r.inverse_root_theta[i]; };
  auto heat_flux = [&](const VectorSolution& v, int i) { return heat_weight[i] * (v.s0[i] - v.s1[i]); };
  for (int i = 0; i < S; ++i) {
    out.thermal_diffusion[i] = -r.m[i] * number_flux(heat, i) * per_diffusion;
    out.thermal_conductivity_species[i] = -heat_flux(heat, i) / temperature * per_conductivity;
    out.thermal_conductivity += out.thermal_conductivity_species[i];
  }
  if (r.dense) {  // (18.9): f0 f^(1) and f0 ∂f0 parts
    double q = collisional_heat(heat);
    for (int i = 0; i < S; ++i)
      for (int j = 0; j < S; ++j) {
        const int P = i * kMax + j;
        q += gradient_heat(P) * r.x[i] * r.x[j] * (transfer[P].energy_partner - transfer[P].energy_self);
      }
    out.thermal_conductivity -= q / temperature * per_conductivity;
  }
  // ℬ^j (∇n_j), sources (17.6), (18.4): −θ_i^{−1/2}[δ_ij M(p,0) + x_i(∂_j ln γ_i (M(p,0) − M(p,1)) − θ_i P_j M(p,0))]
  // + ∂ζ/∂n_j M φ̃^𝒜_i + the transfer of the pairs (i, k) (18.21).
  for (int j = 0; j < S; ++j) {
    Vec b0{}, b1{};
    for (int i = 0; i < S; ++i) {
      const double g = sens.log_gamma[i * kMax + j], per_root = r.inverse_root_theta[i];
      b0[i] = -m00 * per_root * ((i == j ? 1.0 : 0.0) + r.x[i] * (g - r.theta[i] * out.pressure_derivative[j])) +
              sens.zeta[j] * m00 * heat.s0[i];
      b1[i] = m11 * per_root * r.x[i] * g + sens.zeta[j] * m11 * heat.s1[i];
      if (r.dense)
        for (int k = 0; k < S; ++k) {
          const int P = i * kMax + k;
          const PairTransfer& t = transfer[P];
          const double f = r.length[P] * rate[P] * r.x[i], gk = sens.log_gamma[k * kMax + j];
          const double density = (k == j ? 1.0 : 0.0) + 0.5 * (r.x[k] * r.closures->log_chi_derivative[P * kMax + j] +
                                                               r.closures->functionals[P * kMax + j]);
          b0[i] += f * (density * t.density0 + r.x[k] * gk * t.temperature0);
          b1[i] += f * (density * t.density1 + r.x[k] * gk * t.temperature1);
        }
    }
    const VectorSolution density = density_mode.solve(b0, b1);
    double collisional = 0;
    for (int i = 0; i < S; ++i) {
      out.mutual_diffusion[i * kMax + j] = -number_flux(density, i) * r.inverse_m[j] * per_diffusion;
      out.dufour_species[i * kMax + j] = -r.x[j] * heat_flux(density, i) / temperature * per_conductivity;
      out.dufour[j] += out.dufour_species[i * kMax + j];
    }
    if (r.dense) {
      collisional = collisional_heat(density);
      for (int i = 0; i < S; ++i)
        for (int k = 0; k < S; ++k) {
          const int P = i * kMax + k;
          const PairTransfer& t = transfer[P];
          const double gi = sens.log_gamma[i * kMax + j], gk = sens.log_gamma[k * kMax + j];
          // (18.22) with the off-midpoint contact value I_jik/x_k per ∇n_j
          const double v =
              ((k == j ? r.x[i] : 0.0) - (i == j ? r.x[k] : 0.0) + r.x[i] * r.closures->functionals[P * kMax + j]) *
                  t.energy +
              r.x[i] * r.x[k] *
                  (gk * (t.energy_partner - 0.5 * d * t.energy) - gi * (t.energy_self - 0.5 * d * t.energy));
          collisional += gradient_heat(P) * v;
        }
      out.dufour[j] -= r.x[j] * collisional / temperature * per_conductivity;
    }
    // External force on species j (18.14): source 2√θ_i x_i M(0,0)(δ_ij/m_i − x_j), operator ζ(D + M).
    Vec f0{};
    for (int i = 0; i < S; ++i) f0[i] = 2 * r.root_theta[i] * r.x[i] * ((i == j ? r.inverse_m[i] : 0.0) - r.x[j]) * m00;
    const VectorSolution force = force_mode.solve(f0, Vec{});
    for (int i = 0; i < S; ++i) {
      out.mobility[i * kMax + j] = -r.m[i] * number_flux(force, i) * temperature * per_diffusion;
      out.heat_mobility_species[i * kMax + j] = -heat_flux(force, i) * per_conductivity;
      out.heat_mobility[j] += out.heat_mobility_species[i * kMax + j];
    }
    if (r.dense) out.heat_mobility[j] -= collisional_heat(force) * per_conductivity;  // (18.15)
  }
  for (int i = 0; i < S; ++i)
    for (int j = 0; j < S; ++j)
      out.pressure_diffusion[i] += r.m[i] * r.m[j] * r.x[j] * out.mutual_diffusion[i * kMax + j];
  // Shear (17.11) with Y_2 S_0 alone: (ℒ + ζD) φ̃ = −2x_i((d−1)/d)F_0 (+ the transfer (18.5) dense),
  // η_i = −(m_i/θ_i) F_0 φ̃_i/(d(d+2)).
  Mat shear;  // the s × s block of op.shear
  Vec source{};
  for (int i = 0; i < S; ++i) {
    for (int k = 0; k < S; ++k) shear[i * kMax + k] = op.shear[i * kMax + k];
    shear[i * kMax + i] -= z * (d - 1) * (d + 2) / 8;
    source[i] = -r.x[i] * (d - 1) * (d + 2) / 2;
    if (r.dense)
      for (int j = 0; j < S; ++j) {
        const int P = i * kMax + j;
        source[i] += r.length[P] * rate[P] * r.x[i] * r.x[j] * 2 * r.root_theta[j] * transfer[P].shear_source;
      }
  }
  const Vec c = Lu<S>(shear).solve(source);
  for (int i = 0; i < S; ++i) {
    out.shear_viscosity_species[i] = -r.m[i] * r.inverse_theta[i] * c[i] * 0.25 * per_viscosity;
    out.shear_viscosity += out.shear_viscosity_species[i];
  }
  if (r.dense) {
    // (18.8): f0 f^(1) part −(1/(2(d−1)(d+2))) Σ_ij m_i μ_ji (1+α) L R [x_i ⟨⟨…Y(c2)⟩⟩ c_j + x_j ⟨⟨…Y(c1)⟩⟩ c_i];
    // f0 ∂f0 part with ⟨⟨(σ̂·g)σ̂·(2θ_j v2 − 2θ_i v1)⟩⟩ = −4, whose (d+2)/d multiple is the bulk viscosity; ζ_U of
    // (17.18).
    double eta = 0, gradient = 0;
    const double per_shear = 0.5 / (d - 1) * per_d2;  // 1/(2(d−1)(d+2))
    for (int i = 0; i < S; ++i)
      for (int j = 0; j < S; ++j) {
        const int P = i * kMax + j;
        const PairTransfer& t = transfer[P];
        const double w = r.m[i] * r.mu_a[P] * r.length[P] * rate[P];
        eta -= w * per_shear * (r.x[i] * t.shear_partner * c[j] + r.x[j] * t.shear_self * c[i]);
        gradient += w * r.length[P] * r.x[i] * r.x[j] * per_d * per_d2;
        const double a = r.alpha[P];
        // (1 − α²)/(1 + α) = 1 − α
        out.cooling_rate_first_order +=
            (1 - a) * r.m[i] * r.mu_a[P] * rate[P] * r.length[P] * r.x[i] * r.x[j] * t.cooling_gradient * per_d * per_d;
      }
    out.shear_viscosity += (eta + gradient) * per_viscosity;
    out.bulk_viscosity = (d + 2) * per_d * gradient * per_viscosity;
  }
  return out;
}

}  // namespace

MixtureCell mixture_cell(const Mixture& mixture) {
  mixture.validate();
  if (mixture.size() > kMax) throw std::invalid_argument("species: the closed form takes at most 4 species");
  MixtureCell cell;
  cell.dimension = mixture.dimension;
  cell.species = static_cast<int>(mixture.size());
  cell.packing_fraction = mixture.packing_fraction;
  for (std::size_t i = 0; i < mixture.size(); ++i) {
    cell.mass[i] = mixture.species[i].mass.value();
    cell.diameter[i] = mixture.species[i].diameter;
    cell.fraction[i] = mixture.species[i].fraction;
    for (std::size_t j = 0; j < mixture.size(); ++j) cell.restitution[i * kMax + j] = mixture.restitution(i, j);
  }
  return cell;
}

PublishedFirstSonine published_first_sonine(const MixtureCell& cell) {
  Reduced r = reduce(cell);
  // The species count is a template argument: every loop and the small solves unroll (theory.md §17.10 gives the cost).
  switch (r.s) {
    case 2:
      return first_sonine<2>(r);
    case 3:
      return first_sonine<3>(r);
    default:
      return first_sonine<4>(r);
  }
}

}  // namespace gkt
