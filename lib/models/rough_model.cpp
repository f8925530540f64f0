// The "rough" model: rough inelastic hard spheres (d = 3) or disks (d = 2) with constant normal
// and tangential restitution α, β and reduced moment of inertia κ = 4I/(mσ²). Provides the
// homogeneous cooling state in the Maxwellian or the linear first-Sonine approximation
// (rough_homogeneous_cooling_state.hpp; docs/theory.md §19): θ = T_r/T_t, ζ*, a20, a02, a11, and at
// Sonine orders up to 3 in the linear or nonlinear scheme with the cumulants a_pq
// (rough_sonine_cooling_state.hpp, §19.14; in 3D both schemes there carry the velocity–spin orientation
// terms b_pq — the nonlinear one beyond order 1 or with a tolerance — and the orientation correlation C at
// order N > 1 comes from that solution); and the
// shear viscosity at first Sonine (rough_shear_viscosity.hpp, §19.7) and the orientational
// correlation C (rough_orientation_correlation.hpp, §19.8); κ*, μ* (rough_thermal_conductivity.hpp) and
// the bulk viscosity and first-order cooling rate (rough_bulk_viscosity.hpp, §19.9), d = 2, 3; at order
// N > 1 (or with a tolerance) these five Navier–Stokes columns come from rough_sonine_transport.hpp (§19.16)
// with the error of theory.md (6.1) from orders N + 1, N + 2, about Maxwellians or (reference_state = "hcs") about
// the Sonine HCS with its cumulants (§19.16, (19.44)–(19.45); the error then adds the step from the next lower
// cumulant degree); the linear stability of the HCS from the
// first-Sonine coefficients (rough_hcs_stability.hpp, §19.15), or at order N about the Maxwellian HCS or
// (reference_state = "hcs") about the Sonine HCS, from its θ, ζ* and the coefficients about it (§19.15, (19.33)).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

#include "gkt/evolution/rough_hcs_stability.hpp"
#include "gkt/transport/rough/rough_bulk_viscosity.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_orientation_correlation.hpp"
#include "gkt/transport/rough/rough_shear_viscosity.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_state.hpp"
#include "gkt/transport/rough/rough_sonine_transport.hpp"
#include "gkt/transport/rough/rough_split_slopes.hpp"
#include "gkt/transport/rough/rough_thermal_conductivity.hpp"
#include "models/models.hpp"
#include "models/rough_mixture_columns.hpp"
#include "models/rough_parameters.hpp"

