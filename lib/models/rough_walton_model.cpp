// The "rough-walton" model: rough inelastic hard spheres (d = 3) or disks (d = 2) with Coulomb
// friction in Walton's form, β(γ) = min{β0, −1 + ((1+κ)/κ)(1+α) μ_f cot γ}
// (rough_walton.hpp; docs/theory.md §19.10): the Maxwellian HCS (θ, ζ*), the first-Sonine η*, κ*, μ*
// and the scalar Navier–Stokes response (bulk viscosity, first-order cooling rate); with `order` > 1 or a
// `tolerance` the five Navier–Stokes columns at higher Sonine orders (rough_walton_sonine.hpp, §19.20). μ_f → ∞ is
// the "rough" model. The linear stability of the HCS from these coefficients (rough_hcs_stability.hpp, §19.15). The
// HCS cumulants at orders 1–3 (§19.19, §19.25) and, with `hcs = "linear-oriented"`, the orientation terms (§19.29).
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "gkt/evolution/rough_hcs_stability.hpp"
#include "gkt/transport/rough/rough_walton.hpp"
#include "gkt/transport/rough/rough_walton_cumulants.hpp"
#include "gkt/transport/rough/rough_walton_sonine.hpp"
#include "gkt/transport/rough/rough_walton_sonine_hcs.hpp"
#include "models/models.hpp"
#include "models/rough_parameters.hpp"

namespace gkt::detail {

namespace {

/// The coefficients of `gkt table` before the stability values were added (its default columns).
const std::vector<std::string> kWaltonTableColumns{"rotational_temperature_ratio",
                                                   "cooling_rate",
                                                   "shear_viscosity",
                                                   "bulk_viscosity",
                                                   "thermal_conductivity",
                                                   "density_heat_coefficient",
                                                   "cooling_rate_first_order"};

/// Highest Sonine order of the Navier–Stokes columns: the error of order N needs orders N + 1, N + 2 (N + 3 to
/// confirm a sign change, theory.md (6.3); past the cap such a change stays unconfirmed and flagged), and the Walton
/// elements stop at order 4 (10–25 s of CPU there; order 5 would take minutes, docs/performance.md).
constexpr int kMaxWaltonOrder = 2;

/// Highest Sonine order of the HCS columns with `hcs = "linear"` (theory.md §19.25; order 4 would cost ~15× order 3).
constexpr int kMaxWaltonHcsOrder = kWaltonHcsHighestOrder;

/// Returns the HCS stability of the Walton gas from its Maxwellian θ, ζ* and first-Sonine coefficients
/// (theory.md §19.15); NaN everywhere where the spin decouples (no HCS of the spin, §19.10).
HcsStability walton_stability(int d, const RoughWaltonState& s) {
  if (s.spin_decoupled) return {std::nan(""), std::nan(""), std::nan("")};
  RoughStabilityInput in;
  in.dimension = d;
  in.temperature_ratio = s.temperature_ratio;
  in.cooling_rate = s.cooling_rate;
  in.shear_viscosity = s.shear_viscosity;
  in.bulk_viscosity = s.bulk_viscosity;
  in.thermal_conductivity = s.thermal_conductivity;
  in.density_heat_coefficient = s.density_heat_coefficient;
  in.cooling_rate_first_order = s.cooling_rate_first_order;
  return rough_hcs_stability(in);
}

/// The orientation columns of the oriented Walton HCS (`hcs = "linear-oriented"`, spheres; theory.md §19.29): C and
/// b_pq, p + q ≤ kWaltonHcsHighestOrder − 1, named as in the model rough.
const std::vector<std::string>& walton_orientation_columns() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out{"orientation_correlation"};
    for (int n = 0; n <= kWaltonHcsHighestOrder - 1; ++n)
      for (int q = 0; q <= n; ++q) {
        std::string b = "b00";
        b[1] = static_cast<char>('0' + n - q);
        b[2] = static_cast<char>('0' + q);
        out.push_back(b);
      }
    return out;
  }();
  return names;
}

