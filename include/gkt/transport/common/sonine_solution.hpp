// Exact solution of truncated Sonine systems and the estimate of their truncation error.
//
// Layer: Chapman–Enskog solvers. Exact linear algebra is FLINT's fmpq_mat (fraction-free
// solve); nothing here rounds.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "gkt/algebra/dense_matrix.hpp"
#include "gkt/algebra/rational.hpp"

namespace gkt {

/// Returns component 0 of x solving L_b x = e_0, where L_b is the n × n diagonal block of L
/// starting at (first, first) and e_0 the first unit vector (exact; throws if singular).
Rational solve_first_component(const DenseMatrix<Rational>& l, int first, int n);

/// Why a truncation estimate is flagged not converging (docs/theory.md (6.1), (6.3)).
enum class Divergence {
  none,              ///< converging (or the estimate did not look past its three values)
  growing,           ///< (6.1): |Δ2| ≥ |Δ1|, the changes do not shrink
  turn_growing,      ///< (6.3): Δ1, Δ2 change sign and Δ3 follows Δ2 without shrinking (q ≥ 1)
  turn_unconfirmed,  ///< (6.3): Δ1, Δ2 change sign and no v_{N+3} exists to confirm an alternation
  /// (19.101): a later order of the window differs from v_N by more than (6.3) claimed; the error was widened to
  /// the window's spread (set with `converging` as (6.3) left it: it says why a missed tolerance was missed)
  wandering,
};

/// A Sonine-order sequence value with its estimated truncation error.
struct TruncationEstimate {
  Rational value;                            ///< the value at the requested order N
  Rational error;                            ///< estimated |value − converged value|
  bool converging;                           ///< false if the next two corrections do not shrink
  Divergence divergence = Divergence::none;  ///< why `converging` is false (wandering: why the error was widened)
};

/// Returns the reason a value at Sonine order `order` is flagged not converging, in words naming the orders
/// whose changes showed it (e.g. "error estimate not confirmed: changes do not shrink at orders 7–9"); empty for
/// Divergence::none.
std::string describe_divergence(Divergence divergence, int order);

/// Returns v_N with error (5/4)|Δ1|/(1 − r), Δ1 = v_{N+1} − v_N, r = Δ2/Δ1 (signed),
/// Δ2 = v_{N+2} − v_{N+1}: the geometric tail, monotone or alternating, with a 25 % margin
/// (docs/theory.md §6). If |r| ≥ 1 the error is |Δ1| + |Δ2| and `converging` is false.
TruncationEstimate estimate_truncation(const Rational& v_n, const Rational& v_n1, const Rational& v_n2);

/// Returns true if the changes v_{N+1} − v_N and v_{N+2} − v_{N+1} have opposite signs: (6.1) then reads
/// an alternation, which a turning point mimics, and estimate_truncation_confirmed needs v_{N+3}.
bool changes_sign(const Rational& v_n, const Rational& v_n1, const Rational& v_n2);

/// Returns v_N with the error (6.3) of docs/theory.md §6: (6.1) from v_N, v_{N+1}, v_{N+2}, except where the
/// changes Δ1 = v_{N+1} − v_N, Δ2 = v_{N+2} − v_{N+1} have opposite signs. There the alternation must be
/// confirmed by Δ3 = v_{N+3} − v_{N+2} flipping back (then (6.1)); if Δ3 has the sign of Δ2 the sequence
/// turned at N + 1 and the error is (5/4)(|Δ1| + |Δ2|/(1 − q)), q = Δ3/Δ2, the monotone tail after the turn
/// (q ≥ 1: |Δ1| + |Δ2| + |Δ3|, `converging` false). Without v_{N+3} (`v_n3` empty) an unconfirmed
/// alternation is |Δ1| + |Δ2|, `converging` false. v_n3 is read only where Δ1, Δ2 change sign.
TruncationEstimate estimate_truncation_confirmed(const Rational& v_n, const Rational& v_n1, const Rational& v_n2,
                                                 const std::optional<Rational>& v_n3);

/// Returns estimate_truncation_confirmed(v_n, v_n1, v_n2, next()) where Δ1, Δ2 change sign and
/// estimate_truncation(v_n, v_n1, v_n2) elsewhere: rule (6.3) of docs/theory.md §6, every Sonine scan's one
/// error rule; `next()` (a std::optional<Rational>, empty where order N + 3 does not exist) is called only there.
template <class Next>
TruncationEstimate estimate_truncation_checked(const Rational& v_n, const Rational& v_n1, const Rational& v_n2,
                                               Next&& next) {
  if (!changes_sign(v_n, v_n1, v_n2)) return estimate_truncation(v_n, v_n1, v_n2);
  return estimate_truncation_confirmed(v_n, v_n1, v_n2, next());
}

/// Returns v_N with the window error of docs/theory.md (19.100)–(19.101), from the values v = (v_N, …, v_H) of
/// every order up to the highest one H a scan computed: (6.3) from v_N … v_{N+3} (estimate_truncation_confirmed,
/// v_{N+3} where H ≥ N + 3), widened to W + T if that is larger, W = max_{N<M≤H} |v_M − v_N| the window's spread
/// and T the (6.1) error of v_{H−2} from v_{H−2}, v_{H−1}, v_H (its |Δ1| + |Δ2| where (6.1) flags it). Where W
/// exceeds the (6.3) error the divergence is Divergence::wandering (`converging` as (6.3) says). With H ≤ N + 2
/// it is (6.3). Throws std::invalid_argument if v has fewer than three values.
TruncationEstimate estimate_truncation_windowed(std::span<const Rational> v);

/// Returns true if v_N, v_{N+1}, v_{N+2} alternate as on the plateau of an asymptotic series: the
/// signed ratio (v_{N+2} − v_{N+1})/(v_{N+1} − v_N) lies in [−2, −1/2] (docs/theory.md §6).
bool alternates_on_plateau(const Rational& v_n, const Rational& v_n1, const Rational& v_n2);

/// Returns the Euler sum of v_N … v_{N+3} with its error if every three successive values
/// alternate on a plateau (alternates_on_plateau), else nothing: the value is the third Euler mean
/// (v_N + 3v_{N+1} + 3v_{N+2} + v_{N+3})/8, the error 5/4 of the spread (largest minus smallest) of
/// the window's six Euler means (three first, two second, one third) but at least half the smallest
/// change, `converging` true (docs/theory.md (6.2); measured honest against the tail scheme there).
std::optional<TruncationEstimate> estimate_alternating_plateau(std::span<const Rational, 4> v);

}  // namespace gkt
