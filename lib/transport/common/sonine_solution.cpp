#include "gkt/transport/common/sonine_solution.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <stdexcept>
#include <string>

#include <flint/fmpq_mat.h>

namespace gkt {

namespace {
/// RAII owner of an fmpq_mat_t.
class ExactMatrix {
 public:
  ExactMatrix(long rows, long cols) { fmpq_mat_init(m_, rows, cols); }
  ExactMatrix(const ExactMatrix&) = delete;
  ExactMatrix& operator=(const ExactMatrix&) = delete;
  ~ExactMatrix() { fmpq_mat_clear(m_); }
  fmpq* at(long r, long c) { return fmpq_mat_entry(m_, r, c); }
  fmpq_mat_struct* raw() { return m_; }

 private:
  fmpq_mat_t m_;
};
}  // namespace

Rational solve_first_component(const DenseMatrix<Rational>& l, int first, int n) {
  if (first < 0 || n < 1 || first + n > l.rows() || first + n > l.cols())
    throw std::out_of_range("solve_first_component: block outside the matrix");
  ExactMatrix a(n, n), b(n, 1), x(n, 1);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) fmpq_set(a.at(r, c), l(first + r, first + c).raw());
  fmpq_set_si(b.at(0, 0), 1, 1);
  if (fmpq_mat_solve(x.raw(), a.raw(), b.raw()) == 0)
    throw std::domain_error("solve_first_component: singular Sonine matrix");
  Rational result;
  fmpq_set(result.raw(), x.at(0, 0));
  return result;
}

TruncationEstimate estimate_truncation(const Rational& v_n, const Rational& v_n1, const Rational& v_n2) {
  const Rational first = v_n1 - v_n;
  const Rational second = v_n2 - v_n1;
  if (first.is_zero())
    return {v_n, second.abs(), second.is_zero(), second.is_zero() ? Divergence::none : Divergence::growing};
  // Signed ratio: monotone (r > 0) and alternating (r < 0) geometric tails both sum to
  // first/(1 − r).
  const Rational ratio = second / first;
  if (ratio.abs() >= Rational(1)) return {v_n, first.abs() + second.abs(), false, Divergence::growing};
  // The geometric tail underestimates slowly accelerating-ratio sequences by ~2 % (elastic hard
  // spheres, N = 1..25: actual/estimate = 0.98–1.00); the 5/4 margin makes it an upper bound there.
  return {v_n, Rational(5, 4) * first.abs() / (Rational(1) - ratio), true};
}

std::string describe_divergence(Divergence divergence, int order) {
  const std::string n = std::to_string(order), n1 = std::to_string(order + 1), n2 = std::to_string(order + 2),
                    n3 = std::to_string(order + 3);
  switch (divergence) {
    case Divergence::growing:  // (6.1) with |r| ≥ 1
      return "error estimate not confirmed: the changes do not shrink at orders " + n + "–" + n2 + " (|v" + n2 +
             " − v" + n1 + "| ≥ |v" + n1 + " − v" + n + "|)";
    case Divergence::turn_growing:  // (6.3) with q ≥ 1
      return "error estimate not confirmed: the changes turn at order " + n1 + " and do not shrink after it (orders " +
             n + "–" + n3 + ")";
    case Divergence::turn_unconfirmed:  // (6.3) without v_{N+3}
      return "error estimate not confirmed: the changes change sign at order " + n1 + " and no order " + n3 +
             " exists to tell an alternation from a turn";
    case Divergence::wandering:  // (19.101): a later order refutes (6.3)
      return "error estimate widened: a later order (up to the scan's cap) differs from v" + n +
             " by more than the estimate from orders " + n + "–" + n3 +
             "; the sequence wanders and the error is the window's spread (theory.md §19.23)";
    case Divergence::none:
      break;
  }
  return {};
}

bool changes_sign(const Rational& v_n, const Rational& v_n1, const Rational& v_n2) {
  return (v_n1 - v_n).sign() * (v_n2 - v_n1).sign() < 0;
}

