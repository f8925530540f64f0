#include "gkt/operators/weighted_pair_transfer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "gkt/algebra/sonine.hpp"
#include "gkt/collision/collision_rule.hpp"
#include "gkt/collision/quadratic_form_moments.hpp"
#include "operators/transfer_contractions.hpp"

namespace gkt {

namespace {

using detail::contract2;
using detail::contract3;
using detail::max_degree;
using detail::scaled_argument;
using detail::Table;
using Q = QuadraticFormMoments<Rational>;

/// G_l = −½ D_l = S_l − S_l': the factor of ∂_V(f_M S_l) = −2θV f_M G_l.
Table gradient_factors(int d, int k_max) {
  Table out = detail::derivative_factors(d, k_max);
  for (auto& row : out)
    for (auto& c : row) c *= Rational(-1, 2);
  return out;
}

std::vector<double> rounded(const std::vector<Rational>& v, double scale) {
  std::vector<double> out;
  out.reserve(v.size());
  for (const auto& x : v) out.push_back(scale * x.to_double());
  return out;
}

}  // namespace

WeightedPairTransferMoments weighted_pair_transfer_moments(int dimension, const Rational& mass_ratio,
                                                           const Rational& width_root, const Rational& alpha, int n_max,
                                                           int k_max, double mass_i, double theta_j) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("dimension: must be 2 or 3");
  if (n_max < 0) throw std::invalid_argument("n_max: must be >= 0");
  if (k_max < 0) throw std::invalid_argument("k_max: must be >= 0");
  if (!(theta_j > 0) || !(mass_i > 0))
    throw std::invalid_argument("weighted_pair_transfer_moments: mass and width must be > 0");
  const int d = dimension;
  // Pair units u = √θ_j v (θ_j = 1, θ_i = r²) as in pair_transfer_moments: X1 = r² u1², X2 = u2².
  const Rational r = width_root, r2 = width_root * width_root;
  const CollisionPair pair{d, mass_ratio, Rational(1), r2, Rational(1)};
  const SlotVector u1 = slot_vector(Slot::v1), u2 = slot_vector(Slot::v2), u1p = slot_vector(Slot::v1_post);
  const SlotVector h = collision_vector();
  const VelocityForm x1 = dot_form(u1, u1), x2 = dot_form(u2, u2), x1p = dot_form(u1p, u1p), hh = dot_form(h, h);
  const VelocityForm h1 = dot_form(h, u1), h2 = dot_form(h, u2), h1p = dot_form(h, u1p);
  const Rational minus_one(-1), one(1), two(2), zero(0), inv_d(1, static_cast<unsigned long>(d)), quarter(1, 4);
  // Weights: S_k, T_k, G_k of X2 (partner) and, scaled by r², of X1 (particle 1).
  const Table s2 = sonine_table(sonine_twice_m(d, 0), k_max), t2 = detail::temperature_factors(d, k_max),
              g2 = gradient_factors(d, k_max);
  const Table s1 = scaled_argument(s2, r2), t1 = scaled_argument(t2, r2), g1 = scaled_argument(g2, r2);
  const int nw = std::max({max_degree(s2), max_degree(t2), max_degree(g2)});
  // Test and basis polynomials, as pair_transfer_moments.
  const Table vec1 = scaled_argument(sonine_table(sonine_twice_m(d, 1), n_max), r2),
              vec2 = sonine_table(sonine_twice_m(d, 1), n_max);
  const Table ten1 = scaled_argument(sonine_table(sonine_twice_m(d, 2), n_max), r2),
              ten2 = sonine_table(sonine_twice_m(d, 2), n_max);
  const Table sca1 = scaled_argument(sonine_table(sonine_twice_m(d, 0), n_max), r2),
              sca2 = sonine_table(sonine_twice_m(d, 0), n_max);
  const int nv = max_degree(vec1), nt = max_degree(ten1), ns = max_degree(sca1);

  const double a1 = 1 + alpha.to_double(), root = std::sqrt(theta_j);
  const double energy_unit = mass_i / (2 * theta_j);
  WeightedPairTransferMoments out;
  out.dimension = d;
  out.n_max = n_max;
  out.k_max = k_max;

