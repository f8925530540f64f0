// The thermodynamics behind the revised Enskog theory of a mixture: the chemical potentials of the
// hard-sphere mixture whose pressure is the Enskog virial with the mixture's contact values, and the
// functionals I_ℓij that make the contact value of an unequal pair depart from its midpoint value
// (docs/theory.md §18.12).
#pragma once

#include <vector>

#include "gkt/transport/mixture/mixture.hpp"

namespace gkt {

/// Returns n_i ∂(μ_i/T)/∂n_ℓ at i·s + ℓ (dimensionless; T and n_k, k ≠ ℓ, fixed) of the elastic
/// hard-sphere mixture whose pressure is p/T = n + B_2 Σ_ij n_i n_j σ_ij^d χ_ij with the mixture's
/// closure (16.1) — its free energy is fixed by that pressure, theory.md (18.16)–(18.17). Zero-fraction
/// (tracer) species are allowed. Throws std::invalid_argument as Mixture::validate does.
std::vector<double> chemical_potential_derivatives(const Mixture& mixture);

/// How I_ℓij is closed for three or more species (theory.md §18.12). (18.19) fixes only the sums
/// Σ_j n_j σ_ij^d K_ℓij of the antisymmetric K_ℓij (s − 1 equations per ℓ); every closure takes a reference
/// K^ref_ℓij = δ_ijℓ ∂_ℓχ_ij/σ_ij (χ_ij read at the densities of the point R + δ_ijℓ σ̂, R the pair's
/// midpoint) and adds the gradient u_ℓi − u_ℓj that makes (18.19) hold — the smallest change in the norm
/// Σ_{i<j} n_i n_j σ_ij^d K² — so all of them satisfy (18.19) and reduce to the exact (18.20) of a binary.
enum class FunctionalClosure {
  /// δ_ijℓ the offset of the centroid of the lens where a sphere ℓ overlaps both i and j: exact to first
  /// order in density in 3D (the Mayer term of the non-uniform contact value). The default.
  lens_centroid,
  /// δ_ijℓ = (σ_i − σ_j)/4, the contact point: χ_ij read where the two spheres touch.
  contact_point,
  /// δ_ijℓ = 0: K_ℓij = u_ℓi − u_ℓj alone.
  gradient,
};

/// Returns the revised-Enskog functionals I_ℓij at (i·s + j)·s + ℓ (dimensionless), normalised as in
/// [garzo2007mixture]: the ∇n_ℓ part of the contact value carries δ_jℓ + ½(n_j ∂_ℓ ln χ_ij + I_ℓij),
/// theory.md (18.18)–(18.20). A binary's are exact ((18.20), `closure` unused); for s ≥ 3 (18.19) leaves
/// (s − 1)(s − 2)/2 per ℓ open and `closure` fixes them (a closure of an incomplete definition, §18.12).
/// Exactly zero for equal diameters and for a dilute mixture (φ = 0); I_ℓii = 0 and x_i I_ℓij + x_j I_ℓji = 0
/// always. Throws std::invalid_argument as Mixture::validate does.
std::vector<double> revised_enskog_functionals(const Mixture& mixture,
                                               FunctionalClosure closure = FunctionalClosure::lens_centroid);

}  // namespace gkt
