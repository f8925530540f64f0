// The column catalogue: what every coefficient column of every model means, what it is reduced by
// (docs/conventions.md "Canonical names", which a test compares with this list) and how a reduced
// value becomes a physical one in SI units given the reference gas (m, σ, n, T).
#pragma once

#include <string>
#include <vector>

namespace gkt {

/// The reference quantity a reduced column is divided by (docs/conventions.md "Reference values"),
/// for the reference gas of mass m, diameter σ, number density n and temperature T (k_B = 1 in
/// the formulas; in SI T is in kelvin and k_B enters as noted).
enum class Reduction {
  none,                 ///< dimensionless (a ratio, a cumulant, a restitution-series constant)
  viscosity,            ///< η0 = ((d+2)Γ(d/2)/(8π^{(d−1)/2})) σ^{1−d} √(mT)
  conductivity,         ///< κ0 = (d(d+2)/(2(d−1))) η0/m (SI: times k_B)
  self_diffusion,       ///< D0 = (dΓ(d/2)/(4π^{(d−1)/2})) √(T/m)/(nσ^{d−1})
  density_heat,         ///< Tκ0/n (μ* = nμ/(Tκ0))
  collision_frequency,  ///< ν0 = nT/η0
  pressure,             ///< nT
  wavenumber,           ///< ν0/v0, v0 = √(2T/m) (k* = k v0/ν0)
  length,               ///< v0/ν0 (L* = L ν0/v0)
  mutual_diffusion,     ///< n D0
  dufour,               ///< κ0/T
  mobility,             ///< m n D0/T
  other_reference,      ///< reduced by another reference (host species, aggregation units): never converted
};

/// One entry of the catalogue. `name` is a canonical column name or a pattern in which `<i>`,
/// `<j>` (species indices) and `<k>` (an order or power) stand for a positive integer.
struct ColumnDescription {
  std::string name;                       ///< the column name or pattern (e.g. `mutual_diffusion_<i>_<j>`)
  std::vector<std::string> models;        ///< the models this entry is for; empty: every model without its own entry
  std::string meaning;                    ///< the quantity, with the equation or section that defines it
  std::string reduced_by;                 ///< the reference quantity as docs/conventions.md writes it ("—": none)
  Reduction reduction = Reduction::none;  ///< what --units physical multiplies the column by
};

/// Returns the whole catalogue, model-specific entries before the general ones.
const std::vector<ColumnDescription>& column_catalogue();

/// Returns true if `column` is `pattern` with each `<i>`, `<j>`, `<k>` replaced by a positive
/// integer (docs/conventions.md also writes the index letter itself: `mutual_diffusion_i_j`).
bool column_matches(const std::string& pattern, const std::string& column);

/// Returns the description of the coefficient column `column` of `model`: the model's own entry
/// if it has one, else the general one. A `<name>_error` column is described as the estimated
/// truncation error of `<name>` (theory.md (6.1)) in its reduction; `order` as the Sonine order.
/// Throws std::invalid_argument "<column>: not in the column catalogue" for an unknown column.
ColumnDescription describe_column(const std::string& model, const std::string& column);

/// Returns the SI unit of a column reduced by `reduction` in dimension d once converted by
/// physical_scale (e.g. "kg m^-1 s^-1" for viscosity in 3D, "1" for none); "reduced" for
/// Reduction::other_reference.
std::string si_unit(Reduction reduction, int dimension);

/// The reference gas of `--units physical`, in SI: kg, m, m^-d, K.
struct PhysicalReference {
  double mass;            ///< m in kg
  double diameter;        ///< σ in m
  double number_density;  ///< n in m^-d
  double temperature;     ///< T in K
};

/// Boltzmann's constant in J/K (exact in the SI since 2019).
inline constexpr double boltzmann_constant = 1.380649e-23;

/// Returns the factor that turns a reduced value into SI units (si_unit) in dimension d for the
/// reference gas `reference`: η0, κ0 k_B, D0, Tκ0/n, ν0, n k_B T, ν0/v0, v0/ν0, n D0, κ0 k_B/T,
/// m n D0/(k_B T) (docs/conventions.md "Physical units"); 1 for Reduction::none and
/// Reduction::other_reference. Throws std::invalid_argument naming the field if a reference value
/// is not a finite number > 0 or a factor over- or underflows a double.
double physical_scale(Reduction reduction, int dimension, const PhysicalReference& reference);

}  // namespace gkt
