// The façade (include/gkt/models/): every model validates its calls against its declared schema
// the way the scene loader does — unknown names and out-of-range values are refused with
// std::invalid_argument naming the key, never answered with a default — and every capability
// (table, formula, evolve, stability) is reached through the model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

#include "gkt/evolution/aggregation_evolution.hpp"
#include "gkt/evolution/homogeneous_cooling_evolution.hpp"
#include "gkt/models/tolerance_row.hpp"
#include "gkt/models/transport_model.hpp"
#include "gkt/transport/closed_forms/first_sonine_formulas.hpp"
#include "gkt/transport/common/pair_correlation.hpp"
#include "gkt/transport/mixture/mixture_cooling_state.hpp"
#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"
#include "gkt/transport/monodisperse/tail_galerkin.hpp"

using gkt::Capability;
using gkt::ParameterPoint;
using gkt::Rational;

namespace {

/// Returns the message of the std::invalid_argument `call` throws ("" and a test failure if none).
template <class Call>
std::string refusal(Call&& call) {
  try {
    call();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "no std::invalid_argument";
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// A dilute binary mixture point (the keys the scene loader makes of two [[species]] tables).
ParameterPoint binary() {
  ParameterPoint p;
  p.numbers = {{"species", Rational(2)},       {"mass_1", Rational(1)},     {"mass_2", Rational(2)},
               {"diameter_1", Rational(1)},    {"diameter_2", Rational(1)}, {"fraction_1", Rational(1, 2)},
               {"fraction_2", Rational(1, 2)}, {"alpha", Rational(9, 10)}};
  return p;
}

}  // namespace

// Issue 17: "alpah" used to be ignored and the α = 1 answer returned.
TEST(ModelSchema, MisspelledParameterIsRefusedWithTheValidNames) {
  auto model = gkt::make_transport_model("smooth-inelastic");
  ParameterPoint point;
  point.numbers["alpah"] = Rational(1, 2);
  const std::string message = refusal([&] { (void)model->evaluate(point, {"a2"}, {}); });
  EXPECT_TRUE(contains(message, "alpah: unknown parameter for model \"smooth-inelastic\"")) << message;
  for (const auto& spec : model->parameters()) EXPECT_TRUE(contains(message, spec.name)) << spec.name;
  EXPECT_EQ(message.find('\n'), std::string::npos);
  // A misspelled choice too (it used to fall back to the standard scheme).
  ParameterPoint choice;
  choice.choices["schem"] = "modified";
  EXPECT_TRUE(contains(refusal([&] { (void)model->evaluate(choice, {"shear_viscosity"}, {}); }),
                       "schem: unknown parameter for model \"smooth-inelastic\""));
  for (const auto& name : gkt::transport_model_names()) {
    auto m = gkt::make_transport_model(name);
    ParameterPoint typo = name == "mixture" ? binary() : ParameterPoint{};
    typo.numbers["dimensoin"] = Rational(2);
    EXPECT_TRUE(contains(refusal([&] { (void)m->evaluate(typo, {m->coefficient_names().front()}, {}); }),
                         "dimensoin: unknown parameter for model \"" + name + "\""))
        << name;
  }
}

// Out-of-range values get the scene loader's message: ParameterSpec::check of the declared spec.
TEST(ModelSchema, OutOfRangeValuesAreRefusedAsTheSceneLoaderRefusesThem) {
  for (const auto& name : gkt::transport_model_names()) {
    auto model = gkt::make_transport_model(name);
    for (const auto& spec : model->parameters()) {
      if (spec.kind == gkt::ParameterSpec::Kind::choice) {
        ParameterPoint p = name == "mixture" ? binary() : ParameterPoint{};
        p.choices[spec.name] = "no-such-choice";
        EXPECT_EQ(refusal([&] { (void)model->evaluate(p, {model->coefficient_names().front()}, {}); }),
                  spec.name + ": must be " + spec.allowed() + ", got \"no-such-choice\"");
        continue;
      }
      ParameterPoint p = name == "mixture" ? binary() : ParameterPoint{};
      const Rational bad = spec.max + Rational(1);
      p.numbers[spec.name] = bad;
      EXPECT_EQ(refusal([&] { (void)model->evaluate(p, {model->coefficient_names().front()}, {}); }),
                spec.name + ": must be " + spec.allowed() + ", got " + bad.to_decimal_string())
          << name;
    }
  }
  // The mixture's masses used to reach the solver unchecked.
  auto mixture = gkt::make_transport_model("mixture");
  ParameterPoint p = binary();
  p.numbers["mass_2"] = Rational(-2);
  EXPECT_TRUE(contains(refusal([&] { (void)mixture->evaluate(p, {"cooling_rate"}, {}); }),
                       "mass_2: must be a number in (0, 1000000000], got -2"));
}

// The order request is part of the schema: order in [1, max_order()], tolerance in (0, 1].
TEST(ModelSchema, OrderOutsideTheModelsRangeIsRefused) {
  for (const auto& name : gkt::transport_model_names()) {
    auto model = gkt::make_transport_model(name);
    const ParameterPoint p = name == "mixture" ? binary() : ParameterPoint{};
    const std::string coefficient = model->coefficient_names().front();
    const int too_high = model->max_order() + 1;
    EXPECT_EQ(refusal([&] {
                (void)model->evaluate(p, {coefficient}, {too_high, {}});
              }),
              (model->max_order() == 1 ? std::string("order: must be exactly 1, got ")
               : model->max_order() == 2
                   ? std::string("order: must be 1 or 2, got ")  // ParameterSpec::allowed()
                   : "order: must be an integer in [1, " + std::to_string(model->max_order()) + "], got ") +
                  std::to_string(too_high))
        << name;
    EXPECT_TRUE(contains(refusal([&] { (void)model->evaluate(p, {coefficient}, {0, {}}); }), "order: "));
    EXPECT_EQ(refusal([&] {
                (void)model->evaluate(p, {coefficient}, {1, Rational(2)});
              }),
              "tolerance: must be a number in (0, 1], got 2");
  }
}

// Issue 22: the 2D HCS a3 at α = 0.8 converges slowly (estimated error 3.7e-8 at order 12, the former
// cap); with the order cap raised `tolerance = 1e-8` is met, at an order above 12.
TEST(ModelSchema, SmoothInelasticReachesTolerance1e8PastOrder12) {
  auto model = gkt::make_transport_model("smooth-inelastic");
  ParameterPoint p;
  p.numbers = {{"dimension", Rational(2)}, {"alpha", Rational(4, 5)}};
  const Rational tolerance = Rational::parse("1e-8");
  const auto v = model->evaluate(p, {"a3"}, {1, tolerance}).front();
  EXPECT_TRUE(v.converged);
  EXPECT_GT(v.order, 12);
  EXPECT_LE(v.order, model->max_order());
  EXPECT_LT(v.error, tolerance);
  EXPECT_LT(v.value, Rational(0));
}

// theory.md (6.2): past the turn of the asymptotic Sonine series (2D, α = 0.8: order ≈ A²/4 = 19.8)
// a tolerance scan may stop, from order 18 on, on the Euler sum of an alternating plateau. The cheap
// case of the mechanism is the HCS: a2 alternates by ±(1.4–1.6)e-11 from order 20 on, so
// `tolerance = 1e-11` is met only by the sum (the (6.1) estimates stay ≥ 1.05e-11, r ≈ −1).
// Reference: the tail scheme, tail_galerkin_sequence(2, 0.8, 29, power_law) past its resolution cap in a
// scratch build, extrapolated geometrically from N = 27–29: −0.0262441287448, uncertain by ≈ 5e-12
// (N = 26–28 give −0.0262441287404).
TEST(ModelFacade, SmoothInelasticPlateauSumMeetsATightToleranceIn2DAtAlpha08) {
  auto model = gkt::make_transport_model("smooth-inelastic");
  ParameterPoint p;
  p.numbers = {{"dimension", Rational(2)}, {"alpha", Rational(4, 5)}};
  const Rational tolerance = Rational::parse("1e-11");
  const auto v = model->evaluate(p, {"a2"}, {1, tolerance}).front();
  EXPECT_TRUE(v.converged);
  EXPECT_GE(v.order, 18);
  EXPECT_LT(v.error, tolerance);
  EXPECT_LT(std::fabs(v.value.to_double() + 0.0262441287448), v.error.to_double() + 5e-12);
}

// Each model declares which subcommands it answers; the stability values are offered where declared.
TEST(ModelSchema, DeclaredCapabilities) {
  for (const auto& name : gkt::transport_model_names()) {
    auto model = gkt::make_transport_model(name);
    EXPECT_TRUE(model->supports(Capability::table)) << name;
    const auto names = model->coefficient_names();
    for (const auto& c : gkt::stability_coefficient_names()) {
      EXPECT_EQ(std::find(names.begin(), names.end(), c) != names.end(), model->supports(Capability::stability))
          << name << " " << c;
    }
    EXPECT_EQ(model->evolution_parameters().empty(), !model->supports(Capability::evolve)) << name;
    if (!model->supports(Capability::formula)) {
      EXPECT_TRUE(contains(refusal([&] { (void)model->closed_form({}, names.front(), 1); }), "has no closed forms"));
    }
    if (!model->supports(Capability::evolve)) {
      EXPECT_TRUE(contains(refusal([&] { (void)model->evolve({}); }), "has no cooling trajectory"));
    }
  }
  EXPECT_TRUE(gkt::make_transport_model("smooth-inelastic")->supports(Capability::formula));
  EXPECT_TRUE(gkt::make_transport_model("mixture")->supports(Capability::evolve));
  EXPECT_FALSE(gkt::make_transport_model("hard-spheres")->supports(Capability::evolve));
}

// `gkt formula` asks the model: the first-Sonine closed form of the one-component gas, validated.
TEST(ModelFacade, ClosedFormsThroughTheModel) {
  auto model = gkt::make_transport_model("smooth-inelastic");
  ParameterPoint p;
  p.numbers["dimension"] = Rational(2);
  p.choices["scheme"] = "modified";
  const gkt::ClosedForm f = model->closed_form(p, "thermal_conductivity", 1);
  ASSERT_TRUE(std::holds_alternative<gkt::RationalFunction>(f.form));
  EXPECT_TRUE(std::get<gkt::RationalFunction>(f.form).equals(
      gkt::first_sonine_closed_form(2, "thermal_conductivity", gkt::SonineScheme::modified)));
  EXPECT_EQ(f.dimension, 2);
  p.choices.erase("scheme");
  p.numbers["packing_fraction"] = Rational(1, 5);
  EXPECT_TRUE(std::holds_alternative<gkt::EnskogClosedForm>(model->closed_form(p, "shear_viscosity", 1).form));
  EXPECT_TRUE(contains(refusal([&] { (void)model->closed_form(p, "shear_viscosity", 2); }),
                       "order: \"smooth-inelastic\" has closed forms at order 1 only"));
  p.numbers["alpah"] = Rational(1, 2);
  EXPECT_TRUE(contains(refusal([&] { (void)model->closed_form(p, "shear_viscosity", 1); }), "alpah: unknown"));
  // Hard spheres: the exact Sonine approximant is a constant (Chapman & Cowling §10.51: 205/202).
  const auto hs = gkt::make_transport_model("hard-spheres")->closed_form({}, "shear_viscosity", 2);
  EXPECT_EQ(std::get<gkt::RationalFunction>(hs.form).numerator.coefficient(0), Rational(205, 202));
}

// `gkt evolve` asks the model: the trajectory equals the integrator called directly, and the
// evolution keys are validated (unknown names, α, a2 in the dimension's positivity range).
TEST(ModelFacade, CoolingTrajectoryThroughTheModel) {
  auto model = gkt::make_transport_model("smooth-inelastic");
  ASSERT_TRUE(model->supports(Capability::evolve));
  gkt::TrajectoryRequest request;
  request.parameters.numbers = {{"alpha", Rational(4, 5)}, {"order", Rational(2)}, {"a2", Rational(1, 10)}};
  request.times = gkt::log_spaced_times(10, 5);
  const gkt::Trajectory t = model->evolve(request);
  ASSERT_EQ(t.columns, (std::vector<std::string>{"time", "collisions", "temperature", "a2", "a3", "cooling_rate"}));
  gkt::HomogeneousCoolingState hcs(3);
  const auto direct =
      gkt::evolve_homogeneous_cooling(hcs.hierarchy(Rational(4, 5), 3), 1.0, {0.1}, request.times, 1e-8, 1e-12);
  ASSERT_EQ(t.rows.size(), direct.samples.size());
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    EXPECT_EQ(t.rows[i][2], direct.samples[i].temperature);
    EXPECT_EQ(t.rows[i][3], direct.samples[i].a[2]);
    EXPECT_EQ(t.rows[i][5], direct.samples[i].cooling_rate);
  }
  gkt::TrajectoryRequest bad = request;
  bad.parameters.numbers["alpah"] = Rational(1, 2);
  EXPECT_TRUE(contains(refusal([&] { (void)model->evolve(bad); }), "alpah: unknown parameter"));
  bad = request;
  bad.parameters.numbers.erase("alpha");
  EXPECT_EQ(refusal([&] { (void)model->evolve(bad); }), "alpha: required, a number in (0, 1]");
  bad = request;
  bad.parameters.numbers["a2"] = Rational(9, 10);  // inside 2D's [-1, 1], outside 3D's
  EXPECT_EQ(refusal([&] { (void)model->evolve(bad); }), "a2: must be a number in [-0.5333333333333333, 0.8], got 0.9");
  bad = request;
  bad.coefficients = {"viscosity"};
  EXPECT_TRUE(contains(refusal([&] { (void)model->evolve(bad); }), "coefficients: 'viscosity' is not offered"));
  bad = request;
  bad.times = {2, 1};
  EXPECT_TRUE(contains(refusal([&] { (void)model->evolve(bad); }), "times: must be a non-empty list"));
}

// `gkt evolve` asks the aggregation model too: it sets its own output times from t_end and points,
// and its trajectory (and long-format distribution) equals the population balance called directly.
TEST(ModelFacade, AggregationTrajectoryThroughTheModel) {
  auto model = gkt::make_transport_model("aggregation");
  ASSERT_TRUE(model->supports(Capability::evolve));
  gkt::TrajectoryRequest request;
  request.parameters.numbers = {
      {"alpha", Rational(9, 10)}, {"sizes", Rational(20)}, {"t_end", Rational(2)}, {"points", Rational(4)}};
  request.parameters.choices = {{"distribution", "true"}};
  const gkt::Trajectory t = model->evolve(request);
  gkt::AggregationGas gas;
  gas.alpha = 0.9;
  gas.critical_energy = 1;  // the model's default
  const auto direct = gkt::evolve_aggregation(gas, 20, gkt::log_spaced_times(2, 4), 1e-8, 1e-14, true);
  ASSERT_EQ(t.columns.size(), 8U);
  EXPECT_EQ(t.columns.back(), "size_density");
  ASSERT_EQ(t.rows.size(), 4U * 20U);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(t.rows[i * 20][0], direct.samples[i].time);
    EXPECT_EQ(t.rows[i * 20][1], direct.samples[i].temperature);
    EXPECT_EQ(t.rows[i * 20 + 19][7], direct.samples[i].distribution[19]);
  }
  EXPECT_EQ(t.linear_solver, direct.linear_solver);
  request.times = {1.0};
  EXPECT_TRUE(contains(refusal([&] { (void)model->evolve(request); }), "times: model \"aggregation\" sets its"));
  request.times.clear();
  request.parameters.numbers.erase("t_end");
  EXPECT_TRUE(contains(refusal([&] { (void)model->evolve(request); }), "t_end: required"));
  request.parameters.numbers["t_end"] = Rational(2);
  request.parameters.choices["distribution"] = "yes";
  EXPECT_TRUE(contains(refusal([&] { (void)model->evolve(request); }), "distribution: must be one of"));
}

