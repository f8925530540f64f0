// Private: the Gaussian blocks of the rough collision integral at fixed σ̂ (docs/theory.md §19.2, (19.5), (19.5a)):
// the normal block over (v1n, v2n, ŵ1n, ŵ2n), the tangential block A over (v1t, v2t, ŝ1, ŝ2) and its rotation part
// B (forms coupling v and w, d = 3), each entry a polynomial in the Taylor variables of the forms, with their
// determinants. Shared by the moments of quadratic forms (rough_collision_moments.cpp) and those with one triple
// product (rough_triple_product_moments.cpp, theory.md §19.22).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

#include "collision/power_product_series.hpp"
#include "collision/ring.hpp"
#include "gkt/collision/rough_collision_map.hpp"
#include "gkt/collision/rough_collision_moments.hpp"

namespace gkt::detail {

template <class Ring, std::size_t N>
using PolyMatrix4 = std::array<std::array<SmallPolynomial<Ring, N>, 4>, 4>;

/// Returns det of the submatrix m[rows][cols] by the Leibniz formula, truncated to the box.
template <class Ring, std::size_t N>
SmallPolynomial<Ring, N> determinant(const PolyMatrix4<Ring, N>& m, const std::vector<int>& rows,
                                     const std::vector<int>& cols, const ExponentVector<N>& box) {
  std::vector<int> perm(cols.size());
  for (std::size_t i = 0; i < perm.size(); ++i) perm[i] = static_cast<int>(i);
  SmallPolynomial<Ring, N> det;
  do {
    int inversions = 0;
    for (std::size_t i = 0; i < perm.size(); ++i)
      for (std::size_t j = i + 1; j < perm.size(); ++j)
        if (perm[i] > perm[j]) ++inversions;
    SmallPolynomial<Ring, N> term = m[rows[0]][cols[perm[0]]];
    for (std::size_t i = 1; i < perm.size() && !term.terms.empty(); ++i)
      term = truncated_product(term, m[rows[i]][cols[perm[i]]], box);
    det = inversions % 2 == 0 ? det + term : det - term;
  } while (std::next_permutation(perm.begin(), perm.end()));
  return det;
}

/// Returns det(A + iB) (real for A symmetric, B antisymmetric: a Hermitian matrix) by Leibniz.
template <class Ring, std::size_t N>
SmallPolynomial<Ring, N> hermitian_determinant(const PolyMatrix4<Ring, N>& a, const PolyMatrix4<Ring, N>& b,
                                               const ExponentVector<N>& box) {
  std::array<int, 4> perm{0, 1, 2, 3};
  SmallPolynomial<Ring, N> det;
  do {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (perm[i] > perm[j]) ++inversions;
    SmallPolynomial<Ring, N> re = a[0][perm[0]], im = b[0][perm[0]];
    for (int i = 1; i < 4; ++i) {
      const SmallPolynomial<Ring, N>& x = a[i][perm[i]];
      const SmallPolynomial<Ring, N>& y = b[i][perm[i]];
      SmallPolynomial<Ring, N> next_re = truncated_product(re, x, box) - truncated_product(im, y, box);
      SmallPolynomial<Ring, N> next_im = truncated_product(re, y, box) + truncated_product(im, x, box);
      re = std::move(next_re);
      im = std::move(next_im);
    }
    det = inversions % 2 == 0 ? det + re : det - re;
  } while (std::next_permutation(perm.begin(), perm.end()));
  return det;
}

/// The three blocks of the exponent −[X_Nᵀ normal X_N + Σ tangential_rs X_r·X_s + Σ rotation_rs X_rᵀ J X_s]
/// (J the rotation by +π/2 in the tangent plane, `rotation` antisymmetric); `mixed` when some form couples v and w.
template <class Ring, std::size_t N>
struct RoughBlocks {
  PolyMatrix4<Ring, N> normal, tangential, rotation;
  bool mixed = false;
};

/// Returns the blocks of exp(−reference + Σ_v x_v F_v) (x_v the v-th Taylor variable). Throws std::invalid_argument
/// for a width ≤ 0 and for a form pairing v and w when d = 2.
template <class Ring, std::size_t N>
RoughBlocks<Ring, N> assemble_rough_blocks(const RoughCollisionMap<Ring>& rows, const std::vector<RoughForm>& forms) {
  const int d = rows.dimension;
  // Normal block over (v1n, v2n, ŵ1n, ŵ2n) (the spin part only for d = 3), tangential block A over
  // (v1t, v2t, ŝ1, ŝ2) and, for forms coupling v and w, its rotation part B (theory.md (19.5a)).
  RoughBlocks<Ring, N> blocks;
  auto& mn = blocks.normal;
  auto& mt = blocks.tangential;
  auto& mb = blocks.rotation;
  // The reference Gaussians exp(−Σ width_r x_r²) (theory.md §19.2, (19.52)).
  for (int r = 0; r < 4; ++r) {
    if (rows.width[r].sign() <= 0) throw std::invalid_argument("RoughCollisionMoments: Gaussian widths must be > 0");
    mn[r][r].add(ExponentVector<N>{}, Ring(rows.width[r]));
    mt[r][r].add(ExponentVector<N>{}, Ring(rows.width[r]));
  }
  // exp(+Σ x_v F_v): each form subtracts x_v Σ_ab F_ab (row_a row_bᵀ) from the blocks.
  for (std::size_t v = 0; v < forms.size(); ++v) {
    ExponentVector<N> e{};
    e[v] = 1;
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b) {
        const Rational& f = forms[v][a][b];
        if (f.is_zero()) continue;
        const bool spin_a = is_spin_slot(static_cast<RoughSlot>(a)), spin_b = is_spin_slot(static_cast<RoughSlot>(b));
        if (spin_a != spin_b && d == 2)
          throw std::invalid_argument(
              "RoughCollisionMoments: v·w vanishes for disks (the spin is normal to the plane)");
        const Ring c(-f);
        const int oa = spin_a ? 2 : 0, ob = spin_b ? 2 : 0;
        for (int r = 0; r < 2; ++r)
          for (int s = 0; s < 2; ++s) mn[oa + r][ob + s].add(e, c * rows.normal[a][r] * rows.normal[b][s]);
        if (spin_a == spin_b) {
          for (int r = 0; r < 4; ++r)
            for (int s = 0; s < 4; ++s) mt[r][s].add(e, c * rows.tangential[a][r] * rows.tangential[b][s]);
          continue;
        }
        // v_t·w_t = v_t·(σ̂ × s): X_rᵀ J X_s with J the rotation by +π/2 (sign − when w comes first);
        // only the antisymmetric part in (r, s) survives.
        blocks.mixed = true;
        Ring half = spin_a ? -c : c;
        divide(half, Rational(2));
        for (int r = 0; r < 4; ++r)
          for (int s = 0; s < 4; ++s) {
            const Ring k = half * rows.tangential[a][r] * rows.tangential[b][s];
            mb[r][s].add(e, k);
            mb[s][r].add(e, -k);
          }
      }
  }
  return blocks;
}

}  // namespace gkt::detail
