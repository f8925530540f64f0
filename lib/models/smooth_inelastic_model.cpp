// The "smooth-inelastic" model: smooth inelastic hard spheres/disks with constant normal
// restitution α, dilute (Boltzmann) or dense (Enskog, packing fraction φ > 0). Provides the
// homogeneous cooling state (cumulants a2…a18, cooling rate; homogeneous_cooling_state.hpp),
// the pressure and the Navier–Stokes coefficients η*, κ*, μ*, bulk viscosity
// (navier_stokes.hpp, theory.md §10, §15). Order N keeps N Sonine polynomials per
// transport mode and the cumulants a_2 … a_{N+1}.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>

#include "gkt/evolution/homogeneous_cooling_evolution.hpp"
#include "gkt/transport/closed_forms/enskog_closed_form.hpp"
#include "gkt/transport/closed_forms/first_sonine_formulas.hpp"
#include "gkt/transport/common/pair_correlation.hpp"
#include "gkt/transport/monodisperse/hcs_tail_amplitude.hpp"
#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"
#include "gkt/transport/monodisperse/tail_galerkin.hpp"
#include "models/models.hpp"

namespace gkt::detail {

namespace {

// Order N keeps a_2 … a_{N+1}; its error estimate needs orders N + 1, N + 2 (NS operators to index
// N + 4 with the solver's headroom, cumulants to a_{N+3}), and the plateau sum (theory.md (6.2)) order
// N + 3. The cap is set where the series stops helping: in 2D at α = 0.8 the Sonine series turns
// asymptotic near N ≈ 20 and its alternating plateau is summed at N = 18 … 20 (theory.md §6); orders
// to 23 come from one operator build (docs/performance.md: ≈ 60 s of CPU for a scan that gets there).
constexpr int kMaxOrder = 20;
// The first order at which the plateau sum may stand in for (6.1): the orders above the former cap 17,
// where it was checked against the tail scheme (2D, α = 0.8). Below it every scan is what it was
// (at 2D α = 0.7 and 0.75 it was honest too, but would change shipped tables; theory.md §6).
constexpr int kFirstPlateauOrder = 18;
constexpr int kHighestCumulant = kMaxOrder + 1;
// The first resolution of the tail scheme (power-law trial space) at which a tolerance may stop: measured
// over d = 2, 3 and α = 0.2 … 1 against resolution 22 (20 for α ≥ 0.8), its (6.1) error let a tolerance of
// 1e-4 stop with a wrong claim at N = 9 (2D α = 0.6: κ* 8.4e-5 claimed, 1.4e-4 true; κ*, μ* turn near
// N ≈ 10 there) and never from N = 10 on (theory.md §10.6).
constexpr int kTailFirstStoppingResolution = 10;

/// The density of one evaluation: φ, χ(φ), φ dχ/dφ (exact) and the closure's name.
struct Dense {
  Rational phi, chi, phi_dchi;
  std::string closure;
  [[nodiscard]] EnskogState state() const { return {phi.to_double(), chi.to_double(), phi_dchi.to_double()}; }
  /// Memo key fragment: α alone when dilute.
  [[nodiscard]] std::string key(const Rational& alpha) const {
    if (phi.sign() == 0) return alpha.to_string();
    std::string k = alpha.to_string();
    k.append("|").append(phi.to_string()).append("|").append(closure);
    return k;
  }
};

/// The coefficients of the Navier–Stokes solution, read from one order's η*, κ*, μ*, bulk viscosity
/// and ζ_U; the three HCS stability values also need ζ* and the density (theory.md §14).
enum class Transport {
  shear_viscosity,
  thermal_conductivity,
  density_heat_coefficient,
  critical_wavenumber_shear,
  critical_wavenumber_heat,
  critical_length,
  bulk_viscosity,
  cooling_rate_first_order
};

/// The canonical name of each Transport value, in enum order (built once).
constexpr std::array<const char*, 8> kTransportNames{
    "shear_viscosity",          "thermal_conductivity", "density_heat_coefficient", "critical_wavenumber_shear",
    "critical_wavenumber_heat", "critical_length",      "bulk_viscosity",           "cooling_rate_first_order"};

/// Returns the Transport value named `c`, or none (a cumulant, ζ*, p*).
std::optional<Transport> transport_named(const std::string& c) {
  const auto it = std::find(kTransportNames.begin(), kTransportNames.end(), c);
  if (it == kTransportNames.end()) return std::nullopt;
  return static_cast<Transport>(it - kTransportNames.begin());
}

/// True for the HCS stability values (critical wave numbers and length).
bool is_stability(Transport t) {
  return t == Transport::critical_wavenumber_shear || t == Transport::critical_wavenumber_heat ||
         t == Transport::critical_length;
}

/// True for the coefficients that vanish in the dilute gas (bulk viscosity, ζ_U).
bool is_dense_only(Transport t) { return t == Transport::bulk_viscosity || t == Transport::cooling_rate_first_order; }

/// The columns of the HCS tail φ ~ 𝒜 c^γ exp(−A c) (theory.md §10.6, §10.7): scheme = "tail" only.
constexpr std::array<const char*, 2> kTailColumns{"tail_exponent", "tail_amplitude"};

/// True for a column of kTailColumns.
bool is_tail_column(const std::string& c) {
  return std::find(kTailColumns.begin(), kTailColumns.end(), c) != kTailColumns.end();
}

// The tail amplitude (hcs_tail_amplitude, theory.md §10.7): under a tolerance it is computed at this resolution
// (where it was measured, 2D and 3D α = 0.05 … 0.7: relative errors 0.1–0.4 %, so no tolerance below ≈ 1e-3 of
// the value is met and `gkt table` warns), at a fixed order at that order, which must be at least this (2D α = 0.5
// at resolutions 5 and 6: the continuation does not settle; theory.md §10.7).
constexpr int kTailAmplitudeResolution = 12;

/// Returns the canonical name "a<k>" of the k-th cumulant.
std::string cumulant_name(int k) {
  std::string name(1, 'a');
  name += std::to_string(k);
  return name;
}

class SmoothInelasticModel final : public TransportModel {
 public:
  [[nodiscard]] std::string name() const override { return "smooth-inelastic"; }
  [[nodiscard]] std::string description() const override {
    return "smooth inelastic hard spheres (d = 3) or disks (d = 2), constant restitution alpha: "
           "homogeneous cooling state, pressure and Navier-Stokes coefficients, dilute or dense (Enskog), "
           "standard or modified Sonine scheme, or the tail-carrying scheme for strong dissipation";
  }
  [[nodiscard]] std::vector<std::string> coefficient_names() const override {
    std::vector<std::string> names;
    for (int k = 2; k <= kHighestCumulant; ++k) names.push_back(cumulant_name(k));
    names.emplace_back("cooling_rate");
    names.emplace_back("shear_viscosity");
    names.emplace_back("thermal_conductivity");
    names.emplace_back("density_heat_coefficient");
    names.emplace_back("critical_wavenumber_shear");
    names.emplace_back("critical_wavenumber_heat");
    names.emplace_back("critical_length");
    names.emplace_back("bulk_viscosity");
    names.emplace_back("cooling_rate_first_order");
    names.emplace_back("pressure");
    for (const char* c : kTailColumns) names.emplace_back(c);
    return names;
  }
  /// Every column but the tail's (scheme = "tail" only; the amplitude costs minutes): a scene that lists
  /// none gets what every scheme computes.
  [[nodiscard]] std::vector<std::string> default_coefficients(const ParameterPoint& fixed) const override {
    auto names = scene_coefficient_names(fixed);
    std::erase_if(names, is_tail_column);
    return names;
  }
  [[nodiscard]] std::vector<ParameterSpec> parameters() const override {
    return {
        dimension_spec(),
        restitution_spec("alpha", "normal restitution coefficient"),
        choice_spec("hcs", "cumulant scheme of the homogeneous cooling state", {"nonlinear", "linear"}),
        choice_spec("scheme",
                    "trial-function weight: Maxwellian (standard), HCS (modified) or Gaussian core with the "
                    "exponential HCS tail (tail: dilute or Enskog, converges at strong dissipation)",
                    {"standard", "modified", "tail"}),
        {"packing_fraction",
         ParameterSpec::Kind::real,
         Rational(0),
         max_packing_fraction(2),
         true,
         true,
         Rational(0),
         "packing fraction phi (0 = dilute; Enskog theory above; at most 0.5 in 3D, 0.7 in 2D)",
         {}},
        choice_spec("pair_correlation", "contact value chi(phi) of the pair correlation", pair_correlation_names())};
  }
  /// At a fixed dimension the packing fraction is limited to that dimension's range.
  [[nodiscard]] std::vector<ParameterSpec> scene_parameters(const ParameterPoint& fixed) const override {
    auto specs = parameters();
    const Rational dim = fixed.number("dimension", Rational(0));
    if (dim == Rational(2) || dim == Rational(3))
      for (auto& spec : specs)
        if (spec.name == "packing_fraction") spec.max = max_packing_fraction(dim == Rational(2) ? 2 : 3);
    return specs;
  }
  /// The order request's range covers both schemes: the Sonine orders to kMaxOrder, the tail scheme's
  /// resolutions to kTailGalerkinMaxOrder − 2 (its error needs two more); each scheme refuses past its own.
  [[nodiscard]] int max_order() const override { return std::max(kMaxOrder, kTailGalerkinMaxOrder - 2); }

