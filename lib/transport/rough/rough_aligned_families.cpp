#include "transport/rough/rough_aligned_families.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "gkt/algebra/sonine.hpp"
#include "gkt/collision/rough_collision_moments.hpp"
#include "transport/rough/rough_sonine_systems.hpp"

namespace gkt::detail {

namespace {

using S = RoughSlot;

/// The invariants of a slot pair (a the trial's, b the test's): X = c², Y = ŵ², P = c·ŵ of each, and the four
/// cross products.
enum Invariant { kXa, kYa, kPa, kXb, kYb, kPb, kCC, kCW, kWC, kWW, kInvariants };
using Exponents = std::array<int, kInvariants>;
using DotPolynomial = std::map<Exponents, Rational>;

DotPolynomial monomial(const Rational& c, std::initializer_list<std::pair<Invariant, int>> factors) {
  Exponents e{};
  for (const auto& [v, k] : factors) e[v] += k;
  return {{e, c}};
}

DotPolynomial operator*(const DotPolynomial& a, const DotPolynomial& b) {
  DotPolynomial out;
  for (const auto& [ea, ca] : a)
    for (const auto& [eb, cb] : b) {
      Exponents e{};
      for (int v = 0; v < kInvariants; ++v) e[v] = ea[v] + eb[v];
      out[e] += ca * cb;
    }
  return out;
}

DotPolynomial operator+(DotPolynomial a, const DotPolynomial& b) {
  for (const auto& [e, c] : b) a[e] += c;
  return a;
}

/// Returns (kind_a at slot a) : (kind_b at slot b), fully contracted (kind 0 the product's tensor T_r, 1 and 2 the
/// aligned families; theory.md (19.48)).
DotPolynomial contraction(int rank, int kind_a, int kind_b) {
  const auto m = [](long n, unsigned long d, std::initializer_list<std::pair<Invariant, int>> f) {
    return monomial(Rational(n, d), f);
  };
  if (rank == 0) {
    const DotPolynomial pa = m(1, 1, {{kPa, 2}}) + m(-1, 3, {{kXa, 1}, {kYa, 1}});
    const DotPolynomial pb = m(1, 1, {{kPb, 2}}) + m(-1, 3, {{kXb, 1}, {kYb, 1}});
    const DotPolynomial one = m(1, 1, {});
    return (kind_a == 0 ? one : pa) * (kind_b == 0 ? one : pb);
  }
  if (rank == 1) {
    if (kind_a == 0 && kind_b == 0) return m(1, 1, {{kCC, 1}});
    if (kind_a == 0) return m(1, 1, {{kPb, 1}, {kCW, 1}}) + m(-1, 3, {{kCC, 1}, {kYb, 1}});
    if (kind_b == 0) return m(1, 1, {{kPa, 1}, {kWC, 1}}) + m(-1, 3, {{kCC, 1}, {kYa, 1}});
    return m(1, 1, {{kPa, 1}, {kPb, 1}, {kWW, 1}}) + m(-1, 3, {{kPa, 1}, {kWC, 1}, {kYb, 1}}) +
           m(-1, 3, {{kPb, 1}, {kCW, 1}, {kYa, 1}}) + m(1, 9, {{kCC, 1}, {kYa, 1}, {kYb, 1}});
  }
  // Rank 2: (c_a c_a)°:(c_b c_b)° = (c_a·c_b)² − X_a X_b/3, and T2 = P (cŵ)°_sym − (Y/3)(cc)°.
  const DotPolynomial cc_cc = m(1, 1, {{kCC, 2}}) + m(-1, 3, {{kXa, 1}, {kXb, 1}});
  const DotPolynomial cc_t1 = m(1, 1, {{kCW, 2}}) + m(-1, 3, {{kXa, 1}, {kYb, 1}});  // (c_a c_a)°:(ŵ_b ŵ_b)°
  const DotPolynomial t1_cc = m(1, 1, {{kWC, 2}}) + m(-1, 3, {{kYa, 1}, {kXb, 1}});
  const DotPolynomial t1_t1 = m(1, 1, {{kWW, 2}}) + m(-1, 3, {{kYa, 1}, {kYb, 1}});
  // (c_a c_a)°:(c_b ŵ_b)_sym = (c_a·c_b)(c_a·ŵ_b) − X_a P_b/3, and the like.
  const DotPolynomial cc_cw = m(1, 1, {{kCC, 1}, {kCW, 1}}) + m(-1, 3, {{kXa, 1}, {kPb, 1}});
  const DotPolynomial cw_cc = m(1, 1, {{kCC, 1}, {kWC, 1}}) + m(-1, 3, {{kXb, 1}, {kPa, 1}});
  const DotPolynomial t1_cw = m(1, 1, {{kWC, 1}, {kWW, 1}}) + m(-1, 3, {{kYa, 1}, {kPb, 1}});
  const DotPolynomial cw_t1 = m(1, 1, {{kCW, 1}, {kWW, 1}}) + m(-1, 3, {{kYb, 1}, {kPa, 1}});
  const DotPolynomial cw_cw =
      m(1, 2, {{kCC, 1}, {kWW, 1}}) + m(1, 2, {{kCW, 1}, {kWC, 1}}) + m(-1, 3, {{kPa, 1}, {kPb, 1}});
  const DotPolynomial pa = m(1, 1, {{kPa, 1}}), pb = m(1, 1, {{kPb, 1}});
  const DotPolynomial ya = m(-1, 3, {{kYa, 1}}), yb = m(-1, 3, {{kYb, 1}});
  // T2_b = P_b (c_b ŵ_b)° + (−Y_b/3)(c_b c_b)°, likewise T2_a.
  const auto with_t2_b = [&](const DotPolynomial& x_cw, const DotPolynomial& x_cc) { return pb * x_cw + yb * x_cc; };
  const auto with_t2_a = [&](const DotPolynomial& cw_x, const DotPolynomial& cc_x) { return pa * cw_x + ya * cc_x; };
  if (kind_a == 0 && kind_b == 0) return cc_cc;
  if (kind_a == 0 && kind_b == 1) return cc_t1;
  if (kind_a == 1 && kind_b == 0) return t1_cc;
  if (kind_a == 1 && kind_b == 1) return t1_t1;
  if (kind_a == 0 && kind_b == 2) return with_t2_b(cc_cw, cc_cc);
  if (kind_a == 2 && kind_b == 0) return with_t2_a(cw_cc, cc_cc);
  if (kind_a == 1 && kind_b == 2) return with_t2_b(t1_cw, t1_cc);
  if (kind_a == 2 && kind_b == 1) return with_t2_a(cw_t1, cc_t1);
  return pa * with_t2_b(cw_cw, cw_cc) + ya * with_t2_b(cc_cw, cc_cc);
}

/// Returns Σ s_i X^i Σ l_j Y^j on slot a (or b).
DotPolynomial multiplier(const std::vector<Rational>& s, const std::vector<Rational>& l, bool slot_a) {
  DotPolynomial out;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = 0; j < l.size(); ++j) {
      if (s[i].is_zero() || l[j].is_zero()) continue;
      Exponents e{};
      e[slot_a ? kXa : kXb] = static_cast<int>(i);
      e[slot_a ? kYa : kYb] = static_cast<int>(j);
      out[e] += s[i] * l[j];
    }
  return out;
}

int spin_degree(const Exponents& e) { return 2 * e[kYa] + 2 * e[kYb] + e[kPa] + e[kPb] + e[kCW] + e[kWC] + 2 * e[kWW]; }

/// Returns the same monomial on one slot (a = b = 1, the loss term ⟨ψ(1)φ(1)⟩): exponents of X, Y, P.
std::array<int, 3> on_one_slot(const Exponents& e) {
  return {e[kXa] + e[kXb] + e[kCC], e[kYa] + e[kYb] + e[kWW], e[kPa] + e[kPb] + e[kCW] + e[kWC]};
}

/// Returns the degree in C_b = (c_b, ŵ_b) of a monomial (the test function's; C·∂_C multiplies by it).
int test_degree(const Exponents& e) { return 2 * e[kXb] + 2 * e[kYb] + 2 * e[kPb] + e[kCC] + e[kCW] + e[kWC] + e[kWW]; }

/// Returns ⟨X^i Y^j P^k⟩ over the Maxwellians e^{−c²}, e^{−ŵ²} (3D): ⟨x^{i+n}⟩⟨y^{j+n}⟩/(2n + 1) for k = 2n, 0 for odd
/// k (theory.md (19.48)).
Rational maxwell_average(const std::array<int, 3>& e) {
  if (e[2] % 2 != 0) return Rational(0);
  const int n = e[2] / 2;
  return Rational::rising_half(3, static_cast<unsigned long>(e[0] + n)) *
         Rational::rising_half(3, static_cast<unsigned long>(e[1] + n)) *
         Rational(1, static_cast<unsigned long>(2 * n + 1));
}

constexpr int kCross = 6;  // P_a, P_b, c_a·c_b, c_a·ŵ_b, ŵ_a·c_b, ŵ_a·ŵ_b
constexpr std::array<Invariant, kCross> kCrossInvariants{kPa, kPb, kCC, kCW, kWC, kWW};
using CrossKey = std::array<int, kCross>;

/// One slot pair's averages ⟨Π invariants⟩/⟨1⟩: one engine table per set of cross exponents, with X_a, Y_a, X_b,
/// Y_b as the last four forms.
class PairAverages {
 public:
  PairAverages(S va, S wa, S vb, S wb) : va_(va), wa_(wa), vb_(vb), wb_(wb) {}
  void request(const Exponents& e) {
    CrossKey key{};
    for (int v = 0; v < kCross; ++v) key[v] = e[kCrossInvariants[v]];
    auto& box = boxes_[key];
    box[0] = std::max(box[0], e[kXa]);
    box[1] = std::max(box[1], e[kYa]);
    box[2] = std::max(box[2], e[kXb]);
    box[3] = std::max(box[3], e[kYb]);
    box[4] = std::max(box[4], e[kXa] + e[kYa]);
    box[5] = std::max(box[5], e[kXb] + e[kYb]);
  }
  void build(const RoughCollisionParameters<RationalPolynomial>& p) {
    const std::array<RoughForm, kCross> cross{rough_dot_form(va_, wa_), rough_dot_form(vb_, wb_),
                                              rough_dot_form(va_, vb_), rough_dot_form(va_, wb_),
                                              rough_dot_form(wa_, vb_), rough_dot_form(wa_, wb_)};
    for (const auto& [key, box] : boxes_) {
      std::vector<RoughForm> forms;
      std::vector<int> degrees;
      for (int v = 0; v < kCross; ++v)
        if (key[v] > 0) {
          forms.push_back(cross[static_cast<std::size_t>(v)]);
          degrees.push_back(key[v]);
        }
      const std::size_t n = forms.size();
      for (const auto& [x, y] : {std::pair{va_, wa_}, std::pair{vb_, wb_}}) {
        forms.push_back(rough_dot_form(x, x));
        forms.push_back(rough_dot_form(y, y));
      }
      for (int k = 0; k < 4; ++k) degrees.push_back(box[static_cast<std::size_t>(k)]);
      const int ta = box[4], tb = box[5];
      tables_.emplace(key, std::make_pair(n, RoughCollisionMoments<RationalPolynomial>(
                                                 p, forms, degrees, [n, ta, tb](const RoughExponents& e) {
                                                   return e[n] + e[n + 1] <= ta && e[n + 2] + e[n + 3] <= tb;
                                                 })));
    }
  }
  [[nodiscard]] RationalPolynomial average(const Exponents& e) const {
    CrossKey key{};
    for (int v = 0; v < kCross; ++v) key[v] = e[kCrossInvariants[v]];
    const auto& [n, table] = tables_.at(key);
    RoughExponents k{};
    std::size_t slot = 0;
    for (int v = 0; v < kCross; ++v)
      if (key[v] > 0) k[slot++] = key[v];
    k[n] = e[kXa];
    k[n + 1] = e[kYa];
    k[n + 2] = e[kXb];
    k[n + 3] = e[kYb];
    return table.moment(k);
  }

