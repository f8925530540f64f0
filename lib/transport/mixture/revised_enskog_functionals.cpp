#include "gkt/transport/mixture/revised_enskog_functionals.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace gkt {

namespace {

/// The closures (16.1) as χ_ij = F(φ, a_ij y) = Σ_k c_k u^k (1 − φ)^{−(k+1)}, u = a_ij y, with their
/// first and second derivatives: 3D [boublik1970], [mansoori1971] c = (1, 3/2, 1/2); 2D [jenkins1987]
/// c = (1, 9/16) (the same numbers as Mixture::contact_values, which the tests compare).
struct ContactFunction {
  double f = 0, f_phi = 0, f_u = 0, f_phiphi = 0, f_phiu = 0, f_uu = 0;
};

ContactFunction contact_function(int dimension, double phi, double u) {
  const std::array<double, 3> c =
      dimension == 3 ? std::array<double, 3>{1, 1.5, 0.5} : std::array<double, 3>{1, 0.5625, 0};
  const double g = 1 - phi;
  ContactFunction out;
  for (int k = 0; k < 3; ++k) {
    const double ck = c[static_cast<std::size_t>(k)] * std::pow(g, -(k + 1));
    out.f += ck * std::pow(u, k);
    out.f_phi += ck * (k + 1) * std::pow(u, k) / g;
    out.f_phiphi += ck * (k + 1) * (k + 2) * std::pow(u, k) / (g * g);
    if (k >= 1) {
      out.f_u += ck * k * std::pow(u, k - 1);
      out.f_phiu += ck * k * (k + 1) * std::pow(u, k - 1) / g;
    }
    if (k >= 2) out.f_uu += ck * k * (k - 1) * std::pow(u, k - 2);
  }
  return out;
}

/// Gauss–Legendre rule on [0, 1] (Golub–Welsch): the λ integrands of (18.17) are rational in λ with
/// their poles at λ ≥ 1/φ > 1.4, so 24 nodes integrate them to rounding.
struct LambdaRule {
  std::array<double, 24> node{}, weight{};
};

const LambdaRule& lambda_rule() {
  static const LambdaRule rule = [] {
    constexpr int n = 24;
    Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(n, n);
    for (int k = 1; k < n; ++k) jacobi(k, k - 1) = jacobi(k - 1, k) = k / std::sqrt(4.0 * k * k - 1);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(jacobi);
    LambdaRule r;
    for (int q = 0; q < n; ++q) {
      r.node[static_cast<std::size_t>(q)] = 0.5 * (1 + solver.eigenvalues()(q));
      r.weight[static_cast<std::size_t>(q)] = solver.eigenvectors()(0, q) * solver.eigenvectors()(0, q);
    }
    return r;
  }();
  return rule;
}

/// The mixture in the units σ̄ = 1 with absolute partial densities n_k = n x_k, n = φ/(v_d Σ x σ^d):
/// φ = v_d Σ n_k σ_k^d and y = v_d Σ n_k σ_k^{d−1} (3D y = φM2/M3, 2D y = φM1/M2 of (18.1)).
struct Geometry {
  int d = 3;
  std::size_t s = 0;
  std::vector<double> sigma, density;
  std::vector<double> volume_power, surface_power;  // σ_k^d and σ_k^{d−1}, computed once (the λ loop reads them)
  double v_d = 0, b2 = 0, phi = 0, y = 0;

