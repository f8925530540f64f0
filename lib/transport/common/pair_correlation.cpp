#include "gkt/transport/common/pair_correlation.hpp"

#include <charconv>
#include <stdexcept>
#include <string>

#include "support/strings.hpp"

namespace gkt {

namespace {

std::string number(double x) {  // shortest round-trip form
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return {buffer, result.ptr};
}

// Carnahan & Starling (1969) in 3D, χ = (1 − φ/2)/(1 − φ)³; Henderson (1975) in 2D,
// χ = (1 − 7φ/16)/(1 − φ)² ([carnahan1969], [henderson1975]; PHYSICS.md §2). One formula for
// T = Rational (exact) and T = double (per cell): 7/16 and 1/2 are exact in both.
template <class T>
T carnahan_starling(int d, const T& phi) {
  const T one(1), q = one - phi;
  if (d == 3) return (one - phi / T(2)) / (q * q * q);
  return (one - T(7) / T(16) * phi) / (q * q);
}

// φ dχ/dφ of the same, by the quotient rule: 3D χ' = [−½(1−φ) + 3(1 − φ/2)]/(1−φ)⁴ = (5/2 − φ)/(1−φ)⁴,
// 2D χ' = [−(7/16)(1−φ) + 2(1 − 7φ/16)]/(1−φ)³ = (25 − 7φ)/(16(1−φ)³).
template <class T>
T carnahan_starling_derivative(int d, const T& phi) {
  const T one(1), q = one - phi;
  if (d == 3) return phi * (T(-1) / T(2) * q + T(3) * (one - phi / T(2))) / (q * q * q * q);
  return phi * (T(-7) / T(16) * q + T(2) * (one - T(7) / T(16) * phi)) / (q * q * q);
}

double carnahan_starling_double(int d, double phi) { return carnahan_starling<double>(d, phi); }
double carnahan_starling_derivative_double(int d, double phi) { return carnahan_starling_derivative<double>(d, phi); }

}  // namespace

const std::vector<PairCorrelation>& pair_correlations() {
  static const std::vector<PairCorrelation> all{
      {"carnahan-starling", "Carnahan-Starling (3D), Henderson (2D)", carnahan_starling<Rational>,
       carnahan_starling_derivative<Rational>, carnahan_starling_double, carnahan_starling_derivative_double},
  };
  return all;
}

std::vector<std::string> pair_correlation_names() {
  std::vector<std::string> names;
  for (const auto& p : pair_correlations()) names.push_back(p.name);
  return names;
}

const PairCorrelation& pair_correlation(const std::string& name) {
  for (const auto& p : pair_correlations())
    if (p.name == name) return p;
  throw std::invalid_argument("pair_correlation: unknown \"" + name +
                              "\"; valid: " + detail::join(pair_correlation_names(), "\""));
}

Rational max_packing_fraction(int dimension) { return dimension == 3 ? Rational(1, 2) : Rational(7, 10); }

EnskogState enskog_state(int dimension, double packing_fraction, const PairCorrelation& closure) {
  // The limits in double, rounded once (a function-local static: no exact arithmetic per cell).
  static const double limit[2] = {max_packing_fraction(2).to_double(), max_packing_fraction(3).to_double()};
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  const double top = limit[dimension - 2];
  if (!(packing_fraction >= 0 && packing_fraction <= top))
    throw std::invalid_argument("packing_fraction: must be a number in [0, " +
                                max_packing_fraction(dimension).to_decimal_string() +
                                "] for dimension = " + std::to_string(dimension) + ", got " + number(packing_fraction));
  return {packing_fraction, closure.contact_value_double(dimension, packing_fraction),
          closure.packing_derivative_double(dimension, packing_fraction)};
}

EnskogState enskog_state(int dimension, double packing_fraction) {
  return enskog_state(dimension, packing_fraction, pair_correlations().front());
}

}  // namespace gkt
