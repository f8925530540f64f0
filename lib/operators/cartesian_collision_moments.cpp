// Bilinear collision moments of Cartesian Hermite polynomials by an exact product quadrature
// (cartesian_collision_moments.hpp; docs/theory.md §22.7).
#include "gkt/operators/cartesian_collision_moments.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace gkt {

namespace {

struct GaussRule {
  std::vector<double> nodes, weights;
};

/// Gauss rule of the orthogonal polynomials with recurrence diagonal `a`, off-diagonal `b` (b[0]
/// unused) and total weight mu0 (Golub–Welsch).
GaussRule golub_welsch(const std::vector<double>& a, const std::vector<double>& b, double mu0) {
  const auto n = static_cast<Eigen::Index>(a.size());
  Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    jacobi(i, i) = a[static_cast<std::size_t>(i)];
    if (i > 0) jacobi(i, i - 1) = jacobi(i - 1, i) = b[static_cast<std::size_t>(i)];
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(jacobi);
  GaussRule rule;
  for (Eigen::Index i = 0; i < n; ++i) {
    rule.nodes.push_back(eig.eigenvalues()(i));
    rule.weights.push_back(mu0 * eig.eigenvectors()(0, i) * eig.eigenvectors()(0, i));
  }
  return rule;
}

/// n-point Gauss–Hermite rule, weight e^{−u²} on ℝ; the nodes are symmetrised exactly.
GaussRule gauss_hermite(int n) {
  std::vector<double> a(static_cast<std::size_t>(n), 0.0), b(static_cast<std::size_t>(n), 0.0);
  for (int k = 1; k < n; ++k) b[static_cast<std::size_t>(k)] = std::sqrt(k / 2.0);
  GaussRule r = golub_welsch(a, b, std::sqrt(std::numbers::pi));
  for (int i = 0; i < n / 2; ++i) {  // exact symmetry: odd integrands cancel to rounding
    const auto lo = static_cast<std::size_t>(i), hi = static_cast<std::size_t>(n - 1 - i);
    const double x = 0.5 * (r.nodes[hi] - r.nodes[lo]), w = 0.5 * (r.weights[hi] + r.weights[lo]);
    r.nodes[lo] = -x, r.nodes[hi] = x, r.weights[lo] = r.weights[hi] = w;
  }
  if (n % 2 == 1) r.nodes[static_cast<std::size_t>(n / 2)] = 0.0;
  return r;
}

/// n-point Gauss–Legendre rule on [−1, 1], symmetrised exactly.
GaussRule gauss_legendre(int n) {
  std::vector<double> a(static_cast<std::size_t>(n), 0.0), b(static_cast<std::size_t>(n), 0.0);
  for (int k = 1; k < n; ++k) b[static_cast<std::size_t>(k)] = k / std::sqrt(4.0 * k * k - 1);
  GaussRule r = golub_welsch(a, b, 2.0);
  for (int i = 0; i < n / 2; ++i) {
    const auto lo = static_cast<std::size_t>(i), hi = static_cast<std::size_t>(n - 1 - i);
    const double x = 0.5 * (r.nodes[hi] - r.nodes[lo]), w = 0.5 * (r.weights[hi] + r.weights[lo]);
    r.nodes[lo] = -x, r.nodes[hi] = x, r.weights[lo] = r.weights[hi] = w;
  }
  if (n % 2 == 1) r.nodes[static_cast<std::size_t>(n / 2)] = 0.0;
  return r;
}

/// n-point generalised Gauss–Laguerre rule, weight s^λ e^{−s} on [0, ∞).
GaussRule gauss_laguerre(int n, double lambda) {
  std::vector<double> a(static_cast<std::size_t>(n)), b(static_cast<std::size_t>(n), 0.0);
  for (int k = 0; k < n; ++k) {
    a[static_cast<std::size_t>(k)] = 2.0 * k + 1 + lambda;
    if (k > 0) b[static_cast<std::size_t>(k)] = std::sqrt(k * (k + lambda));
  }
  return golub_welsch(a, b, std::tgamma(lambda + 1));
}

/// A direction σ̂ about ĝ: σ̂ = u ĝ + v e1 + w e2 (e1, e2 ⊥ ĝ) and its quadrature weight.
struct SphereNode {
  double u, v, w, weight;
};

/// Nodes with Σ weight·P(σ̂) = ∫dσ̂ Θ(σ̂·ĝ) P(σ̂) for every polynomial P of degree ≤ 2p + 1 in the
/// components of σ̂ (2D: P = P_odd + P_even in cos θ, Gauss–Legendre in sin θ for P_odd/cos θ and
/// Gauss–Chebyshev for P_even; 3D: Gauss–Legendre in u = cos θ ∈ [0, 1] × trapezoid in φ).
std::vector<SphereNode> hemisphere_rule(int dimension, int p) {
  std::vector<SphereNode> nodes;
  const int n = p + 1;  // exact to degree 2n − 1 = 2p + 1
  if (dimension == 2) {
    const GaussRule gl = gauss_legendre(n);
    for (int i = 0; i < n; ++i) {
      const double s = gl.nodes[static_cast<std::size_t>(i)], c = std::sqrt(1 - s * s);
      const double w = 0.5 * gl.weights[static_cast<std::size_t>(i)] / c;  // (P(c) − P(−c))/2 / cos θ
      nodes.push_back({c, s, 0, w});
      nodes.push_back({-c, s, 0, -w});
    }
    for (int j = 1; j <= n; ++j) {
      const double s = std::cos((2.0 * j - 1) * std::numbers::pi / (2.0 * n)), c = std::sqrt(1 - s * s);
      const double w = 0.5 * std::numbers::pi / n;  // (P(c) + P(−c))/2, weight 1/√(1 − s²)
      nodes.push_back({c, s, 0, w});
      nodes.push_back({-c, s, 0, w});
    }
    return nodes;
  }
  const GaussRule gl = gauss_legendre(n);
  const int m = 2 * p + 2;  // trapezoid in φ: exact to trigonometric degree m − 1
  for (int i = 0; i < n; ++i) {
    const double u = 0.5 * (gl.nodes[static_cast<std::size_t>(i)] + 1), s = std::sqrt(1 - u * u);
    for (int j = 0; j < m; ++j) {
      const double phi = 2 * std::numbers::pi * (j + 0.5) / m;
      nodes.push_back({u, s * std::cos(phi), s * std::sin(phi),
                       0.5 * gl.weights[static_cast<std::size_t>(i)] * 2 * std::numbers::pi / m});
    }
  }
  return nodes;
}

/// A direction ĝ with its frame e1, e2 and its weight on the unit sphere (circle in 2D).
struct Direction {
  std::array<double, 3> g, e1, e2;
  double weight;
};

/// A rule exact for polynomials of degree ≤ q on the sphere, centrally symmetric.
std::vector<Direction> sphere_rule(int dimension, int q) {
  std::vector<Direction> out;
  const int m = q + 2 + (q % 2);  // even count, trigonometric degree ≤ m − 1
  if (dimension == 2) {
    for (int j = 0; j < m; ++j) {
      const double phi = 2 * std::numbers::pi * j / m, c = std::cos(phi), s = std::sin(phi);
      out.push_back({{c, s, 0}, {-s, c, 0}, {0, 0, 0}, 2 * std::numbers::pi / m});
    }
    return out;
  }
  const GaussRule gl = gauss_legendre(q / 2 + 1);
  for (std::size_t i = 0; i < gl.nodes.size(); ++i) {
    const double ct = gl.nodes[i], st = std::sqrt(1 - ct * ct);
    for (int j = 0; j < m; ++j) {
      const double phi = 2 * std::numbers::pi * (j + 0.5) / m, c = std::cos(phi), s = std::sin(phi);
      out.push_back(
          {{st * c, st * s, ct}, {ct * c, ct * s, -st}, {-s, c, 0}, gl.weights[i] * 2 * std::numbers::pi / m});
    }
  }
  return out;
}

/// Evaluates every basis polynomial at c into out (scratch: d × (p + 1) Hermite values).
void basis_values(const std::vector<HermiteIndex>& basis, int dimension, int p, const std::array<double, 3>& c,
                  double* hermite, double* out) {
  const auto stride = static_cast<std::size_t>(p + 1);
  for (int a = 0; a < dimension; ++a)
    orthonormal_hermite_values(c[static_cast<std::size_t>(a)], p, hermite + a * stride);
  for (std::size_t k = 0; k < basis.size(); ++k) {
    double v = hermite[basis[k][0]] * hermite[stride + static_cast<std::size_t>(basis[k][1])];
    if (dimension == 3) v *= hermite[2 * stride + static_cast<std::size_t>(basis[k][2])];
    out[k] = v;
  }
}

}  // namespace

