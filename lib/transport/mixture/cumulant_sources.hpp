// The Maxwellian averages that the Chapman–Enskog sources of a mixture species gain when its f⁰
// carries HCS cumulants (docs/theory.md §17.11, (17.20)); shared by MixtureNavierStokes and TracerDiffusion.
#pragma once

#include <vector>

namespace gkt::detail {

/// Maxwellian averages over the reduced speed x = c² with weight x^{d/2−1}e^{−x}/Γ(d/2) of the
/// source polynomials of a reference with cumulants, at [p][k] (vector S_p, tensor S_p; scalar S_k,
/// k = 0 … K; theory.md (17.20)):
///   weight      ⟨x S_p S_k⟩,   temperature ⟨x S_p ((x − d/2) S_k − x S_k')⟩,
///   drift       ⟨x S_p (S_k' − S_k)⟩,   shear ⟨x² S_p^tensor (S_k − S_k')⟩.
struct CumulantSources {
  std::vector<std::vector<double>> weight, temperature, drift, shear;
};

/// Returns the averages for vector indices p ≤ n_vector, tensor p ≤ n_tensor and k ≤ k_max (exact, rounded once).
CumulantSources cumulant_sources(int d, int n_vector, int n_tensor, int k_max);

/// The scalar (∇·u) mode's averages of a reference with cumulants, at [p][k] (scalar S_p, p ≤ n_scalar;
/// S_k, k ≤ k_max; theory.md (17.25)): weight ⟨S_p S_k⟩, temperature ⟨S_p ((x − d/2) S_k − x S_k')⟩.
struct ScalarCumulantSources {
  std::vector<std::vector<double>> weight, temperature;
};

/// Returns the scalar averages (exact, rounded once).
ScalarCumulantSources scalar_cumulant_sources(int d, int n_scalar, int k_max);

}  // namespace gkt::detail
