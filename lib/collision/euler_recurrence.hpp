// Private: the Euler-operator recurrence of docs/theory.md (3.3),
//   |m| f_m = Σ_{e≠0} (Qc_e − |m−e| Π_e) f_{m−e},   f_0 = 1,
// run on integers (polynomials in α with integer coefficients) under one common denominator
// per total degree instead of on normalised rationals (docs/performance.md: a gcd per operation
// was most of the cost). With c the least common multiple of the denominators of all Qc_e, Π_e
// and G_m := c^{|m|} |m|! f_m, multiplying the recurrence by c^{|m|} (|m| − 1)! gives
//   G_m = Σ_{j ≥ 1} c^{j−1} (|m| − 1)!/(|m| − j)! Σ_{|e| = j} (c Qc_e − (|m| − j) c Π_e) G_{m−e},
// integer throughout (the factor (|m| − 1)!/(|m| − j)! is a falling factorial). Each f_m is
// reduced once at the end: the result is the same exact value in the same canonical form.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <type_traits>
#include <utility>
#include <vector>

#include <flint/fmpq_poly.h>
#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_vec.h>

#include "collision/ring.hpp"

namespace gkt::detail {

/// An fmpz_poly with value semantics, for the recurrence's storage.
class IntegerPolynomial {
 public:
  IntegerPolynomial() { fmpz_poly_init(value_); }
  IntegerPolynomial(const IntegerPolynomial& o) {
    fmpz_poly_init(value_);
    fmpz_poly_set(value_, o.value_);
  }
  IntegerPolynomial(IntegerPolynomial&& o) noexcept {
    fmpz_poly_init(value_);
    fmpz_poly_swap(value_, o.value_);
  }
  IntegerPolynomial& operator=(const IntegerPolynomial& o) {
    if (this != &o) fmpz_poly_set(value_, o.value_);
    return *this;
  }
  IntegerPolynomial& operator=(IntegerPolynomial&& o) noexcept {
    fmpz_poly_swap(value_, o.value_);
    return *this;
  }
  ~IntegerPolynomial() { fmpz_poly_clear(value_); }
  fmpz_poly_struct* raw() { return value_; }
  [[nodiscard]] const fmpz_poly_struct* raw() const { return value_; }

 private:
  fmpz_poly_t value_;
};

/// An fmpz with value semantics.
class Integer {
 public:
  Integer() { fmpz_init(value_); }
  Integer(const Integer& o) {
    fmpz_init(value_);
    fmpz_set(value_, o.value_);
  }
  Integer& operator=(const Integer& o) {
    if (this != &o) fmpz_set(value_, o.value_);
    return *this;
  }
  ~Integer() { fmpz_clear(value_); }
  fmpz* raw() { return value_; }
  [[nodiscard]] const fmpz* raw() const { return value_; }

