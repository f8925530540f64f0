// Navier–Stokes coefficients of the dilute rough gas (constant β) at Sonine order N with Maxwellian
// weights at the temperature ratio θ (docs/theory.md §19.16): the shear, heat and scalar (∇·u) modes
// expanded in products of translational and spin Sonine polynomials,
//   tensor: (c c)° S_p(c²) L_q(ŵ²), p + q ≤ N − 1;   vector: c S_p(c²) L_q(ŵ²), 1 ≤ p + q ≤ N;
//   scalar: S_p(c²) L_q(ŵ²), 1 ≤ p + q ≤ N (zero total energy; ζ_U the energy row's unknown),
// every collision average exact in the rough engine with θ symbolic (one table per slot pair, shared by
// the three modes), the Galerkin systems solved in double. Order 1 is the first-Sonine approximation of
// rough_shear_viscosity.hpp, rough_thermal_conductivity.hpp and rough_bulk_viscosity.hpp. About the Sonine HCS
// (at_cooling_state) the reference f0 carries the HCS's θ, ζ* and cumulants a_pq (theory.md §19.16, "Cumulant
// reference"): the collision matrix gains one exact weighted table per cumulant and the sources are averages over f0.
#pragma once

#include <memory>

#include "gkt/algebra/rational.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_state.hpp"

namespace gkt {

/// η*, κ*, μ*, η_b*, ζ_U of one Sonine order (reductions as in conventions.md: η0(T_t), κ0(T_t), ν0(T_t)).
struct RoughTransportValues {
  double shear_viscosity = 0;                     ///< η/η0(T_t)
  double thermal_conductivity = 0;                ///< κ/κ0(T_t), q the total energy flux (NaN at β = −1)
  double thermal_conductivity_translational = 0;  ///< its translational flux alone
  double density_heat_coefficient = 0;            ///< nμ/(T_t κ0) (NaN at β = −1)
  double density_heat_translational = 0;          ///< its translational flux alone
  double bulk_viscosity = 0;                      ///< η_b/η0(T_t) (NaN at β = −1)
  double cooling_rate_first_order = 0;            ///< ζ_U of ζ = ζ⁽⁰⁾ + ζ_U∇·u (NaN at β = −1)
};

/// Which trial families the Galerkin spaces hold (theory.md §19.16, §19.21).
enum class RoughTrialSpace {
  product,  ///< the translation × spin Sonine products of (19.40) only (the default)
  aligned,  ///< 3D: the products plus the lowest aligned-spin families (ŵŵ)°, (c·ŵ)(cŵ)°, (ŵŵ)°·c, (c·ŵ)² − c²ŵ²/3
  full,  ///< the products, the aligned families (3D) and the chiral ones (c(c×ŵ))_sym, (c·ŵ)(ŵ(c×ŵ))_sym, c×ŵ
         ///< (2D: ŵ(c c⊥)_sym, ŵ c⊥) with their members, theory.md §19.22, §19.28
};

/// The `aligned_order` that ties RoughTrialSpace::full's member level to the Sonine order (rough_full_space_members).
inline constexpr int kRoughMembersTiedToOrder = 0;

/// Returns the member level M(N) = ⌈N/2⌉ of the full space at Sonine order N when tied to it (theory.md (19.155)):
/// the aligned and chiral families times S_p L_q of p + q ≤ M − 1 ((cc)° P, c P: p + q ≤ M − 2). Throws
/// std::invalid_argument naming `order` below 1.
int rough_full_space_members(int order);

/// The exact collision tables of one (d, α, β, κ) up to a highest Sonine order, with θ symbolic; each call
/// evaluates them at θ and solves the three Galerkin systems of one order (theory.md §19.16).
class RoughSonineTransport {
 public:
  /// Builds the tables for orders 1 … highest_order. Throws std::invalid_argument naming the field for
  /// d ∉ {2, 3}, α ∉ (0, 1], β ∉ [−1, 1], κ ∉ (0, 1] or highest_order < 1.
  RoughSonineTransport(int dimension, const Rational& alpha, const Rational& beta, const Rational& kappa,
                       int highest_order);
  /// As above, also building the collision elements weighted by the HCS cumulants a_pq of total degree
  /// 2 ≤ p + q ≤ cumulant_degree (the Sonine HCS of order cumulant_degree − 1) for at_cooling_state, and with
  /// `orientation` (3D) those weighted by the orientation terms b_pq P S_p S_q, p + q ≤ cumulant_degree − 2, of the
  /// oriented ansatz (theory.md (19.26a)). Throws std::invalid_argument naming `cumulant_degree` below 2, or
  /// `orientation` for d = 2.
  RoughSonineTransport(int dimension, const Rational& alpha, const Rational& beta, const Rational& kappa,
                       int highest_order, int cumulant_degree, bool orientation = false);
  /// As the first constructor, with the trial space `space`: RoughTrialSpace::aligned appends to each mode the
  /// aligned-spin families (theory.md §19.21) times S_p(x) L_q(y), p + q ≤ aligned_order − 1 (1: the lowest members
  /// alone), exact elements with the products of every order, about Maxwellians only (at, at_maxwellian_state).
  /// RoughTrialSpace::full appends the same aligned members (3D), the chiral families times S_p L_q of the same
  /// p + q (theory.md §19.22; 2D: the chiral ones alone) and (3D) (cc)° P, c P (P = (c·ŵ)² − c²ŵ²/3) times S_p L_q,
  /// p + q ≤ aligned_order − 2 (theory.md §19.28); with aligned_order = kRoughMembersTiedToOrder the member level
  /// follows each order N, M = rough_full_space_members(N). Throws std::invalid_argument naming `trial_space` for
  /// aligned with d = 2 (no c·ŵ for disks) and `aligned_order` below 1 (below 0 for full).
  RoughSonineTransport(int dimension, const Rational& alpha, const Rational& beta, const Rational& kappa,
                       int highest_order, RoughTrialSpace space, int aligned_order = 1);
  ~RoughSonineTransport();
  RoughSonineTransport(const RoughSonineTransport&) = delete;
  RoughSonineTransport& operator=(const RoughSonineTransport&) = delete;
  /// Takes the tables.
  RoughSonineTransport(RoughSonineTransport&&) noexcept;
  /// Takes the tables.
  RoughSonineTransport& operator=(RoughSonineTransport&&) noexcept;