// `tolerance` drives a mixture's HCS cumulant order (issue 20 item 8; theory.md §16.3): without
// `hcs_order` the value is mixture_cooling_state at the smallest K whose value differs from K + 1's by
// less than the tolerance, that difference its error; the row's second pass (order fixed,
// row_tolerance set) gives the same value; a tolerance no K ≤ 5 meets is reported not converged;
// `hcs_order` given keeps the fixed K (and the old error, the distance to the Maxwellian state).
TEST(ModelFacade, ToleranceDrivesTheMixtureHcsOrder) {
  auto model = gkt::make_transport_model("mixture");
  ParameterPoint p = binary();
  p.numbers["mass_2"] = Rational(4);
  p.numbers["alpha"] = Rational(4, 5);
  gkt::Mixture m = gkt::make_mixture(3, {{1, 1, 0.5, ""}, {4, 1, 0.5, ""}}, 0.8);
  std::vector<double> ratio;  // T_1/T at K = 2, 3, … as far as the scan needs
  auto at = [&](std::size_t i) {
    while (ratio.size() <= i)
      ratio.push_back(gkt::mixture_cooling_state(m, gkt::MixtureHcsScheme::linear, static_cast<int>(ratio.size()) + 2)
                          .temperature_ratio[0]);
    return ratio[i];
  };
  const Rational tolerance(1, 10000);
  std::size_t chosen = 0;
  while (!(std::abs(at(chosen) - at(chosen + 1)) < 1e-4)) ++chosen;
  ASSERT_GT(chosen, 0U);  // K = 2 does not meet 1e-4 here: the scan has work to do
  const auto scanned = model->evaluate(p, {"temperature_ratio_1"}, {1, tolerance});
  EXPECT_DOUBLE_EQ(scanned[0].value.to_double(), ratio[chosen]);
  EXPECT_NEAR(scanned[0].error.to_double(), std::abs(ratio[chosen] - ratio[chosen + 1]), 1e-15);
  EXPECT_TRUE(scanned[0].converged);
  gkt::OrderRequest second{3, std::nullopt};
  second.row_tolerance = tolerance;
  EXPECT_DOUBLE_EQ(model->evaluate(p, {"temperature_ratio_1"}, second)[0].value.to_double(), ratio[chosen]);
  EXPECT_FALSE(model->evaluate(p, {"temperature_ratio_1"}, {1, Rational(1, 100000000)})[0].converged);
  ParameterPoint fixed = p;
  fixed.numbers["hcs_order"] = Rational(2);
  const auto k2 = model->evaluate(fixed, {"temperature_ratio_1"}, {1, tolerance});
  EXPECT_DOUBLE_EQ(k2[0].value.to_double(), ratio[0]);
  EXPECT_GT(k2[0].error.to_double(), 1e-3);
}