  {  // vector sources: raw(a, b, j) with X1^a, X2^b of the weights and (r²u1'²)^j of the test
    const Q gain(pair, alpha, {x1p, h1p, x2, x1}, {nv, 1, nw, nw}, minus_one);
    const Q loss(pair, alpha, {x1, h1, x2}, {nv + nw, 1, nw}, minus_one);
    auto raw = [&](int a, int b, int j) { return gain.moment({j, 1, b, a}) - loss.moment({j + a, 1, b, 0}); };
    const double scale = r.to_double() * gain.power_factor() / a1;
    out.source_density = rounded(contract3<Rational>(raw, vec1, s1, s2), scale);
    out.source_temperature = rounded(contract3<Rational>(raw, vec1, s1, t2), scale);
  }
  {  // shear source, polarised as pair_transfer_moments
    const SlotVector hp = combine(h, u2, one), hm = combine(h, u2, minus_one);
    const Q gp(pair, alpha, {x1p, dot_form(u1p, hp), x2, x1}, {nt, 2, nw, nw}, minus_one);
    const Q gm(pair, alpha, {x1p, dot_form(u1p, hm), x2, x1}, {nt, 2, nw, nw}, minus_one);
    const Q gh(pair, alpha, {x1p, h2, x2, x1}, {nt + 1, 1, nw, nw}, minus_one);
    const Q lp(pair, alpha, {x1, dot_form(u1, hp), x2}, {nt + nw, 2, nw}, minus_one);
    const Q lm(pair, alpha, {x1, dot_form(u1, hm), x2}, {nt + nw, 2, nw}, minus_one);
    const Q lh(pair, alpha, {x1, h2, x2}, {nt + nw + 1, 1, nw}, minus_one);
    auto raw = [&](int a, int b, int j) {
      const Rational g =
          quarter * (gp.moment({j, 2, b, a}) - gm.moment({j, 2, b, a})) - inv_d * gh.moment({j + 1, 1, b, a});
      const Rational l = quarter * (lp.moment({j + a, 2, b, 0}) - lm.moment({j + a, 2, b, 0})) -
                         inv_d * lh.moment({j + a + 1, 1, b, 0});
      return g - l;
    };
    out.source_shear = rounded(contract3<Rational>(raw, ten1, s1, g2), r2.to_double() * gp.power_factor() / a1);
  }
  {  // scalar source: (H·u2)[S_p(X1') − S_p(X1)]
    const Q f(pair, alpha, {x1p, x1, h2, x2}, {ns, ns + nw, 1, nw}, minus_one);
    auto raw = [&](int a, int b, int j) { return f.moment({j, a, 1, b}) - f.moment({0, j + a, 1, b}); };
    out.source_scalar = rounded(contract3<Rational>(raw, sca1, s1, g2), f.power_factor() / a1);
  }
  {  // shear fluxes: raw(w, j) with the weight's power w and the basis power j
    const Q fp(pair, alpha, {x2, h2, hh, x1}, {nt + 1, 2, 1, nw}, minus_one);
    const Q fs(pair, alpha, {x1, h1, hh, x2}, {nt + 1, 2, 1, nw}, minus_one);
    auto raw_p = [&](int a, int j) { return fp.moment({j, 2, 0, a}) - inv_d * fp.moment({j + 1, 0, 1, a}); };
    auto raw_s = [&](int b, int j) { return r2 * (fs.moment({j, 2, 0, b}) - inv_d * fs.moment({j + 1, 0, 1, b})); };
    const double scale = fp.power_factor() / (root * a1 * a1);
    out.shear_flux_partner = rounded(contract2<Rational>(raw_p, ten2, s1), scale);
    out.shear_flux_self = rounded(contract2<Rational>(raw_s, ten1, s2), scale);
  }
  {  // heat fluxes: (H·c)(u1'² − u1²) S_q(X)
    const Q fp(pair, alpha, {x2, h2, x1p, x1}, {nv, 1, 1, nw + 1}, minus_one);
    const Q fs(pair, alpha, {x1, h1, x1p, x2}, {nv + 1, 1, 1, nw}, minus_one);
    auto raw_p = [&](int a, int j) { return fp.moment({j, 1, 1, a}) - fp.moment({j, 1, 0, a + 1}); };
    auto raw_s = [&](int b, int j) { return r * (fs.moment({j, 1, 1, b}) - fs.moment({j + 1, 1, 0, b})); };
    const double scale = energy_unit * fp.power_factor() / a1;
    out.heat_flux_partner = rounded(contract2<Rational>(raw_p, vec2, s1), scale);
    out.heat_flux_self = rounded(contract2<Rational>(raw_s, vec1, s2), scale);
  }
  {  // pressure (s = 1) and cooling (s = 2) pieces
    const Q p1(pair, alpha, {x1, x2}, {ns + nw, ns + nw}, one);
    const Q p2(pair, alpha, {x1, x2}, {ns + nw, ns + nw}, two);
    auto partner = [](const Q& q) { return [&q](int a, int j) { return q.moment({a, j, 0, 0}); }; };
    auto self = [](const Q& q) { return [&q](int b, int j) { return q.moment({j, b, 0, 0}); }; };
    out.pressure_partner = rounded(contract2<Rational>(partner(p1), sca2, s1), p1.power_factor() / root);
    out.pressure_self = rounded(contract2<Rational>(self(p1), sca1, s2), p1.power_factor() / root);
    out.cooling_partner = rounded(contract2<Rational>(partner(p2), sca2, s1), p2.power_factor() / theta_j);
    out.cooling_self = rounded(contract2<Rational>(self(p2), sca1, s2), p2.power_factor() / theta_j);
  }
  // [k][l] tables: contract2's first raw argument runs with l (X2), the second with k (X1).
  {  // shear gradient: 2θ_j v2 − 2θ_i v1 = 2√θ_j (u2 − r² u1), each with its own gradient weight
    const Q g0(pair, alpha, {h2, h1, x1, x2}, {1, 1, nw, nw}, zero);
    auto partner = [&](int b, int a) { return g0.moment({1, 0, a, b}); };
    auto self = [&](int b, int a) { return r2 * g0.moment({0, 1, a, b}); };
    const std::vector<Rational> p = contract2<Rational>(partner, s1, g2), s = contract2<Rational>(self, g1, s2);
    for (std::size_t k = 0; k < p.size(); ++k) out.shear_gradient.push_back(2 / a1 * (p[k] - s[k]).to_double());
  }
  {  // cooling gradient (s = 1)
    const Q c(pair, alpha, {h2, x1, x2}, {1, nw, nw}, one);
    auto raw = [&](int b, int a) { return c.moment({1, a, b, 0}); };
    out.cooling_gradient = rounded(contract2<Rational>(raw, s1, g2), 2 / (root * a1) * c.power_factor());
  }
  {  // energy changes (s = 0): ΔE_1 = energy_unit (u1'² − u1²)
    const Q e(pair, alpha, {x1p, x1, x2}, {1, nw + 1, nw}, zero);
    auto raw = [&](int b, int a) { return e.moment({1, a, b, 0}) - e.moment({0, a + 1, b, 0}); };
    out.energy = rounded(contract2<Rational>(raw, s1, s2), energy_unit);
    out.energy_temperature_self = rounded(contract2<Rational>(raw, t1, s2), energy_unit);
    out.energy_temperature_partner = rounded(contract2<Rational>(raw, s1, t2), energy_unit);
  }
  return out;
}

