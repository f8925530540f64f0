#include "gkt/transport/common/pair_correlation.hpp"

#include <stdexcept>

#include "support/strings.hpp"

namespace gkt {

namespace {

// Carnahan & Starling (1969) in 3D, χ = (1 − φ/2)/(1 − φ)³; Henderson (1975) in 2D,
// χ = (1 − 7φ/16)/(1 − φ)² ([carnahan1969], [henderson1975]; PHYSICS.md §2).
Rational carnahan_starling(int d, const Rational& phi) {
  const Rational one(1), q = one - phi;
  if (d == 3) return (one - phi / Rational(2)) / (q * q * q);
  return (one - Rational(7, 16) * phi) / (q * q);
}

// φ dχ/dφ of the same, by the quotient rule: 3D χ' = [−½(1−φ) + 3(1 − φ/2)]/(1−φ)⁴ = (5/2 − φ)/(1−φ)⁴,
// 2D χ' = [−(7/16)(1−φ) + 2(1 − 7φ/16)]/(1−φ)³ = (25 − 7φ)/(16(1−φ)³).
Rational carnahan_starling_derivative(int d, const Rational& phi) {
  const Rational one(1), q = one - phi;
  if (d == 3) return phi * (Rational(-1, 2) * q + Rational(3) * (one - phi / Rational(2))) / (q * q * q * q);
  return phi * (Rational(-7, 16) * q + Rational(2) * (one - Rational(7, 16) * phi)) / (q * q * q);
}

}  // namespace

const std::vector<PairCorrelation>& pair_correlations() {
  static const std::vector<PairCorrelation> all{
      {"carnahan-starling", "Carnahan-Starling (3D), Henderson (2D)", carnahan_starling, carnahan_starling_derivative},
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

}  // namespace gkt
