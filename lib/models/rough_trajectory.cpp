// What `gkt evolve` asks the "rough" model for: the free cooling of rough spheres or disks from
// Maxwellians at T_t(0), T_r(0), in the Maxwellian or the linear first-Sonine scheme, the latter for spheres
// optionally with the orientation term b00 P (hcs = "linear-oriented"), or the linear scheme at Sonine order 2–3
// or the nonlinear one at orders 1–3 (hcs = "nonlinear", "nonlinear-oriented") with every a_pq (and b_pq) (`order`,
// (19.25b), §19.24) (rough_cooling_evolution.hpp; docs/theory.md §19.13, conventions.md), and of the Walton gas in the
// Maxwellian approximation.
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "gkt/evolution/rough_cooling_evolution.hpp"
#include "gkt/evolution/rough_walton_evolution.hpp"
#include "gkt/transport/rough/rough_oriented_cooling_rates.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_rates.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_state.hpp"
#include "gkt/transport/rough/rough_walton.hpp"
#include "gkt/transport/rough/rough_walton_cumulants.hpp"
#include "models/models.hpp"

namespace gkt::detail {

namespace {

/// Returns the rows of a rough trajectory: temperatures, θ, ζ*, (linear scheme) the cumulants and (`oriented`) b00
/// and the orientation correlation C.
Trajectory tabulate_rough_trajectory(const RoughEvolutionResult& result, bool linear, bool oriented = false);

/// Returns "<letter><p><q>" (single digits at these orders).
std::string indexed_column(char letter, const std::array<int, 2>& pq) {
  return std::string(1, letter) + static_cast<char>('0' + pq[0]) + static_cast<char>('0' + pq[1]);
}

/// Returns the trajectory of the Sonine scheme at order N (theory.md §19.13, (19.25b)–(19.25c), §19.24): hcs =
/// "linear" (N > 1) or "nonlinear" the isotropic ansatz (a_pq), "linear-oriented" (N > 1) or "nonlinear-oriented"
/// (spheres) with the b_pq; columns as the order-1 ones, then the higher a_pq (by p + q, then q), then b00 … and
/// orientation_correlation (oriented); spin cumulants nan at β = −1.
Trajectory rough_sonine_trajectory(const SchemaPoint& p, int d, const Rational& alpha, const Rational& beta,
                                   const Rational& kappa, const std::string& scheme, int order,
                                   const RoughCumulants& initial, const std::vector<double>& times) {
  const bool nonlinear = scheme == "nonlinear" || scheme == "nonlinear-oriented";
  if (!nonlinear && scheme != "linear" && scheme != "linear-oriented")
    throw std::invalid_argument("order: must be 1 with hcs = \"" + scheme + "\" (orders 1-3 need hcs = \"linear\", " +
                                "\"linear-oriented\", \"nonlinear\" or \"nonlinear-oriented\"), got " +
                                std::to_string(order));
  const bool oriented = scheme == "linear-oriented" || scheme == "nonlinear-oriented";
  if (oriented && d != 3)
    throw std::invalid_argument("hcs: \"" + scheme + "\" needs dimension = 3 (disks have c.w = 0)");
  if (oriented && beta == Rational(-1))
    throw std::invalid_argument("hcs: \"" + scheme + "\" needs beta > -1 (at -1 the spin decouples)");
  check_rough_initial_cumulants(d, initial);
  const RoughSonineAnsatz ansatz = oriented ? RoughSonineAnsatz::oriented : RoughSonineAnsatz::isotropic;
  const RoughSonineScheme sonine_scheme = nonlinear ? RoughSonineScheme::nonlinear : RoughSonineScheme::linear;
  // A steady state to relax to: the HCS of this order and scheme (theory.md §19.14).
  if (!rough_sonine_cooling_state(d, alpha, beta, kappa, order, sonine_scheme, ansatz).solved)
    throw std::invalid_argument("hcs: the " + std::string(oriented ? "oriented " : "") +
                                (nonlinear ? "nonlinear" : "linear") + " scheme has no root at order " +
                                std::to_string(order) + ", dimension = " + std::to_string(d) +
                                ", alpha = " + alpha.to_decimal_string() + ", beta = " + beta.to_decimal_string() +
                                " (theory.md §19.14); use a lower order");
  const RoughSonineCoolingRates rates(d, alpha, beta, kappa, order, ansatz, sonine_scheme);
  const RoughEvolutionResult result = evolve_rough_sonine_cooling(
      rates, p.number("translational_temperature").to_double(), p.number("rotational_temperature").to_double(), times,
      p.number("rtol").to_double(), p.number("atol").to_double(), initial,
      static_cast<long>(p.number("max_steps").to_double()));
  Trajectory out = tabulate_rough_trajectory(result, true, oriented);
  const auto& ia = rates.cumulant_indices();
  const auto& ib = rates.orientation_indices();
  const std::size_t base = out.columns.size() - (oriented ? 2 : 0);  // after a11
  std::vector<std::string> extra;
  std::vector<std::size_t> extra_a;
  for (std::size_t w = 0; w < ia.size(); ++w)
    if (ia[w][0] + ia[w][1] > 2) extra.push_back(indexed_column('a', ia[w])), extra_a.push_back(w);
  for (std::size_t o = 1; o < ib.size(); ++o) extra.push_back(indexed_column('b', ib[o]));  // b00 is there
  // Columns: …, a11, the higher a_pq, [b00, the higher b_pq, orientation_correlation].
  std::vector<std::string> columns(out.columns.begin(), out.columns.begin() + static_cast<std::ptrdiff_t>(base));
  columns.insert(columns.end(), extra.begin(), extra.begin() + static_cast<std::ptrdiff_t>(extra_a.size()));
  if (oriented) {
    columns.emplace_back("b00");
    columns.insert(columns.end(), extra.begin() + static_cast<std::ptrdiff_t>(extra_a.size()), extra.end());
    columns.emplace_back("orientation_correlation");
  }
  const double nan = std::nan("");
  const bool decoupled = rates.spin_decoupled();
  for (std::size_t r = 0; r < out.rows.size(); ++r) {
    const RoughEvolutionSample& s = result.samples[r];
    std::vector<double> row(out.rows[r].begin(), out.rows[r].begin() + static_cast<std::ptrdiff_t>(base));
    if (decoupled) row[base - 2] = row[base - 1] = nan;  // a02, a11: no spin cumulant at β = −1
    for (const std::size_t w : extra_a) row.push_back(s.cumulants[w]);
    if (oriented) {
      row.insert(row.end(), s.orientation_coefficients.begin(), s.orientation_coefficients.end());
      row.push_back(s.orientation_correlation);
    }
    out.rows[r] = std::move(row);
  }
  out.columns = std::move(columns);
  return out;
}

}  // namespace

std::vector<ParameterSpec> rough_evolution_parameters(const std::vector<ParameterSpec>& model_parameters,
                                                      const std::vector<std::string>& names) {
  std::vector<ParameterSpec> specs;
  for (const auto& name : names) specs.push_back(find_parameter(model_parameters, name));
  auto positive = [](const char* name, const Rational& fallback, const char* description) {
    return ParameterSpec{
        name, ParameterSpec::Kind::real, Rational(0), ParameterSpec::unbounded(), false, true, fallback, description,
        {}};
  };
  specs.push_back(positive("translational_temperature", Rational(1),
                           "initial translational temperature T_t(0)/T_ref (T_ref sets the time unit)"));
  specs.push_back(positive("rotational_temperature", Rational(1), "initial rotational temperature T_r(0)/T_ref"));
  for (auto& spec : evolution_common_parameters())
    if (spec.name == "rtol" || spec.name == "atol") specs.push_back(std::move(spec));
  return specs;
}

std::vector<ParameterSpec> rough_initial_cumulant_parameters() {
  auto cumulant = [](const char* name, const Rational& min, const char* description) {
    return ParameterSpec{
        name, ParameterSpec::Kind::real, min, ParameterSpec::unbounded(), true, true, Rational(0), description, {}};
  };
  // Var c² >= 0: a20 >= -2/(d+2) (-1/2 for disks); Var w² >= 0: a02 >= -2/(d_r+2) (-2/3 for disks).
  return {cumulant("a20", Rational(-1, 2),
                   "initial a20(0), not with hcs = \"maxwellian\": >= -2/(d+2) (Var c^2 >= 0, theory.md (19.24a))"),
          cumulant("a02", Rational(-2, 3),
                   "initial a02(0), not with hcs = \"maxwellian\": >= -2/(d_r+2) (Var w^2 >= 0, theory.md (19.24a))"),
          cumulant("a11", -ParameterSpec::unbounded(),
                   "initial a11(0), not with hcs = \"maxwellian\": d d_r a11^2 <= (2 + (d+2) a20)(2 + (d_r+2) a02) "
                   "(Cauchy-Schwarz, theory.md (19.24a))")};
}

/// Highest Sonine order of the trajectory: the HCS columns' (kMaxRoughHcsOrder of rough_model.cpp).
constexpr int kMaxRoughEvolveOrder = 3;

ParameterSpec rough_evolution_order_parameter() {
  return {"order",
          ParameterSpec::Kind::integer,
          Rational(1),
          Rational(kMaxRoughEvolveOrder),
          true,
          true,
          Rational(1),
          "Sonine order N of the trajectory, hcs = \"linear\", \"linear-oriented\", \"nonlinear\" or "
          "\"nonlinear-oriented\": the cumulants a_pq with p + q <= N + 1 (and, oriented, b_pq with p + q <= N - 1) of "
          "the linear or nonlinear scheme (theory.md (19.25b), §19.24); 1 with the other hcs",
          {}};
}

ParameterSpec rough_evolution_max_steps_parameter() {
  // The other models' budget key, with the rough default and what its Sonine schemes add to the message.
  ParameterSpec spec = evolution_max_steps_parameter();
  spec.default_value = Rational(kRoughSonineMaxSteps);
  spec.description =
      "CVODE step budget over the whole trajectory, every hcs; past it exit 2, the Sonine schemes (order > 1 or "
      "hcs = \"nonlinear\", \"nonlinear-oriented\") naming the stall (theory.md §19.24)";
  return spec;
}

Trajectory rough_trajectory(const std::vector<ParameterSpec>& schema, const TrajectoryRequest& request) {
  const SchemaPoint p(schema, request.parameters);
  const int d = p.number("dimension") == Rational(2) ? 2 : 3;
  const Rational alpha = p.number("alpha"), beta = p.number("beta"), kappa = p.number("moment_of_inertia");
  const std::string scheme = p.choice("hcs");
  const RoughCumulants initial{p.number("a20").to_double(), p.number("a02").to_double(), p.number("a11").to_double()};
  const int order = static_cast<int>(p.number("order").to_double());
  if (order > 1 || scheme == "nonlinear" || scheme == "nonlinear-oriented")
    return rough_sonine_trajectory(p, d, alpha, beta, kappa, scheme, order, initial, request.times);
  if (scheme == "linear-oriented") {
    // The linear scheme with the orientation term b00 P (theory.md §19.13, (19.26a) at order 1): spheres, and a
    // steady state to relax to.
    if (d != 3) throw std::invalid_argument("hcs: \"linear-oriented\" needs dimension = 3 (disks have c.w = 0)");
    if (beta == Rational(-1))
      throw std::invalid_argument("hcs: \"linear-oriented\" needs beta > -1 (at -1 the spin decouples)");
    check_rough_initial_cumulants(d, initial);
    if (!rough_sonine_cooling_state(d, alpha, beta, kappa, 1, RoughSonineScheme::linear, RoughSonineAnsatz::oriented)
             .solved)
      throw std::invalid_argument(
          "hcs: the oriented linear scheme has no root at dimension = 3, alpha = " + alpha.to_string() +
          ", beta = " + beta.to_string() + " (theory.md §19.14); use hcs = \"maxwellian\"");
    const RoughCoolingRates rates(d, alpha, beta, kappa);
    const RoughOrientedCoolingRates oriented(alpha, beta, kappa);
    const RoughEvolutionResult result = evolve_rough_oriented_cooling(
        rates, oriented, p.number("translational_temperature").to_double(),
        p.number("rotational_temperature").to_double(), request.times, p.number("rtol").to_double(),
        p.number("atol").to_double(), initial, static_cast<long>(p.number("max_steps").to_double()));
    return tabulate_rough_trajectory(result, true, true);
  }
  // "linear-or-maxwellian": the linear scheme where it has a root, else the Maxwellian one.
  const bool linear =
      scheme == "linear" ||
      (scheme == "linear-or-maxwellian" &&
       rough_homogeneous_cooling_state(d, alpha, beta, kappa, RoughHcsScheme::linear).linear_scheme_solved);
  if (scheme == "linear") (void)linear_rough_state(d, alpha, beta, kappa);  // refuses the no-root region
  check_rough_initial_cumulants(d, initial);                                // before the tables are built
  if (!linear && initial != RoughCumulants{})
    throw std::invalid_argument(
        "a20, a02, a11: initial cumulants need the linear scheme (hcs = \"linear\"" +
        std::string(scheme == "linear-or-maxwellian" ? ", which has no root at this state" : "") + "); got hcs = \"" +
        scheme + "\"");
  const RoughCoolingRates rates(d, alpha, beta, kappa);
  const RoughEvolutionResult result =
      evolve_rough_cooling(rates, linear, p.number("translational_temperature").to_double(),
                           p.number("rotational_temperature").to_double(), request.times, p.number("rtol").to_double(),
                           p.number("atol").to_double(), initial, static_cast<long>(p.number("max_steps").to_double()));
  return tabulate_rough_trajectory(result, linear);
}

Trajectory rough_walton_trajectory(const std::vector<ParameterSpec>& schema, const TrajectoryRequest& request) {
  const SchemaPoint p(schema, request.parameters);
  const int d = p.number("dimension") == Rational(2) ? 2 : 3;
  const double alpha = p.number("alpha").to_double(), beta0 = p.number("beta0").to_double();
  const double kappa = p.number("moment_of_inertia").to_double(), friction = p.number("friction").to_double();
  const std::string scheme = p.choice("hcs");
  const RoughCumulants initial{p.number("a20").to_double(), p.number("a02").to_double(), p.number("a11").to_double()};
  check_rough_initial_cumulants(d, initial);
  const double t0 = p.number("translational_temperature").to_double();
  const double r0 = p.number("rotational_temperature").to_double();
  // The first-Sonine balances (theory.md §19.19) where the linear HCS exists ("linear" refuses elsewhere).
  bool linear = scheme == "linear";
  if (scheme == "linear-or-maxwellian") {
    const RoughWaltonCumulantState s = rough_walton_linear_cooling_state(d, alpha, beta0, kappa, friction);
    linear = !s.spin_decoupled && s.linear_scheme_solved;
  }
  if (!linear && initial != RoughCumulants{})
    throw std::invalid_argument(
        "a20, a02, a11: initial cumulants need the linear scheme (hcs = \"linear\"" +
        std::string(scheme == "linear-or-maxwellian" ? ", which has no root at this state" : "") + "); got hcs = \"" +
        scheme + "\"");
  if (linear) {
    const RoughEvolutionResult result = evolve_rough_walton_cooling(
        d, alpha, beta0, kappa, friction, t0, r0, request.times, p.number("rtol").to_double(),
        p.number("atol").to_double(), initial, static_cast<long>(p.number("max_steps").to_double()));
    return tabulate_rough_trajectory(result, true);
  }
  // Maxwellian rates by quadrature (theory.md (19.21)), ζ/ν0 → z = ζ/(nσ^{d−1}v_t ν) = (4/(d+2)) ζ/ν0.
  const RoughMaxwellianRates rates = [=](double theta) {
    const RoughWaltonRates r = rough_walton_rates(d, alpha, beta0, kappa, friction, theta);
    return std::array<double, 2>{4.0 / (d + 2) * r.translational, 4.0 / (d + 2) * r.rotational};
  };
  const RoughEvolutionResult result = evolve_rough_maxwellian_cooling(
      d, rates, t0, r0, request.times, p.number("rtol").to_double(), p.number("atol").to_double(),
      static_cast<long>(p.number("max_steps").to_double()));
  return tabulate_rough_trajectory(result, false);
}

namespace {

Trajectory tabulate_rough_trajectory(const RoughEvolutionResult& result, bool linear, bool oriented) {
  Trajectory out;
  out.columns = {"time",
                 "collisions",
                 "translational_temperature",
                 "rotational_temperature",
                 "rotational_temperature_ratio",
                 "cooling_rate"};
  if (linear) out.columns.insert(out.columns.end(), {"a20", "a02", "a11"});
  if (oriented) out.columns.insert(out.columns.end(), {"b00", "orientation_correlation"});
  for (const auto& s : result.samples) {
    std::vector<double> row{s.time,
                            s.collisions,
                            s.translational_temperature,
                            s.rotational_temperature,
                            s.rotational_temperature / s.translational_temperature,
                            s.cooling_rate};
    if (linear) row.insert(row.end(), {s.a20, s.a02, s.a11});
    if (oriented) row.insert(row.end(), {s.b00, s.orientation_correlation});
    out.rows.push_back(std::move(row));
  }
  out.counters = result.counters;
  return out;
}

}  // namespace

}  // namespace gkt::detail