namespace gkt::detail {

namespace {

/// The coefficients of `gkt table` before the stability values were added (its default columns).
const std::vector<std::string> kRoughTableColumns{"rotational_temperature_ratio",
                                                  "cooling_rate",
                                                  "a20",
                                                  "a02",
                                                  "a11",
                                                  "shear_viscosity",
                                                  "bulk_viscosity",
                                                  "thermal_conductivity",
                                                  "density_heat_coefficient",
                                                  "cooling_rate_first_order",
                                                  "orientation_correlation"};

/// Returns the HCS stability of the constant-β gas from its first-Sonine coefficients at the Maxwellian
/// θ, ζ* (the state they are computed about, whatever `hcs`; theory.md §19.15). At β = −1 the spin
/// decouples: the smooth gas's translational equations with the translational κ*, μ*.
HcsStability rough_stability(int d, const Rational& alpha, const Rational& beta, const Rational& kappa,
                             bool rotational_field = false) {
  const RoughCoolingState m = rough_homogeneous_cooling_state(d, alpha, beta, kappa, RoughHcsScheme::maxwellian);
  const RoughThermalConductivity q = rough_thermal_conductivity(d, alpha, beta, kappa);
  const RoughScalarResponse b = rough_bulk_viscosity(d, alpha, beta, kappa);
  const bool decoupled = std::isinf(m.temperature_ratio);
  RoughStabilityInput in;
  in.dimension = d;
  in.temperature_ratio = m.temperature_ratio;
  // α = 1, β = ±1 loses no energy ((19.3)): ζ* = 0 exactly, where the solver's double may leave 1e-17.
  const bool conservative = alpha == Rational(1) && (beta == Rational(1) || beta == Rational(-1));
  in.cooling_rate = conservative ? 0.0 : m.cooling_rate;
  in.shear_viscosity = rough_shear_viscosity(d, alpha, beta, kappa);
  in.bulk_viscosity = b.bulk_viscosity;  // NaN at β = −1: not used there
  in.thermal_conductivity = decoupled ? q.translational : q.total;
  in.density_heat_coefficient = decoupled ? q.density_heat_translational : q.density_heat_total;
  in.cooling_rate_first_order = b.cooling_rate_first_order;
  in.relaxation_rate = b.relaxation_rate;  // Γ* of (19.17), NaN at β = −1: not used there
  // rotational_temperature_closure = "field": T_r as a fourth field (theory.md §19.15.1, (19.36)).
  return rotational_field ? rough_hcs_stability_with_spin(in) : rough_hcs_stability(in);
}

/// Returns the HCS stability of the constant-β gas about a reference state with temperature ratio θ and cooling
/// rate ζ* and the Navier–Stokes values `v` computed about it (Sonine order N; theory.md §19.15, (19.33)); NaN values
/// where the state or the coefficients do not exist or η*, κ* − μ* make (19.31) meaningless (η* ≤ 0 or κ* ≤ 0 at a
/// diverging order). At β = −1 (θ = +∞) the translational κ*, μ*.
HcsStability rough_reference_stability(int d, const Rational& alpha, const Rational& beta, double theta, double zeta,
                                       const RoughTransportValues& v,
                                       const std::optional<RoughSplitSlopes>& split = std::nullopt) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const bool decoupled = std::isinf(theta);
  RoughStabilityInput in;
  in.dimension = d;
  in.temperature_ratio = theta;
  const bool conservative = alpha == Rational(1) && (beta == Rational(1) || beta == Rational(-1));
  in.cooling_rate = conservative ? 0.0 : zeta;  // ζ* = 0 exactly where no energy is lost ((19.3))
  in.shear_viscosity = v.shear_viscosity;
  in.bulk_viscosity = v.bulk_viscosity;
  in.thermal_conductivity = decoupled ? v.thermal_conductivity_translational : v.thermal_conductivity;
  in.density_heat_coefficient = decoupled ? v.density_heat_translational : v.density_heat_coefficient;
  in.cooling_rate_first_order = v.cooling_rate_first_order;
  if (!(theta > 0) || !std::isfinite(zeta) || !(in.shear_viscosity > 0) || !std::isfinite(in.shear_viscosity) ||
      !(in.thermal_conductivity > 0) || !std::isfinite(in.thermal_conductivity) ||
      !std::isfinite(in.density_heat_coefficient))
    return HcsStability{nan, nan, nan};
  if (!split) return rough_hcs_stability(in);
  // rotational_temperature_closure = "field" (theory.md §19.15.1, §19.27): Γ*, Z_δ of the reference's rates.
  if (decoupled) return rough_hcs_stability_with_spin(in);
  if (!std::isfinite(split->relaxation_rate) || !std::isfinite(split->cooling_split_slope))
    return HcsStability{nan, nan, nan};
  in.relaxation_rate = split->relaxation_rate;
  in.cooling_split_slope = split->cooling_split_slope;
  return rough_hcs_stability_with_spin(in);
}

/// Returns the stability value `name` of `s` as a double (critical_length +∞ for a stable HCS).
double pick_stability(const HcsStability& s, const std::string& name) {
  return name == "critical_wavenumber_shear"  ? s.shear_wavenumber
         : name == "critical_wavenumber_heat" ? s.heat_wavenumber
                                              : s.critical_length;
}

/// Highest Sonine order of the rough HCS (cumulants a_pq, p + q ≤ N + 1); its error needs order N + 1
/// (~2 s cold at N = 3, ~20 s at N = 4; docs/performance.md).
constexpr int kMaxRoughHcsOrder = 3;

/// Returns "a<p><q>" (both single digits at these orders).
std::string cumulant_column(int p, int q) {
  std::string name(3, 'a');
  name[1] = static_cast<char>('0' + p);
  name[2] = static_cast<char>('0' + q);
  return name;
}

/// Returns (p, q) of a cumulant column a<p><q> with 2 ≤ p + q ≤ kMaxRoughHcsOrder + 1, or none.
std::optional<std::array<int, 2>> cumulant_of(const std::string& name) {
  if (name.size() != 3 || name[0] != 'a' || name[1] < '0' || name[1] > '9' || name[2] < '0' || name[2] > '9')
    return std::nullopt;
  const int p = name[1] - '0', q = name[2] - '0';
  if (p + q < 2 || p + q > kMaxRoughHcsOrder + 1) return std::nullopt;
  return std::array<int, 2>{p, q};
}

/// Returns (p, q) of an orientation column b<p><q> with p + q ≤ kMaxRoughHcsOrder − 1 (theory.md (19.26a)), or none.
std::optional<std::array<int, 2>> orientation_of(const std::string& name) {
  if (name.size() != 3 || name[0] != 'b' || name[1] < '0' || name[1] > '9' || name[2] < '0' || name[2] > '9')
    return std::nullopt;
  const int p = name[1] - '0', q = name[2] - '0';
  if (p + q > kMaxRoughHcsOrder - 1) return std::nullopt;
  return std::array<int, 2>{p, q};
}

/// Returns true for the columns of the velocity–spin orientation: C and the b_pq (3D only; theory.md §19.8, §19.14).
bool is_orientation_column(const std::string& name) {
  return name == "orientation_correlation" || orientation_of(name).has_value();
}

/// Returns the HCS columns that take a Sonine order (θ, ζ*, every a_pq).
bool is_hcs_column(const std::string& name) {
  return name == "rotational_temperature_ratio" || name == "cooling_rate" || cumulant_of(name).has_value();
}

// The Navier–Stokes columns at order N need the tables to N + 2 for their error estimate: K = 10 at the cap
// costs ~5 s per (α, β, κ) in 3D (docs/performance.md).
constexpr int kMaxRoughOrder = 8;

// trial_space = "full" ties its family members to the order (M = ⌈N/2⌉, theory.md (19.155)): its tables to N + 2 = 6
// (M = 3) cost 1-4 s of CPU per (α, β, κ) in 3D alone and 12-17 s on the loaded machine, M = 4 ten times more
// (docs/performance.md): orders 1 … 4.
constexpr int kMaxRoughFullOrder = 4;

// About the Sonine HCS (reference_state = "hcs", theory.md §19.16) the weighted tables of seven (oriented: eight)
// engine forms cost 1.6–9 s of CPU at K = 6 (cumulant degree 2–4, 3D; docs/performance.md), 7 s and more at K = 8:
// orders 1 … 4 (K = N + 2 ≤ 6) and cumulants p + q ≤ 4.
constexpr int kMaxRoughReferenceOrder = 4;
constexpr int kMaxRoughReferenceDegree = kMaxRoughHcsOrder + 1;

/// The tables of one (d, α, β, κ) and the values of every order solved so far.
struct RoughSonineEntry {
  std::unique_ptr<RoughSonineTransport> transport;
  std::map<int, RoughTransportValues> values;
};

class RoughModel final : public TransportModel {
 public:
  [[nodiscard]] std::string name() const override { return "rough"; }
  [[nodiscard]] std::string description() const override {
    return "rough inelastic hard spheres (d = 3) or disks (d = 2), constant normal and tangential restitution "
           "alpha, beta and reduced moment of inertia: homogeneous cooling state (temperature ratio, cooling "
           "rate, cumulants a20, a02, a11 and a_pq to p + q = 4), Maxwellian or Sonine orders 1-3 (linear or "
           "nonlinear); shear and bulk viscosity, thermal conductivity, density heat coefficient, first-order "
           "cooling rate at first Sonine or Sonine order up to 8 (translation x spin Sonine products, Maxwellian "
           "reference; with reference_state = hcs about the Sonine HCS and its cumulants, order up to 4); "
           "translation-rotation "
           "correlation (3D; first approximation at order 1, from the oriented Sonine HCS at orders 2-3); "
           "linear stability of the homogeneous cooling state (first Sonine about the Maxwellian HCS, or at order up "
           "to 8, or 4 about the Sonine HCS with reference_state = hcs); a binary mixture (species = 2, two "
           "[[species]] "
           "tables): Maxwellian HCS T_t,i/T, T_r,i/T_t,i and the cooling rate";
  }
  [[nodiscard]] std::vector<std::string> coefficient_names() const override {
    auto names = kRoughTableColumns;
    // The higher cumulants of the Sonine HCS (theory.md §19.14), by total degree p + q.
    for (int n = 3; n <= kMaxRoughHcsOrder + 1; ++n)
      for (int q = 0; q <= n; ++q) names.push_back(cumulant_column(n - q, q));
    // The orientation coefficients b_pq of the oriented Sonine HCS (3D, theory.md (19.26a)).
    for (int n = 0; n <= kMaxRoughHcsOrder - 1; ++n)
      for (int q = 0; q <= n; ++q) {
        std::string b = cumulant_column(n - q, q);
        b[0] = 'b';
        names.push_back(b);
      }
    for (const auto& c : stability_coefficient_names()) names.push_back(c);
    for (const auto& c : rough_mixture_columns())  // cooling_rate is a column of both
      if (std::find(names.begin(), names.end(), c) == names.end()) names.push_back(c);
    for (const auto& c : rough_mixture_cumulant_columns()) names.push_back(c);
    return names;
  }
  /// A binary (species = 2, theory.md §19.17) has its HCS columns only (the cumulants a20_i, a02_i, a11_i of
  /// §19.30 included); one gas every other column.
  [[nodiscard]] std::vector<std::string> scene_coefficient_names(const ParameterPoint& fixed) const override {
    auto binary = rough_mixture_columns();
    for (const auto& c : rough_mixture_cumulant_columns()) binary.push_back(c);
    if (is_rough_mixture_point(fixed)) return binary;
    auto names = coefficient_names();
    std::erase_if(names, [&binary](const std::string& c) {
      return c != "cooling_rate" && std::find(binary.begin(), binary.end(), c) != binary.end();
    });
    return names;
  }
  /// Without `coefficients` a scene gets the columns it had before the stability values and the
  /// higher cumulants existed (a binary: its Maxwellian-HCS columns, and with hcs = "linear" or
  /// "linear-or-maxwellian" the cumulants too).
  [[nodiscard]] std::vector<std::string> default_coefficients(const ParameterPoint& fixed) const override {
    if (!is_rough_mixture_point(fixed)) return kRoughTableColumns;
    auto binary = rough_mixture_columns();
    const std::string scheme = fixed.choice("hcs", "maxwellian");
    if (scheme == "linear" || scheme == "linear-or-maxwellian")
      for (const auto& c : rough_mixture_cumulant_columns()) binary.push_back(c);
    return binary;
  }
  [[nodiscard]] std::vector<ParameterSpec> parameters() const override {
    auto specs = rough_grain_parameters("beta", "tangential restitution coefficient (-1 smooth, +1 perfectly rough)");
    specs.push_back(choice_spec("hcs",
                                "approximation of the homogeneous cooling state: Sonine with cumulants linear, "
                                "Maxwellian, first Sonine falling back to Maxwellian (cumulants nan) where the "
                                "linear scheme has no root, or Sonine with all products of cumulants (nonlinear); "
                                "order N keeps a_pq with p + q <= N + 1",
                                {"linear", "maxwellian", "linear-or-maxwellian", "nonlinear"}));
    specs.push_back(
        choice_spec("reference_state",
                    "f0 of the Navier-Stokes columns: Maxwellians at the Maxwellian theta (default), or the "
                    "Sonine HCS of `hcs` (linear or nonlinear; spheres: oriented, with its b_pq) with its theta, "
                    "cooling rate and cumulants a_pq, p + q <= hcs_order; the error adds the change from "
                    "hcs_order - 1 (2: from the Maxwellian reference)",
                    {"maxwellian", "hcs"}));
    specs.push_back(choice_spec("trial_space",
                                "trial functions of the Navier-Stokes columns at a Sonine order (order >= 2 or a "
                                "tolerance; about Maxwellians): the translation x spin Sonine products (default), "
                                "plus the aligned-spin families (spheres), or plus those and the chiral families "
                                "with their members tied to the order (theory.md 19.21, 19.22, 19.28)",
                                {"products", "aligned", "full"}));
    specs.push_back(choice_spec("rotational_temperature_closure",
                                "stability columns: T_rot slaved to T in the normal solution (Navier-Stokes, "
                                "default), or T_rot a fourth field relaxing at the reference's rate (Maxwellian; "
                                "with reference_state = hcs, hcs = linear: the cumulant rates' slopes, cumulants "
                                "held)",
                                {"slaved", "field"}));
    specs.push_back({"hcs_order",
                     ParameterSpec::Kind::integer,
                     Rational(2),
                     Rational(kMaxRoughReferenceDegree),
                     true,
                     true,
                     Rational(2),
                     "highest total degree p + q of the HCS cumulants a_pq carried into f0 (reference_state = hcs; "
                     "2: a20, a02, a11)",
                     {}});
    for (auto& spec : rough_mixture_parameters()) specs.push_back(std::move(spec));
    return specs;
  }
  /// The HCS columns take orders 1 … kMaxRoughHcsOrder, the Navier–Stokes columns and the stability values
  /// 1 … kMaxRoughOrder (1 … kMaxRoughReferenceOrder about the Sonine HCS); C beyond order 1 is the Sonine HCS's.
  [[nodiscard]] int max_order() const override { return kMaxRoughOrder; }
  [[nodiscard]] bool supports(Capability capability) const override {
    return capability == Capability::table || capability == Capability::evolve || capability == Capability::stability;
  }
  [[nodiscard]] std::vector<ParameterSpec> evolution_parameters() const override {
    auto specs = parameters();
    // The trajectory integrates the linear or nonlinear scheme's balances at Sonine order `order` (theory.md §19.13,
    // (19.25b), §19.24); for spheres either may carry the orientation terms b_pq P S_p S_q ("linear-oriented",
    // "nonlinear-oriented", §19.14).
    for (auto& spec : specs)
      if (spec.name == "hcs") {
        spec.choices = {"linear",          "maxwellian", "linear-or-maxwellian",
                        "linear-oriented", "nonlinear",  "nonlinear-oriented"};
        spec.description +=
            "; gkt evolve: linear-oriented = the linear scheme with the orientation term b00 "
            "((c.w)^2 - c^2 w^2/3), spheres only, columns b00 and orientation_correlation (with order N > 1 "
            "every b_pq, p + q <= N - 1); nonlinear-oriented the same with every product of cumulants kept";
      }
    specs = rough_evolution_parameters(specs, {"dimension", "alpha", "beta", "moment_of_inertia", "hcs"});
    for (auto& spec : rough_initial_cumulant_parameters()) specs.push_back(std::move(spec));
    specs.push_back(rough_evolution_order_parameter());
    specs.push_back(rough_evolution_max_steps_parameter());
    // A binary (two [[species]] tables): its keys and initial temperatures (theory.md §19.31).
    for (auto& spec : rough_mixture_parameters()) specs.push_back(std::move(spec));
    for (auto& spec : rough_mixture_evolution_parameters()) specs.push_back(std::move(spec));
    return specs;
  }
  /// T_t(τ), T_r(τ) and the cumulants (at Sonine order `order`) from T_t(0), T_r(0) (theory.md §19.13); a binary
  /// (species = 2): the four temperatures T_t,i(τ), T_r,i(τ), Maxwellian (theory.md §19.31).
  Trajectory evolve(const TrajectoryRequest& request) override {
    if (is_rough_mixture_point(request.parameters)) return rough_mixture_trajectory(evolution_parameters(), request);
    refuse_species_keys_for_one_gas(request.parameters);
    for (const auto& spec : rough_mixture_evolution_parameters())
      if (request.parameters.numbers.contains(spec.name))
        throw std::invalid_argument(spec.name + ": per-species keys need species = 2 (two [[species]] tables)");
    return rough_trajectory(evolution_parameters(), request);
  }
  /// The product trial space's Sonine error leaves out the aligned-spin and chiral families (theory.md §19.21,
  /// §19.22), which move η*, κ*, μ* by percents (3D α = 0.9, β = 0.5: η* +1.9 %, κ* +3.4 %, μ* +7.8 %): said once
  /// per table where a Navier–Stokes or stability column is asked at order ≥ 2 or to a tolerance in that space. The
  /// full space needs none: its family members follow the order (theory.md §19.28), so its _error covers them.
  /// Order 1 alone is the first approximation, whose error is not estimated (nan): nothing to qualify there.
  [[nodiscard]] std::vector<std::string> table_caveats(const std::map<std::string, std::string>& choices,
                                                       const std::vector<std::string>& coefficients, int highest_order,
                                                       bool tolerance) const override {
    const auto choice = [&choices](const std::string& key, const std::string& fallback) {
      const auto it = choices.find(key);
      return it == choices.end() ? fallback : it->second;
    };
    if (choice("trial_space", "products") != "products" || (highest_order < 2 && !tolerance)) return {};
    const auto& critical = stability_coefficient_names();
    std::string columns;
    for (const auto& c : coefficients)
      if (is_rough_sonine_column(c) || std::find(critical.begin(), critical.end(), c) != critical.end())
        columns += (columns.empty() ? "" : ", ") + c;
    if (columns.empty()) return {};
    const bool maxwellian = choice("reference_state", "maxwellian") == "maxwellian";
    return {"trial_space: the _error of " + columns +
            " covers the Sonine truncation in the product trial space only; " +
            (maxwellian ? std::string("trial_space = \"full\" adds the aligned and chiral families "
                                      "(theory.md 19.21-19.22, 19.28; their members follow the order, so its _error "
                                      "covers them)")
                        : std::string("it leaves out the aligned and chiral families (theory.md "
                                      "19.21-19.22; trial_space = \"full\", about Maxwellians only)")) +
            ", which move these coefficients by percents"};
  }

