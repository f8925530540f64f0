// The rough collision at fixed σ̂ as a linear map (docs/theory.md (19.4), (19.52)): every one of the
// eight vectors of RoughSlot is a linear combination of the normal coordinates (v1n, v2n) resp.
// (ŵ1n, ŵ2n) and of the tangential coordinates (v1t, v2t, ŝ1, ŝ2) (ŝ = ŵ × σ̂; disks: ŵ ẑ × σ̂),
// and the pre-collisional coordinates carry the Gaussian weight
//   exp(−width_0 v1² − width_1 v2² − width_2 ŵ1² − width_3 ŵ2²).
// One species (rough_collision_rule.hpp) and a pair of species (rough_mixture_collision_rule.hpp)
// differ only in this map; the Gaussian integral and its Taylor expansion
// (rough_collision_moments.hpp) take it as input.
#pragma once

#include <array>

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// Rows of the rough collision map and the Gaussian widths of the pre-collisional coordinates.
template <class Ring>
struct RoughCollisionMap {
  /// Spatial dimension d (2 or 3).
  int dimension = 3;
  /// Row of slot a over (v1n, v2n) for translational slots, over (ŵ1n, ŵ2n) for spin slots.
  std::array<std::array<Ring, 2>, 8> normal;
  /// Row of slot a over the tangential coordinates (v1t, v2t, ŝ1, ŝ2).
  std::array<std::array<Ring, 4>, 8> tangential;
  /// Gaussian widths of (v1, v2, ŵ1, ŵ2): the weight is exp(−Σ width_r x_r²) (exact, > 0).
  std::array<Rational, 4> width{Rational(1), Rational(1), Rational(1), Rational(1)};
};

}  // namespace gkt