  [[nodiscard]] bool supports(Capability) const override { return true; }

  std::vector<CoefficientValue> evaluate(const ParameterPoint& point, const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    const SchemaPoint p(parameters(), point);  // validated by the registry's guard
    const int d = p.number("dimension") == Rational(2) ? 2 : 3;
    const Rational alpha = p.number("alpha");
    const std::string scheme = p.choice("hcs");
    const SonineScheme sonine = p.choice("scheme") == "modified" ? SonineScheme::modified : SonineScheme::standard;
    const Rational phi = p.number("packing_fraction");
    const std::string closure = p.choice("pair_correlation");
    if (phi > max_packing_fraction(d))
      throw std::invalid_argument("packing_fraction: must be a number in [0, " +
                                  max_packing_fraction(d).to_decimal_string() +
                                  "] for dimension = " + std::to_string(d) + ", got " + phi.to_decimal_string());
    if (p.choice("scheme") == "tail") {
      const PairCorrelation& closure_tail = pair_correlation(closure);
      const Dense dense_tail{phi, phi.sign() == 0 ? Rational(1) : closure_tail.contact_value(d, phi),
                             phi.sign() == 0 ? Rational(0) : closure_tail.packing_derivative(d, phi), closure};
      return evaluate_tail(d, alpha, dense_tail, scheme, coefficients, order);
    }
    if (!order.tolerance && order.order > kMaxOrder)
      throw std::invalid_argument("order: must be an integer in [1, " + std::to_string(kMaxOrder) +
                                  "] for scheme = \"" + p.choice("scheme") + "\", got " + std::to_string(order.order));
    const PairCorrelation& pc = pair_correlation(closure);
    const Rational chi = pc.contact_value(d, phi);
    const Dense dense{phi, chi, pc.packing_derivative(d, phi), closure};
    auto& hcs = solvers_[static_cast<std::size_t>(d - 2)];
    if (!hcs) hcs = std::make_unique<HomogeneousCoolingState>(d);
    if (scheme == "linear" && (order.tolerance || order.order != 1))
      throw std::invalid_argument(
          "hcs: \"linear\" is the first Sonine approximation: use order = 1, or hcs = \"nonlinear\"");

    if (memo_.size() > 4096) memo_.clear();  // bound memory in long sweeps (never mid-evaluation)
    if (ns_memo_.size() > 4096) ns_memo_.clear();
    if (tail_memo_.size() > 256) tail_memo_.clear();
    for (const auto& c : coefficients)
      if (is_tail_column(c))
        throw std::invalid_argument("coefficients: " + c +
                                    " is computed by scheme = \"tail\" only, not by scheme = \"" + p.choice("scheme") +
                                    "\"");
    std::vector<CoefficientValue> out;
    for (const auto& c : coefficients) {
      if (c == "pressure") {  // exact, independent of the cumulants
        out.push_back({reduced_pressure(d, alpha, phi * chi), Rational(0), order.order, true, true, true});
        continue;
      }
      if (const auto transport = transport_named(c)) {
        out.push_back(transport_value(*hcs, d, alpha, scheme, sonine, dense, *transport, order));
        continue;
      }
      const int k = c == "cooling_rate" ? -1 : cumulant_index(c);
      // Enskog HCS: the collision operator is χ times Boltzmann's, so the cumulants are the dilute
      // ones and ζ* = χ ζ*_dilute (theory.md (15.1)).
      const Rational scale = k < 0 ? chi : Rational(1);
      if (scheme == "linear") {
        if (k > 2)
          throw std::invalid_argument(std::string("coefficients: ") + c +
                                      " is not computed by hcs = \"linear\" (a2 only)");
        const HcsState lin = hcs->solve(alpha, 2, HcsScheme::linear);
        const Rational exact = k == 2 ? *lin.exact_a2 : *lin.exact_cooling_rate * chi;
        // Error of the first-Sonine value: against the next two nonlinear orders.
        const auto next1 = nonlinear(*hcs, d, alpha, 3), next2 = nonlinear(*hcs, d, alpha, 4);
        TruncationEstimate e = estimate_truncation(exact, Rational::from_double(pick(next1, k)) * scale,
                                                   Rational::from_double(pick(next2, k)) * scale);
        e.value = exact;
        out.push_back({e.value, e.error, 1, e.converging && next1.solved && next2.solved, true, true});
        continue;
      }
      out.push_back(choose_order(order, kMaxOrder, [&](int n) {
        const auto& s0 = nonlinear(*hcs, d, alpha, n + 1);
        const auto& s1 = nonlinear(*hcs, d, alpha, n + 2);
        const auto& s2 = nonlinear(*hcs, d, alpha, n + 3);
        OrderValue v;
        v.exact = false;
        v.defined = s0.solved && s1.solved && s2.solved;
        if (!v.defined) return v;
        auto next = [&] {  // v_{N+3}: for the turning-point check (6.3) and the plateau sum (6.2)
          const auto& s3 = nonlinear(*hcs, d, alpha, n + 4);
          return s3.solved ? pick(s3, k) : NAN;
        };
        const Rational r0 = Rational::from_double(pick(s0, k)) * scale, r1 = Rational::from_double(pick(s1, k)) * scale,
                       r2 = Rational::from_double(pick(s2, k)) * scale;
        std::optional<Rational> r3;
        if (changes_sign(r0, r1, r2))
          if (const double w3 = next(); std::isfinite(w3)) r3 = Rational::from_double(w3) * scale;
        v.estimate = estimate_truncation_confirmed(r0, r1, r2, r3);
        if (!plateau_summable(sonine, dense) || (k != -1 && k != 2 && k != 3)) return v;
        return summed_if_plateau(n, v, {pick(s0, k), pick(s1, k), pick(s2, k)}, order, next);
      }));
    }
    return out;
  }

