#include "gkt/transport/rough/rough_mixture_sonine_cooling_state.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "algebra/nearby_rational.hpp"
#include "gkt/collision/rough_mixture_collision_moments.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"

namespace gkt {

namespace {

int rotational_freedom(int d) { return d == 3 ? 3 : 1; }

std::size_t pair_index(std::size_t i, std::size_t j) { return i + j; }  // 0: 1–1, 1: 1–2, 2: 2–2

/// A polynomial in (X, Y) of one species: terms (coefficient, power of X, power of Y).
struct Term {
  Rational c;
  int x, y;
};
using Polynomial = std::vector<Term>;

/// The weights of (19.170): 1, S_2(X), S_2(Y), S_1(X)S_1(Y), S^(m) with m = d/2 − 1 (X), d_r/2 − 1 (Y).
std::array<Polynomial, 4> sonine_weights(int d) {
  const Rational mt(d - 2, 2), mr(d == 3 ? 1 : -1, 2);
  const auto s1 = [](const Rational& m, bool spin) {
    return Polynomial{{m + Rational(1), 0, 0}, {Rational(-1), spin ? 0 : 1, spin ? 1 : 0}};
  };
  const auto s2 = [](const Rational& m, bool spin) {
    const int x = spin ? 0 : 1, y = spin ? 1 : 0;
    return Polynomial{{(m + Rational(1)) * (m + Rational(2)) / Rational(2), 0, 0},
                      {-(m + Rational(2)), x, y},
                      {Rational(1, 2), 2 * x, 2 * y}};
  };
  Polynomial mixed;
  for (const auto& a : s1(mt, false))
    for (const auto& b : s1(mr, true)) mixed.push_back({a.c * b.c, a.x + b.x, a.y + b.y});
  return {Polynomial{{Rational(1), 0, 0}}, s2(mt, false), s2(mr, true), mixed};
}

/// The tests ψ of (19.171): X, Y, X², Y², XY (powers of X, Y).
constexpr std::array<std::array<int, 2>, 5> kTests{{{1, 0}, {0, 1}, {2, 0}, {0, 2}, {1, 1}}};

/// Collision averages of an i–j collision for the particle of species i (slot 1), normalised by the
/// Maxwellian collision rate: own[w][t] = ⟨Φ_w(1)(ψ_t(1') − ψ_t(1))⟩, partner[w][t] = ⟨Φ_w(2)(ψ_t(1') − ψ_t(1))⟩
/// (w = 0: Φ = 1, counted once, in own only).
struct PairProductions {
  std::array<std::array<double, 5>, 4> own{}, partner{};
};

PairProductions pair_productions(int d, const Rational& alpha, const Rational& beta, const RoughMixtureComponent& si,
                                 const RoughMixtureComponent& sj, const std::array<Rational, 4>& t) {
  const RoughSpecies i{si.mass, si.kappa, t[0], t[2]};
  const RoughSpecies j{sj.mass, sj.kappa, t[1], t[3]};
  const auto p = rough_mixture_parameters(d, alpha, beta, i, j);
  // Forms: 0 X1, 1 Y1, 2 X2, 3 Y2, 4 X1', 5 Y1' (each in its species' reduced velocity).
  const std::vector<RoughForm> forms{
      rough_mixture_reduced_square(p, RoughSlot::v1),      rough_mixture_reduced_square(p, RoughSlot::w1),
      rough_mixture_reduced_square(p, RoughSlot::v2),      rough_mixture_reduced_square(p, RoughSlot::w2),
      rough_mixture_reduced_square(p, RoughSlot::v1_post), rough_mixture_reduced_square(p, RoughSlot::w1_post)};
  // Only the products one weight × one test are needed (linear scheme): a down-closed union of four boxes.
  const auto keep = [](const RoughExponents& e) {
    const int own = e[0] + e[1], other = e[2] + e[3], post = e[4] + e[5];
    return (other == 0 && post == 0 && own <= 4) || (other == 0 && own <= 2 && post <= 2) ||
           (own == 0 && other <= 2 && post <= 2) || (post == 0 && own <= 2 && other <= 2);
  };
  const auto table = rough_mixture_collision_moments(p, forms, {4, 4, 2, 2, 2, 2}, keep);
  const auto m = [&table](int a, int b, int c, int e, int f, int g) {
    return table.moment(std::array<int, 6>{a, b, c, e, f, g});
  };
  const auto weights = sonine_weights(d);
  PairProductions out;
  for (std::size_t w = 0; w < 4; ++w)
    for (std::size_t k = 0; k < 5; ++k) {
      const int tx = kTests[k][0], ty = kTests[k][1];
      Rational own, partner;
      for (const auto& term : weights[w]) {
        own += term.c * (m(term.x, term.y, 0, 0, tx, ty) - m(term.x + tx, term.y + ty, 0, 0, 0, 0));
        partner += term.c * (m(0, 0, term.x, term.y, tx, ty) - m(tx, ty, term.x, term.y, 0, 0));
      }
      out.own[w][k] = own.to_double();
      out.partner[w][k] = w == 0 ? 0.0 : partner.to_double();
    }
  return out;
}

/// Q_i[t] = Σ_j w_ij R_ij[ψ_t] = constant[i][t] + Σ_u linear[i][t][u] a_u, a = (a20_1, a02_1, a11_1, a20_2, …)
/// ((19.171)); w_ij = Λ x_j (σ_ij/σ̄)^{d−1} √(γ_i m̄/m_i + γ_j m̄/m_j).
struct Productions {
  std::array<std::array<double, 5>, 2> constant{};
  std::array<std::array<std::array<double, 6>, 5>, 2> linear{};
};

Productions productions(const RoughBinaryMixture& m, const std::array<double, 4>& temperatures) {
  const int d = m.dimension;
  std::array<Rational, 4> t;
  for (std::size_t k = 0; k < 4; ++k) t[k] = detail::nearby_rational(temperatures[k] / temperatures[0]);
  std::array<double, 4> td;
  for (std::size_t k = 0; k < 4; ++k) td[k] = t[k].to_double();
  const auto& s = m.species;
  const double mean_mass = s[0].fraction * s[0].mass.to_double() + s[1].fraction * s[1].mass.to_double();
  const double mean_diameter = s[0].fraction * s[0].diameter + s[1].fraction * s[1].diameter;
  const double mix = s[0].fraction * td[0] + s[1].fraction * td[1];
  const double lambda = (d + 2) * std::sqrt(2.0) / 8.0;
  Productions q;
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t j = 0; j < 2; ++j) {
      if (s[j].fraction == 0) continue;
      const std::array<Rational, 4> tij{t[i], t[j], t[2 + i], t[2 + j]};
      const auto p = pair_productions(d, m.alpha[pair_index(i, j)], m.beta[pair_index(i, j)], s[i], s[j], tij);
      const double sigma_ij = 0.5 * (s[i].diameter + s[j].diameter) / mean_diameter;
      const double w =
          lambda * s[j].fraction * std::pow(sigma_ij, d - 1) *
          std::sqrt(td[i] / mix * mean_mass / s[i].mass.to_double() + td[j] / mix * mean_mass / s[j].mass.to_double());
      for (std::size_t k = 0; k < 5; ++k) {
        q.constant[i][k] += w * p.own[0][k];
        for (std::size_t c = 0; c < 3; ++c) {
          q.linear[i][k][3 * i + c] += w * p.own[c + 1][k];
          q.linear[i][k][3 * j + c] += w * p.partner[c + 1][k];
        }
      }
    }
  return q;
}

/// The Maxwellian fourth moments ⟨X²⟩, ⟨Y²⟩, ⟨XY⟩ = d(d+2)/4, d_r(d_r+2)/4, d d_r/4.
std::array<double, 3> maxwellian_fourth(int d) {
  const double dt = d, dr = rotational_freedom(d);
  return {dt / 2 * (dt / 2 + 1), dr / 2 * (dr / 2 + 1), dt / 2 * dr / 2};
}

/// The rates and balances, both affine in a: value = constant + linear·a ((19.172)–(19.173)).
struct Affine {
  Eigen::Vector4d rate_constant;
  Eigen::Matrix<double, 4, 6> rate_linear;
  Eigen::Matrix<double, 6, 1> balance_constant;
  Eigen::Matrix<double, 6, 6> balance_linear;
};

Affine affine_balances(const RoughBinaryMixture& m, const std::array<double, 4>& temperatures) {
  const Productions q = productions(m, temperatures);
  const double dt = m.dimension, dr = rotational_freedom(m.dimension);
  const auto base = maxwellian_fourth(m.dimension);
  Affine a;
  a.rate_linear.setZero();
  a.balance_linear.setZero();
  for (std::size_t i = 0; i < 2; ++i) {
    const auto ii = static_cast<Eigen::Index>(i);
    a.rate_constant(ii) = -2 / dt * q.constant[i][0];
    a.rate_constant(2 + ii) = -2 / dr * q.constant[i][1];
    for (std::size_t u = 0; u < 6; ++u) {
      a.rate_linear(ii, static_cast<Eigen::Index>(u)) = -2 / dt * q.linear[i][0][u];
      a.rate_linear(2 + ii, static_cast<Eigen::Index>(u)) = -2 / dr * q.linear[i][1][u];
    }
    // G_{p,i} = 2[ζ^M_t,i ⟨ψ_p⟩_M (1 + a_{p,i}) + δζ_t,i ⟨ψ_p⟩_M] + Q_i[ψ_p]  (19.173).
    for (std::size_t p = 0; p < 3; ++p) {
      const auto r = static_cast<Eigen::Index>(3 * i + p);
      a.balance_constant(r) = 2 * a.rate_constant(ii) * base[p] + q.constant[i][p + 2];
      for (std::size_t u = 0; u < 6; ++u)
        a.balance_linear(r, static_cast<Eigen::Index>(u)) =
            2 * a.rate_linear(ii, static_cast<Eigen::Index>(u)) * base[p] + q.linear[i][p + 2][u];
      a.balance_linear(r, r) += 2 * a.rate_constant(ii) * base[p];
    }
  }
  return a;
}

void check_temperatures(const std::array<double, 4>& t) {
  for (std::size_t k = 0; k < 4; ++k)
    if (!(t[k] > 0) || !std::isfinite(t[k]))
      throw std::invalid_argument("temperatures[" + std::to_string(k) + "]: must be a finite number > 0");
}

}  // namespace

