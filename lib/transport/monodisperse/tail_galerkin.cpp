// Tail-carrying Petrov–Galerkin solution of the HCS and the Chapman–Enskog equations of dilute
// smooth inelastic hard spheres and disks (tail_galerkin.hpp; docs/theory.md §10.6).
//
// Trial functions F_k(c) = w(c) Q_k(c²), w(c) = exp(−2c²/(1 + √(1 + 4c²/A²))) (Gaussian for
// c ≪ A, exp(−A c) for c ≫ A; theory.md (10.11)), Q_k orthonormal in ∫ w Q_k Q_l dc
// (TailTrialSpace::power_law: w(c)(1 + c²)^{γ/2} × polynomials in √(4 + c²) − 2, theory.md (10.15)); test
// functions the Sonine polynomials of the standard scheme. Collision moments of a polynomial test
// function: the σ̂ integral is a polynomial in s = ĝ·σ̂ and cos φ (exact Gauss rules), the angle
// between v1 and v2 becomes |g| with dμ = g dg/(c1 c2) (3D, polynomial integrand, exact Gauss
// rule; in 2D the integrand in that angle θ is g(θ) × polynomial, elliptic, done by Gauss–Legendre
// in v with θ = η sinh v), leaving a 2-D radial integral over (c1, c2) by composite Gauss–Legendre split at c1 = c2.
#include "gkt/transport/monodisperse/tail_galerkin.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <tuple>
#include <utility>

#include "gkt/operators/collisional_transfer.hpp"
#include "gkt/transport/common/pair_correlation.hpp"
#include "transport/monodisperse/tail_collisional_transfer.hpp"
#include "transport/monodisperse/tail_quadrature.hpp"

namespace gkt {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kPanelWidth = 1.0;  // composite Gauss–Legendre: panels of width 1 in the core …
constexpr int kPanelNodes = 12;      // … 20 % of c beyond c = 5, 12 nodes each (measured: theory.md §10.6)
constexpr double kNegligible = 40;   // radial nodes of weight below e^{−40} (with the polynomial growth) are dropped
constexpr int kWeightPasses = 3;     // A of the weight taken from the previous pass's ζ_r

/// Gauss–Legendre nodes in v (θ = η sinh v) of the 2D angle between c1 and c2 (measured: theory.md §10.6).
/// (2 p_max + 40 changes nothing above 1e-12 at α = 0.5).
int theta_nodes(int p_max) { return 2 * p_max + 16; }

using detail::gauss_legendre;
using detail::Rule;
using detail::sonine_values;

/// x S_p'(x) = p S_p − (p + index) S_{p−1} (theory.md (1.1)).
double x_derivative(const std::vector<double>& s, int p, double index) {
  return p * s[static_cast<std::size_t>(p)] - (p > 0 ? (p + index) * s[static_cast<std::size_t>(p - 1)] : 0.0);
}

/// log w(c) of the trial weight (theory.md (10.11)); A = ∞ gives the Gaussian −c².
double log_weight(double c, double tail) {
  const double z = std::isinf(tail) ? 0.0 : 4 * c * c / (tail * tail);
  return -2 * c * c / (std::sqrt(1 + z) + 1);
}

/// A trial space: weight w(c) (1 + c²)^{γ/2} times polynomials in y = √(4 + c²) − 2 (TailTrialSpace::power_law:
/// the tail of the solutions is c^{γ + j} exp(−A c), j = 0, 1, 2, …, and y ≈ c²/4 in the core, ≈ c − 2 in
/// the tail; theory.md §10.6) or w(c) times polynomials in c².
struct TrialWeight {
  double tail = INFINITY;  ///< A
  double power = 0;        ///< γ
  bool in_speed = false;   ///< polynomials in y (else in c²)
  [[nodiscard]] double operator()(double c) const {
    return std::exp(log_weight(c, tail) + (power == 0 ? 0.0 : 0.5 * power * std::log1p(c * c)));
  }
  [[nodiscard]] double variable(double c) const { return in_speed ? std::sqrt(4 + c * c) - 2 : c * c; }
  /// d(log of the weight)/dc.
  [[nodiscard]] double log_slope(double c) const {
    double slope = -2 * c;  // Gaussian
    if (!std::isinf(tail)) {
      const double r = std::sqrt(1 + 4 * c * c / (tail * tail));
      slope = -4 * c / (r + 1) + 8 * c * c * c / (tail * tail * r * (r + 1) * (r + 1));
    }
    return slope + power * c / (1 + c * c);
  }
  /// d(variable)/dc.
  [[nodiscard]] double variable_slope(double c) const { return in_speed ? c / std::sqrt(4 + c * c) : 2 * c; }
};

/// ν = √2 π^{(d−1)/2}/Γ(d/2): the factor that turns the reduced operator of (9.1) into the
/// units of ν0 (theory.md (9.4)); 2√(2π) in 3D, √(2π) in 2D.
double frequency_factor(int d) { return std::sqrt(2.0) * std::pow(kPi, (d - 1) / 2.0) / std::tgamma(d / 2.0); }

/// β = ∫dσ̂ Θ(ĝ·σ̂) ĝ·σ̂ = π^{(d−1)/2}/Γ((d+1)/2): the loss rate of a fast particle is β c ([vannoije1998]).
double loss_rate_factor(int d) { return std::pow(kPi, (d - 1) / 2.0) / std::tgamma((d + 1) / 2.0); }

struct RadialNode {
  double c1, c2, weight;
  int i1, i2;  ///< index of c1, c2 in the 1-D rule, −1 off it (the inner node of a diagonal triangle)
};

/// The 1-D composite rule on [0, c_max] and the 2-D rule on [0, c_max]², panels on the diagonal split
/// into two triangles (the collision kernel has a kink at c1 = c2).
struct Grid {
  int dimension = 3;
  std::vector<double> c, w;
  std::vector<double> shell;  // w × S_d c^{d−1}: the 1-D rule for ∫ d^d c of an isotropic function
  std::vector<RadialNode> pairs;
};

Grid make_grid(int dimension, double c_max, double tail, int degree) {
  const Rule r = gauss_legendre(kPanelNodes);
  std::vector<double> edges{0.0};  // panels of width 1 in the core, growing by 20 % in the tail
  while (edges.back() < c_max) edges.push_back(edges.back() + std::max(kPanelWidth, 0.2 * edges.back()));
  const std::size_t panels = edges.size() - 1, n = r.x.size();
  Grid g;
  g.dimension = dimension;
  for (std::size_t i = 0; i < panels; ++i)
    for (std::size_t a = 0; a < n; ++a) {
      g.c.push_back(edges[i] + r.x[a] * (edges[i + 1] - edges[i]));
      g.w.push_back(r.w[a] * (edges[i + 1] - edges[i]));
      const double c = g.c.back();
      g.shell.push_back(dimension == 3 ? g.w.back() * 4 * kPi * (c * c)
                                       : g.w.back() * 2 * kPi * c);  // S_3 = 4π, S_2 = 2π
    }
  constexpr std::size_t kOff = static_cast<std::size_t>(-1);
  // A node is dropped when even the highest polynomial degree cannot lift w(c1) w(c2) to e^{−kNegligible}
  // of the core (where w ≈ 1).
  auto add = [&](double c1, double c2, double w, std::size_t i1, std::size_t i2) {
    if (log_weight(c1, tail) + log_weight(c2, tail) + degree * std::log1p(c1 + c2) > -kNegligible)
      g.pairs.push_back({c1, c2, w, i1 == kOff ? -1 : static_cast<int>(i1), i2 == kOff ? -1 : static_cast<int>(i2)});
  };
  for (std::size_t i = 0; i < panels; ++i)
    for (std::size_t j = 0; j < panels; ++j)
      for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = 0; b < n; ++b) {
          if (i != j) {
            add(g.c[i * n + a], g.c[j * n + b], g.w[i * n + a] * g.w[j * n + b], i * n + a, j * n + b);
            continue;
          }
          const double lo = edges[i], c1 = g.c[i * n + a];
          const double c2 = lo + r.x[b] * (c1 - lo), w = g.w[i * n + a] * r.w[b] * (c1 - lo);
          add(c1, c2, w, i * n + a, kOff);
          add(c2, c1, w, kOff, i * n + a);
        }
  return g;
}