  /// First-Sonine closed forms in α (theory.md (9.2), (10.8), (10.10)); with φ > 0 in `point` the
  /// dense form Σ R_m(α) m with φ, χ symbolic (standard scheme only; theory.md §15.7).
  ClosedForm closed_form(const ParameterPoint& point, const std::string& coefficient, int order) override {
    if (order != 1)
      throw std::invalid_argument("order: \"" + name() +
                                  "\" has closed forms at order 1 only (higher orders use the nonlinear HCS)");
    const SchemaPoint p(parameters(), point);
    const int d = p.number("dimension") == Rational(2) ? 2 : 3;
    const std::string scheme = p.choice("scheme");
    if (scheme == "tail")
      throw std::invalid_argument(
          "scheme: \"tail\" is numerical and has no closed forms: use \"standard\" or "
          "\"modified\"");
    if (p.number("packing_fraction").sign() != 0) {
      if (scheme != "standard")
        throw std::invalid_argument("scheme: dense-gas closed forms exist for \"standard\" only, got \"" + scheme +
                                    "\"");
      return {enskog_first_sonine_closed_form(d, coefficient), d, SonineScheme::standard};
    }
    const SonineScheme sonine = scheme == "modified" ? SonineScheme::modified : SonineScheme::standard;
    return {first_sonine_closed_form(d, coefficient, sonine), d, sonine};
  }

