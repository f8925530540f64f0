// The moment solution of the steady uniform shear flow beyond Grad (uniform_shear_moments.hpp;
// docs/theory.md §22.7).
#include "gkt/transport/closed_forms/uniform_shear_moments.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "gkt/operators/cartesian_collision_moments.hpp"
#include "gkt/transport/closed_forms/uniform_shear_flow.hpp"

namespace gkt {

namespace {

/// Returns ⟨c^m h_n(c)⟩ = ∫π^{−1/2}e^{−c²} c^m h_n(c) dc from c h_n = √((n+1)/2) h_{n+1} + √(n/2) h_{n−1}.
double hermite_moment(int m, int n) {
  std::vector<double> v(static_cast<std::size_t>(m + 2), 0.0), next(v.size());
  v[0] = 1;  // c⁰ = h_0
  for (int step = 0; step < m; ++step) {
    std::fill(next.begin(), next.end(), 0.0);
    for (int k = 0; k <= step; ++k) {
      const double x = v[static_cast<std::size_t>(k)];
      next[static_cast<std::size_t>(k + 1)] += std::sqrt((k + 1) / 2.0) * x;
      if (k > 0) next[static_cast<std::size_t>(k - 1)] += std::sqrt(k / 2.0) * x;
    }
    v.swap(next);
  }
  return n <= m ? v[static_cast<std::size_t>(n)] : 0.0;
}

/// ν0/(n σ^{d−1} √(2T/m)): √(2π) (d = 2), (16/5)√(π/2) (d = 3) (docs/conventions.md ν0 = nT/η0).
double collision_frequency_factor(int d) {
  return d == 2 ? std::sqrt(2 * std::numbers::pi) : 3.2 * std::sqrt(std::numbers::pi / 2);
}

/// The Galerkin system of one order: basis, collision tensor, streaming matrix.
class MomentEquations {
 public:
  MomentEquations(int d, double alpha, int order)
      : d_(d),
        basis_(shear_symmetric_hermite_basis(d, 2 * order)),
        moments_(cartesian_collision_moments(d, alpha, basis_)),
        k_(basis_.size()),
        streaming_(Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(k_), static_cast<Eigen::Index>(k_))) {
    // S(k, i) = ∫w ψ_i c_y ∂ψ_k/∂c_x: ∂_x h_n = √(2n) h_{n−1}, c h_n = √((n+1)/2) h_{n+1} + √(n/2) h_{n−1}.
    for (std::size_t k = 0; k < k_; ++k) {
      const auto& n = basis_[k];
      if (n[0] == 0) continue;
      const double dx = std::sqrt(2.0 * n[0]);
      add_streaming(k, {n[0] - 1, n[1] + 1, n[2]}, dx * std::sqrt((n[1] + 1) / 2.0));
      if (n[1] > 0) add_streaming(k, {n[0] - 1, n[1] - 1, n[2]}, dx * std::sqrt(n[1] / 2.0));
    }
  }

  [[nodiscard]] std::size_t size() const { return k_; }
  [[nodiscard]] const std::vector<HermiteIndex>& basis() const { return basis_; }
  [[nodiscard]] std::size_t index(const HermiteIndex& n) const {
    for (std::size_t i = 0; i < k_; ++i)
      if (basis_[i] == n) return i;
    return k_;
  }

  /// Q_k = Σ_ij B(k; i, j) x_i x_j (bilinear) or B(k; 0, 0) + 2 Σ_{i>0} B(k; i, 0) x_i (linear).
  [[nodiscard]] double collision(std::size_t k, const Eigen::VectorXd& x, UniformShearCollisionTerms terms) const {
    double q = 0;
    if (terms == UniformShearCollisionTerms::linear) {
      q = moments_(k, 0, 0);
      for (std::size_t i = 1; i < k_; ++i) q += 2 * moments_(k, i, 0) * x[static_cast<Eigen::Index>(i)];
      return q;
    }
    for (std::size_t i = 0; i < k_; ++i)
      for (std::size_t j = 0; j < k_; ++j)
        q += moments_(k, i, j) * x[static_cast<Eigen::Index>(i)] * x[static_cast<Eigen::Index>(j)];
    return q;
  }

