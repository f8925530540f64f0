// The Galerkin systems of the rough gas's Navier–Stokes modes at Sonine order N (docs/theory.md §19.16):
// basis functions ψ = T_r(c) S_p(x) L_q(y) (x = c², y = ŵ², ŵ the spin scaled by √(2T_r/(κm)); T_0 = 1,
// T_1 = c, T_2 = (c c)°), their collision matrix L = ⟨ψ_p, 𝓛ψ_q⟩ (normalisation of theory.md (5.2)) and the
// Maxwellian products N_pq = ⟨ψ_p ψ_q⟩, G_pq = ⟨ψ_q C·∂_C ψ_p⟩ (C = (c, ŵ)) of the cooling term
// (ζ/2)∂_C·(C ·). Every element is exact (a polynomial in τ = θ/κ) until it is evaluated at θ.
#pragma once

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/rough_collision_rule.hpp"
#include "gkt/transport/rough/rough_sonine_transport.hpp"

namespace gkt::detail {

/// Returns d_r: 3 for spheres, 1 for disks.
int rough_rotational_dimension(int dimension);
/// Returns ⟨T_r:T_r⟩/x^r over directions: 1, 1, (d − 1)/d for r = 0, 1, 2 (Y_2:Y_2 = (1 − 1/d) x², theory.md §4).
Rational rough_contraction_weight(int dimension, int rank);

/// A dense 4-index array of exact polynomials, each index 0 … K.
class RoughTable4 {
 public:
  /// Returns a table of zero polynomials, indices 0 … k.
  explicit RoughTable4(int k) : n_(k + 1), v_(static_cast<std::size_t>(n_ * n_ * n_ * n_)) {}
  /// Returns the entry (a, b, c, e).
  RationalPolynomial& operator()(int a, int b, int c, int e) { return v_[index(a, b, c, e)]; }
  /// Returns the entry (a, b, c, e).
  const RationalPolynomial& operator()(int a, int b, int c, int e) const { return v_[index(a, b, c, e)]; }
  /// Returns the entries, index ((a n + b) n + c) n + e; the table is left empty.
  std::vector<RationalPolynomial> release() { return std::move(v_); }

 private:
  [[nodiscard]] std::size_t index(int a, int b, int c, int e) const {
    return static_cast<std::size_t>(((a * n_ + b) * n_ + c) * n_ + e);
  }
  int n_;
  std::vector<RationalPolynomial> v_;
};

/// acc += c·x (exact).
void add_scaled(RationalPolynomial& acc, const RationalPolynomial& x, const Rational& c);
/// Returns p·λ^n.
RationalPolynomial shifted_by(const RationalPolynomial& p, long n);
/// Returns E(p, q, p', q') = Σ s_p(i) t_q(j) s_p'(k) t_q'(l) t(i, j, k, l): t (trial powers i of x, j of y; test
/// powers k, l; i + j, k + l ≤ k) contracted with the Sonine coefficients (indices twice_m for x, twice_m_spin for
/// y) one index at a time.
RoughTable4 contract_sonine(const RoughTable4& t, int k, long twice_m, long twice_m_spin);

/// ψ = T_rank(c) (Σ_i s[i] x^i)(Σ_j l[j] y^j) (exact), e.g. T_rank S_p^(d/2−1+rank)(x) L_q^(d_r/2−1)(y).
struct RoughTrialFunction {
  int rank = 0;
  int p = 0, q = 0;            ///< the Sonine indices (of a basis function)
  std::vector<Rational> s, l;  ///< coefficients of x^i and y^j
};

/// Returns T_rank S_p L_q (d_r = 3 spheres, 1 disks).
RoughTrialFunction rough_sonine_function(int dimension, int rank, int p, int q);

/// Returns ⟨a b⟩ over the Maxwellians (a, b of equal rank, contracted), exact.
Rational rough_maxwell_product(int dimension, const RoughTrialFunction& a, const RoughTrialFunction& b);
/// Returns ⟨b C·∂_C a⟩ over the Maxwellians (C = (c, ŵ); the cooling term's G), exact.
Rational rough_maxwell_scaling_product(int dimension, const RoughTrialFunction& a, const RoughTrialFunction& b);

/// The exact collision elements ⟨T_r S_p' L_q', 𝓛 T_r S_p L_q⟩ for p + q, p' + q' ≤ K (K − 1 for rank 2), as
/// polynomials in λ = √(θ/κ) times λ^{4K}: the engine's slot-pair tables (1,1), (1,1'), (2,1), (2,1') of
/// (c_a·c_b)^r X_a^i Y_a^j X_b^k Y_b^l combined and contracted with the Sonine coefficients one index at a time.
class RoughCollisionElements {
 public:
  /// Builds the elements up to K = highest_order (the engine tables are dropped after the contraction).
  RoughCollisionElements(const RoughCollisionParameters<RationalPolynomial>& parameters, int highest_order);
  /// Wraps numeric elements computed at one τ (the Walton gas, rough_walton_sonine.cpp): per rank, index
  /// ((p_trial n + q_trial) n + p_test) n + q_test, n = K + 1 (K for rank 2); element() refuses any other τ.
  RoughCollisionElements(int highest_order, double tau, const std::array<std::vector<double>, 3>& elements);
  /// Returns ⟨T_r S_p' L_q', 𝓛 T_r S_p L_q⟩ (test p', q'; trial p, q) at τ = θ/κ: the exact coefficients in τ,
  /// rounded once, summed in long double.
  [[nodiscard]] double element(int rank, int p_test, int q_test, int p_trial, int q_trial, double tau) const;
  /// Returns K.
  [[nodiscard]] int highest_order() const { return k_; }