RoughMixtureLinearBalances rough_mixture_linear_balances(const RoughBinaryMixture& mixture,
                                                         const std::array<double, 4>& temperatures,
                                                         const std::array<double, 6>& cumulants) {
  mixture.validate();
  check_temperatures(temperatures);
  for (std::size_t u = 0; u < 6; ++u)
    if (!std::isfinite(cumulants[u]))
      throw std::invalid_argument("cumulants[" + std::to_string(u) + "]: must be a finite number");
  const Affine a = affine_balances(mixture, temperatures);
  const Eigen::Matrix<double, 6, 1> c(cumulants.data());
  const Eigen::Vector4d rates = a.rate_constant + a.rate_linear * c;
  const Eigen::Matrix<double, 6, 1> balances = a.balance_constant + a.balance_linear * c;
  RoughMixtureLinearBalances out;
  for (Eigen::Index k = 0; k < 4; ++k) out.cooling_rate[static_cast<std::size_t>(k)] = rates(k);
  for (Eigen::Index k = 0; k < 6; ++k) out.balance[static_cast<std::size_t>(k)] = balances(k);
  return out;
}

RoughMixtureSonineCoolingState rough_mixture_sonine_cooling_state(const RoughBinaryMixture& mixture) {
  const RoughMixtureCoolingState maxwellian = rough_mixture_cooling_state(mixture);  // validates, refuses
  RoughMixtureSonineCoolingState out;
  for (std::size_t k = 0; k < 2; ++k) out.spin_decoupled[k] = std::isinf(maxwellian.rotational_ratio[k]);
  // Unknowns: ln(T_t,2/T_t,1) and ln θ_k of the coupled spins; cumulants: a20_k, and a02_k, a11_k if coupled.
  std::vector<Eigen::Index> cumulant_slots;
  for (std::size_t k = 0; k < 2; ++k) {
    cumulant_slots.push_back(static_cast<Eigen::Index>(3 * k));
    if (!out.spin_decoupled[k]) {
      cumulant_slots.push_back(static_cast<Eigen::Index>(3 * k + 1));
      cumulant_slots.push_back(static_cast<Eigen::Index>(3 * k + 2));
    }
  }
  std::vector<std::size_t> spins;
  for (std::size_t k = 0; k < 2; ++k)
    if (!out.spin_decoupled[k]) spins.push_back(k);
  const auto n = static_cast<Eigen::Index>(1 + spins.size());
  const auto nc = static_cast<Eigen::Index>(cumulant_slots.size());
  const auto temperatures_of = [&](const Eigen::VectorXd& u) {
    // A decoupled spin's temperature is any: its cumulants are held at 0 and nothing reads its spin (19.130).
    const double t2 = std::exp(u(0));
    std::array<double, 4> t{1.0, t2, 1.0, t2};
    for (std::size_t s = 0; s < spins.size(); ++s)
      t[2 + spins[s]] = t[spins[s]] * std::exp(u(static_cast<Eigen::Index>(1 + s)));
    return t;
  };
  struct Evaluation {
    Eigen::VectorXd residual;
    Eigen::Matrix<double, 6, 1> cumulants;
    Eigen::Vector4d rates;
  };
  const auto evaluate = [&](const Eigen::VectorXd& u) {
    const Affine a = affine_balances(mixture, temperatures_of(u));
    Eigen::MatrixXd m(nc, nc);
    Eigen::VectorXd g(nc);
    for (Eigen::Index r = 0; r < nc; ++r) {
      g(r) = a.balance_constant(cumulant_slots[static_cast<std::size_t>(r)]);
      for (Eigen::Index c = 0; c < nc; ++c)
        m(r, c) =
            a.balance_linear(cumulant_slots[static_cast<std::size_t>(r)], cumulant_slots[static_cast<std::size_t>(c)]);
    }
    const Eigen::VectorXd solution = m.fullPivLu().solve(-g);
    Evaluation e;
    e.cumulants.setZero();
    for (Eigen::Index r = 0; r < nc; ++r) e.cumulants(cumulant_slots[static_cast<std::size_t>(r)]) = solution(r);
    e.rates = a.rate_constant + a.rate_linear * e.cumulants;
    // Equal rates (19.174): ζ_t,1 = ζ_t,2 and ζ_t,k = ζ_r,k for each coupled spin.
    e.residual.resize(n);
    e.residual(0) = e.rates(0) - e.rates(1);
    for (std::size_t s = 0; s < spins.size(); ++s)
      e.residual(static_cast<Eigen::Index>(1 + s)) =
          e.rates(static_cast<Eigen::Index>(spins[s])) - e.rates(static_cast<Eigen::Index>(2 + spins[s]));
    return e;
  };
  Eigen::VectorXd u(n);
  u(0) = std::log(maxwellian.temperature_ratio[1] / maxwellian.temperature_ratio[0]);
  for (std::size_t s = 0; s < spins.size(); ++s)
    u(static_cast<Eigen::Index>(1 + s)) = std::log(maxwellian.rotational_ratio[spins[s]]);
  Evaluation e = evaluate(u);
  bool converged = false;
  try {
    int stalled = 0;
    for (int it = 0; it < 40 && !converged && stalled < 3; ++it) {
      out.iterations = it + 1;
      Eigen::MatrixXd jacobian(n, n);
      const double h = 1e-6;
      for (Eigen::Index c = 0; c < n; ++c) {
        Eigen::VectorXd shifted = u;
        shifted(c) += h;
        jacobian.col(c) = (evaluate(shifted).residual - e.residual) / h;
      }
      Eigen::VectorXd step = jacobian.fullPivLu().solve(-e.residual);
      if (!step.allFinite()) break;
      // A trust region of one unit in the logs (a factor e in a temperature ratio), then damping: halve the
      // step until the residual decreases (at most 10 times). Three steps in a row that reduce the residual by
      // less than 1 % are a local minimum of |residual| without a root (seen at α = 0.5, β = −0.5): give up.
      if (step.norm() > 1) step /= step.norm();
      double scale = 1;
      Evaluation next = evaluate(u + step);
      for (int halving = 0; halving < 10 && !(next.residual.norm() < e.residual.norm()) && step.norm() > 1e-12;
           ++halving) {
        scale /= 2;
        next = evaluate(u + scale * step);
      }
      stalled = next.residual.norm() > 0.99 * e.residual.norm() ? stalled + 1 : 0;
      u += scale * step;
      e = next;
      // The residual is exact at the rationalised temperatures (relative 1e-15): a full step of 1e-10 in the logs,
      // after steps that shrank quadratically, leaves the state at round-off; smaller steps only chase that noise.
      converged = scale == 1 && step.norm() < 1e-10;
    }
  } catch (const std::exception&) {
    // An iterate whose temperatures the engine refuses (a ratio under- or overflowing): no root on this path.
    converged = false;
  }
  const auto t = temperatures_of(u);
  const double mix = mixture.species[0].fraction * t[0] + mixture.species[1].fraction * t[1];
  const double nan = std::numeric_limits<double>::quiet_NaN();
  bool realizable = true;
  for (std::size_t k = 0; k < 2; ++k) {
    out.temperature_ratio[k] = t[k] / mix;
    out.rotational_ratio[k] = out.spin_decoupled[k] ? std::numeric_limits<double>::infinity() : t[2 + k] / t[k];
    out.a20[k] = e.cumulants(static_cast<Eigen::Index>(3 * k));
    out.a02[k] = out.spin_decoupled[k] ? nan : e.cumulants(static_cast<Eigen::Index>(3 * k + 1));
    out.a11[k] = out.spin_decoupled[k] ? nan : e.cumulants(static_cast<Eigen::Index>(3 * k + 2));
    realizable = realizable &&
                 rough_cumulants_realizable(mixture.dimension, out.a20[k], out.spin_decoupled[k] ? 0.0 : out.a02[k],
                                            out.spin_decoupled[k] ? 0.0 : out.a11[k]);
  }
  out.cooling_rate = e.rates(0);
  out.solved = converged && realizable;
  return out;
}

}  // namespace gkt