  [[nodiscard]] std::vector<ParameterSpec> evolution_parameters() const override {
    std::vector<ParameterSpec> specs{find_parameter(parameters(), "dimension"),
                                     find_parameter(parameters(), "alpha"),
                                     {"temperature",
                                      ParameterSpec::Kind::real,
                                      Rational(0),
                                      ParameterSpec::unbounded(),
                                      false,
                                      true,
                                      Rational(1),
                                      "initial temperature T(0)/T0",
                                      {}},
                                     find_parameter(parameters(), "packing_fraction"),
                                     find_parameter(parameters(), "pair_correlation")};
    for (auto& spec : evolution_common_parameters()) specs.push_back(std::move(spec));
    return specs;
  }
  [[nodiscard]] std::vector<std::string> trajectory_coefficients() const override {
    return trajectory_coefficient_names();
  }
  /// The cumulant hierarchy at constant α integrated from T(0), a2(0) (theory.md §12); η*, κ*, μ* at
  /// Sonine order N about the instantaneous cumulants a(τ) (§12.3). Dense (φ > 0): every collision
  /// rate carries χ(φ) (theory.md §12.4), the coefficients are the Enskog ones at φ.
  Trajectory evolve(const TrajectoryRequest& request) override {
    const SchemaPoint p(evolution_parameters(), request.parameters);
    if (!p.given("alpha")) throw missing(p.spec("alpha"));
    const int d = p.number("dimension") == Rational(2) ? 2 : 3;
    evolution_a2_spec(d).check(p.number("a2"));
    const Rational alpha = p.number("alpha");
    const Rational phi = p.number("packing_fraction");
    if (phi > max_packing_fraction(d))
      throw std::invalid_argument("packing_fraction: must be a number in [0, " +
                                  max_packing_fraction(d).to_decimal_string() +
                                  "] for dimension = " + std::to_string(d) + ", got " + phi.to_decimal_string());
    const PairCorrelation& closure = pair_correlation(p.choice("pair_correlation"));
    const EnskogState dense =
        phi.sign() == 0 ? EnskogState{} : enskog_state(d, phi.to_double(), closure);  // dilute: χ = 1 exactly
    const int order = static_cast<int>(p.number("order").to_double());
    const int k_max = order + 1;  // cumulants a_2 … a_{order+1}
    HomogeneousCoolingState hcs(d);
    const EvolutionResult result = evolve_homogeneous_cooling(
        hcs.hierarchy(alpha, k_max), p.number("temperature").to_double(), {p.number("a2").to_double()}, request.times,
        p.number("rtol").to_double(), p.number("atol").to_double(), dense.chi,
        static_cast<long>(p.number("max_steps").to_double()));
    std::optional<NavierStokesSolver> solver;
    if (!request.coefficients.empty()) solver.emplace(d);
    return tabulate_trajectory(name(), d, k_max, result, request.coefficients, [&](const EvolutionSample& s) {
      if (phi.sign() == 0) return SampleTransport{solver->solve(alpha, order, s.a)};
      return SampleTransport{solver->solve(alpha, order, s.a, SonineScheme::standard, dense), 0.5, dense,
                             alpha.to_double()};
    });
  }

