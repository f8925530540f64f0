// The homogeneous cooling state (HCS) of smooth inelastic hard spheres (d = 3) or disks
// (d = 2): cumulants a_k of f = f_M [1 + Σ_{k≥2} a_k S_k(c²)] and the reduced cooling rate
// ζ* = ζ/ν0, from the Sonine moments of the scaled Boltzmann equation (docs/theory.md §9):
//
//   F_p(a) = R[S_p](a) − (2/d) R_1(a) ⟨x S_p'(x)⟩_a = 0   (p = 2..K),    ζ* = −(d+2) R_1(a)/(2d),
//   R[ψ](a) = Σ_{k,l} a_k a_l ⟨S_k(X1) S_l(X2)[ψ(X1') − ψ(X1)]⟩/J0,  R_1 = R[x].
#pragma once

#include <optional>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_function.hpp"
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
  std::vector<double> a;                                 ///< a[0] = 1, a[1] = 0, a[2..K]
  double cooling_rate = 0;                               ///< ζ* = ζ/ν0
  bool solved = true;                                    ///< false if Newton's method did not converge
  std::optional<Rational> exact_a2, exact_cooling_rate;  ///< linear scheme only
};

/// The cumulant (moment) hierarchy of the scaled Boltzmann equation at one α, truncated at a_K
/// (theory.md (9.2)–(9.3)), in double: the equations the HCS solver zeroes and the time
/// evolution integrates. Vectors a hold a_0 = 1, a_1 = 0, a_2 … a_K.
class CumulantHierarchy {
 public:
  CumulantHierarchy(int dimension, int k_max, std::vector<double> t, std::vector<double> e, std::vector<double> c,
                    std::vector<std::vector<double>> w, std::vector<double> norms);
  [[nodiscard]] int dimension() const { return dimension_; }
  [[nodiscard]] int k_max() const { return k_max_; }
  /// Returns R_1(a) = Σ a_k a_l E(k, l); ζ* = −((d+2)/(2d)) R_1 (9.4).
  [[nodiscard]] double energy_moment(const std::vector<double>& a) const;
  /// Returns ⟨1⟩_a = Σ a_k a_l C(k, l): the collision rate relative to the Maxwellian one.
  [[nodiscard]] double collision_rate(const std::vector<double>& a) const;
  /// Returns ∂R_1/∂a_q and ∂⟨1⟩_a/∂a_q for q = 0..K.
  void gradients(const std::vector<double>& a, std::vector<double>& energy, std::vector<double>& rate) const;
  /// Writes F_p(a), p = 2..K, to f[p − 2] and, if jacobian is not null, ∂F_p/∂a_q to
  /// (*jacobian)[(p − 2)(K − 1) + q − 2].
  void residual(const std::vector<double>& a, std::vector<double>& f, std::vector<double>* jacobian) const;
  /// Returns N_p = ⟨S_p S_p⟩ under the Maxwellian (the mass matrix of ∂_t a_p).
  [[nodiscard]] double norm(int p) const { return norms_[static_cast<std::size_t>(p)]; }

 private:
  friend class ViscoelasticHierarchy;  // refreshes t_, e_ in place as δ' changes
  int dimension_, k_max_;
  std::vector<double> t_, e_, c_;
  std::vector<std::vector<double>> w_;
  std::vector<double> norms_;
};

/// HCS solver for one dimension. The collision moments are built once, exactly, as polynomials
/// in α (Q[α]); each restitution evaluates them in long double (relative error ≤ 4e-14 measured,
/// K ≤ 10) and solves in double.
class HomogeneousCoolingState {
 public:
  /// Throws std::invalid_argument unless dimension is 2 or 3.
  explicit HomogeneousCoolingState(int dimension);

  /// Returns the HCS at restitution alpha ∈ (0, 1] keeping a_2..a_K (K ≥ 2; linear: K = 2).
  HcsState solve(const Rational& alpha, int k_max, HcsScheme scheme);

  /// Returns the cumulant hierarchy at alpha ∈ (0, 1] truncated at a_K (K ≥ 2).
  CumulantHierarchy hierarchy(const Rational& alpha, int k_max);

  [[nodiscard]] int dimension() const { return dimension_; }

 private:
  /// The exact tensors as polynomials in α, coefficients rounded to long double.
  struct Tables {
    int k_max = 0;
    std::vector<std::vector<long double>> t, e, c;  // T(p; k, l), E(k, l), C(k, l): coefficients of α^j
  };
  void ensure_tables(int k_max);
  int dimension_;
  std::optional<FirstSonineHcs> first_sonine_;
  Tables tables_;
  std::vector<std::vector<double>> derivative_weights_;  // ⟨x S_p' S_k⟩, p, k ≤ tables_.k_max
};

}  // namespace gkt