  std::vector<CoefficientValue> evaluate(const ParameterPoint& point, const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    const auto specs = parameters();
    // Two [[species]] tables: the Maxwellian HCS of the binary (theory.md §19.17).
    if (is_rough_mixture_point(point)) return rough_mixture_values(specs, point, coefficients, order);
    refuse_species_keys_for_one_gas(point);
    const auto [d, alpha, beta, kappa] = read_rough_grain(specs, point, "beta");
    const std::string scheme = SchemaPoint(specs, point).choice("hcs");
    // Order 1 asked for as such is the first approximation of §19.6–19.9 (error not estimated); order 1
    // chosen by a tolerance scan (row_tolerance set) carries its estimate like any other order. The HCS
    // columns take the Sonine HCS (theory.md §19.14) beyond it or with the nonlinear scheme, the five
    // Navier–Stokes columns the Sonine solver of §19.16; C at order 1 is §19.8's first approximation, beyond it
    // the oriented Sonine HCS's (§19.14, linear or nonlinear); the stability values at order N > 1 come from the
    // coefficients of order N about the Maxwellian HCS, or with reference_state = "hcs" about the Sonine HCS (§19.15).
    const bool first = order.order == 1 && !order.tolerance && !order.row_tolerance;
    const bool hcs_sonine = scheme == "nonlinear" || !first;
    // reference_state = "hcs": the five Navier–Stokes columns about the Sonine HCS of `hcs` (3D: oriented, both
    // schemes) with its cumulants a_pq, p + q ≤ hcs_order (theory.md §19.16), at every order including 1, with the
    // error (6.1) plus the step from cumulant degree hcs_order − 1.
    const bool cumulant_reference = SchemaPoint(specs, point).choice("reference_state") == "hcs";
    if (point.numbers.contains("hcs_order") && !cumulant_reference)
      throw std::invalid_argument(
          "hcs_order: needs reference_state = \"hcs\" (the cumulants carried into f0 of the Navier-Stokes columns)");
    if (cumulant_reference && scheme != "linear" && scheme != "nonlinear")
      throw std::invalid_argument(
          "reference_state: \"hcs\" needs hcs = \"linear\" or \"nonlinear\" (the Sonine HCS "
          "whose cumulants f0 carries), got hcs = \"" +
          scheme + "\"");
    const auto& critical = stability_coefficient_names();
    const auto is_critical = [&critical](const std::string& c) {
      return std::find(critical.begin(), critical.end(), c) != critical.end();
    };
    // trial_space (theory.md §19.21, §19.22): the Sonine solver's space about Maxwellians; order 1 alone is the
    // product space's first approximation, so the families need a Sonine order.
    const std::string space = SchemaPoint(specs, point).choice("trial_space");
    trial_space_ = space == "aligned" ? RoughTrialSpace::aligned
                   : space == "full"  ? RoughTrialSpace::full
                                      : RoughTrialSpace::product;
    // trial_space and reference_state = "hcs" shape only the Navier–Stokes and stability columns: a table without
    // them would ignore the key silently, so it is refused (docs/conventions.md).
    const bool shaped = std::any_of(coefficients.begin(), coefficients.end(), [&is_critical](const std::string& c) {
      return is_rough_sonine_column(c) || is_critical(c);
    });
    if (!shaped && (space != "products" || cumulant_reference))
      throw std::invalid_argument(
          std::string(space != "products" ? "trial_space: \"" + space + "\"" : "reference_state: \"hcs\"") +
          " applies to the Navier-Stokes columns (shear_viscosity, bulk_viscosity, thermal_conductivity, "
          "density_heat_coefficient, cooling_rate_first_order) and the stability columns; this table asks for "
          "neither: drop the key or ask for one of them");
    if (trial_space_ != RoughTrialSpace::product) {
      if (trial_space_ == RoughTrialSpace::aligned && d != 3)
        throw std::invalid_argument(
            "trial_space: \"aligned\" needs dimension = 3 (c.w vanishes for disks; \"full\" has their chiral "
            "families)");
      if (cumulant_reference)
        throw std::invalid_argument("trial_space: \"" + space +
                                    "\" is built about Maxwellians only (reference_state = \"maxwellian\")");
      // The stability values at order 1 come from the first approximations too (theory.md §19.15): refused alike.
      if (first && shaped)
        throw std::invalid_argument("trial_space: \"" + space +
                                    "\" needs a Sonine order (order >= 2 or a tolerance) for the Navier-Stokes and "
                                    "stability columns; order = 1 alone is the first approximation in the product "
                                    "space");
      if (trial_space_ == RoughTrialSpace::full && !order.tolerance && order.order > kMaxRoughFullOrder && shaped)
        throw std::invalid_argument("order: trial_space = \"full\" takes orders 1 to " +
                                    std::to_string(kMaxRoughFullOrder) +
                                    " for the Navier-Stokes and stability columns (its family members follow the "
                                    "order), got " +
                                    std::to_string(order.order));
    }
    // T_r as a fourth field (theory.md §19.15.1) needs Γ* and Z_δ of the reference's rates: the Maxwellian ones of
    // (19.17), (19.37), or about the Sonine HCS the slopes of the linear scheme's cumulant rates (§19.27), which the
    // nonlinear scheme's products would change.
    const bool rotational_field = SchemaPoint(specs, point).choice("rotational_temperature_closure") == "field";
    // The closure shapes the stability columns alone: a table without them would ignore it silently.
    if (rotational_field && std::none_of(coefficients.begin(), coefficients.end(), is_critical))
      throw std::invalid_argument(
          "rotational_temperature_closure: \"field\" applies to the stability columns (gkt stability: "
          "critical_wavenumber_shear, critical_wavenumber_heat, critical_length); this table asks for none: drop the "
          "key or ask for one "
          "of them");
    if (rotational_field && cumulant_reference && scheme != "linear" &&
        std::any_of(coefficients.begin(), coefficients.end(), is_critical))
      throw std::invalid_argument(
          "rotational_temperature_closure: \"field\" with reference_state = \"hcs\" needs hcs = \"linear\" (the "
          "slopes of the linear scheme's rates, theory.md section 19.27), got hcs = \"" +
          scheme + "\"");
    for (const auto& name : coefficients) {
      if (is_orientation_column(name)) {
        if (d != 3)
          throw std::invalid_argument("coefficients: " + name +
                                      " needs dimension = 3 (disks spin normal to the plane)");
        // Beyond the first approximation C and b_pq are the oriented Sonine HCS's (theory.md §19.14), linear or
        // nonlinear.
        if (!first && scheme != "linear" && scheme != "nonlinear")
          throw std::invalid_argument(
              "hcs: \"" + scheme + "\" is a first approximation: use order = 1, or hcs = \"linear\" or \"nonlinear\"");
        if (!first && !order.tolerance && order.order > kMaxRoughHcsOrder)
          throw std::invalid_argument("order: " + name + " of model rough takes orders 1 to " +
                                      std::to_string(kMaxRoughHcsOrder) + ", got " + std::to_string(order.order));
        continue;
      }
      if (is_hcs_column(name)) {
        if (hcs_sonine && (scheme == "maxwellian" || scheme == "linear-or-maxwellian"))
          throw std::invalid_argument(
              "hcs: \"" + scheme + "\" is a first approximation: use order = 1, or hcs = \"linear\" or \"nonlinear\"");
        if (!order.tolerance && order.order > kMaxRoughHcsOrder)
          throw std::invalid_argument("order: " + name + " of model rough takes orders 1 to " +
                                      std::to_string(kMaxRoughHcsOrder) + ", got " + std::to_string(order.order));
        continue;
      }
      if (cumulant_reference && (is_rough_sonine_column(name) || is_critical(name))) {
        if (!order.tolerance && order.order > kMaxRoughReferenceOrder)
          throw std::invalid_argument("order: " + name +
                                      " of model rough with reference_state = \"hcs\" takes orders 1 to " +
                                      std::to_string(kMaxRoughReferenceOrder) + ", got " + std::to_string(order.order));
        continue;
      }
      if (!first && !is_rough_sonine_column(name) && !is_critical(name))
        throw std::invalid_argument("coefficients: " + name +
                                    " of model rough is computed at order 1 only; use order = 1 without tolerance, "
                                    "or ask for the HCS columns or shear_viscosity, bulk_viscosity, "
                                    "thermal_conductivity, density_heat_coefficient, cooling_rate_first_order or the "
                                    "stability columns");
    }
    // The first-approximation state of the scheme, only for first-approximation HCS columns (the transport and
    // stability values use the Maxwellian state whatever `hcs`, §19.7, §19.15).
    RoughCoolingState s;
    const bool first_hcs = !hcs_sonine && std::any_of(coefficients.begin(), coefficients.end(), is_hcs_column);
    if (first_hcs) {
      if (scheme == "linear") {
        s = linear_rough_state(d, alpha, beta, kappa);  // refuses the no-root region (theory.md §19.6)
      } else if (scheme == "maxwellian") {
        s = rough_homogeneous_cooling_state(d, alpha, beta, kappa, RoughHcsScheme::maxwellian);
      } else {  // linear-or-maxwellian: the Maxwellian θ, ζ* and nan cumulants where the linear scheme has no root
        s = rough_homogeneous_cooling_state(d, alpha, beta, kappa, RoughHcsScheme::linear);
        if (!s.linear_scheme_solved) {
          s = rough_homogeneous_cooling_state(d, alpha, beta, kappa, RoughHcsScheme::maxwellian);
          s.a20 = s.a02 = s.a11 = std::nan("");
        }
      }
    }
    // 3D: the oriented ansatz (a_pq and b_pq, theory.md §19.14), except the nonlinear scheme at order 1 without a
    // tolerance, which keeps the isotropic ansatz it had before the oriented one existed; for disks the two are the
    // same (c·ŵ ≡ 0).
    const bool linear_sonine = scheme != "nonlinear";
    const bool oriented = d == 3 && (linear_sonine || !first);
    HcsSonineStates hcs_states(d, alpha, beta, kappa,
                               linear_sonine ? RoughSonineScheme::linear : RoughSonineScheme::nonlinear,
                               oriented ? RoughSonineAnsatz::oriented : RoughSonineAnsatz::isotropic);
    // The cumulant degree K of the reference: hcs_order, or with a tolerance and no hcs_order the smallest K at which
    // (i) the HCS of order K − 1 differs from the next (order K) by less than the tolerance in θ, ζ*, a20, a02, a11 and
    // (ii) the column's own error — Sonine (6.1) plus the reference step |v(K) − v(K − 1)| — is below it; if no K up
    // to the cap meets both, the K of (i) with the smallest error (none: the K of smallest HCS step), flagged not
    // converged (theory.md §19.16, "Cumulant reference").
    const int fixed_degree = static_cast<int>(SchemaPoint(specs, point).number("hcs_order").to_double());
    const std::optional<Rational> tolerance = order.tolerance ? order.tolerance : order.row_tolerance;
    const bool wants_reference =
        cumulant_reference && std::any_of(coefficients.begin(), coefficients.end(), [&](const std::string& c) {
          return is_rough_sonine_column(c) || is_critical(c);
        });
    const bool scan_degree = wants_reference && tolerance && !point.numbers.contains("hcs_order");
    std::array<bool, kMaxRoughReferenceDegree + 1> hcs_settled{};
    int closest_hcs_degree = 2;                      // the K of smallest HCS step, used when no K settles the HCS
    if (reference_.size() > 16) reference_.clear();  // bound memory in sweeps, between evaluations
    if (scan_degree) {
      double closest = std::numeric_limits<double>::infinity();
      for (int k = 2; k <= kMaxRoughReferenceDegree; ++k) {
        const double step = hcs_step(reference_hcs(d, alpha, beta, kappa, linear_sonine, k),
                                     reference_hcs(d, alpha, beta, kappa, linear_sonine, k + 1));
        if (step < closest) closest = step, closest_hcs_degree = k;
        hcs_settled[k] = step < tolerance->to_double();
      }
    }
    std::optional<HcsStability> stability;
    std::vector<CoefficientValue> out;
    for (const auto& name : coefficients) {
      if ((hcs_sonine && is_hcs_column(name)) || (!first && is_orientation_column(name))) {
        out.push_back(hcs_sonine_value(hcs_states, name, order));
        continue;
      }
      // theory.md §19.16 about the Sonine HCS; the stability values from its θ, ζ* and those coefficients (§19.15,
      // (19.33)), with the same error: (6.1) on the value itself plus the step from the next lower cumulant degree.
      if (cumulant_reference && (is_rough_sonine_column(name) || is_critical(name))) {
        const int tables = order.tolerance ? kMaxRoughReferenceOrder + 2 : order.order + 2;
        const auto at_degree = [&, d = d, alpha = alpha, beta = beta, kappa = kappa](int k) {
          return choose_order(order, kMaxRoughReferenceOrder, [&](int n) {
            return reference_value(d, alpha, beta, kappa, linear_sonine, name, k, n, tables, rotational_field);
          });
        };
        if (!scan_degree) {
          out.push_back(at_degree(fixed_degree));
          continue;
        }
        // Only the K whose HCS has settled are tried (each costs its weighted tables); none settled: the K of
        // smallest HCS step, flagged.
        std::optional<CoefficientValue> chosen, closest;
        for (int k = 2; k <= kMaxRoughReferenceDegree && !chosen; ++k) {
          if (!hcs_settled[k]) continue;
          const CoefficientValue v = at_degree(k);
          if (v.defined && v.converged && v.error < *tolerance) chosen = v;
          if (v.defined && (!closest || v.error < closest->error)) closest = v;
        }
        if (!chosen) {
          chosen = closest ? *closest : at_degree(closest_hcs_degree);
          chosen->converged = false;
        }
        out.push_back(*chosen);
        continue;
      }
      // About the Maxwellian HCS (theory.md §19.16; the stability values (19.33) from those coefficients, §19.15).
      // A fixed order: error (6.3) from orders N + 1, N + 2 (N + 3), tables to N + 2. A tolerance (and the row pass
      // at the order it chose): the tables to the cap + 2 at once and the window error (19.100)–(19.101) over every
      // order to the cap + 2, since these sequences may settle and then wander (theory.md §19.23).
      if (!first && (is_rough_sonine_column(name) || is_critical(name))) {
        const bool windowed = order.tolerance || order.row_tolerance;
        // The full space's members follow the order: its cap is lower (kMaxRoughFullOrder, the tables' cost).
        const int cap = trial_space_ == RoughTrialSpace::full ? kMaxRoughFullOrder : kMaxRoughOrder;
        const int tables = windowed ? cap + 2 : order.order + 2;
        out.push_back(choose_order(order, cap, [&, d = d, alpha = alpha, beta = beta, kappa = kappa](int n) {
          const auto at = [&](int m) {
            if (m > cap + 2) return std::numeric_limits<double>::quiet_NaN();  // past the tables' cap
            return is_critical(name)
                       ? reference_column(d, alpha, beta, kappa, true, name, 1, m, tables, rotational_field)
                       : rough_sonine_column(transport_values(d, alpha, beta, kappa, m, tables), name);
          };
          if (!windowed) return estimate_from_doubles_confirmed(at(n), at(n + 1), at(n + 2), [&] { return at(n + 3); });
          std::vector<double> window;
          for (int m = n; m <= cap + 2; ++m) window.push_back(at(m));
          return estimate_from_doubles_windowed(window);
        }));
        continue;
      }
      if (is_critical(name)) {
        if (!stability) stability = rough_stability(d, alpha, beta, kappa, rotational_field);  // theory.md §19.15
        out.push_back(rough_stability_value(*stability, name));
        continue;
      }
      double x = 0;
      if (name == "rotational_temperature_ratio") {
        x = s.temperature_ratio;
      } else if (name == "cooling_rate") {
        x = s.cooling_rate;
      } else if (name == "a20") {
        x = s.a20;
      } else if (name == "a02") {
        x = s.a02;
      } else if (name == "a11") {
        x = s.a11;
      } else if (cumulant_of(name)) {
        x = 0;  // first Sonine: the higher cumulants are truncated
      } else if (name == "orientation_correlation") {
        x = rough_orientation_correlation(alpha, beta, kappa).correlation;  // first approximation, theory.md §19.8
      } else if (const auto pq = orientation_of(name)) {
        // First approximation (19.14): b00 alone; the higher b_pq are truncated.
        x = *pq == std::array<int, 2>{0, 0} ? rough_orientation_correlation(alpha, beta, kappa).b : 0.0;
      } else if (name == "thermal_conductivity") {
        x = rough_thermal_conductivity(d, alpha, beta, kappa).total;  // theory.md §19.7; NaN at β = −1
      } else if (name == "density_heat_coefficient") {
        x = rough_thermal_conductivity(d, alpha, beta, kappa).density_heat_total;  // theory.md (19.16)
      } else if (name == "bulk_viscosity") {
        x = rough_bulk_viscosity(d, alpha, beta, kappa).bulk_viscosity;  // theory.md (19.18); NaN at β = −1
      } else if (name == "cooling_rate_first_order") {
        x = rough_bulk_viscosity(d, alpha, beta, kappa).cooling_rate_first_order;  // theory.md (19.19)
      } else if (name == "shear_viscosity") {
        // First Sonine with Maxwellian weights at the Maxwellian θ, whatever `hcs` (theory.md §19.7).
        x = rough_shear_viscosity(d, alpha, beta, kappa);
      } else {
        throw std::invalid_argument("coefficients: unknown coefficient '" + name +
                                    "' for model rough; valid: " + join(coefficient_names()));
      }
      // θ = inf at β = −1 (no spin cooling state), NaN where the linear scheme has no root.
      out.push_back(first_approximation(x));
    }
    return out;
  }