 private:
  /// The values (2D, 3D) of the tail scheme (tail_galerkin.hpp, theory.md §10.6; dense: §15.8): a2, a3, ζ*,
  /// η*, κ*, μ* (dense also the bulk viscosity and ζ_U; the HCS stability values from them) at resolution N with
  /// the error (6.1) from N + 1, N + 2, in the power-law trial space; the pressure exactly (15.5).
  std::vector<CoefficientValue> evaluate_tail(int d, const Rational& alpha, const Dense& dense,
                                              const std::string& hcs_scheme,
                                              const std::vector<std::string>& coefficients, const OrderRequest& order) {
    if (hcs_scheme != "nonlinear")
      throw std::invalid_argument("hcs: the tail scheme solves the full HCS: use hcs = \"nonlinear\"");
    // The highest resolution with an error (two more needed); the model's order range covers it (`gkt table`
    // re-evaluates a tolerance row at its order through the schema, which allows [1, max_order()]).
    const int highest = std::min(kTailGalerkinMaxOrder - 2, max_order());
    if (!order.tolerance && order.order > highest)
      throw std::invalid_argument("order: must be an integer in [1, " + std::to_string(highest) +
                                  "] for scheme = \"tail\", got " + std::to_string(order.order));
    std::vector<CoefficientValue> out;
    for (const auto& c : coefficients) {
      if (c == "pressure") {  // exact, independent of the cumulants (theory.md (15.5))
        out.push_back({reduced_pressure(d, alpha, dense.phi * dense.chi), Rational(0), order.order, true, true, true});
        continue;
      }
      if (c == "tail_amplitude") {
        out.push_back(tail_amplitude_value(d, alpha, order));
        continue;
      }
      if (c == "tail_exponent" && alpha == Rational(1)) {  // the Maxwellian: no exponential tail, A = ∞
        CoefficientValue infinite{Rational(0), Rational(0), order.order, true, false, true};
        infinite.infinite = true;
        out.push_back(infinite);
        continue;
      }
      const auto transport = transport_named(c);
      if (!transport && c != "a2" && c != "a3" && c != "cooling_rate" && c != "tail_exponent")
        throw std::invalid_argument(std::string("coefficients: ") + c +
                                    " is not computed by scheme = \"tail\" (a2, a3, cooling_rate, transport, "
                                    "tail_exponent, tail_amplitude)");
      auto pick = [&](const TailGalerkinValues& v) {
        if (c == "a2") return v.a2;
        if (c == "a3") return v.a3;
        if (c == "cooling_rate") return v.cooling_rate;
        if (c == "tail_exponent") return v.tail_exponent;
        const NavierStokesValues ns{v.shear_viscosity, v.thermal_conductivity, v.density_heat_coefficient,
                                    v.bulk_viscosity, v.cooling_rate_first_order};
        // pick_transport wants the dilute ζ* (the dense one is χ times it, theory.md (15.1)).
        return pick_transport(ns, *transport, d, v.cooling_rate / dense.chi.to_double(), dense, alpha);
      };
      auto value_at = [&](int n) {
        const auto& seq = tail_sequence(d, alpha, dense, n + 2);
        const auto& s0 = seq[static_cast<std::size_t>(n - 1)];
        const auto& s1 = seq[static_cast<std::size_t>(n)];
        const auto& s2 = seq[static_cast<std::size_t>(n + 1)];
        if (!s0.solved || !s1.solved || !s2.solved) return OrderValue{{Rational(0), Rational(0), false}, false, false};
        return estimate_from_doubles_confirmed(pick(s0), pick(s1), pick(s2), [&] {
          // v_{N+3} for the turning-point check (6.3): none past the resolution cap
          if (n + 3 > kTailGalerkinMaxOrder) return static_cast<double>(NAN);
          const auto& s3 = tail_sequence(d, alpha, dense, n + 3)[static_cast<std::size_t>(n + 2)];
          return s3.solved ? pick(s3) : static_cast<double>(NAN);
        });
      };
      if (!order.tolerance) {
        out.push_back(choose_order(order, highest, value_at));
        continue;
      }
      // A tolerance may stop the scan only from resolution kTailFirstStoppingResolution on: below it the
      // power-law sequences still overshoot, and (6.1) was measured too small there. The scan then goes on
      // to the highest resolution: the sequences converge, but κ*, μ* turn near N ≈ 10–13, where their
      // estimates grow for a few resolutions before they fall (2D α = 0.3, 0.6), which choose_order takes
      // for an asymptotic series and stops at (theory.md §10.6).
      CoefficientValue best{};
      for (int n = kTailFirstStoppingResolution; n <= highest; ++n) {
        const OrderValue v = value_at(n);
        if (!v.defined) continue;
        const bool met = v.estimate.converging && v.estimate.error < *order.tolerance;
        if (met || best.order == 0 || v.estimate.error < best.error)
          best = {v.estimate.value, v.estimate.error, n, met, v.exact, v.defined};
        if (met) break;
      }
      if (best.order == 0) {  // no resolution gave an estimate: the highest, undefined (as choose_order)
        const OrderValue v = value_at(highest);
        best = {v.estimate.value, v.estimate.error, highest, false, v.exact, v.defined};
      }
      out.push_back(best);
    }
    return out;
  }
  /// The amplitude 𝒜 of the HCS tail φ ~ 𝒜 c^γ exp(−A c) (hcs_tail_amplitude, theory.md §10.7) with its own error
  /// (spread over matching speeds and resolutions N, N − 1): at resolution kTailAmplitudeResolution under a
  /// tolerance (converged if that error meets it), else at the requested order (≥ 12). hcs_tail_amplitude refuses α
  /// outside the range where it was measured to work (invalid_argument naming the column, exit 2 in the CLI).
  CoefficientValue tail_amplitude_value(int d, const Rational& alpha, const OrderRequest& order) {
    const bool scanned = order.tolerance || order.row_tolerance;
    const int n = scanned ? kTailAmplitudeResolution : order.order;
    if (n < kTailAmplitudeResolution)
      throw std::invalid_argument(
          "order: tail_amplitude needs a resolution in [" + std::to_string(kTailAmplitudeResolution) + ", " +
          std::to_string(kTailGalerkinMaxOrder - 2) +
          "] (measured to work from 12; at 2D alpha = 0.5 resolutions 5 and 6 do not settle), got " +
          std::to_string(n));
    const auto key = std::make_tuple(d, alpha.to_string(), n);
    auto it = amplitude_memo_.find(key);
    if (it == amplitude_memo_.end()) {
      try {
        it = amplitude_memo_.emplace(key, hcs_tail_amplitude(d, alpha.to_double(), n)).first;
      } catch (const std::invalid_argument& e) {
        const std::string why = e.what();
        if (why.starts_with("alpha: ")) throw std::invalid_argument("coefficients: tail_amplitude: " + why);
        throw;
      } catch (const std::runtime_error& e) {  // not seen in the measured range: named, never a number
        throw std::runtime_error(std::string("tail_amplitude: ") + e.what());
      }
    }
    const HcsTailAmplitude& a = it->second;
    const Rational error = Rational::from_double(a.error);
    const bool met = !order.tolerance || error < *order.tolerance;
    return {Rational::from_double(a.amplitude), error, n, met, false, true};
  }
  /// The tail-scheme values at resolutions 1 … at least `needed` (memoised per d and α; a longer sequence
  /// is computed in steps of four resolutions, the collision kernel being shared within one sequence).
  const std::vector<TailGalerkinValues>& tail_sequence(int d, const Rational& alpha, const Dense& dense, int needed) {
    auto& seq = tail_memo_[std::to_string(d) + ":" + dense.key(alpha)];
    if (static_cast<int>(seq.size()) < needed)
      seq = tail_galerkin_sequence(d, alpha.to_double(),
                                   std::min(kTailGalerkinMaxOrder, std::max(needed, static_cast<int>(seq.size()) + 4)),
                                   TailTrialSpace::power_law, dense.phi.sign() == 0 ? EnskogState{} : dense.state());
    return seq;
  }
  /// The transport value `which` from one order's η*, κ*, μ*, …; the stability values also need the
  /// dilute ζ* of the same order and the density (theory.md (14.4)–(14.5)).
  static double pick_transport(const NavierStokesValues& v, Transport which, int d, double zeta_dilute,
                               const Dense& dense, const Rational& alpha) {
    switch (which) {
      case Transport::shear_viscosity:
        return v.shear_viscosity;
      case Transport::thermal_conductivity:
        return v.thermal_conductivity;
      case Transport::density_heat_coefficient:
        return v.density_heat_coefficient;
      case Transport::bulk_viscosity:
        return v.bulk_viscosity;
      case Transport::cooling_rate_first_order:
        return v.cooling_rate_first_order;
      default:
        break;
    }
    const EnskogState st = dense.state();
    const HcsStability s = monodisperse_stability(d, st.chi * zeta_dilute, v, st, alpha.to_double());
    return which == Transport::critical_wavenumber_shear  ? s.shear_wavenumber
           : which == Transport::critical_wavenumber_heat ? s.heat_wavenumber
                                                          : s.critical_length;
  }
  CoefficientValue transport_value(HomogeneousCoolingState& hcs, int d, const Rational& alpha,
                                   const std::string& scheme, SonineScheme sonine, const Dense& dense, Transport which,
                                   const OrderRequest& order) {
    if (scheme == "linear") {
      // First Sonine about f_M(1 + a2 S2) with the van Noije–Ernst a2; error against orders 2, 3.
      const HcsState linear = hcs.solve(alpha, 2, HcsScheme::linear);
      const Rational a2 = *linear.exact_a2;
      const double zeta_linear = linear.exact_cooling_rate->to_double();  // ζ0 + a2 ζ2, dilute
      Rational value;          // exact: η*, κ*, μ* of the dilute closed forms
      double approximate = 0;  // otherwise (square roots, solver output; +∞ for L_c* of the elastic gas)
      bool exact = false;
      if ((dense.phi.sign() > 0 || is_dense_only(which)) && sonine == SonineScheme::standard) {
        // The dense closed forms, linear in a2 like Garzó–Dufty's (theory.md §15.7).
        const EnskogState st = dense.state();
        auto form = [&](Transport k) {
          return enskog_form(d, k).evaluate(alpha, st.packing_fraction, st.chi, st.phi_dchi);
        };
        if (is_stability(which)) {
          const NavierStokesValues v1{form(Transport::shear_viscosity), form(Transport::thermal_conductivity),
                                      form(Transport::density_heat_coefficient), form(Transport::bulk_viscosity),
                                      form(Transport::cooling_rate_first_order)};
          approximate = pick_transport(v1, which, d, zeta_linear, dense, alpha);
        } else {
          approximate = form(which);
        }
      } else if (dense.phi.sign() > 0 || is_dense_only(which)) {
        // Modified scheme: through the solver (the a2² products of the collisional terms kept).
        auto& solver = ns_[static_cast<std::size_t>(d - 2)];
        if (!solver) solver = std::make_unique<NavierStokesSolver>(d);
        const NavierStokesValues v1 = solver->solve(alpha, 1, {1.0, 0.0, a2.to_double()}, sonine, dense.state());
        approximate = pick_transport(v1, which, d, zeta_linear, dense, alpha);
      } else {
        // The closed forms linear in a2 (theory.md (10.8)): exact for η*, κ*, μ* (the stability
        // values take square roots).
        auto& fs = first_sonine_[static_cast<std::size_t>(d - 2)];
        if (!fs) fs = first_sonine_navier_stokes(d);
        const auto v = fs->evaluate(alpha, a2, sonine);
        exact = which == Transport::shear_viscosity || which == Transport::thermal_conductivity ||
                which == Transport::density_heat_coefficient;  // v holds η*, κ*, μ* in enum order
        if (exact)
          value = v[static_cast<std::size_t>(which)];
        else
          approximate = pick_transport({v[0].to_double(), v[1].to_double(), v[2].to_double()}, which, d, zeta_linear,
                                       dense, alpha);
      }
      const auto* n2 = navier_stokes(hcs, d, alpha, 2, sonine, dense);
      const auto* n3 = navier_stokes(hcs, d, alpha, 3, sonine, dense);
      if (!exact) {
        const bool alone = n2 == nullptr || n3 == nullptr;  // no error estimate: the value with error 0
        const OrderValue e = estimate_from_doubles(
            approximate,
            alone ? approximate : pick_transport(*n2, which, d, nonlinear(hcs, d, alpha, 3).cooling_rate, dense, alpha),
            alone ? approximate
                  : pick_transport(*n3, which, d, nonlinear(hcs, d, alpha, 4).cooling_rate, dense, alpha));
        CoefficientValue c{e.estimate.value, e.estimate.error, 1, !alone && e.defined && e.estimate.converging, false,
                           e.defined};
        c.infinite = e.infinite;
        return c;
      }
      if (n2 == nullptr || n3 == nullptr) return {value, Rational(0), 1, false, exact, true};
      const TruncationEstimate e = estimate_truncation(
          value,
          Rational::from_double(pick_transport(*n2, which, d, nonlinear(hcs, d, alpha, 3).cooling_rate, dense, alpha)),
          Rational::from_double(pick_transport(*n3, which, d, nonlinear(hcs, d, alpha, 4).cooling_rate, dense, alpha)));
      return {value, e.error, 1, e.converging, exact, true};
    }
    const bool summable = plateau_summable(sonine, dense) &&
                          (which == Transport::shear_viscosity || which == Transport::thermal_conductivity ||
                           which == Transport::density_heat_coefficient);
    return choose_order(order, kMaxOrder, [&](int n) {
      const auto* s0 = navier_stokes(hcs, d, alpha, n, sonine, dense);
      const auto* s1 = navier_stokes(hcs, d, alpha, n + 1, sonine, dense);
      const auto* s2 = navier_stokes(hcs, d, alpha, n + 2, sonine, dense);
      if (s0 == nullptr || s1 == nullptr || s2 == nullptr)  // no HCS solution at some order: undefined
        return OrderValue{{Rational(0), Rational(0), false}, false, false};
      auto at = [&](const NavierStokesValues& s, int m) {
        return pick_transport(s, which, d, nonlinear(hcs, d, alpha, m + 1).cooling_rate, dense, alpha);
      };
      const std::array<double, 3> w{at(*s0, n), at(*s1, n + 1), at(*s2, n + 2)};
      auto next = [&] {  // v_{N+3}: for the turning-point check (6.3) and the plateau sum (6.2)
        const auto* s3 = navier_stokes(hcs, d, alpha, n + 3, sonine, dense);
        return s3 == nullptr ? NAN : at(*s3, n + 3);
      };
      const OrderValue v = estimate_from_doubles_confirmed(w[0], w[1], w[2], next);
      if (!summable) return v;
      return summed_if_plateau(n, v, w, order, next);
    });
  }
  /// True where the plateau sum of theory.md (6.2) was checked against the tail scheme: the dilute gas in
  /// the standard scheme (nonlinear HCS), for a2, a3, ζ*, η*, κ*, μ*.
  static bool plateau_summable(SonineScheme sonine, const Dense& dense) {
    return sonine == SonineScheme::standard && dense.phi.sign() == 0;
  }
  /// Returns `v`, the (6.1) estimate of order N = `order_n` from `w` = v_N, v_{N+1}, v_{N+2}, unless it
  /// misses the tolerance of `order` (the scan's, or the row's on a `gkt table` second pass) while N ≥
  /// kFirstPlateauOrder and w alternates on a plateau: then the Euler sum of v_N … v_{N+3} (`next()` gives v_{N+3},
  /// computed only then) if its error meets the tolerance (theory.md (6.2): past the turn of the asymptotic series,
  /// where (6.1) does not apply).
  template <class Next>
  static OrderValue summed_if_plateau(int order_n, const OrderValue& v, const std::array<double, 3>& w,
                                      const OrderRequest& order, Next&& next) {
    const std::optional<Rational> tolerance = order.tolerance ? order.tolerance : order.row_tolerance;
    if (!tolerance || !v.defined || (v.estimate.converging && v.estimate.error < *tolerance)) return v;
    if (order_n < kFirstPlateauOrder) return v;
    std::array<Rational, 4> r{Rational::from_double(w[0]), Rational::from_double(w[1]), Rational::from_double(w[2]),
                              Rational(0)};
    if (!alternates_on_plateau(r[0], r[1], r[2])) return v;
    const double w3 = next();
    if (!std::isfinite(w3)) return v;
    r[3] = Rational::from_double(w3);
    const auto summed = estimate_alternating_plateau(r);
    if (!summed || summed->error >= *tolerance) return v;
    OrderValue out = v;
    out.estimate = *summed;
    return out;
  }
  /// The dense first-Sonine closed form of a transport coefficient (not a stability value), built once.
  const EnskogClosedForm& enskog_form(int d, Transport which) {
    const auto key = std::make_pair(d, which);
    const auto it = enskog_forms_.find(key);
    if (it != enskog_forms_.end()) return it->second;
    return enskog_forms_
        .emplace(key, enskog_first_sonine_closed_form(d, kTransportNames[static_cast<std::size_t>(which)]))
        .first->second;
  }
  /// η*, κ*, μ* at Sonine order N about the nonlinear HCS with a_2..a_{N+1}; null if that HCS has
  /// no solution. Memoised per (d, α, φ, N, scheme).
  const NavierStokesValues* navier_stokes(HomogeneousCoolingState& hcs, int d, const Rational& alpha, int n,
                                          SonineScheme sonine, const Dense& dense) {
    auto key = std::make_tuple(d, dense.key(alpha), 2 * n + (sonine == SonineScheme::modified ? 1 : 0));
    const auto it = ns_memo_.find(key);
    if (it != ns_memo_.end()) return it->second ? &*it->second : nullptr;
    const HcsState& state = nonlinear(hcs, d, alpha, n + 1);
    std::optional<NavierStokesValues> value;
    if (state.solved) {
      auto& solver = ns_[static_cast<std::size_t>(d - 2)];
      if (!solver) solver = std::make_unique<NavierStokesSolver>(d);
      value = solver->solve(alpha, n, state.a, sonine, dense.state());
    }
    const auto& stored = ns_memo_.emplace(std::move(key), value).first->second;
    return stored ? &*stored : nullptr;
  }
  static int cumulant_index(const std::string& c) {
    for (int k = 2; k <= kHighestCumulant; ++k)
      if (c == cumulant_name(k)) return k;
    throw std::invalid_argument(std::string("coefficients: unknown coefficient '") + c +
                                "' for model smooth-inelastic");
  }
  static double pick(const HcsState& s, int k) {
    if (k < 0) return s.cooling_rate;
    return k < static_cast<int>(s.a.size()) ? s.a[static_cast<std::size_t>(k)] : 0.0;
  }
  /// The nonlinear HCS keeping a_2..a_K, memoised per (d, α, K).
  const HcsState& nonlinear(HomogeneousCoolingState& hcs, int d, const Rational& alpha, int k_max) {
    auto key = std::make_tuple(d, alpha.to_string(), k_max);
    const auto it = memo_.find(key);
    if (it != memo_.end()) return it->second;
    return memo_.emplace(std::move(key), hcs.solve(alpha, k_max, HcsScheme::nonlinear)).first->second;
  }

  std::array<std::unique_ptr<HomogeneousCoolingState>, 2> solvers_;
  std::map<std::tuple<int, std::string, int>, HcsState> memo_;
  std::array<std::unique_ptr<NavierStokesSolver>, 2> ns_;
  std::array<std::optional<FirstSonineNavierStokes>, 2> first_sonine_;
  std::map<std::pair<int, Transport>, EnskogClosedForm> enskog_forms_;
  std::map<std::tuple<int, std::string, int>, std::optional<NavierStokesValues>> ns_memo_;
  std::map<std::string, std::vector<TailGalerkinValues>> tail_memo_;
  std::map<std::tuple<int, std::string, int>, HcsTailAmplitude> amplitude_memo_;
};

}  // namespace

std::unique_ptr<TransportModel> make_smooth_inelastic_model() { return std::make_unique<SmoothInelasticModel>(); }

}  // namespace gkt::detail