// scheme = "tail" (theory.md §10.6): the model's value at order N is the solver's resolution N with the
// error (6.1) from N + 1, N + 2, in 3D and 2D, dilute and dense; what the scheme does not do (linear HCS, a4,
// closed forms, orders past the cap) is refused with the field named.
TEST(ModelFacade, TailSchemeThroughTheModel) {
  auto model = gkt::make_transport_model("smooth-inelastic");
  ParameterPoint p;
  p.numbers["alpha"] = Rational(1, 2);
  p.choices["scheme"] = "tail";
  gkt::OrderRequest order;
  order.order = 3;
  const auto v = model->evaluate(p, {"thermal_conductivity", "a2", "pressure"}, order);
  const auto seq = gkt::tail_galerkin_sequence(3, 0.5, 5, gkt::TailTrialSpace::power_law);  // theory.md §10.6
  ASSERT_EQ(v.size(), 3U);
  EXPECT_NEAR(v[0].value.to_double(), seq[2].thermal_conductivity, 1e-12);
  EXPECT_NEAR(v[1].value.to_double(), seq[2].a2, 1e-12);
  const double d1 = std::fabs(seq[3].a2 - seq[2].a2), d2 = std::fabs(seq[4].a2 - seq[3].a2);
  EXPECT_NEAR(v[1].error.to_double(), 1.25 * d1 / (1 - d2 / d1), 1e-6 * d1);  // (6.1)
  EXPECT_FALSE(v[0].exact);
  EXPECT_EQ(v[2].value, Rational(1));  // dilute pressure p* = 1
  auto refused = [&](ParameterPoint q, const std::vector<std::string>& c, int n) {
    gkt::OrderRequest r;
    r.order = n;
    return refusal([&] { (void)model->evaluate(q, c, r); });
  };
  ParameterPoint two = p;
  two.numbers["dimension"] = Rational(2);
  const auto v2 = model->evaluate(two, {"shear_viscosity", "a2"}, order);
  const auto seq2 = gkt::tail_galerkin_sequence(2, 0.5, 5, gkt::TailTrialSpace::power_law);
  ASSERT_EQ(v2.size(), 2U);
  EXPECT_NEAR(v2[0].value.to_double(), seq2[2].shear_viscosity, 1e-12);
  EXPECT_NEAR(v2[1].value.to_double(), seq2[2].a2, 1e-12);
  EXPECT_GT(std::fabs(v2[1].value.to_double() - v[1].value.to_double()), 1e-2);  // not the 3D values
  // Dense (theory.md §15.8): the model's values are the Enskog sequence at φ with the Carnahan–Starling χ.
  ParameterPoint dense = p;
  dense.numbers["packing_fraction"] = Rational(1, 10);
  const auto vd = model->evaluate(dense, {"thermal_conductivity", "bulk_viscosity", "cooling_rate", "pressure"}, order);
  const gkt::EnskogState state = gkt::enskog_state(3, 0.1);
  const auto seqd = gkt::tail_galerkin_sequence(3, 0.5, 5, gkt::TailTrialSpace::power_law, state);
  ASSERT_EQ(vd.size(), 4U);
  EXPECT_NEAR(vd[0].value.to_double(), seqd[2].thermal_conductivity, 1e-12);
  EXPECT_NEAR(vd[1].value.to_double(), seqd[2].bulk_viscosity, 1e-12);
  EXPECT_NEAR(vd[2].value.to_double(), state.chi * seq[2].cooling_rate, 1e-12);  // (15.1)
  EXPECT_NEAR(vd[3].value.to_double(), state.pressure(3, 0.5), 1e-15);           // (15.5)
  EXPECT_GT(std::fabs(vd[0].value.to_double() - v[0].value.to_double()), 0.01);  // not the dilute κ* (1.623)
  ParameterPoint linear = p;
  linear.choices["hcs"] = "linear";
  EXPECT_TRUE(contains(refused(linear, {"a2"}, 1), "hcs:"));
  EXPECT_TRUE(contains(refused(p, {"a4"}, 2), "coefficients: a4 is not computed by scheme = \"tail\""));
  EXPECT_TRUE(contains(refused(p, {"a2"}, gkt::kTailGalerkinMaxOrder - 1), "order: must be an integer in [1, "));
  EXPECT_TRUE(contains(refusal([&] { (void)model->closed_form(p, "shear_viscosity", 1); }),
                       "scheme: \"tail\" is numerical and has no closed forms"));
}

