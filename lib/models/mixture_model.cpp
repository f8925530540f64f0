// The "mixture" transport model (docs/conventions.md): s = 2 … 4 smooth inelastic species,
// dilute or dense: the homogeneous cooling state (temperature ratios, cooling rate, the species
// cumulants a2,i; theory.md §16) and the Navier–Stokes coefficients at any Sonine order (theory.md
// §17 dilute, §18 dense).
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>

#include "gkt/evolution/hcs_stability.hpp"
#include "gkt/evolution/mixture_cooling_evolution.hpp"
#include "gkt/models/cooling_trajectory.hpp"
#include "gkt/transport/common/pair_correlation.hpp"
#include "gkt/transport/common/sonine_solution.hpp"
#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/mixture_basis_width.hpp"
#include "gkt/transport/mixture/mixture_cooling_state.hpp"
#include "gkt/transport/mixture/mixture_navier_stokes.hpp"
#include "gkt/transport/mixture/tracer_diffusion.hpp"
#include "models/models.hpp"

namespace gkt {

namespace {

constexpr int kMaxSpecies = 4;

std::string index_name(const std::string& base, int i) { return base + "_" + std::to_string(i); }
std::string index_name(const std::string& base, int i, int j) { return index_name(index_name(base, i), j); }

ParameterSpec real(const std::string& name, const Rational& min, bool min_inclusive, const Rational& max,
                   bool max_inclusive, const Rational& fallback, const std::string& description) {
  return {name, ParameterSpec::Kind::real, min, max, min_inclusive, max_inclusive, fallback, description, {}};
}

class MixtureModel final : public TransportModel {
 public:
  [[nodiscard]] std::string name() const override { return "mixture"; }
  [[nodiscard]] std::string description() const override {
    return "granular mixture of s = 2..4 smooth inelastic hard spheres/disks (dilute or Enskog): homogeneous "
           "cooling state (first Sonine or Maxwellian); Navier-Stokes coefficients at any order";
  }
  [[nodiscard]] std::vector<std::string> coefficient_names() const override {
    auto n = names(kMaxSpecies, kMaxHcsOrder);
    for (const auto& t : transport_names(kMaxSpecies)) n.push_back(t);
    for (int i = 1; i <= 2; ++i) n.push_back(index_name("tracer_diffusion", i));
    return n;
  }
  [[nodiscard]] std::vector<std::string> scene_coefficient_names(const ParameterPoint& fixed) const override {
    const int s = static_cast<int>(fixed.number("species", Rational(kMaxSpecies)).to_double());
    auto n = names(s, hcs_order(fixed));
    for (const auto& t : transport_names(s)) n.push_back(t);
    if (s == 2)
      for (int i = 1; i <= 2; ++i) n.push_back(index_name("tracer_diffusion", i));
    return n;
  }
  /// The HCS always; the Navier–Stokes coefficients and the HCS stability when the scene fixes φ,
  /// with p*, bulk viscosity and ζ_U too at φ > 0 (theory.md §18) — a sweep over φ lists the HCS
  /// only unless it names its coefficients;
  /// tracer_diffusion_i only when asked for (a property of the pair at infinite dilution, not of
  /// the scene's composition).
  [[nodiscard]] std::vector<std::string> default_coefficients(const ParameterPoint& fixed) const override {
    const int s = static_cast<int>(fixed.number("species", Rational(kMaxSpecies)).to_double());
    auto n = names(s, hcs_order(fixed));
    const Rational phi = fixed.number("packing_fraction", Rational(-1));
    for (const auto& t : transport_names(s))
      if (!on_request(t) && (phi.sign() > 0 || (phi.sign() == 0 && !dense_only(t)))) n.push_back(t);
    return n;
  }
  [[nodiscard]] std::vector<ParameterSpec> parameters() const override {
    std::vector<ParameterSpec> p{
        detail::dimension_spec(),
        {"species",
         ParameterSpec::Kind::integer,
         Rational(2),
         Rational(kMaxSpecies),
         true,
         true,
         Rational(2),
         "number of species (set by the [[species]] tables)",
         {}},
        real("packing_fraction", Rational(0), true, max_packing_fraction(2), false, Rational(0),
             "packing fraction phi (below 0.5 in 3D, 0.7 in 2D)"),
        detail::restitution_spec("alpha", "restitution coefficient of every pair (alpha_i_j overrides one pair)"),
        real("reduced_gravity", Rational(-1000000L), true, Rational(1000000L), true, Rational(0),
             "g* = rho g/(n dT/dz) of the segregation criterion thermal_diffusion_factor_i "
             "(dp/dz = -rho g)"),
        hcs_spec(),
        detail::choice_spec("scheme",
                            "truncation of the Navier-Stokes equations: gkt's Galerkin method at any order "
                            "(Maxwellian-weighted trial functions, all coupled) or Garzo-Hrenya-Dufty's published "
                            "first Sonine (order 1: mass flux solved alone, partial temperatures dropped)",
                            {"standard", "published"}),
        detail::choice_spec("reference_state",
                            "species distributions f0 of the Navier-Stokes coefficients: Maxwellian at T_i (GDH) or "
                            "the HCS of `hcs` with its cumulants a_2 ... a_K (K = hcs_order)",
                            {"maxwellian", "hcs"}),
        detail::choice_spec("basis_width",
                            "Gaussian width of each species' vector Sonine basis (dilute, Maxwellian reference): its "
                            "own temperature T_i, or the automatic width of theory.md (17.30) from the species' tail "
                            "exponents (wider at strong dissipation, where the standard series turns)",
                            {"standard", "auto"}),
        {"hcs_order",
         ParameterSpec::Kind::integer,
         Rational(2),
         Rational(kMaxHcsOrder),
         true,
         true,
         Rational(2),
         "highest cumulant a_K of each species in the HCS",
         {}}};
    for (int i = 1; i <= kMaxSpecies; ++i) {
      p.push_back(real(index_name("mass", i), Rational(0), false, Rational(1000000000L), true, Rational(1),
                       "mass of species i (any unit)"));
      p.push_back(real(index_name("diameter", i), Rational(0), false, Rational(1000000000L), true, Rational(1),
                       "diameter of species i (any unit)"));
      p.push_back(real(index_name("fraction", i), Rational(0), true, Rational(1), true, Rational(1),
                       "mole fraction x_i (the fractions sum to 1; 0 = tracer)"));
    }
    for (int i = 1; i <= kMaxSpecies; ++i)
      for (int j = i; j <= kMaxSpecies; ++j)
        p.push_back(detail::restitution_spec(index_name("alpha", i, j), "restitution coefficient of the pair (i, j)"));
    return p;
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
  [[nodiscard]] int max_order() const override { return kMaxOrder; }
  [[nodiscard]] bool supports(Capability capability) const override {
    return capability == Capability::table || capability == Capability::stability || capability == Capability::evolve;
  }

  /// The keys of `gkt evolve`: the mixture's own (species, α, φ, hcs, hcs_order), the initial
  /// T_i(0)/T(0) and a2,i(0) of every species, and CVODE's tolerances (theory.md §16.7).
  [[nodiscard]] std::vector<ParameterSpec> evolution_parameters() const override {
    std::vector<ParameterSpec> specs;
    for (const auto& spec : parameters())
      if (spec.name != "reduced_gravity" && spec.name != "reference_state" && spec.name != "basis_width")
        specs.push_back(spec);
    const ParameterSpec a2 = detail::evolution_a2_spec(2);  // the union of both dimensions' ranges; evolve() checks d's
    for (int i = 1; i <= kMaxSpecies; ++i) {
      specs.push_back(real(index_name("temperature_ratio", i), Rational(0), false, Rational(1000000L), true,
                           Rational(1),
                           "initial T_i(0)/T(0) of species i (sum_i x_i T_i/T = 1; default: equipartition)"));
      ParameterSpec a = a2;
      a.name = index_name("a2_species", i);
      a.description = "initial a2 of species i (hcs = \"linear\" or \"nonlinear\")";
      specs.push_back(a);
    }
    for (auto& spec : detail::evolution_common_parameters())
      if (spec.name == "rtol" || spec.name == "atol" || spec.name == "max_steps") specs.push_back(std::move(spec));
    return specs;
  }

  /// T(τ)/T(0), T_i/T, the a_k,i and ζ* from mixture_cooling_state's equations away from the HCS,
  /// integrated from the given start (theory.md §16.7).
  Trajectory evolve(const TrajectoryRequest& request) override {
    if (!request.coefficients.empty())
      throw std::invalid_argument("coefficients: none are offered along a mixture trajectory");
    const detail::SchemaPoint p(evolution_parameters(), request.parameters);
    const Mixture mixture = make(p);
    const auto s = static_cast<int>(mixture.size());
    const std::string hcs = p.choice("hcs");
    const MixtureHcsScheme scheme = hcs == "maxwellian" ? MixtureHcsScheme::maxwellian
                                    : hcs == "linear"   ? MixtureHcsScheme::linear
                                                        : MixtureHcsScheme::nonlinear;
    const int k_max = hcs_order(request.parameters);
    std::vector<double> ratio;
    std::vector<std::vector<double>> cumulants;
    for (int i = 1; i <= s; ++i) {
      ratio.push_back(p.number(index_name("temperature_ratio", i)).to_double());
      const std::string a2 = index_name("a2_species", i);
      if (p.given(a2) && scheme == MixtureHcsScheme::maxwellian)
        throw std::invalid_argument(a2 + ": hcs = \"maxwellian\" carries no cumulants");
      ParameterSpec range = detail::evolution_a2_spec(mixture.dimension);
      range.name = a2;
      range.check(p.number(a2));
      if (scheme != MixtureHcsScheme::maxwellian) cumulants.push_back({p.number(a2).to_double()});
    }
    for (int i = s + 1; i <= kMaxSpecies; ++i)
      for (const std::string& key : {index_name("temperature_ratio", i), index_name("a2_species", i)})
        if (p.given(key)) throw std::invalid_argument(key + ": the scene has " + std::to_string(s) + " species");
    const MixtureEvolutionResult result =
        evolve_mixture_cooling(mixture, scheme, k_max, ratio, cumulants, request.times, p.number("rtol").to_double(),
                               p.number("atol").to_double(), static_cast<long>(p.number("max_steps").to_double()));
    Trajectory t;
    t.columns = {"time", "temperature"};
    for (int i = 1; i <= s; ++i) t.columns.push_back(index_name("temperature_ratio", i));
    const int carried = scheme == MixtureHcsScheme::maxwellian ? 1 : k_max;
    for (int q = 2; q <= carried; ++q)
      for (int i = 1; i <= s; ++i) t.columns.push_back(index_name(cumulant_base(q), i));
    t.columns.emplace_back("cooling_rate");
    for (const auto& sample : result.samples) {
      std::vector<double> row{sample.time, sample.temperature};
      for (const double g : sample.temperature_ratio) row.push_back(g);
      for (int q = 2; q <= carried; ++q)
        for (const auto& c : sample.cumulants) row.push_back(c[static_cast<std::size_t>(q)]);
      row.push_back(sample.cooling_rate);
      t.rows.push_back(std::move(row));
    }
    t.counters = result.counters;
    return t;
  }

  std::vector<CoefficientValue> evaluate(const ParameterPoint& point, const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    const detail::SchemaPoint p(parameters(), point);  // validated by the registry's guard
    const std::string hcs = p.choice("hcs");
    if (hcs_memo_.size() > 256) hcs_memo_.clear();  // bound memory in long sweeps (never mid-evaluation)
    const Mixture mixture = make(p);
    const auto s = static_cast<int>(mixture.size());
    std::vector<CoefficientValue> out;
    const int hcs_k = hcs_order(point);
    // What a name asks for: the HCS (ζ*, T_i/T, a_k,i), D* of a tracer, or a transport value.
    enum class Kind { cooling_rate, temperature_ratio, cumulant, tracer_diffusion, transport };
    std::optional<MixtureCoolingState> chosen, alternative, higher;  // solved once, if an HCS value is asked for
    TransportCache transport;                                        // built once, if a transport value is asked for
    transport.gravity = p.number("reduced_gravity").to_double();
    transport.published = p.choice("scheme") == "published";
    const MixtureHcsScheme scheme = hcs == "maxwellian" ? MixtureHcsScheme::maxwellian
                                    : hcs == "linear"   ? MixtureHcsScheme::linear
                                                        : MixtureHcsScheme::nonlinear;

    struct Parsed {
      Kind kind;
      int i, cumulant;  // species from 1 (0: none), cumulant index (0: none)
    };
    auto parse = [&](const std::string& c) {
      Parsed q{c == "cooling_rate" ? Kind::cooling_rate : Kind::transport, 0, 0};
      for (int k = 1; k <= s; ++k) {
        if (c == index_name("temperature_ratio", k)) q = {Kind::temperature_ratio, k, 0};
        for (int n = 2; n <= hcs_k; ++n)
          if (c == index_name(cumulant_base(n), k)) q = {Kind::cumulant, k, n};
        if (c == index_name("tracer_diffusion", k)) q = {Kind::tracer_diffusion, k, 0};
      }
      return q;
    };
    // `tolerance` without `hcs_order` (first Sonine or more): one cumulant order K for every HCS value
    // of the call, the smallest at which successive K agree within it (theory.md §16.3).
    const std::optional<Rational> tolerance = order.tolerance ? order.tolerance : order.row_tolerance;
    const bool scan = tolerance && !point.numbers.contains("hcs_order") && scheme != MixtureHcsScheme::maxwellian;
    std::vector<HcsPick> picks;
    for (const auto& c : coefficients)
      if (const Parsed q = parse(c); scan && q.kind != Kind::transport && q.kind != Kind::tracer_diffusion)
        picks.push_back({q.kind == Kind::cooling_rate ? -1 : q.i - 1, q.cumulant});
    const std::string memo = scan ? memo_key(point) : std::string();
    const int scan_k = picks.empty() ? 0 : common_hcs_order(mixture, scheme, memo, picks, *tolerance);
    // f0 of the transport coefficients: Maxwellian (GDH) or this HCS with a_2 … a_K (theory.md §17.11), K =
    // hcs_order or, with a tolerance and no hcs_order, the smallest K at which ζ*, every T_i/T and every
    // a2,i differ from their values at K + 1 by less than the tolerance (the scan above).
    if (p.choice("reference_state") == "hcs") {
      if (transport.published)
        throw std::invalid_argument(
            "reference_state: \"hcs\" cannot be combined with scheme = \"published\" (GDH's first Sonine is "
            "about Maxwellians); use reference_state = \"maxwellian\" or scheme = \"standard\"");
      int k = hcs_k;
      if (scan) {
        std::vector<HcsPick> all{{-1, 0}};
        for (int i = 0; i < s; ++i) all.push_back({i, 0}), all.push_back({i, 2});
        k = common_hcs_order(mixture, scheme, memo_key(point), all, *tolerance);
      }
      transport.reference = {scheme, k};
    }
    // basis_width = "auto": one width for every species' vector basis (theory.md (17.30)); all 1 is the
    // standard basis, kept as such (the wide build costs ≈ 2.3 times the standard one).
    if (p.choice("basis_width") == "auto") {
      if (transport.published)
        throw std::invalid_argument(
            "basis_width: \"auto\" cannot be combined with scheme = \"published\" (GDH's first Sonine is defined "
            "in the standard basis); use basis_width = \"standard\"");
      if (p.choice("reference_state") == "hcs")
        throw std::invalid_argument(
            "basis_width: \"auto\" needs reference_state = \"maxwellian\" (the cumulant reference keeps the "
            "standard basis)");
      if (mixture.packing_fraction > 0)
        throw std::invalid_argument("basis_width: \"auto\" is for the dilute gas only (packing_fraction = 0)");
      const std::vector<double> w = mixture_basis_width(mixture, mixture_cooling_state(mixture));
      if (std::any_of(w.begin(), w.end(), [](double v) { return v != 1.0; })) transport.reference.basis_width = w;
    }
    for (const auto& c : coefficients) {
      const Parsed parsed = parse(c);
      const Kind kind = parsed.kind;
      const int i = parsed.i, cumulant = parsed.cumulant;
      if (kind == Kind::transport) {
        const auto all = transport_names(s);
        if (std::find(all.begin(), all.end(), c) == all.end())
          throw std::invalid_argument("coefficients: unknown coefficient '" + c + "' for " + std::to_string(s) +
                                      " species; valid: " + detail::join(names(s, hcs_k)) + ", " + detail::join(all));
        out.push_back(transport.value(mixture, c, order));
        continue;
      }
      const auto k = static_cast<std::size_t>(i > 0 ? i - 1 : 0);
      if (kind == Kind::tracer_diffusion) {
        MixtureReference tracer = transport.reference;
        tracer.basis_width.clear();  // D* of a tracer keeps the standard basis (its own Sonine series)
        out.push_back(tracer_diffusion(mixture, k, order, tracer));
        continue;
      }
      // The HCS carries a_2 … a_K (K = hcs_order) whatever the transport order. The errors of ζ* and
      // T_i/T are the difference from the Maxwellian (or first-Sonine) state, those of the a_k,i the
      // difference from the linear scheme at K + 1 (theory.md §16.3).
      if (scan) {
        const HcsPick pick{kind == Kind::cooling_rate ? -1 : static_cast<int>(k), cumulant};
        const MixtureCoolingState &here = hcs_state(mixture, scheme, memo, scan_k),
                                  &next = hcs_state(mixture, scheme, memo, scan_k + 1);
        const double v = pick(here), error = std::abs(v - pick(next));
        out.push_back({Rational::from_double(v), Rational::from_double(error), order.tolerance ? 1 : order.order,
                       here.solved && next.solved && error < tolerance->to_double(), false, here.solved, true});
        continue;
      }
      if (!chosen) {
        chosen = mixture_cooling_state(mixture, scheme, hcs_k);
        alternative = mixture_cooling_state(
            mixture, scheme == MixtureHcsScheme::maxwellian ? MixtureHcsScheme::linear : MixtureHcsScheme::maxwellian);
      }
      if (kind == Kind::cumulant && !higher)
        higher = mixture_cooling_state(mixture, MixtureHcsScheme::linear, hcs_k + 1);
      const MixtureCoolingState& state = *chosen;
      const MixtureCoolingState& other = *alternative;
      auto value = [&](double v, double other_value, bool estimated) {
        return CoefficientValue{Rational::from_double(v),
                                Rational::from_double(std::abs(v - other_value)),
                                order.tolerance ? 1 : order.order,
                                state.solved && other.solved,
                                false,
                                state.solved,
                                estimated};
      };
      if (kind == Kind::cooling_rate)
        out.push_back(value(state.cooling_rate, other.cooling_rate, true));
      else if (kind == Kind::temperature_ratio)
        out.push_back(value(state.temperature_ratio[k], other.temperature_ratio[k], true));
      else {
        const auto q = static_cast<std::size_t>(cumulant);
        CoefficientValue v = value(state.cumulants[k][q], higher->cumulants[k][q], true);
        v.converged = v.converged && higher->solved;
        out.push_back(v);
      }
    }
    return out;
  }

 private:
  static constexpr int kMaxOrder = 12;

  static ParameterSpec hcs_spec() {
    return detail::choice_spec(
        "hcs",
        "species distributions of the homogeneous cooling state: first Sonine (a2 of each species, linear or "
        "nonlinear in them) or Maxwellian",
        {"linear", "nonlinear", "maxwellian"});
  }

  /// One HCS value of a tolerance scan: ζ* (species < 0), T_i/T (cumulant 0) or a_q,i (species from 0).
  struct HcsPick {
    int species, cumulant;
    [[nodiscard]] double operator()(const MixtureCoolingState& st) const {
      const auto i = static_cast<std::size_t>(species < 0 ? 0 : species);
      return species < 0     ? st.cooling_rate
             : cumulant == 0 ? st.temperature_ratio[i]
                             : st.cumulants[i][static_cast<std::size_t>(cumulant)];
    }
  };

  /// Returns the HCS at cumulant order K, solved once per parameter point (`memo` its key).
  const MixtureCoolingState& hcs_state(const Mixture& mixture, MixtureHcsScheme scheme, const std::string& memo,
                                       int k) {
    const std::string key = memo + "K" + std::to_string(k);
    if (auto it = hcs_memo_.find(key); it != hcs_memo_.end()) return it->second;
    return hcs_memo_.emplace(key, mixture_cooling_state(mixture, scheme, k)).first->second;
  }

  /// Returns the smallest K ∈ [max(2, q), kMaxHcsOrder] at which every pick's value differs from its
  /// value at K + 1 by less than `tolerance`; else the K of the smallest largest difference (the
  /// values are then flagged, and the CLI warns).
  int common_hcs_order(const Mixture& mixture, MixtureHcsScheme scheme, const std::string& memo,
                       const std::vector<HcsPick>& picks, const Rational& tolerance) {
    int lowest = 2;
    for (const HcsPick& pick : picks) lowest = std::max(lowest, pick.cumulant);
    const double limit = tolerance.to_double();
    int best = kMaxHcsOrder;
    double best_error = INFINITY;
    for (int k = lowest; k <= kMaxHcsOrder; ++k) {
      const MixtureCoolingState &here = hcs_state(mixture, scheme, memo, k),
                                &next = hcs_state(mixture, scheme, memo, k + 1);
      if (!here.solved || !next.solved) continue;
      double worst = 0;
      for (const HcsPick& pick : picks) worst = std::max(worst, std::abs(pick(here) - pick(next)));
      if (worst < limit) return k;
      if (worst < best_error) best = k, best_error = worst;
    }
    return best;
  }

  /// D* of species k as a tracer in the other species of a dilute binary (theory.md §16.5) about the
  /// `reference` (§17.11), at the requested order or tolerance; error from the next two orders.
  static CoefficientValue tracer_diffusion(const Mixture& m, std::size_t k, const OrderRequest& order,
                                           const MixtureReference& reference) {
    const std::string name = "tracer_diffusion_" + std::to_string(k + 1);
    if (m.size() != 2) throw std::invalid_argument("coefficients: " + name + " needs exactly 2 species");
    if (m.packing_fraction > 0)
      throw std::invalid_argument("coefficients: " + name +
                                  " is computed for the dilute gas only (packing_fraction = 0)");
    const std::size_t h = 1 - k;
    const Tracer tracer{m.dimension, ExactValue(m.species[k].mass.exact() / m.species[h].mass.exact()),
                        m.species[k].diameter / m.species[h].diameter, m.restitution(k, h), m.restitution(h, h)};
    // Built for the order asked (+2 for the estimate); a tolerance scan rebuilds it larger as it goes.
    std::optional<TracerDiffusion> diffusion;
    return detail::choose_order(order, kMaxOrder, [&](int n) {
      // Order n + 3 too for the turning-point check (6.3) of theory.md §6 (the estimate reads it only where the
      // changes change sign; at the cap, where it is past the operator, the turn is not confirmed).
      const int needed = std::min(kMaxOrder + 2, n + 3);
      if (!diffusion || diffusion->max_order() < needed)
        diffusion.emplace(tracer, std::min(kMaxOrder + 2, std::max(needed, diffusion ? 2 * diffusion->max_order() : 6)),
                          reference);
      detail::OrderValue v;
      v.exact = false;
      // Undefined (no positive D*, e.g. a heavy tracer at strong dissipation) unless orders n … n+2
      // are finite and D*(n) > 0; only then the estimate, which converts them to exact rationals.
      const double value = diffusion->coefficient(n);
      v.defined = value > 0 && std::isfinite(value) && std::isfinite(diffusion->coefficient(n + 1)) &&
                  std::isfinite(diffusion->coefficient(n + 2));
      if (v.defined) v.estimate = diffusion->estimate(n);
      return v;
    });
  }

  /// The mixture's Navier–Stokes operator for one parameter point, grown as orders are asked for,
  /// and the coefficients of every order solved so far.
  struct TransportCache {
    struct AtOrder {
      MixtureTransportValues values;
      HcsStability stability;  ///< critical wave numbers from this order's coefficients (nan if η* or λ* ≤ 0)
    };
    std::optional<MixtureNavierStokes> operators;
    std::map<int, AtOrder> by_order;
    std::optional<AtOrder> published_values;  ///< GDH's first Sonine (scheme = "published"), solved once
    double gravity = 0;                       ///< g* of the segregation criterion
    bool published = false;                   ///< scheme = "published" (theory.md §17.10)
    MixtureReference reference;               ///< f0 of the coefficients (Maxwellian unless reference_state = "hcs")

    /// Returns GDH's published first-Sonine values (MixtureTruncation::published) of the point.
    const AtOrder& at_published(const Mixture& m) {
      if (published_values) return *published_values;
      if (!operators) operators.emplace(m, 6);
      AtOrder a{operators->coefficients(1, MixtureTruncation::published), {NAN, NAN, NAN}};
      const MixtureTransportValues& v = a.values;
      if (v.shear_viscosity > 0 && v.thermal_conductivity > 0)
        a.stability = mixture_hcs_stability(mixture_stability_input(m, *operators, v));
      return published_values.emplace(std::move(a));
    }

    const AtOrder& at(const Mixture& m, int n) {
      if (const auto it = by_order.find(n); it != by_order.end()) return it->second;
      if (!operators || operators->max_order() < n)
        operators.emplace(m, std::min(kMaxOrder + 2, std::max(n, operators ? 2 * operators->max_order() : 6)),
                          reference);
      AtOrder a{operators->coefficients(n), {NAN, NAN, NAN}};
      const MixtureTransportValues& v = a.values;
      if (v.shear_viscosity > 0 && v.thermal_conductivity > 0)
        a.stability = mixture_hcs_stability(mixture_stability_input(m, *operators, v));
      return by_order.emplace(n, std::move(a)).first->second;
    }

    /// Returns how the transport value `name` of s species is read from one order's values: resolved
    /// once per coefficient through tables of the scalar and the per-species (pair) values.
    [[nodiscard]] std::function<double(const AtOrder&)> reader(std::size_t s, const std::string& name) const {
      using Scalar = double (*)(const AtOrder&);
      static const std::map<std::string, Scalar> scalars{
          {"critical_wavenumber_shear", [](const AtOrder& a) { return a.stability.shear_wavenumber; }},
          {"critical_wavenumber_heat", [](const AtOrder& a) { return a.stability.heat_wavenumber; }},
          {"critical_length", [](const AtOrder& a) { return a.stability.critical_length; }},
          {"shear_viscosity", [](const AtOrder& a) { return a.values.shear_viscosity; }},
          {"thermal_conductivity", [](const AtOrder& a) { return a.values.thermal_conductivity; }},
          {"bulk_viscosity", [](const AtOrder& a) { return a.values.bulk_viscosity; }},
          {"cooling_rate_first_order", [](const AtOrder& a) { return a.values.cooling_rate_first_order; }},
          {"pressure", [](const AtOrder& a) { return a.values.pressure; }}};
      using Vector = std::vector<double> MixtureTransportValues::*;
      static const std::map<std::string, Vector> per_species{
          {"thermal_diffusion", &MixtureTransportValues::thermal_diffusion},
          {"pressure_diffusion", &MixtureTransportValues::pressure_diffusion},
          {"dufour", &MixtureTransportValues::dufour},
          {"heat_mobility", &MixtureTransportValues::heat_mobility}};
      static const std::map<std::string, Vector> per_pair{
          {"mutual_diffusion", &MixtureTransportValues::mutual_diffusion},
          {"mobility", &MixtureTransportValues::mobility}};
      if (const auto it = scalars.find(name); it != scalars.end()) return it->second;
      for (std::size_t i = 0; i < s; ++i) {
        const int a = static_cast<int>(i) + 1;
        for (const auto& [base, field] : per_species)
          if (name == index_name(base, a)) return [i, f = field](const AtOrder& o) { return (o.values.*f)[i]; };
        if (name == index_name("thermal_diffusion_factor", a))
          return [i, g = gravity](const AtOrder& o) {
            const MixtureTransportValues& v = o.values;
            return v.segregation.empty() ? NAN : v.segregation[i] + g * v.segregation_gravity[i];
          };
        for (std::size_t j = 0; j < s; ++j)
          for (const auto& [base, field] : per_pair)
            if (name == index_name(base, a, static_cast<int>(j) + 1))
              return [k = i * s + j, f = field](const AtOrder& o) { return (o.values.*f)[k]; };
      }
      throw std::logic_error("mixture: no transport value named " + name);
    }

    /// Returns the coefficient `name` at the requested order or tolerance, its error from the next
    /// two orders, three where their changes change sign (theory.md (6.3)), undefined (nan) if a value is not finite.
    /// With scheme = "published" the value is GDH's first Sonine (order 1 only), its error estimated
    /// from it and gkt's orders 2 and 3 as (6.1) does from orders 1 … 3.
    CoefficientValue value(const Mixture& m, const std::string& name, const OrderRequest& order) {
      const auto pick = reader(m.size(), name);
      if (published) {
        if (order.tolerance)
          throw std::invalid_argument(
              "tolerance: scheme = \"published\" is GDH's first Sonine truncation, order = 1 only; drop tolerance");
        if (order.order != 1)
          throw std::invalid_argument("order: scheme = \"published\" exists at order = 1 only, got " +
                                      std::to_string(order.order));
        const double c = pick(at(m, 3)), b = pick(at(m, 2)), a = pick(at_published(m));
        const detail::OrderValue v = detail::estimate_from_doubles_confirmed(a, b, c, [&] { return pick(at(m, 4)); });
        CoefficientValue out{v.estimate.value, v.estimate.error, 1, v.defined && v.estimate.converging, false,
                             v.defined};
        out.infinite = v.infinite;
        return out;
      }
      return detail::choose_order(order, kMaxOrder, [&](int n) {
        // Highest order first: the operator is then built once to n + 2, not to n and again larger.
        const double c = pick(at(m, n + 2)), b = pick(at(m, n + 1)), a = pick(at(m, n));
        // L_c* = +∞ of a gas that never clusters (elastic). (6.3): order n + 3 where the changes change sign, within
        // the operator's cap (else the turn is not confirmed).
        return detail::estimate_from_doubles_confirmed(
            a, b, c, [&] { return n + 3 <= kMaxOrder + 2 ? pick(at(m, n + 3)) : std::nan(""); });
      });
    }
  };

  /// Returns the Navier–Stokes coefficient names of s species (theory.md §17).
  static std::vector<std::string> transport_names(int s) {
    std::vector<std::string> n{"shear_viscosity", "thermal_conductivity"};
    for (int i = 1; i <= s; ++i)
      for (int j = 1; j <= s; ++j) n.push_back(index_name("mutual_diffusion", i, j));
    for (const char* base : {"thermal_diffusion", "pressure_diffusion", "dufour"})
      for (int i = 1; i <= s; ++i) n.push_back(index_name(base, i));
    if (s == 2)
      for (int i = 1; i <= s; ++i) n.push_back(index_name("thermal_diffusion_factor", i));
    for (const char* c : {"critical_wavenumber_shear", "critical_wavenumber_heat", "critical_length"})
      n.emplace_back(c);
    for (const char* c : {"bulk_viscosity", "cooling_rate_first_order", "pressure"}) n.emplace_back(c);
    for (int i = 1; i <= s; ++i)
      for (int j = 1; j <= s; ++j) n.push_back(index_name("mobility", i, j));
    for (int i = 1; i <= s; ++i) n.push_back(index_name("heat_mobility", i));
    return n;
  }
  /// The external-force coefficients D^F_ij and L_j: listed only when the scene names them.
  static bool on_request(const std::string& name) {
    return name.rfind("mobility_", 0) == 0 || name.rfind("heat_mobility_", 0) == 0;
  }
  /// Zero in the dilute gas (p* = 1): listed by default only for a dense scene.
  static bool dense_only(const std::string& name) {
    return name == "bulk_viscosity" || name == "cooling_rate_first_order" || name == "pressure";
  }

  static constexpr int kMaxHcsOrder = 5;
  /// HCS states of the tolerance scans (scanned_hcs_value), kept across calls.
  std::map<std::string, MixtureCoolingState> hcs_memo_;
  /// Returns the memo key of a parameter point: every exact number and choice (the scheme included).
  static std::string memo_key(const ParameterPoint& point) {
    std::string key;
    for (const auto& [name, value] : point.numbers) key.append(name).append("=").append(value.to_string()).append("|");
    for (const auto& [name, value] : point.choices) key.append(name).append("=").append(value).append("|");
    return key;
  }

  /// Returns "a<q>_species" (built by appending: GCC 12 misreports "a" + std::string as overlapping).
  static std::string cumulant_base(int q) {
    std::string base(1, 'a');
    base.append(std::to_string(q)).append("_species");
    return base;
  }

  /// Returns the scene's hcs_order K (the HCS carries a_2 … a_K).
  static int hcs_order(const ParameterPoint& p) {
    return static_cast<int>(p.number("hcs_order", Rational(2)).to_double());
  }

  static std::vector<std::string> names(int s, int hcs_k) {
    std::vector<std::string> n{"cooling_rate"};
    for (int i = 1; i <= s; ++i) n.push_back(index_name("temperature_ratio", i));
    for (int q = 2; q <= hcs_k; ++q)
      for (int i = 1; i <= s; ++i) n.push_back(index_name(cumulant_base(q), i));
    return n;
  }
  static Mixture make(const detail::SchemaPoint& p) {
    const int s = p.given("species") ? static_cast<int>(p.number("species").to_double()) : 0;
    if (s < 2 || s > kMaxSpecies)
      throw std::invalid_argument("species: give 2 to " + std::to_string(kMaxSpecies) +
                                  " [[species]] tables (mass, diameter, fraction), got " + std::to_string(s));
    Mixture m;
    m.dimension = static_cast<int>(p.number("dimension").to_double());
    m.packing_fraction = p.number("packing_fraction").to_double();
    for (int i = 1; i <= s; ++i) {
      Species sp;
      for (const char* field : {"mass", "diameter", "fraction"})
        if (!p.given(index_name(field, i)))
          throw std::invalid_argument("species[" + std::to_string(i) + "]." + field + ": required");
      sp.mass = ExactValue(p.number(index_name("mass", i)));
      sp.diameter = p.number(index_name("diameter", i)).to_double();
      sp.fraction = p.number(index_name("fraction", i)).to_double();
      m.species.push_back(sp);
    }
    const Rational alpha = p.number("alpha");
    m.alpha.assign(static_cast<std::size_t>(s * s), 0.0);
    for (int i = 1; i <= s; ++i)
      for (int j = i; j <= s; ++j) {
        const double a = (p.given(index_name("alpha", i, j)) ? p.number(index_name("alpha", i, j)) : alpha).to_double();
        m.alpha[static_cast<std::size_t>((i - 1) * s + j - 1)] = a;
        m.alpha[static_cast<std::size_t>((j - 1) * s + i - 1)] = a;
      }
    m.validate();
    return m;
  }
};

}  // namespace

std::unique_ptr<TransportModel> detail::make_mixture_model() { return std::make_unique<MixtureModel>(); }

}  // namespace gkt