 private:
  int k_;
  double fixed_tau_ = 0;  ///< > 0: the numeric elements hold at this τ only
  /// Per rank, index (p, q, p', q'): the coefficients of τ^{j − 2K}, j = 0, 1, … (rounded from the exact ones).
  std::array<std::vector<std::vector<long double>>, 3> contracted_;
};

using RoughMatrix = std::vector<std::vector<double>>;

/// One mode's basis and its Galerkin pieces (row p = test ψ_p, column q = trial ψ_q).
struct RoughGalerkinSystem {
  std::vector<RoughTrialFunction> basis;
  RoughMatrix collision;  ///< L_pq (about the reference state: Σ_w a_w W^{(w)}_pq added)
  RoughMatrix cooling;    ///< G_pq = ⟨ψ_q C·∂_C ψ_p⟩
  RoughMatrix product;    ///< N_pq = ⟨ψ_p ψ_q⟩
};

class RoughWeightedCollisionElements;
class RoughFamilyElements;

/// The cumulants of the reference state f0 = f_M [1 + Σ a_pq S_p(x) S_q(y) (+ Σ b_pq P S_p S_q, (19.26a))] and its
/// cooling rate: the Sonine HCS carried into the Chapman–Enskog equations (theory.md §19.16, "Cumulant reference").
struct RoughCumulantReference {
  const RoughWeightedCollisionElements* elements = nullptr;  ///< the weighted collision elements (W ≥ max p + q)
  std::vector<std::array<int, 2>> indices;                   ///< (p, q) of the cumulants
  std::vector<double> cumulants;                             ///< a_pq, in the order of `indices`
  std::vector<std::array<int, 2>> orientation_indices;       ///< (p, q) of the b_pq (3D; needs oriented elements)
  std::vector<double> orientation_coefficients;              ///< b_pq, in the order of `orientation_indices`
  double cooling_rate = 0;                                   ///< ζ* of that HCS (ζ/ν0(T_t))
  /// Σ_w a_w W^(w) already summed at τ (the Walton gas's quadrature, theory.md §19.25), used instead of `elements`
  /// and the cumulants when set (`indices`, `cumulants` still give the sources).
  const RoughCollisionElements* weighted_sum = nullptr;
};

/// Where the systems are evaluated: dimension, τ = θ/κ, whether the spin is decoupled (β = −1: translational
/// families only; the spin blocks neither feel nor feed them and can be singular) and the reference state (none:
/// Maxwellians at θ with the Maxwellian ζ*).
struct RoughModeState {
  int dimension = 3;
  double tau = 1;
  bool spin_decoupled = false;
  const RoughCumulantReference* reference = nullptr;
  /// The aligned-spin families (3D, theory.md §19.21) appended to every mode's basis after the products (null: the
  /// products only). Their rows and columns follow the products' in the matrices; `basis` lists the products only,
  /// and every source, flux and constraint of an aligned family is 0 (each is orthogonal to every product).
  const RoughFamilyElements* aligned = nullptr;
  /// The highest member level of `aligned` appended (0: every function of the tables; theory.md (19.155)).
  int family_members = 0;
};

/// Returns the shear system of order N: (c c)° S_p L_q, p + q ≤ N − 1 (theory.md (19.41)).
RoughGalerkinSystem rough_tensor_system(const RoughCollisionElements& elements, const RoughModeState& state, int order);
/// Returns the heat system of order N: c S_p L_q, 1 ≤ p + q ≤ N (no momentum; theory.md (19.42)).
RoughGalerkinSystem rough_vector_system(const RoughCollisionElements& elements, const RoughModeState& state, int order);
/// Returns the scalar system of order N: S_p L_q, 1 ≤ p + q ≤ N (no mass; theory.md (19.43)).
RoughGalerkinSystem rough_scalar_system(const RoughCollisionElements& elements, const RoughModeState& state, int order);

/// Returns ⟨s(x) l(y) f0⟩/⟨f_M⟩ over the reference state (Maxwellian when `reference` is null): ⟨s⟩⟨l⟩ +
/// Σ a_pq ⟨s S_p⟩⟨l L_q⟩ (x = c², y = ŵ²; s, l coefficients of powers).
double rough_reference_average(int dimension, const std::vector<Rational>& s, const std::vector<Rational>& l,
                               const RoughCumulantReference* reference);

/// Returns η*, κ*, μ*, η_b*, ζ_U at order N about Maxwellians at θ (θ = +inf: spin decoupled), or about the
/// cumulant reference of `state` (its ζ*, its weighted collision elements and sources, theory.md §19.16).
RoughTransportValues solve_rough_navier_stokes(const RoughCollisionElements& elements, const RoughModeState& state,
                                               int order, double theta);

}  // namespace gkt::detail