/// The σ̂- and angle-integrated collisional change of the test functions at each radial node, five
/// families × (p_max + 1): scalar S_p(c²) (HCS), vector c S_p^{(d/2)} contracted with the particle's own
/// c1 ("self") or the partner's c2 ("partner"), tensor Y2 S_p^{(d/2+1)} contracted likewise.
struct Kernel {
  int p_max = 0;
  std::vector<double> values;  // [node][family][p]
  [[nodiscard]] const double* at(std::size_t node, int family) const {
    return &values[(node * 5 + static_cast<std::size_t>(family)) * static_cast<std::size_t>(p_max + 1)];
  }
};

enum Family { kScalar = 0, kVectorSelf = 1, kVectorPartner = 2, kTensorSelf = 3, kTensorPartner = 4 };

/// The collisional change of the five test-function families at one radial node (c1, c2) for all p ≤ p_max,
/// integrated over σ̂ (hemisphere g·σ̂ > 0, weight g·σ̂) and over the angle between c1 and c2 (`add` per
/// |g| with that angle's weight). In 3D σ̂ = s ĝ + √(1−s²)(cos φ, sin φ) with Gauss–Legendre in s and
/// Gauss–Chebyshev in cos φ; in 2D σ̂ = s ĝ ± √(1−s²) ĝ⊥ and ds (g s)/√(1−s²) = g dt with t = √(1−s²),
/// Gauss–Legendre in t (the integrand is then a polynomial in t).
///
/// The points are gathered in blocks of kBlock and the three Sonine recurrences run over a block at once,
/// kLanes points side by side with one partial sum per lane: the loops over points then vectorise and the
/// recurrences' dependency chains overlap (one point at a time, they were bound by the latency of the
/// division, docs/performance.md "Tail scheme").
class SigmaIntegral {
 public:
  SigmaIntegral(int dimension, double alpha, int p_max) : dimension_(dimension), alpha_(alpha), p_max_(p_max) {
    const auto width = static_cast<std::size_t>(p_max + 1);
    s0_.resize(width);
    v0_.resize(width);
    t0_.resize(width);
    sums_.resize(width * kFamilies * kLanes);
    inverse_.resize(width);
    for (std::size_t n = 0; n < width; ++n) inverse_[n] = 1.0 / static_cast<double>(n + 1);
    // Exact rules: after the φ average the integrand is a polynomial of degree ≤ 2 p_max + 5 in s (3D; in t
    // in 2D), and of degree ≤ p_max + 2 in cos φ (Gauss–Chebyshev: exact to 2 n_phi − 1); in 2D cos φ = ±1.
    s_rule_ = gauss_legendre(p_max + 3);
    if (dimension == 3) {
      const int n_phi = p_max / 2 + 2;
      for (int j = 0; j < n_phi; ++j) cos_phi_.push_back(std::cos(kPi * (j + 0.5) / n_phi));
    } else {
      cos_phi_ = {1.0, -1.0};
    }
  }

  /// Starts the node (c1², c2²) = (x1, x2).
  void begin(double x1, double x2) {
    const double m = dimension_ / 2.0 - 1;
    x1_ = x1;
    x2_ = x2;
    sonine_values(p_max_, m, x1, s0_.data());
    sonine_values(p_max_, m + 1, x1, v0_.data());
    sonine_values(p_max_, m + 2, x1, t0_.data());
    std::fill(sums_.begin(), sums_.end(), 0.0);
    weight_sum_ = partner_v0_sum_ = partner_t0_sum_ = 0;
    count_ = 0;
  }

  /// Adds the σ̂ integral at relative speed g with the weight w_angle of the angle between c1 and c2.
  void add(double g, double w_angle) {
    const double d = dimension_, eps = 1 - alpha_ * alpha_, x1 = x1_, x2 = x2_;
    // Centre of mass G and relative velocity g: G·g = (x1 − x2)/2, |g|²G² − (G·g)² = g² G⊥².
    const double big_g2 = (2 * x1 + 2 * x2 - g * g) / 4, gg = (x1 - x2) / 2, v12 = (x1 + x2 - g * g) / 2;
    const double perp2 = g * g * big_g2 - gg * gg, g_perp = perp2 > 0 ? std::sqrt(perp2) : 0.0;
    const double partner_t = v12 * v12 - x1 * x2 / d;
    for (std::size_t is = 0; is < s_rule_.x.size(); ++is) {
      const double node = s_rule_.x[is], sv = dimension_ == 3 ? node : std::sqrt(1 - node * node);
      const double sq = dimension_ == 3 ? std::sqrt(1 - sv * sv) : node, big_x = g * sv;
      // (g·σ̂) dσ̂: 3D (g s) ds dφ, 2D g dt per sign of the perpendicular component.
      const double w_s = s_rule_.w[is] * (dimension_ == 3 ? big_x : g) * w_angle;
      for (const double cp : cos_phi_) {
        const double w = dimension_ == 3 ? w_s * 2 * kPi / static_cast<double>(cos_phi_.size()) : w_s;
        // X = g·σ̂, XY = (g·σ̂)(G·σ̂); v1' = v1 − ((1+α)/2) X σ̂ (theory.md (1.2)).
        const double xy = sv * sv * gg + sv * sq * cp * g_perp, x_sq = big_x * big_x;
        const double u = x1 - (1 + alpha_) * xy - eps * x_sq / 4;
        const double self_v = x1 - 0.5 * (1 + alpha_) * (xy + x_sq / 2);
        const double partner_v = v12 - 0.5 * (1 + alpha_) * (xy - x_sq / 2);
        const std::size_t j = count_++;
        weight_[j] = w;
        energy_[j] = u;
        self_v_[j] = self_v;
        partner_v_[j] = partner_v;
        self_t_[j] = self_v * self_v - u * x1 / d;
        partner_t_[j] = partner_v * partner_v - u * x2 / d;
        partner_v0_[j] = v12;
        partner_t0_[j] = partner_t;
        if (count_ == kBlock) flush();
      }
    }
  }

  /// Ends the node: writes the five families × (p_max + 1) sums, times `measure`, to `out`.
  void finish(double measure, double* out) {
    flush();
    const auto width = static_cast<std::size_t>(p_max_ + 1);
    const double self_t0 = x1_ * x1_ - x1_ * x1_ / dimension_;
    for (std::size_t p = 0; p < width; ++p) {
      const double at_c1[kFamilies] = {s0_[p] * weight_sum_, x1_ * v0_[p] * weight_sum_, v0_[p] * partner_v0_sum_,
                                       self_t0 * t0_[p] * weight_sum_, t0_[p] * partner_t0_sum_};
      for (std::size_t f = 0; f < kFamilies; ++f) {
        const double* lane = &sums_[(p * kFamilies + f) * kLanes];
        double sum = 0;
        for (std::size_t l = 0; l < kLanes; ++l) sum += lane[l];
        out[f * width + p] = (sum - at_c1[f]) * measure;
      }
    }
  }

 private:
  static constexpr std::size_t kLanes = 4, kBlock = 64, kFamilies = 5;