 private:
  /// The Sonine HCS states of one (d, α, β, κ) and scheme, solved on first use per order.
  class HcsSonineStates {
   public:
    HcsSonineStates(int d, Rational alpha, Rational beta, Rational kappa, RoughSonineScheme scheme,
                    RoughSonineAnsatz ansatz)
        : d_(d),
          alpha_(std::move(alpha)),
          beta_(std::move(beta)),
          kappa_(std::move(kappa)),
          scheme_(scheme),
          ansatz_(ansatz) {}
    const RoughSonineCoolingState& at(int n) {
      auto it = states_.find(n);
      if (it == states_.end())
        it = states_.emplace(n, rough_sonine_cooling_state(d_, alpha_, beta_, kappa_, n, scheme_, ansatz_)).first;
      return it->second;
    }

   private:
    int d_;
    Rational alpha_, beta_, kappa_;
    RoughSonineScheme scheme_;
    RoughSonineAnsatz ansatz_;
    std::map<int, RoughSonineCoolingState> states_;
  };

  /// Returns one HCS column at the requested order or tolerance: v_N with the error |v_{N+1} − v_N|
  /// (theory.md §19.14).
  static CoefficientValue hcs_sonine_value(HcsSonineStates& states, const std::string& name,
                                           const OrderRequest& order) {
    auto pick = [&name](const RoughSonineCoolingState& st) {
      if (name == "rotational_temperature_ratio") return st.temperature_ratio;
      if (name == "cooling_rate") return st.cooling_rate;
      if (name == "orientation_correlation") return st.orientation_correlation;
      if (const auto b = orientation_of(name)) return st.orientation_coefficient((*b)[0], (*b)[1]);
      const auto pq = *cumulant_of(name);
      return st.cumulant(pq[0], pq[1]);
    };
    return choose_order(order, kMaxRoughHcsOrder, [&](int n) {
      const double v = pick(states.at(n)), next = pick(states.at(n + 1));
      OrderValue value;
      value.exact = false;
      value.defined = std::isfinite(v);
      if (!value.defined) return value;
      value.estimate.value = Rational::from_double(v);
      value.estimate.converging = std::isfinite(next);
      value.estimate.error = value.estimate.converging ? Rational::from_double(std::abs(next - v)) : Rational(0);
      if (!value.estimate.converging) value.defined = false;  // no error estimate: nan, error inf
      return value;
    });
  }

