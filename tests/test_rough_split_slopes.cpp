// The four-field stability closure about the Sonine HCS (docs/theory.md §19.27): the slopes Γ*, Z_δ of the
// cumulant-corrected rates (rough_split_slopes.hpp) against
//  (a) the Maxwellian closure of §19.15.1: at zero cumulants and the Maxwellian θ they are (19.17) and (19.37) from the
//      first-Sonine bulk response (rough_bulk_viscosity.hpp), and the four-field modes with them are those of (19.36);
//  (b) a finite difference written here through other tables: the first-Sonine rates of rough_cooling_rates.hpp at
//      the linear HCS of rough_homogeneous_cooling_state, θ perturbed with the cumulants held, and with the cumulants
//      re-solved from their balances at the perturbed θ (the slaved slope, (19.143));
//  (c) switching the cumulants off (a_pq → λa_pq, θ re-balanced): Γ*, Z_δ and the growth rate of the clustering mode
//      tend to the Maxwellian ones linearly in λ;
//  (d) α = β = 1: no energy loss at any θ, Z_δ = ζ* = 0, no growing mode;
//  (e) the slowest homogeneous rate (19.144) against the late-time approach of θ to the HCS in the CVODE integration of
//      the same linear scheme (`gkt evolve`'s integrator);
//  (f) the model: the critical values with the field closure about the Sonine HCS equal the slaved ones ((19.38)).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "gkt/evolution/rough_cooling_evolution.hpp"
#include "gkt/evolution/rough_hcs_stability.hpp"
#include "gkt/models/transport_model.hpp"
#include "gkt/transport/rough/rough_bulk_viscosity.hpp"
#include "gkt/transport/rough/rough_cooling_rates.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_shear_viscosity.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_rates.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_state.hpp"
#include "gkt/transport/rough/rough_split_slopes.hpp"
#include "gkt/transport/rough/rough_thermal_conductivity.hpp"

using gkt::Rational;

namespace {

struct State {
  int d;
  Rational alpha, beta, kappa;
};

/// Strong and medium roughness, spheres and disks, inside the linear scheme's root region (theory.md §19.6).
std::vector<State> states() {
  return {{3, Rational(9, 10), Rational(1, 2), Rational(2, 5)},
          {3, Rational(7, 10), Rational(0), Rational(2, 5)},
          {3, Rational(9, 10), Rational(-1, 2), Rational(2, 5)},
          {2, Rational(9, 10), Rational(1, 2), Rational(1, 2)},
          {2, Rational(7, 10), Rational(0), Rational(1, 2)}};
}

/// The order-1 isotropic rates' unknowns (a_pq in the order of cumulant_indices) from (a20, a02, a11).
std::vector<double> unknowns_of(const gkt::RoughSonineCoolingRates& rates, double a20, double a02, double a11) {
  std::vector<double> u;
  for (const auto& pq : rates.cumulant_indices())
    u.push_back(pq == std::array<int, 2>{2, 0} ? a20 : pq == std::array<int, 2>{0, 2} ? a02 : a11);
  return u;
}

/// The first-Sonine input of (19.36) at θ, ζ* (coefficients about the Maxwellian, as in §19.15.1).
gkt::RoughStabilityInput first_sonine_input(const State& s, double theta, double zeta) {
  const auto q = gkt::rough_thermal_conductivity(s.d, s.alpha, s.beta, s.kappa);
  const auto b = gkt::rough_bulk_viscosity(s.d, s.alpha, s.beta, s.kappa);
  gkt::RoughStabilityInput in;
  in.dimension = s.d;
  in.temperature_ratio = theta;
  in.cooling_rate = zeta;
  in.shear_viscosity = gkt::rough_shear_viscosity(s.d, s.alpha, s.beta, s.kappa);
  in.bulk_viscosity = b.bulk_viscosity;
  in.thermal_conductivity = q.total;
  in.density_heat_coefficient = q.density_heat_total;
  in.cooling_rate_first_order = b.cooling_rate_first_order;
  in.relaxation_rate = b.relaxation_rate;
  return in;
}

}  // namespace

