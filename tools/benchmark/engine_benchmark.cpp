// Speed against error of the exact Sonine engine (docs/performance.md).
//
//   build/bin/gkt_benchmark --benchmark_min_time=0.2
//
// Counters: err_eta, err_kappa = |value at order N − value at order 40| (3D); these are the
// actual truncation errors, not estimates.
#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
#include <numbers>
#include <utility>

#include "gkt/evolution/homogeneous_cooling_evolution.hpp"
#include "gkt/models/transport_model.hpp"
#include "gkt/operators/linearized_operator.hpp"
#include "gkt/operators/viscoelastic_hierarchy.hpp"
#include "gkt/transport/closed_forms/enskog_closed_form.hpp"
#include "gkt/transport/closed_forms/first_sonine_formulas.hpp"
#include "gkt/transport/common/sonine_solution.hpp"
#include "gkt/transport/mixture/mixture_cooling_state.hpp"
#include "gkt/transport/mixture/mixture_navier_stokes.hpp"
#include "gkt/transport/mixture/mixture_transport_table.hpp"
#include "gkt/transport/mixture/published_first_sonine.hpp"
#include "gkt/transport/mixture/ternary_transport_table.hpp"
#include "gkt/transport/mixture/tracer_diffusion.hpp"
#include "gkt/transport/monodisperse/hard_spheres.hpp"
#include "gkt/transport/viscoelastic/viscoelastic_transport.hpp"

namespace {

using gkt::HardSphereCoefficient;
using gkt::Rational;

const std::map<int, std::pair<double, double>>& actual_errors() {
  static const auto table = [] {
    std::map<int, std::pair<double, double>> t;
    gkt::HardSphereSonineSystem s(3);
    const Rational eta = s.reduced_coefficient(HardSphereCoefficient::shear_viscosity, 40);
    const Rational kappa = s.reduced_coefficient(HardSphereCoefficient::thermal_conductivity, 40);
    for (int n = 1; n <= 20; ++n)
      t[n] = {(s.reduced_coefficient(HardSphereCoefficient::shear_viscosity, n) - eta).abs().to_double(),
              (s.reduced_coefficient(HardSphereCoefficient::thermal_conductivity, n) - kappa).abs().to_double()};
    return t;
  }();
  return table;
}

/// Cold: a new system each iteration (nothing cached), η and κ at order N, exact.
void ColdEtaKappa(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) {
    gkt::HardSphereSonineSystem s(3);
    benchmark::DoNotOptimize(s.reduced_coefficient(HardSphereCoefficient::shear_viscosity, n));
    benchmark::DoNotOptimize(s.reduced_coefficient(HardSphereCoefficient::thermal_conductivity, n));
  }
  state.counters["err_eta"] = actual_errors().at(n).first;
  state.counters["err_kappa"] = actual_errors().at(n).second;
}
BENCHMARK(ColdEtaKappa)->DenseRange(1, 20)->Unit(benchmark::kMillisecond);

/// Cold, with the error estimate (orders N, N+1, N+2), as `gkt table` does.
void ColdEtaKappaWithErrorEstimate(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) {
    gkt::HardSphereSonineSystem s(3);
    benchmark::DoNotOptimize(s.estimate(HardSphereCoefficient::shear_viscosity, n));
    benchmark::DoNotOptimize(s.estimate(HardSphereCoefficient::thermal_conductivity, n));
  }
}
BENCHMARK(ColdEtaKappaWithErrorEstimate)
    ->Arg(1)
    ->Arg(4)
    ->Arg(8)
    ->Arg(12)
    ->Arg(16)
    ->Arg(20)
    ->Unit(benchmark::kMillisecond);

/// The engine alone: exact tensor (viscosity) matrix up to Sonine index N, numeric α.
void OperatorMatrixExact(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state)
    benchmark::DoNotOptimize(gkt::linearized_operator_matrix<Rational>(3, Rational(1), gkt::OperatorPart::full, 2, n));
}
BENCHMARK(OperatorMatrixExact)->Arg(4)->Arg(8)->Arg(16)->Arg(24)->Arg(32)->Arg(40)->Unit(benchmark::kMillisecond);

/// The engine with α symbolic (entries are polynomials in α over Q).
void OperatorMatrixSymbolicAlpha(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto alpha = gkt::RationalPolynomial::variable();
  for (auto _ : state)
    benchmark::DoNotOptimize(
        gkt::linearized_operator_matrix<gkt::RationalPolynomial>(3, alpha, gkt::OperatorPart::full, 2, n));
}
BENCHMARK(OperatorMatrixSymbolicAlpha)->Arg(2)->Arg(4)->Arg(8)->Arg(12)->Unit(benchmark::kMillisecond);

