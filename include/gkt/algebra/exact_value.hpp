// A number the user gave — a decimal of a scene, or a double of the C API, Python or C++ — kept
// exactly once for the engine, together with its nearest double for the solvers (the number
// policy of docs/architecture.md §4: converted once, where it enters).
#pragma once

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// An exact value and its correctly rounded double, fixed at construction and never converted again.
class ExactValue {
 public:
  /// Converts a double once: to the continued-fraction convergent with denominator ≤ 2^26 when one lies
  /// within 1e-12 (relative) of x — so 0.1 is 1/10 and 1.0/3 is 1/3, as if typed as text — else to
  /// x's exact binary value. A non-finite x keeps its double and has exact() = 0 (callers refuse it
  /// by value(), as Mixture::validate does, before anything exact is asked).
  ExactValue(double x);  // NOLINT(google-explicit-constructor): a double given by a caller is a value
  /// Takes an exact value as it is (a scene's decimal, "1/3", …).
  explicit ExactValue(Rational x);

  /// Returns the exact value (what the engine's exact arithmetic uses).
  [[nodiscard]] const Rational& exact() const { return exact_; }
  /// Returns the double nearest to exact() (the given double itself when it was not finite).
  [[nodiscard]] double value() const { return value_; }

 private:
  Rational exact_;
  double value_ = 0;
};

}  // namespace gkt