  explicit Geometry(const Mixture& m) : d(m.dimension), s(m.size()) {
    m.validate();
    v_d = std::pow(std::numbers::pi, d / 2.0) / (std::pow(2.0, d) * std::tgamma(d / 2.0 + 1));
    b2 = std::pow(std::numbers::pi, d / 2.0) / (2 * std::tgamma(d / 2.0 + 1));  // B_2 of (18.2)
    double volume = 0;
    for (const Species& sp : m.species) {
      sigma.push_back(sp.diameter / m.mean_diameter());
      volume += sp.fraction * std::pow(sigma.back(), d);
    }
    const double n = m.packing_fraction / (v_d * volume);
    for (std::size_t k = 0; k < s; ++k) {
      density.push_back(n * m.species[k].fraction);
      volume_power.push_back(std::pow(sigma[k], d));
      surface_power.push_back(std::pow(sigma[k], d - 1));
      phi += v_d * density[k] * volume_power[k];
      y += v_d * density[k] * surface_power[k];
    }
  }
  [[nodiscard]] double pair_diameter(std::size_t i, std::size_t j) const { return 0.5 * (sigma[i] + sigma[j]); }
  [[nodiscard]] double pair_width(std::size_t i, std::size_t j) const {  // a_ij = σ_iσ_j/σ_ij
    return sigma[i] * sigma[j] / pair_diameter(i, j);
  }
  /// χ_jk and ∂χ_jk/∂n_l at the densities λ n_k.
  [[nodiscard]] double contact_derivative(const ContactFunction& f, std::size_t j, std::size_t k, std::size_t l) const {
    return v_d * (f.f_phi * volume_power[l] + f.f_u * pair_width(j, k) * surface_power[l]);
  }
};

/// Returns ∂(μ_i^ex/T)/∂n_l at i·s + l: ∫_0^1 dλ ∂_i∂_l (p^ex/T)(λn) with p^ex/T = B_2 Σ_jk n_j n_k σ_jk^d χ_jk
/// (18.17).
std::vector<double> excess_hessian(const Geometry& g) {
  const std::size_t s = g.s;
  const int d = g.d;
  std::vector<double> out(s * s, 0.0);
  const LambdaRule& rule = lambda_rule();
  for (std::size_t q = 0; q < rule.node.size(); ++q) {
    const double lambda = rule.node[q], w = rule.weight[q] * g.b2;
    for (std::size_t j = 0; j < s; ++j)
      for (std::size_t k = 0; k < s; ++k) {
        const double a = g.pair_width(j, k), wjk = std::pow(g.pair_diameter(j, k), d);
        const ContactFunction f = contact_function(d, lambda * g.phi, a * lambda * g.y);
        const double nj = lambda * g.density[j], nk = lambda * g.density[k];
        for (std::size_t i = 0; i < s; ++i)
          for (std::size_t l = 0; l < s; ++l) {
            const double si = g.volume_power[i], si1 = g.surface_power[i];
            const double sl = g.volume_power[l], sl1 = g.surface_power[l];
            const double d2chi =
                g.v_d * g.v_d *
                (f.f_phiphi * si * sl + f.f_phiu * a * (si * sl1 + sl * si1) + f.f_uu * a * a * si1 * sl1);
            const double h = ((j == i && k == l ? 1.0 : 0.0) + (j == l && k == i ? 1.0 : 0.0)) * f.f +
                             ((j == i ? nk : 0.0) + (k == i ? nj : 0.0)) * g.contact_derivative(f, j, k, l) +
                             ((j == l ? nk : 0.0) + (k == l ? nj : 0.0)) * g.contact_derivative(f, j, k, i) +
                             nj * nk * d2chi;
            out[i * s + l] += w * wjk * h;
          }
      }
  }
  return out;
}

/// Returns b_ℓi = ∂_ℓ(μ_i^ex/T)/(2B_2) − Σ_k σ_ik^d [χ_ik δ_kℓ + ½ n_k ∂_ℓ χ_ik], the part of (18.19) over
/// 2B_2 n_i that the off-midpoint contact values must carry: b_ℓi = Σ_j n_j σ_ij^d K_ℓij (theory.md (18.19)).
double thermodynamic_remainder(const Geometry& g, const std::vector<double>& hessian, std::size_t i, std::size_t l) {
  double rest = hessian[i * g.s + l] / (2 * g.b2);
  for (std::size_t k = 0; k < g.s; ++k) {
    const ContactFunction f = contact_function(g.d, g.phi, g.pair_width(i, k) * g.y);
    rest -= std::pow(g.pair_diameter(i, k), g.d) *
            ((k == l ? f.f : 0.0) + 0.5 * g.density[k] * g.contact_derivative(f, i, k, l));
  }
  return rest;
}

/// Returns (c − R)·σ̂ (units of σ̄): the offset from the pair's midpoint R, along σ̂ from i to j, of the
/// centroid c of the lens where a sphere ℓ overlaps both i and j (the balls of radii σ_iℓ about r_i and
/// σ_jℓ about r_j = r_i + σ_ij σ̂; they always intersect properly, |σ_iℓ − σ_jℓ| < σ_ij < σ_iℓ + σ_jℓ).
/// The lens is two caps (3D) or circular segments (2D) cut by the plane x0 where the spheres meet.
double lens_centroid_offset(int d, double sigma_i, double sigma_j, double sigma_l) {
  const double distance = 0.5 * (sigma_i + sigma_j), ra = 0.5 * (sigma_i + sigma_l), rb = 0.5 * (sigma_j + sigma_l);
  const double x0 = (distance * distance + ra * ra - rb * rb) / (2 * distance);
  // The cap of the ball of radius r beyond a plane at distance a from its centre: its size (volume or
  // area) and its centroid's distance from the centre.
  auto cap = [d](double r, double a) -> std::pair<double, double> {
    if (d == 3) {
      const double h = r - a;
      return {std::numbers::pi * h * h * (3 * r - h) / 3, 3 * (2 * r - h) * (2 * r - h) / (4 * (3 * r - h))};
    }
    const double half_chord = std::sqrt(r * r - a * a);
    const double area = r * r * std::acos(a / r) - a * half_chord;
    return {area, 2 * half_chord * half_chord * half_chord / (3 * area)};
  };
  const auto [va, ca] = cap(ra, x0);             // ball i's cap, on the side of j: centroid at +ca
  const auto [vb, cb] = cap(rb, distance - x0);  // ball j's cap, on the side of i: centroid at distance − cb
  return (va * ca + vb * (distance - cb)) / (va + vb) - 0.5 * distance;
}

/// Returns I_ℓij at (i·s + j)·s + ℓ for s ≥ 3 with the closure of theory.md §18.12: K_ℓij = K^ref_ℓij +
/// u_ℓi − u_ℓj, the reference of `closure` plus the gradient that makes (18.19) hold, Σ_j n_j σ_ij^d K_ℓij =
/// b_ℓi for every i. The rows are those of (18.19) over n_i (regular at tracers); by Gibbs–Duhem they sum
/// to zero with weights n_i, so the row of the most abundant species k* is dropped and u_ℓk* = 0 fixes the
/// gauge. The remaining matrix is strictly diagonally dominant by rows (margin n_k* σ_ik*^d).
std::vector<double> closed_functionals(const Geometry& g, const std::vector<double>& hessian,
                                       FunctionalClosure closure) {
  const std::size_t s = g.s;
  const int d = g.d;
  const auto major = static_cast<std::size_t>(std::max_element(g.density.begin(), g.density.end()) - g.density.begin());
  auto unknown = [major](std::size_t k) { return static_cast<Eigen::Index>(k < major ? k : k - 1); };
  std::vector<double> chi(s * s), out(s * s * s, 0.0);
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j) chi[i * s + j] = contact_function(d, g.phi, g.pair_width(i, j) * g.y).f;
  const auto m = static_cast<Eigen::Index>(s - 1);
  for (std::size_t l = 0; l < s; ++l) {
    // The reference K^ref_ℓij = δ_ijℓ ∂_ℓχ_ij/σ_ij: χ_ij at the densities of the point R + δ σ̂ (18.18).
    Eigen::MatrixXd reference = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(s), static_cast<Eigen::Index>(s));
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) {
        if (i == j || closure == FunctionalClosure::gradient) continue;
        const double offset = closure == FunctionalClosure::lens_centroid
                                  ? lens_centroid_offset(d, g.sigma[i], g.sigma[j], g.sigma[l])
                                  : 0.25 * (g.sigma[i] - g.sigma[j]);
        const ContactFunction f = contact_function(d, g.phi, g.pair_width(i, j) * g.y);
        reference(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
            offset * g.contact_derivative(f, i, j, l) / g.pair_diameter(i, j);
      }
    Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(m, m);
    Eigen::VectorXd rhs(m);
    for (std::size_t i = 0; i < s; ++i) {
      if (i == major) continue;
      const Eigen::Index row = unknown(i);
      rhs(row) = thermodynamic_remainder(g, hessian, i, l);
      for (std::size_t j = 0; j < s; ++j) {
        if (j == i) continue;
        const double w = g.density[j] * std::pow(g.pair_diameter(i, j), d);
        rhs(row) -= w * reference(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
        matrix(row, row) += w;
        if (j != major) matrix(row, unknown(j)) -= w;
      }
    }
    const Eigen::VectorXd solved = matrix.partialPivLu().solve(rhs);
    auto u = [&](std::size_t k) { return k == major ? 0.0 : solved(unknown(k)); };
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) {
        if (i == j) continue;
        const double k = reference(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) + u(i) - u(j);
        out[(i * s + j) * s + l] = 2 * g.density[j] * k / chi[i * s + j];
      }
  }
  return out;
}

}  // namespace