bool is_walton_orientation_column(const std::string& name) {
  const auto& o = walton_orientation_columns();
  return std::find(o.begin(), o.end(), name) != o.end();
}

/// The HCS columns the `hcs` key governs (theory.md §19.19, §19.29).
bool is_walton_hcs_column(const std::string& name) {
  return name == "rotational_temperature_ratio" || name == "cooling_rate" || name == "a20" || name == "a02" ||
         name == "a11" || is_walton_orientation_column(name);
}

/// θ, ζ*, a20, a02, a11 of the first-Sonine (linear) HCS with the one-step error |linear − Maxwellian| (the
/// cumulants: |a|, their step from the Maxwellian 0); theory.md §19.19.
CoefficientValue linear_value(double x, double maxwellian) {
  CoefficientValue v = first_approximation(x);
  if (v.defined) {
    v.error_estimated = true;
    v.error = Rational::from_double(std::abs(x - maxwellian));
  }
  return v;
}

class RoughWaltonModel final : public TransportModel {
 public:
  [[nodiscard]] std::string name() const override { return "rough-walton"; }
  [[nodiscard]] std::string description() const override {
    return "rough inelastic hard spheres (d = 3) or disks (d = 2) with Coulomb friction (Walton): "
           "beta = min{beta0, -1 + ((1+kappa)/kappa)(1+alpha) friction cot(impact angle)}; Maxwellian "
           "homogeneous cooling state (temperature ratio, cooling rate); first-Sonine shear and bulk viscosity, "
           "thermal conductivity, density heat coefficient and first-order cooling rate (also at Sonine order 2 or a "
           "tolerance, with errors); linear stability of the homogeneous cooling state; HCS cumulants (hcs = linear, "
           "orders 1-3) and, spheres, the orientation correlation and b_pq (hcs = linear-oriented)";
  }
  [[nodiscard]] std::vector<std::string> coefficient_names() const override {
    auto names = kWaltonTableColumns;
    for (const auto& c : stability_coefficient_names()) names.push_back(c);
    for (const char* c : {"a20", "a02", "a11"}) names.emplace_back(c);      // theory.md §19.19
    for (const auto& c : walton_orientation_columns()) names.push_back(c);  // theory.md §19.29
    return names;
  }
  /// Without `coefficients` a scene gets the columns it had before the stability values existed.
  [[nodiscard]] std::vector<std::string> default_coefficients(const ParameterPoint&) const override {
    return kWaltonTableColumns;
  }
  [[nodiscard]] std::vector<ParameterSpec> parameters() const override {
    auto specs = rough_grain_parameters(
        "beta0", "tangential restitution of sticking collisions (-1 smooth, +1 perfectly rough)");
    specs.push_back({"friction",
                     ParameterSpec::Kind::real,
                     Rational(0),
                     Rational(1000000),
                     true,
                     true,
                     Rational(1, 2),
                     "Coulomb friction coefficient mu_f (0: smooth; the model rough is mu_f -> infinity)",
                     {}});
    specs.push_back(choice_spec("hcs",
                                "approximation of the homogeneous cooling state (theta, cooling rate, cumulants a20, "
                                "a02, a11): Maxwellian (cumulants 0), first Sonine with cumulants in the linear scheme "
                                "(error: the step from the Maxwellian), or first Sonine falling back to Maxwellian "
                                "(cumulants nan) where the linear scheme has no root, or (spheres) the linear scheme "
                                "with the orientation terms b_pq ((c.w)^2 - c^2 w^2/3) S_p S_q, p + q <= N - 1, and "
                                "the columns orientation_correlation and b_pq (linear-oriented, orders 1-3); the "
                                "transport and stability columns stay at the Maxwellian theta",
                                {"maxwellian", "linear", "linear-or-maxwellian", "linear-oriented"}));
    specs.push_back(
        choice_spec("reference_state",
                    "f0 of the Navier-Stokes columns: Maxwellians at the Maxwellian theta (default), or the "
                    "first-Sonine linear Walton HCS with its theta, cooling rate and a20, a02, a11 (order = 1 "
                    "only; the error adds the change from the Maxwellian reference)",
                    {"maxwellian", "hcs"}));
    return specs;
  }
  [[nodiscard]] int max_order() const override { return std::max(kMaxWaltonOrder, kMaxWaltonHcsOrder); }
  [[nodiscard]] bool supports(Capability capability) const override {
    return capability == Capability::table || capability == Capability::evolve || capability == Capability::stability;
  }
  [[nodiscard]] std::vector<ParameterSpec> evolution_parameters() const override {
    auto specs = parameters();
    // gkt evolve: the Maxwellian equations (default, as before) or the first-Sonine balances (theory.md §19.19).
    for (auto& spec : specs)
      if (spec.name == "hcs") {
        spec.choices = {"maxwellian", "linear", "linear-or-maxwellian"};
        spec.description =
            "scheme of the trajectory: the Maxwellian two-temperature equations, or the first-Sonine balances "
            "carrying a20, a02, a11 (linear; refused where the linear HCS has no root), or linear where it has one "
            "and Maxwellian elsewhere";
      }
    specs = rough_evolution_parameters(specs, {"dimension", "alpha", "beta0", "moment_of_inertia", "friction", "hcs"});
    for (auto& spec : rough_initial_cumulant_parameters()) specs.push_back(std::move(spec));
    specs.push_back(evolution_max_steps_parameter());
    return specs;
  }
  /// T_t(τ), T_r(τ) from Maxwellians, the Walton rates by quadrature at every step (theory.md §19.13), or with
  /// hcs = "linear" the first-Sonine trajectory with a20, a02, a11 (theory.md §19.19).
  Trajectory evolve(const TrajectoryRequest& request) override {
    return rough_walton_trajectory(evolution_parameters(), request);
  }