TruncationEstimate estimate_truncation_confirmed(const Rational& v_n, const Rational& v_n1, const Rational& v_n2,
                                                 const std::optional<Rational>& v_n3) {
  if (!changes_sign(v_n, v_n1, v_n2)) return estimate_truncation(v_n, v_n1, v_n2);
  const Rational first = (v_n1 - v_n).abs();
  const Rational second = v_n2 - v_n1;
  // An alternation read from two changes may be a turning point (theory.md (6.3)): a monotone approach that
  // overshot at N + 1 and now comes back. Only a third change flipping back confirms the alternation.
  if (!v_n3) return {v_n, first + second.abs(), false, Divergence::turn_unconfirmed};
  const Rational third = *v_n3 - v_n2;
  if (third.sign() * second.sign() < 0) return estimate_truncation(v_n, v_n1, v_n2);
  // Turned at N + 1: the remainder is Δ1 plus the monotone tail Δ2/(1 − q) after the turn; they have opposite
  // signs, so their magnitudes' sum bounds it (5/4 as in (6.1)).
  const Rational q = third / second;
  if (q >= Rational(1)) return {v_n, first + second.abs() + third.abs(), false, Divergence::turn_growing};
  return {v_n, Rational(5, 4) * (first + second.abs() / (Rational(1) - q)), true};
}

TruncationEstimate estimate_truncation_windowed(std::span<const Rational> v) {
  if (v.size() < 3) throw std::invalid_argument("estimate_truncation_windowed: needs v_N, v_{N+1}, v_{N+2}");
  const std::optional<Rational> v3 = v.size() > 3 ? std::optional<Rational>(v[3]) : std::nullopt;
  TruncationEstimate base = estimate_truncation_confirmed(v[0], v[1], v[2], v3);
  if (v.size() == 3) return base;  // no order beyond those (6.3) reads
  // theory.md (19.100): every later order computed must agree with v_N within the error; past the last one H the
  // remainder of v_{H−2} by (6.1) (its magnitude-sum bound where (6.1) flags it).
  Rational spread(0);
  for (std::size_t m = 1; m < v.size(); ++m) spread = std::max(spread, (v[m] - v[0]).abs());
  const std::size_t h = v.size() - 1;
  const Rational widened = spread + estimate_truncation(v[h - 2], v[h - 1], v[h]).error;
  if (spread > base.error && base.divergence == Divergence::none) base.divergence = Divergence::wandering;  // (19.101)
  if (widened > base.error) base.error = widened;
  return base;
}

bool alternates_on_plateau(const Rational& v_n, const Rational& v_n1, const Rational& v_n2) {
  const Rational first = v_n1 - v_n;
  if (first.is_zero()) return false;
  const Rational ratio = (v_n2 - v_n1) / first;
  return ratio >= Rational(-2) && ratio <= Rational(-1, 2);
}

std::optional<TruncationEstimate> estimate_alternating_plateau(std::span<const Rational, 4> v) {
  if (!alternates_on_plateau(v[0], v[1], v[2]) || !alternates_on_plateau(v[1], v[2], v[3])) return std::nullopt;
  // Euler means (theory.md (6.2)): each averages successive values, which multiplies an alternating
  // part of ratio −ρ by |1 − ρ|/2 (≤ 1/2 for ρ in [1/2, 2]) and a monotone part of ratio q by (1 + q)/2.
  const Rational half(1, 2);
  const std::array<Rational, 3> first{(v[0] + v[1]) * half, (v[1] + v[2]) * half, (v[2] + v[3]) * half};
  const std::array<Rational, 2> second{(first[0] + first[1]) * half, (first[1] + first[2]) * half};
  const Rational third = (second[0] + second[1]) * half;
  Rational low = third, high = third;
  for (const Rational& m : {first[0], first[1], first[2], second[0], second[1]}) {
    if (m < low) low = m;
    if (m > high) high = m;
  }
  // The spread bounds the remainder of the slow monotone part it sees decaying across the window
  // (5/4 as in (6.1)); it is floored at half the smallest change, the bracket of the optimal truncation,
  // since a clean ± alternation makes the spread collapse beyond what was measured. Measured: actual/
  // estimated ≤ 0.62 against the tail scheme (2D, α = 0.8, κ*, μ*; theory.md §6).
  Rational smallest = (v[1] - v[0]).abs();
  for (std::size_t i = 2; i < v.size(); ++i)
    if ((v[i] - v[i - 1]).abs() < smallest) smallest = (v[i] - v[i - 1]).abs();
  Rational error = Rational(5, 4) * (high - low);
  if (error < smallest * half) error = smallest * half;
  return TruncationEstimate{third, error, true};
}

}  // namespace gkt
