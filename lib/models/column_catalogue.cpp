// The column catalogue (docs/conventions.md "Canonical names"; tests/test_column_catalogue.cpp
// checks that the two agree) and the conversion of reduced columns into SI units.
#include "gkt/models/column_catalogue.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string_view>

#include "gkt/transport/common/reference_gas.hpp"

namespace gkt {

namespace {

using R = Reduction;

const std::vector<std::string> kRough{"rough", "rough-walton"};
const std::vector<std::string> kMixture{"mixture"};
const std::vector<std::string> kRoughOnly{"rough"};
const std::vector<std::string> kViscoelastic{"viscoelastic"};
const std::vector<std::string> kAggregation{"aggregation"};
const std::vector<std::string> kSmoothInelastic{"smooth-inelastic"};

std::vector<ColumnDescription> make_catalogue() {
  const std::string aggregation_units = "m₁ = σ₁ = θ0 = n₁(0) = 1, time t₀ = 1/(n₁(0)σ₁^{d−1}√(θ0/m₁)); energies in θ0";
  return {
      // Rough spheres and disks (theory.md §19): reduced at the translational temperature T_t.
      {"rotational_temperature_ratio", {}, "rough HCS: θ = T_r/T_t (theory.md §19.4)", "—", R::none},
      {"rotational_temperature_ratio_<i>", kRoughOnly, "rough binary HCS: θ_i = T_r,i/T_t,i (theory.md §19.17)", "—",
       R::none},
      {"translational_temperature", kRough, "gkt evolve: T_t(τ)/T_ref, T_t = m⟨v²⟩/d (theory.md §19.13)", "T_ref",
       R::other_reference},
      {"rotational_temperature", kRough, "gkt evolve: T_r(τ)/T_ref, T_r = I⟨ω²⟩/d_r (theory.md §19.13)", "T_ref",
       R::other_reference},
      {"translational_temperature_<i>", kRoughOnly, "gkt evolve, rough binary: T_t,i(τ)/T_ref (theory.md §19.31)",
       "T_ref", R::other_reference},
      {"rotational_temperature_<i>", kRoughOnly, "gkt evolve, rough binary: T_r,i(τ)/T_ref (theory.md §19.31)", "T_ref",
       R::other_reference},
      {"a20", kRough, "rough HCS cumulant ⟨c⁴⟩/⟨c⁴⟩_M − 1 (theory.md §19.4; rough-walton: §19.19)", "—", R::none},
      {"a02", kRough, "rough HCS cumulant ⟨ŵ⁴⟩/⟨ŵ⁴⟩_M − 1 (theory.md §19.4; rough-walton: §19.19)", "—", R::none},
      {"a11", kRough, "rough HCS cumulant ⟨c²ŵ²⟩/(⟨c²⟩⟨ŵ²⟩) − 1 (theory.md §19.4; rough-walton: §19.19)", "—", R::none},
      {"a20_<i>", kRoughOnly, "rough binary first-Sonine HCS: ⟨X_i²⟩/⟨X_i²⟩_M − 1 of species i (theory.md §19.30)", "—",
       R::none},
      {"a02_<i>", kRoughOnly, "rough binary first-Sonine HCS: ⟨Y_i²⟩/⟨Y_i²⟩_M − 1 of species i (theory.md §19.30)", "—",
       R::none},
      {"a11_<i>", kRoughOnly,
       "rough binary first-Sonine HCS: ⟨X_iY_i⟩/(⟨X_i⟩⟨Y_i⟩) − 1 of species i (theory.md §19.30)", "—", R::none},
      {"a30", {"rough"}, "rough HCS Sonine coefficient of S_3(c²)S_0(ŵ²), order ≥ 2 (theory.md §19.14)", "—", R::none},
      {"a21", {"rough"}, "rough HCS Sonine coefficient of S_2(c²)S_1(ŵ²), order ≥ 2 (theory.md §19.14)", "—", R::none},
      {"a12", {"rough"}, "rough HCS Sonine coefficient of S_1(c²)S_2(ŵ²), order ≥ 2 (theory.md §19.14)", "—", R::none},
      {"a03", {"rough"}, "rough HCS Sonine coefficient of S_0(c²)S_3(ŵ²), order ≥ 2 (theory.md §19.14)", "—", R::none},
      {"a40", {"rough"}, "rough HCS Sonine coefficient of S_4(c²)S_0(ŵ²), order ≥ 3 (theory.md §19.14)", "—", R::none},
      {"a31", {"rough"}, "rough HCS Sonine coefficient of S_3(c²)S_1(ŵ²), order ≥ 3 (theory.md §19.14)", "—", R::none},
      {"a22", {"rough"}, "rough HCS Sonine coefficient of S_2(c²)S_2(ŵ²), order ≥ 3 (theory.md §19.14)", "—", R::none},
      {"a13", {"rough"}, "rough HCS Sonine coefficient of S_1(c²)S_3(ŵ²), order ≥ 3 (theory.md §19.14)", "—", R::none},
      {"a04", {"rough"}, "rough HCS Sonine coefficient of S_0(c²)S_4(ŵ²), order ≥ 3 (theory.md §19.14)", "—", R::none},
      {"b00", kRough,
       "rough HCS (3D): coefficient of P = (c·ŵ)² − c²ŵ²/3 (theory.md (19.26a), §19.8; rough-walton: §19.29)", "—",
       R::none},
      {"b10", kRough, "rough HCS (3D): coefficient of P S_1(c²), order ≥ 2 (theory.md (19.26a))", "—", R::none},
      {"b01", kRough, "rough HCS (3D): coefficient of P S_1(ŵ²), order ≥ 2 (theory.md (19.26a))", "—", R::none},
      {"b20", kRough, "rough HCS (3D): coefficient of P S_2(c²), order 3 (theory.md (19.26a))", "—", R::none},
      {"b11", kRough, "rough HCS (3D): coefficient of P S_1(c²)S_1(ŵ²), order 3 (theory.md (19.26a))", "—", R::none},
      {"b02", kRough, "rough HCS (3D): coefficient of P S_2(ŵ²), order 3 (theory.md (19.26a))", "—", R::none},
      {"orientation_correlation",
       {},
       "rough spheres: C = ⟨cos²Θ⟩ of velocity and spin (theory.md §19.8)",
       "—",
       R::none},
      {"cooling_rate", kRough,
       "HCS cooling rate ζ* = ζ/ν0(T_t), ν0 = nT_t/η0(T_t) (rough binary: ν0 = nT/η0(m̄, σ̄), T = Σ x_i T_t,i)",
       "ν0(T_t)", R::collision_frequency},
      {"bulk_viscosity", kRough, "bulk viscosity η_b: nT_t − nτ_tT = −η_b∇·u (theory.md §19.9)", "η0(T_t)",
       R::viscosity},
      {"cooling_rate_first_order", kRough, "ζ_U in ζ = ζ⁽⁰⁾ + ζ_U∇·u (theory.md §19.9)", "dimensionless", R::none},
      {"shear_viscosity", kRough, "shear viscosity η (theory.md §19.7)", "η0(T_t)", R::viscosity},
      {"thermal_conductivity", kRough, "κ in q = −κ∇T_t − μ∇n, q the total energy flux (theory.md §19.7)", "κ0(T_t)",
       R::conductivity},
      {"density_heat_coefficient", kRough, "μ in q = −κ∇T_t − μ∇n (theory.md §19.7)", "T_tκ0/n", R::density_heat},
      {"critical_wavenumber_shear", kRough, "rough HCS stability: k⊥c* = √(ζ*/η*) of the shear mode (theory.md §19.15)",
       "ν0(T_t)/v0(T_t) (k* = k v0/ν0)", R::wavenumber},
      {"critical_wavenumber_heat", kRough, "rough HCS stability: k∥c* of the heat mode (theory.md (19.32))",
       "ν0(T_t)/v0(T_t) (k* = k v0/ν0)", R::wavenumber},
      {"critical_length", kRough, "rough HCS stability: L_c* = 2π/max(k⊥c*, k∥c*) (theory.md §19.15)",
       "v0(T_t)/ν0(T_t) (L* = L ν0/v0)", R::length},
      // Uniform shear flow (theory.md §22): GNB's units, never converted by --units physical.
      {"reduced_shear_rate",
       {"uniform-shear"},
       "steady uniform shear flow: γ = a ℓ/√(2T/m) (theory.md §22)",
       "ℓ/√(2T/m)",
       R::none},
      {"stress_xx", {"uniform-shear"}, "uniform shear flow: P_xx/(2nT) (theory.md §22)", "2nT", R::other_reference},
      {"stress_yy", {"uniform-shear"}, "uniform shear flow: P_yy/(2nT) (theory.md §22)", "2nT", R::other_reference},
      {"stress_zz",
       {"uniform-shear"},
       "uniform shear flow (3D): P_zz/(2nT) (theory.md §22)",
       "2nT",
       R::other_reference},
      {"stress_xy", {"uniform-shear"}, "uniform shear flow: P_xy/(2nT) < 0 (theory.md §22)", "2nT", R::other_reference},
      // The granular column in gravity (theory.md §23): units m = σ = g = 1, never converted.
      {"number_density",
       {"gravity-column"},
       "gravity column: n(z) σ^d at the row's height (theory.md §23)",
       "σ^{−d}",
       R::other_reference},
      {"temperature",
       {"gravity-column"},
       "gravity column: T(z)/(mgσ) at the row's height (theory.md §23)",
       "mgσ",
       R::other_reference},
      {"heat_flux",
       {"gravity-column"},
       "gravity column: upward energy flux q(z) (theory.md §23)",
       "m g^{3/2} σ^{5/2−d}",
       R::other_reference},
      {"knudsen_number",
       {"gravity-column"},
       "gravity column: ℓ max(|d ln T/dz|, |d ln n/dz|), ℓ = 1/(√2 n S_d) (theory.md §23.4)",
       "—",
       R::none},
      // Aggregation (theory.md §20): its own units, never converted.
      {"success_factor", kAggregation, "ψ, collision-weighted fraction of i-j collisions that stick (theory.md §20)",
       aggregation_units, R::none},
      {"collision_rate", kAggregation, "R_ij, collision rate per n_i n_j (theory.md §20)", aggregation_units,
       R::other_reference},
      {"aggregation_kernel", kAggregation, "β_ij, aggregation rate per n_i n_j (theory.md §20)", aggregation_units,
       R::other_reference},
      {"sticking_energy", kAggregation, "relative energy lost per collision by sticking (theory.md §20)",
       aggregation_units, R::other_reference},
      {"rebound_energy", kAggregation, "relative energy lost per collision by rebounds, times 1 − α² (theory.md §20)",
       aggregation_units, R::other_reference},
      {"energy_loss", kAggregation, "R_ij times the sum of the sticking and rebound energies (theory.md §20)",
       aggregation_units, R::other_reference},
      // Viscoelastic spheres (theory.md §13): constants and coefficients of δ'^j.
      {"omega0", kViscoelastic, "viscoelastic expansion constant ω0 (theory.md (13.3))", "—", R::none},
      {"omega1", kViscoelastic, "viscoelastic expansion constant ω1 (theory.md (13.3))", "—", R::none},
      {"q0", kViscoelastic, "viscoelastic expansion constant q0 (theory.md (13.4))", "—", R::none},
      {"a2_<j>", kViscoelastic, "coefficient of δ'^j in a2 (theory.md §13.2)", "—", R::none},
      {"shear_viscosity_<j>", kViscoelastic, "coefficient of δ'^j in η* (theory.md §13.2)", "η0", R::viscosity},
      {"thermal_conductivity_<j>", kViscoelastic, "coefficient of δ'^j in κ* (theory.md §13.2)", "κ0", R::conductivity},
      {"density_heat_coefficient_<j>", kViscoelastic, "coefficient of δ'^j in μ* (theory.md §13.2)", "Tκ0/n",
       R::density_heat},
      {"cooling_rate_<j>", kViscoelastic, "coefficient of δ'^j in ζ* (theory.md §13.2)", "ν0", R::collision_frequency},
      // Mixtures (theory.md §16–18): the reference gas has m̄ = Σ x_i m_i, σ̄ = Σ x_i σ_i.
      {"cooling_rate", kMixture, "common HCS cooling rate ζ* = ζ/ν0, ν0 = nT/η0(m̄, σ̄)", "ν0(m̄, σ̄)",
       R::collision_frequency},
      {"temperature_ratio_<i>", {}, "mixture HCS: T_i/T, T = Σ x_i T_i (rough binary: T_t,i/T)", "T", R::none},
      {"tracer_diffusion_<i>",
       {},
       "tracer diffusion coefficient of species i in the other species (dilute binary)",
       "D0 of the host (m, σ of the host, total n)",
       R::other_reference},
      {"a<k>_species_<i>", {}, "mixture HCS cumulant a_k of species i", "—", R::none},
      {"shear_viscosity", kMixture, "shear viscosity η of the mixture", "η0(m̄, σ̄)", R::viscosity},
      {"thermal_conductivity", kMixture, "thermal conductivity λ (q = −λ∇T)", "κ0(m̄, σ̄)", R::conductivity},
      {"mutual_diffusion_<i>_<j>",
       {},
       "D_ij, coefficient of ∇ln n_j in the flux j_i (theory.md (17.1))",
       "n D0",
       R::mutual_diffusion},
      {"thermal_diffusion_<i>", {}, "D^T_i, j_i ∋ −ρ D^T_i ∇ln T (theory.md (17.1))", "D0", R::self_diffusion},
      {"pressure_diffusion_<i>", {}, "D^p_i = Σ_j m_i m_j n_j D_ij/ρ², j_i ∋ −ρ D^p_i ∇ln p", "D0", R::self_diffusion},
      {"dufour_<i>", {}, "D''_i, the coefficient of −T²∇ln n_i in q (theory.md (17.1))", "κ0/T", R::dufour},
      {"thermal_diffusion_factor_<i>", {}, "Λ_i of a binary (theory.md (17.15))", "—", R::none},
      {"mobility_<i>_<j>",
       {},
       "D^F_ij (GDH's D^F, not their L), j_i ∋ −Σ_j D^F_ij F_j for forces F_j on species j (theory.md (18.14))",
       "m̄ n D0/T",
       R::mobility},
      {"heat_mobility_<i>",
       {},
       "L_i, q ∋ −Σ_i L_i F_i, the heat flux per force on species i (theory.md (18.15)); left reduced by --units "
       "physical",
       "κ0",
       R::other_reference},
      {"pressure", kMixture, "hydrostatic pressure p* = p/(nT) (theory.md (18.2))", "nT", R::pressure},
      {"bulk_viscosity", kMixture, "bulk viscosity κ, P ∋ −κ I ∇·u (theory.md (18.8))", "η0(m̄, σ̄)", R::viscosity},
      {"critical_wavenumber_shear", kMixture, "mixture HCS stability: k⊥c* (theory.md §17.7, §18.8)",
       "ν0/v̄ (k* = k v̄/ν0)", R::wavenumber},
      {"critical_wavenumber_heat", kMixture, "mixture HCS stability: k∥c* (theory.md §17.7, §18.8)",
       "ν0/v̄ (k* = k v̄/ν0)", R::wavenumber},
      {"critical_length", kMixture, "mixture HCS stability: L_c* (theory.md §17.7, §18.8)", "v̄/ν0 (L* = L ν0/v̄)",
       R::length},
      {"cooling_rate_first_order", kMixture, "ζ_U in ζ = ζ0 + ζ_U ∇·u (theory.md (18.7))", "dimensionless", R::none},
      // The HCS tail φ ~ 𝒜 c^γ exp(−A c) of the tail scheme (theory.md §10.6, §10.7), in the scaled variables.
      {"tail_exponent", kSmoothInelastic,
       "HCS tail exponent A of φ ~ exp(−A c), A = 2β/ζ_r, c = v/v0 (scheme = \"tail\"; theory.md §10.6)", "1/v0",
       R::other_reference},
      {"tail_amplitude", kSmoothInelastic,
       "HCS tail amplitude 𝒜 of φ ~ 𝒜 c^γ exp(−A c), φ the scaled distribution (scheme = \"tail\"; theory.md "
       "§10.7)",
       "n v0^{−d}", R::other_reference},
      // Every model without its own entry.
      {"shear_viscosity", {}, "shear viscosity η", "η0", R::viscosity},
      {"thermal_conductivity", {}, "thermal conductivity κ (q = −κ∇T)", "κ0", R::conductivity},
      {"self_diffusion", {}, "self-diffusion coefficient D", "D0", R::self_diffusion},
      {"density_heat_coefficient", {}, "μ in q = −κ∇T − μ∇n", "Tκ0/n (μ* = nμ/(Tκ0))", R::density_heat},
      {"a<k>", {}, "HCS cumulant a_k: f = f_M[1 + Σ a_k S_{d/2−1}^(k)(c²)]", "—", R::none},
      {"cooling_rate", {}, "HCS cooling rate ζ* = ζ/ν0, ν0 = nT/η0", "ν0", R::collision_frequency},
      {"bulk_viscosity", {}, "bulk viscosity (zero when dilute)", "η0", R::viscosity},
      {"pressure", {}, "hydrostatic pressure p* = p/(nT)", "nT", R::pressure},
      {"cooling_rate_first_order", {}, "ζ_U in ζ = ζ0 + ζ_U ∇·u (0 when dilute)", "dimensionless", R::none},
      {"critical_wavenumber_shear",
       {},
       "HCS stability: critical wave number k⊥c* of the shear mode (theory.md §14)",
       "ν0/v0 (k* = k v0/ν0)",
       R::wavenumber},
      {"critical_wavenumber_heat",
       {},
       "HCS stability: critical wave number k∥c* of the heat mode (theory.md §14)",
       "ν0/v0 (k* = k v0/ν0)",
       R::wavenumber},
      {"critical_length",
       {},
       "HCS stability: critical length L_c* = 2π/max(k⊥c*, k∥c*) (theory.md §14)",
       "v0/ν0 (L* = L ν0/v0)",
       R::length},
  };
}

bool applies_to(const ColumnDescription& entry, const std::string& model) {
  return entry.models.empty() || std::find(entry.models.begin(), entry.models.end(), model) != entry.models.end();
}

}  // namespace

const std::vector<ColumnDescription>& column_catalogue() {
  static const std::vector<ColumnDescription> catalogue = make_catalogue();
  return catalogue;
}

bool column_matches(const std::string& pattern, const std::string& column) {
  std::size_t p = 0, c = 0;
  while (p < pattern.size()) {
    if (pattern[p] == '<') {
      const std::size_t close = pattern.find('>', p);
      const char letter = pattern[p + 1];
      p = close + 1;
      if (c < column.size() && column[c] == letter && (c + 1 == column.size() || column[c + 1] == '_')) {
        ++c;  // the index letter itself, as the docs write it
        continue;
      }
      const std::size_t start = c;
      while (c < column.size() && std::isdigit(static_cast<unsigned char>(column[c])) != 0) ++c;
      if (c == start || column[start] == '0') return false;
      continue;
    }
    if (c >= column.size() || pattern[p] != column[c]) return false;
    ++p;
    ++c;
  }
  return c == column.size();
}

ColumnDescription describe_column(const std::string& model, const std::string& column) {
  if (column == "order") return {"order", {}, "Sonine order used (number of polynomials)", "—", R::none};
  constexpr std::string_view suffix = "_error";
  if (column.size() > suffix.size() && column.ends_with(suffix)) {
    const std::string base = column.substr(0, column.size() - suffix.size());
    try {
      ColumnDescription d = describe_column(model, base);
      d.name += "_error";
      d.meaning = "estimated truncation error of " + base + " (theory.md (6.1)): " + d.meaning;
      return d;
    } catch (const std::invalid_argument&) {  // e.g. a column truly named …_error: look it up as is
    }
  }
  constexpr std::string_view order_suffix = "_order";  // tolerance tables: the order each column is reported at
  if (column.size() > order_suffix.size() && column.ends_with(order_suffix)) {
    const std::string base = column.substr(0, column.size() - order_suffix.size());
    try {
      describe_column(model, base);
      return {column,
              {},
              "order at which " + base + " is reported (tolerance tables: the row's order, or " + base +
                  "'s own stop where its error at the row's order misses the tolerance)",
              "—",
              R::none};
    } catch (const std::invalid_argument&) {  // e.g. cooling_rate_first_order: look it up as is
    }
  }
  // Model-specific entries come first in the catalogue: the first match is the most specific.
  for (const auto& entry : column_catalogue())
    if (!entry.models.empty() && applies_to(entry, model) && column_matches(entry.name, column)) return entry;
  for (const auto& entry : column_catalogue())
    if (entry.models.empty() && column_matches(entry.name, column)) return entry;
  throw std::invalid_argument(column + ": not in the column catalogue (model \"" + model + "\")");
}

std::string si_unit(Reduction reduction, int dimension) {
  // Exponents of kg, m, s, K; the length exponent as a + b·d.
  struct Exponents {
    int kg, m_const, m_per_d, s, kelvin;
  };
  Exponents e{};
  switch (reduction) {
    case R::none:
      return "1";
    case R::other_reference:
      return "reduced";
    case R::viscosity:
      e = {1, 2, -1, -1, 0};
      break;
    case R::conductivity:
      e = {1, 4, -1, -3, -1};
      break;
    case R::self_diffusion:
      e = {0, 2, 0, -1, 0};
      break;
    case R::density_heat:
      e = {1, 4, 0, -3, 0};
      break;
    case R::collision_frequency:
      e = {0, 0, 0, -1, 0};
      break;
    case R::pressure:
      e = {1, 2, -1, -2, 0};
      break;
    case R::wavenumber:
      e = {0, -1, 0, 0, 0};
      break;
    case R::length:
      e = {0, 1, 0, 0, 0};
      break;
    case R::mutual_diffusion:
      e = {0, 2, -1, -1, 0};
      break;
    case R::dufour:
      e = {1, 4, -1, -3, -2};
      break;
    case R::mobility:
      e = {0, 0, -1, 1, 0};
      break;
  }
  std::string unit;
  const auto factor = [&unit](const char* symbol, int power) {
    if (power == 0) return;
    if (!unit.empty()) unit += ' ';
    unit += symbol;
    if (power != 1) {
      unit += '^';
      unit += std::to_string(power);  // appended apart: GCC 12 warns (-Wrestrict) on "^" + std::string
    }
  };
  factor("kg", e.kg);
  factor("m", e.m_const + e.m_per_d * dimension);
  factor("s", e.s);
  factor("K", e.kelvin);
  return unit.empty() ? "1" : unit;
}

double physical_scale(Reduction reduction, int dimension, const PhysicalReference& reference) {
  const auto require_positive = [](double v, const char* name) {
    if (!std::isfinite(v) || v <= 0)
      throw std::invalid_argument(std::string(name) + ": must be a finite number > 0 (SI units)");
  };
  require_positive(reference.mass, "mass");
  require_positive(reference.diameter, "diameter");
  require_positive(reference.number_density, "number_density");
  require_positive(reference.temperature, "temperature");
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("dimension: must be 2 or 3");
  const double m = reference.mass, n = reference.number_density, kelvin = reference.temperature;
  const double energy = boltzmann_constant * kelvin;  // T as an energy (k_B = 1 in the reductions)
  const ReferenceGas gas = reference_gas(dimension, m, reference.diameter, n, energy);
  const double v0 = std::sqrt(2 * energy / m);
  double scale = 1;
  switch (reduction) {
    case R::none:
    case R::other_reference:
      return 1;
    case R::viscosity:
      scale = gas.viscosity;
      break;
    case R::conductivity:
      scale = gas.conductivity * boltzmann_constant;
      break;
    case R::self_diffusion:
      scale = gas.self_diffusion;
      break;
    case R::density_heat:
      scale = energy * gas.conductivity / n;
      break;
    case R::collision_frequency:
      scale = gas.collision_frequency;
      break;
    case R::pressure:
      scale = n * energy;
      break;
    case R::wavenumber:
      scale = gas.collision_frequency / v0;
      break;
    case R::length:
      scale = v0 / gas.collision_frequency;
      break;
    case R::mutual_diffusion:
      scale = n * gas.self_diffusion;
      break;
    case R::dufour:
      scale = gas.conductivity * boltzmann_constant / kelvin;
      break;
    case R::mobility:
      scale = m * n * gas.self_diffusion / energy;
      break;
  }
  if (!std::isnormal(scale)) {
    char value[32];
    std::snprintf(value, sizeof value, "%.3g", scale);
    throw std::invalid_argument(std::string("--units physical: the reference values make a scale of ") + value +
                                " (over- or underflow of a double); give the gas in SI units");
  }
  return scale;
}

}  // namespace gkt