  /// Runs the Sonine recurrences S_p^{(m)}, S_p^{(m+1)}, S_p^{(m+2)} of the block's u (m = d/2 − 1) and
  /// adds each p's change, times the weight, to the lane sums.
  void flush() {
    if (count_ == 0) return;
    while (count_ % kLanes != 0) {  // pad with zero weight
      const std::size_t j = count_++;
      weight_[j] = energy_[j] = self_v_[j] = partner_v_[j] = self_t_[j] = partner_t_[j] = 0;
      partner_v0_[j] = partner_t0_[j] = 0;
    }
    // The p-independent parts of the changes, Σ w (the test function at c1), once per block.
    for (std::size_t j = 0; j < count_; ++j) {
      const double w = weight_[j];
      weight_sum_ += w;
      partner_v0_sum_ += w * partner_v0_[j];
      partner_t0_sum_ += w * partner_t0_[j];
      self_v_[j] *= w;
      partner_v_[j] *= w;
      self_t_[j] *= w;
      partner_t_[j] *= w;
    }
    const double m = dimension_ / 2.0 - 1;
    std::array<double, kBlock> s_prev{}, s{}, v{}, t{};
    for (std::size_t j = 0; j < count_; ++j) s[j] = v[j] = t[j] = 1;  // S_0 = 1, S_{−1} = 0
    for (int p = 0; p <= p_max_; ++p) {
      const auto pu = static_cast<std::size_t>(p);
      // S_{p+1} = ((2p + 1 + index − u) S_p − (p + index) S_{p−1})/(p + 1) (theory.md (1.1)), and
      // S^{(index+1)}_p = Σ_{q ≤ p} S^{(index)}_q ([abramowitz1964] 22.12.7).
      const double as = 2 * p + 1 + m, bs = p + m, inv = inverse_[pu];
      double scalar[kLanes] = {}, self_vec[kLanes] = {}, partner_vec[kLanes] = {}, self_ten[kLanes] = {},
             partner_ten[kLanes] = {};
      for (std::size_t j0 = 0; j0 < count_; j0 += kLanes)
        for (std::size_t l = 0; l < kLanes; ++l) {
          const std::size_t j = j0 + l;
          scalar[l] += weight_[j] * s[j];
          self_vec[l] += self_v_[j] * v[j];
          partner_vec[l] += partner_v_[j] * v[j];
          self_ten[l] += self_t_[j] * t[j];
          partner_ten[l] += partner_t_[j] * t[j];
        }
      if (p < p_max_)
        for (std::size_t j = 0; j < count_; ++j) {
          const double sn = ((as - energy_[j]) * s[j] - bs * s_prev[j]) * inv;
          s_prev[j] = s[j];
          s[j] = sn;
          v[j] += sn;
          t[j] += v[j];
        }
      double* out = &sums_[pu * kFamilies * kLanes];
      for (std::size_t l = 0; l < kLanes; ++l) {
        out[l] += scalar[l];
        out[kLanes + l] += self_vec[l];
        out[2 * kLanes + l] += partner_vec[l];
        out[3 * kLanes + l] += self_ten[l];
        out[4 * kLanes + l] += partner_ten[l];
      }
    }
    count_ = 0;
  }

  int dimension_;
  double alpha_;
  int p_max_;
  Rule s_rule_;
  std::vector<double> cos_phi_;  // 3D: Gauss–Chebyshev nodes (weight 2π/n each); 2D: ±1 (weight 1 each)
  std::vector<double> s0_, v0_, t0_, inverse_;
  std::vector<double> sums_;  // [p][family][lane]
  double x1_ = 0, x2_ = 0;
  double weight_sum_ = 0, partner_v0_sum_ = 0, partner_t0_sum_ = 0;  // Σ w, Σ w c1·c2, Σ w (its tensor)
  std::size_t count_ = 0;
  // The block: weight, u = c1'², c1'·c1, c1'·c2, the tensor contractions, and the partner terms of v1.
  std::array<double, kBlock> weight_{}, energy_{}, self_v_{}, partner_v_{}, self_t_{}, partner_t_{}, partner_v0_{},
      partner_t0_{};
};

/// The number of threads the kernel uses for `pairs` radial nodes: every core, none for small grids.
unsigned kernel_threads(std::size_t pairs) {
  if (pairs < 4096) return 1;
  return std::clamp(std::thread::hardware_concurrency(), 1U, 8U);
}

Kernel collision_kernel(const Grid& grid, double alpha, int p_max) {
  const int dim = grid.dimension;
  // Exact in g (3D: degree ≤ 2 p_max + 6); 2D: converged in v (θ = η sinh v).
  const Rule g_rule = gauss_legendre(p_max + 4), theta_rule = gauss_legendre(theta_nodes(p_max));
  Kernel k;
  k.p_max = p_max;
  const auto width = static_cast<std::size_t>(p_max + 1);
  k.values.assign(grid.pairs.size() * 5 * width, 0.0);
  // Each node is independent: contiguous ranges per thread give the same values for any thread count.
  auto range = [&](std::size_t first, std::size_t last) {
    SigmaIntegral sigma(dim, alpha, p_max);
    for (std::size_t node = first; node < last; ++node) {
      const double c1 = grid.pairs[node].c1, c2 = grid.pairs[node].c2, x1 = c1 * c1, x2 = c2 * c2;
      sigma.begin(x1, x2);
      if (dim == 3) {
        const double g_lo = std::fabs(c1 - c2), g_hi = c1 + c2;
        for (std::size_t ig = 0; ig < g_rule.x.size(); ++ig) {
          const double g = g_lo + (g_hi - g_lo) * g_rule.x[ig];
          sigma.add(g, g_rule.w[ig] * (g_hi - g_lo) * g / (c1 * c2));  // ∫_{−1}^{1} dμ = ∫ g dg/(c1 c2)
        }
      } else {
        // 2D: ∫_0^π dθ with g² = c1² + c2² − 2 c1 c2 cos θ. g is analytic in θ but has branch points at
        // θ = ±i η, η = |ln(c1/c2)|, close to θ = 0 when c1 ≈ c2; θ = η sinh v moves them to
        // v = ±iπ/2, and Gauss–Legendre in v converges geometrically for every c1/c2 (theory.md §10.6).
        const double eta = std::max(std::fabs(std::log(c1 / c2)), 1e-12), v_max = std::asinh(kPi / eta);
        for (std::size_t it = 0; it < theta_rule.x.size(); ++it) {
          const double v = v_max * theta_rule.x[it], theta = eta * std::sinh(v);
          const double g = std::sqrt(std::max(0.0, x1 + x2 - 2 * c1 * c2 * std::cos(theta)));
          sigma.add(g, theta_rule.w[it] * v_max * eta * std::cosh(v));
        }
      }
      // ∫d^d c1 d^d c2 of isotropic functions: 3D S_3 S_2 c1² c2² ∫dμ, 2D S_2 c1 c2 · 2∫_0^π dθ.
      const double measure = dim == 3 ? grid.pairs[node].weight * (4 * kPi) * (2 * kPi) * x1 * x2
                                      : grid.pairs[node].weight * (2 * kPi) * 2 * c1 * c2;
      sigma.finish(measure, &k.values[node * 5 * width]);
    }
  };
  const std::size_t threads = kernel_threads(grid.pairs.size()), n = grid.pairs.size();
  std::vector<std::thread> pool;
  std::size_t started = 1;
  try {
    for (; started < threads; ++started) pool.emplace_back(range, started * n / threads, (started + 1) * n / threads);
  } catch (const std::system_error&) {  // no thread to be had: the rest here
  }
  range(0, n / threads);
  for (std::size_t i = started; i < threads; ++i) range(i * n / threads, (i + 1) * n / threads);
  for (auto& t : pool) t.join();
  return k;
}

