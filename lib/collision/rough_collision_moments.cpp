#include "gkt/collision/rough_collision_moments.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "collision/power_product_series.hpp"
#include "collision/rough_gaussian_blocks.hpp"

namespace gkt {

namespace {

constexpr std::size_t kRoughVariables = kMaxRoughForms;
/// The recurrence runs in eight variables up to eight forms and in nine above (the oriented nonlinear HCS,
/// theory.md §19.14): a wider exponent vector slows every product, so the narrow one is kept where it suffices.
constexpr std::size_t kNarrowVariables = 8;
static_assert(kRoughVariables >= kNarrowVariables);
template <std::size_t N>
using Box = detail::ExponentVector<N>;
template <class Ring, std::size_t N>
using Poly = detail::SmallPolynomial<Ring, N>;
template <class Ring, std::size_t N>
using PolyMatrix4 = detail::PolyMatrix4<Ring, N>;
using detail::determinant;
using detail::hermitian_determinant;
/// Returns the Taylor coefficients of the rough integral J (theory.md (19.5), (19.5a)) along the forms, in N ≥ the
/// number of forms variables, over the box (the forms past their number at degree 0) and the kept set, in the index
/// order of the box (the first form slowest).
template <class Ring, std::size_t N>
std::vector<Ring> rough_taylor_coefficients(const RoughCollisionMap<Ring>& rows, const std::vector<RoughForm>& forms,
                                            const RoughExponents& full_box,
                                            const std::function<bool(const RoughExponents&)>& keep) {
  const int d = rows.dimension;
  Box<N> box{};
  for (std::size_t v = 0; v < N; ++v) box[v] = full_box[v];
  const detail::RoughBlocks<Ring, N> blocks = detail::assemble_rough_blocks<Ring, N>(rows, forms);
  const PolyMatrix4<Ring, N>& mn = blocks.normal;
  const PolyMatrix4<Ring, N>& mt = blocks.tangential;
  const PolyMatrix4<Ring, N>& mb = blocks.rotation;
  const bool mixed = blocks.mixed;
  std::vector<detail::PowerFactor<Ring, N>> factors;
  const Ring two(2L);
  if (!mixed) {
    // a = ℓᵀ adj(M_v) ℓ with ℓ = (1, −1) (u = v1n − v2n), n_v = det M_v, n_w = det M_w, t = det M_t.
    Poly<Ring, N> a = mn[0][0] + mn[1][1] + two * mn[0][1];
    factors.push_back({a, Rational(1, 2)});
    factors.push_back({determinant(mn, {0, 1}, {0, 1}, box), Rational(-1)});
    if (d == 3) factors.push_back({determinant(mn, {2, 3}, {2, 3}, box), Rational(-1, 2)});
    factors.push_back({determinant(mt, {0, 1, 2, 3}, {0, 1, 2, 3}, box), Rational(-(d - 1), 2)});
  } else {
    // d = 3 with v·w forms: a = ℓᵀ adj(M_N) ℓ, n = det M_N over the whole normal block, and the two
    // tangential copies give det(A⊗I + B⊗J)^{−1/2} = det(A + iB)^{−1}.
    const Poly<Ring, N> c00 = determinant(mn, {1, 2, 3}, {1, 2, 3}, box),
                        c11 = determinant(mn, {0, 2, 3}, {0, 2, 3}, box);
    const Poly<Ring, N> c01 = determinant(mn, {1, 2, 3}, {0, 2, 3}, box);  // (−1)^{0+1}·this = adj_01
    factors.push_back({c00 + c11 + two * c01, Rational(1, 2)});
    factors.push_back({determinant(mn, {0, 1, 2, 3}, {0, 1, 2, 3}, box), Rational(-1)});
    factors.push_back({hermitian_determinant(mt, mb, box), Rational(-1)});
  }
  std::function<bool(const Box<N>&)> narrow_keep;
  if (keep) narrow_keep = [&keep](const Box<N>& e) { return keep(rough_exponents(e)); };
  return detail::expand_power_product(std::move(factors), box, narrow_keep);
}

}  // namespace

RoughForm rough_dot_form(RoughSlot a, RoughSlot b) {
  RoughForm f{};
  const auto i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b);
  f[i][j] += Rational(1, 2);
  f[j][i] += Rational(1, 2);
  return f;
}

