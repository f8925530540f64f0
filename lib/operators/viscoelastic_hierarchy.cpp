#include <cmath>
#include <stdexcept>

#include "gkt/algebra/sonine.hpp"
#include "gkt/collision/collision_moments.hpp"
#include "gkt/operators/linearized_operator.hpp"
#include "gkt/operators/viscoelastic_hierarchy.hpp"

namespace gkt {

namespace {

/// Coefficients of (α − 1)^m of p(α) (Taylor shift to α = 1), m = 0..deg.
std::vector<Rational> shifted(const RationalPolynomial& p) {
  RationalPolynomial q;
  const RationalPolynomial x_plus_one = RationalPolynomial::variable() + RationalPolynomial(1L);
  fmpq_poly_compose(q.raw(), p.raw(), x_plus_one.raw());  // q(y) = p(y + 1)
  std::vector<Rational> c;
  for (long m = 0; m <= std::max(q.degree(), 0L); ++m) c.push_back(q.coefficient(m));
  return c;
}

/// coef[m][J] = Σ_{j_1+…+j_m = J, j_i ≥ 1} Π h_{j_i}: (ε − 1)^m = Σ_J coef[m][J] δ'^J u^{J/5}.
std::vector<std::vector<double>> power_coefficients(const std::vector<double>& h, int orders) {
  std::vector<std::vector<double>> coef(static_cast<std::size_t>(orders) + 1,
                                        std::vector<double>(static_cast<std::size_t>(orders) + 1, 0.0));
  coef[0][0] = 1.0;
  for (int m = 1; m <= orders; ++m)
    for (int total = m; total <= orders; ++total)
      for (int j = 1; j <= std::min<int>(static_cast<int>(h.size()), total - (m - 1)); ++j)
        coef[m][total] += h[static_cast<std::size_t>(j) - 1] * coef[m - 1][total - j];
  return coef;
}

}  // namespace

ViscoelasticHierarchy::ViscoelasticHierarchy(int k_max, const ViscoelasticRestitution& restitution, int moment_orders)
    : k_max_(k_max), orders_(static_cast<int>(restitution.series().size())), exponent_(restitution.exponent) {
  if (k_max < 2) throw std::invalid_argument("hcs order: the highest cumulant must be >= 2");
  if (restitution.series().empty()) throw std::invalid_argument("restitution: needs at least the coefficient h_1");
  const int orders = std::max(moment_orders, orders_);
  const int d = 3, n = k_max + 1;
  const CollisionPair pair{d, Rational(1), Rational(1), Rational(1), Rational(1)};
  const auto alpha = RationalPolynomial::variable();
  const long twice_m = sonine_twice_m(d, 0);
  const auto s = sonine_table(twice_m, k_max);
  const auto coef = power_coefficients(restitution.series(), orders);
  t_.assign(orders + 1, std::vector<double>(static_cast<std::size_t>(n) * n * n, 0.0));
  e_.assign(orders + 1, std::vector<double>(static_cast<std::size_t>(n) * n, 0.0));
  auto idx3 = [n](int p, int k, int l) { return (static_cast<std::size_t>(p) * n + k) * n + l; };
  for (int order = 0; order <= orders; ++order) {
    // Moments ⟨u^{J s} X1^a X2^b X1'^c⟩ with α symbolic; gain terms take the (α − 1)^m coefficients.
    const Rational power = Rational(order) * exponent_;
    const CollisionMomentTable<RationalPolynomial> gain(pair, alpha, {Slot::v1, Slot::v2, Slot::v1_post},
                                                        {k_max, k_max, k_max}, std::nullopt, 0, power);
    const double factor = gain.power_factor();
    // x-moments of the gain for each (a, b, c): Σ_m coef[m][J] μ_m.
    std::vector<double> g(static_cast<std::size_t>(n) * n * n, 0.0);
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        for (int c = 0; c < n; ++c) {
          const auto mu = shifted(gain.moment({a, b, c}));
          double v = 0;
          for (int m = (order == 0 ? 0 : 1); m <= order && m < static_cast<int>(mu.size()); ++m)
            v += coef[static_cast<std::size_t>(m)][static_cast<std::size_t>(order)] *
                 mu[static_cast<std::size_t>(m)].to_double();
          g[idx3(a, b, c)] = factor * v;
        }
    // The loss term ⟨S_k S_l ψ(X1)⟩ does not depend on ε: order 0 only.
    std::vector<double> loss(static_cast<std::size_t>(2 * n) * n, 0.0);
    if (order == 0) {
      const CollisionMomentTable<Rational> l(pair, Rational(1), {Slot::v1, Slot::v2}, {2 * k_max, k_max}, std::nullopt,
                                             0);
      for (int a = 0; a < 2 * n - 1; ++a)
        for (int b = 0; b < n; ++b) loss[static_cast<std::size_t>(a) * n + b] = l.moment({a, b}).to_double();
    }
    for (int p = 0; p < n; ++p)
      for (int k = 0; k < n; ++k)
        for (int l = 0; l < n; ++l) {
          double v = 0;
          for (int a = 0; a <= k; ++a)
            for (int b = 0; b <= l; ++b)
              for (int c = 0; c <= p; ++c) {
                const double sk = s[k][a].to_double(), sl = s[l][b].to_double(), sp = s[p][c].to_double();
                v += sk * sl * sp * (g[idx3(a, b, c)] - loss[static_cast<std::size_t>(a + c) * n + b]);
              }
          t_[order][idx3(p, k, l)] = v;
        }
    for (int k = 0; k < n; ++k)
      for (int l = 0; l < n; ++l) {
        double v = 0;
        for (int a = 0; a <= k; ++a)
          for (int b = 0; b <= l; ++b) {
            const double sk = s[k][a].to_double(), sl = s[l][b].to_double();
            v += sk * sl * ((k_max >= 1 ? g[idx3(a, b, 1)] : 0.0) - loss[static_cast<std::size_t>(a + 1) * n + b]);
          }
        e_[order][static_cast<std::size_t>(k) * n + l] = v;
      }
  }
  // α-independent pieces, as in HomogeneousCoolingState::hierarchy.
  const CollisionMomentTable<Rational> rate(pair, Rational(1), {Slot::v1, Slot::v2}, {k_max, k_max}, std::nullopt, 0);
  c_.assign(static_cast<std::size_t>(n) * n, 0.0);
  for (int k = 0; k < n; ++k)
    for (int l = 0; l < n; ++l)
      for (int a = 0; a <= k; ++a)
        for (int b = 0; b <= l; ++b)
          c_[static_cast<std::size_t>(k) * n + l] +=
              s[k][a].to_double() * s[l][b].to_double() * rate.moment({a, b}).to_double();
  w_.assign(static_cast<std::size_t>(n), std::vector<double>(static_cast<std::size_t>(n)));
  norms_.resize(static_cast<std::size_t>(n));
  for (int p = 0; p < n; ++p) {
    norms_[static_cast<std::size_t>(p)] = sonine_norm(twice_m, p).to_double();
    for (int k = 0; k < n; ++k) w_[p][k] = scaling_weight(d, p, k).to_double();
  }
}

std::vector<std::vector<DenseMatrix<double>>> viscoelastic_operator_series(int rank, int n_max, int k_max,
                                                                           const ViscoelasticRestitution& restitution) {
  const int d = 3, orders = static_cast<int>(restitution.series().size());
  const auto alpha = RationalPolynomial::variable();
  const auto coef = power_coefficients(restitution.series(), orders);
  std::vector<std::vector<DenseMatrix<double>>> out;
  for (int order = 0; order <= orders; ++order) {
    // (13.2): Σ_m coef[m][J] × the (α − 1)^m coefficient of the moments weighted by u^{J s}, × J_s0/J0.
    const Rational power = Rational(order) * restitution.exponent;
    const double factor = std::tgamma(1 + power.to_double() / 2) * std::pow(2.0, power.to_double() / 2);
    const auto by_weight = hcs_linearized_operator_matrices<RationalPolynomial>(d, alpha, rank, n_max, k_max, power);
    out.emplace_back();
    for (const auto& m : by_weight) {
      DenseMatrix<double> g(n_max + 1, n_max + 1);
      for (int p = 0; p <= n_max; ++p)
        for (int q = 0; q <= n_max; ++q) {
          const auto mu = shifted(m(p, q));
          double v = 0;
          for (int j = (order == 0 ? 0 : 1); j <= order && j < static_cast<int>(mu.size()); ++j)
            v += coef[static_cast<std::size_t>(j)][static_cast<std::size_t>(order)] *
                 mu[static_cast<std::size_t>(j)].to_double();
          g(p, q) = factor * v;
        }
      out.back().push_back(std::move(g));
    }
  }
  return out;
}

CumulantHierarchy ViscoelasticHierarchy::at(double delta_prime) const {
  CumulantHierarchy hierarchy(3, k_max_, t_[0], e_[0], c_, w_, norms_);
  refresh(delta_prime, hierarchy);
  return hierarchy;
}

void ViscoelasticHierarchy::refresh(double delta_prime, CumulantHierarchy& hierarchy) const {
  hierarchy.assign_power_series(delta_prime, t_, e_);
}

double ViscoelasticHierarchy::energy(int order, int k, int l) const {
  return e_[static_cast<std::size_t>(order)][static_cast<std::size_t>(k) * (k_max_ + 1) + l];
}

double ViscoelasticHierarchy::transfer(int order, int p, int k, int l) const {
  const auto n = static_cast<std::size_t>(k_max_ + 1);
  return t_[static_cast<std::size_t>(order)]
           [(static_cast<std::size_t>(p) * n + static_cast<std::size_t>(k)) * n + static_cast<std::size_t>(l)];
}

double ViscoelasticHierarchy::fourth(int order, int k, int l) const {
  // x² = 2 S_2 − 5 S_1 + 15/4 (d = 3): Δ(x²) = 2 T(2; ·) + 5 E (since S_1 = 3/2 − x, T(0; ·) = 0).
  const int n = k_max_ + 1;
  return 2 * t_[static_cast<std::size_t>(order)][(static_cast<std::size_t>(2) * n + k) * n + l] +
         5 * energy(order, k, l);
}

}  // namespace gkt