/// Orthonormal polynomials Q_k(y), y = c or c² (TrialWeight), in ∫ w Q_k Q_l d^d c (Stieltjes on the 1-D rule).
struct TrialBasis {
  TrialWeight weight;
  std::vector<double> a, b;  // three-term recurrence
  double q0 = 0;
  /// Q_0 … Q_k_max at speed c.
  void values(double c, int k_max, double* out) const {
    const double x = weight.variable(c);
    out[0] = q0;
    if (k_max >= 1) out[1] = (x - a[0]) * out[0] / b[1];
    for (int k = 1; k < k_max; ++k)
      out[k + 1] = ((x - a[static_cast<std::size_t>(k)]) * out[k] - b[static_cast<std::size_t>(k)] * out[k - 1]) /
                   b[static_cast<std::size_t>(k + 1)];
  }
  /// Σ_k coefficient_k w(c) Q_k(c) and its derivative in c (the HCS φ and φ' for the collisional transfer).
  [[nodiscard]] std::pair<double, double> function_and_slope(double c, const Eigen::VectorXd& coefficient) const {
    const double x = weight.variable(c);
    const auto k_max = static_cast<int>(coefficient.size()) - 1;
    double q_prev = 0, q = q0, dq_prev = 0, dq = 0, f = coefficient[0] * q, df = 0;
    for (int k = 0; k < k_max; ++k) {
      const auto ku = static_cast<std::size_t>(k);
      const double qn = ((x - a[ku]) * q - (k > 0 ? b[ku] : 0.0) * q_prev) / b[ku + 1];
      const double dqn = (q + (x - a[ku]) * dq - (k > 0 ? b[ku] : 0.0) * dq_prev) / b[ku + 1];
      q_prev = q;
      q = qn;
      dq_prev = dq;
      dq = dqn;
      f += coefficient[k + 1] * q;
      df += coefficient[k + 1] * dq;
    }
    const double w = weight(c);
    return {w * f, w * (weight.log_slope(c) * f + weight.variable_slope(c) * df)};
  }
};

TrialBasis trial_basis(const Grid& grid, const TrialWeight& weight, int k_max) {
  const std::size_t n = grid.c.size();
  std::vector<double> wt(n), p(n, 1.0), prev(n, 0.0), next(n);
  double norm = 0;
  for (std::size_t i = 0; i < n; ++i) {
    // 3D: the shell factor multiplied in the order the shipped 3D table was computed with (bit-identical).
    const double shell = grid.dimension == 3 ? grid.w[i] * 4 * kPi * grid.c[i] * grid.c[i] : grid.shell[i];
    wt[i] = shell * weight(grid.c[i]);
    norm += wt[i];
  }
  TrialBasis basis{weight, std::vector<double>(static_cast<std::size_t>(k_max + 1), 0.0),
                   std::vector<double>(static_cast<std::size_t>(k_max + 2), 0.0), 1 / std::sqrt(norm)};
  for (auto& v : p) v = basis.q0;
  for (int k = 0; k <= k_max; ++k) {
    double a = 0;
    for (std::size_t i = 0; i < n; ++i) a += wt[i] * weight.variable(grid.c[i]) * p[i] * p[i];
    basis.a[static_cast<std::size_t>(k)] = a;
    double b = 0;
    for (std::size_t i = 0; i < n; ++i) {
      next[i] =
          (weight.variable(grid.c[i]) - a) * p[i] - (k > 0 ? basis.b[static_cast<std::size_t>(k)] : 0.0) * prev[i];
      b += wt[i] * next[i] * next[i];
    }
    b = std::sqrt(b);
    basis.b[static_cast<std::size_t>(k + 1)] = b;
    for (std::size_t i = 0; i < n; ++i) {
      prev[i] = p[i];
      p[i] = next[i] / b;
    }
  }
  return basis;
}

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// The trial functions w(c) Q_k(c), k = 0 … k_max, at speed c.
void trial_values(const TrialBasis& basis, int k_max, double c, double* out) {
  basis.values(c, k_max, out);
  const double w = basis.weight(c);
  for (int k = 0; k <= k_max; ++k) out[k] *= w;
}

/// The trial functions w(c) Q_k(c) on the 1-D rule (row i at c_i): the radial nodes on the rule share them.
RowMatrix trial_values_on_rule(const Grid& grid, const TrialBasis& basis, int k_max) {
  RowMatrix f(static_cast<Eigen::Index>(grid.c.size()), k_max + 1);
  for (std::size_t i = 0; i < grid.c.size(); ++i)
    trial_values(basis, k_max, grid.c[i], f.row(static_cast<Eigen::Index>(i)).data());
  return f;
}

/// Returns the HCS collision tensors T_p(k, l) = ∫∫ F_k(c1) F_l(c2) ΔS_p, p, k, l = 0 … k_max (theory.md (9.2)),
/// with F = w Q_k of `basis`. The nodes are first summed over those that share c1 (or, inside a diagonal
/// triangle, c2) on the 1-D rule: T_p = Fᵀ Z_p + Y_pᵀ F with Z_p(i, l) = Σ_{c1 = c_i} K_p F_l(c2) and Y_p
/// likewise, F on the rule; nodes × (k_max + 1)² operations instead of nodes × (k_max + 1)³.
std::vector<Eigen::MatrixXd> collision_tensors(const Grid& grid, const Kernel& kernel, const TrialBasis& basis,
                                               int k_max) {
  const auto kk = static_cast<std::size_t>(k_max + 1), n = grid.c.size();
  const RowMatrix f = trial_values_on_rule(grid, basis, k_max);
  std::vector<double> z(kk * n * kk, 0.0), y(kk * n * kk, 0.0), other(kk);  // [p][i][k]
  for (std::size_t node = 0; node < grid.pairs.size(); ++node) {
    const auto& r = grid.pairs[node];
    const bool first = r.i1 >= 0;  // sum over c2 at c1 = c_{i1}; else over c1 at c2 = c_{i2}
    const int on = first ? r.i1 : r.i2, off = first ? r.i2 : r.i1;
    const double* partner = other.data();
    if (off >= 0)
      partner = f.row(off).data();
    else
      trial_values(basis, k_max, first ? r.c2 : r.c1, other.data());
    const double* ker = kernel.at(node, kScalar);
    double* sums = first ? z.data() : y.data();
    for (std::size_t p = 0; p < kk; ++p) {
      double* row = &sums[(p * n + static_cast<std::size_t>(on)) * kk];
      const double kp = ker[p];
      for (std::size_t l = 0; l < kk; ++l) row[l] += kp * partner[l];
    }
  }
  std::vector<Eigen::MatrixXd> tensor(kk);
  const auto rows = static_cast<Eigen::Index>(n), cols = static_cast<Eigen::Index>(kk);
  for (std::size_t p = 0; p < kk; ++p) {
    const Eigen::Map<const RowMatrix> zp(&z[p * n * kk], rows, cols), yp(&y[p * n * kk], rows, cols);
    tensor[p] = f.transpose() * zp + yp.transpose() * f;
  }
  return tensor;
}

