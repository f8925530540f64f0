// The "smooth-inelastic" model: smooth inelastic hard spheres/disks with constant normal
// restitution α, dilute (Boltzmann) or dense (Enskog, packing fraction φ > 0). Provides the
// homogeneous cooling state (cumulants a2…a13, cooling rate; homogeneous_cooling_state.hpp),
// the pressure and the Navier–Stokes coefficients η*, κ*, μ*, bulk viscosity
// (navier_stokes.hpp, theory.md §10, §15). Order N keeps N Sonine polynomials per
// transport mode and the cumulants a_2 … a_{N+1}.
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>

#include "gkt/evolution/hcs_stability.hpp"
#include "gkt/transport/closed_forms/enskog_closed_form.hpp"
#include "gkt/transport/common/pair_correlation.hpp"
#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"
#include "models/models.hpp"

namespace gkt::detail {

namespace {

constexpr int kHighestCumulant = 13;
constexpr int kMaxOrder = kHighestCumulant - 1;

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
           "standard or modified Sonine scheme";
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
    return names;
  }
  [[nodiscard]] std::vector<ParameterSpec> parameters() const override {
    return {{"dimension",
             ParameterSpec::Kind::integer,
             Rational(2),
             Rational(3),
             true,
             true,
             Rational(3),
             "spatial dimension",
             {}},
            {"alpha",
             ParameterSpec::Kind::real,
             Rational(0),
             Rational(1),
             false,
             true,
             Rational(1),
             "normal restitution coefficient",
             {}},
            {"hcs",
             ParameterSpec::Kind::choice,
             Rational(0),
             Rational(0),
             true,
             true,
             Rational(0),
             "cumulant scheme of the homogeneous cooling state",
             {"nonlinear", "linear"}},
            {"scheme",
             ParameterSpec::Kind::choice,
             Rational(0),
             Rational(0),
             true,
             true,
             Rational(0),
             "Sonine trial-function weight of the Navier-Stokes coefficients: Maxwellian or HCS",
             {"standard", "modified"}},
            {"packing_fraction",
             ParameterSpec::Kind::real,
             Rational(0),
             max_packing_fraction(2),
             true,
             true,
             Rational(0),
             "packing fraction phi (0 = dilute; Enskog theory above; at most 0.5 in 3D, 0.7 in 2D)",
             {}},
            {"pair_correlation", ParameterSpec::Kind::choice, Rational(0), Rational(0), true, true, Rational(0),
             "contact value chi(phi) of the pair correlation", pair_correlation_names()}};
  }
  [[nodiscard]] int max_order() const override { return kMaxOrder; }

