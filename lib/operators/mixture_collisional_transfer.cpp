#include "gkt/operators/mixture_collisional_transfer.hpp"

#include <cmath>
#include <stdexcept>

#include "gkt/algebra/sonine.hpp"
#include "gkt/collision/collision_rule.hpp"
#include "gkt/collision/quadratic_form_moments.hpp"
#include "operators/transfer_contractions.hpp"

namespace gkt {

namespace {

using Q = QuadraticFormMoments<Rational>;
using Poly = std::vector<Rational>;  // coefficients of x^a

/// The Sonine polynomials of the index with twice_m, as polynomials in x = u² for X = w x.
std::vector<Poly> sonine_in(long twice_m, int n_max, const Rational& w) {
  return detail::scaled_argument(sonine_table(twice_m, n_max), w);
}

int degree(const std::vector<Poly>& t) {
  std::size_t n = 1;
  for (const auto& s : t) n = std::max(n, s.size());
  return static_cast<int>(n) - 1;
}

/// Σ_a s[a] · m(a): a polynomial of one form's power, the other exponents fixed by `moment`.
template <class F>
Rational contract(const Poly& s, F moment) {
  Rational acc(0);
  for (std::size_t a = 0; a < s.size(); ++a)
    if (!s[a].is_zero()) acc += s[a] * moment(static_cast<int>(a));
  return acc;
}

}  // namespace

PairTransferMoments pair_transfer_moments(int dimension, const Rational& mass_ratio, const Rational& width_root,
                                          const Rational& alpha, int n_max, double mass_i, double theta_j) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("dimension: must be 2 or 3");
  if (n_max < 0) throw std::invalid_argument("n_max: must be >= 0");
  if (!(theta_j > 0) || !(mass_i > 0)) throw std::invalid_argument("pair_transfer_moments: mass and width must be > 0");
  const int d = dimension;
  // Pair units u = √θ_j v (θ_j = 1, θ_i = r²): c1 = r u1, c2 = u2, X1 = r² u1², X2 = u2².
  const Rational r = width_root, r2 = width_root * width_root;
  const CollisionPair pair{d, mass_ratio, Rational(1), r2, Rational(1)};
  const SlotVector u1 = slot_vector(Slot::v1), u2 = slot_vector(Slot::v2), u1p = slot_vector(Slot::v1_post);
  const SlotVector h = collision_vector();
  const VelocityForm x1 = dot_form(u1, u1), x2 = dot_form(u2, u2), x1p = dot_form(u1p, u1p), hh = dot_form(h, h);
  const VelocityForm h1 = dot_form(h, u1), h2 = dot_form(h, u2), h1p = dot_form(h, u1p);
  const Rational minus_one(-1), one(1), two(2), zero(0), inv_d(1, static_cast<unsigned long>(d));
  const Rational half_d(d, 2);
  const auto vec1 = sonine_in(sonine_twice_m(d, 1), n_max, r2);  // vector S_p(X1)
  const auto vec2 = sonine_in(sonine_twice_m(d, 1), n_max, one);
  const auto ten1 = sonine_in(sonine_twice_m(d, 2), n_max, r2);
  const auto ten2 = sonine_in(sonine_twice_m(d, 2), n_max, one);
  const auto sca1 = sonine_in(sonine_twice_m(d, 0), n_max, r2);
  const auto sca2 = sonine_in(sonine_twice_m(d, 0), n_max, one);
  const int nv = degree(vec1), nt = degree(ten1), ns = degree(sca1);

  // ⟨⟨(σ̂·g)^a Π_k (σ̂·A) Y⟩⟩ = θ_j^{−a/2} (1+α)^{−k} (J_s0/J0) ⟨Π_k (H·A) Y⟩_s in pair units, s = a − k.
  const double a1 = 1 + alpha.to_double(), root = std::sqrt(theta_j);
  const double energy_unit = mass_i / (2 * theta_j);  // ΔE_1 = energy_unit (u1'² − u1²)
  const auto n = static_cast<std::size_t>(n_max) + 1;
  PairTransferMoments out;
  out.n_max = n_max;

