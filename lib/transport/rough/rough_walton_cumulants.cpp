#include "gkt/transport/rough/rough_walton_cumulants.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_walton.hpp"
#include "transport/rough/rough_walton_quadrature.hpp"

namespace gkt {

namespace {

/// The six quadratic forms of the linear scheme: x1 = c1², y1 = ŵ1², x2, y2, x1' = c1'², y1' = ŵ1'².
enum Form { kX1, kY1, kX2, kY2, kX1p, kY1p, kForms };

/// A monomial x1^e0 y1^e1 x2^e2 y2^e3 x1'^e4 y1'^e5 (total degree ≤ 4).
using Exponents = std::array<int, kForms>;

/// The joint cumulants and the moments of the six forms on the conditioned Gaussian at fixed τ. Each form is
/// q_f = (ε + m_f)ᵀA_f(ε + m_f), ε ~ N(0, C), with a diagonal A_f and a mean m_f = B_f p linear in
/// p = (u, G, H), H = η_t G (the post-collisional shifts −η_n u σ̂ − η_t g_c,t and −(η_t/κ) σ̂ × g_c,t are
/// linear in u and H). The joint cumulant of q_f1 … q_fn is (theory.md (19.71))
///   κ_1 = tr(A C) + mᵀA m,
///   κ_n = 2^{n−1} Σ_{orderings of f2…fn} tr(A_f1 C A_f2 C … A_fn C)
///       + 2^{n−1} Σ_{orderings of f1…fn} m_f1ᵀ A_f1 C A_f2 C … C A_fn m_fn    (n ≥ 2),
/// a constant plus pᵀM p with a 3 × 3 matrix M fixed at τ; moments are sums over set partitions of products
/// of cumulants.
class FormMoments {
 public:
  FormMoments(int d, double tau, double eta_n, double kappa) {
    const detail::ConditionedGaussian g = detail::condition(d, tau);
    const int n = g.n, dr = d == 3 ? 3 : 1, w1 = 2 * d, w2 = 2 * d + dr;
    Eigen::MatrixXd c(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) c(i, j) = g.cov[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    std::array<Eigen::MatrixXd, kForms> a, b;
    for (int f = 0; f < kForms; ++f) {
      a[f] = Eigen::MatrixXd::Zero(n, n);
      b[f] = Eigen::MatrixXd::Zero(n, 3);
      for (int i = 0; i < n; ++i) {
        b[f](i, 0) = g.gain[static_cast<std::size_t>(i)][0];
        b[f](i, 1) = g.gain[static_cast<std::size_t>(i)][1];
      }
    }
    for (int k = 0; k < d; ++k) a[kX1](k, k) = a[kX1p](k, k) = a[kX2](d + k, d + k) = 1;
    for (int k = 0; k < dr; ++k) {
      a[kY1](w1 + k, w1 + k) = a[kY1p](w1 + k, w1 + k) = 1 / tau;
      a[kY2](w2 + k, w2 + k) = 1 / tau;
    }
    b[kX1p](0, 0) -= eta_n;                          // −η_n u σ̂ (σ̂ = e0)
    b[kX1p](1, 2) -= 1;                              // −η_t G e1 = −H e1
    b[kY1p](w1 + (d == 3 ? 2 : 0), 2) -= 1 / kappa;  // −(η_t/κ) σ̂ × G e1 = −(H/κ) e2 (disks: the scalar)
    std::array<Eigen::MatrixXd, kForms> ac;
    for (int f = 0; f < kForms; ++f) ac[f] = a[f] * c;
    // Chains over every ordered sequence of up to four forms: trace and 3 × 3 mean part.
    const auto chain = [&](const std::vector<int>& s, double& trace, Eigen::Matrix3d& mean) {
      Eigen::MatrixXd p = ac[s[0]];
      for (std::size_t i = 1; i < s.size(); ++i) p = p * ac[s[i]];
      trace = p.trace();
      // m_f1ᵀ A_f1 C A_f2 … C A_fn m_fn: (A_f1 C … A_f(n−1) C) A_fn.
      Eigen::MatrixXd q = a[s[0]];
      for (std::size_t i = 1; i < s.size(); ++i) q = q * c * a[s[i]];
      mean = b[s[0]].transpose() * q * b[s.back()];
    };
    // Cumulants of every multiset of size ≤ 4 (sorted form lists).
    const auto add = [&](const std::vector<int>& multiset) {
      const int k = static_cast<int>(multiset.size());
      std::vector<int> order(multiset.size());
      std::iota(order.begin(), order.end(), 0);
      double constant = 0;
      Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
      if (k == 1) {
        double t = 0;
        chain(multiset, t, m);
        constant = t;
      } else {
        const double scale = std::ldexp(1.0, k - 1);
        do {
          std::vector<int> seq(multiset.size());
          for (std::size_t i = 0; i < seq.size(); ++i) seq[i] = multiset[static_cast<std::size_t>(order[i])];
          double t = 0;
          Eigen::Matrix3d mm;
          chain(seq, t, mm);
          m += scale * mm;
          if (order[0] == 0) constant += scale * t;
        } while (std::next_permutation(order.begin(), order.end()));
      }
      index_[multiset] = static_cast<int>(constant_.size());
      constant_.push_back(constant);
      quadratic_.push_back(0.5 * (m + m.transpose()));
    };
    for (int f0 = 0; f0 < kForms; ++f0) {
      add({f0});
      for (int f1 = f0; f1 < kForms; ++f1) {
        add({f0, f1});
        for (int f2 = f1; f2 < kForms; ++f2) {
          add({f0, f1, f2});
          for (int f3 = f2; f3 < kForms; ++f3) add({f0, f1, f2, f3});
        }
      }
    }
  }

  /// Registers a monomial; returns its index among the moments evaluate() fills.
  int monomial(const Exponents& e) {
    std::vector<int> positions;
    for (int f = 0; f < kForms; ++f)
      for (int k = 0; k < e[static_cast<std::size_t>(f)]; ++k) positions.push_back(f);
    if (positions.size() > 4) throw std::logic_error("rough_walton_productions: monomial degree above 4");
    std::vector<std::vector<int>> partitions;  // each: the cumulant indices of its blocks
    std::vector<std::vector<int>> blocks;
    const auto recurse = [&](auto&& self, std::size_t i) -> void {
      if (i == positions.size()) {
        std::vector<int> ids;
        for (const auto& blk : blocks) {
          std::vector<int> forms;
          for (int p : blk) forms.push_back(positions[static_cast<std::size_t>(p)]);
          std::sort(forms.begin(), forms.end());
          ids.push_back(index_.at(forms));
        }
        partitions.push_back(ids);
        return;
      }
      for (std::size_t b = 0; b < blocks.size(); ++b) {  // by index: the recursion may reallocate `blocks`
        blocks[b].push_back(static_cast<int>(i));
        self(self, i + 1);
        blocks[b].pop_back();
      }
      blocks.push_back({static_cast<int>(i)});
      self(self, i + 1);
      blocks.pop_back();
    };
    recurse(recurse, 0);
    partitions_.push_back(partitions);
    return static_cast<int>(partitions_.size()) - 1;
  }

  /// Fills `moments` (one per registered monomial) at p = (u, G, H).
  void evaluate(const Eigen::Vector3d& p, std::vector<double>& moments) const {
    cumulant_.resize(constant_.size());
    for (std::size_t i = 0; i < constant_.size(); ++i) cumulant_[i] = constant_[i] + p.dot(quadratic_[i] * p);
    moments.assign(partitions_.size(), 0);
    for (std::size_t m = 0; m < partitions_.size(); ++m) {
      double sum = 0;
      for (const auto& partition : partitions_[m]) {
        double prod = 1;
        for (int id : partition) prod *= cumulant_[static_cast<std::size_t>(id)];
        sum += prod;
      }
      moments[m] = sum;
    }
  }

 private:
  std::map<std::vector<int>, int> index_;
  std::vector<double> constant_;
  std::vector<Eigen::Matrix3d> quadratic_;
  std::vector<std::vector<std::vector<int>>> partitions_;
  mutable std::vector<double> cumulant_;
};

/// A polynomial in (x, y) of one particle: terms (coefficient, power of x, power of y).
struct Term {
  double c;
  int i, j;
};
using Polynomial = std::vector<Term>;

}  // namespace

RoughWaltonProductions rough_walton_productions(int dimension, double alpha, double beta0, double kappa,
                                                double friction, double tau, int panels) {
  detail::check_walton_parameters(dimension, alpha, beta0, kappa, friction);
  if (!(tau > 0) || !std::isfinite(tau)) throw std::invalid_argument("temperature_ratio: must be > 0");
  if (panels < 1) throw std::invalid_argument("panels: must be >= 1");
  const int d = dimension;
  const double eta_n = (1 + alpha) / 2, eta0 = (1 + beta0) * kappa / (2 * (1 + kappa)), s = std::sqrt(1 + tau);
  const double m = std::isinf(friction) ? friction : friction * (1 + alpha) / 2;
  const double c = std::isinf(m) ? 0 : (m == 0 ? std::numeric_limits<double>::infinity() : eta0 / m);
  FormMoments forms(d, tau, eta_n, kappa);
  // The weights and tests of (19.10): R_X[ψ] = ⟨(Φ_X(1) + Φ_X(2))(ψ(1') − ψ(1))⟩/⟨1⟩, Φ_0 = 1 once.
  const double mt = d / 2.0 - 1, mr = (d == 3 ? 3 : 1) / 2.0 - 1;
  const auto s2 = [](double mm, bool spin) {
    const int x = spin ? 0 : 1, y = spin ? 1 : 0;
    return Polynomial{{(mm + 1) * (mm + 2) / 2, 0, 0}, {-(mm + 2), x, y}, {0.5, 2 * x, 2 * y}};
  };
  Polynomial s11;
  for (const Term& p : Polynomial{{mt + 1, 0, 0}, {-1, 1, 0}})
    for (const Term& q : Polynomial{{mr + 1, 0, 0}, {-1, 0, 1}}) s11.push_back({p.c * q.c, p.i + q.i, p.j + q.j});
  const std::array<Polynomial, 4> weights{Polynomial{{1, 0, 0}}, s2(mt, false), s2(mr, true), s11};
  const std::array<std::array<int, 2>, 5> tests{{{1, 0}, {0, 1}, {2, 0}, {0, 2}, {1, 1}}};
  // Each table entry as a list of (coefficient, monomial index).
  std::map<Exponents, int> registered;
  const auto id = [&](const Exponents& e) {
    const auto it = registered.find(e);
    if (it != registered.end()) return it->second;
    return registered[e] = forms.monomial(e);
  };
  std::array<std::array<std::vector<std::pair<double, int>>, 5>, 4> combination;
  for (std::size_t w = 0; w < 4; ++w)
    for (std::size_t t = 0; t < 5; ++t)
      for (const Term& term : weights[w]) {
        const int k = tests[t][0], l = tests[t][1];
        auto& out = combination[w][t];
        out.push_back({term.c, id({term.i, term.j, 0, 0, k, l})});
        out.push_back({-term.c, id({term.i + k, term.j + l, 0, 0, 0, 0})});
        if (w == 0) continue;
        out.push_back({term.c, id({0, 0, term.i, term.j, k, l})});
        out.push_back({-term.c, id({k, l, term.i, term.j, 0, 0})});
      }
  std::vector<std::pair<double, int>> collision;  // ⟨S_2(x1)⟩
  for (const Term& term : weights[1]) collision.push_back({term.c, id({term.i, 0, 0, 0, 0, 0})});
  const std::size_t count = registered.size();
  // (u, G) quadrature, weights Θ(u) u e^{−u²/2} and the density of r = G/s (as rough_walton_heat_operator).
  std::vector<double> moments, sum_u(count), total(count, 0.0);
  const double upper = 12;
  const auto over_u = [&](double big_g) {
    std::fill(sum_u.begin(), sum_u.end(), 0.0);
    const auto piece = [&](double lo, double hi) {
      detail::for_each_gauss_legendre_node(lo, hi, panels, [&](double u, double weight) {
        const double eta_t = (big_g == 0 || u >= c * big_g) ? eta0 : m * u / big_g;
        forms.evaluate(Eigen::Vector3d(u, big_g, eta_t * big_g), moments);
        const double factor = weight * u * std::exp(-u * u / 2);
        for (std::size_t k = 0; k < count; ++k) sum_u[k] += factor * moments[k];
      });
    };
    const double kink = big_g > 0 ? std::min(c * big_g, upper) : 0.0;
    piece(0, kink);
    piece(kink, upper);
    return sum_u;
  };
  const auto outer = [&](double r) {
    const double density = (d == 3 ? r : std::sqrt(2 / std::numbers::pi)) * std::exp(-r * r / 2);
    std::vector<double> v = over_u(s * r);
    for (auto& x : v) x *= density;
    return v;
  };
  const double edge = c > 0 && std::isfinite(c) ? std::min(upper / (c * s), upper) : upper;
  for (const auto& [lo, hi] : {std::pair{0.0, edge}, std::pair{edge, upper}})
    detail::for_each_gauss_legendre_node(lo, hi, panels, [&](double r, double weight) {
      const std::vector<double> v = outer(r);
      for (std::size_t k = 0; k < count; ++k) total[k] += weight * v[k];
    });
  RoughWaltonProductions out;
  for (std::size_t w = 0; w < 4; ++w)
    for (std::size_t t = 0; t < 5; ++t)
      for (const auto& [coefficient, index] : combination[w][t])
        out.table[w][t] += coefficient * total[static_cast<std::size_t>(index)];
  double s2x = 0;
  for (const auto& [coefficient, index] : collision) s2x += coefficient * total[static_cast<std::size_t>(index)];
  out.collision_a20 = 2 * s2x;
  return out;
}

RoughWaltonCumulantState rough_walton_linear_cooling_state(int dimension, double alpha, double beta0, double kappa,
                                                           double friction, int panels) {
  detail::check_walton_parameters(dimension, alpha, beta0, kappa, friction);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  RoughWaltonCumulantState out;
  const auto decoupled = [&]() {
    out.temperature_ratio = out.maxwellian_temperature_ratio = std::numeric_limits<double>::infinity();
    out.cooling_rate = out.maxwellian_cooling_rate = out.a20 = out.a02 = out.a11 = nan;
    out.spin_decoupled = true;
    return out;
  };
  // The Maxwellian root (rough_walton.hpp): the centre of the scan.
  out.maxwellian_temperature_ratio = rough_walton_temperature_ratio(dimension, alpha, beta0, kappa, friction);
  if (std::isinf(out.maxwellian_temperature_ratio)) return decoupled();
  out.maxwellian_cooling_rate =
      rough_walton_rates(dimension, alpha, beta0, kappa, friction, out.maxwellian_temperature_ratio).translational;
  // Linear scheme: at fixed τ the fourth-degree balances give a(τ) = −M(τ)⁻¹g(τ); G_0(τ, a(τ)) = 0 fixes τ
  // (as rough_homogeneous_cooling_state, theory.md §19.6, with the Walton averages).
  struct Point {
    double g0 = 0, det = 0;
    std::array<double, 3> a{};
    RoughBalances balances;
  };
  // The scan runs on a coarser rule (half the panels per piece, a quarter of the nodes; its G_0 differs by ~1e-7,
  // far below the steps between scan points); the root and its cumulants come from the full rule.
  const auto at = [&](double log_tau, int rule) {
    const RoughWaltonProductions p =
        rough_walton_productions(dimension, alpha, beta0, kappa, friction, std::exp(log_tau), rule);
    const RoughBalances b = rough_linear_balances(dimension, p.table, {});
    Eigen::Matrix3d mat;
    Eigen::Vector3d g;
    for (int i = 0; i < 3; ++i) {
      g(i) = b.residual[static_cast<std::size_t>(i) + 1];
      for (int j = 0; j < 3; ++j) mat(i, j) = b.jacobian[static_cast<std::size_t>(i) + 1][static_cast<std::size_t>(j)];
    }
    const Eigen::Vector3d x = mat.fullPivLu().solve(-g);
    Point pt{b.residual[0], mat.determinant(), {x(0), x(1), x(2)}, {}};
    for (std::size_t q = 0; q < 3; ++q) pt.g0 += b.jacobian[0][q] * pt.a[q];
    pt.balances = rough_linear_balances(dimension, p.table, pt.a);
    return pt;
  };
  const double center = std::log(out.maxwellian_temperature_ratio / kappa), step = 1.0 / 16, span = 2;
  const int scan = std::max(1, panels / 2);
  const Point mid_point = at(center, scan);
  // Walk outward on both sides at once; try each bracket (sign change of G_0 without a pole) as found.
  const auto solve = [&](double a_lt, Point pa, double b_lt, Point pb) -> bool {
    // Regula falsi (Illinois) on G_0.
    int side = 0;
    Point pc = pa;
    double c_lt = a_lt;
    for (int it = 0; it < 100 && std::abs(b_lt - a_lt) > 1e-12; ++it) {
      c_lt = (a_lt * pb.g0 - b_lt * pa.g0) / (pb.g0 - pa.g0);
      pc = at(c_lt, panels);
      if (pc.g0 == 0) break;
      if ((pc.g0 < 0) == (pb.g0 < 0)) {
        b_lt = c_lt;
        pb = pc;
        if (side == -1) pa.g0 /= 2;
        side = -1;
      } else {
        a_lt = c_lt;
        pa = pc;
        if (side == 1) pb.g0 /= 2;
        side = 1;
      }
      if (std::abs(pc.g0) < 1e-15) break;
    }
    if (!rough_cumulants_realizable(dimension, pc.a[0], pc.a[1], pc.a[2])) return false;
    out.temperature_ratio = std::exp(c_lt) * kappa;
    out.cooling_rate = (dimension + 2) / 4.0 * pc.balances.translational_rate;
    out.a20 = pc.a[0];
    out.a02 = pc.a[1];
    out.a11 = pc.a[2];
    return true;
  };
  Point left = mid_point, right = mid_point;
  for (double k = 1; k * step <= span + step / 2; ++k) {
    const double l_lt = center - k * step, r_lt = center + k * step;
    const Point r_new = at(r_lt, scan);
    if ((right.g0 < 0) != (r_new.g0 < 0) && (right.det < 0) == (r_new.det < 0) &&
        solve(r_lt - step, right, r_lt, r_new))
      return out;
    right = r_new;
    const Point l_new = at(l_lt, scan);
    if ((left.g0 < 0) != (l_new.g0 < 0) && (left.det < 0) == (l_new.det < 0) && solve(l_lt, l_new, l_lt + step, left))
      return out;
    left = l_new;
  }
  out.temperature_ratio = out.cooling_rate = out.a20 = out.a02 = out.a11 = nan;
  out.linear_scheme_solved = false;
  return out;
}

}  // namespace gkt