  /// Returns the coefficients at Sonine order `order` (1 … highest_order) about Maxwellians at
  /// θ = T_r/T_t, with ζ* the Maxwellian cooling rate at that θ (theory.md (19.12)); θ = +inf only at
  /// β = −1 (spin decoupled: total fluxes, η_b and ζ_U NaN). α = β = 1, θ = 1 is Pidduck's gas.
  [[nodiscard]] RoughTransportValues at(int order, double temperature_ratio) const;
  /// Returns the same at the Maxwellian HCS θ (θ = +inf at β = −1).
  [[nodiscard]] RoughTransportValues at_maxwellian_state(int order) const;
  /// Returns the coefficients at Sonine order `order` about the Sonine HCS `hcs` of the same (d, α, β, κ):
  /// f0 = f_M(c) f_M(ŵ)[1 + Σ a_pq S_p(c²) S_q(ŵ²)] at its θ, with its ζ* (theory.md §19.16, (19.44)). Throws
  /// std::invalid_argument naming `trial_space` for tables built with RoughTrialSpace::aligned (no weighted elements
  /// for those families), `hcs` when it is not solved, carries cumulants above the weighted tables' degree
  /// or orientation terms b_pq without the orientation tables, and `order` outside [1, highest_order]. With them
  /// the oriented HCS (its b_pq) is carried too.
  [[nodiscard]] RoughTransportValues at_cooling_state(int order, const RoughSonineCoolingState& hcs) const;
  /// Returns the highest cumulant degree p + q of the weighted tables (0 without them).
  [[nodiscard]] int cumulant_degree() const;
  /// Returns the highest order the tables allow.
  [[nodiscard]] int highest_order() const;

 private:
  struct Tables;
  std::unique_ptr<Tables> tables_;
};

}  // namespace gkt
