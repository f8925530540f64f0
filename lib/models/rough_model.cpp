// The "rough" model: rough inelastic hard spheres (d = 3) or disks (d = 2) with constant normal
// and tangential restitution α, β and reduced moment of inertia κ = 4I/(mσ²). Provides the
// homogeneous cooling state in the Maxwellian or the linear first-Sonine approximation
// (rough_homogeneous_cooling_state.hpp; docs/theory.md §19): θ = T_r/T_t, ζ*, a20, a02, a11, and at
// Sonine orders up to 3 in the linear or nonlinear scheme with the cumulants a_pq
// (rough_sonine_cooling_state.hpp, §19.14); and the
// shear viscosity at first Sonine (rough_shear_viscosity.hpp, §19.7) and the orientational
// correlation C (rough_orientation_correlation.hpp, §19.8); κ*, μ* (rough_thermal_conductivity.hpp) and
// the bulk viscosity and first-order cooling rate (rough_bulk_viscosity.hpp, §19.9), d = 2, 3; the
// linear stability of the HCS from them (rough_hcs_stability.hpp, §19.15).
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>

#include "gkt/evolution/rough_hcs_stability.hpp"
#include "gkt/transport/rough/rough_bulk_viscosity.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_orientation_correlation.hpp"
#include "gkt/transport/rough/rough_shear_viscosity.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_state.hpp"
#include "gkt/transport/rough/rough_thermal_conductivity.hpp"
#include "models/models.hpp"
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
HcsStability rough_stability(int d, const Rational& alpha, const Rational& beta, const Rational& kappa) {
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
  return rough_hcs_stability(in);
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

/// Returns the HCS columns that take a Sonine order (θ, ζ*, every a_pq).
bool is_hcs_column(const std::string& name) {
  return name == "rotational_temperature_ratio" || name == "cooling_rate" || cumulant_of(name).has_value();
}

class RoughModel final : public TransportModel {
 public:
  [[nodiscard]] std::string name() const override { return "rough"; }
  [[nodiscard]] std::string description() const override {
    return "rough inelastic hard spheres (d = 3) or disks (d = 2), constant normal and tangential restitution "
           "alpha, beta and reduced moment of inertia: homogeneous cooling state (temperature ratio, cooling "
           "rate, cumulants a20, a02, a11 and a_pq to p + q = 4), Maxwellian or Sonine orders 1-3 (linear or "
           "nonlinear); first-Sonine shear and bulk viscosity, "
           "thermal conductivity, density heat coefficient, first-order cooling rate; translation-rotation "
           "correlation (3D); linear stability of the homogeneous cooling state";
  }
  [[nodiscard]] std::vector<std::string> coefficient_names() const override {
    auto names = kRoughTableColumns;
    // The higher cumulants of the Sonine HCS (theory.md §19.14), by total degree p + q.
    for (int n = 3; n <= kMaxRoughHcsOrder + 1; ++n)
      for (int q = 0; q <= n; ++q) names.push_back(cumulant_column(n - q, q));
    for (const auto& c : stability_coefficient_names()) names.push_back(c);
    return names;
  }
  /// Without `coefficients` a scene gets the columns it had before the stability values and the
  /// higher cumulants existed.
  [[nodiscard]] std::vector<std::string> default_coefficients(const ParameterPoint&) const override {
    return kRoughTableColumns;
  }
  [[nodiscard]] std::vector<ParameterSpec> parameters() const override {
    auto specs = rough_grain_parameters("beta", "tangential restitution coefficient (-1 smooth, +1 perfectly rough)");
    specs.push_back(choice_spec("hcs",
                                "approximation of the homogeneous cooling state: Sonine with cumulants linear, "
                                "Maxwellian, first Sonine falling back to Maxwellian (cumulants nan) where the "
                                "linear scheme has no root, or Sonine with all products of cumulants (nonlinear); "
                                "order N keeps a_pq with p + q <= N + 1",
                                {"linear", "maxwellian", "linear-or-maxwellian", "nonlinear"}));
    return specs;
  }
  /// The HCS columns take orders 1 … kMaxRoughHcsOrder; the transport columns are first Sonine only.
  [[nodiscard]] int max_order() const override { return kMaxRoughHcsOrder; }
  [[nodiscard]] bool supports(Capability capability) const override {
    return capability == Capability::table || capability == Capability::evolve || capability == Capability::stability;
  }
  [[nodiscard]] std::vector<ParameterSpec> evolution_parameters() const override {
    auto specs = parameters();
    // The trajectory integrates the first-Sonine balances (theory.md §19.13): no nonlinear scheme there.
    for (auto& spec : specs)
      if (spec.name == "hcs") spec.choices = {"linear", "maxwellian", "linear-or-maxwellian"};
    specs = rough_evolution_parameters(specs, {"dimension", "alpha", "beta", "moment_of_inertia", "hcs"});
    for (auto& spec : rough_initial_cumulant_parameters()) specs.push_back(std::move(spec));
    return specs;
  }
  /// T_t(τ), T_r(τ) and the cumulants from Maxwellians at T_t(0), T_r(0) (theory.md §19.13).
  Trajectory evolve(const TrajectoryRequest& request) override {
    return rough_trajectory(evolution_parameters(), request);
  }

  std::vector<CoefficientValue> evaluate(const ParameterPoint& point, const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    const auto specs = parameters();
    const auto [d, alpha, beta, kappa] = read_rough_grain(specs, point, "beta");
    const std::string scheme = SchemaPoint(specs, point).choice("hcs");
    // Orders above 1, a tolerance or the nonlinear scheme: the Sonine HCS (theory.md §19.14) for θ, ζ*
    // and the cumulants, with the error from the next order; the first-Sonine path otherwise.
    const bool sonine = scheme == "nonlinear" || order.order > 1 || order.tolerance || order.row_tolerance;
    for (const auto& name : coefficients) {
      if (is_hcs_column(name)) {
        if (sonine && (scheme == "maxwellian" || scheme == "linear-or-maxwellian"))
          throw std::invalid_argument(
              "hcs: \"" + scheme + "\" is a first approximation: use order = 1, or hcs = \"linear\" or \"nonlinear\"");
        continue;
      }
      if (order.tolerance)
        throw std::invalid_argument("tolerance: " + name +
                                    " of model rough is a first approximation: use order = 1 (tolerance applies to "
                                    "rotational_temperature_ratio, cooling_rate and the cumulants only)");
      if (order.order != 1)
        throw std::invalid_argument("order: must be exactly 1, got " + std::to_string(order.order) + " for " + name +
                                    " (first Sonine; the HCS columns take orders up to " +
                                    std::to_string(kMaxRoughHcsOrder) + ")");
    }
    if (sonine) return sonine_values(d, alpha, beta, kappa, scheme, coefficients, order);
    const auto& critical = stability_coefficient_names();
    const auto is_critical = [&critical](const std::string& c) {
      return std::find(critical.begin(), critical.end(), c) != critical.end();
    };
    // The stability values use the Maxwellian state whatever `hcs` (theory.md §19.15): a request for
    // them alone does not need, nor refuse, the scheme's state.
    RoughCoolingState s;
    if (!std::all_of(coefficients.begin(), coefficients.end(), is_critical)) {
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
    std::optional<HcsStability> stability;
    std::vector<CoefficientValue> out;
    for (const auto& name : coefficients) {
      if (is_critical(name)) {
        if (!stability) stability = rough_stability(d, alpha, beta, kappa);  // theory.md §19.15
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
        if (d != 3)
          throw std::invalid_argument(
              "coefficients: orientation_correlation needs dimension = 3 (disks spin normal to the plane)");
        x = rough_orientation_correlation(alpha, beta, kappa).correlation;  // theory.md §19.8
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
  /// The Sonine HCS values at the requested order or tolerance: v_N with the error |v_{N+1} − v_N|
  /// (theory.md §19.14); the transport columns as in the first-Sonine path.
  std::vector<CoefficientValue> sonine_values(int d, const Rational& alpha, const Rational& beta, const Rational& kappa,
                                              const std::string& scheme, const std::vector<std::string>& coefficients,
                                              const OrderRequest& order) {
    const RoughSonineScheme s = scheme == "nonlinear" ? RoughSonineScheme::nonlinear : RoughSonineScheme::linear;
    std::map<int, RoughSonineCoolingState> states;
    auto state = [&](int n) -> const RoughSonineCoolingState& {
      auto it = states.find(n);
      if (it == states.end()) it = states.emplace(n, rough_sonine_cooling_state(d, alpha, beta, kappa, n, s)).first;
      return it->second;
    };
    auto pick = [](const RoughSonineCoolingState& st, const std::string& name) {
      if (name == "rotational_temperature_ratio") return st.temperature_ratio;
      if (name == "cooling_rate") return st.cooling_rate;
      const auto pq = *cumulant_of(name);
      return st.cumulant(pq[0], pq[1]);
    };
    std::vector<CoefficientValue> out;
    for (const auto& name : coefficients) {
      if (!is_hcs_column(name)) {
        out.push_back(evaluate_first_sonine(d, alpha, beta, kappa, name));
        continue;
      }
      out.push_back(choose_order(order, kMaxRoughHcsOrder, [&](int n) {
        const double v = pick(state(n), name), next = pick(state(n + 1), name);
        OrderValue value;
        value.exact = false;
        value.defined = std::isfinite(v);
        if (!value.defined) return value;
        value.estimate.value = Rational::from_double(v);
        value.estimate.converging = std::isfinite(next);
        value.estimate.error = value.estimate.converging ? Rational::from_double(std::abs(next - v)) : Rational(0);
        if (!value.estimate.converging) value.defined = false;  // no error estimate: nan, error inf
        return value;
      }));
    }
    return out;
  }

  /// One transport column (or C) in the first approximation, whatever the HCS order.
  CoefficientValue evaluate_first_sonine(int d, const Rational& alpha, const Rational& beta, const Rational& kappa,
                                         const std::string& name) {
    ParameterPoint point;
    point.numbers["dimension"] = Rational(d);
    point.numbers["alpha"] = alpha;
    point.numbers["beta"] = beta;
    point.numbers["moment_of_inertia"] = kappa;
    point.choices["hcs"] = "maxwellian";  // the transport columns do not use the HCS cumulants
    return evaluate(point, {name}, OrderRequest{})[0];
  }
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