  /// ∂Q_k/∂x_i.
  [[nodiscard]] double collision_derivative(std::size_t k, std::size_t i, const Eigen::VectorXd& x,
                                            UniformShearCollisionTerms terms) const {
    if (terms == UniformShearCollisionTerms::linear) return 2 * moments_(k, i, 0);
    double q = 0;
    for (std::size_t j = 0; j < k_; ++j) q += 2 * moments_(k, i, j) * x[static_cast<Eigen::Index>(j)];
    return q;
  }

  [[nodiscard]] const Eigen::MatrixXd& streaming() const { return streaming_; }
  [[nodiscard]] int dimension() const { return d_; }

 private:
  void add_streaming(std::size_t k, const HermiteIndex& n, double value) {
    const std::size_t i = index(n);
    if (i < k_) streaming_(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(i)) += value;
  }

  int d_;
  std::vector<HermiteIndex> basis_;
  CartesianCollisionMoments moments_;
  std::size_t k_;
  Eigen::MatrixXd streaming_;
};

/// Returns ⟨Π_a c_a^{m_a}⟩ of f = w Σ x_i ψ_i.
double velocity_moment(const MomentEquations& eq, const Eigen::VectorXd& x, const HermiteIndex& m) {
  double s = 0;
  for (std::size_t i = 0; i < eq.size(); ++i) {
    const auto& n = eq.basis()[i];
    s += x[static_cast<Eigen::Index>(i)] * hermite_moment(m[0], n[0]) * hermite_moment(m[1], n[1]) *
         hermite_moment(m[2], n[2]);
  }
  return s;
}

/// Solves the Galerkin equations a*(S x)_k = Q_k/c_d (k ≥ 1) with Σ_a x_{2e_a} = 0 (⟨c²⟩ = d/2)
/// by Newton's method from (x, a*); returns the number of steps.
int solve(const MomentEquations& eq, UniformShearCollisionTerms terms, Eigen::VectorXd& x, double& shear) {
  const auto k = static_cast<Eigen::Index>(eq.size());
  const int d = eq.dimension();
  const double cd = collision_frequency_factor(d);
  std::vector<Eigen::Index> trace;
  for (int a = 0; a < d; ++a) {
    HermiteIndex n{0, 0, 0};
    n[static_cast<std::size_t>(a)] = 2;
    trace.push_back(static_cast<Eigen::Index>(eq.index(n)));
  }
  auto residual = [&](const Eigen::VectorXd& xv, double a, Eigen::MatrixXd* jac) {
    Eigen::VectorXd r(k);
    const Eigen::VectorXd sx = eq.streaming() * xv;
    for (Eigen::Index row = 1; row < k; ++row)
      r[row - 1] = a * sx[row] - eq.collision(static_cast<std::size_t>(row), xv, terms) / cd;
    r[k - 1] = 0;
    for (const auto t : trace) r[k - 1] += xv[t];
    if (jac) {
      jac->setZero(k, k);  // columns: x_1 … x_{K−1}, a*
      for (Eigen::Index row = 1; row < k; ++row) {
        for (Eigen::Index col = 1; col < k; ++col)
          (*jac)(row - 1, col - 1) =
              a * eq.streaming()(row, col) -
              eq.collision_derivative(static_cast<std::size_t>(row), static_cast<std::size_t>(col), xv, terms) / cd;
        (*jac)(row - 1, k - 1) = sx[row];
      }
      for (const auto t : trace) (*jac)(k - 1, t - 1) = 1;
    }
    return r;
  };
  Eigen::MatrixXd jac(k, k);
  for (int it = 1; it <= 60; ++it) {
    const Eigen::VectorXd r = residual(x, shear, &jac);
    const Eigen::VectorXd step = jac.partialPivLu().solve(r);
    double lambda = 1;  // backtracking on the residual norm
    for (int half = 0; half < 30; ++half, lambda /= 2) {
      Eigen::VectorXd xt = x;
      xt.tail(k - 1) -= lambda * step.head(k - 1);
      const double at = shear - lambda * step[k - 1];
      if (residual(xt, at, nullptr).norm() < r.norm() || half == 29) {
        x = xt;
        shear = at;
        break;
      }
    }
    if (lambda * step.cwiseAbs().maxCoeff() < 1e-14 * (1 + std::abs(shear))) return it;
  }
  throw std::runtime_error("uniform-shear: Newton's method did not converge for the moment equations of order " +
                           std::to_string((eq.basis().back()[0] + eq.basis().back()[1] + eq.basis().back()[2]) / 2));
}

UniformShearMoments summarise(const MomentEquations& eq, UniformShearCollisionTerms terms, const Eigen::VectorXd& x,
                              double shear, int order, int iterations) {
  const int d = eq.dimension();
  UniformShearMoments out;
  out.order = order;
  out.basis_size = static_cast<int>(eq.size());
  out.shear_rate = shear;
  out.reduced_shear_rate = shear * uniform_shear_length_factor(d);
  out.stress_xx = velocity_moment(eq, x, {2, 0, 0});
  out.stress_yy = velocity_moment(eq, x, {0, 2, 0});
  out.stress_zz = d == 3 ? velocity_moment(eq, x, {0, 0, 2}) : 0.0;
  out.stress_xy = velocity_moment(eq, x, {1, 1, 0});
  double c4 = 0, energy_source = 0;
  for (int a = 0; a < d; ++a)
    for (int b = 0; b < d; ++b) {
      HermiteIndex m{0, 0, 0};
      m[static_cast<std::size_t>(a)] += 2;
      m[static_cast<std::size_t>(b)] += 2;
      c4 += velocity_moment(eq, x, m);
    }
  for (int a = 0; a < d; ++a) {  // c_a² = h_2(c_a)/√2 + 1/2
    HermiteIndex n{0, 0, 0};
    n[static_cast<std::size_t>(a)] = 2;
    energy_source += eq.collision(eq.index(n), x, terms) / std::numbers::sqrt2;
  }
  out.kurtosis = c4 / (d * (d + 2) / 4.0) - 1;
  // m∫V²J = 2T n² σ^{d−1} v0 Σ_a Q_a/√2 = −d p ζ  ⇒  ζ/ν0 = −2 Σ_a Q_a/√2 / (d c_d)
  out.cooling_rate = -2 * energy_source / (d * collision_frequency_factor(d));
  out.energy_balance = 2 * shear * 2 * out.stress_xy + d * out.cooling_rate;
  out.newton_iterations = iterations;
  return out;
}

}  // namespace

