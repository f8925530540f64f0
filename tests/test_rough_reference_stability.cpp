// Linear stability of the rough HCS about the Sonine HCS with its cumulants (docs/theory.md §19.15, (19.33);
// `gkt stability` with reference_state = "hcs"): the values are (19.31)–(19.32) with the HCS θ, ζ* and the
// Navier–Stokes coefficients about it (§19.16); β = −1 is the smooth gas about its own HCS at the matching order
// (§14); the default (Maxwellian, first approximation) is unchanged; the error is (6.1) on the value plus the step
// from the next lower cumulant degree, as for the coefficients (19.46).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "gkt/evolution/rough_hcs_stability.hpp"
#include "gkt/models/transport_model.hpp"
#include "gkt/transport/common/sonine_solution.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_state.hpp"
#include "gkt/transport/rough/rough_sonine_transport.hpp"

namespace gkt {
namespace {

const std::vector<std::string> kStability{"critical_wavenumber_shear", "critical_wavenumber_heat", "critical_length"};

ParameterPoint rough_point(int d, const Rational& alpha, const Rational& beta) {
  ParameterPoint point;
  point.numbers = {{"dimension", Rational(d)}, {"alpha", alpha}, {"beta", beta}, {"moment_of_inertia", Rational(2, 5)}};
  return point;
}

double pick(const HcsStability& s, std::size_t c) {
  return c == 0 ? s.shear_wavenumber : c == 1 ? s.heat_wavenumber : s.critical_length;
}

/// (19.31)–(19.32) from a state θ, ζ* and the coefficients about it (total fluxes).
HcsStability by_hand(int d, double theta, double zeta, const RoughTransportValues& v) {
  RoughStabilityInput in;
  in.dimension = d;
  in.temperature_ratio = theta;
  in.cooling_rate = zeta;
  in.shear_viscosity = v.shear_viscosity;
  in.bulk_viscosity = v.bulk_viscosity;
  in.thermal_conductivity = v.thermal_conductivity;
  in.density_heat_coefficient = v.density_heat_coefficient;
  in.cooling_rate_first_order = v.cooling_rate_first_order;
  return rough_hcs_stability(in);
}

// β = −1: the spin decouples and the rough gas about its Sonine HCS (cumulants a_p0, p ≤ K) is the smooth gas about
// its own HCS. The smooth model at Sonine order N uses the nonlinear HCS with a_2 … a_{N+1} for ζ* and the
// coefficients (§14, standard scheme), so K = N + 1 with hcs = "nonlinear" must give its values.
TEST(RoughReferenceStability, SmoothLimitIsTheSmoothGasAboutItsHcs) {
  struct Case {
    int d;
    Rational alpha;
    int order;
  };
  auto smooth_model = make_transport_model("smooth-inelastic");
  auto rough_model = make_transport_model("rough");
  for (const Case& c : {Case{3, Rational(7, 10), 2}, Case{2, Rational(3, 5), 1}}) {
    {
      const int n = c.order;
      OrderRequest request;
      request.order = n;
      ParameterPoint smooth;
      smooth.numbers = {{"dimension", Rational(c.d)}, {"alpha", c.alpha}};
      smooth.choices = {{"hcs", "nonlinear"}};
      const auto s = smooth_model->evaluate(smooth, kStability, request);
      ParameterPoint rough = rough_point(c.d, c.alpha, Rational(-1));
      rough.choices = {{"hcs", "nonlinear"}, {"reference_state", "hcs"}};
      rough.numbers["hcs_order"] = Rational(n + 1);
      const auto r = rough_model->evaluate(rough, kStability, request);
      for (std::size_t k = 0; k < 3; ++k) {
        const double x = s[k].value.to_double(), y = r[k].value.to_double();
        EXPECT_NEAR(y, x, 1e-10 * std::abs(x)) << c.d << " N=" << n << " " << kStability[k];
      }
      // And it differs from the Maxwellian reference (a2 moves κ*, μ*, ζ*).
      rough.choices = {{"hcs", "nonlinear"}};
      rough.numbers.erase("hcs_order");
      const auto m = rough_model->evaluate(rough, kStability, request);
      EXPECT_GT(std::abs(m[1].value.to_double() - r[1].value.to_double()), 1e-4) << c.d << " N=" << n;
    }
  }
}

// The value is (19.31)–(19.32) with the oriented linear HCS of order 1 (3D, (0.9, 0.5)) and the coefficients about it
// at Sonine order 1; its error is (6.1) from orders 2, 3 plus the step to the Maxwellian reference at order 1.
// Closed forms: k⊥c* = √(ζ*/η*) with the HCS ζ*.
TEST(RoughReferenceStability, ValueAndErrorFromTheReferenceCoefficients) {
  const Rational alpha(9, 10), beta(1, 2), kappa(2, 5);
  auto model = make_transport_model("rough");
  ParameterPoint point = rough_point(3, alpha, beta);
  point.choices = {{"hcs", "linear"}, {"reference_state", "hcs"}};
  point.numbers["hcs_order"] = Rational(2);
  OrderRequest request;
  request.order = 1;
  const auto out = model->evaluate(point, kStability, request);
  const RoughSonineCoolingState hcs =
      rough_sonine_cooling_state(3, alpha, beta, kappa, 1, RoughSonineScheme::linear, RoughSonineAnsatz::oriented);
  ASSERT_TRUE(hcs.solved);
  const RoughSonineTransport t(3, alpha, beta, kappa, 3, 2, true);
  const RoughCoolingState m = rough_homogeneous_cooling_state(3, alpha, beta, kappa, RoughHcsScheme::maxwellian);
  std::vector<HcsStability> about;
  for (int n = 1; n <= 3; ++n)
    about.push_back(by_hand(3, hcs.temperature_ratio, hcs.cooling_rate, t.at_cooling_state(n, hcs)));
  const HcsStability maxwellian = by_hand(3, m.temperature_ratio, m.cooling_rate, t.at_maxwellian_state(1));
  for (std::size_t c = 0; c < 3; ++c) {
    const double v = pick(about[0], c);
    EXPECT_NEAR(out[c].value.to_double(), v, 1e-14 * v) << kStability[c];
    const TruncationEstimate e = estimate_truncation(Rational::from_double(v), Rational::from_double(pick(about[1], c)),
                                                     Rational::from_double(pick(about[2], c)));
    const double step = std::abs(v - pick(maxwellian, c));
    EXPECT_GT(step, 1e-5) << kStability[c];  // the cumulants and b00 move every value
    EXPECT_NEAR(out[c].error.to_double(), e.error.to_double() + step, 1e-14) << kStability[c];
    EXPECT_EQ(out[c].order, 1);
  }
  EXPECT_NEAR(about[0].shear_wavenumber, std::sqrt(hcs.cooling_rate / t.at_cooling_state(1, hcs).shear_viscosity),
              1e-14);
}

// Beyond order 1 the Maxwellian reference gives (19.31)–(19.32) from the order-N coefficients at the Maxwellian θ,
// ζ*; order 1 (the default) stays the first approximation of §19.15, unchanged.
TEST(RoughReferenceStability, MaxwellianReferenceAtHigherOrders) {
  const Rational alpha(7, 10), beta(0), kappa(2, 5);
  auto model = make_transport_model("rough");
  const ParameterPoint point = rough_point(3, alpha, beta);
  const RoughSonineTransport t(3, alpha, beta, kappa, 5);
  const RoughCoolingState m = rough_homogeneous_cooling_state(3, alpha, beta, kappa, RoughHcsScheme::maxwellian);
  OrderRequest request;
  request.order = 3;
  const auto out = model->evaluate(point, kStability, request);
  const HcsStability s = by_hand(3, m.temperature_ratio, m.cooling_rate, t.at_maxwellian_state(3));
  for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(out[c].value.to_double(), pick(s, c), 1e-13 * pick(s, c));
  request.order = 1;
  const auto first = model->evaluate(point, kStability, request);
  const HcsStability one = by_hand(3, m.temperature_ratio, m.cooling_rate, t.at_maxwellian_state(1));
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_NEAR(first[c].value.to_double(), pick(one, c), 1e-12 * pick(one, c));
    EXPECT_FALSE(first[c].error_estimated);  // the first approximation, as before
  }
}

// α = β = 1: the HCS is the equilibrium, ζ* = 0: never unstable, about either reference and at any order.
TEST(RoughReferenceStability, PidduckGasIsStable) {
  auto model = make_transport_model("rough");
  ParameterPoint point = rough_point(3, Rational(1), Rational(1));
  point.choices = {{"hcs", "nonlinear"}, {"reference_state", "hcs"}};
  OrderRequest request;
  request.order = 1;
  const auto out = model->evaluate(point, kStability, request);
  EXPECT_EQ(out[0].value.to_double(), 0);
  EXPECT_EQ(out[1].value.to_double(), 0);
  EXPECT_TRUE(out[2].infinite);
}

TEST(RoughReferenceStability, RefusesOrdersBeyondTheReferenceTables) {
  auto model = make_transport_model("rough");
  ParameterPoint point = rough_point(3, Rational(9, 10), Rational(1, 2));
  point.choices = {{"reference_state", "hcs"}};
  OrderRequest request;
  request.order = 5;
  EXPECT_THROW((void)model->evaluate(point, {"critical_length"}, request), std::invalid_argument);
  point.choices = {{"hcs", "maxwellian"}, {"reference_state", "hcs"}};
  request.order = 1;
  EXPECT_THROW((void)model->evaluate(point, {"critical_length"}, request), std::invalid_argument);
}

}  // namespace
}  // namespace gkt
