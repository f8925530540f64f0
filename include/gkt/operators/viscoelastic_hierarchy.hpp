// Viscoelastic spheres (3D): restitution ε(g) = 1 − C1 δ' u^{1/5} + C2 δ'^2 u^{2/5} − …,
// u = σ̂·g/v0, δ'(t) = δ [2T(t)/T0]^{1/10} ([brilliantov2002] eqs. 2.2, 3.11–3.12), and the
// expansion of the bilinear collision moments in δ' (docs/theory.md §13).
#pragma once

#include <vector>

#include "gkt/algebra/dense_matrix.hpp"
#include "gkt/algebra/rational.hpp"
#include "gkt/collision/viscoelastic_contact.hpp"
#include "gkt/operators/cumulant_hierarchy.hpp"

namespace gkt {

/// The restitution series ε = 1 + Σ_j h_j δ'^j u^{j s} ([brilliantov2002] eq. 2.2 for s = 1/5).
struct ViscoelasticRestitution {
  /// h_1 … h_J. Default: viscoelastic (Hertz) spheres to δ'^3 with BP's C1 = 1.15344 — h_1 = −C1,
  /// h_2 = C2 = (3/5) C1², h_3 = −C3 from the contact equation (viscoelastic_contact.hpp).
  std::vector<double> coefficients = hertz_restitution_coefficients(1.15344, 3);
  /// Exponent s of the reduced impact speed u = σ̂·g/v0. δ' ∝ T^{s/2} (for s = 1/5, δ' ∝ T^{1/10});
  /// s = 0 is a constant restitution 1 + Σ h_j δ'^j — the check against the constant-α solvers.
  Rational exponent{1, 5};
  /// Returns the Hertz series to δ'^orders (≤ 4) for a given C1.
  static ViscoelasticRestitution hertz(double c1, int orders = 3) {
    return {hertz_restitution_coefficients(c1, orders), Rational(1, 5)};
  }
  /// Returns h_1 … h_J.
  [[nodiscard]] const std::vector<double>& series() const { return coefficients; }
};

/// The bilinear collision moments of theory.md §9 expanded in δ': T = Σ_J δ'^J T^(J), with the same
/// layout as BilinearCollisionMoments (double). Every J ≤ kMomentOrders is kept, so that at() gives
/// the moments of the truncated restitution series itself (to δ'^16), not their expansion cut at the
/// series' order (theory.md §13: the cut moments are off by 0.01 in a2 at δ' = 0.2).
class ViscoelasticHierarchy {
 public:
  /// Builds the expansion for cumulants up to a_K (K ≥ 2), d = 3, keeping the moments to
  /// δ'^max(moment_orders, number of restitution coefficients).
  ViscoelasticHierarchy(int k_max, const ViscoelasticRestitution& restitution = {}, int moment_orders = kMomentOrders);
  /// Returns the cumulant hierarchy at the current δ'.
  [[nodiscard]] CumulantHierarchy at(double delta_prime) const;
  /// Overwrites the δ'-dependent tensors T, E of a hierarchy made by at() with their series at
  /// delta_prime (CumulantHierarchy::assign_power_series) — no allocation (ODE hot path). Throws
  /// std::invalid_argument if the hierarchy's K differs from k_max().
  void refresh(double delta_prime, CumulantHierarchy& hierarchy) const;
  /// Returns E^(J)(k, l) (energy moment of order J in δ').
  [[nodiscard]] double energy(int order, int k, int l) const;
  /// Returns T^(J)(p; k, l) = ⟨S_k S_l Δ S_p⟩/J0 at order J in δ' (theory.md (9.2), (13.2)).
  [[nodiscard]] double transfer(int order, int p, int k, int l) const;
  /// Returns the test-x² moment M^(J)(k, l) = ⟨S_k S_l Δ(X1²)⟩/J0 (BP's μ4 up to the factor −ν).
  [[nodiscard]] double fourth(int order, int k, int l) const;
  /// Returns the largest Sonine index K of the tables.
  [[nodiscard]] int k_max() const { return k_max_; }
  /// Returns the number of restitution coefficients (the order of the δ'-series built on it).
  [[nodiscard]] int orders() const { return orders_; }
  /// Returns the highest J of the stored tensors T^(J), E^(J).
  [[nodiscard]] int moment_orders() const { return static_cast<int>(t_.size()) - 1; }
  /// The highest power of δ' kept in the moments: (1 − ε)^J ≤ 0.35^J with ε of (13.1) at δ' ≤ 0.3.
  static constexpr int kMomentOrders = 16;
  /// Returns the exponent s of the restitution series (δ' ∝ T^{s/2}).
  [[nodiscard]] const Rational& exponent() const { return exponent_; }

 private:
  int k_max_, orders_;
  Rational exponent_;
  std::vector<std::vector<double>> t_, e_;  // [J][index]
  std::vector<double> c_;
  std::vector<std::vector<double>> w_;
  std::vector<double> norms_;
};

/// Returns G[J][k](p, q), J = 0 … (number of restitution coefficients), k = 0 … k_max: the δ'^J
/// coefficient of the operator matrix L^(k)(p, q) of linearized_operator.hpp (basis S_m^(p) Y_rank,
/// p, q ≤ n_max, partner weighted by S_k; same prefactor ν) with the restitution ε(u) in place of α,
/// normalised by the Maxwellian J0 (theory.md (13.2)). d = 3. Exact moments rounded once to double.
std::vector<std::vector<DenseMatrix<double>>> viscoelastic_operator_series(
    int rank, int n_max, int k_max, const ViscoelasticRestitution& restitution = {});

}  // namespace gkt