 private:
  S va_, wa_, vb_, wb_;
  std::map<CrossKey, std::array<int, 6>> boxes_;
  std::map<CrossKey, std::pair<std::size_t, RoughCollisionMoments<RationalPolynomial>>> tables_;
};

struct Function {
  int kind = 0;                ///< 0 product, 1 and 2 aligned
  std::vector<Rational> s, l;  ///< the product's Sonine multipliers (kind 0)
};

}  // namespace

RoughAlignedFamilyElements::RoughAlignedFamilyElements(const RoughCollisionParameters<RationalPolynomial>& parameters,
                                                       int highest_order, int aligned_order)
    : k_(highest_order), members_(aligned_order * (aligned_order + 1) / 2) {
  const int d = parameters.dimension;
  if (d != 3)
    throw std::invalid_argument("dimension: the aligned-spin families need dimension = 3 (c.w = 0 for disks)");
  if (highest_order < 1) throw std::invalid_argument("order: must be an integer >= 1");
  if (aligned_order < 1) throw std::invalid_argument("aligned_order: must be an integer >= 1");
  // The functions of each rank: products (p, q), p + q ≤ top, in the order of index(), then the aligned families.
  std::array<std::vector<Function>, 3> functions;
  for (int rank = 0; rank <= 2; ++rank) {
    const int top = rank == 2 ? k_ - 1 : k_;
    for (int p = 0; p <= top; ++p)
      for (int q = 0; p + q <= top; ++q) {
        const RoughTrialFunction f = rough_sonine_function(d, rank, p, q);
        functions[static_cast<std::size_t>(rank)].push_back({0, f.s, f.l});
      }
    for (int k = 1; k <= (rank == 2 ? 2 : 1); ++k)
      for (int p = 0; p < aligned_order; ++p)
        for (int q = 0; p + q < aligned_order; ++q) {
          const RoughTrialFunction f = rough_sonine_function(d, rank, p, q);
          functions[static_cast<std::size_t>(rank)].push_back({k, f.s, f.l});
        }
    size_[static_cast<std::size_t>(rank)] = static_cast<int>(functions[static_cast<std::size_t>(rank)].size());
  }
  // ⟨φ, 𝓛ψ⟩ = ⟨ψ(1)φ(1)⟩ − ⟨ψ(1)φ(1')⟩ + ⟨ψ(2)φ(1)⟩ − ⟨ψ(2)φ(1')⟩ (theory.md (5.2)), each the average of the
  // contraction polynomial of trial (slot a) and test (slot b). Pass 1: the polynomials and the table boxes.
  PairAverages post(S::v1, S::w1, S::v1_post, S::w1_post), other(S::v2, S::w2, S::v1, S::w1),
      other_post(S::v2, S::w2, S::v1_post, S::w1_post);
  std::array<int, 3> self_box{};
  std::array<std::vector<DotPolynomial>, 3> polys;
  for (int rank = 0; rank <= 2; ++rank) {
    const auto& fs = functions[static_cast<std::size_t>(rank)];
    for (const Function& test : fs)
      for (const Function& trial : fs) {
        DotPolynomial poly = contraction(rank, trial.kind, test.kind);
        poly = poly * multiplier(trial.s, trial.l, true);
        poly = poly * multiplier(test.s, test.l, false);
        if (trial.kind > 0 && test.kind > 0) {  // N and G of the aligned block over the Maxwellians, exact
          Rational n(0), g(0);
          for (const auto& [e, c] : poly) {
            const Rational m = maxwell_average(on_one_slot(e));
            n += c * m;
            g += c * m * Rational(test_degree(e));
          }
          product_[static_cast<std::size_t>(rank)].push_back(n.to_double());
          scaling_[static_cast<std::size_t>(rank)].push_back(g.to_double());
        }
        for (const auto& [e, c] : poly) {
          if (c.is_zero()) continue;
          shift_ = std::max(shift_, spin_degree(e));
          post.request(e);
          other.request(e);
          other_post.request(e);
          const auto one = on_one_slot(e);
          for (int v = 0; v < 3; ++v) self_box[static_cast<std::size_t>(v)] = std::max(self_box[v], one[v]);
        }
        polys[static_cast<std::size_t>(rank)].push_back(std::move(poly));
      }
  }
  // Pass 2: the tables, then every element exact in λ (times λ^shift: ŵ = w/λ), rounded once.
  post.build(parameters);
  other.build(parameters);
  other_post.build(parameters);
  const RoughCollisionMoments<RationalPolynomial> self(
      parameters, {rough_dot_form(S::v1, S::v1), rough_dot_form(S::w1, S::w1), rough_dot_form(S::v1, S::w1)},
      {self_box[0], self_box[1], self_box[2]});
  for (int rank = 0; rank <= 2; ++rank)
    for (const DotPolynomial& poly : polys[static_cast<std::size_t>(rank)]) {
      RationalPolynomial sum;
      for (const auto& [e, c] : poly) {
        if (c.is_zero()) continue;
        const auto one = on_one_slot(e);
        RationalPolynomial v = self.moment({one[0], one[1], one[2]});
        v -= post.average(e);
        v += other.average(e);
        v -= other_post.average(e);
        add_scaled(sum, shifted_by(v, shift_ - spin_degree(e)), c);
      }
      std::vector<long double> coefficients;
      for (long j = 0; j <= sum.degree(); ++j) coefficients.push_back(sum.coefficient(j).to_double());
      elements_[static_cast<std::size_t>(rank)].push_back(std::move(coefficients));
    }
}