std::vector<double> chemical_potential_derivatives(const Mixture& mixture) {
  const Geometry g(mixture);
  std::vector<double> out = excess_hessian(g);
  for (std::size_t i = 0; i < g.s; ++i)
    for (std::size_t l = 0; l < g.s; ++l) out[i * g.s + l] = (i == l ? 1.0 : 0.0) + g.density[i] * out[i * g.s + l];
  return out;
}

std::vector<double> revised_enskog_functionals(const Mixture& mixture, FunctionalClosure closure) {
  const Geometry g(mixture);
  const std::size_t s = g.s;
  std::vector<double> out(s * s * s, 0.0);
  bool equal = true;
  for (std::size_t k = 1; k < s; ++k) equal = equal && g.sigma[k] == g.sigma[0];
  if (g.phi == 0 || equal) return out;  // (18.20): the midpoint expansion is then exact
  const std::vector<double> hessian = excess_hessian(g);
  if (s > 2) return closed_functionals(g, hessian, closure);
  const int d = g.d;
  // (18.20), from the consistency (18.19) of the revised theory [vanbeijeren1973], [lopezdeharo1983]:
  // ½ σ_ij^d χ_ij I_ℓij = ∂_ℓ(μ_i^ex/T)/(2B_2) − Σ_k σ_ik^d [χ_ik δ_kℓ + ½ n_k ∂_ℓ χ_ik], j ≠ i.
  for (std::size_t i = 0; i < s; ++i) {
    const std::size_t j = 1 - i;
    for (std::size_t l = 0; l < s; ++l) {
      const double chi = contact_function(d, g.phi, g.pair_width(i, j) * g.y).f;
      out[(i * s + j) * s + l] =
          2 * thermodynamic_remainder(g, hessian, i, l) / (std::pow(g.pair_diameter(i, j), d) * chi);
    }
  }
  return out;
}

}  // namespace gkt