  /// Returns the Navier–Stokes values of order n; the tables are built to order 3 first, then to `tables`
  /// (≥ n) if needed.
  RoughTransportValues transport_values(int d, const Rational& alpha, const Rational& beta, const Rational& kappa,
                                        int n, int tables) {
    if (sonine_.size() > 64) sonine_.clear();  // bound memory in long sweeps (never mid-evaluation)
    const std::string key = std::to_string(d) + "|" + alpha.to_string() + "|" + beta.to_string() + "|" +
                            kappa.to_string() + "|" + std::to_string(static_cast<int>(trial_space_));
    RoughSonineEntry& entry = sonine_[key];
    if (const auto it = entry.values.find(n); it != entry.values.end()) return it->second;
    if (!entry.transport || entry.transport->highest_order() < n) {
      const int k = n <= 3 ? 3 : std::max(n, tables);
      entry.transport =
          trial_space_ == RoughTrialSpace::product ? std::make_unique<RoughSonineTransport>(d, alpha, beta, kappa, k)
          : trial_space_ == RoughTrialSpace::full
              // the family members follow the order (theory.md (19.155)): the scan converges them too
              ? std::make_unique<RoughSonineTransport>(d, alpha, beta, kappa, k, trial_space_, kRoughMembersTiedToOrder)
              : std::make_unique<RoughSonineTransport>(d, alpha, beta, kappa, k, trial_space_);
    }
    return entry.values[n] = entry.transport->at_maxwellian_state(n);
  }