 private:
  fmpz_t value_;
};

/// acc += r · g for a short integer polynomial r (a few coefficients) and a long g; acc is left
/// unnormalised (call _fmpz_poly_normalise when done).
inline void add_short_product(fmpz_poly_struct* acc, const fmpz_poly_struct* r, const fmpz_poly_struct* g) {
  if (r->length == 0 || g->length == 0) return;
  const slong length = g->length + r->length - 1;
  if (acc->length < length) {
    fmpz_poly_fit_length(acc, length);
    // Past its length a polynomial may hold stale small values (FLINT only demotes them).
    _fmpz_vec_zero(acc->coeffs + acc->length, length - acc->length);
    _fmpz_poly_set_length(acc, length);
  }
  for (slong k = 0; k < r->length; ++k)
    if (!fmpz_is_zero(r->coeffs + k))
      _fmpz_vec_scalar_addmul_fmpz(acc->coeffs + k, g->coeffs, g->length, r->coeffs + k);
}

/// Returns f_m, 0 ≤ m_v ≤ box_v (k0 slowest, the last variable fastest), of the recurrence in N
/// variables whose terms `rec` carry the exponent shift e and the coefficients q = Qc_e, p = Π_e
/// (Term: members e (std::array<int, N>), q, p). With `keep` only the m it accepts are computed
/// (the others are left 0); the accepted set must be down-closed (m kept and m' ≤ m componentwise
/// ⇒ m' kept), which is what makes it closed under the recurrence.
template <class Ring, class Term, std::size_t N>
std::vector<Ring> solve_euler_recurrence(
    const std::vector<Term>& rec, const std::array<int, N>& box,
    const std::type_identity_t<std::function<bool(const std::array<int, N>&)>>& keep = {}) {
  // Row-major strides of the box: index(k) = Σ_v k_v stride_v, so index(m − e) = index(m) − index(e).
  std::array<std::size_t, N> stride{};
  std::size_t size = 1;
  for (std::size_t v = N; v-- > 0;) {
    stride[v] = size;
    size *= static_cast<std::size_t>(box[v] + 1);
  }
  int top_degree = 0;
  for (std::size_t v = 0; v < N; ++v) top_degree += box[v];

  // Common denominator c of every Qc_e, Π_e and their integer numerators c Qc_e, c Π_e.
  Integer c;
  fmpz_one(c.raw());
  for (const auto& r : rec) {
    accumulate_denominator(c.raw(), r.q);
    accumulate_denominator(c.raw(), r.p);
  }
  struct IntegerTerm {
    std::array<int, N> e;
    int degree;          // |e|
    std::size_t offset;  // index(e)
    IntegerPolynomial q, p;
  };
  std::vector<IntegerTerm> terms;
  int top_shift = 1;
  for (const auto& r : rec) {
    int degree = 0;
    std::size_t offset = 0;
    bool inside = true;
    for (std::size_t v = 0; v < N; ++v) {
      degree += r.e[v];
      offset += static_cast<std::size_t>(r.e[v]) * stride[v];
      inside = inside && r.e[v] <= box[v];
    }
    if (!inside || (keep && !keep(r.e))) continue;  // never reaches a computed coefficient
    IntegerTerm t{r.e, degree, offset, {}, {}};
    integer_numerator(t.q.raw(), r.q, c.raw());
    integer_numerator(t.p.raw(), r.p, c.raw());
    top_shift = std::max(top_shift, t.degree);
    terms.push_back(std::move(t));
  }
  std::vector<IntegerPolynomial> g(size);
  fmpz_poly_one(g[0].raw());

  // Per total degree n: the multipliers c^{j−1} (n−1)!/(n−j)! and the terms' r_e = c Qc_e − (n−|e|) c Π_e.
  const std::size_t shifts = static_cast<std::size_t>(top_shift) + 1;
  std::vector<Integer> multiplier(static_cast<std::size_t>(top_degree + 1) * shifts);
  std::vector<IntegerPolynomial> r_of_term(static_cast<std::size_t>(top_degree + 1) * terms.size());
  for (int n = 1; n <= top_degree; ++n) {
    for (int j = 2; j <= std::min(top_shift, n); ++j) {
      auto* m = multiplier[static_cast<std::size_t>(n) * shifts + static_cast<std::size_t>(j)].raw();
      fmpz_pow_ui(m, c.raw(), static_cast<ulong>(j - 1));
      for (int i = 1; i < j; ++i) fmpz_mul_ui(m, m, static_cast<ulong>(n - i));
    }
    for (std::size_t t = 0; t < terms.size(); ++t) {
      auto* r = r_of_term[static_cast<std::size_t>(n) * terms.size() + t].raw();
      fmpz_poly_scalar_mul_si(r, terms[t].p.raw(), -static_cast<slong>(n - terms[t].degree));
      fmpz_poly_add(r, r, terms[t].q.raw());
    }
  }
  std::vector<IntegerPolynomial> by_shift(shifts);
  IntegerPolynomial scaled;
  // Lexicographic order (an odometer, the last variable fastest): every m − e (e ≥ 0, e ≠ 0)
  // comes before m.
  std::array<int, N> k{};
  std::vector<int> total_degree(size, 0);
  for (std::size_t at = 1; at < size; ++at) {
    for (std::size_t v = N; v-- > 0;) {
      if (k[v] < box[v]) {
        ++k[v];
        break;
      }
      k[v] = 0;
    }
    int n = 0;
    for (std::size_t v = 0; v < N; ++v) n += k[v];
    total_degree[at] = n;
    if (keep && !keep(k)) continue;
    for (auto& s : by_shift) fmpz_poly_zero(s.raw());
    for (std::size_t t = 0; t < terms.size(); ++t) {
      const auto& e = terms[t].e;
      bool below = true;
      for (std::size_t v = 0; v < N && below; ++v) below = e[v] <= k[v];
      if (!below) continue;
      add_short_product(by_shift[static_cast<std::size_t>(terms[t].degree)].raw(),
                        r_of_term[static_cast<std::size_t>(n) * terms.size() + t].raw(), g[at - terms[t].offset].raw());
    }
    auto* out = g[at].raw();
    for (int j = 1; j <= top_shift; ++j) {
      auto* s = by_shift[static_cast<std::size_t>(j)].raw();
      if (s->length == 0) continue;
      _fmpz_poly_normalise(s);
      if (j == 1) {
        fmpz_poly_add(out, out, s);
      } else {
        fmpz_poly_scalar_mul_fmpz(scaled.raw(), s,
                                  multiplier[static_cast<std::size_t>(n) * shifts + static_cast<std::size_t>(j)].raw());
        fmpz_poly_add(out, out, scaled.raw());
      }
    }
  }

  // f_m = G_m / (c^{|m|} |m|!), reduced once.
  std::vector<Integer> denominator(static_cast<std::size_t>(top_degree) + 1);
  fmpz_one(denominator[0].raw());
  for (int n = 1; n <= top_degree; ++n) {
    fmpz_mul(denominator[n].raw(), denominator[n - 1].raw(), c.raw());
    fmpz_mul_ui(denominator[n].raw(), denominator[n].raw(), static_cast<ulong>(n));
  }
  std::vector<Ring> f;
  f.reserve(size);
  for (std::size_t at = 0; at < size; ++at) {
    f.push_back(ring_from_integer<Ring>(g[at].raw(), denominator[static_cast<std::size_t>(total_degree[at])].raw()));
    g[at] = IntegerPolynomial();  // free as we go
  }
  return f;
}

}  // namespace gkt::detail