// The tolerance rule of scheme = "tail" (theory.md §10.6): a tolerance stops no earlier than resolution 10,
// and the value it returns lies within its (6.1) error of resolution 13. At 3D α = 0.9, tolerance 1e-4,
// κ* would stop at resolution 6 (estimate 1.9e-5) and a2 at 4 without the rule.
TEST(ModelFacade, TailSchemeToleranceIsHonestAgainstAHigherResolution) {
  auto model = gkt::make_transport_model("smooth-inelastic");
  ParameterPoint p;
  p.numbers["alpha"] = Rational(9, 10);
  p.choices["scheme"] = "tail";
  gkt::OrderRequest order;
  order.tolerance = Rational(1, 10000);
  const std::vector<std::string> names = {
      "a2", "a3", "cooling_rate", "shear_viscosity", "thermal_conductivity", "density_heat_coefficient"};
  const auto v = model->evaluate(p, names, order);
  const auto seq = gkt::tail_galerkin_sequence(3, 0.9, 13, gkt::TailTrialSpace::power_law);
  const auto& high = seq.back();
  const double reference[] = {high.a2,
                              high.a3,
                              high.cooling_rate,
                              high.shear_viscosity,
                              high.thermal_conductivity,
                              high.density_heat_coefficient};
  ASSERT_EQ(v.size(), names.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_TRUE(v[i].converged) << names[i];
    EXPECT_GE(v[i].order, 10) << names[i];
    EXPECT_LT(v[i].error.to_double(), 1e-4) << names[i];
    EXPECT_LE(std::fabs(v[i].value.to_double() - reference[i]), v[i].error.to_double()) << names[i];
  }
}