// (a) Zero cumulants at the Maxwellian θ: the order-1 Sonine tables' slopes are the Maxwellian closure's — Γ* of
// (19.17) and Z_δ = (d/2)(ζ*/2 + Γ*)ζ_U of (19.37), both from rough_bulk_viscosity's first-Sonine solution (other
// tables, closed in θ). Tolerance 1e-9: the Richardson difference's O(h⁴) = 1e-12 and round-off 1e-13/h². The
// four-field eigenvalues with the explicit slopes equal those of the default path (1e-9).
TEST(RoughSplitSlopes, MaxwellianRatesGiveTheFirstApproximation) {
  for (const State& s : states()) {
    const auto m = gkt::rough_homogeneous_cooling_state(s.d, s.alpha, s.beta, s.kappa, gkt::RoughHcsScheme::maxwellian);
    const auto b = gkt::rough_bulk_viscosity(s.d, s.alpha, s.beta, s.kappa);
    const gkt::RoughSonineCoolingRates rates(s.d, s.alpha, s.beta, s.kappa, 1, gkt::RoughSonineAnsatz::isotropic);
    const std::vector<double> zero(rates.unknowns(), 0.0);
    const auto slopes = gkt::rough_split_slopes(rates, m.temperature_ratio, zero);
    const double split = b.cooling_rate_first_order * s.d * (m.cooling_rate / 2 + b.relaxation_rate) / 2;
    EXPECT_NEAR(slopes.cooling_rate, m.cooling_rate, 1e-12) << s.d << s.beta.to_string();
    EXPECT_NEAR(slopes.relaxation_rate, b.relaxation_rate, 1e-9 * b.relaxation_rate) << s.d << s.beta.to_string();
    EXPECT_NEAR(slopes.cooling_split_slope, split, 1e-9 * std::abs(split)) << s.d << s.beta.to_string();
    auto in = first_sonine_input(s, m.temperature_ratio, m.cooling_rate);
    const auto before = gkt::rough_longitudinal_modes_with_spin(in, 0.2);
    in.relaxation_rate = slopes.relaxation_rate;
    in.cooling_split_slope = slopes.cooling_split_slope;
    const auto after = gkt::rough_longitudinal_modes_with_spin(in, 0.2);
    for (const auto& x : after) {  // nearest match: a complex pair's two members tie in the ordering
      double best = INFINITY;
      for (const auto& y : before) best = std::min(best, std::abs(x - y));
      EXPECT_LT(best, 1e-9) << s.d << s.beta.to_string();
    }
  }
}

// (b) About the linear first-Sonine HCS (θ, a20, a02, a11 of rough_homogeneous_cooling_state, its own tables): the
// held slopes against a central difference of RoughCoolingRates in ln θ (step 1e-4: error (1e-4)² ~ 1e-8 relative,
// tolerance 1e-6); the slaved Γ* against the same difference with a20, a02, a11 re-solved at θe^{±ε} from the three
// balances dv/dτ = 0 (G_p + l_p (z_r − z_t)⟨ψ_p⟩ = 0, ⟨ψ_p⟩ = ⟨ψ_p⟩_M(1 + a_p), l = (0, 2, 1); Newton with the exact
// ∂G/∂a and a difference for the rest); the homogeneous eigenvalue lies with the slaved rate, not the held one, where
// the cumulants relax faster than θ.
TEST(RoughSplitSlopes, AgainstTheFirstSonineTablesHeldAndSlaved) {
  for (const State& s : states()) {
    const auto h = gkt::rough_homogeneous_cooling_state(s.d, s.alpha, s.beta, s.kappa, gkt::RoughHcsScheme::linear);
    ASSERT_TRUE(h.linear_scheme_solved) << s.d << s.alpha.to_string() << s.beta.to_string();
    const gkt::RoughSonineCoolingRates rates(s.d, s.alpha, s.beta, s.kappa, 1, gkt::RoughSonineAnsatz::isotropic);
    const auto slopes = gkt::rough_split_slopes(rates, h.temperature_ratio, unknowns_of(rates, h.a20, h.a02, h.a11));
    const gkt::RoughCoolingRates first(s.d, s.alpha, s.beta, s.kappa);
    const double c = (s.d + 2) / 4.0, kappa = s.kappa.to_double(), theta = h.temperature_ratio;
    const double d = s.d, d_r = s.d == 3 ? 3.0 : 1.0;
    const std::array<double, 3> held{h.a20, h.a02, h.a11};
    const auto excess = [&](double t, const std::array<double, 3>& a) {
      const auto r = first.at(t / kappa, a);
      return c * (r.rotational_rate - r.translational_rate);
    };
    const auto cooling = [&](double t, const std::array<double, 3>& a) {
      const auto r = first.at(t / kappa, a);
      const double share = d / (d + d_r * t);
      return c * std::sqrt((d + d_r * theta) / (d + d_r * t)) *
             (share * r.translational_rate + (1 - share) * r.rotational_rate);
    };
    const double eps = 1e-4, up = theta * std::exp(eps), down = theta * std::exp(-eps);
    const double gamma_held = (excess(up, held) - excess(down, held)) / (2 * eps);
    const double split_held = (cooling(up, held) - cooling(down, held)) / (2 * eps);
    EXPECT_NEAR(slopes.relaxation_rate, gamma_held, 1e-6 * std::abs(gamma_held)) << s.d << s.beta.to_string();
    EXPECT_NEAR(slopes.cooling_split_slope, split_held, 1e-6 * std::abs(split_held)) << s.d << s.beta.to_string();
    // The cumulants on their static balance at θ'.
    const auto base = first.maxwellian_fourth_moments();
    constexpr std::array<double, 3> spin{0, 2, 1};
    const auto balance = [&](double t, const std::array<double, 3>& a) {
      const auto r = first.at(t / kappa, a);
      Eigen::Vector3d g;
      for (int p = 0; p < 3; ++p)
        g(p) = r.residual[p + 1] + spin[p] * (r.rotational_rate - r.translational_rate) * base[p] * (1 + a[p]);
      return g;
    };
    const auto slaved = [&](double t) {
      std::array<double, 3> a = held;
      for (int iteration = 0; iteration < 20; ++iteration) {
        Eigen::Matrix3d jac;
        for (int w = 0; w < 3; ++w) {
          auto plus = a, minus = a;
          plus[w] += 1e-6;
          minus[w] -= 1e-6;
          jac.col(w) = (balance(t, plus) - balance(t, minus)) / 2e-6;
        }
        const Eigen::Vector3d step = jac.fullPivLu().solve(-balance(t, a));
        for (int w = 0; w < 3; ++w) a[w] += step(w);
        if (step.norm() < 1e-15) break;
      }
      return a;
    };
    EXPECT_LT(balance(theta, held).norm(), 1e-10);  // the HCS is the static solution at its own θ
    const double gamma_slaved = (excess(up, slaved(up)) - excess(down, slaved(down))) / (2 * eps);
    const double split_slaved = (cooling(up, slaved(up)) - cooling(down, slaved(down))) / (2 * eps);
    EXPECT_NEAR(slopes.relaxation_rate_slaved, gamma_slaved, 1e-6 * std::abs(gamma_slaved)) << s.d;
    EXPECT_NEAR(slopes.cooling_split_slope_slaved, split_slaved, 1e-6 * std::abs(split_slaved)) << s.d;
    EXPECT_GT(slopes.homogeneous_relaxation_rate, 0) << s.d;
  }
}