/// Returns L(p, q) = Σ_nodes [φ(c1) G_q(c2) K^partner_p + G_q(c1) φ(c2) K^self_p], p, q = 0 … n_max: the
/// linearised collision operator J*[φ, X] + J*[X, φ] of the mode with trial functions G = w Q of `basis`
/// between the tests of the families `self`, `partner` (theory.md (10.12)–(10.14)); φ on the 1-D rule and
/// its value at any speed given. Summed over the nodes that share the speed of G first, as
/// collision_tensors.
template <class PhiAt>
Eigen::MatrixXd linearised_operator(const Grid& grid, const Kernel& kernel, Family self, Family partner,
                                    const TrialBasis& basis, int n_max, const std::vector<double>& phi_on_rule,
                                    PhiAt&& phi_at) {
  const auto nn = static_cast<std::size_t>(n_max + 1), n = grid.c.size();
  const RowMatrix g = trial_values_on_rule(grid, basis, n_max);
  RowMatrix z = RowMatrix::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(nn));  // [i][p]
  Eigen::MatrixXd l = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(nn), static_cast<Eigen::Index>(nn));
  std::vector<double> g_off(nn);
  for (std::size_t node = 0; node < grid.pairs.size(); ++node) {
    const auto& r = grid.pairs[node];
    const double phi1 = r.i1 >= 0 ? phi_on_rule[static_cast<std::size_t>(r.i1)] : phi_at(r.c1);
    const double phi2 = r.i2 >= 0 ? phi_on_rule[static_cast<std::size_t>(r.i2)] : phi_at(r.c2);
    // X at c2 (the partner family, weight φ(c1)) and X at c1 (the self family, weight φ(c2)).
    for (const auto& [index, speed, phi, family] :
         {std::tuple{r.i2, r.c2, phi1, partner}, std::tuple{r.i1, r.c1, phi2, self}}) {
      const double* ker = kernel.at(node, family);
      if (index >= 0) {
        double* row = z.row(index).data();
        for (std::size_t p = 0; p < nn; ++p) row[p] += phi * ker[p];
        continue;
      }
      trial_values(basis, n_max, speed, g_off.data());
      for (std::size_t q = 0; q < nn; ++q)
        for (std::size_t p = 0; p < nn; ++p)
          l(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(q)) += phi * ker[p] * g_off[q];
    }
  }
  l.noalias() += z.transpose() * g;
  return l;
}

/// The collisional-transfer tables of collisional_transfer.hpp over the tail-basis HCS φ instead of a Sonine
/// sum (theory.md §15.8): f_M Σ a_k S_k → φ, f_M Σ a_l D_l c → ∂_c φ = φ'(c) ĉ, f_M Σ a_l T_l → −½∂_c·(cφ)
/// = −½(d φ + c φ'), and a trial function f_M S_q → F_q of the mode's basis.
struct DenseTransfer {
  std::vector<double> shear_source, heat_source_temperature, heat_source_density, scalar_source;  // [p]
  std::vector<double> shear_flux, heat_flux, cooling_scalar;  // [q]: tensor, vector, scalar (HCS basis) trials
  double shear_gradient = 0, heat_gradient_temperature = 0, heat_gradient_density = 0, cooling_gradient = 0;
};

DenseTransfer dense_transfer_sums(const Grid& grid, const detail::TransferKernel& kernel, const TrialBasis& hcs,
                                  const Eigen::VectorXd& phi_coefficients, const TrialBasis& vector_basis,
                                  const TrialBasis& tensor_basis, int n_max) {
  const int k_max = n_max + 1;
  const auto nn = static_cast<std::size_t>(n_max + 1), kk = static_cast<std::size_t>(k_max + 1);
  const double d = grid.dimension;
  DenseTransfer t;
  t.shear_source.assign(nn, 0.0);
  t.heat_source_temperature.assign(nn, 0.0);
  t.heat_source_density.assign(nn, 0.0);
  t.scalar_source.assign(kk, 0.0);
  t.shear_flux.assign(nn, 0.0);
  t.heat_flux.assign(nn, 0.0);
  t.cooling_scalar.assign(kk, 0.0);
  // φ, φ' on the 1-D rule (the nodes off it, inside the diagonal triangles, directly).
  std::vector<std::pair<double, double>> on_rule(grid.c.size());
  for (std::size_t i = 0; i < grid.c.size(); ++i) on_rule[i] = hcs.function_and_slope(grid.c[i], phi_coefficients);
  std::vector<double> fv(nn), ft(nn), fs(kk);
  for (std::size_t node = 0; node < grid.pairs.size(); ++node) {
    const auto& r = grid.pairs[node];
    const double phi1 = r.i1 >= 0 ? on_rule[static_cast<std::size_t>(r.i1)].first
                                  : hcs.function_and_slope(r.c1, phi_coefficients).first;
    const auto [phi2, slope2] =
        r.i2 >= 0 ? on_rule[static_cast<std::size_t>(r.i2)] : hcs.function_and_slope(r.c2, phi_coefficients);
    const double gradient2 = slope2 / r.c2;                         // ∂_c φ = (φ'/c) c
    const double temperature2 = -0.5 * (d * phi2 + r.c2 * slope2);  // −½∂_c·(cφ)
    trial_values(vector_basis, n_max, r.c2, fv.data());
    trial_values(tensor_basis, n_max, r.c2, ft.data());
    trial_values(hcs, k_max, r.c2, fs.data());
    const double* shear = kernel.family(node, detail::kTransferShearSource);
    const double* heat = kernel.family(node, detail::kTransferHeatSource);
    const double* scalar = kernel.family(node, detail::kTransferScalarSource);
    const double* v = kernel.scalars(node);
    for (std::size_t p = 0; p < nn; ++p) {
      t.shear_source[p] += phi1 * gradient2 * shear[p];
      t.heat_source_temperature[p] += phi1 * temperature2 * heat[p];
      t.heat_source_density[p] += phi1 * phi2 * heat[p];
      t.shear_flux[p] += phi1 * ft[p] * v[detail::kTransferShearFlux];
      t.heat_flux[p] += phi1 * fv[p] * v[detail::kTransferHeatFlux];
    }
    for (std::size_t p = 0; p < kk; ++p) {
      t.scalar_source[p] += phi1 * gradient2 * scalar[p];
      t.cooling_scalar[p] += phi1 * fs[p] * v[detail::kTransferCoolingScalar];
    }
    t.shear_gradient += phi1 * gradient2 * v[detail::kTransferShearGradient];
    t.heat_gradient_temperature += phi1 * temperature2 * v[detail::kTransferHeatGradient];
    t.heat_gradient_density += phi1 * phi2 * v[detail::kTransferHeatGradient];
    t.cooling_gradient += phi1 * gradient2 * v[detail::kTransferCoolingGradient];
  }
  return t;
}

/// Returns the solution x of m x = rhs with every row scaled to unit norm first. The rows of the Sonine
/// tests S_p differ in size by up to 1e15 at N ≥ 11 and α = 0.2 (the tail reaches c ≈ 30 there), and
/// full-pivoting LU of the unscaled matrix then loses the small rows: the tensor mode broke down at
/// N = 11 (2D) and 12 (3D) with a condition number 1.6e15, 2e6 after the scaling (theory.md §10.6).
Eigen::VectorXd solve_equilibrated(const Eigen::MatrixXd& m, const Eigen::VectorXd& rhs) {
  const Eigen::VectorXd scale = m.rowwise().norm().cwiseInverse();
  return (scale.asDiagonal() * m).fullPivLu().solve(scale.asDiagonal() * rhs);
}