// scheme = "tail" past the former resolution cap 12 (theory.md §10.6): at 2D α = 0.7 κ*, μ* met no
// tolerance of 1e-4 by resolution 10 (1.6e-4, 2.1e-4); now they stop at 11 (the scan computes the
// resolutions to 16), converged, within their errors of resolution 22 (`tail_galerkin_sequence(2, 0.7, 22,
// power_law)`, 2026-12-02: κ* 1.2276219798121442, μ* 0.5780166644811896; changes < 3e-7 per step there).
TEST(ModelFacade, TailSchemeMeetsTolerance1e4PastTheFormerCap) {
  auto model = gkt::make_transport_model("smooth-inelastic");
  ParameterPoint p;
  p.numbers["dimension"] = Rational(2);
  p.numbers["alpha"] = Rational(7, 10);
  p.choices["scheme"] = "tail";
  gkt::OrderRequest order;
  order.tolerance = Rational(1, 10000);
  const auto v = model->evaluate(p, {"thermal_conductivity", "density_heat_coefficient"}, order);
  const double reference[] = {1.2276219798121442, 0.5780166644811896};
  ASSERT_EQ(v.size(), 2U);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_TRUE(v[i].converged) << i;
    EXPECT_GT(v[i].order, 10) << i;  // beyond the former highest resolution
    EXPECT_LT(v[i].error.to_double(), 1e-4) << i;
    EXPECT_LE(std::fabs(v[i].value.to_double() - reference[i]), v[i].error.to_double()) << i;
  }
}