  std::vector<CoefficientValue> evaluate(const ParameterPoint& point, const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    const auto specs = parameters();
    const auto [d, alpha, beta0, kappa] = read_rough_grain(specs, point, "beta0");
    // Order 1 asked for as such is the first approximation of §19.10 (error not estimated); beyond it, or with a
    // tolerance, the five Navier–Stokes columns come from the Sonine solver of §19.20 about the Maxwellian HCS with
    // the error (6.3) from orders N + 1 … N + 3 (theory.md §6); every other column exists at order 1 only.
    const bool first = order.order == 1 && !order.tolerance && !order.row_tolerance;
    const std::string scheme = SchemaPoint(specs, point).choice("hcs");
    // hcs = "linear-oriented" (theory.md §19.29): spheres only; the reference state of the Navier–Stokes columns does
    // not carry the b_pq (not done), so reference_state = "hcs" is refused with it.
    const bool oriented = scheme == "linear-oriented";
    if (oriented && d != 3)
      throw std::invalid_argument(
          "hcs: \"linear-oriented\" needs dimension = 3 (disks: c.w = 0, the oriented ansatz is hcs = \"linear\")");
    for (const auto& name : coefficients)
      if (is_walton_orientation_column(name) && !oriented)
        throw std::invalid_argument("coefficients: " + name +
                                    " of model rough-walton needs hcs = \"linear-oriented\" and dimension = 3");
    if (SchemaPoint(specs, point).choice("reference_state") == "hcs") {
      if (oriented)
        throw std::invalid_argument(
            "reference_state: \"hcs\" of model rough-walton carries the isotropic first-Sonine HCS only; use hcs = "
            "\"linear\" (or \"maxwellian\", \"linear-or-maxwellian\")");
      return about_cooling_state(d, alpha, beta0, kappa, SchemaPoint(specs, point).number("friction"), coefficients,
                                 order);
    }
    // With hcs = "linear" (or "linear-or-maxwellian", "linear-oriented") the HCS columns exist at orders 1 … 3
    // (theory.md §19.25, §19.29).
    const bool sonine_hcs = scheme != "maxwellian";
    if (!first)
      for (const auto& name : coefficients) {
        if (sonine_hcs && is_walton_hcs_column(name)) continue;
        if (!is_rough_sonine_column(name))
          throw std::invalid_argument("coefficients: " + name +
                                      " of model rough-walton is computed at order 1 only; use order = 1 without "
                                      "tolerance, or ask for shear_viscosity, bulk_viscosity, thermal_conductivity, "
                                      "density_heat_coefficient or cooling_rate_first_order" +
                                      (is_walton_hcs_column(name) ? " (or hcs = \"linear\", orders 1 to 3)" : ""));
        if (!order.tolerance && order.order > kMaxWaltonOrder)
          throw std::invalid_argument("order: " + name + " of model rough-walton is computed at orders 1 to " +
                                      std::to_string(kMaxWaltonOrder) + ", got " + std::to_string(order.order) +
                                      " (only the HCS columns with hcs = \"linear\" reach order 3)");
      }
    if (!first) {
      const double friction = SchemaPoint(specs, point).number("friction").to_double();
      const bool any_transport = std::any_of(coefficients.begin(), coefficients.end(),
                                             [](const std::string& c) { return is_rough_sonine_column(c); });
      const std::vector<RoughTransportValues> empty;
      const std::vector<RoughTransportValues>& v =
          any_transport ? sonine_values(d, alpha.to_double(), beta0.to_double(), kappa.to_double(), friction,
                                        order.tolerance ? kMaxWaltonOrder + 2 : order.order + 2)
                        : empty;
      std::vector<CoefficientValue> out;
      for (const auto& name : coefficients) {
        if (is_walton_hcs_column(name)) {
          out.push_back(sonine_hcs_value(d, alpha, beta0, kappa, SchemaPoint(specs, point).number("friction"), scheme,
                                         name, order));
          continue;
        }
        out.push_back(choose_order(order, kMaxWaltonOrder, [&](int n) {
          // Orders past the solved ones (N + 3 beyond the library's cap 4) are nan: an unconfirmed sign change.
          const auto at = [&](int m) {
            return m > static_cast<int>(v.size()) ? std::nan("")
                                                  : rough_sonine_column(v[static_cast<std::size_t>(m - 1)], name);
          };
          return estimate_from_doubles_confirmed(at(n), at(n + 1), at(n + 2), [&] { return at(n + 3); });
        }));
      }
      return out;
    }
    // The HCS columns of `hcs` (theory.md §19.19); the transport and stability columns use the Maxwellian θ, ζ*.
    // The oriented HCS at order 1 is its own solution (theory.md §19.29), with the step from the Maxwellian.
    std::optional<RoughWaltonCumulantState> linear;
    if (scheme != "maxwellian" && !oriented &&
        std::any_of(coefficients.begin(), coefficients.end(), is_walton_hcs_column)) {
      linear = rough_walton_linear_cooling_state(d, alpha.to_double(), beta0.to_double(), kappa.to_double(),
                                                 SchemaPoint(specs, point).number("friction").to_double());
      if (!linear->linear_scheme_solved && scheme == "linear")
        throw std::invalid_argument(
            "hcs: the linear scheme of the Walton gas has no root with realizable cumulants at dimension = " +
            std::to_string(d) + ", alpha = " + alpha.to_decimal_string() + ", beta0 = " + beta0.to_decimal_string() +
            ", moment_of_inertia = " + kappa.to_decimal_string() +
            ", friction = " + SchemaPoint(specs, point).number("friction").to_decimal_string() +
            " (strong inelasticity with weak roughness or weak friction, docs/theory.md section 19.19); use hcs = "
            "\"maxwellian\" or \"linear-or-maxwellian\"");
    }
    // The Maxwellian state with its transport coefficients, unless `linear` (which carries the Maxwellian θ, ζ*)
    // serves every column.
    RoughWaltonState s;
    if (!(linear || oriented) || !std::all_of(coefficients.begin(), coefficients.end(), is_walton_hcs_column))
      s = rough_walton_cooling_state(d, alpha, beta0, kappa, SchemaPoint(specs, point).number("friction"));
    std::vector<CoefficientValue> out;
    for (const auto& name : coefficients) {
      if (oriented && is_walton_hcs_column(name)) {
        out.push_back(sonine_hcs_value(d, alpha, beta0, kappa, SchemaPoint(specs, point).number("friction"), scheme,
                                       name, order));
        continue;
      }
      if (linear && is_walton_hcs_column(name)) {
        const bool solved = linear->linear_scheme_solved && !linear->spin_decoupled;
        if (name == "rotational_temperature_ratio") {
          out.push_back(solved ? linear_value(linear->temperature_ratio, linear->maxwellian_temperature_ratio)
                               : first_approximation(linear->maxwellian_temperature_ratio));
        } else if (name == "cooling_rate") {
          out.push_back(solved ? linear_value(linear->cooling_rate, linear->maxwellian_cooling_rate)
                               : first_approximation(linear->maxwellian_cooling_rate));
        } else {
          const double a = name == "a20" ? linear->a20 : name == "a02" ? linear->a02 : linear->a11;
          out.push_back(solved ? linear_value(a, 0) : first_approximation(std::nan("")));
        }
        continue;
      }
      const auto& critical = stability_coefficient_names();
      if (std::find(critical.begin(), critical.end(), name) != critical.end()) {
        out.push_back(rough_stability_value(walton_stability(d, s), name));  // theory.md §19.15
        continue;
      }
      double x = 0;
      if (name == "rotational_temperature_ratio") {
        x = s.temperature_ratio;  // +inf when the spin decouples
      } else if (name == "cooling_rate") {
        x = s.cooling_rate;
      } else if (name == "shear_viscosity") {
        x = s.shear_viscosity;  // theory.md (19.23)
      } else if (name == "thermal_conductivity") {
        x = s.thermal_conductivity;  // theory.md (19.15) with (19.23)
      } else if (name == "density_heat_coefficient") {
        x = s.density_heat_coefficient;  // theory.md (19.16)
      } else if (name == "bulk_viscosity") {
        x = s.bulk_viscosity;  // theory.md (19.18)
      } else if (name == "cooling_rate_first_order") {
        x = s.cooling_rate_first_order;  // theory.md (19.19)
      } else if (name == "a20" || name == "a02" || name == "a11") {
        x = s.spin_decoupled ? std::nan("") : 0.0;  // hcs = "maxwellian": no cumulants
      } else {
        throw std::invalid_argument("coefficients: unknown coefficient '" + name +
                                    "' for model rough-walton; valid: " + join(coefficient_names()));
      }
      out.push_back(first_approximation(x));
    }
    return out;
  }

