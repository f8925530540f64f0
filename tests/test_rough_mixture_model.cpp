// The rough binary mixture through the "rough" model (species = 2; docs/theory.md §19.17, §19.26): the limits
// the binary must reproduce through the same façade the CLI uses — identical species give the one-gas rough
// model's Maxwellian θ and ζ* to 1e-12, β = −1 the smooth `mixture` model's Maxwellian temperature ratios and
// cooling rate, x_2 → 0 tends to the tracer state (x_2 = 0) linearly in x_2 — and the refusals.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "gkt/models/transport_model.hpp"

using gkt::ParameterPoint;
using gkt::Rational;

namespace {

const std::vector<std::string> kColumns{"temperature_ratio_1", "temperature_ratio_2", "rotational_temperature_ratio_1",
                                        "rotational_temperature_ratio_2", "cooling_rate"};

struct Grain {
  Rational mass, diameter, fraction, kappa;
};

/// The keys the scene loader makes of two [[species]] tables (model "rough").
ParameterPoint binary(int d, const Grain& a, const Grain& b, const Rational& alpha, const Rational& beta) {
  ParameterPoint p;
  p.numbers["dimension"] = Rational(d);
  p.numbers["species"] = Rational(2);
  p.numbers["alpha"] = alpha;
  p.numbers["beta"] = beta;
  p.choices["hcs"] = "maxwellian";
  const std::array<Grain, 2> g{a, b};
  for (std::size_t i = 0; i < 2; ++i) {
    const std::string k = std::to_string(i + 1);
    p.numbers["mass_" + k] = g[i].mass;
    p.numbers["diameter_" + k] = g[i].diameter;
    p.numbers["fraction_" + k] = g[i].fraction;
    p.numbers["moment_of_inertia_" + k] = g[i].kappa;
  }
  return p;
}

std::vector<double> values(gkt::TransportModel& model, const ParameterPoint& p, const std::vector<std::string>& c) {
  std::vector<double> out;
  for (const auto& v : model.evaluate(p, c, {})) out.push_back(v.defined ? v.value.to_double() : std::nan(""));
  return out;
}

const Grain kLight{Rational(1), Rational(1), Rational(3, 10), Rational(2, 5)};
const Grain kHeavy{Rational(4), Rational(2), Rational(7, 10), Rational(1, 2)};

}  // namespace

// Two identical species (x = 1/4, 3/4; mass 3, diameter 3/2): γ_i = 1 and θ_i, ζ* of the one-gas rough model
// with hcs = "maxwellian" (theory.md §19.5), to 1e-12, d = 2, 3, three (α, β, κ).
TEST(RoughMixtureModel, IdenticalSpeciesAreTheOneGasModel) {
  auto rough = gkt::make_transport_model("rough");
  for (int d : {2, 3})
    for (const auto& [alpha, beta, kappa] : {std::array{Rational(9, 10), Rational(1, 2), Rational(2, 5)},
                                             {Rational(1, 2), Rational(-4, 5), Rational(1, 2)},
                                             {Rational(7, 10), Rational(1), Rational(1, 10)}}) {
      const Grain a{Rational(3), Rational(3, 2), Rational(1, 4), kappa},
          b{Rational(3), Rational(3, 2), Rational(3, 4), kappa};
      const auto mix = values(*rough, binary(d, a, b, alpha, beta), kColumns);
      ParameterPoint one;
      one.numbers = {{"dimension", Rational(d)}, {"alpha", alpha}, {"beta", beta}, {"moment_of_inertia", kappa}};
      one.choices["hcs"] = "maxwellian";
      const auto gas = values(*rough, one, {"rotational_temperature_ratio", "cooling_rate"});
      EXPECT_NEAR(mix[0], 1.0, 1e-12) << "d=" << d;
      EXPECT_NEAR(mix[1], 1.0, 1e-12) << "d=" << d;
      EXPECT_NEAR(mix[2], gas[0], 1e-12 * gas[0]) << "d=" << d;
      EXPECT_NEAR(mix[3], gas[0], 1e-12 * gas[0]) << "d=" << d;
      EXPECT_NEAR(mix[4], gas[1], 1e-12 * gas[1]) << "d=" << d;
    }
}

