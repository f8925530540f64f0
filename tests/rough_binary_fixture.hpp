// Test helper: the rough binary mixtures of the mixture tests — one constructor from two components and the pair
// restitutions, and the unequal species of theory.md §19.17 (m = 1, 4; κ = 2/5, 1/2; σ = 1, 2; x = 0.3, 0.7).
#pragma once

#include <array>

#include "gkt/algebra/rational.hpp"
#include "gkt/transport/rough/rough_mixture_cooling_state.hpp"

namespace gkt::test {

/// Returns the binary of components a, b in d dimensions with the pair restitutions (1–1, 1–2, 2–2).
inline RoughBinaryMixture binary(int d, const RoughMixtureComponent& a, const RoughMixtureComponent& b,
                                 const std::array<Rational, 3>& alpha, const std::array<Rational, 3>& beta) {
  RoughBinaryMixture m;
  m.dimension = d;
  m.species = {a, b};
  m.alpha = alpha;
  m.beta = beta;
  return m;
}

inline const RoughMixtureComponent kLight{Rational(1), Rational(2, 5), 1.0, 0.3};
inline const RoughMixtureComponent kHeavy{Rational(4), Rational(1, 2), 2.0, 0.7};

}  // namespace gkt::test