/// A sweep of 10⁴ points through the model interface that reuses the matrices: tolerances
/// from 1e-3 to 1e-10 (each point picks its own order), all three coefficients, 3D.
void Sweep10kReusingMatrices(benchmark::State& state) {
  for (auto _ : state) {
    auto model = gkt::make_transport_model("hard-spheres");
    const std::vector<std::string> all{"shear_viscosity", "thermal_conductivity", "self_diffusion"};
    for (int k = 0; k < 10000; ++k) {
      gkt::OrderRequest request;
      request.tolerance = Rational(1, 1000) * Rational(1, 10).pow(k % 8);
      benchmark::DoNotOptimize(model->evaluate({{{"dimension", Rational(3)}}, {}}, all, request));
    }
  }
}
BENCHMARK(Sweep10kReusingMatrices)->Unit(benchmark::kMillisecond);

/// One first-Sonine evaluation of a2, ζ*, η*, κ*, μ* through the generated closed forms.
void FirstSonineFullSetGenerated(benchmark::State& state) {
  double alpha = 0.5;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gkt::first_sonine_values(3, alpha));
    alpha = alpha < 0.99 ? alpha + 1e-3 : 0.5;
  }
}
BENCHMARK(FirstSonineFullSetGenerated)->Unit(benchmark::kNanosecond);

/// One dense first-Sonine evaluation (a2, ζ*, p*, η*, bulk, κ*, μ*, ζ_U) through the generated
/// closed forms (EnskogOrderWarm/1/1 is the order-1 numerical solve of the same kind of state).
void EnskogFirstSonineFullSetGenerated(benchmark::State& state) {
  double alpha = 0.5;
  const gkt::EnskogState dense{0.3, 2.4781341107871726, 2.7488546438983756};  // Carnahan–Starling at φ = 0.3
  for (auto _ : state) {
    benchmark::DoNotOptimize(gkt::enskog_first_sonine_values(3, alpha, dense));
    alpha = alpha < 0.99 ? alpha + 1e-3 : 0.5;
  }
}
BENCHMARK(EnskogFirstSonineFullSetGenerated)->Unit(benchmark::kNanosecond);

/// Binary mixture HCS (3D, m2/m1 = 2.5, σ2/σ1 = 1.5, x1 = 0.4, α = 0.8, φ = 0.2): arg 0 Maxwellian,
/// 1 first Sonine (engine moments at the iterated widths).
void MixtureHcs(benchmark::State& state) {
  const auto mixture = gkt::make_mixture(3, {{1.0, 1.0, 0.4, ""}, {2.5, 1.5, 0.6, ""}}, 0.8, 0.2);
  const auto scheme = state.range(0) == 0 ? gkt::MixtureHcsScheme::maxwellian : gkt::MixtureHcsScheme::linear;
  for (auto _ : state) benchmark::DoNotOptimize(gkt::mixture_cooling_state(mixture, scheme));
}
BENCHMARK(MixtureHcs)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

/// Tracer diffusion (3D, m0/m = 2.5, σ0/σ = 1.5, α = 0.8): build to order N + 2 and estimate at N.
void TracerDiffusionEstimate(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  double error = 0;
  for (auto _ : state) {
    const gkt::TracerDiffusion tracer({3, 2.5, 1.5, 0.8, 0.8}, n + 2);
    error = tracer.estimate(n).error.to_double();
    benchmark::DoNotOptimize(error);
  }
  state.counters["error"] = error;
}
BENCHMARK(TracerDiffusionEstimate)->Arg(1)->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond);

