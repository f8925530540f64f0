#include "gkt/collision/rough_triple_product_moments.hpp"

#include <stdexcept>
#include <utility>

#include "collision/power_product_series.hpp"
#include "collision/rough_gaussian_blocks.hpp"

namespace gkt {

namespace {

constexpr std::size_t kVariables = kMaxTripleProductForms + 1;
using Box = detail::ExponentVector<kVariables>;
template <class Ring>
using Poly = detail::SmallPolynomial<Ring, kVariables>;
template <class Ring>
using Blocks = detail::RoughBlocks<Ring, kVariables>;

/// One term of the triple product at fixed σ̂ (theory.md (19.90)): (k·X_N) times the tangential bilinear
/// sign · P·Q (symmetric) or sign · PᵀJQ (rotation), P, Q rows over (v1t, v2t, ŝ1, ŝ2).
template <class Ring>
struct TripleTerm {
  std::array<Ring, 4> normal;
  std::array<Ring, 4> p, q;
  bool rotation = false;
  int sign = 1;
};

template <class Ring>
std::array<Ring, 4> zero_row() {
  return {Ring(0L), Ring(0L), Ring(0L), Ring(0L)};
}

/// Returns the normal component of slot a as a row over (v1n, v2n, ŵ1n, ŵ2n).
template <class Ring>
std::array<Ring, 4> normal_row(const RoughCollisionMap<Ring>& rows, RoughSlot a) {
  std::array<Ring, 4> k = zero_row<Ring>();
  const auto i = static_cast<std::size_t>(a);
  const std::size_t offset = is_spin_slot(a) ? 2 : 0;
  for (std::size_t r = 0; r < 2; ++r) k[offset + r] = rows.normal[i][r];
  return k;
}

/// Returns the terms of W_a·(W_b × W_c) (theory.md (19.90)).
template <class Ring>
std::vector<TripleTerm<Ring>> triple_terms(const RoughCollisionMap<Ring>& rows, RoughTripleProduct t) {
  std::vector<TripleTerm<Ring>> terms;
  const auto tangential = [&rows](RoughSlot a) { return rows.tangential[static_cast<std::size_t>(a)]; };
  if (rows.dimension == 2) {
    // w_x ẑ·(W_y × W_z) = ŝ_x (y_n z_t − y_t z_n): the spin's tangential coordinate is w (ŝ = ŵ ẑ × σ̂).
    int spins = 0;
    for (const RoughSlot s : t) spins += is_spin_slot(s) ? 1 : 0;
    if (spins != 1)
      throw std::invalid_argument("RoughTripleProductMoments: a disk triple product needs exactly one spin slot");
    while (!is_spin_slot(t[0])) t = {t[1], t[2], t[0]};
    terms.push_back({normal_row(rows, t[1]), tangential(t[0]), tangential(t[2]), false, 1});
    terms.push_back({normal_row(rows, t[2]), tangential(t[0]), tangential(t[1]), false, -1});
    return terms;
  }
  // d = 3: Σ_cyc W_xn σ̂·(W_yt × W_zt); a spin's tangential part is σ̂ × S (S its ŝ row), so
  // σ̂·(P × Q) = −PᵀJQ, σ̂·((σ̂ × S) × P) = −S·P, σ̂·(P × (σ̂ × S)) = P·S, σ̂·((σ̂×S) × (σ̂×S')) = −SᵀJS'.
  for (int c = 0; c < 3; ++c) {
    const RoughSlot x = t[c], y = t[(c + 1) % 3], z = t[(c + 2) % 3];
    const bool sy = is_spin_slot(y), sz = is_spin_slot(z);
    TripleTerm<Ring> term{normal_row(rows, x), tangential(y), tangential(z), sy == sz, 1};
    if (sy == sz || (sy && !sz)) term.sign = -1;
    terms.push_back(std::move(term));
  }
  return terms;
}

/// Returns the box index of e (first variable slowest).
std::size_t box_index(const Box& e, const Box& box) {
  std::size_t index = 0;
  for (std::size_t v = 0; v < kVariables; ++v) index = index * static_cast<std::size_t>(box[v] + 1) + e[v];
  return index;
}

/// Returns Σ_terms [x^k ε] (k·adj(M)ℓ) (det M/det M_0)^{−3/2} (T/T_0)^{r} over the box of the forms (ε the last
/// variable), T = det(A + iB) (r = −1, d = 3) or det A (r = −1/2, d = 2) with the term's bilinear added.
template <class Ring>
std::vector<Ring> triple_taylor(const RoughCollisionMap<Ring>& rows, const RoughTripleProduct& triple,
                                const std::vector<RoughForm>& forms, const Box& box) {
  const int d = rows.dimension;
  const std::size_t eps = kMaxTripleProductForms;
  const Blocks<Ring> blocks = detail::assemble_rough_blocks<Ring, kVariables>(rows, forms);
  const std::size_t m = d == 3 ? 4 : 2;
  std::vector<int> all(m);
  for (std::size_t i = 0; i < m; ++i) all[i] = static_cast<int>(i);
  const Poly<Ring> det_n = detail::determinant(blocks.normal, all, all, box);
  // adj(M)ℓ with ℓ = (1, −1, 0, 0): (adj ℓ)_i = adj_i0 − adj_i1, adj_ij = (−1)^{i+j} det M[≠j][≠i].
  std::array<Poly<Ring>, 4> adj_l;
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = 0; j < 2; ++j) {
      std::vector<int> r, c;
      for (std::size_t s = 0; s < m; ++s) {
        if (s != j) r.push_back(static_cast<int>(s));
        if (s != i) c.push_back(static_cast<int>(s));
      }
      Poly<Ring> minor = m == 2 ? blocks.normal[r[0]][c[0]] : detail::determinant(blocks.normal, r, c, box);
      const bool negative = ((i + j) % 2 == 1) != (j == 1);
      adj_l[i] = negative ? adj_l[i] - minor : adj_l[i] + minor;
    }
  Box slice = box;
  slice[eps] = 0;
  std::vector<Ring> out(box_index(slice, slice) + 1, Ring(0L));
  for (const TripleTerm<Ring>& term : triple_terms(rows, triple)) {
    Poly<Ring> linear;
    for (std::size_t i = 0; i < m; ++i) linear = linear + term.normal[i] * adj_l[i];
    if (linear.terms.empty()) continue;
    detail::PolyMatrix4<Ring, kVariables> mt = blocks.tangential, mb = blocks.rotation;
    Box e{};
    e[eps] = 1;
    for (std::size_t r = 0; r < 4; ++r)
      for (std::size_t s = 0; s < 4; ++s) {
        // exp(+ε sign bilinear): subtract its symmetric (A) or antisymmetric (B) matrix.
        Ring k = term.p[r] * term.q[s];
        Ring k_t = term.p[s] * term.q[r];
        Ring entry = term.rotation ? k - k_t : k + k_t;
        detail::divide(entry, Rational(-2 * term.sign));
        (term.rotation ? mb : mt)[r][s].add(e, entry);
      }
    std::vector<detail::PowerFactor<Ring, kVariables>> factors;
    factors.push_back({det_n, Rational(-3, 2)});
    if (d == 3)
      factors.push_back({detail::hermitian_determinant(mt, mb, box), Rational(-1)});
    else
      factors.push_back({detail::determinant(mt, {0, 1, 2, 3}, {0, 1, 2, 3}, box), Rational(-1, 2)});
    const std::vector<Ring> g = detail::expand_power_product(std::move(factors), box);
    // out[k] += Σ_{e ≤ k} linear_e g[k − e, ε = 1], walking k over the slice as an odometer.
    Box k{};
    for (std::size_t index = 0; index < out.size(); ++index) {
      for (const auto& t : linear.terms) {
        Box rest = k;
        bool inside = true;
        for (std::size_t v = 0; v < kVariables; ++v) {
          rest[v] -= t.e[v];
          inside = inside && rest[v] >= 0;
        }
        if (!inside) continue;
        rest[eps] = 1;
        out[index] = out[index] + t.c * g[box_index(rest, box)];
      }
      for (std::size_t v = kVariables; v-- > 0;) {
        if (k[v] < slice[v]) {
          ++k[v];
          break;
        }
        k[v] = 0;
      }
    }
  }
  return out;
}

}  // namespace