// β = −1 on every pair: the spins decouple (θ_i nan, as the one gas's θ at β = −1) and T_t,i/T, ζ* are the
// smooth `mixture` model's Maxwellian HCS (theory.md §16), with pair-dependent α.
TEST(RoughMixtureModel, SmoothLimitIsTheSmoothMixtureModel) {
  auto rough = gkt::make_transport_model("rough");
  auto smooth = gkt::make_transport_model("mixture");
  for (int d : {2, 3}) {
    ParameterPoint p = binary(d, kLight, kHeavy, Rational(3, 4), Rational(-1));
    p.numbers["alpha_1_2"] = Rational(9, 10);
    p.numbers["alpha_2_2"] = Rational(1, 2);
    const auto r = values(*rough, p, kColumns);
    ParameterPoint q;
    for (const char* key : {"dimension", "species", "alpha", "alpha_1_2", "alpha_2_2", "mass_1", "mass_2", "diameter_1",
                            "diameter_2", "fraction_1", "fraction_2"})
      q.numbers[key] = p.numbers.at(key);
    q.choices["hcs"] = "maxwellian";
    const auto s = values(*smooth, q, {"temperature_ratio_1", "temperature_ratio_2", "cooling_rate"});
    EXPECT_NEAR(r[0], s[0], 1e-10) << "d=" << d;
    EXPECT_NEAR(r[1], s[1], 1e-10) << "d=" << d;
    EXPECT_NEAR(r[4], s[2], 1e-10 * s[2]) << "d=" << d;
    EXPECT_TRUE(std::isnan(r[2]) && std::isnan(r[3])) << "d=" << d;
    EXPECT_GT(std::abs(r[0] - 1), 0.01);  // a genuine non-equipartition, not the trivial γ = 1
  }
}

// Only species 1's pairs smooth (β_11 = β_12 = −1, β_22 = 1/2): its spin decouples (θ_1 nan) while species 2
// keeps a cooling state; the four rates at that state agree (checked in the library test), here θ_2 is finite.
TEST(RoughMixtureModel, OneDecoupledSpin) {
  auto rough = gkt::make_transport_model("rough");
  ParameterPoint p = binary(3, kLight, kHeavy, Rational(9, 10), Rational(-1));
  p.numbers["beta_2_2"] = Rational(1, 2);
  const auto r = values(*rough, p, kColumns);
  EXPECT_TRUE(std::isnan(r[2]));
  EXPECT_TRUE(std::isfinite(r[3]) && r[3] > 0);
  EXPECT_NEAR(0.3 * r[0] + 0.7 * r[1], 1.0, 1e-12);
}

// Tracer limit: x_2 = 0 is a state (species 2 meets only species 1), and x_2 → 0 approaches it linearly:
// |v(x_2) − v(0)| / x_2 settles (the ratios at x_2 = 1e-4 and 1e-6 agree to 1 %), for every column, d = 2, 3; at
// x_2 = 0 species 1 is the one-gas rough model (theory.md (19.132)).
TEST(RoughMixtureModel, TracerLimitIsContinuous) {
  auto rough = gkt::make_transport_model("rough");
  for (int d : {2, 3}) {
    const auto at = [&](const Rational& x2) {
      Grain a = kLight, b = kHeavy;
      a.fraction = Rational(1) - x2;
      b.fraction = x2;
      return values(*rough, binary(d, a, b, Rational(4, 5), Rational(1, 2)), kColumns);
    };
    const auto tracer = at(Rational(0));
    const auto small = at(Rational(1, 10000)), smaller = at(Rational(1, 1000000));
    for (std::size_t k = 0; k < kColumns.size(); ++k) {
      ASSERT_TRUE(std::isfinite(tracer[k]) && tracer[k] > 0) << kColumns[k];
      const double slope_small = (small[k] - tracer[k]) / 1e-4, slope_smaller = (smaller[k] - tracer[k]) / 1e-6;
      EXPECT_NEAR(slope_smaller, slope_small, 0.01 * std::abs(slope_small) + 1e-5) << kColumns[k] << " d=" << d;
    }
    // x_2 = 0: species 1 is the one rough gas (κ = 2/5; ν0 of m̄ = m_1, σ̄ = σ_1): γ_1 = 1, θ_1 and ζ* its own.
    ParameterPoint one;
    one.numbers = {{"dimension", Rational(d)},
                   {"alpha", Rational(4, 5)},
                   {"beta", Rational(1, 2)},
                   {"moment_of_inertia", kLight.kappa}};
    one.choices["hcs"] = "maxwellian";
    const auto gas = values(*rough, one, {"rotational_temperature_ratio", "cooling_rate"});
    EXPECT_NEAR(tracer[0], 1.0, 1e-12);
    EXPECT_NEAR(tracer[2], gas[0], 1e-12 * gas[0]);
    EXPECT_NEAR(tracer[4], gas[1], 1e-12 * gas[1]);
  }
}