// (c) The cumulants switched off: a_pq → λa_pq with θ(λ) re-balancing z_r = z_t (bisection in ln θ), λ = 0.1, 0.01,
// 0.001: Γ*, Z_δ and the clustering mode's growth rate at k* = 0.2 (four fields, first-Sonine coefficients at θ(λ))
// approach the Maxwellian values, the distance falling by 10 ± 1.5 per decade of λ (linear); at λ = 1 they are the
// HCS's.
TEST(RoughSplitSlopes, SwitchingOffTheCumulantsGivesTheMaxwellianClosure) {
  for (const State& s : {states()[0], states()[3]}) {
    const auto m = gkt::rough_homogeneous_cooling_state(s.d, s.alpha, s.beta, s.kappa, gkt::RoughHcsScheme::maxwellian);
    const auto h = gkt::rough_homogeneous_cooling_state(s.d, s.alpha, s.beta, s.kappa, gkt::RoughHcsScheme::linear);
    const gkt::RoughSonineCoolingRates rates(s.d, s.alpha, s.beta, s.kappa, 1, gkt::RoughSonineAnsatz::isotropic);
    const std::vector<double> u = unknowns_of(rates, h.a20, h.a02, h.a11);
    const double kappa = s.kappa.to_double();
    const auto slopes_at = [&](double lambda) {
      std::vector<double> v = u;
      for (double& x : v) x *= lambda;
      const auto excess = [&](double ell) {
        const auto r = rates.at(std::exp(ell) / kappa, v);
        return r.rotational_rate - r.translational_rate;
      };
      double lo = std::log(m.temperature_ratio) - 1, hi = std::log(m.temperature_ratio) + 1;
      EXPECT_LT(excess(lo) * excess(hi), 0);
      for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
        const double mid = (lo + hi) / 2;
        (excess(mid) * excess(lo) > 0 ? lo : hi) = mid;
      }
      return gkt::rough_split_slopes(rates, std::exp((lo + hi) / 2), v);
    };
    const auto growth = [&](const gkt::RoughSplitSlopes& sl) {
      auto in = first_sonine_input(s, sl.temperature_ratio, sl.cooling_rate);
      in.relaxation_rate = sl.relaxation_rate;
      in.cooling_split_slope = sl.cooling_split_slope;
      return gkt::rough_longitudinal_modes_with_spin(in, 0.2)[0].real();
    };
    const auto full = slopes_at(1);
    EXPECT_NEAR(full.temperature_ratio, h.temperature_ratio, 1e-10 * h.temperature_ratio);
    const double maxwellian_growth =
        gkt::rough_longitudinal_modes_with_spin(first_sonine_input(s, m.temperature_ratio, m.cooling_rate), 0.2)[0]
            .real();
    const auto b = gkt::rough_bulk_viscosity(s.d, s.alpha, s.beta, s.kappa);
    std::vector<std::array<double, 3>> distance;
    for (double lambda : {0.1, 0.01, 0.001}) {
      const auto sl = slopes_at(lambda);
      distance.push_back({std::abs(sl.relaxation_rate - b.relaxation_rate),
                          std::abs(sl.cooling_split_slope -
                                   b.cooling_rate_first_order * s.d * (m.cooling_rate / 2 + b.relaxation_rate) / 2),
                          std::abs(growth(sl) - maxwellian_growth)});
    }
    for (std::size_t q = 0; q < 3; ++q)
      for (std::size_t j = 1; j < 3; ++j) {
        const double ratio = distance[j - 1][q] / distance[j][q];
        EXPECT_GT(ratio, 8.5) << s.d << " quantity " << q << " decade " << j;
        EXPECT_LT(ratio, 11.5) << s.d << " quantity " << q << " decade " << j;
      }
  }
}

