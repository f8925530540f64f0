#include "gkt/linearized_operator.hpp"

#include <cmath>
#include <numbers>

#include "gkt/collision_moments.hpp"
#include "gkt/gaussian_collision_integral.hpp"

namespace gkt {

double linearized_operator_prefactor(int dimension) {
  // ν = π^{−d} J0 with θ = 1: J0 = K_d √2 (collision_moments.hpp).
  const CollisionPair unit{dimension, Rational(1), Rational(1), Rational(1), Rational(1)};
  return reference_collision_integral(unit) * std::pow(std::numbers::pi, -dimension);
}

template <class Ring>
DenseMatrix<Ring> linearized_operator_matrix(int dimension, const Ring& alpha, OperatorPart part, int rank, int n_max) {
  const CollisionPair pair{dimension, Rational(1), Rational(1), Rational(1), Rational(1)};
  // L = −[M(1→1') − M(1→1)] − [M(2→1') − M(2→1)]   (unknown → test slot)
  auto gain1 = sonine_collision_moments<Ring>(pair, alpha, Slot::v1, Slot::v1_post, rank, n_max);
  const auto loss1 = sonine_collision_moments<Ring>(pair, alpha, Slot::v1, Slot::v1, rank, n_max);
  DenseMatrix<Ring> l(n_max + 1, n_max + 1);
  for (int p = 0; p <= n_max; ++p)
    for (int q = 0; q <= n_max; ++q) l(p, q) = loss1(p, q) - gain1(p, q);
  if (part == OperatorPart::full) {
    const auto gain2 = sonine_collision_moments<Ring>(pair, alpha, Slot::v2, Slot::v1_post, rank, n_max);
    const auto loss2 = sonine_collision_moments<Ring>(pair, alpha, Slot::v2, Slot::v1, rank, n_max);
    for (int p = 0; p <= n_max; ++p)
      for (int q = 0; q <= n_max; ++q) l(p, q) += loss2(p, q) - gain2(p, q);
  }
  return l;
}

template DenseMatrix<Rational> linearized_operator_matrix<Rational>(int, const Rational&, OperatorPart, int, int);
template DenseMatrix<RationalPolynomial> linearized_operator_matrix<RationalPolynomial>(int, const RationalPolynomial&,
                                                                                        OperatorPart, int, int);

}  // namespace gkt
