// The homogeneous cooling state (HCS) of smooth inelastic hard spheres (d = 3) or disks
// (d = 2): cumulants a_k of f = f_M [1 + Σ_{k≥2} a_k S_k(c²)] and the reduced cooling rate
// ζ* = ζ/ν0, from the Sonine moments of the scaled Boltzmann equation (docs/theory.md §9):
//
//   F_p(a) = R[S_p](a) − (2/d) R_1(a) ⟨x S_p'(x)⟩_a = 0   (p = 2..K),    ζ* = −(d+2) R_1(a)/(2d),
//   R[ψ](a) = Σ_{k,l} a_k a_l ⟨S_k(X1) S_l(X2)[ψ(X1') − ψ(X1)]⟩/J0,  R_1 = R[x].
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_function.hpp"
#include "gkt/operators/cumulant_hierarchy.hpp"
#include "gkt/operators/nonlinear_collision_moments.hpp"

namespace gkt {

/// How the cumulant equations are truncated.
enum class HcsScheme {
  linear,     ///< first Sonine, linearised in a2 (van Noije & Ernst): exact rational functions of α
  nonlinear,  ///< a_2..a_K with all quadratic terms kept, solved by Newton's method
};

/// Closed forms of the first Sonine approximation, linear in a2 (exact in α).
struct FirstSonineHcs {
  RationalFunction a2;                 ///< a2(α)
  RationalPolynomial cooling_rate_0;   ///< ζ*(α) at a2 = 0
  RationalPolynomial cooling_rate_a2;  ///< ∂ζ*/∂a2 (ζ* is linearised in a2)
  RationalFunction cooling_rate;       ///< ζ*(α) with a2(α) inserted
};

/// Returns the first-Sonine HCS closed forms for dimension d, derived from the engine.
FirstSonineHcs first_sonine_hcs(int dimension);

/// The HCS at one restitution and truncation.
struct HcsState {
  std::vector<double> a;    ///< a[0] = 1, a[1] = 0, a[2..K]
  double cooling_rate = 0;  ///< ζ* = ζ/ν0
  bool solved = true;       ///< false if Newton's method did not converge
  /// Exact a2 and ζ* (linear scheme only; empty otherwise).
  /// @{
  std::optional<Rational> exact_a2, exact_cooling_rate;  ///< linear scheme only
  /// @}
};

/// HCS solver for one dimension. The collision moments are built once, exactly, as polynomials
/// in α (Q[α]); each restitution evaluates them in long double (relative error ≤ 4e-14 measured,
/// K ≤ 10) and solves in double.
class HomogeneousCoolingState {
 public:
  /// Throws std::invalid_argument unless dimension is 2 or 3.
  explicit HomogeneousCoolingState(int dimension);
  /// Copies carry the tables built so far (deep copy); a moved-from solver may only be assigned to or destroyed.
  ~HomogeneousCoolingState();
  /// Deep copy, including the tables built so far.
  HomogeneousCoolingState(const HomogeneousCoolingState& other);
  /// Deep copy, including the tables built so far.
  HomogeneousCoolingState& operator=(const HomogeneousCoolingState& other);
  /// Takes the tables; the moved-from solver may only be assigned to or destroyed.
  HomogeneousCoolingState(HomogeneousCoolingState&&) noexcept;
  /// Takes the tables; the moved-from solver may only be assigned to or destroyed.
  HomogeneousCoolingState& operator=(HomogeneousCoolingState&&) noexcept;

  /// Returns the HCS at restitution alpha ∈ (0, 1] keeping a_2..a_K (K ≥ 2; linear: K = 2).
  HcsState solve(const Rational& alpha, int k_max, HcsScheme scheme);

  /// Returns the cumulant hierarchy at alpha ∈ (0, 1] truncated at a_K (K ≥ 2).
  CumulantHierarchy hierarchy(const Rational& alpha, int k_max);

  /// Returns the spatial dimension d.
  [[nodiscard]] int dimension() const { return dimension_; }

 private:
  struct Impl;  // the exact tensors as α-polynomials, built lazily (homogeneous_cooling_state.cpp)
  int dimension_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gkt
