// Navier–Stokes transport coefficients of smooth inelastic hard spheres (d = 3) or disks
// (d = 2) about the homogeneous cooling state: dilute (Boltzmann; docs/theory.md §10,
// [brey1998], [garzo2019] ch. 3) or dense (Enskog; theory.md §15, [garzo1999]), in the standard
// (Maxwellian-weighted) or modified (HCS-weighted, [garzo2007modified]) Sonine scheme.
//
// Reduced as in docs/conventions.md: η* = η/η0, κ* = κ/κ0, μ* = nμ/(Tκ0), bulk viscosity/η0
// (η0, κ0 the dilute elastic first-Sonine values).
#pragma once

#include <optional>
#include <vector>

#include "gkt/algebra/dense_matrix.hpp"
#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/transport/common/enskog_state.hpp"
#include "gkt/transport/common/sonine_scheme.hpp"

namespace gkt {

/// First Sonine approximation, linear in a2, as exact polynomials in α and a2:
/// ν = ν0(α) + a2 ν2(α) for the collision frequencies of the shear and heat modes
/// (normalised so that both equal 1 … (d−1)/d at α = 1 as in [garzo2019]).
struct FirstSonineNavierStokes {
  RationalPolynomial nu_eta_0, nu_eta_a2;      ///< ν_η* = nu_eta_0 + a2 nu_eta_a2
  RationalPolynomial nu_kappa_0, nu_kappa_a2;  ///< ν_κ* = nu_kappa_0 + a2 nu_kappa_a2
  RationalPolynomial zeta_0, zeta_a2;          ///< ζ* = zeta_0 + a2 zeta_a2
  /// Modified scheme ([garzo2007modified]): ν = nu_0 + a2 modified_nu_a2 (theory.md (10.10)).
  RationalPolynomial modified_nu_eta_a2, modified_nu_kappa_a2;
  /// Returns η*, κ*, μ* at exact α and a2 (first-Sonine formulas, theory.md (10.8), with the
  /// scheme's collision frequencies).
  [[nodiscard]] std::vector<Rational> evaluate(const Rational& alpha, const Rational& a2,
                                               SonineScheme scheme = SonineScheme::standard) const;
};

/// Returns the first-Sonine closed forms derived by the engine for dimension d.
FirstSonineNavierStokes first_sonine_navier_stokes(int dimension);

/// η*, κ*, μ* of one Sonine order.
struct NavierStokesValues {
  double shear_viscosity = 0;
  double thermal_conductivity = 0;
  double density_heat_coefficient = 0;
  double bulk_viscosity = 0;  ///< /η0; zero in the dilute gas (theory.md (15.9))
  /// ζ_U of ζ = ζ0 + ζ_U ∇·u (dimensionless; theory.md (15.13)); zero in the dilute gas.
  double cooling_rate_first_order = 0;
};

namespace detail {
/// The α-independent pieces of one mode's Galerkin system (theory.md (10.4)–(10.7)): exact
/// (T = Rational, for the closed forms) or rounded to double (the solver).
template <class T>
struct GalerkinPieces {
  std::vector<std::vector<T>> d, m;        ///< D(p, q), M(p, q)
  std::vector<std::vector<T>> u, u2;       ///< source projections per HCS weight S_k (u2: density)
  std::vector<std::vector<T>> u_pressure;  ///< ⟨((d/2)S_p + xS_p') S_k⟩: the part ∝ p* (vector)
  std::vector<T> flux;                     ///< ⟨x² S_q⟩
  /// product[k](q, r) = ⟨w S_k S_q S_r⟩/⟨w S_r²⟩ (w the mode's weight; S_k scalar index), the
  /// expansion of S_k S_q in the mode's basis (modified scheme, theory.md (10.9)).
  std::vector<std::vector<std::vector<T>>> product;
};
}  // namespace detail

/// Solver for orders N ≥ 1: the operator (and, on the first dense call, the collisional-transfer
/// tables) are built once per dimension as exact polynomials in α; each call evaluates them at
/// α (long double) and solves in double.
class NavierStokesSolver {
 public:
  /// Throws std::invalid_argument unless dimension is 2 or 3.
  explicit NavierStokesSolver(int dimension);

  /// Returns η*, κ*, μ* at Sonine order `order` (N polynomials per mode) about the HCS with
  /// cumulants hcs_a (a[0] = 1, a[1] = 0, a[2..K]); α in (0, 1]. The modified scheme multiplies
  /// each trial polynomial by Σ_k a_k S_k (theory.md (10.9)).
  NavierStokesValues solve(const Rational& alpha, int order, const std::vector<double>& hcs_a,
                           SonineScheme scheme = SonineScheme::standard, const EnskogState& dense = {});

  [[nodiscard]] int dimension() const { return dimension_; }

 private:
  struct PolynomialMatrices {
    int n_max = -1, k_max = -1;
    std::vector<DenseMatrix<std::vector<long double>>> by_weight;  // [k](p, q): coefficients of α^j
  };
  using Pieces = detail::GalerkinPieces<double>;
  /// Builds the exact operators for `order` trial functions plus `extra_columns` more (the
  /// modified scheme's trial functions reach degree order + K).
  void ensure_built(int order, int k_max, int extra_columns, bool dense);
  /// Collisional-transfer tensors (theory.md §15) as α-polynomials, built on the first dense call.
  struct DensePieces {
    int n_max = -1, k_max = -1, n_test = -1;
    std::vector<std::vector<long double>> shear_source, shear_flux, shear_gradient, heat_source_temperature,
        heat_source_density, heat_flux, heat_gradient_temperature, heat_gradient_density, scalar_source,
        cooling_gradient, cooling_scalar;
  };
  DensePieces dense_;
  Pieces vector_pieces_, tensor_pieces_, scalar_pieces_;
  int dimension_;
  double transfer_factor_ = 0, gradient_factor_ = 0;             // e_d and g_d of theory.md (15.3), (15.8)
  PolynomialMatrices vector_, tensor_, scalar_;                  // scalar: built on the first dense call
  std::optional<std::vector<std::vector<long double>>> energy_;  // E(k, l) polynomials
  int energy_k_ = -1;
};

}  // namespace gkt