  {  // vector sources (a = 0, k = 1): gain (H·u1') S_p(r² u1'²), loss (H·u1) S_p(r² u1²), × (x2 − d/2)
    const Q gain(pair, alpha, {x1p, h1p, x2}, {nv, 1, 1}, minus_one);
    const Q loss(pair, alpha, {x1, h1, x2}, {nv, 1, 1}, minus_one);
    const double scale = r.to_double() * gain.power_factor() / a1;
    for (std::size_t p = 0; p < n; ++p) {
      auto term = [&](int b) {
        return contract(vec1[p], [&](int a) { return gain.moment({a, 1, b, 0}) - loss.moment({a, 1, b, 0}); });
      };
      out.source_density.push_back(scale * term(0).to_double());
      out.source_temperature.push_back(scale * (term(1) - half_d * term(0)).to_double());
    }
  }
  {  // shear source: Y(c1'):(H c2) = r²[(u1'·H)(u1'·u2) − u1'²(H·u2)/d], polarised
    const SlotVector hp = combine(h, u2, one), hm = combine(h, u2, minus_one);
    const Q gp(pair, alpha, {x1p, dot_form(u1p, hp)}, {nt, 2}, minus_one);
    const Q gm(pair, alpha, {x1p, dot_form(u1p, hm)}, {nt, 2}, minus_one);
    const Q gh(pair, alpha, {x1p, h2}, {nt + 1, 1}, minus_one);
    const Q lp(pair, alpha, {x1, dot_form(u1, hp)}, {nt, 2}, minus_one);
    const Q lm(pair, alpha, {x1, dot_form(u1, hm)}, {nt, 2}, minus_one);
    const Q lh(pair, alpha, {x1, h2}, {nt + 1, 1}, minus_one);
    const double scale = r2.to_double() * gp.power_factor() / a1;
    const Rational quarter(1, 4);
    for (std::size_t p = 0; p < n; ++p) {
      const Rational v = contract(ten1[p], [&](int a) {
        const Rational g =
            quarter * (gp.moment({a, 2, 0, 0}) - gm.moment({a, 2, 0, 0})) - inv_d * gh.moment({a + 1, 1, 0, 0});
        const Rational l =
            quarter * (lp.moment({a, 2, 0, 0}) - lm.moment({a, 2, 0, 0})) - inv_d * lh.moment({a + 1, 1, 0, 0});
        return g - l;
      });
      out.source_shear.push_back(scale * v.to_double());
    }
  }
  {  // scalar source: (H·u2)[S_p(r² u1'²) − S_p(r² u1²)]
    const Q f(pair, alpha, {x1p, x1, h2}, {ns, ns, 1}, minus_one);
    const double scale = f.power_factor() / a1;
    for (std::size_t p = 0; p < n; ++p) {
      const Rational v = contract(sca1[p], [&](int a) { return f.moment({a, 0, 1, 0}) - f.moment({0, a, 1, 0}); });
      out.source_scalar.push_back(scale * v.to_double());
    }
  }
  {  // shear fluxes (a = 1, k = 2): (H·c)² − H² X/d
    const Q fp(pair, alpha, {x2, h2, hh}, {nt + 1, 2, 1}, minus_one);
    const Q fs(pair, alpha, {x1, h1, hh}, {nt + 1, 2, 1}, minus_one);
    const double scale = fp.power_factor() / (root * a1 * a1);
    for (std::size_t q = 0; q < n; ++q) {
      const Rational vp = contract(ten2[q], [&](int a) {
        return fp.moment({a, 2, 0, 0}) - inv_d * fp.moment({a + 1, 0, 1, 0});
      });
      const Rational vs = contract(ten1[q], [&](int a) {
        return r2 * (fs.moment({a, 2, 0, 0}) - inv_d * fs.moment({a + 1, 0, 1, 0}));
      });
      out.shear_flux_partner.push_back(scale * vp.to_double());
      out.shear_flux_self.push_back(scale * vs.to_double());
    }
  }
  {  // heat fluxes (a = 0, k = 1): (H·c) (u1'² − u1²) S_q(X)
    const Q fp(pair, alpha, {x2, h2, x1p, x1}, {nv, 1, 1, 1}, minus_one);
    const Q fs(pair, alpha, {x1, h1, x1p}, {nv + 1, 1, 1}, minus_one);
    const double scale = energy_unit * fp.power_factor() / a1;
    for (std::size_t q = 0; q < n; ++q) {
      const Rational vp = contract(vec2[q], [&](int a) { return fp.moment({a, 1, 1, 0}) - fp.moment({a, 1, 0, 1}); });
      const Rational vs = contract(vec1[q], [&](int a) {
        return r * (fs.moment({a, 1, 1, 0}) - fs.moment({a + 1, 1, 0, 0}));
      });
      out.heat_flux_partner.push_back(scale * vp.to_double());
      out.heat_flux_self.push_back(scale * vs.to_double());
    }
  }
  {  // pressure (s = 1) and cooling (s = 2) pieces: S_q(X) alone
    const Q p1(pair, alpha, {x1, x2}, {ns, ns}, one);
    const Q p2(pair, alpha, {x1, x2}, {ns, ns}, two);
    for (std::size_t q = 0; q < n; ++q) {
      out.pressure_partner.push_back(p1.power_factor() / root * contract(sca2[q], [&](int a) {
                                                                  return p1.moment({0, a, 0, 0});
                                                                }).to_double());
      out.pressure_self.push_back(p1.power_factor() / root * contract(sca1[q], [&](int a) {
                                                               return p1.moment({a, 0, 0, 0});
                                                             }).to_double());
      out.cooling_partner.push_back(p2.power_factor() / theta_j * contract(sca2[q], [&](int a) {
                                                                    return p2.moment({0, a, 0, 0});
                                                                  }).to_double());
      out.cooling_self.push_back(p2.power_factor() / theta_j * contract(sca1[q], [&](int a) {
                                                                 return p2.moment({a, 0, 0, 0});
                                                               }).to_double());
    }
  }
  {  // gradients: shear (a = 1, k = 1, s = 0), 2θ_j v2 − 2θ_i v1 = 2√θ_j (u2 − r² u1); cooling (a = 2, s = 1)
    const Q g0(pair, alpha, {h2, h1}, {1, 1}, zero);
    out.shear_gradient = 2 / a1 * (g0.moment({1, 0, 0, 0}) - r2 * g0.moment({0, 1, 0, 0})).to_double();
    const Q g1(pair, alpha, {h2}, {1}, one);
    out.cooling_gradient = 2 / (root * a1) * g1.power_factor() * g1.moment({1, 0, 0, 0}).to_double();
  }
  {  // energy changes (s = 0): ΔE_1 × {1, X1, X2}
    const Q e(pair, alpha, {x1p, x1, x2}, {1, 2, 1}, zero);
    const Rational de = e.moment({1, 0, 0, 0}) - e.moment({0, 1, 0, 0});
    const Rational de1 = r2 * (e.moment({1, 1, 0, 0}) - e.moment({0, 2, 0, 0}));
    const Rational de2 = e.moment({1, 0, 1, 0}) - e.moment({0, 1, 1, 0});
    out.energy = energy_unit * de.to_double();
    out.energy_self = energy_unit * de1.to_double();
    out.energy_partner = energy_unit * de2.to_double();
  }
  return out;
}

}  // namespace gkt