int uniform_shear_max_moment_order(int dimension) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  return dimension == 2 ? 6 : 3;
}

std::vector<UniformShearMoments> uniform_shear_flow_moments(int dimension, double alpha, int max_order,
                                                            UniformShearCollisionTerms terms) {
  const int cap = uniform_shear_max_moment_order(dimension);
  if (!(alpha > 0 && alpha < 1))
    throw std::invalid_argument("alpha: must be a number in (0, 1), got " + std::to_string(alpha));
  if (max_order < 1 || max_order > cap)
    throw std::invalid_argument("order: must be an integer in [1, " + std::to_string(cap) + "] in dimension " +
                                std::to_string(dimension) + ", got " + std::to_string(max_order));
  const UniformShearFlow grad = uniform_shear_flow_grad(dimension, alpha);
  std::vector<UniformShearMoments> out;
  Eigen::VectorXd previous;
  double shear = grad.shear_rate;
  for (int order = 1; order <= max_order; ++order) {
    const MomentEquations eq(dimension, alpha, order);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(eq.size()));
    if (order == 1) {  // Grad's (22.7): ⟨c_a²⟩ = 1/2 + x_{2e_a}/√2, ⟨c_x c_y⟩ = x_{110}/2
      x[0] = 1;
      x[static_cast<Eigen::Index>(eq.index({2, 0, 0}))] = std::numbers::sqrt2 * (grad.stress_xx - 0.5);
      x[static_cast<Eigen::Index>(eq.index({0, 2, 0}))] = std::numbers::sqrt2 * (grad.stress_yy - 0.5);
      if (dimension == 3)
        x[static_cast<Eigen::Index>(eq.index({0, 0, 2}))] = std::numbers::sqrt2 * (grad.stress_zz - 0.5);
      x[static_cast<Eigen::Index>(eq.index({1, 1, 0}))] = 2 * grad.stress_xy;
    } else {
      x.head(previous.size()) = previous;  // the basis of order N − 1 is a prefix of order N's
    }
    const int iterations = solve(eq, terms, x, shear);
    out.push_back(summarise(eq, terms, x, shear, order, iterations));
    previous = x;
  }
  return out;
}

}  // namespace gkt
