#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include <Eigen/Dense>

#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/rough_collision_moments.hpp"

namespace gkt {

namespace {

/// Σ_j c_j τ^{j − shift}: an exact Laurent polynomial in τ = θ/κ.
struct Laurent {
  int shift = 0;
  std::vector<Rational> c;

  [[nodiscard]] double operator()(double tau) const {
    double v = 0;
    for (std::size_t j = c.size(); j-- > 0;) v = v * tau + c[j].to_double();
    return v * std::pow(tau, -shift);
  }
  /// Returns this + s·o (exact).
  void add(const Laurent& o, const Rational& s) {
    if (o.shift > shift) {
      c.insert(c.begin(), static_cast<std::size_t>(o.shift - shift), Rational(0));
      shift = o.shift;
    }
    const auto offset = static_cast<std::size_t>(shift - o.shift);
    if (c.size() < o.c.size() + offset) c.resize(o.c.size() + offset, Rational(0));
    for (std::size_t j = 0; j < o.c.size(); ++j) c[j + offset] += s * o.c[j];
  }
};

/// A moment in the unscaled spin w = λŵ divided by τ^{spin power}: the moment of ŵ-powers.
Laurent scaled(const RationalPolynomial& p, int spin_power) {
  Laurent l;
  l.shift = spin_power;
  for (long j = 0; j <= p.degree(); j += 2) l.c.push_back(p.coefficient(j));
  return l;
}

/// A polynomial in (x, y) = (c², ŵ²): terms (coefficient, power of x, power of y).
struct Term {
  Rational c;
  int i, j;
};
using Polynomial = std::vector<Term>;

/// Returns S_m^(1)(x) = m+1 − x and S_m^(2)(x) = (m+1)(m+2)/2 − (m+2)x + x²/2 with 2m given.
Polynomial sonine1(const Rational& m, bool spin) {
  return {{m + Rational(1), 0, 0}, {Rational(-1), spin ? 0 : 1, spin ? 1 : 0}};
}
Polynomial sonine2(const Rational& m, bool spin) {
  const int x = spin ? 0 : 1, y = spin ? 1 : 0;
  return {{(m + Rational(1)) * (m + Rational(2)) / Rational(2), 0, 0},
          {-(m + Rational(2)), x, y},
          {Rational(1, 2), 2 * x, 2 * y}};
}
Polynomial product(const Polynomial& a, const Polynomial& b) {
  Polynomial r;
  for (const auto& s : a)
    for (const auto& t : b) r.push_back({s.c * t.c, s.i + t.i, s.j + t.j});
  return r;
}

/// The collision averages of the linear scheme (theory.md (19.10)), exact in τ: R_0[ψ] =
/// ⟨ψ(1') − ψ(1)⟩/⟨1⟩ and R_X[ψ] = ⟨(Φ_X(1) + Φ_X(2))(ψ(1') − ψ(1))⟩/⟨1⟩ for the weights
/// Φ_X ∈ {S2(x), S2(y), S1(x)S1(y)} and tests ψ ∈ {x, y, x², y², xy}.
class CollisionalProduction {
 public:
  CollisionalProduction(int d, const Rational& alpha, const Rational& beta, const Rational& kappa) {
    const auto p = rough_parameters_symbolic_temperature(d, alpha, beta, kappa);
    const RoughForm x1 = rough_dot_form(RoughSlot::v1, RoughSlot::v1),
                    y1 = rough_dot_form(RoughSlot::w1, RoughSlot::w1);
    const RoughForm x2 = rough_dot_form(RoughSlot::v2, RoughSlot::v2),
                    y2 = rough_dot_form(RoughSlot::w2, RoughSlot::w2);
    const RoughForm x1p = rough_dot_form(RoughSlot::v1_post, RoughSlot::v1_post);
    const RoughForm y1p = rough_dot_form(RoughSlot::w1_post, RoughSlot::w1_post);
    same_.emplace(p, std::vector<RoughForm>{x1, y1, x1p, y1p}, std::vector<int>{4, 4, 2, 2});
    other_gain_.emplace(p, std::vector<RoughForm>{x2, y2, x1p, y1p}, std::vector<int>{2, 2, 2, 2});
    other_loss_.emplace(p, std::vector<RoughForm>{x2, y2, x1, y1}, std::vector<int>{2, 2, 2, 2});
    const Rational mt(d - 2, 2), mr(d == 3 ? 1 : -1, 2);  // m = d/2 − 1, d_r/2 − 1
    const std::array<Polynomial, 4> weights{Polynomial{{Rational(1), 0, 0}}, sonine2(mt, false), sonine2(mr, true),
                                            product(sonine1(mt, false), sonine1(mr, true))};
    const std::array<std::pair<int, int>, 5> tests{{{1, 0}, {0, 1}, {2, 0}, {0, 2}, {1, 1}}};
    for (std::size_t w = 0; w < 4; ++w)
      for (std::size_t t = 0; t < 5; ++t) table_[w][t] = production(weights[w], w > 0, tests[t].first, tests[t].second);
  }
  /// Returns R_X[ψ_t] (X = 0: Maxwellian, 1: a20, 2: a02, 3: a11; t indexes x, y, x², y², xy).
  [[nodiscard]] const Laurent& operator()(std::size_t weight, std::size_t test) const { return table_[weight][test]; }