 private:
  /// Returns the five Navier–Stokes columns at order 1 about the first-Sonine linear Walton HCS (theory.md §19.25,
  /// (19.127)) with the error (6.1) from orders 2, 3 about it plus the reference step |v_1(hcs) − v_1(Maxwellian)|
  /// ((19.46)); every other column, other orders and a tolerance are refused (one line): order 2 would need the
  /// weighted tables of order 4, twelve forms, minutes per state.
  std::vector<CoefficientValue> about_cooling_state(int d, const Rational& alpha, const Rational& beta0,
                                                    const Rational& kappa, const Rational& friction,
                                                    const std::vector<std::string>& coefficients,
                                                    const OrderRequest& order) {
    for (const auto& name : coefficients)
      if (!is_rough_sonine_column(name))
        throw std::invalid_argument("coefficients: " + name +
                                    " of model rough-walton is not computed with reference_state = \"hcs\"; ask for "
                                    "shear_viscosity, bulk_viscosity, thermal_conductivity, density_heat_coefficient "
                                    "or cooling_rate_first_order");
    if (order.tolerance || order.row_tolerance || order.order != 1)
      throw std::invalid_argument(
          "order: rough-walton with reference_state = \"hcs\" is computed at order = 1 only (no tolerance)");
    const double a = alpha.to_double(), b = beta0.to_double(), k = kappa.to_double(), f = friction.to_double();
    const std::vector<RoughWaltonSonineState>& hcs = hcs_values(d, a, b, k, f, 1);
    if (hcs[0].spin_decoupled) {  // no Walton HCS: every column NaN, as about the Maxwellian
      std::vector<CoefficientValue> out;
      for (std::size_t i = 0; i < coefficients.size(); ++i) out.push_back(first_approximation(std::nan("")));
      return out;
    }
    if (!hcs[0].solved)
      throw std::invalid_argument(
          "reference_state: the linear scheme of the Walton gas has no root with realizable cumulants at dimension = " +
          std::to_string(d) + ", alpha = " + alpha.to_decimal_string() + ", beta0 = " + beta0.to_decimal_string() +
          ", moment_of_inertia = " + kappa.to_decimal_string() + ", friction = " + friction.to_decimal_string() +
          " (docs/theory.md section 19.19); use reference_state = \"maxwellian\"");
    const std::vector<RoughTransportValues> v = rough_walton_sonine_transport_about_hcs(d, a, b, k, f, hcs[0], 3);
    const std::vector<RoughTransportValues>& m = sonine_values(d, a, b, k, f, 3);
    std::vector<CoefficientValue> out;
    for (const auto& name : coefficients) {
      const OrderValue ov = estimate_from_doubles(rough_sonine_column(v[0], name), rough_sonine_column(v[1], name),
                                                  rough_sonine_column(v[2], name));
      CoefficientValue c{ov.estimate.value, ov.estimate.error, 1, ov.defined && ov.estimate.converging, false,
                         ov.defined};
      c.divergence = ov.estimate.divergence;
      if (ov.defined) {
        const double step = std::abs(rough_sonine_column(v[0], name) - rough_sonine_column(m[0], name));
        c.error = c.error + Rational::from_double(step);  // (19.46): the reference step
      }
      out.push_back(c);
    }
    return out;
  }

