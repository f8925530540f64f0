#include "transport/rough/rough_sonine_systems.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <flint/fmpq_poly.h>

#include "gkt/algebra/sonine.hpp"
#include "gkt/collision/rough_collision_moments.hpp"
#include "transport/rough/rough_aligned_families.hpp"
#include "transport/rough/rough_weighted_elements.hpp"

namespace gkt::detail {

namespace {

using S = RoughSlot;

int rotational_dimension(int d) { return rough_rotational_dimension(d); }

Rational contraction_weight(int d, int rank) { return rough_contraction_weight(d, rank); }

/// Returns the table ⟨(c_a·c_b)^r X_a^i Y_a^j X_b^k Y_b^l⟩/⟨1⟩ of one slot pair (r ≤ 2; i + j, k + l ≤ K).
RoughCollisionMoments<RationalPolynomial> pair_table(const RoughCollisionParameters<RationalPolynomial>& p, S va, S wa,
                                                     S vb, S wb, int k) {
  return {p,
          {rough_dot_form(va, vb), rough_dot_form(va, va), rough_dot_form(wa, wa), rough_dot_form(vb, vb),
           rough_dot_form(wb, wb)},
          {2, k, k, k, k},
          [k](const RoughExponents& e) { return e[1] + e[2] <= k && e[3] + e[4] <= k; }};
}

/// Returns Σ_ik a_i b_k (c0 + c1 k) ⟨u^{shift + i + k}⟩ for u = x (twice_h = d) or y (twice_h = d_r), exact.
Rational one_dimensional(const std::vector<Rational>& a, const std::vector<Rational>& b, long twice_h, int shift,
                         long c0, long c1) {
  Rational sum(0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t k = 0; k < b.size(); ++k) {
      if (a[i].is_zero() || b[k].is_zero()) continue;
      const long factor = c0 + c1 * static_cast<long>(k);
      if (factor == 0) continue;
      sum += a[i] * b[k] * Rational(factor) * Rational::rising_half(twice_h, static_cast<unsigned long>(shift) + i + k);
    }
  return sum;
}

/// Solves a x = b by Gaussian elimination with partial pivoting (small dense systems).
std::vector<double> solve_linear(RoughMatrix a, std::vector<double> b) {
  const std::size_t n = b.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
    std::swap(a[c], a[pivot]);
    std::swap(b[c], b[pivot]);
    for (std::size_t r = c + 1; r < n; ++r) {
      const double factor = a[r][c] / a[c][c];
      for (std::size_t k = c; k < n; ++k) a[r][k] -= factor * a[c][k];
      b[r] -= factor * b[c];
    }
  }
  std::vector<double> x(n);
  for (std::size_t r = n; r-- > 0;) {
    double s = b[r];
    for (std::size_t k = r + 1; k < n; ++k) s -= a[r][k] * x[k];
    x[r] = s / a[r][r];
  }
  return x;
}

/// Returns the basis T_rank S_p L_q, lowest ≤ p + q ≤ highest (q = 0 only when the spin is decoupled).
std::vector<RoughTrialFunction> sonine_basis(const RoughModeState& state, int rank, int lowest, int highest) {
  std::vector<RoughTrialFunction> basis;
  for (int total = lowest; total <= highest; ++total)
    for (int q = 0; q <= (state.spin_decoupled ? 0 : total); ++q)
      basis.push_back(rough_sonine_function(state.dimension, rank, total - q, q));
  return basis;
}

/// Appends the aligned-spin functions of the basis's rank to s (theory.md (19.49)): their collision rows and columns
/// with every product and with each other; N and G vanish between an aligned function and a product (orthogonal, and
/// C·∂_C maps each set into itself).
void append_aligned_families(RoughGalerkinSystem& s, const RoughFamilyElements& aligned, double tau, int members) {
  const int rank = s.basis.front().rank, m = members > 0 ? aligned.count_up_to(rank, members) : aligned.count(rank);
  const std::size_t n = s.basis.size(), total = n + static_cast<std::size_t>(m);
  for (RoughMatrix* x : {&s.collision, &s.cooling, &s.product}) {
    for (auto& row : *x) row.resize(total, 0.0);
    x->resize(total, std::vector<double>(total, 0.0));
  }
  for (int k = 1; k <= m; ++k) {
    const std::size_t r = n + static_cast<std::size_t>(k - 1);
    for (std::size_t q = 0; q < n; ++q) {
      s.collision[r][q] = aligned.element(rank, -1, k, s.basis[q].p, s.basis[q].q, tau);
      s.collision[q][r] = aligned.element(rank, s.basis[q].p, s.basis[q].q, -1, k, tau);
    }
    for (int j = 1; j <= m; ++j) {
      const std::size_t c = n + static_cast<std::size_t>(j - 1);
      s.collision[r][c] = aligned.element(rank, -1, k, -1, j, tau);
      s.product[r][c] = aligned.maxwell_product(rank, k, j);
      s.cooling[r][c] = aligned.maxwell_scaling_product(rank, k, j);
    }
  }
}

/// Returns v padded with zeros to n entries (the aligned families' sources and fluxes).
std::vector<double> padded(std::vector<double> v, std::size_t n) {
  v.resize(n, 0.0);
  return v;
}

/// Returns the system of `basis`: the collision elements at τ and the exact Maxwellian products.
RoughGalerkinSystem system_of(const RoughCollisionElements& elements, const RoughModeState& state,
                              std::vector<RoughTrialFunction> basis) {
  const std::size_t n = basis.size();
  RoughGalerkinSystem s;
  s.collision.assign(n, std::vector<double>(n));
  s.cooling = s.product = s.collision;
  for (std::size_t p = 0; p < n; ++p) {
    for (std::size_t q = 0; q < n; ++q) {
      s.collision[p][q] = elements.element(basis[p].rank, basis[p].p, basis[p].q, basis[q].p, basis[q].q, state.tau);
      if (state.reference) {  // about f_M(1 + Φ): Σ_w a_w W^{(w)} (rough_weighted_elements.hpp)
        const RoughCumulantReference& r = *state.reference;
        if (r.weighted_sum)
          s.collision[p][q] +=
              r.weighted_sum->element(basis[p].rank, basis[p].p, basis[p].q, basis[q].p, basis[q].q, state.tau);
        for (std::size_t w = 0; !r.weighted_sum && w < r.indices.size(); ++w)
          s.collision[p][q] +=
              r.cumulants[w] * r.elements->element(basis[p].rank, basis[p].p, basis[p].q, basis[q].p, basis[q].q,
                                                   r.indices[w][0], r.indices[w][1], state.tau);
        for (std::size_t w = 0; !r.weighted_sum && w < r.orientation_indices.size(); ++w)
          s.collision[p][q] +=
              r.orientation_coefficients[w] *
              r.elements->orientation_element(basis[p].rank, basis[p].p, basis[p].q, basis[q].p, basis[q].q,
                                              r.orientation_indices[w][0], r.orientation_indices[w][1], state.tau);
      }
      s.cooling[p][q] = rough_maxwell_scaling_product(state.dimension, basis[p], basis[q]).to_double();
      s.product[p][q] = rough_maxwell_product(state.dimension, basis[p], basis[q]).to_double();
    }
  }
  s.basis = std::move(basis);
  if (state.aligned && !state.spin_decoupled && !s.basis.empty())
    append_aligned_families(s, *state.aligned, state.tau, state.family_members);
  return s;
}

/// Returns ⟨T_rank (c0 + cx x + cy y) ψ_q⟩ for every q (the exact products ⟨ψ_q⟩, ⟨xψ_q⟩, ⟨yψ_q⟩ combined).
std::vector<double> projections(int d, double c0, double cx, double cy, const std::vector<RoughTrialFunction>& basis) {
  std::vector<double> out;
  for (const auto& psi : basis) {
    const RoughTrialFunction one{psi.rank, 0, 0, {Rational(1)}, {Rational(1)}};
    const RoughTrialFunction x{psi.rank, 0, 0, {Rational(0), Rational(1)}, {Rational(1)}};
    const RoughTrialFunction y{psi.rank, 0, 0, {Rational(1)}, {Rational(0), Rational(1)}};
    out.push_back(c0 * rough_maxwell_product(d, one, psi).to_double() +
                  cx * rough_maxwell_product(d, x, psi).to_double() +
                  cy * rough_maxwell_product(d, y, psi).to_double());
  }
  return out;
}

using Coefficients = std::vector<Rational>;

/// Returns x·s(x) (coefficients of powers).
Coefficients times_x(const Coefficients& s) {
  Coefficients out(s.size() + 1, Rational(0));
  for (std::size_t i = 0; i < s.size(); ++i) out[i + 1] = s[i];
  return out;
}

/// Returns c0 s + c1 x s'(x) (coefficients of powers).
Coefficients with_degree(const Coefficients& s, const Rational& c0, const Rational& c1) {
  Coefficients out(s.size(), Rational(0));
  for (std::size_t i = 0; i < s.size(); ++i) out[i] = s[i] * (c0 + c1 * Rational(static_cast<long>(i)));
  return out;
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

/// Returns L + c_g G + c_n N.
RoughMatrix combine(const RoughGalerkinSystem& s, double c_g, double c_n) {
  RoughMatrix m = s.collision;
  for (std::size_t p = 0; p < m.size(); ++p)
    for (std::size_t q = 0; q < m.size(); ++q) m[p][q] += c_g * s.cooling[p][q] + c_n * s.product[p][q];
  return m;
}

}  // namespace

int rough_rotational_dimension(int d) { return d == 3 ? 3 : 1; }

Rational rough_contraction_weight(int d, int rank) {
  return rank == 2 ? Rational(d - 1, static_cast<unsigned long>(d)) : Rational(1);
}

void add_scaled(RationalPolynomial& acc, const RationalPolynomial& x, const Rational& c) {
  if (x.is_zero() || c.is_zero()) return;
  RationalPolynomial t = x;
  t *= c;
  acc += t;
}

RationalPolynomial shifted_by(const RationalPolynomial& p, long n) {
  RationalPolynomial out;
  fmpq_poly_shift_left(out.raw(), p.raw(), n);
  return out;
}

RoughTable4 contract_sonine(const RoughTable4& t, int k, long twice_m, long twice_m_spin) {
  const auto s = sonine_table(twice_m, k);
  const auto r = sonine_table(twice_m_spin, k);
  RoughTable4 u1(k), u2(k), u3(k), e(k);
  for (int p = 0; p <= k; ++p)
    for (int j = 0; p + j <= k; ++j)
      for (int a = 0; a <= k; ++a)
        for (int b = 0; a + b <= k; ++b)
          for (int i = 0; i <= p; ++i) add_scaled(u1(p, j, a, b), t(i, j, a, b), s[p][i]);
  for (int p = 0; p <= k; ++p)
    for (int q = 0; p + q <= k; ++q)
      for (int a = 0; a <= k; ++a)
        for (int b = 0; a + b <= k; ++b)
          for (int j = 0; j <= q; ++j) add_scaled(u2(p, q, a, b), u1(p, j, a, b), r[q][j]);
  for (int p = 0; p <= k; ++p)
    for (int q = 0; p + q <= k; ++q)
      for (int pt = 0; pt <= k; ++pt)
        for (int b = 0; pt + b <= k; ++b)
          for (int a = 0; a <= pt; ++a) add_scaled(u3(p, q, pt, b), u2(p, q, a, b), s[pt][a]);
  for (int p = 0; p <= k; ++p)
    for (int q = 0; p + q <= k; ++q)
      for (int pt = 0; pt <= k; ++pt)
        for (int qt = 0; pt + qt <= k; ++qt)
          for (int b = 0; b <= qt; ++b) add_scaled(e(p, q, pt, qt), u3(p, q, pt, b), r[qt][b]);
  return e;
}

RoughTrialFunction rough_sonine_function(int dimension, int rank, int p, int q) {
  return {rank, p, q, sonine_coefficients(sonine_twice_m(dimension, rank), p),
          sonine_coefficients(rotational_dimension(dimension) - 2, q)};
}

Rational rough_maxwell_product(int d, const RoughTrialFunction& a, const RoughTrialFunction& b) {
  if (a.rank != b.rank) throw std::logic_error("rough_maxwell_product: ranks differ");
  // ⟨x^n⟩ = Γ(d/2 + n)/Γ(d/2), ⟨y^m⟩ = Γ(d_r/2 + m)/Γ(d_r/2); T_r:T_r = w_r x^r.
  return contraction_weight(d, a.rank) * one_dimensional(b.s, a.s, d, a.rank, 1, 0) *
         one_dimensional(b.l, a.l, rotational_dimension(d), 0, 1, 0);
}

Rational rough_maxwell_scaling_product(int d, const RoughTrialFunction& a, const RoughTrialFunction& b) {
  if (a.rank != b.rank) throw std::logic_error("rough_maxwell_scaling_product: ranks differ");
  // C·∂_C (T_r x^i y^j) = (r + 2i + 2j) T_r x^i y^j: the translational and spin degrees add.
  const long dr = rotational_dimension(d);
  return contraction_weight(d, a.rank) *
         (one_dimensional(b.s, a.s, d, a.rank, a.rank, 2) * one_dimensional(b.l, a.l, dr, 0, 1, 0) +
          one_dimensional(b.s, a.s, d, a.rank, 1, 0) * one_dimensional(b.l, a.l, dr, 0, 0, 2));
}

double rough_reference_average(int d, const std::vector<Rational>& s, const std::vector<Rational>& l,
                               const RoughCumulantReference* reference) {
  const long dr = rotational_dimension(d);
  const Coefficients one{Rational(1)};
  double sum = (one_dimensional(s, one, d, 0, 1, 0) * one_dimensional(l, one, dr, 0, 1, 0)).to_double();
  if (!reference) return sum;
  for (std::size_t w = 0; w < reference->indices.size(); ++w) {
    const auto [p, q] = reference->indices[w];
    sum += reference->cumulants[w] * (one_dimensional(s, sonine_coefficients(sonine_twice_m(d, 0), p), d, 0, 1, 0) *
                                      one_dimensional(l, sonine_coefficients(dr - 2, q), dr, 0, 1, 0))
                                         .to_double();
  }
  return sum;
}

RoughCollisionElements::RoughCollisionElements(const RoughCollisionParameters<RationalPolynomial>& parameters,
                                               int highest_order)
    : k_(highest_order) {
  const int k = k_, d = parameters.dimension;
  const auto post = pair_table(parameters, S::v1, S::w1, S::v1_post, S::w1_post, k);
  const auto other = pair_table(parameters, S::v2, S::w2, S::v1, S::w1, k);
  const auto other_post = pair_table(parameters, S::v2, S::w2, S::v1_post, S::w1_post, k);
  const RoughCollisionMoments<RationalPolynomial> self(
      parameters, {rough_dot_form(S::v1, S::v1), rough_dot_form(S::w1, S::w1)}, {2 * k + 2, 2 * k});
  const Rational inv_d(1, static_cast<unsigned long>(d));
  for (int rank = 0; rank <= 2; ++rank) {
    // L = [⟨ψ(1)ψ'(1)⟩ − ⟨ψ(1)ψ'(1')⟩] + [⟨ψ(2)ψ'(1)⟩ − ⟨ψ(2)ψ'(1')⟩] (theory.md (5.2)), the tensor parts contracted
    // as (c_a·c_b)^r, minus X_a X_b/d for r = 2 (theory.md (4.2)); ŷ = Y/τ: every entry times λ^{2(2K − j − l)}.
    const auto cross = [&](const RoughCollisionMoments<RationalPolynomial>& m, int i, int j, int a, int b) {
      if (rank < 2) return m.moment({rank, i, j, a, b});
      RationalPolynomial v = m.moment({2, i, j, a, b});
      RationalPolynomial x = m.moment({0, i + 1, j, a + 1, b});
      x *= inv_d;
      v -= x;
      return v;
    };
    const int top = rank == 2 ? k - 1 : k;
    RoughTable4 t(k);
    for (int i = 0; i <= top; ++i)
      for (int j = 0; i + j <= top; ++j)
        for (int a = 0; a <= top; ++a)
          for (int b = 0; a + b <= top; ++b) {
            RationalPolynomial v = self.moment({rank + i + a, j + b});
            v *= contraction_weight(d, rank);
            v -= cross(post, i, j, a, b);
            v += cross(other, i, j, a, b);
            v -= cross(other_post, i, j, a, b);
            t(i, j, a, b) = shifted_by(v, 2L * (2 * k - j - b));
          }
    auto& out = contracted_[static_cast<std::size_t>(rank)];
    for (const RationalPolynomial& e :
         contract_sonine(t, top, sonine_twice_m(d, rank), rotational_dimension(d) - 2).release()) {
      // e = λ^{4K} × element, even in λ: Σ_j e_{2j} τ^{j − 2K}.
      std::vector<long double> c;
      for (long j = 0; j <= e.degree(); j += 2) c.push_back(static_cast<long double>(e.coefficient(j).to_double()));
      out.push_back(std::move(c));
    }
  }
}

RoughCollisionElements::RoughCollisionElements(int highest_order, double tau,
                                               const std::array<std::vector<double>, 3>& elements)
    : k_(highest_order), fixed_tau_(tau) {
  // Stored as the coefficient of τ^{2K}, so that element() returns value·τ^{2K}·τ^{−2K} (long double).
  for (std::size_t rank = 0; rank < 3; ++rank)
    for (const double value : elements[rank]) {
      std::vector<long double> c(static_cast<std::size_t>(2 * k_ + 1), 0.0L);
      c.back() = value;
      contracted_[rank].push_back(std::move(c));
    }
}

double RoughCollisionElements::element(int rank, int p_test, int q_test, int p_trial, int q_trial, double tau) const {
  if (fixed_tau_ > 0 && tau != fixed_tau_)
    throw std::logic_error("RoughCollisionElements: numeric elements evaluated at another tau");
  const int top = rank == 2 ? k_ - 1 : k_, n = top + 1;
  if (p_test + q_test > top || p_trial + q_trial > top || p_test < 0 || q_test < 0 || p_trial < 0 || q_trial < 0)
    throw std::out_of_range("RoughCollisionElements: Sonine index above the table");
  const auto& c = contracted_[static_cast<std::size_t>(rank)]
                             [static_cast<std::size_t>(((p_trial * n + q_trial) * n + p_test) * n + q_test)];
  long double value = 0;
  const long double t = tau;
  for (std::size_t j = c.size(); j-- > 0;) value = value * t + c[j];
  return static_cast<double>(value * std::pow(t, -2.0L * k_));
}

RoughGalerkinSystem rough_tensor_system(const RoughCollisionElements& elements, const RoughModeState& state,
                                        int order) {
  return system_of(elements, state, sonine_basis(state, 2, 0, order - 1));
}

RoughGalerkinSystem rough_vector_system(const RoughCollisionElements& elements, const RoughModeState& state,
                                        int order) {
  return system_of(elements, state, sonine_basis(state, 1, 1, order));
}

RoughGalerkinSystem rough_scalar_system(const RoughCollisionElements& elements, const RoughModeState& state,
                                        int order) {
  return system_of(elements, state, sonine_basis(state, 0, 1, order));
}

RoughTransportValues solve_rough_navier_stokes(const RoughCollisionElements& elements, const RoughModeState& state,
                                               int order, double theta) {
  const int d = state.dimension;
  const double dd = d, dr = rotational_dimension(d);
  const bool decoupled = std::isinf(theta);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const RoughCumulantReference* ref = state.reference;
  // Cooling rate in engine units, z = (4/(d+2))ζ*: the reference HCS's, or the Maxwellian one at θ, z = −(2/d)⟨Δc1²⟩
  // (theory.md (19.12)), the scalar element ⟨S_1, 𝓛 1⟩ = 2⟨S_1(x1) − S_1(x1')⟩ = 2⟨Δc1²⟩.
  const double z = ref ? 4 / (dd + 2) * ref->cooling_rate : -(1.0 / dd) * elements.element(0, 1, 0, 0, 0, state.tau);
  // ⟨s(x) l(y)⟩ over f0 (the Maxwellian or the cumulant reference, theory.md (19.44)).
  const auto average = [d, ref](const Coefficients& sx, const Coefficients& ly) {
    return rough_reference_average(d, sx, ly, ref);
  };
  const Rational rd(d);
  RoughTransportValues out;

  // Shear: (L − (z/2)G + (z/2)N) a = b, η* = (d − 1) b⁰ᵀa, b⁰_p = ⟨ψ_p:Y2⟩/⟨Y2:Y2⟩ (the flux) and the source
  // b_p = ½(1 − 1/d)⟨x[(d + 2)F + 2xF_x] f0⟩/⟨Y2:Y2⟩ for ψ_p = Y2 F, equal to b⁰_p about Maxwellians (theory.md
  // (19.41), (19.44)).
  {
    const RoughGalerkinSystem s = rough_tensor_system(elements, state, order);
    const RoughTrialFunction y2 = rough_sonine_function(d, 2, 0, 0);
    const double norm = rough_maxwell_product(d, y2, y2).to_double();
    std::vector<double> flux = projections(d, 1, 0, 0, s.basis), source;
    for (double& x : flux) x /= norm;
    for (const auto& psi : s.basis)
      source.push_back((1 - 1 / dd) / 2 * average(times_x(with_degree(psi.s, rd + 2, Rational(2))), psi.l) / norm);
    const std::size_t size = s.collision.size();
    out.shear_viscosity =
        (dd - 1) * dot(padded(flux, size), solve_linear(combine(s, -z / 2, z / 2), padded(source, size)));
  }

  // Heat: (L − (z/2)(G + N)) x = A, (L − (z/2)G) y = z N x + B; fluxes ⟨c(x + θy)·ψ_q⟩ against the smooth elastic
  // n1²/(d − 1), n1 = d(d+2)/4 (theory.md (19.42)). For ψ_p = c F: A_p = ⟨[½ C·∂_C(xF) − ½(d + 2x∂_x)F] f0⟩ and
  // B_p = ⟨[xF − ½(d + 2x∂_x)F] f0⟩ ((19.44); about Maxwellians A_p = ⟨ψ_p·(ψ1 + ψ2)⟩ and B = 0).
  {
    const RoughGalerkinSystem s = rough_vector_system(elements, state, order);
    std::vector<double> drive, density;
    for (const auto& psi : s.basis) {
      const Coefficients xs = times_x(psi.s), half = with_degree(psi.s, rd / 2, Rational(1));
      const double a = average(with_degree(xs, Rational(0), Rational(1)), psi.l) +
                       average(xs, with_degree(psi.l, Rational(0), Rational(1))) - average(half, psi.l);
      drive.push_back(a);
      density.push_back(ref ? average(xs, psi.l) - average(half, psi.l) : 0.0);
    }
    const std::size_t size = s.collision.size();
    drive = padded(drive, size);
    density = padded(density, size);
    const auto x = solve_linear(combine(s, -z / 2, -z / 2), drive);
    std::vector<double> coupling(x.size());
    for (std::size_t p = 0; p < x.size(); ++p) coupling[p] = z * dot(s.product[p], x) + density[p];
    const auto y = solve_linear(combine(s, -z / 2, 0), coupling);
    const auto translational = padded(projections(d, 0, 1, 0, s.basis), size);
    const auto rotational = padded(projections(d, 0, 0, 1, s.basis), size);
    const double n1 = dd * (dd + 2) / 4, reference = n1 * n1 / (dd - 1);
    out.thermal_conductivity_translational = dot(translational, x) / reference;
    out.density_heat_translational = dot(translational, y) / reference;
    out.thermal_conductivity = decoupled ? nan : (dot(translational, x) + theta * dot(rotational, x)) / reference;
    out.density_heat_coefficient = decoupled ? nan : (dot(translational, y) + theta * dot(rotational, y)) / reference;
  }

  // Scalar: unknowns a_q and ζ_U; rows (L − (z/2)G + (z/2)N) a − (4/(d+2)) h_p ζ_U = (4/(d+2))(split h_p − (2/d) e_p)
  // with h_p = ½⟨(C·∂_C ψ_p) f0⟩, e_p = ½⟨(c·∂_c ψ_p) f0⟩, split = 2/(d + d_rθ), and zero total energy
  // ⟨(x + θy) f1⟩ = 0; η_b* = −(2/d)⟨x f1⟩ (theory.md (19.43), (19.44); about Maxwellians h_p = ⟨ψ_p H⟩,
  // e_p = ⟨ψ_p (x − d/2)⟩).
  if (decoupled) {
    out.bulk_viscosity = out.cooling_rate_first_order = nan;
    return out;
  }
  const RoughGalerkinSystem s = rough_scalar_system(elements, state, order);
  const std::size_t n = s.collision.size();
  const double split = 2 / (dd + dr * theta), scale = 4 / (dd + 2);
  RoughMatrix a = combine(s, -z / 2, z / 2);
  std::vector<double> rhs(n + 1, 0.0);
  for (std::size_t p = 0; p < s.basis.size(); ++p) {
    const auto& psi = s.basis[p];
    const double e = average(with_degree(psi.s, Rational(0), Rational(1)), psi.l);
    const double h = e + average(psi.s, with_degree(psi.l, Rational(0), Rational(1)));
    a[p].push_back(-scale * h);
    rhs[p] = scale * (split * h - (2 / dd) * e);
  }
  for (std::size_t p = s.basis.size(); p < n; ++p) a[p].push_back(0.0);  // aligned rows: no energy, no source
  a.push_back(padded(projections(d, 0, 1, theta, s.basis), n));
  a.back().push_back(0.0);
  const auto solution = solve_linear(a, rhs);
  const auto pressure = padded(projections(d, 0, 1, 0, s.basis), n);
  double trace = 0;
  for (std::size_t q = 0; q < n; ++q) trace += solution[q] * pressure[q];
  out.bulk_viscosity = -(2 / dd) * trace;
  out.cooling_rate_first_order = solution[n];
  return out;
}

}  // namespace gkt::detail
