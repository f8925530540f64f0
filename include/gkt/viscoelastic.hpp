// Viscoelastic spheres (3D): restitution ε(g) = 1 − C1 δ' u^{1/5} + C2 δ'^2 u^{2/5} − …,
// u = σ̂·g/v0, δ'(t) = δ [2T(t)/T0]^{1/10} ([brilliantov2002] eqs. 2.2, 3.11–3.12), and the
// expansion of the bilinear collision moments in δ' (docs/theory.md §13).
#pragma once

#include <vector>

#include "gkt/homogeneous_cooling_state.hpp"

namespace gkt {

/// Coefficients of the restitution series ε = 1 + Σ_j h_j δ'^j u^{j/5}.
struct ViscoelasticRestitution {
  double c1 = 1.15344;  ///< C1 ([brilliantov2002] §2; Schwager & Pöschel 1998)
  /// h_1 … h_J: h_1 = −C1, h_2 = C2 = (3/5) C1² (the viscoelastic relation, C2 ≈ 0.7982).
  [[nodiscard]] std::vector<double> series() const { return {-c1, 0.6 * c1 * c1}; }
};

/// The bilinear collision moments of theory.md §9 expanded in δ': T = Σ_J δ'^J T^(J) for J ≤ 2,
/// with the same layout as BilinearCollisionMoments (double).
class ViscoelasticHierarchy {
 public:
  /// Builds the expansion for cumulants up to a_K (K ≥ 2), d = 3.
  ViscoelasticHierarchy(int k_max, const ViscoelasticRestitution& restitution = {});
  /// Returns the cumulant hierarchy at the current δ'.
  [[nodiscard]] CumulantHierarchy at(double delta_prime) const;
  /// Overwrites the δ'-dependent tensors of a hierarchy made by at() — no allocation (ODE hot path).
  void refresh(double delta_prime, CumulantHierarchy& hierarchy) const;
  /// Returns E^(J)(k, l) (energy moment of order J in δ').
  [[nodiscard]] double energy(int order, int k, int l) const;
  /// Returns the test-x² moment M^(J)(k, l) = ⟨S_k S_l Δ(X1²)⟩/J0 (BP's μ4 up to the factor −ν).
  [[nodiscard]] double fourth(int order, int k, int l) const;
  [[nodiscard]] int k_max() const { return k_max_; }
  /// Highest order in δ' kept (2: the order to which C1, C2 are known).
  static constexpr int kOrders = 2;

 private:
  int k_max_;
  std::vector<std::vector<double>> t_, e_;  // [J][index]
  std::vector<double> c_;
  std::vector<std::vector<double>> w_;
  std::vector<double> norms_;
};

/// BP's constants derived from the engine: ω0 = −ν E^(1)(0,0), ω1 = ν E^(2)(0,0) (μ2 = ω0 δ' − ω1 δ'²
/// + … at a2 = 0), q0 = ω0 2^{1/10}/(16√(2π)) (T ∝ t^{−5/3} time scale), and the quasi-stationary
/// a2 = a21 δ' + a22 δ'² of the first Sonine approximation (K = 2, quadratic in a2).
struct ViscoelasticConstants {
  double omega0, omega1, q0, a2_1, a2_2;
  /// First-order coefficients of η* = 1 + η̃1 δ' + … and μ* = μ̃1 δ' + … (first Sonine,
  /// theory.md (13.5), (13.7)); both equal BP's printed rationals.
  double shear_viscosity_1, density_heat_coefficient_1;
  /// κ* = 1 + κ̃1 δ' from theory.md (13.6). Does NOT reproduce BP's printed 1.98071 (ours 0.394);
  /// unresolved, not exposed by the CLI (theory.md §13.2).
  double thermal_conductivity_1_unverified;
};

/// Returns the constants for the given restitution series.
ViscoelasticConstants viscoelastic_constants(const ViscoelasticRestitution& restitution = {});

}  // namespace gkt