  /// Returns one HCS column (θ, ζ*, a20, a02, a11; with `hcs = "linear-oriented"` also C and b_pq) of the order-N
  /// linear-scheme Walton HCS (theory.md §19.25, oriented §19.29) with the error |v_N − v_{N−1}| (v_0 the Maxwellian
  /// θ, ζ*, cumulants 0, C = 1/3), at `order` or the smallest N ≤ 3 whose error is below the tolerance; `hcs =
  /// "linear"`, `"linear-oriented"` refuse (one line) a state the linear scheme cannot solve at the orders asked for,
  /// `"linear-or-maxwellian"` gives there the Maxwellian θ, ζ* and NaN cumulants.
  CoefficientValue sonine_hcs_value(int d, const Rational& alpha, const Rational& beta0, const Rational& kappa,
                                    const Rational& friction, const std::string& scheme, const std::string& name,
                                    const OrderRequest& order) {
    const int highest = order.tolerance ? kMaxWaltonHcsOrder : order.order;
    const bool oriented = scheme == "linear-oriented";
    const std::vector<RoughWaltonSonineState>& states =
        hcs_values(d, alpha.to_double(), beta0.to_double(), kappa.to_double(), friction.to_double(), highest, oriented);
    const auto column = [&](const RoughWaltonSonineState& s) {
      if (name == "rotational_temperature_ratio") return s.temperature_ratio;
      if (name == "cooling_rate") return s.cooling_rate;
      if (name == "orientation_correlation") return s.orientation_correlation;
      const int p = name[1] - '0', q = name[2] - '0';  // a_pq or b_pq
      return name[0] == 'b' ? s.orientation_coefficient(p, q) : s.cumulant(p, q);
    };
    // A fixed order needs that order's root; a tolerance scans the solved orders (an unsolved one is undefined).
    const RoughWaltonSonineState& top = states[static_cast<std::size_t>(order.tolerance ? 0 : highest - 1)];
    if (!top.solved && !top.spin_decoupled) {
      if (scheme != "linear-or-maxwellian")
        throw std::invalid_argument(
            "hcs: the linear scheme of the Walton gas at order " + std::to_string(highest) +
            " has no root with realizable cumulants near the order below at dimension = " + std::to_string(d) +
            ", alpha = " + alpha.to_decimal_string() + ", beta0 = " + beta0.to_decimal_string() +
            ", moment_of_inertia = " + kappa.to_decimal_string() + ", friction = " + friction.to_decimal_string() +
            " (docs/theory.md section 19.25); use a lower order, hcs = \"maxwellian\" or \"linear-or-maxwellian\"");
      if (name == "rotational_temperature_ratio") return first_approximation(top.maxwellian_temperature_ratio);
      if (name == "cooling_rate") return first_approximation(top.maxwellian_cooling_rate);
      return first_approximation(std::nan(""));
    }
    if (top.spin_decoupled)  // no Walton HCS: θ = inf, the rest NaN (as at order 1)
      return first_approximation(name == "rotational_temperature_ratio" ? top.temperature_ratio : std::nan(""));
    const double maxwellian = name == "rotational_temperature_ratio" ? top.maxwellian_temperature_ratio
                              : name == "cooling_rate"               ? top.maxwellian_cooling_rate
                              : name == "orientation_correlation"    ? 1.0 / 3
                                                                     : 0.0;
    return choose_order(order, highest, [&](int n) {
      const double v = column(states[static_cast<std::size_t>(n - 1)]);
      const double below = n == 1 ? maxwellian : column(states[static_cast<std::size_t>(n - 2)]);
      OrderValue out{{Rational(0), Rational(0), true}, std::isfinite(v) && std::isfinite(below), false};
      if (out.defined) out.estimate = {Rational::from_double(v), Rational::from_double(std::abs(v - below)), true};
      return out;
    });
  }