/// Dilute binary Navier–Stokes set (3D, m2/m1 = 2.5, σ2/σ1 = 1.5, x1 = 0.4, α = 0.8): arg 1 = 0 the
/// cold call (Maxwellian HCS, its derivatives and the operator built to order N + 2, then orders N,
/// N+1, N+2 solved — the estimate), 1 the warm solve of order N alone on a built operator.
void MixtureNavierStokesSet(benchmark::State& state) {
  const auto mixture = gkt::make_mixture(3, {{1.0, 1.0, 0.4, ""}, {2.5, 1.5, 0.6, ""}}, 0.8);
  const int n = static_cast<int>(state.range(0));
  double error = 0;
  if (state.range(1) == 0) {
    for (auto _ : state) {
      const gkt::MixtureNavierStokes ns(mixture, n + 2);
      const auto a = ns.coefficients(n), b = ns.coefficients(n + 1), c = ns.coefficients(n + 2);
      error = gkt::estimate_truncation(Rational::from_double(a.thermal_conductivity),
                                       Rational::from_double(b.thermal_conductivity),
                                       Rational::from_double(c.thermal_conductivity))
                  .error.to_double();
      benchmark::DoNotOptimize(error);
    }
    state.counters["lambda_error"] = error;
  } else {
    const gkt::MixtureNavierStokes ns(mixture, n);
    for (auto _ : state) benchmark::DoNotOptimize(ns.coefficients(n));
  }
}
BENCHMARK(MixtureNavierStokesSet)->ArgsProduct({{1, 2, 4, 8}, {0, 1}})->Unit(benchmark::kMillisecond);

/// GDH's published first Sonine in closed form (theory.md §17.10), one state per call with its HCS
/// solved: arg 0 = species (2: the benchmark binary; 3: a ternary with a restitution matrix),
/// arg 1 = 1 varies x_1 and α from call to call (a new state each time), 0 repeats one state; arg 2 = 1
/// the dense gas at φ = 0.25 (χ_ij, their derivatives, I_ℓij and the collisional transfer), 0 dilute.
void PublishedFirstSonineState(benchmark::State& state) {
  const int s = static_cast<int>(state.range(0));
  gkt::MixtureCell cell;
  cell.dimension = 3;
  cell.species = s;
  cell.packing_fraction = state.range(2) == 1 ? 0.25 : 0.0;
  cell.mass = {1.0, 2.5, 0.4, 0};
  cell.diameter = {1.0, 1.5, 0.8, 0};
  cell.fraction = s == 2 ? std::array<double, 4>{0.4, 0.6, 0, 0} : std::array<double, 4>{0.4, 0.35, 0.25, 0};
  for (int i = 0; i < s; ++i)
    for (int j = 0; j < s; ++j) cell.restitution[static_cast<std::size_t>(i * 4 + j)] = i == j ? 0.8 : 0.7;
  const bool vary = state.range(1) == 1;
  double x = 0.4;
  for (auto _ : state) {
    if (vary) {
      x = x < 0.6 ? x + 1e-4 : 0.2;
      cell.fraction[0] = x;
      cell.fraction[1] = s == 2 ? 1 - x : 0.75 - x;
      cell.restitution[0] = 0.6 + x / 2;
    }
    benchmark::DoNotOptimize(gkt::published_first_sonine(cell));
  }
}
BENCHMARK(PublishedFirstSonineState)->ArgsProduct({{2, 3}, {0, 1}, {0, 1}})->Unit(benchmark::kNanosecond);

/// The engine's published truncation for the states of PublishedFirstSonineState (arg 0 = species,
/// arg 1 = 1 dense at φ = 0.25): the cold call (HCS, operator and transfer averages at order 1, then
/// coefficients(1, published)), the cost the closed form replaces.
void MixtureNavierStokesPublished(benchmark::State& state) {
  const int s = static_cast<int>(state.range(0));
  const double phi = state.range(1) == 1 ? 0.25 : 0.0;
  std::vector<gkt::Species> species{{1.0, 1.0, 0.4, ""}, {2.5, 1.5, 0.6, ""}};
  if (s == 3) {
    species[1].fraction = 0.35;
    species.push_back({0.4, 0.8, 0.25, ""});
  }
  gkt::Mixture mixture = gkt::make_mixture(3, species, 0.7, phi);
  for (int i = 0; i < s; ++i) mixture.alpha[static_cast<std::size_t>(i * s + i)] = 0.8;
  for (auto _ : state) {
    const gkt::MixtureNavierStokes ns(mixture, 1);
    benchmark::DoNotOptimize(ns.coefficients(1, gkt::MixtureTruncation::published));
  }
}
BENCHMARK(MixtureNavierStokesPublished)->ArgsProduct({{2, 3}, {0, 1}})->Unit(benchmark::kMillisecond);

