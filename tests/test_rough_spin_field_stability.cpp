// Linear stability of the rough gas's HCS with the rotational temperature as a fourth field (docs/theory.md
// §19.15.1, (19.36)–(19.38)) against
//  (a) the three-field analysis (19.31): the determinant identity det M4 = −Γ* det M3 (so the critical wave
//      numbers agree to round-off at strong, medium and weak roughness), the elimination of δ at λ = ζ*/2
//      reproducing (19.31) with the library's η_b and ζ_U, and the hydrodynamic eigenvalues converging to
//      the three-field ones as the relaxation of θ is made fast (Γ* → ∞);
//  (b) the relaxation of θ in free cooling: at k* = 0 the extra eigenvalue is −Γ*, and Γ* is measured from the
//      late-time exponential approach of θ to the HCS in the CVODE integration of the Maxwellian two-temperature
//      equations (the integrator of `gkt evolve` with hcs = "maxwellian", built from the exact collision tables);
//  (c) β = −1: the fourth field decouples and the other three modes are the smooth gas's (14.2);
//  and ∂ζ*/∂δ of (19.37) against a finite difference of the Maxwellian energy rates (19.12) written out here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include "gkt/evolution/hcs_stability.hpp"
#include "gkt/evolution/rough_cooling_evolution.hpp"
#include "gkt/evolution/rough_hcs_stability.hpp"
#include "gkt/models/transport_model.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"
#include "gkt/transport/rough/rough_bulk_viscosity.hpp"
#include "gkt/transport/rough/rough_cooling_rates.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_shear_viscosity.hpp"
#include "gkt/transport/rough/rough_thermal_conductivity.hpp"

using gkt::Rational;

namespace {

struct State {
  int d;
  Rational alpha, beta, kappa;
};

/// Strong (β = 1, 0.5), medium (0, −0.5) and weak (−0.9) roughness, spheres and disks.
std::vector<State> states() {
  std::vector<State> out;
  for (int d : {3, 2}) {
    const Rational kappa = d == 3 ? Rational(2, 5) : Rational(1, 2);
    for (const auto& [a, b] : std::vector<std::pair<Rational, Rational>>{{Rational(9, 10), Rational(1)},
                                                                         {Rational(9, 10), Rational(1, 2)},
                                                                         {Rational(9, 10), Rational(-1, 2)},
                                                                         {Rational(7, 10), Rational(0)},
                                                                         {Rational(1, 2), Rational(0)},
                                                                         {Rational(9, 10), Rational(-9, 10)}})
      out.push_back({d, a, b, kappa});
  }
  return out;
}

/// The library's first-Sonine input at the Maxwellian HCS, with Γ* of (19.17).
gkt::RoughStabilityInput input(const State& s) {
  static std::map<std::string, gkt::RoughStabilityInput> cache;  // the first-Sonine tables cost ~0.1 s per state
  const std::string key =
      std::to_string(s.d) + s.alpha.to_string() + "|" + s.beta.to_string() + "|" + s.kappa.to_string();
  if (const auto it = cache.find(key); it != cache.end()) return it->second;
  const auto m = gkt::rough_homogeneous_cooling_state(s.d, s.alpha, s.beta, s.kappa, gkt::RoughHcsScheme::maxwellian);
  const auto q = gkt::rough_thermal_conductivity(s.d, s.alpha, s.beta, s.kappa);
  const auto b = gkt::rough_bulk_viscosity(s.d, s.alpha, s.beta, s.kappa);
  gkt::RoughStabilityInput in;
  in.dimension = s.d;
  in.temperature_ratio = m.temperature_ratio;
  in.cooling_rate = m.cooling_rate;
  in.shear_viscosity = gkt::rough_shear_viscosity(s.d, s.alpha, s.beta, s.kappa);
  in.bulk_viscosity = b.bulk_viscosity;
  in.thermal_conductivity = q.total;
  in.density_heat_coefficient = q.density_heat_total;
  in.cooling_rate_first_order = b.cooling_rate_first_order;
  in.relaxation_rate = b.relaxation_rate;
  return cache[key] = in;
}

template <std::size_t N>
Eigen::Matrix<std::complex<double>, N, N> to_eigen(const std::array<std::array<std::complex<double>, N>, N>& m) {
  Eigen::Matrix<std::complex<double>, N, N> e;
  for (std::size_t r = 0; r < N; ++r)
    for (std::size_t c = 0; c < N; ++c) e(r, c) = m[r][c];
  return e;
}

/// The distance from each of `a` to the nearest of `b`, maximised.
template <std::size_t N, std::size_t M>
double spectral_distance(const std::array<std::complex<double>, N>& a, const std::array<std::complex<double>, M>& b) {
  double worst = 0;
  for (const auto& x : a) {
    double best = INFINITY;
    for (const auto& y : b) best = std::min(best, std::abs(x - y));
    worst = std::max(worst, best);
  }
  return worst;
}

}  // namespace