// The HCS tail columns of scheme = "tail" (theory.md §10.6, §10.7): tail_exponent is the solver's A = 2β/ζ_r at
// the resolution, with the error (6.1) from N + 1, N + 2 like every column, and +∞ at α = 1 (the Maxwellian);
// tail_amplitude is refused where hcs_tail_amplitude was not measured to work (α > 0.7: φ_N converged only inside
// the Gaussian core; resolutions below 12: 2D α = 0.5 at 5 and 6 does not settle) and by the other schemes; a scene
// that lists no columns leaves both out.
TEST(ModelFacade, TailColumnsThroughTheModel) {
  auto model = gkt::make_transport_model("smooth-inelastic");
  ParameterPoint p;
  p.numbers["dimension"] = Rational(2);
  p.numbers["alpha"] = Rational(1, 2);
  p.choices["scheme"] = "tail";
  gkt::OrderRequest order;
  order.order = 3;
  const auto v = model->evaluate(p, {"tail_exponent", "cooling_rate"}, order);
  const auto seq = gkt::tail_galerkin_sequence(2, 0.5, 5, gkt::TailTrialSpace::power_law);
  ASSERT_EQ(v.size(), 2U);
  EXPECT_NEAR(v[0].value.to_double(), seq[2].tail_exponent, 1e-12);
  // 2D: A = 2β/ζ_r, β = 2, ζ_r = ν ζ* with ν = √(2π) (theory.md (9.4), §10.6): A = 4.199 at α = 0.5 (§10.7).
  EXPECT_NEAR(v[0].value.to_double(), 4 / (std::sqrt(2 * M_PI) * v[1].value.to_double()), 1e-10);
  const double d1 = std::fabs(seq[3].tail_exponent - seq[2].tail_exponent);
  const double d2 = std::fabs(seq[4].tail_exponent - seq[3].tail_exponent);
  EXPECT_NEAR(v[0].error.to_double(), 1.25 * d1 / (1 - d2 / d1), 1e-6 * d1);  // (6.1)
  ParameterPoint elastic = p;
  elastic.numbers["alpha"] = Rational(1);
  const auto a1 = model->evaluate(elastic, {"tail_exponent"}, order);
  EXPECT_TRUE(a1[0].infinite);
  auto refused = [&](const ParameterPoint& q, const std::string& c, int n) {
    gkt::OrderRequest r;
    r.order = n;
    return refusal([&] { (void)model->evaluate(q, {c}, r); });
  };
  ParameterPoint core = p;  // 2D α = 0.8: the continuation does not settle at N = 12 (theory.md §10.7)
  core.numbers["alpha"] = Rational(4, 5);
  EXPECT_TRUE(contains(refused(core, "tail_amplitude", 12),
                       "coefficients: tail_amplitude: alpha: must be a number in [0.05, 0.7] for the tail amplitude"));
  EXPECT_TRUE(contains(refused(elastic, "tail_amplitude", 12), "coefficients: tail_amplitude: alpha:"));
  EXPECT_TRUE(contains(refused(p, "tail_amplitude", 6), "order: tail_amplitude needs a resolution in [12, 22]"));
  ParameterPoint standard = p;
  standard.choices["scheme"] = "standard";
  for (const char* c : {"tail_exponent", "tail_amplitude"})
    EXPECT_TRUE(contains(refused(standard, c, 2),
                         std::string("coefficients: ") + c + " is computed by scheme = \"tail\" only"));
  const auto names = model->coefficient_names();
  const auto defaults = model->default_coefficients({});
  for (const char* c : {"tail_exponent", "tail_amplitude"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), c), names.end()) << c;
    EXPECT_EQ(std::find(defaults.begin(), defaults.end(), c), defaults.end()) << c;
  }
}

// reference_state = "hcs" (theory.md §17.11): a mixture of identical species gives the smooth-inelastic
// model's η* and κ* (its first order keeps a2 of the nonlinear HCS in f0) to round-off; the default
// (Maxwellian, GDH) does not; dense (φ = 1/5), the dense smooth-inelastic model with packing_fraction.
TEST(ModelFacade, MixtureReferenceStateHcsIsTheOneComponentGas) {
  auto mixture = gkt::make_transport_model("mixture");
  auto one = gkt::make_transport_model("smooth-inelastic");
  ParameterPoint p = binary();
  p.numbers["mass_2"] = Rational(1);
  p.numbers["fraction_1"] = Rational(3, 10);
  p.numbers["fraction_2"] = Rational(7, 10);
  p.numbers["alpha"] = Rational(4, 5);
  p.choices["hcs"] = "nonlinear";
  ParameterPoint q;
  q.numbers["alpha"] = Rational(4, 5);
  const auto expected = one->evaluate(q, {"shear_viscosity", "thermal_conductivity"}, {1, std::nullopt});
  const auto gdh = mixture->evaluate(p, {"shear_viscosity", "thermal_conductivity"}, {1, std::nullopt});
  p.choices["reference_state"] = "hcs";
  const auto got = mixture->evaluate(p, {"shear_viscosity", "thermal_conductivity"}, {1, std::nullopt});
  for (std::size_t k = 0; k < 2; ++k) {
    const double e = expected[k].value.to_double();
    EXPECT_NEAR(got[k].value.to_double(), e, 1e-12 * e) << k;
  }
  EXPECT_GT(std::abs(gdh[1].value.to_double() / expected[1].value.to_double() - 1), 0.02);
  // Dense (φ = 1/5): the dense smooth-inelastic model with packing_fraction, the bulk viscosity too.
  p.numbers["packing_fraction"] = Rational(1, 5);
  q.numbers["packing_fraction"] = Rational(1, 5);
  const std::vector<std::string> dense_names{"shear_viscosity", "thermal_conductivity", "bulk_viscosity"};
  const auto dense_expected = one->evaluate(q, dense_names, {1, std::nullopt});
  const auto dense_got = mixture->evaluate(p, dense_names, {1, std::nullopt});
  for (std::size_t k = 0; k < 3; ++k) {
    const double e = dense_expected[k].value.to_double();
    EXPECT_NEAR(dense_got[k].value.to_double(), e, 1e-12 * e) << k;
  }
  p.numbers["packing_fraction"] = Rational(0);
  p.choices["scheme"] = "published";  // GDH's truncation is about Maxwellians: refused, not mixed
  EXPECT_TRUE(contains(refusal([&] {
                         mixture->evaluate(p, {"shear_viscosity"}, {1, std::nullopt});
                       }),
                       "reference_state: \"hcs\" cannot be combined with scheme = \"published\""));
}