/// The dense ternary table (theory.md §18.10, "Dense ternary table"): the species of its test (m = 1,
/// 1.2, 1.4, σ = 1, 1.1, 0.95, a restitution matrix), order 1, φ ∈ [0, 0.2], 3 × 3 × 3 nodes, tolerance
/// 5e-2 (4 pieces); each call evaluates the physical set at a new (x_1, x_2, n, T) with φ from n.
void TernaryTransportTableEvaluateDense(benchmark::State& state) {
  static const auto built = [] {
    auto mixture = gkt::make_mixture(3, {{1.0, 1.0, 0.3, ""}, {1.2, 1.1, 0.3, ""}, {1.4, 0.95, 0.4, ""}}, 0.8);
    mixture.alpha = {0.9, 0.85, 0.8, 0.85, 0.8, 0.8, 0.8, 0.8, 0.85};
    const auto start = std::chrono::steady_clock::now();
    gkt::TernaryTransportTable table(mixture, 1, 3, 5e-2, 3, 0.2, 3);
    return std::make_pair(std::move(table),
                          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }();
  const auto& [table, build] = built;
  double x = 0.1, y = 0.05;
  for (auto _ : state) {
    benchmark::DoNotOptimize(table.evaluate(x, y, 0.05 + 0.3 * x, 2.0 - y));  // φ ≈ 0.03 … 0.13
    x = x < 0.6 ? x + 1.3e-3 : 0.1;
    y = y < 0.35 ? y + 0.7e-3 : 0.05;
  }
  state.counters["build_s"] = build;
  state.counters["solves"] = table.build_solves();
  state.counters["pieces"] = table.pieces();
  state.counters["interpolation_error"] = table.interpolation_error();
}
BENCHMARK(TernaryTransportTableEvaluateDense)->Unit(benchmark::kNanosecond);

/// The per-state binary table (theory.md §17.8): arg 0 = Sonine order of the table; the timed loop
/// evaluates the full physical set at a new (x_1, n, T) each call (the build is outside the loop;
/// its time and the measured interpolation error are reported as counters).
void BinaryTransportTableEvaluate(benchmark::State& state) {
  const auto mixture = gkt::make_mixture(3, {{1.0, 1.0, 0.4, ""}, {2.5, 1.5, 0.6, ""}}, 0.8);
  const auto start = std::chrono::steady_clock::now();
  const gkt::BinaryTransportTable table(mixture, static_cast<int>(state.range(0)));
  const double build = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double x = 0.1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(table.evaluate(x, 1.0 + x, 2.0 - x));
    x = x < 0.9 ? x + 1e-3 : 0.1;
  }
  state.counters["build_s"] = build;
  state.counters["interpolation_error"] = table.interpolation_error();
}
BENCHMARK(BinaryTransportTableEvaluate)->Arg(1)->Arg(4)->Unit(benchmark::kNanosecond);

/// The dense per-state table (theory.md §18.10): arg 0 = Sonine order, 24 nodes in x_1 × 12 in
/// φ ∈ [0, 0.4]; each call evaluates a new (x_1, n, T) with φ from n between 0.05 and 0.35. The
/// table is built once per order (static), its build time and interpolation error are counters.
void BinaryTransportTableEvaluateDense(benchmark::State& state) {
  static std::map<int, std::pair<gkt::BinaryTransportTable, double>> tables;
  const int order = static_cast<int>(state.range(0));
  if (!tables.contains(order)) {
    const auto mixture = gkt::make_mixture(3, {{1.0, 1.0, 0.4, ""}, {2.5, 1.5, 0.6, ""}}, 0.8);
    const auto start = std::chrono::steady_clock::now();
    gkt::BinaryTransportTable table(mixture, order, 24, 0.4, 12);
    const double build = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    tables.emplace(order, std::make_pair(std::move(table), build));
  }
  const auto& [table, build] = tables.at(order);
  double x = 0.1;
  for (auto _ : state) {
    // n = φ/(v_3 Σ x_i σ_i³), φ = 0.05 … 0.35 as x moves.
    const double phi = 0.05 + 0.3 * (x - 0.1) / 0.8, volume = std::numbers::pi / 6 * (x + (1 - x) * 3.375);
    benchmark::DoNotOptimize(table.evaluate(x, phi / volume, 2.0 - x));
    x = x < 0.9 ? x + 1e-3 : 0.1;
  }
  state.counters["build_s"] = build;
  state.counters["interpolation_error"] = table.interpolation_error();
}
BENCHMARK(BinaryTransportTableEvaluateDense)->Arg(1)->Arg(4)->Unit(benchmark::kNanosecond);