/// One resolution N with the weight's exponent `tail` and the trial space `trial` (TrialWeight): the HCS
/// with trial/test degree K = N + 1 (Newton from `start`, φ on the 1-D rule — the previous solution, or
/// the Maxwellian if empty; the solution is left there), then, if `transport`, the three Chapman–Enskog modes
/// with degree N (theory.md (10.12)–(10.14)); with `transfer` (the dense gas `dense`), those of the Enskog gas
/// and its scalar mode (theory.md §15.8).
TailGalerkinValues solve_resolution(const Grid& grid, const Kernel& kernel, double alpha, TailTrialSpace trial,
                                    double tail, int order, bool transport, std::vector<double>& start,
                                    const EnskogState& dense = {}, const detail::TransferKernel* transfer = nullptr) {
  const double d = grid.dimension, m = d / 2 - 1, nu = frequency_factor(grid.dimension);
  const int k_max = order + 1, n_max = order;
  const auto kk = static_cast<std::size_t>(k_max + 1);
  // power_law: HCS and tensor mode c^γ, vector modes c^{γ−2} (theory.md §10.6).
  const bool power_law = trial == TailTrialSpace::power_law && alpha < 1;
  const double gamma = power_law ? hcs_tail_power(grid.dimension, alpha) : 0.0;
  const TrialWeight hcs_weight{tail, gamma, power_law}, vector_weight{tail, power_law ? gamma - 2 : 0.0, power_law},
      tensor_weight{tail, gamma, power_law};
  const TrialBasis basis = trial_basis(grid, hcs_weight, k_max);
  TailGalerkinValues out;
  out.order = order;
  // 1-D moments over the trial functions: ∫S_p F_k, ∫ x S_p' F_k, ∫F_k, ∫x F_k.
  Eigen::MatrixXd sonine_moment(kk, kk), drift(kk, kk);
  Eigen::RowVectorXd mass(kk), energy(kk);
  sonine_moment.setZero();
  drift.setZero();
  mass.setZero();
  energy.setZero();
  std::vector<double> q(kk), s(kk);
  for (std::size_t i = 0; i < grid.c.size(); ++i) {
    const double x = grid.c[i] * grid.c[i];
    const double wt = grid.shell[i] * hcs_weight(grid.c[i]);
    basis.values(grid.c[i], k_max, q.data());
    sonine_values(k_max, m, x, s.data());
    for (std::size_t k = 0; k < kk; ++k) {
      const double f = wt * q[k];
      mass[static_cast<Eigen::Index>(k)] += f;
      energy[static_cast<Eigen::Index>(k)] += x * f;
      for (int p = 0; p <= k_max; ++p) {
        sonine_moment(p, static_cast<Eigen::Index>(k)) += s[static_cast<std::size_t>(p)] * f;
        drift(p, static_cast<Eigen::Index>(k)) += x_derivative(s, p, m) * f;
      }
    }
  }
  const std::vector<Eigen::MatrixXd> tensor = collision_tensors(grid, kernel, basis, k_max);
  // Newton's method on: ∫φ = 1, ∫c²φ = d/2, R_p + (2/d) R_1 ⟨x S_p'⟩_φ = 0 (p ≥ 2; R_1 = R[S_1] = −R[x]).
  Eigen::VectorXd b(kk);
  b.setZero();
  for (std::size_t i = 0; i < grid.c.size(); ++i) {  // the start projected on the basis: b_k = ∫ φ Q_k
    const double x = grid.c[i] * grid.c[i];
    const double phi = start.empty() ? std::pow(kPi, -d / 2) * std::exp(-x) : start[i];
    basis.values(grid.c[i], k_max, q.data());
    for (std::size_t k = 0; k < kk; ++k) b[static_cast<Eigen::Index>(k)] += grid.shell[i] * phi * q[k];
  }
  auto residual = [&](const Eigen::VectorXd& v, Eigen::MatrixXd* jac) {
    Eigen::VectorXd f(kk);
    const double r1 = v.dot(tensor[1] * v);
    const Eigen::VectorXd grad_r1 = (tensor[1] + tensor[1].transpose()) * v;
    f[0] = mass.dot(v) - 1;
    f[1] = energy.dot(v) - d / 2;
    if (jac) {
      jac->row(0) = mass;
      jac->row(1) = energy;
    }
    for (int p = 2; p <= k_max; ++p) {
      const double dp = drift.row(p).dot(v);
      f[p] = v.dot(tensor[static_cast<std::size_t>(p)] * v) + (2 / d) * r1 * dp;
      if (jac)
        jac->row(p) =
            ((tensor[static_cast<std::size_t>(p)] + tensor[static_cast<std::size_t>(p)].transpose()) * v).transpose() +
            (2 / d) * (dp * grad_r1.transpose() + r1 * drift.row(p));
    }
    return f;
  };
  Eigen::MatrixXd jac(kk, kk);
  bool converged = false;
  for (int it = 0; it < 100 && !converged; ++it) {
    const Eigen::VectorXd f = residual(b, &jac);
    const Eigen::VectorXd step = solve_equilibrated(jac, f);
    double lambda = 1;
    for (int h = 0; h < 30; ++h, lambda /= 2)
      if (residual(b - lambda * step, nullptr).norm() < f.norm() || f.norm() < 1e-13) break;
    b -= lambda * step;
    converged = step.norm() * lambda < 1e-11 * b.norm();
  }
  // Accept when every equation holds to 1e-9 of the size of its terms (high Sonine rows are large).
  const Eigen::VectorXd final_residual = residual(b, nullptr);
  bool small = std::fabs(final_residual[0]) < 1e-9 && std::fabs(final_residual[1]) < 1e-9;
  const Eigen::VectorXd ab = b.cwiseAbs();
  const double r1_size = ab.dot(tensor[1].cwiseAbs() * ab);
  for (int p = 2; p <= k_max; ++p) {
    const double size = ab.dot(tensor[static_cast<std::size_t>(p)].cwiseAbs() * ab) +
                        (2 / d) * r1_size * std::fabs(drift.row(p).cwiseAbs().dot(ab));
    small = small && std::fabs(final_residual[p]) <= 1e-9 * size;
  }
  if (!converged || !small) return out;
  // Elastic: no cooling, exactly (the quadrature leaves r1 at ±1e-17).
  const double r1 = b.dot(tensor[1] * b), zeta_r = alpha == 1 ? 0.0 : std::max(0.0, (2 / d) * r1);
  if (!((2 / d) * r1 > -1e-12)) return out;  // a heating "HCS": no solution
  auto cumulant = [&](int k) {
    const double norm2 = std::tgamma(d / 2 + k) / (std::tgamma(k + 1.0) * std::tgamma(d / 2));
    if (k <= k_max) return sonine_moment.row(k).dot(b) / norm2;
    double sum = 0;  // beyond the test degree: directly on the 1-D rule
    std::vector<double> sk(static_cast<std::size_t>(k + 1));
    for (std::size_t i = 0; i < grid.c.size(); ++i) {
      const double x = grid.c[i] * grid.c[i];
      basis.values(grid.c[i], k_max, q.data());
      sonine_values(k, m, x, sk.data());
      double phi = 0;
      for (std::size_t j = 0; j < kk; ++j) phi += b[static_cast<Eigen::Index>(j)] * q[j];
      sum += grid.shell[i] * hcs_weight(grid.c[i]) * phi * sk[static_cast<std::size_t>(k)];
    }
    return sum / norm2;
  };
  start.resize(grid.c.size());
  for (std::size_t i = 0; i < grid.c.size(); ++i) {
    basis.values(grid.c[i], k_max, q.data());
    double phi = 0;
    for (std::size_t j = 0; j < kk; ++j) phi += b[static_cast<Eigen::Index>(j)] * q[j];
    start[i] = phi * hcs_weight(grid.c[i]);
  }
  // Elastic: the HCS is the Maxwellian, a_k = 0 exactly (the solution is it to round-off).
  out.a2 = alpha == 1 ? 0.0 : cumulant(2);
  out.a3 = alpha == 1 ? 0.0 : cumulant(3);
  out.cooling_rate = zeta_r * (d + 2) / (4 * nu);  // theory.md (9.4)
  out.tail_exponent = zeta_r > 0 ? 2 * loss_rate_factor(grid.dimension) / zeta_r : INFINITY;
  if (!transport) {  // a pass that only sets the weight's exponent
    out.solved = true;
    return out;
  }

  // Chapman–Enskog: trial F_q c_i (vector), F_q Y2 (tensor), q = 0 … N; tests c_i S_p^{(d/2)}, Y2 S_p^{(d/2+1)}.
  const auto nn = static_cast<std::size_t>(n_max + 1);
  const auto ni = static_cast<Eigen::Index>(nn);
  const TrialBasis vector_basis = trial_basis(grid, vector_weight, n_max);
  const TrialBasis tensor_basis = trial_basis(grid, tensor_weight, n_max);
  std::vector<double> qv(nn), qt(nn);
  Eigen::MatrixXd mv = Eigen::MatrixXd::Zero(ni, ni), dv = mv, dt = mv;
  Eigen::VectorXd ua = Eigen::VectorXd::Zero(ni), ub = ua, ue = ua, vector_flux = ua, tensor_flux = ua;
  Eigen::VectorXd pressure_source = ua;  // ∫φ((d/2)S_p + xS_p'): the part of U^A, U^B ∝ p* (theory.md (15.6))
  std::vector<double> sv(nn), st(nn);
  for (std::size_t i = 0; i < grid.c.size(); ++i) {
    const double c = grid.c[i], x = c * c;
    const double wv = grid.shell[i] * vector_weight(c), wt = grid.shell[i] * tensor_weight(c);
    basis.values(c, k_max, q.data());
    vector_basis.values(c, n_max, qv.data());
    tensor_basis.values(c, n_max, qt.data());
    sonine_values(n_max, m + 1, x, sv.data());
    sonine_values(n_max, m + 2, x, st.data());
    double phi = 0;
    for (std::size_t j = 0; j < kk; ++j) phi += b[static_cast<Eigen::Index>(j)] * q[j];
    phi *= grid.shell[i] * hcs_weight(c);
    for (int p = 0; p <= n_max; ++p) {
      const auto pu = static_cast<std::size_t>(p);
      const double xv = x_derivative(sv, p, m + 1), xt = x_derivative(st, p, m + 2);
      ua[p] += phi * ((d / 2) * sv[pu] + xv - x * sv[pu] - x * xv);  // theory.md (10.5)
      ub[p] += phi * ((d / 2) * sv[pu] + xv - x * sv[pu]);
      pressure_source[p] += phi * ((d / 2) * sv[pu] + xv);
      ue[p] -= phi * x * ((d + 1 - 2 / d) * st[pu] + 2 * ((d - 1) / d) * xt);
      for (int k = 0; k <= n_max; ++k) {
        const double fv = wv * qv[static_cast<std::size_t>(k)], ft = wt * qt[static_cast<std::size_t>(k)];
        mv(p, k) += fv * x * sv[pu];
        dv(p, k) += fv * (x * sv[pu] + 2 * x * xv);
        dt(p, k) += ft * x * x * (st[pu] + 2 * xt);
      }
    }
    for (int k = 0; k <= n_max; ++k) {
      vector_flux[k] += wv * qv[static_cast<std::size_t>(k)] * x * x;
      tensor_flux[k] += wt * qt[static_cast<std::size_t>(k)] * x * x;
    }
  }
  // 𝓛*X = −(J*[φ, X] + J*[X, φ]), φ on the rule being `start`.
  auto phi_at = [&](double c) {
    basis.values(c, k_max, q.data());
    double phi = 0;
    for (std::size_t j = 0; j < kk; ++j) phi += b[static_cast<Eigen::Index>(j)] * q[j];
    return phi * hcs_weight(c);
  };
  const Eigen::MatrixXd lv =
      -linearised_operator(grid, kernel, kVectorSelf, kVectorPartner, vector_basis, n_max, start, phi_at);
  const Eigen::MatrixXd lt =
      -linearised_operator(grid, kernel, kTensorSelf, kTensorPartner, tensor_basis, n_max, start, phi_at);
  // Enskog (theory.md §15.8): the operator and ζ_r carry χ (the solutions divide by it), the kinetic sources
  // gain the pressure terms (15.6) and the collisional-transfer sources, the fluxes their collisional parts.
  const bool is_dense = transfer != nullptr;
  const double chi = is_dense ? dense.chi : 1.0, phi_chi = dense.packing_fraction * chi;
  const double dlnchi = is_dense ? dense.phi_dchi / chi : 0.0;  // φ ∂ln χ/∂φ
  DenseTransfer dt_sums;
  if (is_dense) {
    dt_sums = dense_transfer_sums(grid, *transfer, basis, b, vector_basis, tensor_basis, n_max);
    const double e = collisional_transfer_factor(grid.dimension), inv = 1 / (1 + alpha);
    const double p_star = dense.pressure(grid.dimension, alpha);
    const double phi_dp = std::pow(2.0, d - 2) * (1 + alpha) * phi_chi * (1 + dlnchi);  // φ ∂p*/∂φ
    for (int p = 0; p <= n_max; ++p) {
      ua[p] += (p_star - 1) * pressure_source[p] + e * phi_chi * inv * dt_sums.heat_source_temperature[p];  // (15.6)
      ub[p] += (p_star + phi_dp - 1) * pressure_source[p] +
               e * phi_chi * (1 + 0.5 * dlnchi) * inv * dt_sums.heat_source_density[p];
      ue[p] -= e * phi_chi * inv * dt_sums.shear_source[p];                                                 // (15.4)
      vector_flux[p] += e * phi_chi * inv * dt_sums.heat_flux[p];                                           // (15.10)
      tensor_flux[p] += 0.5 * (1 + alpha) * d / (d - 1) * e * phi_chi * inv * inv * dt_sums.shear_flux[p];  // (15.7)
    }
  }
  // Row p = 0 of the vector modes is the solubility condition ∫ c·c X = 0 (no momentum).
  Eigen::MatrixXd la = lv - (zeta_r / 2) * (dv + mv), lb = lv - (zeta_r / 2) * dv;
  la.row(0) = mv.row(0);
  lb.row(0) = mv.row(0);
  ua[0] = 0;
  const Eigen::VectorXd heat = solve_equilibrated(la, ua) / chi;
  // The A→B coupling comes from ∂_t^(0) of the density gradient: (1 + φ∂_φ ln χ) in the dense gas (§15.3).
  Eigen::VectorXd rb = ub / chi + zeta_r * (1 + dlnchi) * (mv * heat);
  rb[0] = 0;
  const Eigen::VectorXd density = solve_equilibrated(lb, rb);
  const Eigen::VectorXd shear = solve_equilibrated(lt - (zeta_r / 2) * ((d - 1) / d) * dt, ue) / chi;
  const double kappa_factor = -16 * (d - 1) * nu / (d * d * (d + 2) * (d + 2));  // theory.md (10.6)
  out.thermal_conductivity = kappa_factor * vector_flux.dot(heat);
  // Elastic: μ* = 0 exactly (ζ_r = 0 and the source U^B of (10.5) vanishes for the Maxwellian).
  out.density_heat_coefficient = alpha == 1 ? 0.0 : kappa_factor * vector_flux.dot(density);
  out.shear_viscosity = -8 * nu / (d * (d + 2) * (d + 2)) * tensor_flux.dot(shear);  // theory.md (10.7)
  if (is_dense) {
    const double g_d = collisional_gradient_factor(grid.dimension), phi = dense.packing_fraction;
    const double gradient = g_d * (1 + alpha) * chi * phi * phi / (1 + alpha);
    out.thermal_conductivity += -8 * (d - 1) / d * gradient * dt_sums.heat_gradient_temperature;  // (15.11)
    if (alpha != 1) out.density_heat_coefficient += -8 * (d - 1) / d * gradient * dt_sums.heat_gradient_density;
    out.shear_viscosity += 2 * gradient * dt_sums.shear_gradient;              // (15.8)
    out.bulk_viscosity = (d + 2) / d * 2 * gradient * dt_sums.shear_gradient;  // (15.9)
    out.cooling_rate *= chi;                                                   // (15.1)
    if (alpha != 1) {  // the scalar mode and ζ_U (15.12), (15.13); zero at α = 1
      // Trials F_0 … F_{N+1} of the HCS basis, tests S_0 … S_{N+1}; rows 0, 1 are the solubility conditions
      // (no mass, no energy), as the Sonine scheme's trials S_2 … S_{N+1}.
      const Eigen::MatrixXd ls = -linearised_operator(grid, kernel, kScalar, kScalar, basis, k_max, start, phi_at);
      Eigen::MatrixXd scalar_matrix = ls + (zeta_r / 2) * (sonine_moment - 2 * drift);
      scalar_matrix.row(0) = mass;
      scalar_matrix.row(1) = energy;
      const double e = collisional_transfer_factor(grid.dimension), inv = 1 / (1 + alpha);
      const double p_star = dense.pressure(grid.dimension, alpha);
      Eigen::VectorXd u_zeta = drift * b, u_fixed(kk);  // ⟨x S_p'⟩_φ
      for (std::size_t p = 0; p < kk; ++p) {
        const auto pi = static_cast<Eigen::Index>(p);
        u_fixed[pi] = -2 / d * (1 - p_star) * u_zeta[pi] - e * phi_chi * inv / d * dt_sums.scalar_source[p];
      }
      u_zeta.head(2).setZero();
      u_fixed.head(2).setZero();
      const Eigen::VectorXd delta_fixed = solve_equilibrated(scalar_matrix, u_fixed) / chi;
      const Eigen::VectorXd delta_zeta = solve_equilibrated(scalar_matrix, u_zeta) / chi;
      // ζ11 = (2(1−α²)χ/d) Σ_q δ_q ⟨φ, F_q⟩_{+2}, ν for the raw operator's units.
      Eigen::VectorXd cooling(kk);
      for (std::size_t q = 0; q < kk; ++q)
        cooling[static_cast<Eigen::Index>(q)] = nu * 2 * (1 - alpha * alpha) * chi / d * dt_sums.cooling_scalar[q];
      const double zeta10 = -(1 - alpha) * e * phi_chi / (2 * d * d) * dt_sums.cooling_gradient;
      out.cooling_rate_first_order = (zeta10 + cooling.dot(delta_fixed)) / (1 - cooling.dot(delta_zeta));
    }
  }
  out.solved = std::isfinite(out.thermal_conductivity) && std::isfinite(out.shear_viscosity) &&
               std::isfinite(out.density_heat_coefficient);
  return out;
}

}  // namespace