// With reference_state = "hcs", a tolerance and no hcs_order, the reference's K is the smallest at which
// ζ*, every T_i/T and every a2,i differ from their values at K + 1 by less than the tolerance; the
// transport value is then the one with that hcs_order given.
TEST(ModelFacade, ToleranceDrivesTheMixtureReferenceOrder) {
  auto model = gkt::make_transport_model("mixture");
  ParameterPoint p = binary();
  p.numbers["mass_2"] = Rational(4);
  p.numbers["alpha"] = Rational(4, 5);
  p.choices["reference_state"] = "hcs";
  gkt::Mixture m = gkt::make_mixture(3, {{1, 1, 0.5, ""}, {4, 1, 0.5, ""}}, 0.8);
  auto state = [&](int k) { return gkt::mixture_cooling_state(m, gkt::MixtureHcsScheme::linear, k); };
  const double tolerance = 1e-4;
  int chosen = 2;
  for (;; ++chosen) {
    const auto here = state(chosen), next = state(chosen + 1);
    double worst = std::abs(here.cooling_rate - next.cooling_rate);
    for (std::size_t i = 0; i < 2; ++i)
      worst = std::max({worst, std::abs(here.temperature_ratio[i] - next.temperature_ratio[i]),
                        std::abs(here.cumulants[i][2] - next.cumulants[i][2])});
    if (worst < tolerance) break;
  }
  ASSERT_GT(chosen, 2);  // K = 2 does not meet the tolerance: the scan has work to do
  ParameterPoint fixed = p;
  fixed.numbers["hcs_order"] = Rational(chosen);
  const gkt::OrderRequest request{1, std::nullopt};
  gkt::OrderRequest scanned = request;
  scanned.row_tolerance = Rational(1, 10000);
  const double expected = model->evaluate(fixed, {"thermal_conductivity"}, request)[0].value.to_double();
  EXPECT_DOUBLE_EQ(model->evaluate(p, {"thermal_conductivity"}, scanned)[0].value.to_double(), expected);
  fixed.numbers["hcs_order"] = Rational(2);
  EXPECT_NE(model->evaluate(fixed, {"thermal_conductivity"}, request)[0].value.to_double(), expected);
}

// theory.md §6 (6.3): in 2D at α = 0.8 the Sonine sequences turn; a2 at tolerance 1e-5 stopped at order 5
// (2.8e-6 claimed, honest) but from a turn read as an alternation; η* at 1e-8 stopped at order 10 claiming
// 3.3e-9 while 1.6e-8 off. The model's scan must read turns through the next order and stay honest against
// the limit: the tail scheme extrapolated to N → ∞ (theory.md §6 table, column (b)), −0.0262441287448. The
// HCS alone: fast (η* needs Sonine operators to order 17, ≈ 35 s of CPU, measured by tools/truncation_survey.py).
TEST(ModelFacade, SmoothInelasticToleranceReadsATurnThroughTheNextOrder) {
  auto model = gkt::make_transport_model("smooth-inelastic");
  ParameterPoint p;
  p.numbers = {{"dimension", Rational(2)}, {"alpha", Rational(4, 5)}};
  const Rational tolerance = Rational::parse("1e-5");
  const auto v = model->evaluate(p, {"a2"}, {1, tolerance}).front();
  EXPECT_TRUE(v.converged);
  EXPECT_GT(v.order, 5);  // orders 5–8 change by −, +, +: a turn at 6
  EXPECT_LT(v.error, tolerance);
  EXPECT_LE(std::fabs(v.value.to_double() + 0.0262441287448), v.error.to_double());
  // At order 5 (changes −2.4e-6, +1.7e-7, +3.1e-7: the tail after the turn grows) a fixed-order request
  // reports the turn, not converging, with |Δ1| + |Δ2| + |Δ3| ≥ the distance to the limit.
  const auto at5 = model->evaluate(p, {"a2"}, {5, std::nullopt}).front();
  EXPECT_FALSE(at5.converged);
  EXPECT_LE(std::fabs(at5.value.to_double() + 0.0262441287448), at5.error.to_double());
  EXPECT_EQ(at5.divergence, gkt::Divergence::turn_growing);  // the reason the CLI's warning gives
}