void orthonormal_hermite_values(double x, int n, double* out) {
  out[0] = 1;
  if (n >= 1) out[1] = std::numbers::sqrt2 * x;
  for (int k = 1; k < n; ++k)  // h_{k+1} = √(2/(k+1)) x h_k − √(k/(k+1)) h_{k−1}
    out[k + 1] = std::sqrt(2.0 / (k + 1)) * x * out[k] - std::sqrt(static_cast<double>(k) / (k + 1)) * out[k - 1];
}

std::vector<HermiteIndex> shear_symmetric_hermite_basis(int dimension, int max_degree) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  if (max_degree < 0 || max_degree % 2 != 0)
    throw std::invalid_argument("max_degree: must be an even integer >= 0, got " + std::to_string(max_degree));
  std::vector<HermiteIndex> out;
  for (int deg = 0; deg <= max_degree; deg += 2)
    for (int nx = deg; nx >= 0; --nx)
      for (int nz = 0; nz <= (dimension == 3 ? deg - nx : 0); nz += 2) {
        const int ny = deg - nx - nz;
        if (ny >= 0) out.push_back({nx, ny, nz});
      }
  return out;
}

CartesianCollisionMoments cartesian_collision_moments(int dimension, double alpha,
                                                      const std::vector<HermiteIndex>& basis) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  if (!(alpha > 0 && alpha <= 1))
    throw std::invalid_argument("alpha: must be a number in (0, 1], got " + std::to_string(alpha));
  int p = 0;
  for (const auto& n : basis) {
    if (n[0] < 0 || n[1] < 0 || n[2] < 0 || (dimension == 2 && n[2] != 0))
      throw std::invalid_argument("basis: Hermite degrees must be >= 0 (n_z = 0 in dimension 2)");
    p = std::max(p, n[0] + n[1] + n[2]);
  }
  p += p % 2;
  const auto kk = static_cast<Eigen::Index>(basis.size());
  const auto ks = basis.size();
  // The integrand is a polynomial of degree ≤ 3p in (G, g) times the Gaussian weight (theory.md §22.7).
  const GaussRule hermite = gauss_hermite(3 * p / 2 + 1);
  const double lambda = 0.5 * (dimension - 1);
  const GaussRule laguerre = gauss_laguerre(3 * p / 4 + 2, lambda);
  const std::vector<Direction> directions = sphere_rule(dimension, 3 * p);
  const std::vector<SphereNode> hemisphere = hemisphere_rule(dimension, p);
  const double beta = 0.5 * (1 + alpha);
  double half_flux = 0;  // ∫dσ̂ Θ(σ̂·ĝ)(σ̂·ĝ)
  for (const auto& s : hemisphere) half_flux += s.weight * s.u;

  // Centre-of-mass nodes G = u/√2 (e^{−2G²} dG = 2^{−d/2} e^{−u²} du).
  std::vector<std::array<double, 3>> centre;
  std::vector<double> centre_weight;
  const std::size_t nh = hermite.nodes.size();
  for (std::size_t i = 0; i < nh; ++i)
    for (std::size_t j = 0; j < nh; ++j)
      for (std::size_t l = 0; l < (dimension == 3 ? nh : 1); ++l) {
        centre.push_back({hermite.nodes[i] / std::numbers::sqrt2, hermite.nodes[j] / std::numbers::sqrt2,
                          dimension == 3 ? hermite.nodes[l] / std::numbers::sqrt2 : 0.0});
        centre_weight.push_back(hermite.weights[i] * hermite.weights[j] * (dimension == 3 ? hermite.weights[l] : 1.0));
      }
  const auto ng = static_cast<Eigen::Index>(centre.size());
  const double prefactor =
      std::pow(std::numbers::pi, -dimension) * std::pow(2.0, -0.5 * dimension) * std::pow(2.0, lambda);

  std::vector<double> scratch(3 * static_cast<std::size_t>(p + 1)), a(ks), b(ks), d(ks), prime(ks);
  Eigen::MatrixXd left(ng, kk * kk), right(ng, kk), tensor = Eigen::MatrixXd::Zero(kk * kk, kk);
  for (std::size_t ir = 0; ir < laguerre.nodes.size(); ++ir) {
    const double r = std::sqrt(2 * laguerre.nodes[ir]);
    for (const auto& dir : directions) {
      const double w_g = prefactor * laguerre.weights[ir] * dir.weight;
      for (Eigen::Index m = 0; m < ng; ++m) {
        const auto& gc = centre[static_cast<std::size_t>(m)];
        std::array<double, 3> c1{}, c2{};
        for (std::size_t x = 0; x < 3; ++x) {
          c1[x] = gc[x] + 0.5 * r * dir.g[x];
          c2[x] = gc[x] - 0.5 * r * dir.g[x];
        }
        basis_values(basis, dimension, p, c1, scratch.data(), a.data());
        basis_values(basis, dimension, p, c2, scratch.data(), b.data());
        for (std::size_t k = 0; k < ks; ++k) d[k] = -half_flux * a[k];
        for (const auto& s : hemisphere) {
          std::array<double, 3> c1p{};
          const double shift = beta * r * s.u;  // c1' = c1 − β (σ̂·g) σ̂
          for (std::size_t x = 0; x < 3; ++x)
            c1p[x] = c1[x] - shift * (s.u * dir.g[x] + s.v * dir.e1[x] + s.w * dir.e2[x]);
          basis_values(basis, dimension, p, c1p, scratch.data(), prime.data());
          const double w = s.weight * s.u;
          for (std::size_t k = 0; k < ks; ++k) d[k] += w * prime[k];
        }
        const double w = w_g * centre_weight[static_cast<std::size_t>(m)];
        for (std::size_t k = 0; k < ks; ++k)
          for (std::size_t i = 0; i < ks; ++i) left(m, static_cast<Eigen::Index>(k * ks + i)) = w * d[k] * a[i];
        for (std::size_t j = 0; j < ks; ++j) right(m, static_cast<Eigen::Index>(j)) = b[j];
      }
      tensor.noalias() += left.transpose() * right;
    }
  }
  CartesianCollisionMoments out;
  out.dimension = dimension;
  out.alpha = alpha;
  out.basis = basis;
  out.values.resize(ks * ks * ks);
  for (std::size_t k = 0; k < ks; ++k)
    for (std::size_t i = 0; i < ks; ++i)
      for (std::size_t j = 0; j < ks; ++j)
        out.values[(k * ks + i) * ks + j] =
            0.5 * (tensor(static_cast<Eigen::Index>(k * ks + i), static_cast<Eigen::Index>(j)) +
                   tensor(static_cast<Eigen::Index>(k * ks + j), static_cast<Eigen::Index>(i)));
  return out;
}

}  // namespace gkt