double hcs_tail_power(int dimension, double alpha) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  if (!(alpha > 0 && alpha <= 1))
    throw std::invalid_argument("alpha: must be a number in (0, 1], got " + std::to_string(alpha));
  // (ζ_r/2)(d + γ) φ, the scaling term beyond its leading −β c φ, balances the gain G φ from grazing
  // collisions of a fast particle with a thermal one: c'² = c²(1 − k s²), s = ĝ·σ̂, so the gain is
  // φ(c) c ∫dσ̂ s exp(−A c k s²/2) = (2π/(A k)) φ (3D), (2/(A k)) φ (2D); with A = 2β/ζ_r, β = π (3D), 2 (2D).
  const double k = (1 + alpha) * (3 - alpha) / 4;
  return -dimension + (dimension == 3 ? 2.0 : 1.0) / k;
}

namespace {

/// tail_galerkin_sequence, also recording each resolution's φ_N on the nodes if `profiles` is given.
std::vector<TailGalerkinValues> run_tail_sequence(int dimension, double alpha, int max_order, TailTrialSpace trial,
                                                  std::vector<TailHcsProfile>* profiles, const EnskogState& dense) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  if (!(alpha > 0 && alpha <= 1))
    throw std::invalid_argument("alpha: must be a number in (0, 1], got " + std::to_string(alpha));
  if (max_order < 1 || max_order > kTailGalerkinMaxOrder)
    throw std::invalid_argument("order: must be an integer in [1, " + std::to_string(kTailGalerkinMaxOrder) +
                                "] for the tail scheme, got " + std::to_string(max_order));
  const double d = dimension, nu = frequency_factor(dimension);
  // First guess of A from van Noije–Ernst's a2 and ζ* (theory.md §9.2).
  const double a2 = 16 * (1 - alpha) * (1 - 2 * alpha * alpha) /
                    (9 + 24 * d - alpha * (41 - 8 * d) + 30 * alpha * alpha * (1 - alpha));
  const double zeta0 = (d + 2) / (4 * d) * (1 - alpha * alpha) * (1 + 3 * a2 / 16);
  const double tail0 = alpha == 1 ? INFINITY : 2 * loss_rate_factor(dimension) * (d + 2) / (4 * nu * zeta0);
  const int p_max = max_order + 1, degree = 2 * p_max + 2 * dimension + 4;
  // The grid reaches where (1 + c)^degree w(c) has fallen below e^{−kNegligible} past its peak (with a
  // tail longer than the first guess's by 25 %, for margin).
  const double reach = 0.8 * tail0;
  double c_max = 4, best = -INFINITY;
  for (double c = 0.25; c < 400; c += 0.25) {
    const double v = degree * std::log1p(c) + log_weight(c, reach);
    best = std::max(best, v);
    if (v < best && v < -kNegligible) {
      c_max = std::max(c, 4.0);
      break;
    }
  }
  const Grid grid = make_grid(dimension, c_max, reach, degree);
  const Kernel kernel = collision_kernel(grid, alpha, p_max);
  // Enskog: the collisional-transfer kernel on the same nodes (theory.md §15.8), independent of φ and χ.
  std::optional<detail::TransferKernel> transfer;
  if (dense.packing_fraction > 0) {
    std::vector<detail::TransferNode> nodes;
    nodes.reserve(grid.pairs.size());
    for (const auto& r : grid.pairs) nodes.push_back({r.c1, r.c2, r.weight});
    transfer = detail::collisional_transfer_kernel(dimension, alpha, p_max, nodes);
  }
  std::vector<TailGalerkinValues> out;
  std::vector<double> start;  // φ of the previous solution on the 1-D rule (empty: the Maxwellian)
  for (int n = 1; n <= max_order; ++n) {
    double tail = tail0, used = tail0;
    TailGalerkinValues v;
    for (int pass = 0; pass < kWeightPasses; ++pass) {
      used = tail;
      // Only the last pass solves the Chapman–Enskog modes (the others set A of the weight).
      const bool last = pass == kWeightPasses - 1 || alpha == 1;
      v = solve_resolution(grid, kernel, alpha, trial, tail, n, last, start, dense,
                           last && transfer ? &*transfer : nullptr);
      if (!v.solved || alpha == 1) break;
      tail = v.tail_exponent;
    }
    out.push_back(v);
    if (profiles) profiles->push_back({v, used, grid.c, v.solved ? start : std::vector<double>{}});
  }
  return out;
}

}  // namespace

std::vector<TailGalerkinValues> tail_galerkin_sequence(int dimension, double alpha, int max_order, TailTrialSpace trial,
                                                       const EnskogState& dense) {
  if (dimension == 2 || dimension == 3) {  // the dimension itself is checked by run_tail_sequence
    const double phi_max = max_packing_fraction(dimension).to_double();
    if (!(dense.packing_fraction >= 0 && dense.packing_fraction <= phi_max && dense.chi >= 1))
      throw std::invalid_argument("packing_fraction: must be a number in [0, " + std::to_string(phi_max) +
                                  "] with a contact value chi >= 1, got " + std::to_string(dense.packing_fraction));
  }
  return run_tail_sequence(dimension, alpha, max_order, trial, nullptr, dense);
}

std::vector<TailHcsProfile> tail_galerkin_hcs_profiles(int dimension, double alpha, int max_order,
                                                       TailTrialSpace trial) {
  std::vector<TailHcsProfile> profiles;
  run_tail_sequence(dimension, alpha, max_order, trial, &profiles, {});
  return profiles;
}

}  // namespace gkt
