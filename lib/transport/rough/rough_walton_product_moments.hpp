// Internal: the moments of products of quadratic forms of the Walton gas's conditioned Gaussian at one τ
// (docs/theory.md §19.20, (19.80)–(19.81)) and their (u, |g_c,t|) quadrature, shared by the Navier–Stokes
// elements (rough_walton_sonine.cpp, §19.20) and the Sonine HCS (rough_walton_sonine_hcs.cpp, §19.25; with the
// orientation forms c·ŵ of spheres, §19.29).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <vector>

#include <Eigen/Dense>

#include "transport/rough/rough_walton_quadrature.hpp"

namespace gkt::detail {

/// The nine forms of the elements: x1 = c1², y1 = ŵ1², x2, y2, x1' = c1'², y1' = ŵ1'², and the dot products
/// c1·c1', c2·c1, c2·c1' (theory.md §19.20); then the orientation forms f1 = c1·ŵ1, f2 = c2·ŵ2, f1' = c1'·ŵ1' of
/// the oriented HCS (spheres only; identically 0 for disks, theory.md §19.29).
enum WaltonForm { kX1, kY1, kX2, kY2, kX1p, kY1p, kD11p, kD21, kD21p, kF1, kF2, kF1p, kForms };

/// A matrix of the conditioned Gaussian's size (12 × 12 for spheres, 6 × 6 for disks), without heap storage.
using WaltonMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, 12, 12>;

/// One form q = εᵀAε + (Bp)ᵀε + pᵀQp on the conditioned Gaussian ε ~ N(0, C), p = (u, G, H), H = η_t G.
struct QuadraticForm {
  WaltonMatrix a;
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::ColMajor, 12, 3> b;
  Eigen::Matrix3d q;
};

/// The moments of products of the nine forms at fixed τ, from their joint cumulants (theory.md (19.71), (19.80)):
/// each cumulant is a constant plus pᵀMp, computed once; a moment is Σ_{T ∋ first} κ(T) E[rest] over sub-multisets.
class ProductMoments {
 public:
  ProductMoments(int d, double tau, double eta_n, double kappa) {
    const detail::ConditionedGaussian g = detail::condition(d, tau);
    const int n = g.n, dr = d == 3 ? 3 : 1, w1 = 2 * d, w2 = 2 * d + dr;
    c_.resize(n, n);
    Eigen::MatrixXd gain = Eigen::MatrixXd::Zero(n, 3);
    for (int i = 0; i < n; ++i) {
      gain(i, 0) = g.gain[static_cast<std::size_t>(i)][0];
      gain(i, 1) = g.gain[static_cast<std::size_t>(i)][1];
      for (int j = 0; j < n; ++j) c_(i, j) = g.cov[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    }
    // A slot: selector L (k × n) and the collision's shift D (k × 3); its vector is L X − D p, X = gain p + ε.
    struct Slot {
      Eigen::MatrixXd l, shift;
    };
    const auto slot = [&](int first, int size) {
      Slot s{Eigen::MatrixXd::Zero(size, n), Eigen::MatrixXd::Zero(size, 3)};
      for (int k = 0; k < size; ++k) s.l(k, first + k) = 1;
      return s;
    };
    const Slot v1 = slot(0, d), v2 = slot(d, d), s1 = slot(w1, dr), s2 = slot(w2, dr);
    Slot v1p = v1, s1p = s1;
    v1p.shift(0, 0) = eta_n;                   // −η_n u σ̂ (σ̂ = e0)
    v1p.shift(1, 2) = 1;                       // −η_t G e1 = −H e1
    s1p.shift(d == 3 ? 2 : 0, 2) = 1 / kappa;  // −(H/κ) σ̂ × e1 (disks: the scalar)
    // q = (L_a ε + P_a p)ᵀ w (L_b ε + P_b p), P = L·gain − D.
    const auto form = [&](const Slot& x, const Slot& y, double w) {
      const Eigen::MatrixXd px = x.l * gain - x.shift, py = y.l * gain - y.shift;
      QuadraticForm f;
      f.a = 0.5 * w * (x.l.transpose() * y.l + y.l.transpose() * x.l);
      f.b = w * (y.l.transpose() * px + x.l.transpose() * py);
      const Eigen::Matrix3d q = w * px.transpose() * py;
      f.q = 0.5 * (q + q.transpose());
      return f;
    };
    forms_ = {form(v1, v1, 1),         form(s1, s1, 1 / tau), form(v2, v2, 1), form(s2, s2, 1 / tau), form(v1p, v1p, 1),
              form(s1p, s1p, 1 / tau), form(v1, v1p, 1),      form(v2, v1, 1), form(v2, v1p, 1)};
    // c·ŵ = c·w/√τ (ŵ = w/√τ, y = ŵ²); disks have no such form (ŵ ⊥ the plane of c): the zero form.
    const double root = 1 / std::sqrt(tau);
    for (const auto& [v, s] : {std::pair{v1, s1}, std::pair{v2, s2}, std::pair{v1p, s1p}})
      forms_.push_back(d == 3 ? form(v, s, root) : form(v1, v1, 0));
    for (const QuadraticForm& f : forms_) ac_.push_back(f.a * c_);
  }

  /// Registers the moment of a multiset of forms (any order); returns its index in evaluate()'s output.
  int moment(std::vector<int> forms) {
    std::sort(forms.begin(), forms.end());
    if (const auto it = moment_index_.find(forms); it != moment_index_.end()) return it->second;
    if (forms.empty()) {  // the empty product: 1 (no terms)
      moments_.emplace_back();
      return moment_index_[forms] = static_cast<int>(moments_.size()) - 1;
    }
    // Sub-multisets T containing forms[0]: counts t_f ≤ m_f, t_first ≥ 1; weight = the number of position subsets.
    std::array<int, kForms> mult{};
    for (int f : forms) ++mult[static_cast<std::size_t>(f)];
    const int first = forms[0];
    std::vector<Term> terms;
    std::array<int, kForms> take{};
    const auto binomial = [](int m, int k) {
      double r = 1;
      for (int i = 1; i <= k; ++i) r = r * (m - k + i) / i;
      return r;
    };
    const auto recurse = [&](auto&& self, int f) -> void {
      if (f == kForms) {
        if (take[static_cast<std::size_t>(first)] == 0) return;
        std::vector<int> t, rest;
        double count = 1;
        for (int g = 0; g < kForms; ++g) {
          const int m = mult[static_cast<std::size_t>(g)], k = take[static_cast<std::size_t>(g)];
          count *= g == first ? binomial(m - 1, k - 1) : binomial(m, k);
          for (int i = 0; i < k; ++i) t.push_back(g);
          for (int i = k; i < m; ++i) rest.push_back(g);
        }
        terms.push_back({count, cumulant(t), rest.empty() ? -1 : moment(rest)});
        return;
      }
      for (int k = 0; k <= mult[static_cast<std::size_t>(f)]; ++k) {
        take[static_cast<std::size_t>(f)] = k;
        self(self, f + 1);
      }
      take[static_cast<std::size_t>(f)] = 0;
    };
    recurse(recurse, 0);
    moments_.push_back(std::move(terms));
    return moment_index_[forms] = static_cast<int>(moments_.size()) - 1;
  }

  /// Returns the number of registered moments.
  [[nodiscard]] std::size_t size() const { return moments_.size(); }

  /// Fills `out` with every registered moment at p = (u, G, H).
  void evaluate(const Eigen::Vector3d& p, std::vector<double>& out) const {
    cumulant_values_.resize(constant_.size());
    for (std::size_t i = 0; i < constant_.size(); ++i) cumulant_values_[i] = constant_[i] + p.dot(quadratic_[i] * p);
    out.resize(moments_.size());
    for (std::size_t m = 0; m < moments_.size(); ++m) {
      double sum = moments_[m].empty() ? 1.0 : 0.0;
      for (const Term& t : moments_[m])
        sum += t.count * cumulant_values_[static_cast<std::size_t>(t.cumulant)] *
               (t.rest < 0 ? 1.0 : out[static_cast<std::size_t>(t.rest)]);
      out[m] = sum;
    }
  }

 private:
  struct Term {
    double count;
    int cumulant, rest;
  };

  /// Registers the joint cumulant of a sorted multiset: (19.71) with the linear terms Bp,
  ///   κ_1 = tr(AC) + pᵀQp,  κ_n = (2^{n−1}/n) Σ_orderings tr(A C ⋯ A C) + 2^{n−3} Σ_orderings (Bp)ᵀ C A C ⋯ A C (Bp),
  /// summed over the distinct orderings of the multiset, each counted Π m_f! times.
  int cumulant(const std::vector<int>& forms) {
    if (const auto it = cumulant_index_.find(forms); it != cumulant_index_.end()) return it->second;
    const std::size_t n = forms.size();
    double constant = 0;
    Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
    if (n == 1) {
      const QuadraticForm& f = forms_[static_cast<std::size_t>(forms[0])];
      constant = (f.a * c_).trace();
      m = f.q;
    } else {
      double repeats = 1;
      for (std::size_t i = 0, run = 1; i < n; ++i) {
        run = (i > 0 && forms[i] == forms[i - 1]) ? run + 1 : 1;
        repeats *= static_cast<double>(run);
      }
      const double trace_scale = std::ldexp(1.0, static_cast<int>(n) - 1) / static_cast<double>(n) * repeats;
      const double mean_scale = std::ldexp(1.0, static_cast<int>(n) - 3) * repeats;
      // The distinct orderings depth first, sharing the prefixes of the chain C A_s1 C ⋯ A_s(n−2) C (one 12 × 12
      // product per node of the ordering tree); the last factor closes the trace and the mean chain.
      std::array<int, kForms> left{};
      for (int f : forms) ++left[static_cast<std::size_t>(f)];
      std::vector<WaltonMatrix> prefix(n);  // prefix[i] = C A_s1 C ⋯ A_si C
      prefix[0] = c_;
      int head = 0;
      const auto visit = [&](auto&& self, std::size_t depth) -> void {
        for (int f = 0; f < kForms; ++f) {
          if (left[static_cast<std::size_t>(f)] == 0) continue;
          --left[static_cast<std::size_t>(f)];
          if (depth == 0) {
            head = f;
            self(self, 1);
          } else if (depth + 1 < n) {
            prefix[depth] = prefix[depth - 1] * ac_[static_cast<std::size_t>(f)];
            self(self, depth + 1);
          } else {
            const WaltonMatrix& middle = prefix[n - 2];
            const QuadraticForm &h = forms_[static_cast<std::size_t>(head)], &t = forms_[static_cast<std::size_t>(f)];
            // tr(A_h M A_t C) = Σ_ij (A_h M)_ij (A_t C)_ji.
            constant += trace_scale * (h.a * middle).cwiseProduct(ac_[static_cast<std::size_t>(f)].transpose()).sum();
            m += mean_scale * h.b.transpose() * middle * t.b;
          }
          ++left[static_cast<std::size_t>(f)];
        }
      };
      visit(visit, 0);
    }
    constant_.push_back(constant);
    quadratic_.push_back(0.5 * (m + m.transpose()));
    return cumulant_index_[forms] = static_cast<int>(constant_.size()) - 1;
  }

  WaltonMatrix c_;
  std::vector<WaltonMatrix> ac_;  // A_f C
  std::vector<QuadraticForm> forms_;
  std::map<std::vector<int>, int> cumulant_index_, moment_index_;
  std::vector<double> constant_;
  std::vector<Eigen::Matrix3d> quadratic_;
  std::vector<std::vector<Term>> moments_;
  mutable std::vector<double> cumulant_values_;
};

/// Returns the collision averages (weight Θ(u) u e^{−u²/2} times the density of r = |g_c,t|/√(1 + τ), normalised to 1)
/// of every moment registered in `moments`, by the composite 8-point Gauss–Legendre rule in (u, |g_c,t|) with
/// `panels` panels per piece, the sticking–sliding kink u = (η0/M)|g_c,t| and the |g_c,t| where it leaves the u-range
/// as panel edges (theory.md §19.19, §19.20). μ_f = +inf: every contact sticks.
inline std::vector<double> integrate_walton_moments(const ProductMoments& moments, int d, double alpha, double beta0,
                                                    double kappa, double friction, double tau, int panels) {
  const double eta0 = (1 + beta0) * kappa / (2 * (1 + kappa)), s = std::sqrt(1 + tau);
  const double m = std::isinf(friction) ? friction : friction * (1 + alpha) / 2;
  const double c = std::isinf(m) ? 0 : (m == 0 ? std::numeric_limits<double>::infinity() : eta0 / m);
  std::vector<double> value, total;
  const double upper = 12, edge = c > 0 && std::isfinite(c) ? std::min(upper / (c * s), upper) : upper;
  for (const auto& [lo, hi] : {std::pair{0.0, edge}, std::pair{edge, upper}})
    for_each_gauss_legendre_node(lo, hi, panels, [&](double r, double r_weight) {
      const double big_g = s * r;
      const double density = (d == 3 ? r : std::sqrt(2 / std::numbers::pi)) * std::exp(-r * r / 2);
      const double kink = big_g > 0 ? std::min(c * big_g, upper) : 0.0;
      for (const auto& [u_lo, u_hi] : {std::pair{0.0, kink}, std::pair{kink, upper}})
        for_each_gauss_legendre_node(u_lo, u_hi, panels, [&](double u, double u_weight) {
          const double eta_t = (big_g == 0 || u >= c * big_g) ? eta0 : m * u / big_g;
          moments.evaluate(Eigen::Vector3d(u, big_g, eta_t * big_g), value);
          const double w = r_weight * density * u_weight * u * std::exp(-u * u / 2);
          total.resize(value.size(), 0.0);
          for (std::size_t q = 0; q < value.size(); ++q) total[q] += w * value[q];
        });
    });
  total.resize(moments.size(), 0.0);
  return total;
}

}  // namespace gkt::detail
