#include "gkt/collision/collision_moments.hpp"

#include <cmath>
#include <stdexcept>

#include "collision/generating_series.hpp"
#include "gkt/algebra/sonine.hpp"
#include "gkt/collision/gaussian_collision_integral.hpp"
#include "gkt/collision/quadratic_form_moments.hpp"

namespace gkt {

namespace {

/// Returns S · Y · Sᵀ-type contraction: out(p, q) = Σ_{k ≤ q, k' ≤ p} S(q,k) S(p,k') y(k, k').
template <class Ring>
DenseMatrix<Ring> contract_with_sonine(const std::vector<std::vector<Rational>>& s, const DenseMatrix<Ring>& y,
                                       int n_max) {
  // first: t(k, p) = Σ_{k'} y(k, k') S(p, k')
  DenseMatrix<Ring> t(n_max + 1, n_max + 1);
  for (int k = 0; k <= n_max; ++k)
    for (int p = 0; p <= n_max; ++p) {
      Ring acc(0L);
      for (int kp = 0; kp <= p; ++kp) acc.add_product(y(k, kp), Ring(s[p][kp]));
      t(k, p) = std::move(acc);
    }
  DenseMatrix<Ring> out(n_max + 1, n_max + 1);
  for (int p = 0; p <= n_max; ++p)
    for (int q = 0; q <= n_max; ++q) {
      Ring acc(0L);
      for (int k = 0; k <= q; ++k) acc.add_product(t(k, p), Ring(s[q][k]));
      out(p, q) = std::move(acc);
    }
  return out;
}

}  // namespace

double reference_collision_integral(const CollisionPair& pair) {
  const double ti = pair.theta_i.to_double(), tj = pair.theta_j.to_double();
  return gaussian_integral_constant(pair.dimension) * std::sqrt(ti + tj) *
         std::pow(ti * tj, -0.5 * (pair.dimension + 1));
}

template <class Ring>
DenseMatrix<Ring> sonine_collision_moments(const CollisionPair& pair, const Ring& alpha, Slot unknown, Slot test,
                                           int rank, int n_max) {
  pair.validate();
  if (rank < 0 || rank > 2) throw std::invalid_argument("rank: must be 0, 1 or 2");
  if (n_max < 0) throw std::invalid_argument("n_max: must be >= 0");
  const int d = pair.dimension;
  const auto sonine = sonine_table(sonine_twice_m(d, rank), n_max);
  const int a = static_cast<int>(unknown), b = static_cast<int>(test);
  const Rational& theta_a = pair.theta(unknown);
  const Rational& theta_b = pair.theta(test);
  const detail::ExactForm q0 = detail::reference_form(pair);
  std::array<detail::ExactForm, detail::kVariables> dq{};
  DenseMatrix<Ring> y(n_max + 1, n_max + 1);

  if (a == b) {
    // One variable: ⟨x^n⟩ = n! f_n with exp(+x0 θ u²).
    dq[0][a][a] = -theta_a;
    const int top = 2 * n_max + rank;
    const auto f = detail::expand_gaussian_collision_integral<Ring>(pair, alpha, q0, dq, {top, 0, 0, 0});
    // Y_r(c)·Y_r(c) = 1, x, (1 − 1/d) x².
    const Rational tensor_factor = rank == 2 ? Rational(d - 1, static_cast<unsigned long>(d)) : Rational(1);
    for (int k = 0; k <= n_max; ++k)
      for (int kp = 0; kp <= n_max; ++kp) {
        const int n = k + kp + rank;
        Ring v = f(n, 0, 0);
        detail::scale(v, Rational::factorial(static_cast<unsigned long>(n)) * tensor_factor);
        y(k, kp) = std::move(v);
      }
    return contract_with_sonine(sonine, y, n_max);
  }

  // Three variables: exp(x0 θ_a u_a² + x1 θ_b u_b² + x2 √(θ_aθ_b) u_a·u_b).
  dq[0][a][a] = -theta_a;
  dq[1][b][b] = -theta_b;
  const Rational theta_ab = theta_a * theta_b;
  Rational cross_scale(1);  // (√(θ_aθ_b))^rank, applied after the expansion
  if (rank % 2 == 1) {
    if (!theta_ab.is_square())
      throw std::domain_error("sonine_collision_moments: θ_a θ_b = " + theta_ab.to_string() +
                              " has no rational square root (odd rank, exact ring)");
    cross_scale = theta_ab.exact_sqrt();
  } else if (rank == 2) {
    cross_scale = theta_ab;
  }
  dq[2][a][b] = Rational(-1, 2);
  dq[2][b][a] = Rational(-1, 2);
  const int extra = rank == 2 ? 1 : 0;
  const auto f =
      detail::expand_gaussian_collision_integral<Ring>(pair, alpha, q0, dq, {n_max + extra, n_max + extra, rank, 0});
  auto moment = [&](int k, int kp, int j) {  // ⟨x_a^k x_b^kp (u_a·u_b)^j⟩ / J0
    Ring v = f(k, kp, j);
    detail::scale(v, Rational::factorial(static_cast<unsigned long>(k)) *
                         Rational::factorial(static_cast<unsigned long>(kp)) *
                         Rational::factorial(static_cast<unsigned long>(j)));
    return v;
  };
  const Rational inv_d(1, static_cast<unsigned long>(d));
  for (int k = 0; k <= n_max; ++k)
    for (int kp = 0; kp <= n_max; ++kp) {
      Ring v = moment(k, kp, rank);
      detail::scale(v, cross_scale);
      if (rank == 2) {
        // (c_a·c_b)² − c_a² c_b²/d
        Ring w = moment(k + 1, kp + 1, 0);
        detail::scale(w, inv_d);
        v -= w;
      }
      y(k, kp) = std::move(v);
    }
  return contract_with_sonine(sonine, y, n_max);
}

namespace {

/// The forms of a CollisionMomentTable: θ_s u_s² at positions 0..2, and √(θ_aθ_b) u_a·u_b = c_a·c_b
/// at position 3 (theory.md (4.1)); validates the slots.
std::vector<VelocityForm> table_forms(const CollisionPair& pair, const std::vector<Slot>& x_slots,
                                      std::vector<int>& degrees,
                                      const std::optional<std::pair<Slot, Slot>>& contraction, int max_contraction) {
  if (x_slots.size() > 3 || x_slots.size() != degrees.size())
    throw std::invalid_argument("CollisionMomentTable: up to three X slots, one degree each");
  std::vector<VelocityForm> forms;
  for (std::size_t i = 0; i < x_slots.size(); ++i) {
    for (std::size_t k = 0; k < i; ++k)
      if (x_slots[k] == x_slots[i]) throw std::invalid_argument("CollisionMomentTable: repeated X slot");
    VelocityForm f = dot_form(slot_vector(x_slots[i]), slot_vector(x_slots[i]));
    for (auto& row : f)
      for (auto& v : row) v *= pair.theta(x_slots[i]);
    forms.push_back(f);
  }
  if (!contraction) return forms;
  if (contraction->first == contraction->second)
    throw std::invalid_argument("CollisionMomentTable: contraction needs two distinct slots");
  Rational cross_scale(1);
  const Rational product = pair.theta(contraction->first) * pair.theta(contraction->second);
  if (max_contraction > 0) {
    if (!product.is_square())
      throw std::domain_error("CollisionMomentTable: θ_a θ_b = " + product.to_string() + " is not a square");
    cross_scale = product.exact_sqrt();
  }
  while (forms.size() < 3) {
    forms.emplace_back();  // zero form, degree 0
    degrees.push_back(0);
  }
  VelocityForm f = dot_form(slot_vector(contraction->first), slot_vector(contraction->second));
  for (auto& row : f)
    for (auto& v : row) v *= cross_scale;
  forms.push_back(f);
  degrees.push_back(max_contraction);
  return forms;
}

template <class Ring>
QuadraticFormMoments<Ring> table_moments(const CollisionPair& pair, const Ring& alpha, const std::vector<Slot>& x_slots,
                                         std::vector<int> degrees,
                                         const std::optional<std::pair<Slot, Slot>>& contraction, int max_contraction,
                                         const Rational& power) {
  const auto forms = table_forms(pair, x_slots, degrees, contraction, max_contraction);
  return QuadraticFormMoments<Ring>(pair, alpha, forms, degrees, power);
}

}  // namespace

template <class Ring>
CollisionMomentTable<Ring>::CollisionMomentTable(const CollisionPair& pair, const Ring& alpha,
                                                 const std::vector<Slot>& x_slots, const std::vector<int>& max_degree,
                                                 std::optional<std::pair<Slot, Slot>> contraction, int max_contraction,
                                                 const Rational& power)
    : moments_(table_moments(pair, alpha, x_slots, max_degree, contraction, max_contraction, power)) {}

template <class Ring>
Ring CollisionMomentTable<Ring>::moment(const std::vector<int>& k, int j) const {
  std::array<int, 4> e{0, 0, 0, j};
  for (std::size_t i = 0; i < k.size(); ++i) e[i] = k[i];
  return moments_.moment(e);
}

template class CollisionMomentTable<Rational>;
template class CollisionMomentTable<RationalPolynomial>;

template <class Ring>
ScalarMomentTable<Ring> scalar_collision_moments(const CollisionPair& pair, const Ring& alpha, int k_max) {
  pair.validate();
  if (k_max < 0) throw std::invalid_argument("k_max: must be >= 0");
  std::array<detail::ExactForm, detail::kVariables> dq{};
  dq[0][0][0] = -pair.theta_i;  // x0 ↔ X1
  dq[1][1][1] = -pair.theta_j;  // x1 ↔ X2
  dq[2][2][2] = -pair.theta_i;  // x2 ↔ X1'
  const auto f = detail::expand_gaussian_collision_integral<Ring>(pair, alpha, detail::reference_form(pair), dq,
                                                                  {2 * k_max, k_max, k_max, 0});
  ScalarMomentTable<Ring> table;
  table.k_max = k_max;
  table.values.reserve(f.coefficients.size());
  for (int a = 0; a <= 2 * k_max; ++a)
    for (int b = 0; b <= k_max; ++b)
      for (int c = 0; c <= k_max; ++c) {
        Ring v = f(a, b, c);  // (4.1): ⟨X1^a X2^b X1'^c⟩/J0 = a! b! c! f_abc
        detail::scale(v, Rational::factorial(static_cast<unsigned long>(a)) *
                             Rational::factorial(static_cast<unsigned long>(b)) *
                             Rational::factorial(static_cast<unsigned long>(c)));
        table.values.push_back(std::move(v));
      }
  return table;
}

template ScalarMomentTable<Rational> scalar_collision_moments<Rational>(const CollisionPair&, const Rational&, int);
template ScalarMomentTable<RationalPolynomial> scalar_collision_moments<RationalPolynomial>(const CollisionPair&,
                                                                                            const RationalPolynomial&,
                                                                                            int);

template DenseMatrix<Rational> sonine_collision_moments<Rational>(const CollisionPair&, const Rational&, Slot, Slot,
                                                                  int, int);
template DenseMatrix<RationalPolynomial> sonine_collision_moments<RationalPolynomial>(const CollisionPair&,
                                                                                      const RationalPolynomial&, Slot,
                                                                                      Slot, int, int);

}  // namespace gkt