int RoughAlignedFamilyElements::index(int rank, int p, int q) const {
  const int top = rank == 2 ? k_ - 1 : k_;
  if (p < 0) {
    if (q < 1 || q > count(rank)) throw std::out_of_range("RoughAlignedFamilyElements: no such aligned family");
    return size_[static_cast<std::size_t>(rank)] - count(rank) + q - 1;
  }
  if (q < 0 || p + q > top) throw std::out_of_range("RoughAlignedFamilyElements: Sonine index above the table");
  int i = 0;  // products ordered by p, then q ≤ top − p
  for (int pp = 0; pp < p; ++pp) i += top - pp + 1;
  return i + q;
}

double RoughAlignedFamilyElements::element(int rank, int p_test, int q_test, int p_trial, int q_trial,
                                           double tau) const {
  const auto r = static_cast<std::size_t>(rank);
  const auto& c =
      elements_[r][static_cast<std::size_t>(index(rank, p_test, q_test) * size_[r] + index(rank, p_trial, q_trial))];
  const long double lambda = std::sqrt(static_cast<long double>(tau));
  long double value = 0;
  for (std::size_t j = c.size(); j-- > 0;) value = value * lambda + c[j];
  return static_cast<double>(value * std::pow(lambda, -static_cast<long double>(shift_)));
}

int RoughAlignedFamilyElements::count(int rank) const { return (rank == 2 ? 2 : 1) * members_; }

double RoughAlignedFamilyElements::maxwell_product(int rank, int i, int j) const {
  const int n = count(rank);
  if (i < 1 || j < 1 || i > n || j > n) throw std::out_of_range("RoughAlignedFamilyElements: no such aligned function");
  return product_[static_cast<std::size_t>(rank)][static_cast<std::size_t>((i - 1) * n + j - 1)];
}

double RoughAlignedFamilyElements::maxwell_scaling_product(int rank, int i, int j) const {
  const int n = count(rank);
  if (i < 1 || j < 1 || i > n || j > n) throw std::out_of_range("RoughAlignedFamilyElements: no such aligned function");
  return scaling_[static_cast<std::size_t>(rank)][static_cast<std::size_t>((i - 1) * n + j - 1)];
}

}  // namespace gkt::detail