// The model refuses what the CLI refuses (the schema's ranges are checked by the guard, the sum here).
TEST(RoughMixtureModel, RefusesBadInput) {
  auto rough = gkt::make_transport_model("rough");
  const auto refuses = [&](ParameterPoint p, const std::vector<std::string>& columns, const std::string& key,
                           gkt::OrderRequest order = {}) {
    try {
      (void)rough->evaluate(p, columns, order);
      ADD_FAILURE() << key << ": accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(key + ":", 0), 0U) << e.what();
    }
  };
  ParameterPoint p = binary(3, kLight, kHeavy, Rational(9, 10), Rational(1, 2));
  p.numbers["fraction_2"] = Rational(3, 5);
  refuses(p, kColumns, "fraction");
  p = binary(3, kLight, kHeavy, Rational(9, 10), Rational(1, 2));
  p.numbers["mass_1"] = Rational(-1);
  refuses(p, kColumns, "mass_1");
  p.numbers["mass_1"] = Rational(1);
  p.numbers["beta_1_2"] = Rational(3, 2);
  refuses(p, kColumns, "beta_1_2");
  p.numbers["beta_1_2"] = Rational(1, 2);
  p.numbers["moment_of_inertia_2"] = Rational(0);
  refuses(p, kColumns, "moment_of_inertia_2");
  p.numbers["moment_of_inertia_2"] = Rational(1, 2);
  refuses(p, {"shear_viscosity"}, "coefficients");
  gkt::OrderRequest two;
  two.order = 2;
  refuses(p, kColumns, "order", two);
  p.choices["hcs"] = "nonlinear";
  refuses(p, kColumns, "hcs");
  p.choices["hcs"] = "maxwellian";  // the cumulants need the first-Sonine HCS (theory.md §19.30)
  refuses(p, {"a20_1"}, "coefficients");
  p.choices["hcs"] = "linear";
  refuses(p, {"a20_1"}, "order", two);
  // α = 0.5, β = −0.5: the linear scheme has no realizable root (as the one gas there, §19.6).
  p.numbers["alpha"] = Rational(1, 2);
  p.numbers["beta"] = Rational(-1, 2);
  refuses(p, {"a20_1"}, "hcs");
  // A tracer heated by a host spin that does not cool (β_11 = −1, x_2 = 0, β_12 > −1): no HCS.
  p = binary(3, kLight, kHeavy, Rational(9, 10), Rational(1, 2));
  p.numbers["beta_1_1"] = Rational(-1);
  p.numbers["fraction_1"] = Rational(1);
  p.numbers["fraction_2"] = Rational(0);
  refuses(p, kColumns, "beta");
  ParameterPoint one;
  one.numbers["mass_1"] = Rational(2);
  refuses(one, {"cooling_rate"}, "mass_1");
}

// hcs = "linear" (theory.md §19.30) through the model: two identical species (x = 1/4, 3/4) give the one-gas model's
// linear first-Sonine θ, ζ*, a20, a02, a11 (hcs = "linear", order 1) to 1e-10, d = 2, 3; "linear-or-maxwellian"
// falls back to the Maxwellian columns with nan cumulants where the linear scheme has no root, and equals "linear"
// where it has one.
TEST(RoughMixtureModel, FirstSonineHcs) {
  auto rough = gkt::make_transport_model("rough");
  const std::vector<std::string> cumulants{"a20_1", "a02_1", "a11_1", "a20_2", "a02_2", "a11_2"};
  std::vector<std::string> all = kColumns;
  all.insert(all.end(), cumulants.begin(), cumulants.end());
  for (int d : {2, 3}) {
    const Rational alpha(9, 10), beta(1, 2), kappa(2, 5);
    const Grain a{Rational(3), Rational(3, 2), Rational(1, 4), kappa},
        b{Rational(3), Rational(3, 2), Rational(3, 4), kappa};
    ParameterPoint p = binary(d, a, b, alpha, beta);
    p.choices["hcs"] = "linear";
    const auto mix = values(*rough, p, all);
    ParameterPoint one;
    one.numbers = {{"dimension", Rational(d)}, {"alpha", alpha}, {"beta", beta}, {"moment_of_inertia", kappa}};
    one.choices["hcs"] = "linear";
    const auto gas = values(*rough, one, {"rotational_temperature_ratio", "cooling_rate", "a20", "a02", "a11"});
    EXPECT_NEAR(mix[0], 1.0, 1e-10);
    EXPECT_NEAR(mix[2], gas[0], 1e-10) << "d=" << d;
    EXPECT_NEAR(mix[3], gas[0], 1e-10) << "d=" << d;
    EXPECT_NEAR(mix[4], gas[1], 1e-10) << "d=" << d;
    for (std::size_t i = 0; i < 2; ++i)
      for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(mix[5 + 3 * i + k], gas[2 + k], 1e-10) << "d=" << d;
  }
  ParameterPoint p = binary(3, kLight, kHeavy, Rational(1, 2), Rational(-1, 2));
  p.choices["hcs"] = "linear-or-maxwellian";
  const auto fallback = values(*rough, p, all);
  p.choices["hcs"] = "maxwellian";
  const auto maxwellian = values(*rough, p, kColumns);
  for (std::size_t k = 0; k < kColumns.size(); ++k) EXPECT_EQ(fallback[k], maxwellian[k]) << kColumns[k];
  for (std::size_t k = kColumns.size(); k < all.size(); ++k) EXPECT_TRUE(std::isnan(fallback[k])) << all[k];
  p = binary(3, kLight, kHeavy, Rational(9, 10), Rational(1, 2));
  p.choices["hcs"] = "linear-or-maxwellian";
  const auto either = values(*rough, p, all);
  p.choices["hcs"] = "linear";
  const auto linear = values(*rough, p, all);
  for (std::size_t k = 0; k < all.size(); ++k) EXPECT_EQ(either[k], linear[k]) << all[k];
}
