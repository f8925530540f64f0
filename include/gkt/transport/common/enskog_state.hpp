// The dense (Enskog) gas at one density, and its reduced pressure (docs/theory.md §15).
#pragma once

namespace gkt {

/// Returns p* = p/(nT) = 1 + 2^{d−2}(1+α)φχ of the smooth inelastic Enskog gas, exact for any
/// cumulants (theory.md (15.5)); T = Rational (exact) or double.
template <class T>
T reduced_pressure(int dimension, const T& alpha, const T& phi_chi) {
  return T(1) + T(dimension == 3 ? 2 : 1) * (T(1) + alpha) * phi_chi;
}

/// The dense (Enskog) gas at one density: packing fraction φ, contact value χ of the pair
/// correlation and φ dχ/dφ (theory.md §15). The default is the dilute (Boltzmann) gas.
struct EnskogState {
  /// Packing fraction φ.
  double packing_fraction = 0;
  /// Contact value χ of the pair correlation at φ.
  double chi = 1;
  /// φ dχ/dφ at φ.
  double phi_dchi = 0;
  /// Returns p* = p/(nT) (reduced_pressure).
  [[nodiscard]] double pressure(int dimension, double alpha) const {
    return reduced_pressure(dimension, alpha, packing_fraction * chi);
  }
};

}  // namespace gkt