  /// Returns the ansatz of the reference HCS: oriented in 3D in both schemes (a_pq and b_pq, theory.md §19.14, the
  /// HCS columns' ansatz beyond the nonlinear order 1 kept isotropic for compatibility), isotropic for disks.
  static RoughSonineAnsatz reference_ansatz(int d) {
    return d == 3 ? RoughSonineAnsatz::oriented : RoughSonineAnsatz::isotropic;
  }

  /// Returns the largest change of θ, ζ*, a20, a02, a11 between two Sonine HCS orders (ζ*, a20 alone at β = −1;
  /// +inf where either has no solution).
  static double hcs_step(const RoughSonineCoolingState& a, const RoughSonineCoolingState& b) {
    std::vector<std::array<double, 2>> pairs{{a.cooling_rate, b.cooling_rate}, {a.cumulant(2, 0), b.cumulant(2, 0)}};
    if (!a.spin_decoupled)
      for (const auto& pq : {std::array<int, 2>{0, 2}, std::array<int, 2>{1, 1}})
        pairs.push_back({a.cumulant(pq[0], pq[1]), b.cumulant(pq[0], pq[1])});
    if (!a.spin_decoupled) pairs.push_back({a.temperature_ratio, b.temperature_ratio});
    double step = 0;
    for (const auto& [x, y] : pairs) {
      if (!std::isfinite(x) || !std::isfinite(y)) return std::numeric_limits<double>::infinity();
      step = std::max(step, std::abs(x - y));
    }
    return step;
  }

