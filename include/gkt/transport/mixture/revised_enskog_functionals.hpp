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

/// Returns the revised-Enskog functionals I_ℓij at (i·s + j)·s + ℓ (dimensionless), normalised as in
/// [garzo2007mixture]: the ∇n_ℓ part of the contact value carries δ_jℓ + ½(n_j ∂_ℓ ln χ_ij + I_ℓij),
/// theory.md (18.18)–(18.20). Exactly zero for equal diameters and for a dilute mixture (φ = 0);
/// I_ℓii = 0 always. Throws std::invalid_argument for s ≠ 2 ("species: …": the chemical potentials fix
/// I_ℓij for a binary only) and as Mixture::validate does.
std::vector<double> revised_enskog_functionals(const Mixture& mixture);

}  // namespace gkt