// (d) α = β = 1: energy is conserved at every θ and the HCS is the equilibrium (zero cumulants): ζ* = Z_δ = 0 to
// round-off, Γ* > 0 the equipartition rate (19.17), and no mode of (19.36) grows (d = 2, 3).
TEST(RoughSplitSlopes, PidduckGasLosesNoEnergy) {
  for (int d : {3, 2}) {
    const Rational kappa = d == 3 ? Rational(2, 5) : Rational(1, 2);
    const auto state =
        gkt::rough_sonine_cooling_state(d, Rational(1), Rational(1), kappa, 1, gkt::RoughSonineScheme::linear);
    ASSERT_TRUE(state.solved);
    const gkt::RoughSonineCoolingRates rates(d, Rational(1), Rational(1), kappa, 1, gkt::RoughSonineAnsatz::isotropic);
    const auto slopes = gkt::rough_split_slopes(rates, state.temperature_ratio, state.cumulants);
    const auto b = gkt::rough_bulk_viscosity(d, Rational(1), Rational(1), kappa);
    EXPECT_NEAR(slopes.cooling_rate, 0, 1e-13);
    EXPECT_NEAR(slopes.cooling_split_slope, 0, 1e-10);
    EXPECT_NEAR(slopes.relaxation_rate, b.relaxation_rate, 1e-9 * b.relaxation_rate);
    auto in = first_sonine_input({d, Rational(1), Rational(1), kappa}, state.temperature_ratio, 0.0);
    in.relaxation_rate = slopes.relaxation_rate;
    in.cooling_split_slope = slopes.cooling_split_slope;
    for (double k : {0.05, 0.3, 1.0}) EXPECT_LE(gkt::rough_longitudinal_modes_with_spin(in, k)[0].real(), 1e-12) << k;
  }
}

// (f) The model about the Sonine HCS (hcs = linear, hcs_order 2 and 3, d = 2, 3): the field closure's critical values
// equal the slaved ones (det M4 = −Γ* det M3 for any Γ*, Z_δ, (19.38); 1e-10, the bisection's accuracy), and the
// nonlinear scheme, whose products the linear rates' slopes leave out, is refused.
TEST(RoughSplitSlopes, ModelCriticalValuesAboutTheHcsAreTheSlavedOnes) {
  const std::vector<std::string> columns{"critical_wavenumber_shear", "critical_wavenumber_heat", "critical_length"};
  for (int d : {3, 2})
    for (int degree : {2, 3}) {
      auto model = gkt::make_transport_model("rough");
      gkt::ParameterPoint p;
      p.numbers = {{"dimension", Rational(d)},
                   {"alpha", Rational(9, 10)},
                   {"beta", Rational(1, 2)},
                   {"moment_of_inertia", d == 3 ? Rational(2, 5) : Rational(1, 2)},
                   {"hcs_order", Rational(degree)}};
      p.choices = {{"hcs", "linear"}, {"reference_state", "hcs"}};
      gkt::OrderRequest request;
      request.order = 1;
      const auto slaved = model->evaluate(p, columns, request);
      p.choices["rotational_temperature_closure"] = "field";
      const auto field = model->evaluate(p, columns, request);
      for (std::size_t c = 0; c < 3; ++c) {
        const double x = slaved[c].value.to_double(), y = field[c].value.to_double();
        EXPECT_GT(x, 0) << d << degree << c;
        EXPECT_NEAR(y, x, 1e-10 * x) << d << degree << c;
        EXPECT_NEAR(field[c].error.to_double(), slaved[c].error.to_double(), 1e-10 * x) << d << degree << c;
      }
      p.choices["hcs"] = "nonlinear";
      EXPECT_THROW((void)model->evaluate(p, columns, request), std::invalid_argument);
    }
}