  /// The tables of one (d, α, β, κ, scheme) about the Sonine HCS: the HCS of every cumulant degree used, one set of
  /// weighted tables of the highest degree so far (they serve every lower degree) and the values solved so far.
  struct RoughReferenceEntry {
    std::map<int, RoughSonineCoolingState> hcs;  ///< by cumulant degree K (the HCS of order K − 1)
    std::unique_ptr<RoughSonineTransport> transport;
    bool oriented = false;                                      ///< the tables carry the orientation forms
    std::map<std::array<int, 2>, RoughTransportValues> values;  ///< by (K, Sonine order)
    std::optional<RoughCoolingState> maxwellian;                ///< the Maxwellian HCS (θ, ζ* of degree 1)
    std::map<int, RoughSplitSlopes> slopes;                     ///< Γ*, Z_δ by cumulant degree K (theory.md §19.27)
  };

  static std::string reference_key(int d, const Rational& alpha, const Rational& beta, const Rational& kappa,
                                   bool linear) {
    return std::to_string(d) + "|" + alpha.to_string() + "|" + beta.to_string() + "|" + kappa.to_string() + "|" +
           (linear ? "linear" : "nonlinear");
  }

  /// Returns the reference HCS of cumulant degree K: the Sonine HCS of order K − 1 of the scheme, oriented in 3D
  /// (theory.md §19.14), solved once per state.
  const RoughSonineCoolingState& reference_hcs(int d, const Rational& alpha, const Rational& beta,
                                               const Rational& kappa, bool linear, int degree) {
    RoughReferenceEntry& entry = reference_[reference_key(d, alpha, beta, kappa, linear)];
    auto h = entry.hcs.find(degree);
    if (h == entry.hcs.end())
      h = entry.hcs
              .emplace(degree,
                       rough_sonine_cooling_state(d, alpha, beta, kappa, degree - 1,
                                                  linear ? RoughSonineScheme::linear : RoughSonineScheme::nonlinear,
                                                  reference_ansatz(d)))
              .first;
    return h->second;
  }

  /// Returns the Navier–Stokes values of order n about the Sonine HCS of order degree − 1 (theory.md §19.16; in 3D the
  /// oriented one, its b_pq carried), degree 1 the Maxwellian reference; NaN where that HCS has no solution. The
  /// tables are built to max(n, tables) and to the highest degree asked so far.
  RoughTransportValues reference_values(int d, const Rational& alpha, const Rational& beta, const Rational& kappa,
                                        bool linear, int degree, int n, int tables) {
    if (degree == 1) return transport_values(d, alpha, beta, kappa, n, tables);
    RoughReferenceEntry& entry = reference_[reference_key(d, alpha, beta, kappa, linear)];
    if (const auto v = entry.values.find({degree, n}); v != entry.values.end()) return v->second;
    const RoughSonineCoolingState& hcs = reference_hcs(d, alpha, beta, kappa, linear, degree);
    if (!hcs.solved) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      return entry.values[{degree, n}] = RoughTransportValues{nan, nan, nan, nan, nan, nan, nan};
    }
    const bool oriented = std::any_of(hcs.orientation_coefficients.begin(), hcs.orientation_coefficients.end(),
                                      [](double b) { return b != 0; });
    if (!entry.transport || entry.transport->highest_order() < n || entry.transport->cumulant_degree() < degree ||
        (oriented && !entry.oriented)) {
      const int orders = std::max({n, tables, entry.transport ? entry.transport->highest_order() : 0});
      const int degrees = std::max(degree, entry.transport ? entry.transport->cumulant_degree() : 0);
      entry.oriented = entry.oriented || oriented;
      entry.transport = std::make_unique<RoughSonineTransport>(d, alpha, beta, kappa, orders, degrees, entry.oriented);
    }
    return entry.values[{degree, n}] = entry.transport->at_cooling_state(n, hcs);
  }

