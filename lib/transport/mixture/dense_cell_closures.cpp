// Fixed-size contact values, their derivatives and the revised-Enskog functionals of one dense state
// (docs/theory.md §18.1, §18.12). The formulas are those of mixture.cpp and revised_enskog_functionals.cpp,
// rearranged so that each node of the λ integral (18.17) costs O(s²) instead of O(s⁴).
#include "transport/mixture/dense_cell_closures.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>

namespace gkt::detail {

namespace {

constexpr int kMax = 4;

/// The gap factors g^q = (1 − φ)^{−q}, q = 1…5, at one packing fraction ([0] unused), or their λ moments
/// M_q = Σ_nodes w λ^{q−1} (1 − λφ)^{−q} (λ_moments): contact() is linear in them.
using GapPowers = std::array<double, 6>;
GapPowers gap_powers(double inverse_gap) {
  GapPowers g{};
  g[1] = inverse_gap;
  for (std::size_t q = 2; q < g.size(); ++q) g[q] = g[q - 1] * inverse_gap;
  return g;
}

/// χ = F(φ, u) = Σ_k c_k u^k (1 − φ)^{−(k+1)} with its derivatives (16.1): 3D [boublik1970],
/// [mansoori1971] c = (1, 3/2, 1/2); 2D [jenkins1987] c = (1, 9/16). Given g^q = (1 − φ)^{−q}.
/// Every term u^p g^q of F has q = p + 1, of F_φ and F_u q = p + 2, of the second derivatives q = p + 3:
/// so with u = a λ y and g^q replaced by the moments M_q the same formulas give ∫dλ F, ∫dλ λ F_φ,
/// ∫dλ λ F_u and ∫dλ λ² F_φφ, λ² F_φu, λ² F_uu at u = a y (the integrals of (18.17)).
struct Contact {
  double f, f_phi, f_u, f_phiphi, f_phiu, f_uu;
};
template <int D>
[[gnu::always_inline]] inline Contact contact(const GapPowers& g, double u) {
  if constexpr (D == 3)
    return {g[1] + 1.5 * u * g[2] + 0.5 * u * u * g[3],
            g[2] + 3 * u * g[3] + 1.5 * u * u * g[4],
            1.5 * g[2] + u * g[3],
            2 * g[3] + 9 * u * g[4] + 6 * u * u * g[5],
            3 * g[3] + 3 * u * g[4],
            g[3]};
  else
    return {
        g[1] + 0.5625 * u * g[2], g[2] + 1.125 * u * g[3], 0.5625 * g[2], 2 * g[3] + 3.375 * u * g[4], 1.125 * g[3], 0};
}

/// Gauss–Legendre nodes and weights on [0, 1] (Golub–Welsch), for 6, 8, 12, 16 and 24 points.
struct Rule {
  int size = 0;
  std::array<double, 24> node{}, weight{};
};
Rule make_rule(int n) {
  Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(n, n);
  for (int k = 1; k < n; ++k) jacobi(k, k - 1) = jacobi(k - 1, k) = k / std::sqrt(4.0 * k * k - 1);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(jacobi);
  Rule out;
  out.size = n;
  for (int q = 0; q < n; ++q) {
    out.node[static_cast<std::size_t>(q)] = 0.5 * (1 + solver.eigenvalues()(q));
    out.weight[static_cast<std::size_t>(q)] = solver.eigenvectors()(0, q) * solver.eigenvectors()(0, q);
  }
  return out;
}
/// The rule for the λ integrals of (18.17) at packing fraction φ: their integrands are rational in λ with
/// poles (of order ≤ 5) at λ = 1/φ, x = 2/φ − 1 on the interval's [−1, 1], so an n-point rule errs by about
/// ρ^{−2n}, ρ = x + √(x² − 1); n ≥ 22.5/ln ρ puts that below 10^{−19} (with room for the pole order), capped
/// at the 24 points of revised_enskog_functionals.cpp. As a bound on φ: n points suffice for
/// φ ≤ 2/(1 + cosh(22.5/n)) (x = cosh ln ρ), computed once.
const Rule& rule(double phi) {
  static const std::array<Rule, 5> rules{make_rule(6), make_rule(8), make_rule(12), make_rule(16), make_rule(24)};
  static const std::array<double, 5> limit = [] {
    std::array<double, 5> out{};
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = 2 / (1 + std::cosh(22.5 / rules[k].size));
    return out;
  }();
  for (std::size_t k = 0; k + 1 < rules.size(); ++k)
    if (phi <= limit[k]) return rules[k];
  return rules.back();
}

/// M_q = B_2 Σ_nodes w λ^{q−1} (1 − λφ)^{−q}, q = 1…5, on the rule for φ: every λ integral of (18.17)
/// is a combination of these five (see Contact), so the nodes are visited once for all pairs.
GapPowers lambda_moments(double phi, double b2) {
  const Rule& r = rule(phi);
  GapPowers m{};
  for (std::size_t q = 0; q < static_cast<std::size_t>(r.size); ++q) {
    const double g = 1 / (1 - r.node[q] * phi), h = r.node[q] * g;  // λ^{q−1} g^q = g h^{q−1}
    const double w1 = b2 * r.weight[q] * g, w2 = w1 * h, w3 = w2 * h, w4 = w3 * h;
    m[1] += w1;
    m[2] += w2;
    m[3] += w3;
    m[4] += w4;
    m[5] += w4 * h;
  }
  return m;
}

/// (c − R)·σ̂ of revised_enskog_functionals.cpp: the lens centroid's offset from the pair's midpoint.
double lens_centroid_offset(int d, double sigma_i, double sigma_j, double sigma_l) {
  const double distance = 0.5 * (sigma_i + sigma_j), ra = 0.5 * (sigma_i + sigma_l), rb = 0.5 * (sigma_j + sigma_l);
  const double x0 = (distance * distance + ra * ra - rb * rb) / (2 * distance);
  auto cap = [d](double r, double a, double& size, double& centroid) {
    if (d == 3) {
      const double h = r - a;
      size = std::numbers::pi * h * h * (3 * r - h) / 3;
      centroid = 3 * (2 * r - h) * (2 * r - h) / (4 * (3 * r - h));
      return;
    }
    const double half_chord = std::sqrt(r * r - a * a);
    size = r * r * std::acos(a / r) - a * half_chord;
    centroid = 2 * half_chord * half_chord * half_chord / (3 * size);
  };
  double va = 0, ca = 0, vb = 0, cb = 0;
  cap(ra, x0, va, ca);
  cap(rb, distance - x0, vb, cb);
  return (va * ca + vb * (distance - cb)) / (va + vb) - 0.5 * distance;
}

/// dense_cell_closures in dimension D (the contact polynomials then inline without a branch).
template <int D>
void closures(const DenseCellGeometry& g, DenseCellClosures& out) {
  constexpr int d = D;
  const int s = g.s;
  // v_d and B_2 of (18.2) per dimension, computed once (pow and tgamma would dominate a call).
  static const std::array<double, 2> volume_factor{std::numbers::pi / 4, std::numbers::pi / 6},
      virial{std::numbers::pi / 2, 2 * std::numbers::pi / 3};
  const double vd = volume_factor[static_cast<std::size_t>(d - 2)], b2 = virial[static_cast<std::size_t>(d - 2)];
  std::array<double, kMax> volume{}, surface{}, n{};  // σ_k^d, σ_k^{d−1}, n_k (σ̄ = 1)
  double moment = 0;
  for (int k = 0; k < s; ++k) {
    surface[k] = d == 3 ? g.sigma[k] * g.sigma[k] : g.sigma[k];
    volume[k] = surface[k] * g.sigma[k];
    moment += g.fraction[k] * volume[k];
  }
  const double phi = g.packing_fraction, density = phi / (vd * moment);
  double y = 0;
  for (int k = 0; k < s; ++k) {
    n[k] = density * g.fraction[k];
    y += vd * n[k] * surface[k];
  }
  out.density = density;
  // a_ij = σ_iσ_j/σ_ij, σ_ij^d, 1/χ_ij and ∂χ_ij/∂n_ℓ at (i·4 + j)·4 + ℓ; only the s × s pairs are written and read.
  std::array<double, 16> width, weight, inverse_chi;
  std::array<double, 64> dchi;
  const GapPowers gap = gap_powers(1 / (1 - phi));
  for (int i = 0; i < s; ++i)
    for (int j = 0; j < s; ++j) {
      const int P = i * kMax + j;
      const double sij = 0.5 * (g.sigma[i] + g.sigma[j]);
      width[P] = g.sigma[i] * g.sigma[j] / sij;
      weight[P] = d == 3 ? sij * sij * sij : sij * sij;
      const Contact c = contact<D>(gap, width[P] * y);
      out.chi[P] = c.f;
      inverse_chi[P] = 1 / c.f;
      // ∂χ/∂n_ℓ = v_d (F_φ σ_ℓ^d + a F_u σ_ℓ^{d−1}), n ∂ln χ/∂n_ℓ = n ∂χ/∂n_ℓ /χ (18.1)
      const double a = vd * c.f_phi, b = vd * c.f_u * width[P], scale = density * inverse_chi[P];
      for (int l = 0; l < s; ++l) {
        dchi[P * kMax + l] = a * volume[l] + b * surface[l];
        out.log_chi_derivative[P * kMax + l] = scale * dchi[P * kMax + l];
      }
    }
  for (int k = 1; k < s; ++k) out.unequal = out.unequal || g.sigma[k] != g.sigma[0];
  if (!out.unequal) return;

  // ∂_i∂_ℓ (μ^ex/T)… : H_iℓ = ∫_0^1 dλ ∂_i∂_ℓ (p^ex/T)(λn), p^ex/T = B_2 Σ_jk n_j n_k σ_jk^d χ_jk (18.17). With
  // ∂_ℓχ_jk = v_d(F_φ σ_ℓ^d + a F_u σ_ℓ^{d−1}) the Hessian at λn is 2σ_iℓ^d χ_iℓ + 2v_d(T_iφ σ_ℓ^d + T_iu σ_ℓ^{d−1} +
  // (i ↔ ℓ))
  // + v_d² (A_φφ σ_i^dσ_ℓ^d + A_φu(σ_i^dσ_ℓ^{d−1} + σ_ℓ^dσ_i^{d−1}) + A_uu σ_i^{d−1}σ_ℓ^{d−1}).
  // The node-dependent pieces enter H linearly and are polynomials in λ y over (1 − λφ)^q: integrate them
  // over λ through the five moments M_q first (one pass over the nodes for all pairs), assemble H once.
  std::array<double, kMax> t_phi{}, t_u{};
  std::array<double, 16> f{};
  double a_pp = 0, a_pu = 0, a_uu = 0;
  const GapPowers moments = lambda_moments(phi, b2);
  for (int j = 0; j < s; ++j)
    for (int k = j; k < s; ++k) {
      const int P = j * kMax + k;
      const Contact c = contact<D>(moments, width[P] * y);  // ∫dλ F, ∫dλ λ F_φ, …, ∫dλ λ² F_uu
      f[P] = c.f;
      const double pair = (j == k ? 1.0 : 2.0) * weight[P] * n[j] * n[k];
      a_pp += pair * c.f_phiphi;
      a_pu += pair * c.f_phiu * width[P];
      a_uu += pair * c.f_uu * width[P] * width[P];
      t_phi[j] += weight[P] * n[k] * c.f_phi;
      t_u[j] += weight[P] * n[k] * c.f_u * width[P];
      if (k != j) {
        t_phi[k] += weight[P] * n[j] * c.f_phi;
        t_u[k] += weight[P] * n[j] * c.f_u * width[P];
      }
    }
  std::array<double, 16> hessian{};
  for (int i = 0; i < s; ++i)
    for (int l = 0; l < s; ++l)
      hessian[i * kMax + l] =
          2 * weight[i * kMax + l] * f[std::min(i, l) * kMax + std::max(i, l)] +
          2 * vd * (t_phi[i] * volume[l] + t_u[i] * surface[l] + t_phi[l] * volume[i] + t_u[l] * surface[i]) +
          vd * vd *
              (a_pp * volume[i] * volume[l] + a_pu * (volume[i] * surface[l] + volume[l] * surface[i]) +
               a_uu * surface[i] * surface[l]);
  // b_ℓi = H_iℓ/(2B_2) − Σ_k σ_ik^d [χ_ik δ_kℓ + ½ n_k ∂_ℓχ_ik] (18.19)
  std::array<double, 16> remainder{};  // at i·4 + ℓ
  for (int i = 0; i < s; ++i)
    for (int l = 0; l < s; ++l) {
      double rest = hessian[i * kMax + l] / (2 * b2);
      for (int k = 0; k < s; ++k) {
        const int P = i * kMax + k;
        rest -= weight[P] * ((k == l ? out.chi[P] : 0.0) + 0.5 * n[k] * dchi[P * kMax + l]);
      }
      remainder[i * kMax + l] = rest;
    }
  if (s == 2) {  // (18.20)
    for (int i = 0; i < 2; ++i) {
      const int j = 1 - i, P = i * kMax + j;
      for (int l = 0; l < 2; ++l)
        out.functionals[P * kMax + l] = 2 * remainder[i * kMax + l] * inverse_chi[P] / weight[P];
    }
    return;
  }
  // s ≥ 3, lens-centroid closure (§18.12): K_ℓij = δ_ijℓ ∂_ℓχ_ij/σ_ij + u_ℓi − u_ℓj with Σ_j n_j σ_ij^d K_ℓij = b_ℓi;
  // the row of the most abundant species is dropped and its u is 0.
  int major = 0;
  for (int k = 1; k < s; ++k)
    if (n[k] > n[major]) major = k;
  std::array<int, kMax> unknown{};
  for (int k = 0, c = 0; k < s; ++k) unknown[k] = k == major ? -1 : c++;
  const int m = s - 1;
  for (int l = 0; l < s; ++l) {
    std::array<double, 16> reference{};
    for (int i = 0; i < s; ++i)
      for (int j = i + 1; j < s; ++j) {  // the offset is antisymmetric in (i, j), ∂_ℓχ_ij/σ_ij symmetric
        const int P = i * kMax + j;
        const double v = lens_centroid_offset(d, g.sigma[i], g.sigma[j], g.sigma[l]) * dchi[P * kMax + l] /
                         (0.5 * (g.sigma[i] + g.sigma[j]));
        reference[P] = v;
        reference[j * kMax + i] = -v;
      }
    std::array<double, 9> a{};
    std::array<double, 3> b{};
    for (int i = 0; i < s; ++i) {
      if (i == major) continue;
      const int row = unknown[i];
      b[row] = remainder[i * kMax + l];
      for (int j = 0; j < s; ++j) {
        if (j == i) continue;
        const double wij = n[j] * weight[i * kMax + j];
        b[row] -= wij * reference[i * kMax + j];
        a[row * 3 + row] += wij;
        if (j != major) a[row * 3 + unknown[j]] -= wij;
      }
    }
    // Gaussian elimination (strictly diagonally dominant rows: no pivoting needed).
    for (int c = 0; c < m; ++c)
      for (int rr = c + 1; rr < m; ++rr) {
        const double f = a[rr * 3 + c] / a[c * 3 + c];
        for (int k = c; k < m; ++k) a[rr * 3 + k] -= f * a[c * 3 + k];
        b[rr] -= f * b[c];
      }
    std::array<double, 3> u3{};
    for (int rr = m - 1; rr >= 0; --rr) {
      double v = b[rr];
      for (int k = rr + 1; k < m; ++k) v -= a[rr * 3 + k] * u3[k];
      u3[rr] = v / a[rr * 3 + rr];
    }
    auto u = [&](int k) { return k == major ? 0.0 : u3[unknown[k]]; };
    for (int i = 0; i < s; ++i)
      for (int j = 0; j < s; ++j) {
        if (i == j) continue;
        const int P = i * kMax + j;
        out.functionals[P * kMax + l] = 2 * n[j] * (reference[P] + u(i) - u(j)) * inverse_chi[P];
      }
  }
}

}  // namespace

void dense_cell_closures(const DenseCellGeometry& g, DenseCellClosures& out) {
  if (g.d == 3)
    closures<3>(g, out);
  else
    closures<2>(g, out);
}

DenseCellClosures dense_cell_closures(const DenseCellGeometry& g) {
  DenseCellClosures out;
  dense_cell_closures(g, out);
  return out;
}

}  // namespace gkt::detail
