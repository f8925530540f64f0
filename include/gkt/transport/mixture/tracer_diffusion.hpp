// Diffusion of a tracer (intruder) species in a dilute granular gas at its homogeneous cooling
// state, at any Sonine order (docs/theory.md §16.5): the Boltzmann–Lorentz operator of the pair
// from the engine with the tracer's and the host's masses and temperatures.
#pragma once

#include <vector>

#include "gkt/algebra/exact_value.hpp"
#include "gkt/transport/common/sonine_solution.hpp"
#include "gkt/transport/mixture/mixture_cooling_state.hpp"

namespace gkt {

/// A tracer species 0 in a one-component host gas (mass m, diameter σ, restitution α_hh).
struct Tracer {
  /// Spatial dimension d (2 or 3).
  int dimension = 3;
  ExactValue mass_ratio = 1.0;  ///< m0/m, exact in the engine (a double is converted once: ExactValue)
  double diameter_ratio = 1;    ///< σ0/σ
  double alpha_tracer = 1;      ///< α_0h, tracer–host restitution
  double alpha_host = 1;        ///< α_hh, host–host restitution

  /// Throws std::invalid_argument naming the field for d ∉ {2, 3}, ratios ≤ 0, α outside (0, 1].
  void validate() const;
};

/// The tracer diffusion coefficient, built once per tracer and evaluated at any order.
class TracerDiffusion {
 public:
  /// Builds the operator for `tracer` (validated) up to `max_order` Sonine polynomials
  /// (c S_0 … c S_{N−1}), about the host's HCS in the `reference` (Maxwellian tracer and host by
  /// default; with cumulants, the host's f carries its a_k and the tracer's f⁰ its own, theory.md §17.11).
  TracerDiffusion(const Tracer& tracer, int max_order, MixtureReference reference = {});
  /// Returns D0* = D0/D_ref at order N ≤ max_order, D_ref = (dΓ(d/2)/(4π^{(d−1)/2}))√(T/m)/(nσ^{d−1})
  /// the host's first-approximation self-diffusion coefficient (flux of tracer number −D0 ∇n0).
  [[nodiscard]] double coefficient(int order) const;
  /// Returns D0* at `order` with its truncation error (6.3) of docs/theory.md §6 from orders +1, +2 and, where
  /// their changes change sign, +3 (not confirmed, flagged, if order + 3 > max_order; order ≤ max_order − 2).
  [[nodiscard]] TruncationEstimate estimate(int order) const;
  /// Returns γ0 = T0/T of the tracer in the host's HCS (ζ0 = ζ_host; (16.4) with x0 = 0 when Maxwellian).
  [[nodiscard]] double temperature_ratio() const { return gamma_; }
  /// Returns the largest Sonine order the operator was built for (the constructor's max_order).
  [[nodiscard]] int max_order() const { return max_order_; }

 private:
  int max_order_;
  double gamma_ = 1, theta0_ = 1, prefactor_ = 1;
  std::vector<std::vector<double>> matrix_;  // M(p, q), p, q < max_order: (16.9)
  std::vector<double> source_;               // the tracer's ⟨x S_p φ_0⟩/(d/2): (1, 0, …) when Maxwellian
};

}  // namespace gkt