/// The dilute ternary table (theory.md §17.8, "Ternary tables"): m = 1, 2, 3.5, σ = 1, 1.3, 0.8,
/// a full restitution matrix, arg 0 = Sonine order, 9 × 9 starting nodes, tolerance 1e-3; each call
/// evaluates the full physical set at a new (x_1, x_2, n, T) inside the triangle. The build (static,
/// once per order) reports its time, solves, pieces and measured error as counters.
void TernaryTransportTableEvaluate(benchmark::State& state) {
  static std::map<int, std::pair<gkt::TernaryTransportTable, double>> tables;
  const int order = static_cast<int>(state.range(0));
  if (!tables.contains(order)) {
    auto mixture = gkt::make_mixture(3, {{1.0, 1.0, 0.3, ""}, {2.0, 1.3, 0.3, ""}, {3.5, 0.8, 0.4, ""}}, 0.8);
    mixture.alpha = {0.9, 0.85, 0.75, 0.85, 0.8, 0.8, 0.75, 0.8, 0.7};
    const auto start = std::chrono::steady_clock::now();
    gkt::TernaryTransportTable table(mixture, order, 9, 1e-3);
    const double build = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    tables.emplace(order, std::make_pair(std::move(table), build));
  }
  const auto& [table, build] = tables.at(order);
  double x = 0.1, y = 0.05;
  for (auto _ : state) {
    benchmark::DoNotOptimize(table.evaluate(x, y, 1.0 + x, 2.0 - y));
    x = x < 0.6 ? x + 1.3e-3 : 0.1;
    y = y < 0.35 ? y + 0.7e-3 : 0.05;
  }
  state.counters["build_s"] = build;
  state.counters["solves"] = table.build_solves();
  state.counters["pieces"] = table.pieces();
  state.counters["interpolation_error"] = table.interpolation_error();
}
BENCHMARK(TernaryTransportTableEvaluate)->Arg(1)->Arg(2)->Unit(benchmark::kNanosecond);

/// 10⁴-point α sweep (α from 0.5 to 1) of all smooth-inelastic coefficients at order 4 through
/// the model interface (nonlinear HCS a2…a5 and η*, κ*, μ* with error estimates), matrices reused;
/// second argument 0 = standard, 1 = modified Sonine scheme.
void SmoothInelasticSweepOrder4(benchmark::State& state) {
  const std::vector<std::string> all{
      "a2", "a3", "cooling_rate", "shear_viscosity", "thermal_conductivity", "density_heat_coefficient"};
  auto model = gkt::make_transport_model("smooth-inelastic");
  gkt::OrderRequest request;
  request.order = 4;
  const std::map<std::string, std::string> scheme{{"scheme", state.range(1) == 1 ? "modified" : "standard"}};
  (void)model->evaluate({{{"alpha", Rational(1, 2)}}, scheme}, all, request);  // build the matrices once
  const long points = state.range(0);
  for (auto _ : state)
    for (long k = 0; k < points; ++k)
      benchmark::DoNotOptimize(model->evaluate(
          {{{"alpha", Rational(1, 2) + Rational(k, static_cast<unsigned long>(2 * points))}}, scheme}, all, request));
  state.counters["points"] = static_cast<double>(points);
}
BENCHMARK(SmoothInelasticSweepOrder4)->Args({1000, 0})->Args({1000, 1})->Unit(benchmark::kMillisecond);

/// Warm time for all smooth-inelastic coefficients at order N and α ∈ {0.9, 0.5, 0.2} (matrices
/// already built; every call solves the HCS and the Navier–Stokes systems anew for a new α); third
/// argument 0 = standard, 1 = modified scheme.
void SmoothInelasticOrderWarm(benchmark::State& state) {
  const Rational alphas[] = {Rational(9, 10), Rational(1, 2), Rational(1, 5)};
  const Rational alpha = alphas[state.range(0)];
  const int order = static_cast<int>(state.range(1));
  const std::vector<std::string> all{"a2", "cooling_rate", "shear_viscosity", "thermal_conductivity",
                                     "density_heat_coefficient"};
  auto model = gkt::make_transport_model("smooth-inelastic");
  gkt::OrderRequest request;
  request.order = order;
  const std::map<std::string, std::string> scheme{{"scheme", state.range(2) == 1 ? "modified" : "standard"}};
  (void)model->evaluate({{{"alpha", Rational(1, 3)}}, scheme}, all, request);  // build
  long k = 0;
  for (auto _ : state)  // perturb α in the 12th digit so nothing is memoised
    benchmark::DoNotOptimize(
        model->evaluate({{{"alpha", alpha - Rational(++k % 1000, 1000000000000UL)}}, scheme}, all, request));
}
BENCHMARK(SmoothInelasticOrderWarm)
    ->ArgsProduct({{0, 1, 2}, {1, 2, 4, 6, 8}, {0}})
    ->ArgsProduct({{0, 1, 2}, {1, 4}, {1}})
    ->Unit(benchmark::kMicrosecond);