  std::vector<CoefficientValue> evaluate(const ParameterPoint& point, const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    const auto specs = parameters();
    const Rational dim = point.number("dimension", Rational(3));
    specs[0].check(dim);
    const Rational alpha = point.number("alpha", Rational(1));
    specs[1].check(alpha);
    const std::string scheme = point.choice("hcs", "nonlinear");
    specs[2].check(scheme);
    const std::string weight = point.choice("scheme", "standard");
    specs[3].check(weight);
    const SonineScheme sonine = weight == "modified" ? SonineScheme::modified : SonineScheme::standard;
    const Rational phi = point.number("packing_fraction", Rational(0));
    specs[4].check(phi);
    const std::string closure = point.choice("pair_correlation", pair_correlations().front().name);
    specs[5].check(closure);
    const int d = dim == Rational(2) ? 2 : 3;
    if (phi > max_packing_fraction(d))
      throw std::invalid_argument("packing_fraction: must be a number in [0, " +
                                  max_packing_fraction(d).to_decimal_string() +
                                  "] for dimension = " + std::to_string(d) + ", got " + phi.to_decimal_string());
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
    std::vector<CoefficientValue> out;
    for (const auto& c : coefficients) {
      if (c == "pressure") {  // exact, independent of the cumulants
        out.push_back({reduced_pressure(d, alpha, phi * chi), Rational(0), order.order, true, true, true});
        continue;
      }
      const int transport = transport_index(c);
      if (transport >= 0) {
        out.push_back(transport_value(*hcs, d, alpha, scheme, sonine, dense, transport, order));
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
      out.push_back(choose_order(order, max_order(), [&](int n) {
        const auto& s0 = nonlinear(*hcs, d, alpha, n + 1);
        const auto& s1 = nonlinear(*hcs, d, alpha, n + 2);
        const auto& s2 = nonlinear(*hcs, d, alpha, n + 3);
        OrderValue v;
        v.exact = false;
        v.defined = s0.solved && s1.solved && s2.solved;
        if (!v.defined) return v;
        v.estimate =
            estimate_truncation(Rational::from_double(pick(s0, k)) * scale, Rational::from_double(pick(s1, k)) * scale,
                                Rational::from_double(pick(s2, k)) * scale);
        return v;
      }));
    }
    return out;
  }

 private:
  /// 0 shear viscosity, 1 thermal conductivity, 2 density heat coefficient, 3–5 the HCS stability
  /// values of theory.md §14 (from ζ*, η*, κ*, μ* at the same order), 6 bulk viscosity, 7 ζ_U;
  /// −1 otherwise.
  static int transport_index(const std::string& c) {
    if (c == "shear_viscosity") return 0;
    if (c == "thermal_conductivity") return 1;
    if (c == "density_heat_coefficient") return 2;
    if (c == "critical_wavenumber_shear") return 3;
    if (c == "critical_wavenumber_heat") return 4;
    if (c == "critical_length") return 5;
    if (c == "bulk_viscosity") return 6;
    if (c == "cooling_rate_first_order") return 7;
    return -1;
  }
  /// The transport value `which` from one order's η*, κ*, μ*, …; the stability values (3–5) also
  /// need the dilute ζ* of the same order and the density (theory.md (14.4)–(14.5)).
  static double pick_transport(const NavierStokesValues& v, int which, int d, double zeta_dilute, const Dense& dense,
                               const Rational& alpha) {
    if (which == 6) return v.bulk_viscosity;
    if (which == 7) return v.cooling_rate_first_order;
    if (which < 3)
      return which == 0 ? v.shear_viscosity : which == 1 ? v.thermal_conductivity : v.density_heat_coefficient;
    const EnskogState st = dense.state();
    const double a = alpha.to_double(), phi = st.packing_fraction;
    StabilityDensity density;
    density.pressure = st.pressure(d, a);
    density.pressure_derivative = (d == 3 ? 2.0 : 1.0) * (1 + a) * phi * (st.chi + st.phi_dchi);  // φ ∂p*/∂φ
    density.log_chi_derivative = st.phi_dchi / st.chi;
    density.bulk_viscosity = v.bulk_viscosity;
    density.cooling_rate_first_order = v.cooling_rate_first_order;
    const HcsStability s = hcs_stability(d, st.chi * zeta_dilute, v.shear_viscosity, v.thermal_conductivity,
                                         v.density_heat_coefficient, density);
    return which == 3 ? s.shear_wavenumber : which == 4 ? s.heat_wavenumber : s.critical_length;
  }
  CoefficientValue transport_value(HomogeneousCoolingState& hcs, int d, const Rational& alpha,
                                   const std::string& scheme, SonineScheme sonine, const Dense& dense, int which,
                                   const OrderRequest& order) {
    if (scheme == "linear") {
      // First Sonine about f_M(1 + a2 S2) with the van Noije–Ernst a2; error against orders 2, 3.
      const HcsState linear = hcs.solve(alpha, 2, HcsScheme::linear);
      const Rational a2 = *linear.exact_a2;
      const double zeta_linear = linear.exact_cooling_rate->to_double();  // ζ0 + a2 ζ2, dilute
      Rational value;          // exact: η*, κ*, μ* of the dilute closed forms
      double approximate = 0;  // otherwise (square roots, solver output; +∞ for L_c* of the elastic gas)
      bool exact = false;
      if ((dense.phi.sign() > 0 || which >= 6) && sonine == SonineScheme::standard) {
        // The dense closed forms, linear in a2 like Garzó–Dufty's (theory.md §15.7).
        const EnskogState st = dense.state();
        auto form = [&](int k) { return enskog_form(d, k).evaluate(alpha, st.packing_fraction, st.chi, st.phi_dchi); };
        if (which >= 3 && which <= 5) {
          const NavierStokesValues v1{form(0), form(1), form(2), form(6), form(7)};
          approximate = pick_transport(v1, which, d, zeta_linear, dense, alpha);
        } else {
          approximate = form(which);
        }
      } else if (dense.phi.sign() > 0 || which >= 6) {
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
        exact = which < 3;
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
    return choose_order(order, max_order(), [&](int n) {
      const auto* s0 = navier_stokes(hcs, d, alpha, n, sonine, dense);
      const auto* s1 = navier_stokes(hcs, d, alpha, n + 1, sonine, dense);
      const auto* s2 = navier_stokes(hcs, d, alpha, n + 2, sonine, dense);
      if (s0 == nullptr || s1 == nullptr || s2 == nullptr)  // no HCS solution at some order: undefined
        return OrderValue{{Rational(0), Rational(0), false}, false, false};
      return estimate_from_doubles(
          pick_transport(*s0, which, d, nonlinear(hcs, d, alpha, n + 1).cooling_rate, dense, alpha),
          pick_transport(*s1, which, d, nonlinear(hcs, d, alpha, n + 2).cooling_rate, dense, alpha),
          pick_transport(*s2, which, d, nonlinear(hcs, d, alpha, n + 3).cooling_rate, dense, alpha));
    });
  }
  /// The dense first-Sonine closed form of transport coefficient `which` (0–2, 6, 7), built once.
  const EnskogClosedForm& enskog_form(int d, int which) {
    static const char* const names[] = {
        "shear_viscosity", "thermal_conductivity",    "density_heat_coefficient", "", "", "",
        "bulk_viscosity",  "cooling_rate_first_order"};
    const auto key = std::make_pair(d, which);
    const auto it = enskog_forms_.find(key);
    if (it != enskog_forms_.end()) return it->second;
    return enskog_forms_.emplace(key, enskog_first_sonine_closed_form(d, names[which])).first->second;
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
  std::map<std::pair<int, int>, EnskogClosedForm> enskog_forms_;
  std::map<std::tuple<int, std::string, int>, std::optional<NavierStokesValues>> ns_memo_;
};

}  // namespace

std::unique_ptr<TransportModel> make_smooth_inelastic_model() { return std::make_unique<SmoothInelasticModel>(); }

}  // namespace gkt::detail