RoughForm scaled(const RoughForm& f, const Rational& c) {
  RoughForm r = f;
  for (auto& row : r)
    for (auto& x : row) x *= c;
  return r;
}

RoughForm operator+(const RoughForm& f, const RoughForm& g) {
  RoughForm r = f;
  for (std::size_t a = 0; a < 8; ++a)
    for (std::size_t b = 0; b < 8; ++b) r[a][b] += g[a][b];
  return r;
}

template <class Ring>
RoughCollisionMoments<Ring>::RoughCollisionMoments(const RoughCollisionParameters<Ring>& parameters,
                                                   const std::vector<RoughForm>& forms, const std::vector<int>& degrees)
    : RoughCollisionMoments(parameters, forms, degrees, {}) {}

template <class Ring>
RoughCollisionMoments<Ring>::RoughCollisionMoments(const RoughCollisionParameters<Ring>& parameters,
                                                   const std::vector<RoughForm>& forms, const std::vector<int>& degrees,
                                                   std::function<bool(const RoughExponents&)> keep)
    : RoughCollisionMoments(parameters.collision_map(), forms, degrees, std::move(keep)) {}

template <class Ring>
RoughCollisionMoments<Ring>::RoughCollisionMoments(const RoughCollisionMap<Ring>& rows,
                                                   const std::vector<RoughForm>& forms, const std::vector<int>& degrees,
                                                   std::function<bool(const RoughExponents&)> keep)
    : keep_(std::move(keep)) {
  if (forms.size() > kRoughVariables || forms.size() != degrees.size())
    throw std::invalid_argument("RoughCollisionMoments: at most nine forms, one degree each");
  const int d = rows.dimension;
  if (d != 2 && d != 3) throw std::invalid_argument("dimension: must be 2 or 3");
  RoughExponents box{};
  for (std::size_t v = 0; v < forms.size(); ++v) {
    if (degrees[v] < 0) throw std::invalid_argument("RoughCollisionMoments: negative degree");
    box[v] = degrees[v];
  }
  auto f = forms.size() <= kNarrowVariables ? rough_taylor_coefficients<Ring, kNarrowVariables>(rows, forms, box, keep_)
                                            : rough_taylor_coefficients<Ring, kRoughVariables>(rows, forms, box, keep_);
  box_ = box;
  // f_k = ⟨Π F_v^{k_v}⟩/(⟨1⟩ Π k_v!): multiply by the factorials, walking the box in its index
  // order (an odometer, the last form fastest).
  values_.reserve(f.size());
  RoughExponents k{};
  for (std::size_t i = 0; i < f.size(); ++i) {
    Rational factorials(1);
    for (const int kv : k) factorials *= Rational::factorial(static_cast<unsigned long>(kv));
    Ring value = std::move(f[i]);
    detail::scale(value, factorials);
    values_.push_back(std::move(value));
    for (std::size_t v = kRoughVariables; v-- > 0;) {
      if (k[v] < box[v]) {
        ++k[v];
        break;
      }
      k[v] = 0;
    }
  }
}

template <class Ring>
Ring RoughCollisionMoments<Ring>::moment(const RoughExponents& k) const {
  std::size_t index = 0;
  for (std::size_t v = 0; v < kRoughVariables; ++v) {
    if (k[v] < 0 || k[v] > box_[v]) throw std::out_of_range("RoughCollisionMoments: degree outside the expanded box");
    index = index * static_cast<std::size_t>(box_[v] + 1) + static_cast<std::size_t>(k[v]);
  }
  if (keep_ && !keep_(k)) throw std::out_of_range("RoughCollisionMoments: moment outside the kept set");
  return values_[index];
}

template class RoughCollisionMoments<Rational>;
template class RoughCollisionMoments<RationalPolynomial>;

}  // namespace gkt