PairTransferMoments contracted_pair_transfer(const WeightedPairTransferMoments& w, std::span<const double> a_i,
                                             std::span<const double> a_j) {
  const auto nk = static_cast<std::size_t>(w.k_max) + 1;
  if (a_i.size() != nk || a_j.size() != nk)
    throw std::invalid_argument("contracted_pair_transfer: the cumulants must have k_max + 1 entries");
  auto both = [&](const std::vector<double>& t, int p) {  // Σ_kl a_i[k] a_j[l] t[p][k][l]
    double acc = 0;
    for (std::size_t k = 0; k < nk; ++k)
      for (std::size_t l = 0; l < nk; ++l)
        acc += a_i[k] * a_j[l] * t[w.index(p, static_cast<int>(k), static_cast<int>(l))];
    return acc;
  };
  auto pair2 = [&](const std::vector<double>& t) {  // Σ_kl a_i[k] a_j[l] t[k][l]
    double acc = 0;
    for (std::size_t k = 0; k < nk; ++k)
      for (std::size_t l = 0; l < nk; ++l) acc += a_i[k] * a_j[l] * t[k * nk + l];
    return acc;
  };
  auto one = [&](const std::vector<double>& t, std::span<const double> a, int q) {  // Σ_k a[k] t[q][k]
    double acc = 0;
    for (std::size_t k = 0; k < nk; ++k) acc += a[k] * t[w.index(q, static_cast<int>(k))];
    return acc;
  };
  PairTransferMoments out;
  out.n_max = w.n_max;
  for (int p = 0; p <= w.n_max; ++p) {
    out.source_density.push_back(both(w.source_density, p));
    out.source_temperature.push_back(both(w.source_temperature, p));
    out.source_shear.push_back(both(w.source_shear, p));
    out.source_scalar.push_back(both(w.source_scalar, p));
    out.shear_flux_partner.push_back(one(w.shear_flux_partner, a_i, p));
    out.shear_flux_self.push_back(one(w.shear_flux_self, a_j, p));
    out.heat_flux_partner.push_back(one(w.heat_flux_partner, a_i, p));
    out.heat_flux_self.push_back(one(w.heat_flux_self, a_j, p));
    out.pressure_partner.push_back(one(w.pressure_partner, a_i, p));
    out.pressure_self.push_back(one(w.pressure_self, a_j, p));
    out.cooling_partner.push_back(one(w.cooling_partner, a_i, p));
    out.cooling_self.push_back(one(w.cooling_self, a_j, p));
  }
  out.shear_gradient = pair2(w.shear_gradient);
  out.cooling_gradient = pair2(w.cooling_gradient);
  out.energy = pair2(w.energy);
  out.energy_self = pair2(w.energy_temperature_self) + 0.5 * w.dimension * out.energy;
  out.energy_partner = pair2(w.energy_temperature_partner) + 0.5 * w.dimension * out.energy;
  return out;
}

}  // namespace gkt
