// Private: the moment balances of the rough gas's homogeneous cooling state at any Sonine order
// (docs/theory.md §19.14). The scaled distribution is
//   φ(c, ŵ) = φ_M(c) φ_M(ŵ) [1 + Σ_{(p,q) ∈ I} a_pq S_p^(m_t)(x) S_q^(m_r)(y)],   x = c², y = ŵ²,
// I = {(p, q): 2 ≤ p + q ≤ M} (M = order + 1; only q = 0 when the spin decouples, β = −1). For
// each test ψ = x^k y^l, (k, l) ∈ I, and for the energies x, y the Boltzmann equation gives
//   (k + l) z ⟨ψ⟩ + R[ψ] = 0,   R[ψ] = ⟨(1 + Φ(1))(1 + Φ(2))(ψ(1') − ψ(1))⟩/⟨1⟩,   z = −(2/d) R[x],
// and R[x]/d = R[y]/d_r (ζ_t = ζ_r). The collision averages of monomials
//   D(i, j, k, l; m, n) = ⟨x1^i y1^j x2^k y2^l (x1'^m y1'^n − x1^m y1^n)⟩/⟨1⟩
// come from the rough engine with θ symbolic (six forms x1, y1, x2, y2, x1', y1' for the gain
// and four for the loss), combined exactly into Laurent polynomials in τ = θ/κ; per τ they are
// evaluated in double and contracted with the Sonine coefficients.
//
// With `orientation` (spheres only; linear and nonlinear schemes, §19.14) the ansatz adds the velocity–spin
// orientation family Σ b_pq P S_p^(5/2)(x) S_q^(5/2)(y), P = (c·ŵ)² − xy/3, p + q ≤ M − 2 (the same
// total degree in c², ŵ² as the a_pq), with the tests ψ = P x^k y^l; their averages need the forms
// f = c·w of theory.md (19.5a). For disks c·ŵ ≡ 0 (ŵ is normal to the plane of c): the flag does nothing.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "gkt/algebra/rational.hpp"

namespace gkt::detail {

/// Exact Σ_j c_j τ^{j − shift} with its double coefficients (a collision average in powers of τ).
struct TauLaurent {
  int shift = 0;
  std::vector<Rational> exact;
  std::vector<double> c;
  [[nodiscard]] double operator()(double tau) const;
};

/// The balances of the rough HCS with cumulants a_pq, p + q ≤ M (see the file comment).
class RoughSonineBalances {
 public:
  /// Builds the exact tables for d ∈ {2, 3}, α, β, κ (validated: std::invalid_argument naming the
  /// field) and highest Sonine degree M = p + q ≥ 2. With `products` the Φ(1)Φ(2) averages (the
  /// nonlinear scheme) are built too. With `orientation` (d = 3, β > −1) the b_pq family is added; with both,
  /// the products a·a, a·b, b·b come from one gain table of nine forms (x, y, c·w of both partners and of 1').
  RoughSonineBalances(int dimension, const Rational& alpha, const Rational& beta, const Rational& kappa,
                      int highest_degree, bool products, bool orientation = false);
  /// Builds the linear-scheme balances without collision tables, for averages supplied by the caller
  /// (productions_from; the Walton gas, theory.md §19.25, §19.29): d ∈ {2, 3}, M ≥ 2, `spin_decoupled` as at β = −1;
  /// `orientation` adds the b_pq family as above (d = 3 and spin coupled only). Throws std::invalid_argument naming
  /// the field.
  RoughSonineBalances(int dimension, int highest_degree, bool spin_decoupled, bool orientation = false);

  /// Returns the cumulant indices (p, q) of the a_pq, the first unknowns.
  [[nodiscard]] const std::vector<std::array<int, 2>>& cumulants() const { return cumulants_; }
  /// Returns the indices (p, q) of the orientation coefficients b_pq, the unknowns after the a_pq (empty
  /// without `orientation`, for disks and at β = −1).
  [[nodiscard]] const std::vector<std::array<int, 2>>& orientations() const { return orientations_; }
  /// Returns the number of unknowns (a_pq, then b_pq).
  [[nodiscard]] std::size_t unknowns() const { return cumulants_.size() + orientations_.size(); }
  /// Returns C − 1/3 = ⟨(c·ŵ)²/(xy)⟩ − 1/3 per unit b_pq, in the order of orientations() (theory.md §19.14).
  [[nodiscard]] const std::vector<double>& correlation_weights() const { return correlation_weights_; }
  /// Returns ⟨ψ_t⟩_M for the tests t = x, y, then the unknowns' (x^k y^l, P x^k y^l), as doubles of exact rationals.
  [[nodiscard]] const std::vector<double>& maxwellian_moments() const { return maxwellian_; }
  /// Returns ⟨ψ_t Φ_w⟩_M, [t][w] (t as in maxwellian_moments(), w the unknowns): ⟨ψ_t⟩ = ⟨ψ_t⟩_M + Σ_w a_w ⟨ψ_t Φ_w⟩_M.
  [[nodiscard]] const std::vector<std::vector<double>>& projections() const { return projection_; }
  /// Returns the weight of unknown w (0-based) as monomials: ((i, j, e) of x^i y^j (c·ŵ)^{2e}, coefficient).
  [[nodiscard]] std::vector<std::pair<std::array<int, 3>, double>> weight_expansion(std::size_t w) const {
    std::vector<std::pair<std::array<int, 3>, double>> out;
    for (const auto& [m, c] : weight_terms_.at(w + 1)) out.push_back({monomials_[m], c});
    return out;
  }
  /// Returns true at β = −1 (the spin decouples; the unknowns are a_p0 only, τ plays no role).
  [[nodiscard]] bool spin_decoupled() const { return decoupled_; }
  /// Returns the residuals at τ and a (the unknowns: a_pq, then b_pq): F_0 = R[x]/d − R[y]/d_r (absent when
  /// the spin decouples), then F_(k,l) = (k + l) z ⟨x^k y^l⟩ + R[x^k y^l] for the cumulant indices, then
  /// (k + l + 2) z ⟨P x^k y^l⟩ + R[P x^k y^l] for the orientation indices. `linear` drops every
  /// product of cumulants (the linear scheme); otherwise all are kept (needs `products`).
  [[nodiscard]] std::vector<double> residual(double tau, std::span<const double> a, bool linear) const;
  /// Returns z_t = ζ_t/(nσ^{d−1}v_t ν) = −(2/d) R[x] at τ and a (linearised in a when `linear`).
  [[nodiscard]] double translational_rate(double tau, std::span<const double> a, bool linear) const;