// (a) At λ = 0 the split obeys −Γ*δ + (2/d)ik*w = 0, so the marginal modes of the four-field problem are those of
// (19.31) with the static η_b and ζ_U, and det (19.31) does not depend on η_b, ζ_U: det M4 = −Γ* det M3 exactly
// ((19.38)). Hence k∥c* is the three-field value at every roughness — measured: 1e-14 relative at all twelve states
// (Γ*/(ζ*/2) from 0.76 to 37); the tolerance 1e-10 is the bisection's 1e-13 with margin. The shear mode does not
// couple to the scalar δ: k⊥c* unchanged.
TEST(RoughSpinFieldStability, CriticalWavenumbersEqualTheThreeFieldOnes) {
  for (const State& s : states()) {
    const auto in = input(s);
    const auto three = gkt::rough_hcs_stability(in), four = gkt::rough_hcs_stability_with_spin(in);
    const std::string where = std::to_string(s.d) + " " + s.alpha.to_string() + " " + s.beta.to_string();
    EXPECT_GT(four.heat_wavenumber, 0) << where;
    EXPECT_NEAR(four.heat_wavenumber, three.heat_wavenumber, 1e-10 * three.heat_wavenumber) << where;
    EXPECT_EQ(four.shear_wavenumber, three.shear_wavenumber) << where;
    EXPECT_NEAR(four.critical_length, three.critical_length, 1e-10 * three.critical_length) << where;
    for (double k : {0.1, 0.3, 0.7, 1.3}) {
      const std::complex<double> d4 = to_eigen(gkt::rough_longitudinal_matrix_with_spin(in, k)).determinant();
      const std::complex<double> d3 = to_eigen(gkt::rough_longitudinal_matrix(in, k)).determinant();
      EXPECT_LT(std::abs(d4 + in.relaxation_rate * d3), 1e-12 * std::abs(in.relaxation_rate * d3)) << where << k;
    }
    // Below k∥c* a mode grows, above it none (the scan found no other crossing; checked at a few points too).
    for (double f : {0.5, 0.9})
      EXPECT_GT(gkt::rough_longitudinal_modes_with_spin(in, f * four.heat_wavenumber)[0].real(), 0);
    for (double f : {1.1, 2.0, 5.0})
      EXPECT_LT(gkt::rough_longitudinal_modes_with_spin(in, f * four.heat_wavenumber)[0].real(), 0);
  }
}

// (a) The Navier–Stokes closure is the fourth field eliminated at the growth rate of the normal solution, λ = ζ*/2
// ((19.18)): M_AA + M_Aδ M_δA/(ζ*/2 + Γ*) is (19.31) with the library's η_b* and ζ_U, entry by entry (1e-12). This
// ties the w-row coupling (1 − s)/2 (from θ) to η_b of rough_bulk_viscosity and the cooling slope to ζ_U.
TEST(RoughSpinFieldStability, EliminatingTheSplitGivesTheNavierStokesMatrix) {
  for (const State& s : states()) {
    const auto in = input(s);
    for (double k : {0.2, 0.9}) {
      const auto m4 = gkt::rough_longitudinal_matrix_with_spin(in, k);
      const auto m3 = gkt::rough_longitudinal_matrix(in, k);
      const std::complex<double> resolvent = 1.0 / (in.cooling_rate / 2 + in.relaxation_rate);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
          const std::complex<double> eliminated = m4[r][c] + m4[r][3] * resolvent * m4[3][c];
          EXPECT_LT(std::abs(eliminated - m3[r][c]), 1e-12 * (1 + std::abs(m3[r][c])))
              << s.d << " " << s.beta.to_string() << " " << r << c;
        }
    }
  }
}

