// Navier–Stokes transport coefficients of smooth inelastic hard spheres (d = 3) or disks
// (d = 2) about the homogeneous cooling state: dilute (Boltzmann; docs/theory.md §10,
// [brey1998], [garzo2019] ch. 3) or dense (Enskog; theory.md §15, [garzo1999]), in the standard
// (Maxwellian-weighted) or modified (HCS-weighted, [garzo2007modified]) Sonine scheme.
//
// Reduced as in docs/conventions.md: η* = η/η0, κ* = κ/κ0, μ* = nμ/(Tκ0), bulk viscosity/η0
// (η0, κ0 the dilute elastic first-Sonine values).
#pragma once

#include <memory>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/transport/common/enskog_state.hpp"
#include "gkt/transport/common/sonine_scheme.hpp"

namespace gkt {

/// First Sonine approximation, linear in a2, as exact polynomials in α and a2:
/// ν = ν0(α) + a2 ν2(α) for the collision frequencies of the shear and heat modes
/// (normalised so that both equal 1 … (d−1)/d at α = 1 as in [garzo2019]).
struct FirstSonineNavierStokes {
  /// Shear-mode collision frequency ν_η*: the a2-free part and the coefficient of a2 (polynomials in α).
  /// @{
  RationalPolynomial nu_eta_0, nu_eta_a2;  ///< ν_η* = nu_eta_0 + a2 nu_eta_a2
  /// @}
  /// Heat-mode collision frequency ν_κ*: the a2-free part and the coefficient of a2 (polynomials in α).
  /// @{
  RationalPolynomial nu_kappa_0, nu_kappa_a2;  ///< ν_κ* = nu_kappa_0 + a2 nu_kappa_a2
  /// @}
  /// Reduced cooling rate ζ* = ζ/ν0: the a2-free part and the coefficient of a2 (polynomials in α).
  /// @{
  RationalPolynomial zeta_0, zeta_a2;  ///< ζ* = zeta_0 + a2 zeta_a2
  /// @}
  /// Modified scheme ([garzo2007modified]): ν = nu_0 + a2 modified_nu_a2 (theory.md (10.10)).
  /// The a2 coefficients of ν_η* and ν_κ* in the modified scheme.
  /// @{
  RationalPolynomial modified_nu_eta_a2, modified_nu_kappa_a2;
  /// @}
  /// Returns η*, κ*, μ* at exact α and a2 (first-Sonine formulas, theory.md (10.8), with the
  /// scheme's collision frequencies).
  [[nodiscard]] std::vector<Rational> evaluate(const Rational& alpha, const Rational& a2,
                                               SonineScheme scheme = SonineScheme::standard) const;
};

/// Returns the first-Sonine closed forms derived by the engine for dimension d.
FirstSonineNavierStokes first_sonine_navier_stokes(int dimension);

/// η*, κ*, μ* of one Sonine order.
struct NavierStokesValues {
  /// η* = η/η0.
  double shear_viscosity = 0;
  /// κ* = κ/κ0.
  double thermal_conductivity = 0;
  /// μ* = nμ/(Tκ0).
  double density_heat_coefficient = 0;
  double bulk_viscosity = 0;  ///< /η0; zero in the dilute gas (theory.md (15.9))
  /// ζ_U of ζ = ζ0 + ζ_U ∇·u (dimensionless; theory.md (15.13)); zero in the dilute gas.
  double cooling_rate_first_order = 0;
};

/// Solver for orders N ≥ 1: the operator (and, on the first dense call, the collisional-transfer
/// tables) are built once per dimension as exact polynomials in α; each call evaluates them at
/// α (long double) and solves in double.
class NavierStokesSolver {
 public:
  /// Throws std::invalid_argument unless dimension is 2 or 3.
  explicit NavierStokesSolver(int dimension);
  /// Copies carry the operators built so far (deep copy); a moved-from solver may only be assigned to or destroyed.
  ~NavierStokesSolver();
  /// Deep copy, including the operators built so far.
  NavierStokesSolver(const NavierStokesSolver& other);
  /// Deep copy, including the operators built so far.
  NavierStokesSolver& operator=(const NavierStokesSolver& other);
  /// Takes the operators; the moved-from solver may only be assigned to or destroyed.
  NavierStokesSolver(NavierStokesSolver&&) noexcept;
  /// Takes the operators; the moved-from solver may only be assigned to or destroyed.
  NavierStokesSolver& operator=(NavierStokesSolver&&) noexcept;

  /// Returns η*, κ*, μ* at Sonine order `order` (N polynomials per mode) about the HCS with
  /// cumulants hcs_a (a[0] = 1, a[1] = 0, a[2..K]); α in (0, 1]. The modified scheme multiplies
  /// each trial polynomial by Σ_k a_k S_k (theory.md (10.9)).
  NavierStokesValues solve(const Rational& alpha, int order, const std::vector<double>& hcs_a,
                           SonineScheme scheme = SonineScheme::standard, const EnskogState& dense = {});

  /// Returns the spatial dimension d.
  [[nodiscard]] int dimension() const { return dimension_; }

 private:
  struct Impl;  // the exact operators as α-polynomials and their rounded Galerkin pieces (navier_stokes.cpp)
  int dimension_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gkt
