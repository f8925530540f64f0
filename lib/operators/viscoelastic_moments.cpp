#include <cmath>
#include <numbers>
#include <stdexcept>

#include "gkt/collision_moments.hpp"
#include "gkt/linearized_operator.hpp"
#include "gkt/sonine.hpp"
#include "gkt/viscoelastic.hpp"

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

ViscoelasticHierarchy::ViscoelasticHierarchy(int k_max, const ViscoelasticRestitution& restitution) : k_max_(k_max) {
  if (k_max < 2) throw std::invalid_argument("hcs order: the highest cumulant must be >= 2");
  const int d = 3, n = k_max + 1;
  const CollisionPair pair{d, Rational(1), Rational(1), Rational(1), Rational(1)};
  const auto alpha = RationalPolynomial::variable();
  const long twice_m = sonine_twice_m(d, 0);
  const auto s = sonine_table(twice_m, k_max);
  const auto coef = power_coefficients(restitution.series(), kOrders);
  t_.assign(kOrders + 1, std::vector<double>(static_cast<std::size_t>(n) * n * n, 0.0));
  e_.assign(kOrders + 1, std::vector<double>(static_cast<std::size_t>(n) * n, 0.0));
  auto idx3 = [n](int p, int k, int l) { return (static_cast<std::size_t>(p) * n + k) * n + l; };
  for (int order = 0; order <= kOrders; ++order) {
    // Moments ⟨u^{J/5} X1^a X2^b X1'^c⟩ with α symbolic; gain terms take the (α − 1)^m coefficients.
    const Rational power(order, 5);
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

CumulantHierarchy ViscoelasticHierarchy::at(double delta_prime) const {
  std::vector<double> t = t_[0], e = e_[0];
  double power = 1;
  for (int order = 1; order <= kOrders; ++order) {
    power *= delta_prime;
    for (std::size_t i = 0; i < t.size(); ++i) t[i] += power * t_[order][i];
    for (std::size_t i = 0; i < e.size(); ++i) e[i] += power * e_[order][i];
  }
  return CumulantHierarchy(3, k_max_, std::move(t), std::move(e), c_, w_, norms_);
}

void ViscoelasticHierarchy::refresh(double delta_prime, CumulantHierarchy& hierarchy) const {
  hierarchy.t_ = t_[0];  // same sizes: std::vector copy-assignment reuses the storage
  hierarchy.e_ = e_[0];
  double power = 1;
  for (int order = 1; order <= kOrders; ++order) {
    power *= delta_prime;
    for (std::size_t i = 0; i < hierarchy.t_.size(); ++i) hierarchy.t_[i] += power * t_[order][i];
    for (std::size_t i = 0; i < hierarchy.e_.size(); ++i) hierarchy.e_[i] += power * e_[order][i];
  }
}

double ViscoelasticHierarchy::energy(int order, int k, int l) const {
  return e_[static_cast<std::size_t>(order)][static_cast<std::size_t>(k) * (k_max_ + 1) + l];
}

double ViscoelasticHierarchy::fourth(int order, int k, int l) const {
  // x² = 2 S_2 − 5 S_1 + 15/4 (d = 3): Δ(x²) = 2 T(2; ·) + 5 E (since S_1 = 3/2 − x, T(0; ·) = 0).
  const int n = k_max_ + 1;
  return 2 * t_[static_cast<std::size_t>(order)][(static_cast<std::size_t>(2) * n + k) * n + l] +
         5 * energy(order, k, l);
}

ViscoelasticConstants viscoelastic_constants(const ViscoelasticRestitution& restitution) {
  const ViscoelasticHierarchy h(2, restitution);
  const double nu = linearized_operator_prefactor(3);
  ViscoelasticConstants c{};
  c.omega0 = -nu * h.energy(1, 0, 0);
  c.omega1 = nu * h.energy(2, 0, 0);
  c.q0 = c.omega0 * std::pow(2.0, 0.1) / (16 * std::sqrt(2 * std::numbers::pi));
  // F_2(a2, δ') = Σ F_ij a2^i δ'^j = 0 perturbatively (K = 2, quadratic in a2): the hierarchy's F_2
  // is polynomial in a2 (degree ≤ 3) and δ' (degree ≤ 2); extract F_ij by finite sums.
  auto f2 = [&](double a2, double dp) {
    std::vector<double> f;
    h.at(dp).residual({1.0, 0.0, a2}, f, nullptr);
    return f[0];
  };
  // Exact polynomial interpolation on small grids (f is a polynomial of low degree).
  const double e = 1e-3;
  const double f01 = (f2(0, e) - f2(0, -e)) / (2 * e), f02 = (f2(0, e) - 2 * f2(0, 0) + f2(0, -e)) / (2 * e * e);
  const double f10 = (f2(e, 0) - f2(-e, 0)) / (2 * e), f20 = (f2(e, 0) - 2 * f2(0, 0) + f2(-e, 0)) / (2 * e * e);
  const double f11 = (f2(e, e) - f2(e, -e) - f2(-e, e) + f2(-e, -e)) / (4 * e * e);
  c.a2_1 = -f01 / f10;
  // Adiabatic following of the decaying δ'(t) ∝ T^{1/10}: da2/dτ = a21 dδ'/dτ is O(δ'²) and enters
  // at the order of a22 (theory.md (13.4)): F_2 = N_2 a21 δ' (1/10)(2/d) R_1 with R_1 ≈ E^(1) δ'.
  const double drift = sonine_norm(sonine_twice_m(3, 0), 2).to_double() * c.a2_1 * h.energy(1, 0, 0) / (5.0 * 3.0);
  c.a2_2 = (drift - f02 - f11 * c.a2_1 - f20 * c.a2_1 * c.a2_1) / f10;

  // Transport at first order in δ' (theory.md §13.2). Operator entries about the HCS: the δ'^1 part
  // is h_1 × [(α − 1)^1 coefficient at power 1/5] × J_{1/5}/J0, plus a21 × the a2-weighted elastic entry.
  const int d = 3;
  const auto alpha = RationalPolynomial::variable();
  const double h1 = restitution.series()[0];
  const double pf = std::tgamma(1.1) * std::pow(2.0, 0.1);  // J_s0/J0 at θ = 1: Γ(1 + s/2)(A0/N2_0)^{s/2}
  auto first_order = [&](int rank, int n_max, int p, int q) {
    const auto shifted_entry = shifted(
        hcs_linearized_operator_matrices<RationalPolynomial>(d, alpha, rank, n_max, 0, Rational(1, 5))[0](p, q));
    const double gain = shifted_entry.size() > 1 ? shifted_entry[1].to_double() : 0.0;
    const double weighted =
        hcs_linearized_operator_matrices<Rational>(d, Rational(1), rank, n_max, 2)[2](p, q).to_double();
    return h1 * pf * gain + c.a2_1 * weighted;
  };
  const double nu_eta_1 = first_order(2, 0, 0, 0) / (d - 1);
  const double nu_kappa_1 = first_order(1, 1, 1, 1) / d, nu_kappa_0 = (d - 1.0) / d;
  const double zeta_1 = -(d + 2.0) / (2.0 * d) * h.energy(1, 0, 0);
  // Heat source gains −(a21 δ'/10) c S_2 f_M (a2 depends on T through δ'): projected on c S_1 and
  // normalised by d(d+2)/4.
  // ⟨x S_1^(d/2) S_2^(d/2−1)⟩ under the Maxwellian
  std::vector<Rational> x_s1_s2(5);
  {
    const auto s1 = sonine_coefficients(sonine_twice_m(d, 1), 1), s2 = sonine_coefficients(sonine_twice_m(d, 0), 2);
    for (std::size_t i = 0; i < s1.size(); ++i)
      for (std::size_t j = 0; j < s2.size(); ++j) x_s1_s2[i + j + 1] += s1[i] * s2[j];
  }
  const double source_1 = -c.a2_1 / 10 * maxwell_average(d, x_s1_s2).to_double() * 4.0 / (d * (d + 2.0));
  c.shear_viscosity_1 = -nu_eta_1 + zeta_1 / 2;  // (13.5)
  c.thermal_conductivity_1_unverified =
      2 * c.a2_1 + source_1 - nu_kappa_1 / nu_kappa_0 + 2.1 * zeta_1 / nu_kappa_0;  // (13.6)
  c.density_heat_coefficient_1 = d * zeta_1 / (d - 1.0) + c.a2_1;                   // (13.7)
  return c;
}

}  // namespace gkt