// (a) Where θ relaxes fast the hydrodynamic eigenvalues tend to the three-field ones. The exact elimination replaces
// ζ*/2 by the mode's own λ in 1/(λ + Γ*), an error O(k*/Γ*²) on the eigenvalues: with Γ* scaled by F (η_b, ζ_U of
// the three-field input rescaled consistently, (19.18)–(19.19)) the largest distance of the three hydrodynamic modes
// from the three-field ones at k* = k∥c*/2 falls by 100 ± 30 % per decade of F (measured 96–106 between F = 10 and 100
// at the twelve states). The physical states (F = 1) are measured too: at (3, 0.9, 1), Γ*/(ζ*/2) = 37, the growing mode
// differs by < 1e-3 relative (measured 8e-5); at (3, 0.9, −0.5), Γ*/(ζ*/2) = 0.76, by 2 % (measured 2.1 %).
TEST(RoughSpinFieldStability, FastRelaxationGivesTheThreeFieldModes) {
  for (const State& s : states()) {
    const auto base = input(s);
    const double kc = gkt::rough_hcs_stability(base).heat_wavenumber, k = kc / 2;
    double previous = 0;
    for (double f : {10.0, 100.0}) {
      auto in = base;
      const double scale =
          (base.cooling_rate / 2 + base.relaxation_rate) / (base.cooling_rate / 2 + f * base.relaxation_rate);
      in.relaxation_rate = f * base.relaxation_rate;
      in.bulk_viscosity = base.bulk_viscosity * scale;
      in.cooling_rate_first_order = base.cooling_rate_first_order * scale;
      const auto four = gkt::rough_longitudinal_modes_with_spin(in, k);
      std::vector<std::complex<double>> kept;
      std::copy_if(four.begin(), four.end(), std::back_inserter(kept),
                   [&](const auto& x) { return std::abs(x.real() + in.relaxation_rate) > 0.5 * in.relaxation_rate; });
      ASSERT_EQ(kept.size(), 3U) << s.d << " " << s.beta.to_string() << " " << f;
      const std::array<std::complex<double>, 3> hydrodynamic{kept[0], kept[1], kept[2]};
      const double distance = spectral_distance(hydrodynamic, gkt::rough_longitudinal_modes(in, k));
      if (previous > 0) {
        EXPECT_GT(previous / distance, 70.0) << s.d << " " << s.beta.to_string();
        EXPECT_LT(previous / distance, 130.0) << s.d << " " << s.beta.to_string();
      }
      previous = distance;
    }
  }
  const auto growth = [](const State& s) {
    const auto in = input(s);
    const double k = gkt::rough_hcs_stability(in).heat_wavenumber / 2;
    return std::array<double, 2>{gkt::rough_longitudinal_modes(in, k)[0].real(),
                                 gkt::rough_longitudinal_modes_with_spin(in, k)[0].real()};
  };
  const auto strong = growth({3, Rational(9, 10), Rational(1), Rational(2, 5)});
  EXPECT_LT(std::abs(strong[1] / strong[0] - 1), 1e-3);
  const auto medium = growth({3, Rational(9, 10), Rational(-1, 2), Rational(2, 5)});
  EXPECT_NEAR(medium[1] / medium[0] - 1, -0.021, 0.002);
}

// (b) k* = 0: the eigenvalues are ζ*/2 (velocity), 0 (density), −ζ*/2 (temperature) and −Γ* (the split). Γ* is measured
// from the free cooling of a homogeneous gas: CVODE integrates the Maxwellian two-temperature equations (19.24) from
// θ(0) = 0.2 and 3 with the rates of the exact collision tables (RoughCoolingRates, the `gkt evolve` path with
// hcs = "maxwellian"); ln|θ − θ_HCS| against the collision count s is fitted by least squares where
// 1e-7 < |θ/θ_HCS − 1| < 1e-4 (linearisation error < 1e-4 relative, CVODE's rtol 1e-12 far below), and the slope
// per collision times (d + 2)/4 (collisions per unit ν0 t, theory.md (19.11)) is Γ* (measured agreement ≤ 1.2e-5, the
// two starting sides straddling Γ*: the fit's residual curvature; tolerance 1e-4).
TEST(RoughSpinFieldStability, ExtraEigenvalueAtZeroWavenumberIsTheRelaxationOfTheta) {
  std::vector<double> times;
  for (int i = 0; i <= 500; ++i) times.push_back(std::pow(10.0, -1 + 10.0 * i / 500));
  for (const State& s : states()) {
    const auto in = input(s);
    const auto modes = gkt::rough_longitudinal_modes_with_spin(in, 0);
    std::array<std::complex<double>, 4> expected{in.cooling_rate / 2, 0.0, -in.cooling_rate / 2, -in.relaxation_rate};
    EXPECT_LT(spectral_distance(modes, expected), 1e-14) << s.d << " " << s.beta.to_string();
    const gkt::RoughCoolingRates rates(s.d, s.alpha, s.beta, s.kappa);
    for (double theta0 : {0.2, 3.0}) {
      const auto run = gkt::evolve_rough_cooling(rates, false, 1, theta0, times, 1e-12, 1e-30);
      double sx = 0, sy = 0, sxx = 0, sxy = 0;
      int n = 0;
      for (const auto& sample : run.samples) {
        const double dev =
            std::abs(sample.rotational_temperature / sample.translational_temperature / in.temperature_ratio - 1);
        if (dev > 1e-4 || dev < 1e-7) continue;
        const double x = sample.collisions, y = std::log(dev);
        sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
      }
      ASSERT_GE(n, 8) << s.d << " " << s.beta.to_string() << " " << theta0;
      const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
      const double measured = -slope * (s.d + 2) / 4.0;
      EXPECT_NEAR(measured, in.relaxation_rate, 1e-4 * in.relaxation_rate)
          << s.d << " " << s.beta.to_string() << " " << theta0;
    }
  }
}