// (e) The homogeneous linear scheme of order 1 (isotropic) integrated by CVODE (evolve_rough_sonine_cooling, rtol
// 1e-13) from the HCS cumulants with θ(0) = (1 + 1e-5) θ_HCS. The slowest eigenvalue of (19.144) is a complex pair at
// these states (θ and a cumulant mode relax together), so θ/θ_HCS − 1 = e^{−Γ t}(A cos ωt + B sin ωt) at late times,
// t = ν0 time = collisions/(((d + 2)/4) × collision frequency factor): with Γ, ω from the library, A and B fitted by
// least squares where the deviation lies between 1e-11 and 1e-8 (the faster modes gone, round-off 1e-16 of θ below
// 1e-4), the fit's largest residual is below 3e-3 of the envelope (measured 1.2e-3 in 2D: faster modes left at 1e-8);
// with Γ or ω moved by 3 % it is not (the test fails on a wrong rate).
TEST(RoughSplitSlopes, SlowestHomogeneousModeAgainstTheTrajectory) {
  std::vector<double> times;
  for (int i = 0; i <= 600; ++i) times.push_back(std::pow(10.0, -1 + 6.0 * i / 600));
  for (const State& s : {states()[0], states()[3]}) {
    const auto h = gkt::rough_homogeneous_cooling_state(s.d, s.alpha, s.beta, s.kappa, gkt::RoughHcsScheme::linear);
    const gkt::RoughSonineCoolingRates rates(s.d, s.alpha, s.beta, s.kappa, 1, gkt::RoughSonineAnsatz::isotropic);
    const auto u = unknowns_of(rates, h.a20, h.a02, h.a11);
    const auto slopes = gkt::rough_split_slopes(rates, h.temperature_ratio, u);
    ASSERT_GT(slopes.homogeneous_relaxation_frequency, 0) << s.d;
    const auto run = gkt::evolve_rough_sonine_cooling(rates, 1, (1 + 1e-5) * h.temperature_ratio, times, 1e-13, 1e-30,
                                                      {h.a20, h.a02, h.a11});
    const double per_collision = 1 / ((s.d + 2) / 4.0 * rates.collision_frequency_factor(u));
    std::vector<double> t, dev;
    for (const auto& sample : run.samples) {
      const double x = sample.rotational_temperature / sample.translational_temperature / h.temperature_ratio - 1;
      if (std::abs(x) > 1e-8 || std::abs(x) < 1e-11) continue;
      t.push_back(sample.collisions * per_collision);
      dev.push_back(x);
    }
    ASSERT_GE(t.size(), 20u) << s.d;
    const auto worst_residual = [&](double gamma, double omega) {
      Eigen::MatrixXd basis(static_cast<Eigen::Index>(t.size()), 2);
      Eigen::VectorXd y(static_cast<Eigen::Index>(t.size()));
      for (std::size_t i = 0; i < t.size(); ++i) {
        const auto r = static_cast<Eigen::Index>(i);
        const double envelope = std::exp(-gamma * (t[i] - t[0]));
        basis(r, 0) = envelope * std::cos(omega * t[i]);
        basis(r, 1) = envelope * std::sin(omega * t[i]);
        y(r) = dev[i];
      }
      const Eigen::Vector2d ab = basis.colPivHouseholderQr().solve(y);
      const double amplitude = ab.norm();
      double worst = 0;
      for (std::size_t i = 0; i < t.size(); ++i) {
        const auto r = static_cast<Eigen::Index>(i);
        worst = std::max(worst, std::abs(y(r) - basis.row(r).dot(ab)) / (amplitude * std::exp(-gamma * (t[i] - t[0]))));
      }
      return worst;
    };
    const double g = slopes.homogeneous_relaxation_rate, w = slopes.homogeneous_relaxation_frequency;
    EXPECT_LT(worst_residual(g, w), 3e-3) << s.d;
    EXPECT_GT(worst_residual(1.03 * g, w), 3e-3) << s.d;
    EXPECT_GT(worst_residual(g, 1.03 * w), 3e-3) << s.d;
  }
}