  /// Returns column `name` — a Navier–Stokes column or a stability value — at Sonine order n about the HCS of cumulant
  /// degree K (1: the Maxwellian reference at the Maxwellian θ, ζ*); the stability values from that HCS's θ, ζ* and the
  /// five coefficients about it (theory.md (19.33)); NaN where that HCS has no solution.
  double reference_column(int d, const Rational& alpha, const Rational& beta, const Rational& kappa, bool linear,
                          const std::string& name, int degree, int n, int tables, bool field = false) {
    const RoughTransportValues v = reference_values(d, alpha, beta, kappa, linear, degree, n, tables);
    if (is_rough_sonine_column(name)) return rough_sonine_column(v, name);
    double theta = 0, zeta = 0;
    if (degree == 1) {
      RoughReferenceEntry& entry = reference_[reference_key(d, alpha, beta, kappa, linear)];
      if (!entry.maxwellian)
        entry.maxwellian = rough_homogeneous_cooling_state(d, alpha, beta, kappa, RoughHcsScheme::maxwellian);
      theta = entry.maxwellian->temperature_ratio;
      zeta = entry.maxwellian->cooling_rate;
    } else {
      const RoughSonineCoolingState& hcs = reference_hcs(d, alpha, beta, kappa, linear, degree);
      theta = hcs.temperature_ratio;
      zeta = hcs.cooling_rate;
    }
    std::optional<RoughSplitSlopes> split;
    if (field && std::isfinite(theta)) split = reference_slopes(d, alpha, beta, kappa, linear, degree);
    return pick_stability(rough_reference_stability(d, alpha, beta, theta, zeta, v, split), name);
  }

  /// Returns Γ*, Z_δ of the reference of cumulant degree K (theory.md §19.27): K = 1 the Maxwellian rates ((19.17),
  /// (19.37) from the first-Sonine ζ_U, exact for them); K ≥ 2 the linear scheme's rates of order K − 1 at its HCS,
  /// the cumulants held ((19.141)–(19.142)); NaN where that HCS has no solution.
  RoughSplitSlopes reference_slopes(int d, const Rational& alpha, const Rational& beta, const Rational& kappa,
                                    bool linear, int degree) {
    RoughReferenceEntry& entry = reference_[reference_key(d, alpha, beta, kappa, linear)];
    if (const auto found = entry.slopes.find(degree); found != entry.slopes.end()) return found->second;
    RoughSplitSlopes out;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (degree == 1) {
      const RoughCoolingState m = rough_homogeneous_cooling_state(d, alpha, beta, kappa, RoughHcsScheme::maxwellian);
      const RoughScalarResponse b = rough_bulk_viscosity(d, alpha, beta, kappa);
      out.temperature_ratio = m.temperature_ratio;
      out.cooling_rate = m.cooling_rate;
      out.relaxation_rate = b.relaxation_rate;
      out.cooling_split_slope = b.cooling_rate_first_order * d * (m.cooling_rate / 2 + b.relaxation_rate) / 2;
    } else {
      const RoughSonineCoolingState& hcs = reference_hcs(d, alpha, beta, kappa, linear, degree);
      if (!hcs.solved) {
        out.relaxation_rate = out.cooling_split_slope = nan;
      } else {
        const RoughSonineCoolingRates rates(d, alpha, beta, kappa, degree - 1, reference_ansatz(d));
        std::vector<double> unknowns = hcs.cumulants;
        unknowns.insert(unknowns.end(), hcs.orientation_coefficients.begin(), hcs.orientation_coefficients.end());
        try {
          out = rough_split_slopes(rates, hcs.temperature_ratio, unknowns);
        } catch (const std::invalid_argument&) {  // the HCS's rates do not balance to 1e-9: no slopes, NaN values
          out.relaxation_rate = out.cooling_split_slope = nan;
        }
      }
    }
    return entry.slopes[degree] = out;
  }

  /// Returns one Navier–Stokes column at Sonine order n about the HCS of cumulant degree K: v_N(K) with the error
  /// (6.3) from orders n + 1, n + 2 (n + 3 where the changes change sign) plus the reference step |v_N(K) − v_N(K − 1)|
  /// (K = 2 against the Maxwellian reference, the HCS of order 0); flagged not converging where the lower reference has
  /// no value (theory.md §19.16, "Cumulant reference").
  OrderValue reference_value(int d, const Rational& alpha, const Rational& beta, const Rational& kappa, bool linear,
                             const std::string& name, int degree, int n, int tables, bool field = false) {
    const auto at = [&](int k, int m) {
      return reference_column(d, alpha, beta, kappa, linear, name, k, m, tables, field);
    };
    const double v = at(degree, n);
    // (6.3): order N + 3 where the changes change sign, within the cap's tables (else not confirmed).
    const int highest = (degree == 1 ? kMaxRoughOrder : kMaxRoughReferenceOrder) + 2;
    OrderValue out = estimate_from_doubles_confirmed(v, at(degree, n + 1), at(degree, n + 2), [&] {
      return n + 3 <= highest ? at(degree, n + 3) : std::numeric_limits<double>::quiet_NaN();
    });
    if (!out.defined || out.infinite) return out;
    const double lower = at(degree - 1, n);
    if (!std::isfinite(lower)) {
      out.estimate.converging = false;
      return out;
    }
    out.estimate.error = out.estimate.error + Rational::from_double(std::abs(v - lower));
    return out;
  }

  std::map<std::string, RoughSonineEntry> sonine_;
  std::map<std::string, RoughReferenceEntry> reference_;
  RoughTrialSpace trial_space_ = RoughTrialSpace::product;  ///< of the evaluation under way (trial_space)
};

}  // namespace

RoughCoolingState linear_rough_state(int dimension, const Rational& alpha, const Rational& beta,
                                     const Rational& kappa) {
  RoughCoolingState s = rough_homogeneous_cooling_state(dimension, alpha, beta, kappa, RoughHcsScheme::linear);
  if (s.linear_scheme_solved) return s;
  throw std::invalid_argument("hcs: the linear scheme has no root at dimension = " + std::to_string(dimension) +
                              ", alpha = " + alpha.to_decimal_string() + ", beta = " + beta.to_decimal_string() +
                              ", moment_of_inertia = " + kappa.to_decimal_string() + " (" +
                              rough_linear_no_root_region(dimension) +
                              "); use hcs = \"maxwellian\" or \"linear-or-maxwellian\"");
}

std::unique_ptr<TransportModel> make_rough_model() { return std::make_unique<RoughModel>(); }

}  // namespace gkt::detail