namespace {
/// A model of scripted coefficients, for the row logic of a tolerance scan: coefficient c at order n has the
/// value n and the error error(c, n), and takes orders 1 … highest(c) (refused beyond, as the rough HCS
/// columns are beside η*); its tolerance scan stops at the first order whose error is below the tolerance,
/// else at its highest order.
class ScriptedModel final : public gkt::TransportModel {
 public:
  using Error = std::function<Rational(const std::string&, int)>;
  using Highest = std::function<int(const std::string&)>;
  ScriptedModel(std::vector<std::string> names, Error error, Highest highest)
      : names_(std::move(names)), error_(std::move(error)), highest_(std::move(highest)) {}
  [[nodiscard]] std::string name() const override { return "scripted"; }
  [[nodiscard]] std::string description() const override { return "test"; }
  [[nodiscard]] std::vector<std::string> coefficient_names() const override { return names_; }
  [[nodiscard]] std::vector<gkt::ParameterSpec> parameters() const override { return {}; }
  [[nodiscard]] int max_order() const override { return 4; }
  std::vector<gkt::CoefficientValue> evaluate(const ParameterPoint&, const std::vector<std::string>& names,
                                              const gkt::OrderRequest& order) override {
    std::vector<gkt::CoefficientValue> out;
    for (const auto& c : names) {
      const int highest = highest_(c);
      auto at = [&](int n) { return gkt::CoefficientValue{Rational(n), error_(c, n), n, true, true, true}; };
      if (!order.tolerance) {
        if (order.order > highest)
          throw std::invalid_argument("order: " + c + " takes orders 1 to " + std::to_string(highest));
        out.push_back(at(order.order));
        continue;
      }
      int n = 1;
      while (n < highest && !(at(n).error < *order.tolerance)) ++n;
      out.push_back(at(n));
    }
    return out;
  }

 private:
  std::vector<std::string> names_;
  Error error_;
  Highest highest_;
};

/// "steady" meets the tolerance at order 3 and stays within it; "breaks" meets it at order 1 and breaks down
/// at order 3 (error 1e-2, as the 2D α = 0.2 tensor mode of the tail scheme, theory.md §10.6); orders 1 … 4.
ScriptedModel steady_and_breaking_model() {
  return ScriptedModel(
      {"steady", "breaks"},
      [](const std::string& c, int n) {
        return c == "steady" ? Rational(1, 1000 * n * n) : n == 3 ? Rational(1, 100) : Rational(1, 10000);
      },
      [](const std::string&) { return 4; });
}
}  // namespace

// The row of a tolerance scan (gkt/models/tolerance_row.hpp): a coefficient whose error at the row's order
// misses the tolerance its own scan met is reported at its own stop, with that order; one that no order
// brings below the tolerance is flagged. Never an error above the tolerance flagged converged.
TEST(ModelFacade, ToleranceRowReportsEachColumnHonestly) {
  ScriptedModel model = steady_and_breaking_model();
  const Rational tolerance(1, 5000);  // steady: 1e-3, 2.5e-4, 1.1e-4 → order 3; breaks: 1e-4 → order 1
  const gkt::ToleranceRow row = gkt::evaluate_tolerance_row(model, {}, {"steady", "breaks"}, tolerance);
  EXPECT_EQ(row.order, 3);
  ASSERT_EQ(row.values.size(), 2U);
  EXPECT_EQ(row.values[0].order, 3);
  EXPECT_TRUE(row.values[0].converged);
  EXPECT_EQ(row.values[1].order, 1);  // at order 3 its error, 1e-2, is above the tolerance
  EXPECT_EQ(row.values[1].value, Rational(1));
  EXPECT_TRUE(row.values[1].converged);
  for (const auto& v : row.values) EXPECT_TRUE(v.error < tolerance);
  // A tolerance "breaks" meets nowhere (1e-4 is its best): flagged, whatever order it is printed at.
  const gkt::ToleranceRow tight = gkt::evaluate_tolerance_row(model, {}, {"steady", "breaks"}, Rational(1, 20000));
  EXPECT_FALSE(tight.values[1].converged);
  EXPECT_FALSE(tight.values[0].converged);  // steady's best, 1/16000, misses 1/20000 too
}

// A row whose order lies beyond one coefficient's range (the rough HCS columns stop at order 3, η* goes
// on): that coefficient is reported at its own stop, the others at the row's order — not an error (before,
// `gkt table` with cooling_rate and shear_viscosity of model rough at a tolerance failed on the second pass).
TEST(ModelFacade, ToleranceRowKeepsACoefficientWhoseRangeEndsBelowTheRowOrder) {
  // "short" takes orders 1 … 2 only (as the rough HCS columns beside η*), "long" 1 … 4; error 1/(10 n³).
  ScriptedModel model(
      {"long", "short"}, [](const std::string&, int n) { return Rational(1, 10 * n * n * n); },
      [](const std::string& c) { return c == "short" ? 2 : 4; });
  const Rational tolerance(1, 500);  // long: 1e-1, 1.25e-2, 3.7e-3, 1.6e-3 → 4; short: → 2 (1.25e-2, not met)
  const gkt::ToleranceRow row = gkt::evaluate_tolerance_row(model, {}, {"long", "short"}, tolerance);
  EXPECT_EQ(row.order, 4);
  ASSERT_EQ(row.values.size(), 2U);
  EXPECT_EQ(row.values[0].order, 4);
  EXPECT_TRUE(row.values[0].converged);
  EXPECT_EQ(row.values[1].order, 2);
  EXPECT_EQ(row.values[1].value, Rational(2));
  EXPECT_FALSE(row.values[1].converged);  // its best, 1/80, misses the tolerance: flagged
}