template <class Ring>
RoughTripleProductMoments<Ring>::RoughTripleProductMoments(const RoughCollisionParameters<Ring>& parameters,
                                                           const RoughTripleProduct& triple,
                                                           const std::vector<RoughForm>& forms,
                                                           const std::vector<int>& degrees)
    : RoughTripleProductMoments(parameters.collision_map(), triple, forms, degrees) {}

template <class Ring>
RoughTripleProductMoments<Ring>::RoughTripleProductMoments(const RoughCollisionMap<Ring>& rows,
                                                           const RoughTripleProduct& triple,
                                                           const std::vector<RoughForm>& forms,
                                                           const std::vector<int>& degrees) {
  if (forms.size() > kMaxTripleProductForms || forms.size() != degrees.size())
    throw std::invalid_argument("RoughTripleProductMoments: at most seven forms, one degree each");
  const int d = rows.dimension;
  if (d != 2 && d != 3) throw std::invalid_argument("dimension: must be 2 or 3");
  if (rows.width[0] != Rational(1) || rows.width[1] != Rational(1))
    throw std::invalid_argument("RoughTripleProductMoments: the translational widths must be 1");
  Box box{};
  for (std::size_t v = 0; v < forms.size(); ++v) {
    if (degrees[v] < 0) throw std::invalid_argument("RoughTripleProductMoments: negative degree");
    box[v] = degrees[v];
    box_[v] = degrees[v];
  }
  box[kMaxTripleProductForms] = 1;
  std::vector<Ring> f = triple_taylor(rows, triple, forms, box);
  // ⟨…⟩/⟨1⟩ = (√π/2) [x^k ε](…) k! / (a_0 n_0)^{1/2} with a_0 = 2 n_0 (unit translational widths), (19.92).
  Rational n0(1);
  for (int r = 0; r < (d == 3 ? 4 : 2); ++r) n0 *= rows.width[static_cast<std::size_t>(r)];
  values_.reserve(f.size());
  RoughExponents k{};
  for (std::size_t i = 0; i < f.size(); ++i) {
    Rational factor(1);
    for (const int kv : k) factor *= Rational::factorial(static_cast<unsigned long>(kv));
    factor /= Rational(2) * n0;
    Ring value = std::move(f[i]);
    detail::scale(value, factor);
    values_.push_back(std::move(value));
    for (std::size_t v = kMaxTripleProductForms; v-- > 0;) {
      if (k[v] < box_[v]) {
        ++k[v];
        break;
      }
      k[v] = 0;
    }
  }
}

template <class Ring>
Ring RoughTripleProductMoments<Ring>::moment(const RoughExponents& k) const {
  std::size_t index = 0;
  for (std::size_t v = 0; v < kMaxTripleProductForms; ++v) {
    if (k[v] < 0 || k[v] > box_[v])
      throw std::out_of_range("RoughTripleProductMoments: degree outside the expanded box");
    index = index * static_cast<std::size_t>(box_[v] + 1) + static_cast<std::size_t>(k[v]);
  }
  for (std::size_t v = kMaxTripleProductForms; v < kMaxRoughForms; ++v)
    if (k[v] != 0) throw std::out_of_range("RoughTripleProductMoments: degree outside the expanded box");
  return values_[index];
}

template class RoughTripleProductMoments<Rational>;
template class RoughTripleProductMoments<RationalPolynomial>;

}  // namespace gkt
