// Contact values χ(φ) of the pair correlation function of hard spheres (d = 3) and disks
// (d = 2), chosen by name through one registry (docs/theory.md §15.1).
#pragma once

#include <string>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/transport/common/enskog_state.hpp"

namespace gkt {

/// One closure for the contact value of the pair correlation.
struct PairCorrelation {
  /// The closure's key (the `pair_correlation` parameter value).
  std::string name;
  /// One-line description of the closure.
  std::string description;
  /// Returns χ(φ) exactly (rational φ gives a rational χ).
  Rational (*contact_value)(int dimension, const Rational& packing_fraction);
  /// Returns φ dχ/dφ exactly.
  Rational (*packing_derivative)(int dimension, const Rational& packing_fraction);
  /// Returns χ(φ) in double by the same formula (a few flops, no allocation: per-cell use).
  double (*contact_value_double)(int dimension, double packing_fraction);
  /// Returns φ dχ/dφ in double by the same formula.
  double (*packing_derivative_double)(int dimension, double packing_fraction);
};

/// Returns every registered pair correlation (the first is the default).
const std::vector<PairCorrelation>& pair_correlations();

/// Returns the registered names, in registry order.
std::vector<std::string> pair_correlation_names();

/// Returns the pair correlation called `name`; throws std::invalid_argument
/// "pair_correlation: unknown … valid: …" otherwise.
const PairCorrelation& pair_correlation(const std::string& name);

/// Returns the largest packing fraction the kinetic theory is offered at: 0.5 (3D), 0.7 (2D).
Rational max_packing_fraction(int dimension);

/// Returns the dense state (φ, χ(φ), φ dχ/dφ) of `closure` in double, for per-cell use (no
/// allocation, no exact arithmetic; the double formula equals the exact one to rounding). Throws
/// std::invalid_argument for d ∉ {2, 3} or φ outside [0, max_packing_fraction(d)].
EnskogState enskog_state(int dimension, double packing_fraction, const PairCorrelation& closure);
/// The same with the default closure (Carnahan–Starling in 3D, Henderson in 2D).
EnskogState enskog_state(int dimension, double packing_fraction);

}  // namespace gkt
