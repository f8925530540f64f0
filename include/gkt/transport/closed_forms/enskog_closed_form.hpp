// Closed forms of the first Sonine approximation of the dense (Enskog) smooth inelastic gas
// (docs/theory.md §15.7): finite sums of monomials φ^i χ^j (φ dχ/dφ)^k π^{−l} whose coefficients
// are exact rational functions of α, derived by the engine from the same Galerkin pieces and
// collisional-transfer tables as the numerical solver.
#pragma once

#include <compare>
#include <map>
#include <string>
#include <vector>

#include "gkt/algebra/rational_function.hpp"
#include "gkt/transport/common/enskog_state.hpp"

namespace gkt {

/// Exponents of the monomial φ^phi χ^chi (φ dχ/dφ)^phi_dchi π^{−inv_pi} (chi may be negative).
struct EnskogMonomial {
  /// Exponents of φ, χ, φ dχ/dφ and 1/π.
  /// @{
  int phi = 0, chi = 0, phi_dchi = 0, inv_pi = 0;
  /// @}
  /// Lexicographic order (phi, chi, phi_dchi, inv_pi): the key order of EnskogClosedForm::terms().
  auto operator<=>(const EnskogMonomial&) const = default;
};

/// Σ_m R_m(α) m over EnskogMonomials m, exact. The pair correlation stays symbolic: χ and
/// φ dχ/dφ are its contact value and logarithmic-derivative numerator at φ.
class EnskogClosedForm {
 public:
  EnskogClosedForm() = default;
  /// Returns the single term r(α)·m.
  static EnskogClosedForm term(const RationalFunction& r, const EnskogMonomial& m = {});

  /// The non-zero terms, ordered by monomial.
  [[nodiscard]] const std::map<EnskogMonomial, RationalFunction>& terms() const { return terms_; }
  /// Returns the value at (α, φ, χ, φ dχ/dφ): coefficients exact at α, the sum in double.
  [[nodiscard]] double evaluate(const Rational& alpha, double phi, double chi, double phi_dchi) const;
  /// Returns the φ → 0 limit (χ → 1, φ dχ/dφ → 0) as a rational function of α.
  [[nodiscard]] RationalFunction dilute_limit() const;
  /// True if both have the same monomials with equal coefficients (as rational functions).
  [[nodiscard]] bool equals(const EnskogClosedForm& other) const;

  /// Returns a + b, term by term (exact).
  friend EnskogClosedForm operator+(const EnskogClosedForm& a, const EnskogClosedForm& b);
  /// Returns a − b, term by term (exact).
  friend EnskogClosedForm operator-(const EnskogClosedForm& a, const EnskogClosedForm& b);
  /// Returns the product a·b (monomial exponents add; exact).
  friend EnskogClosedForm operator*(const EnskogClosedForm& a, const EnskogClosedForm& b);
  /// Returns a/b for a single-term b; throws std::domain_error if b has several terms or none.
  friend EnskogClosedForm operator/(const EnskogClosedForm& a, const EnskogClosedForm& b);

 private:
  void accumulate(const EnskogMonomial& m, const RationalFunction& r);
  std::map<EnskogMonomial, RationalFunction> terms_;
};

/// Names of the coefficients with dense first-Sonine closed forms.
const std::vector<std::string>& enskog_closed_form_coefficients();

/// Returns the first-Sonine closed form of `coefficient` of the dense gas, reduced as in
/// conventions.md (η*, bulk viscosity, κ*, μ* per dilute η0, κ0; p* = p/(nT); ζ* = ζ/ν0; ζ_U
/// dimensionless), for d = 2, 3 in the standard scheme with f0 = f_M(1 + a2 S_2): every Sonine
/// sum is kept linear in a2 (as the published forms are), and a2 = a2(α) is the given function
/// (theory.md §15.7). Throws std::invalid_argument naming the valid coefficients.
EnskogClosedForm enskog_first_sonine_closed_form(int dimension, const std::string& coefficient,
                                                 const RationalFunction& a2);
/// The same with a2(α) of van Noije and Ernst (first_sonine_hcs).
EnskogClosedForm enskog_first_sonine_closed_form(int dimension, const std::string& coefficient);

/// The dense first-Sonine coefficient set at one state, reduced as in conventions.md.
struct EnskogFirstSonineValues {
  /// a2 (HCS cumulant), ζ* = ζ/ν0, p* = p/(nT), η* = η/η0, bulk viscosity per η0, κ* = κ/κ0, μ* = nμ/(Tκ0) and the
  /// dimensionless first-order cooling rate ζ_U.
  /// @{
  double a2, cooling_rate, pressure, shear_viscosity, bulk_viscosity, thermal_conductivity, density_heat_coefficient,
      cooling_rate_first_order;
  /// @}
};

/// Returns the dense first-Sonine set at α and the state (φ, χ, φ dχ/dφ) from the generated
/// closed forms (lib/transport/generated/, made by `gkt formula --format cpp`): no allocation,
/// for per-cell use in solvers. Throws std::invalid_argument naming the argument for α outside
/// (0, 1], d ∉ {2, 3}, φ outside [0, 1/2] (3D) or [0, 7/10] (2D), χ < 1, φ dχ/dφ < 0, any of them
/// not finite, or a set that overflows a double (χ or φ dχ/dφ beyond ~1e300).
EnskogFirstSonineValues enskog_first_sonine_values(int dimension, double alpha, const EnskogState& state);

}  // namespace gkt