  /// R_{w1,w2}[t] at τ: weights 0 (Φ = 1) and 1 … K (the Sonine products, then the P products), tests
  /// 0 = x, 1 = y, 2 … K + 1 the unknowns' indices. Entries with both weights ≠ 0 only with `products`.
  struct Productions {
    std::size_t weights = 0, tests = 0;
    std::vector<double> r;  // [w1][w2][t]
    [[nodiscard]] double operator()(std::size_t w1, std::size_t w2, std::size_t t) const {
      return r[(w1 * weights + w2) * tests + t];
    }
  };
  /// Returns the collision averages at τ (only those of the linear scheme when `linear`).
  [[nodiscard]] Productions productions(double tau, bool linear) const;
  /// A collision average ⟨x1^i y1^j f1^{2e} x2^k y2^l f2^{2g} x1'^m y1'^n f1'^{2h}⟩/⟨1⟩ (y = ŵ², the scaled spin;
  /// f = c·ŵ) of the linear scheme, from the exponents (i, j, e) of partner 1's weight, (k, l, g) of partner 2's and
  /// (m, n, h) of the test at 1' (e = g = h = 0 for the isotropic ansatz).
  using MonomialAverage =
      std::function<double(const std::array<int, 3>&, const std::array<int, 3>&, const std::array<int, 3>&)>;
  /// Returns the linear-scheme averages from `gain` (the average above) and `loss` (⟨x1^{i+m} y1^{j+n} f1^{2(e+h)}
  /// x2^k y2^l f2^{2g}⟩/⟨1⟩, called with the same three exponent triples): the Walton gas's quadratures (theory.md
  /// §19.25, §19.29) in place of the engine's tables.
  [[nodiscard]] Productions productions_from(const MonomialAverage& gain, const MonomialAverage& loss) const;
  /// Returns z_t = −(2/d) R[x] from averages r at a (linearised in a when `linear`).
  [[nodiscard]] double translational_rate(const Productions& r, std::span<const double> a, bool linear) const;
  /// Returns residual(τ, a, linear) from the averages at τ.
  [[nodiscard]] std::vector<double> evaluate(const Productions& r, std::span<const double> a, bool linear) const;

 private:
  int dimension_;
  int highest_;
  bool products_;
  bool decoupled_;
  std::vector<std::array<int, 2>> cumulants_;
  std::vector<std::array<int, 2>> orientations_;
  /// A test function as monomials x^i y^j (c·ŵ)^{2e} (index into monomials_) with exact coefficients, and its
  /// scaling degree (k + l, or k + l + 2 for P x^k y^l).
  struct Test {
    int degree = 0;
    std::vector<std::pair<std::array<int, 3>, Rational>> terms;
  };
  std::vector<Test> tests_;                    // x, y, then the unknowns
  std::vector<std::array<int, 3>> monomials_;  // (i, j, e): x^i y^j (c·ŵ)^{2e}; i + j + 2e ≤ M (j = 0 when decoupled)
  std::vector<double> correlation_weights_;
  /// Sonine products as monomials: per weight, (monomial index, coefficient).
  std::vector<std::vector<std::pair<std::size_t, double>>> weight_terms_;
  /// ⟨ψ_t⟩_M and ⟨ψ_t Φ_w⟩_M (exact rationals as doubles): [t], [t][w − 1].
  std::vector<double> maxwellian_;
  std::vector<std::vector<double>> projection_;
  /// D(monomial 1, monomial 2; test) as Laurent polynomials in τ, [m1][m2][t]; with `products`
  /// false only the entries with m1 = 0 or m2 = 0 are filled.
  std::vector<TauLaurent> d_;

  /// Fills the unknowns, tests, monomials, weights and Maxwellian projections (no collision tables).
  void build_structure(bool oriented);
  /// Contracts the monomial averages d [m1][m2][t] with the Sonine weights.
  [[nodiscard]] Productions contract(const std::vector<double>& d, bool linear) const;
};

}  // namespace gkt::detail
