// A granular mixture of s smooth inelastic hard spheres (d = 3) or disks (d = 2): masses,
// diameters, mole fractions, the restitution matrix α_ij, the packing fraction, and the contact
// values χ_ij of the pair correlation (docs/theory.md §16).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "gkt/algebra/exact_value.hpp"

namespace gkt {

/// One component. Mass and diameter are in any consistent unit (only ratios enter). The mass reaches
/// the engine exactly (its ratios m_i/m_j are exact rationals there): give it as a Rational (the
/// scene's decimal) or as a double, which ExactValue converts once (0.1 → 1/10; docs/architecture.md §4).
struct Species {
  /// Mass m_i (exact; only ratios enter).
  ExactValue mass = 1.0;
  /// Diameter σ_i (only ratios enter).
  double diameter = 1;
  double fraction = 1;  ///< mole fraction x_i = n_i/n; 0 is a tracer (the limit x_i → 0)
  std::string name;     ///< optional label
};

/// The composition and the state of a mixture; α is stored as a full symmetric s × s matrix.
struct Mixture {
  /// Spatial dimension d (2 or 3).
  int dimension = 3;
  /// The components, at least 2.
  std::vector<Species> species;
  std::vector<double> alpha;  ///< α_ij at i·s + j
  /// Total packing fraction φ (0: dilute).
  double packing_fraction = 0;

  /// Returns the number of species s.
  [[nodiscard]] std::size_t size() const { return species.size(); }
  /// Returns α_ij, the restitution of an i–j collision.
  [[nodiscard]] double restitution(std::size_t i, std::size_t j) const { return alpha[i * size() + j]; }
  /// Throws std::invalid_argument with a one-line message naming the field and its allowed range:
  /// d ∉ {2, 3}, fewer than 2 species, mass or diameter ≤ 0, fractions outside [0, 1] or not
  /// summing to 1 within 1e-12, α not symmetric or outside (0, 1], φ outside [0, φ_max).
  void validate() const;
  /// Returns m̄ = Σ x_i m_i, the reference mass of the reduced units (conventions.md).
  [[nodiscard]] double mean_mass() const;
  /// Returns σ̄ = Σ x_i σ_i, the reference diameter of the reduced units.
  [[nodiscard]] double mean_diameter() const;
  /// Returns χ_ij at i·s + j: Boublík–Grundke–Henderson–Lee–Mansoori in 3D, Jenkins–Mancini in
  /// 2D (theory.md (16.1)); each reduces to the one-component closure for identical species.
  [[nodiscard]] std::vector<double> contact_values() const;
  /// Returns n ∂χ_ij/∂n_l at fixed T and fixed n_k (k ≠ l), at (i·s + j)·s + l: the derivative of
  /// the same closures through φ = Σ_k n_k v_d σ_k^d and their second diameter moment (theory.md (18.1)).
  [[nodiscard]] std::vector<double> contact_value_derivatives() const;
};

/// Returns a mixture with one α for every pair.
Mixture make_mixture(int dimension, std::vector<Species> species, double alpha, double packing_fraction = 0);

}  // namespace gkt