// (c) β = −1: θ = +∞, the fourth field δT_r/T_r is neither cooled nor worked on (eigenvalue 0) and the other three
// modes are the smooth gas's (14.2) with the smooth solver's first-Sonine η*, κ*, μ* at a2 = 0 and
// ζ* = ((d+2)/(4d))(1 − α²), to round-off; the model with rotational_temperature_closure = "field" gives the smooth
// critical values.
TEST(RoughSpinFieldStability, SmoothLimitDecouplesTheRotationalTemperature) {
  for (int d : {2, 3}) {
    gkt::NavierStokesSolver ns(d);
    const Rational kappa = d == 3 ? Rational(2, 5) : Rational(1, 2);
    for (const Rational& alpha : {Rational(9, 10), Rational(1, 2)}) {
      const auto v = ns.solve(alpha, 1, {1.0, 0.0, 0.0});
      const double a = alpha.to_double(), zeta = (d + 2) / (4.0 * d) * (1 - a * a);
      const auto smooth =
          gkt::hcs_stability(d, zeta, v.shear_viscosity, v.thermal_conductivity, v.density_heat_coefficient);
      const auto m =
          gkt::rough_homogeneous_cooling_state(d, alpha, Rational(-1), kappa, gkt::RoughHcsScheme::maxwellian);
      const auto q = gkt::rough_thermal_conductivity(d, alpha, Rational(-1), kappa);
      gkt::RoughStabilityInput in;
      in.dimension = d;
      in.temperature_ratio = m.temperature_ratio;
      ASSERT_TRUE(std::isinf(in.temperature_ratio));
      in.cooling_rate = m.cooling_rate;
      in.shear_viscosity = gkt::rough_shear_viscosity(d, alpha, Rational(-1), kappa);
      in.thermal_conductivity = q.translational;
      in.density_heat_coefficient = q.density_heat_translational;
      in.relaxation_rate = std::nan("");  // not used: the spin is decoupled
      for (double k : {0.0, 0.2, 0.6, 1.5}) {
        const auto m3 =
            gkt::longitudinal_matrix(d, zeta, v.shear_viscosity, v.thermal_conductivity, v.density_heat_coefficient, k);
        const auto smooth_modes = Eigen::ComplexEigenSolver<Eigen::Matrix3cd>(to_eigen(m3)).eigenvalues();
        std::array<std::complex<double>, 4> expected{smooth_modes(0), smooth_modes(1), smooth_modes(2), 0.0};
        EXPECT_LT(spectral_distance(gkt::rough_longitudinal_modes_with_spin(in, k), expected), 1e-12) << d << k;
        EXPECT_LT(spectral_distance(expected, gkt::rough_longitudinal_modes_with_spin(in, k)), 1e-12) << d << k;
      }
      gkt::ParameterPoint p;
      p.numbers = {{"dimension", Rational(d)}, {"alpha", alpha}, {"beta", Rational(-1)}, {"moment_of_inertia", kappa}};
      p.choices["rotational_temperature_closure"] = "field";
      const auto got = gkt::make_transport_model("rough")->evaluate(
          p, {"critical_wavenumber_shear", "critical_wavenumber_heat", "critical_length"}, gkt::OrderRequest{});
      EXPECT_NEAR(got[0].value.to_double(), smooth.shear_wavenumber, 1e-12 * smooth.shear_wavenumber) << d;
      EXPECT_NEAR(got[1].value.to_double(), smooth.heat_wavenumber, 1e-10 * smooth.heat_wavenumber) << d;
      EXPECT_NEAR(got[2].value.to_double(), smooth.critical_length, 1e-10 * smooth.critical_length) << d;
    }
  }
}