  /// Returns the linear-scheme Walton HCS at orders 1 … highest (rough_walton_sonine_cooling_states), isotropic or
  /// (`oriented`, theory.md §19.29) with the b_pq, cached per state and ansatz.
  const std::vector<RoughWaltonSonineState>& hcs_values(int d, double alpha, double beta0, double kappa,
                                                        double friction, int highest, bool oriented = false) {
    if (hcs_cache_.size() > 64) hcs_cache_.clear();
    auto& entry = hcs_cache_[{static_cast<double>(d), alpha, beta0, kappa, friction, oriented ? 1.0 : 0.0}];
    if (static_cast<int>(entry.size()) < highest)
      entry = rough_walton_sonine_cooling_states(d, alpha, beta0, kappa, friction, highest, 8,
                                                 oriented ? RoughSonineAnsatz::oriented : RoughSonineAnsatz::isotropic);
    return entry;
  }
  std::map<std::array<double, 6>, std::vector<RoughWaltonSonineState>> hcs_cache_;

  /// Returns the Navier–Stokes values of orders 1 … highest about the Maxwellian HCS (empty where the spin decouples:
  /// no Walton HCS, every column NaN as at order 1), cached per state.
  const std::vector<RoughTransportValues>& sonine_values(int d, double alpha, double beta0, double kappa,
                                                         double friction, int highest) {
    if (cache_.size() > 64) cache_.clear();  // bound memory in long sweeps (never mid-evaluation)
    auto& entry = cache_[{static_cast<double>(d), alpha, beta0, kappa, friction}];
    if (entry.computed && (entry.values.empty() || static_cast<int>(entry.values.size()) >= highest))
      return entry.values;
    entry.computed = true;
    const double theta = rough_walton_temperature_ratio(d, alpha, beta0, kappa, friction);
    entry.values = std::isinf(theta) ? std::vector<RoughTransportValues>{}
                                     : rough_walton_sonine_transport(d, alpha, beta0, kappa, friction, theta, highest);
    return entry.values;
  }

  struct CacheEntry {
    bool computed = false;
    std::vector<RoughTransportValues> values;
  };
  std::map<std::array<double, 5>, CacheEntry> cache_;
};

}  // namespace

std::unique_ptr<TransportModel> make_rough_walton_model() { return std::make_unique<RoughWaltonModel>(); }

}  // namespace gkt::detail