/// Warm time for all coefficients of the dense gas (φ = 0.3, Carnahan–Starling, standard scheme)
/// at order N and α ∈ {0.9, 0.5, 0.2}, matrices and collisional-transfer tables already built.
void EnskogOrderWarm(benchmark::State& state) {
  const Rational alphas[] = {Rational(9, 10), Rational(1, 2), Rational(1, 5)};
  const Rational alpha = alphas[state.range(0)];
  const int order = static_cast<int>(state.range(1));
  const std::vector<std::string> all{"pressure",       "cooling_rate",         "shear_viscosity",
                                     "bulk_viscosity", "thermal_conductivity", "density_heat_coefficient"};
  auto model = gkt::make_transport_model("smooth-inelastic");
  gkt::OrderRequest request;
  request.order = order;
  (void)model->evaluate({{{"alpha", Rational(1, 3)}, {"packing_fraction", Rational(3, 10)}}, {}}, all, request);
  long k = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(model->evaluate(
        {{{"alpha", alpha - Rational(++k % 1000, 1000000000000UL)}, {"packing_fraction", Rational(3, 10)}}, {}}, all,
        request));
}
BENCHMARK(EnskogOrderWarm)->ArgsProduct({{0, 1, 2}, {1, 2, 4, 6}})->Unit(benchmark::kMicrosecond);

/// Cold: a new model per iteration at order N, α = 0.9 (one-time symbolic builds included).
void SmoothInelasticOrderCold(benchmark::State& state) {
  const int order = static_cast<int>(state.range(0));
  gkt::OrderRequest request;
  request.order = order;
  for (auto _ : state) {
    auto model = gkt::make_transport_model("smooth-inelastic");
    benchmark::DoNotOptimize(model->evaluate(
        {{{"alpha", Rational(9, 10)}}, {}},
        {"a2", "cooling_rate", "shear_viscosity", "thermal_conductivity", "density_heat_coefficient"}, request));
  }
}
BENCHMARK(SmoothInelasticOrderCold)->Arg(1)->Arg(2)->Arg(4)->Arg(6)->Arg(8)->Unit(benchmark::kMillisecond);

/// Free cooling to τ = 10⁶ initial mean free times at rtol = 1e-8 from a Maxwellian, cumulants
/// a2…a4: viscoelastic (δ = 0.1, state-dependent hierarchy) and constant α = 0.8; the hierarchy
/// is built once outside the loop. Counters: CVODE steps.
void CoolingViscoelastic(benchmark::State& state) {
  const gkt::ViscoelasticHierarchy h(4);
  long steps = 0;
  for (auto _ : state) {
    const auto r = gkt::evolve_viscoelastic_cooling(h, 0.1, {0.0}, {1e6}, 1e-8, 1e-14);
    steps = r.counters.steps;
    benchmark::DoNotOptimize(r);
  }
  state.counters["steps"] = static_cast<double>(steps);
}
BENCHMARK(CoolingViscoelastic)->Unit(benchmark::kMillisecond);

/// The δ'-series of a2, ζ*, η*, κ*, μ* of viscoelastic spheres to δ'³ at Sonine order N (cold: the
/// exact operator series, the hierarchy and the solves; theory.md §13.2).
void ViscoelasticTransportSeries(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const gkt::ViscoelasticRestitution restitution;  // the contact-equation fit, once per process
  for (auto _ : state) benchmark::DoNotOptimize(gkt::viscoelastic_transport_series(n, restitution));
}
BENCHMARK(ViscoelasticTransportSeries)->Arg(1)->Arg(2)->Arg(4)->Arg(6)->Unit(benchmark::kMillisecond);

void CoolingConstantAlpha(benchmark::State& state) {
  gkt::HomogeneousCoolingState hcs(3);
  const auto h = hcs.hierarchy(Rational(4, 5), 4);
  long steps = 0;
  for (auto _ : state) {
    const auto r = gkt::evolve_homogeneous_cooling(h, 1.0, {0.0}, {1e6}, 1e-8, 1e-14);
    steps = r.counters.steps;
    benchmark::DoNotOptimize(r);
  }
  state.counters["steps"] = static_cast<double>(steps);
}
BENCHMARK(CoolingConstantAlpha)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