// ∂(ζ/ν0)/∂δ at fixed n and T ((19.37)), which the library takes from ζ_U, against a central difference of the
// Maxwellian rates (19.12) written out here: ζ = (dζ_t T_t + d_r ζ_r T_r)/((d + d_r)T), ζ_{t,r} ∝ √T_t, with
// r = θe^δ and T_t = T(d + d_r)/(d + d_r r) (step 1e-5; measured ≤ 6e-12; tolerance 1e-8).
TEST(RoughSpinFieldStability, CoolingSlopeAgainstTheMaxwellianRates) {
  for (const State& s : states()) {
    const auto in = input(s);
    const double d = s.d, dr = s.d == 3 ? 3 : 1, a = s.alpha.to_double(), b = s.beta.to_double(),
                 kappa = s.kappa.to_double();
    const double eta = (1 + b) * kappa / (2 * (1 + kappa)), theta = in.temperature_ratio;
    const auto zeta = [&](double delta) {  // ζ/ν0(T_t of the HCS) at T = T_HCS, T_t,HCS = 1
      const double r = theta * std::exp(delta);
      const double tt = (d + dr * theta) / (d + dr * r);
      const double zt = 2 / d * ((1 - a * a) / 2 + (d - 1) * (eta * (1 - eta) - eta * eta * r / kappa));
      const double zr = 2 * (d - 1) / dr * (eta / kappa) * (1 - eta / kappa - eta / r);
      return (d + 2) / 4 * std::sqrt(tt) * (d * zt + dr * r * zr) / (d + dr * r);
    };
    const double h = 1e-5, slope = (zeta(h) - zeta(-h)) / (2 * h);
    const double library = -gkt::rough_longitudinal_matrix_with_spin(in, 0.5)[1][3].real();
    EXPECT_NEAR(library, slope, 1e-8) << s.d << " " << s.beta.to_string();
    EXPECT_NEAR(zeta(0), in.cooling_rate, 1e-12) << s.d << " " << s.beta.to_string();
  }
}

// Disks at α = 0.1, β = 0: the first-Sonine κ* ≤ μ* (theory.md §19.15, "not to be trusted"), det M₄ never vanishes
// and a real mode grows at every k*: both closures report k∥c* = 0 (no crossing) and the same k⊥c*.
TEST(RoughSpinFieldStability, NoCrossingWhereConductivityIsBelowTheDensityHeatCoefficient) {
  const auto in = input({2, Rational(1, 10), Rational(0), Rational(1, 2)});
  ASSERT_LE(in.thermal_conductivity, in.density_heat_coefficient);
  const auto three = gkt::rough_hcs_stability(in), four = gkt::rough_hcs_stability_with_spin(in);
  EXPECT_EQ(three.heat_wavenumber, 0);
  EXPECT_EQ(four.heat_wavenumber, 0);
  EXPECT_EQ(four.shear_wavenumber, three.shear_wavenumber);
  for (double k : {0.5, 5.0, 50.0}) EXPECT_GT(gkt::rough_longitudinal_modes_with_spin(in, k)[0].real(), 0) << k;
}

TEST(RoughSpinFieldStability, RefusesWhatItCannotUse) {
  auto in = input({3, Rational(9, 10), Rational(1, 2), Rational(2, 5)});
  in.relaxation_rate = 0;
  EXPECT_THROW((void)gkt::rough_hcs_stability_with_spin(in), std::invalid_argument);
  in.relaxation_rate = std::nan("");
  EXPECT_THROW((void)gkt::rough_longitudinal_matrix_with_spin(in, 0.1), std::invalid_argument);
  gkt::ParameterPoint p;
  p.numbers = {{"dimension", Rational(3)}, {"alpha", Rational(9, 10)}, {"beta", Rational(1, 2)}};
  p.choices["rotational_temperature_closure"] = "field";
  p.choices["reference_state"] = "hcs";
  p.choices["hcs"] = "nonlinear";  // the slopes are the linear scheme's (theory.md §19.27)
  EXPECT_THROW((void)gkt::make_transport_model("rough")->evaluate(p, {"critical_wavenumber_heat"}, gkt::OrderRequest{}),
               std::invalid_argument);
  p.choices.erase("reference_state");
  p.choices.erase("hcs");
  p.choices["rotational_temperature_closure"] = "fourth";
  EXPECT_THROW((void)gkt::make_transport_model("rough")->evaluate(p, {"critical_wavenumber_heat"}, gkt::OrderRequest{}),
               std::invalid_argument);
}
