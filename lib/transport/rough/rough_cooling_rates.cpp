#include "gkt/transport/rough/rough_cooling_rates.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/rough_collision_moments.hpp"

namespace gkt {

namespace {

/// Σ_j c_j τ^{j − shift}: an exact Laurent polynomial in τ = θ/κ (with its double coefficients).
struct Laurent {
  int shift = 0;
  std::vector<Rational> c;
  std::vector<double> cd;

  [[nodiscard]] double operator()(double tau) const {
    double v = 0;
    for (std::size_t j = cd.size(); j-- > 0;) v = v * tau + cd[j];
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
  void freeze() {
    cd.clear();
    for (const auto& x : c) cd.push_back(x.to_double());
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

}  // namespace

/// The collision averages of the linear scheme (theory.md (19.10)), exact in τ: R_0[ψ] =
/// ⟨ψ(1') − ψ(1)⟩/⟨1⟩ and R_X[ψ] = ⟨(Φ_X(1) + Φ_X(2))(ψ(1') − ψ(1))⟩/⟨1⟩ for the weights
/// Φ_X ∈ {S2(x), S2(y), S1(x)S1(y)} and tests ψ ∈ {x, y, x², y², xy}.
struct RoughCoolingRates::Impl {
  Impl(int d, const Rational& alpha, const Rational& beta, const Rational& kappa)
      : dimension(d), kappa_value(kappa.to_double()) {
    const auto p = rough_parameters_symbolic_temperature(d, alpha, beta, kappa);  // validates the ranges
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
      for (std::size_t t = 0; t < 5; ++t) {
        table[w][t] = production(weights[w], w > 0, tests[t].first, tests[t].second);
        table[w][t].freeze();
      }
    // ⟨S_2(x1)⟩ over collisions: translational only (a constant in τ).
    Rational s2;
    for (const auto& term : weights[1]) s2 += term.c * same_->moment({term.i, 0, 0, 0}).coefficient(0);
    collision_a20 = (Rational(2) * s2).to_double();
  }

  /// ⟨Φ(1)(ψ(1') − ψ(1))⟩, plus ⟨Φ(2)(ψ(1') − ψ(1))⟩ when both partners carry the weight.
  [[nodiscard]] Laurent production(const Polynomial& weight, bool both, int k, int l) const {
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

  int dimension;
  double kappa_value;
  std::optional<RoughCollisionMoments<RationalPolynomial>> same_, other_gain_, other_loss_;
  std::array<std::array<Laurent, 5>, 4> table;
  double collision_a20 = 0;
};

RoughCoolingRates::RoughCoolingRates(int dimension, const Rational& alpha, const Rational& beta, const Rational& kappa)
    : impl_(std::make_unique<Impl>(dimension, alpha, beta, kappa)) {}
RoughCoolingRates::~RoughCoolingRates() = default;
RoughCoolingRates::RoughCoolingRates(RoughCoolingRates&&) noexcept = default;
RoughCoolingRates& RoughCoolingRates::operator=(RoughCoolingRates&&) noexcept = default;

int RoughCoolingRates::dimension() const { return impl_->dimension; }
double RoughCoolingRates::kappa() const { return impl_->kappa_value; }

double RoughCoolingRates::production(std::size_t weight, std::size_t test, double tau) const {
  return impl_->table.at(weight).at(test)(tau);
}

std::array<double, 3> RoughCoolingRates::maxwellian_fourth_moments() const {
  const double dt = impl_->dimension, dr = impl_->dimension == 3 ? 3 : 1;
  return {dt / 2 * (dt / 2 + 1), dr / 2 * (dr / 2 + 1), dt / 2 * dr / 2};
}

double RoughCoolingRates::collision_frequency_factor(double a20) const { return 1 + impl_->collision_a20 * a20; }

RoughBalances RoughCoolingRates::at(double tau, const std::array<double, 3>& a) const {
  RoughProductionTable v{};
  for (std::size_t w = 0; w < 4; ++w)
    for (std::size_t t = 0; t < 5; ++t) v[w][t] = impl_->table[w][t](tau);
  return rough_linear_balances(impl_->dimension, v, a);
}

RoughBalances rough_linear_balances(int dimension, const RoughProductionTable& v, const std::array<double, 3>& a) {
  const double dt = dimension, dr = dimension == 3 ? 3 : 1;
  const std::array<double, 3> base{dt / 2 * (dt / 2 + 1), dr / 2 * (dr / 2 + 1), dt / 2 * dr / 2};
  RoughBalances b;
  const double z0 = -2 / dt * v[0][0];
  b.translational_rate = z0;
  b.rotational_rate = -2 / dr * v[0][1];
  for (std::size_t q = 0; q < 3; ++q) {
    b.translational_rate += a[q] * (-2 / dt * v[q + 1][0]);
    b.rotational_rate += a[q] * (-2 / dr * v[q + 1][1]);
  }
  b.residual[0] = v[0][0] / dt - v[0][1] / dr;
  for (std::size_t q = 0; q < 3; ++q) b.jacobian[0][q] = v[q + 1][0] / dt - v[q + 1][1] / dr;
  for (std::size_t p = 0; p < 3; ++p) {
    b.residual[p + 1] = 2 * z0 * base[p] + v[0][p + 2];
    for (std::size_t q = 0; q < 3; ++q)
      b.jacobian[p + 1][q] = v[q + 1][p + 2] + 2 * (-2 / dt * v[q + 1][0]) * base[p] + (p == q ? 2 * z0 * base[p] : 0);
  }
  for (std::size_t p = 0; p < 4; ++p)
    for (std::size_t q = 0; q < 3; ++q) b.residual[p] += b.jacobian[p][q] * a[q];
  return b;
}

std::array<Rational, 3> RoughCoolingRates::maxwellian_temperature_equation() const {
  const int d = impl_->dimension;
  // τ·(R[x]/d − R[y]/d_r) = 0: R[x] = c0 + c1 τ, R[y] = c'/τ + c'' (theory.md (19.7)–(19.8), (19.12)).
  Laurent f = impl_->table[0][0], g = impl_->table[0][1], eq;
  f.shift -= 1;  // × τ
  g.shift -= 1;
  eq.add(f, Rational(1, static_cast<unsigned long>(d)));
  eq.add(g, Rational(-1, static_cast<unsigned long>(d == 3 ? 3 : 1)));
  for (std::size_t j = 3; j < eq.c.size(); ++j)
    if (!eq.c[j].is_zero()) throw std::logic_error("rough_maxwellian_temperature_equation: degree above 2");
  eq.c.resize(3, Rational(0));
  return {eq.c[0], eq.c[1], eq.c[2]};
}

}  // namespace gkt