 private:
  /// ⟨Φ(1)(ψ(1') − ψ(1))⟩, plus ⟨Φ(2)(ψ(1') − ψ(1))⟩ when both partners carry the weight.
  Laurent production(const Polynomial& weight, bool both, int k, int l) const {
    Laurent r;
    for (const auto& term : weight) {
      const int s = term.j + l;  // power of ŵ² in the integrand
      r.add(scaled(same_->moment({term.i, term.j, k, l}), s), term.c);
      r.add(scaled(same_->moment({term.i + k, term.j + l, 0, 0}), s), -term.c);
      if (!both) continue;
      r.add(scaled(other_gain_->moment({term.i, term.j, k, l}), s), term.c);
      r.add(scaled(other_loss_->moment({term.i, term.j, k, l}), s), -term.c);
    }
    return r;
  }

  std::optional<RoughCollisionMoments<RationalPolynomial>> same_, other_gain_, other_loss_;
  std::array<std::array<Laurent, 5>, 4> table_;
};

/// The balances at τ and a = (a20, a02, a11) (theory.md (19.11)): G_0 = R[x]/d − R[y]/d_r
/// (ζ_t = ζ_r) and, for ψ = x², y², xy, G_p = 2 z(a)⟨ψ⟩_a + R[ψ](a) linearised in a, with
/// z(a) = −(2/d) R[x](a) the reduced cooling rate ζ/(nσ^{d−1}v_t ν).
struct Balances {
  std::array<double, 4> residual{};
  std::array<std::array<double, 3>, 4> jacobian_a{};  // ∂G/∂a (exact: G is linear in a)
  double z = 0;
};

Balances balances(const CollisionalProduction& r, int d, double tau, const std::array<double, 3>& a) {
  const double dt = d, dr = d == 3 ? 3 : 1;
  const std::array<double, 3> base{dt / 2 * (dt / 2 + 1), dr / 2 * (dr / 2 + 1), dt / 2 * dr / 2};
  std::array<std::array<double, 5>, 4> v{};
  for (std::size_t w = 0; w < 4; ++w)
    for (std::size_t t = 0; t < 5; ++t) v[w][t] = r(w, t)(tau);
  Balances b;
  const double z0 = -2 / dt * v[0][0];
  b.z = z0;
  for (std::size_t q = 0; q < 3; ++q) b.z += a[q] * (-2 / dt * v[q + 1][0]);
  b.residual[0] = v[0][0] / dt - v[0][1] / dr;
  for (std::size_t q = 0; q < 3; ++q) b.jacobian_a[0][q] = v[q + 1][0] / dt - v[q + 1][1] / dr;
  for (std::size_t p = 0; p < 3; ++p) {
    b.residual[p + 1] = 2 * z0 * base[p] + v[0][p + 2];
    for (std::size_t q = 0; q < 3; ++q)
      b.jacobian_a[p + 1][q] =
          v[q + 1][p + 2] + 2 * (-2 / dt * v[q + 1][0]) * base[p] + (p == q ? 2 * z0 * base[p] : 0);
  }
  for (std::size_t p = 0; p < 4; ++p)
    for (std::size_t q = 0; q < 3; ++q) b.residual[p] += b.jacobian_a[p][q] * a[q];
  return b;
}

void check(int d, const Rational& alpha, const Rational& beta, const Rational& kappa) {
  // rough_parameters_symbolic_temperature validates the ranges; call it once for its checks.
  (void)rough_parameters_symbolic_temperature(d, alpha, beta, kappa);
}

}  // namespace

std::vector<Rational> rough_maxwellian_temperature_equation(int dimension, const Rational& alpha, const Rational& beta,
                                                            const Rational& kappa) {
  check(dimension, alpha, beta, kappa);
  const CollisionalProduction r(dimension, alpha, beta, kappa);
  // τ·(R[x]/d − R[y]/d_r) = 0: R[x] = c0 + c1 τ, R[y] = c'/τ + c'' (theory.md (19.7)–(19.8), (19.12)).
  Laurent f = r(0, 0), g = r(0, 1), eq;
  f.shift -= 1;  // × τ
  g.shift -= 1;
  eq.add(f, Rational(1, static_cast<unsigned long>(dimension)));
  eq.add(g, Rational(-1, static_cast<unsigned long>(dimension == 3 ? 3 : 1)));
  for (std::size_t j = 3; j < eq.c.size(); ++j)
    if (!eq.c[j].is_zero()) throw std::logic_error("rough_maxwellian_temperature_equation: degree above 2");
  eq.c.resize(3, Rational(0));
  return eq.c;
}

RoughCoolingState rough_homogeneous_cooling_state(int dimension, const Rational& alpha, const Rational& beta,
                                                  const Rational& kappa, RoughHcsScheme scheme) {
  check(dimension, alpha, beta, kappa);
  const CollisionalProduction r(dimension, alpha, beta, kappa);
  const bool linear = scheme == RoughHcsScheme::linear;
  const double d = dimension;
  RoughCoolingState s;
  if (beta == Rational(-1)) {
    // Spin frozen: the x and x² balances alone (their spin weights average to zero).
    s.spin_decoupled = true;
    s.temperature_ratio = std::numeric_limits<double>::infinity();
    s.a02 = s.a11 = std::numeric_limits<double>::quiet_NaN();
    const double z0 = -2 / d * r(0, 0)(1.0);
    if (linear) {
      const double base = d / 2 * (d / 2 + 1);
      s.a20 = -(2 * z0 * base + r(0, 2)(1.0)) / (r(1, 2)(1.0) + 2 * (-2 / d * r(1, 0)(1.0)) * base + 2 * z0 * base);
    }
    s.cooling_rate = (d + 2) / 4 * (-2 / d) * (r(0, 0)(1.0) + s.a20 * r(1, 0)(1.0));
    return s;
  }
  // Maxwellian: G_0(τ) = 0 alone. Its τ·G_0 is a quadratic with one positive root (G_0 < 0 for a cold
  // spin, > 0 for a hot one): bisect in log τ.
  const std::array<double, 3> zero{};
  auto g0 = [&](double log_tau) { return balances(r, dimension, std::exp(log_tau), zero).residual[0]; };
  double lo = 0, hi = 0;
  while (g0(lo) > 0 && lo > -80) lo -= 1;
  while (g0(hi) < 0 && hi < 80) hi += 1;
  if (g0(lo) > 0 || g0(hi) < 0) throw std::runtime_error("rough HCS: no temperature ratio found");
  for (int it = 0; it < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(lo)); ++it) {
    const double mid = 0.5 * (lo + hi);
    (g0(mid) < 0 ? lo : hi) = mid;
  }
  double log_tau = 0.5 * (lo + hi);
  std::array<double, 3> a{};
  if (linear) {
    // At fixed τ the three fourth-degree balances are linear in a: a(τ) = −M(τ)⁻¹ g(τ); then
    // G_0(τ, a(τ)) = 0 fixes τ. M(τ) can be singular (a pole of a(τ), where G_0 changes sign
    // without a root): scan log τ around the Maxwellian root for sign changes of G_0 on
    // intervals where det M keeps its sign, take the one nearest the Maxwellian τ, and bisect.
    struct Point {
      double g0, det;
      std::array<double, 3> a;
    };
    auto at = [&](double lt) {
      const Balances b = balances(r, dimension, std::exp(lt), std::array<double, 3>{});
      Eigen::Matrix3d m;
      Eigen::Vector3d g;
      for (int p = 0; p < 3; ++p) {
        g(p) = b.residual[static_cast<std::size_t>(p) + 1];
        for (int q = 0; q < 3; ++q)
          m(p, q) = b.jacobian_a[static_cast<std::size_t>(p) + 1][static_cast<std::size_t>(q)];
      }
      const Eigen::Vector3d x = m.fullPivLu().solve(-g);
      Point pt{b.residual[0], m.determinant(), {x(0), x(1), x(2)}};
      for (std::size_t q = 0; q < 3; ++q) pt.g0 += b.jacobian_a[0][q] * pt.a[q];
      return pt;
    };
    const double center = log_tau, step = 1.0 / 64, span = 4;
    double best_lo = 0, best_hi = 0, best_distance = std::numeric_limits<double>::infinity();
    Point prev = at(center - span);
    for (double lt = center - span + step; lt <= center + span + step / 2; lt += step) {
      const Point cur = at(lt);
      const bool sign_change = (prev.g0 < 0) != (cur.g0 < 0);
      const bool pole = (prev.det < 0) != (cur.det < 0);
      const double distance = std::abs(lt - step / 2 - center);
      if (sign_change && !pole && distance < best_distance) {
        best_distance = distance;
        best_lo = lt - step;
        best_hi = lt;
      }
      prev = cur;
    }
    if (!std::isfinite(best_distance)) {
      s.temperature_ratio = s.cooling_rate = s.a20 = s.a02 = s.a11 = std::numeric_limits<double>::quiet_NaN();
      s.linear_scheme_solved = false;
      return s;
    }
    const bool rising = at(best_lo).g0 < 0;
    for (int it = 0; it < 200 && best_hi - best_lo > 1e-15 * std::max(1.0, std::abs(best_lo)); ++it) {
      const double mid = 0.5 * (best_lo + best_hi);
      ((at(mid).g0 < 0) == rising ? best_lo : best_hi) = mid;
    }
    log_tau = 0.5 * (best_lo + best_hi);
    a = at(log_tau).a;
  }
  const double tau = std::exp(log_tau);
  const Balances e = balances(r, dimension, tau, a);
  s.temperature_ratio = tau * kappa.to_double();
  s.cooling_rate = (d + 2) / 4 * e.z;
  s.a20 = a[0];
  s.a02 = a[1];
  s.a11 = a[2];
  return s;
}

}  // namespace gkt
