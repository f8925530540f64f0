// The binary collision rule of smooth inelastic hard spheres (d = 3) or disks (d = 2)
// between a particle of species i (velocity v1) and one of species j (velocity v2).
//
//   G = μ_i v1 + μ_j v2,  g = v1 − v2,  μ_i = m_i/(m_i+m_j),
//   g' = g − (1+α)(σ̂·g)σ̂,   v1' = G + μ_j g',   v2' = G − μ_i g'.
// ([brilliantov2004] eq. 2.6; [garzo2019] eq. 1.3). The restitution α is not stored
// here: the engine carries it as a number or as a polynomial variable.
//
// Spin (rough spheres) would add angular velocities as further vectors; the collision
// layer's linear map below is where they enter (docs/adding-a-model.md).
#pragma once

#include <array>

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// The four velocities a collision integrand can depend on.
enum class Slot { v1 = 0, v2 = 1, v1_post = 2, v2_post = 3 };

/// Returns the species side (0 = i, 1 = j) of a slot.
constexpr int slot_species(Slot s) { return static_cast<int>(s) % 2; }

/// Masses and Maxwellian widths of a colliding pair; all exact.
struct CollisionPair {
  /// Spatial dimension d (2 or 3).
  int dimension = 3;
  /// Mass of particle i (exact).
  Rational mass_i{1};
  /// Mass of particle j (exact).
  Rational mass_j{1};
  /// Gaussian widths θ = m/(2T) of the reference Maxwellians at v1 and v2, in the
  /// velocity unit of the caller (θ = 1 means velocities in units of √(2T/m)).
  Rational theta_i{1};
  /// Gaussian width θ_j = m_j/(2T_j) of the Maxwellian at v2 (see theta_i).
  Rational theta_j{1};

  /// Throws std::invalid_argument naming the offending field if the pair is unphysical.
  void validate() const;
  /// Returns θ of the species at a slot.
  [[nodiscard]] const Rational& theta(Slot s) const { return slot_species(s) == 0 ? theta_i : theta_j; }
  /// Returns the 4×3 matrix T with (v1, v2, v1', v2') = T · (G, g, g').
  [[nodiscard]] std::array<std::array<Rational, 3>, 4> velocity_map() const;
};

}  // namespace gkt
