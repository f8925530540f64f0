#include "transport/rough/rough_chiral_families.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "gkt/collision/rough_collision_moments.hpp"
#include "gkt/collision/rough_collision_rule.hpp"
#include "gkt/collision/rough_triple_product_moments.hpp"
#include "transport/rough/rough_sonine_systems.hpp"

namespace gkt::detail {

namespace {

using S = RoughSlot;

/// The four vectors of a slot pair (a the trial's, b the test's) and their ten dot products.
enum Vector { kCa, kWa, kCb, kWb };
enum Invariant { kXa, kYa, kPa, kXb, kYb, kPb, kCC, kCW, kWC, kWW, kInvariants };
/// Exponents of the ten dot products, then the triple product (0 none, m + 1 the triple of the three vectors other
/// than m, in increasing order).
using Key = std::array<int, kInvariants + 1>;
using Poly = std::map<Key, Rational>;

Invariant dot_invariant(int i, int j) {
  if (i > j) std::swap(i, j);
  static constexpr std::array<std::array<Invariant, 4>, 4> table{
      {{kXa, kPa, kCC, kCW}, {kPa, kYa, kWC, kWW}, {kCC, kWC, kXb, kPb}, {kCW, kWW, kPb, kYb}}};
  return table[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
}

Poly constant(const Rational& c) { return {{Key{}, c}}; }
Poly dot(int i, int j) {
  Key k{};
  k[dot_invariant(i, j)] = 1;
  return {{k, Rational(1)}};
}
/// Returns u·(x × y) as ± the canonical triple (0 for a repeated vector).
Poly triple(int u, int x, int y) {
  std::array<int, 3> v{u, x, y};
  if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) return {};
  int sign = 1;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j + 1 < 3 - i; ++j)
      if (v[static_cast<std::size_t>(j)] > v[static_cast<std::size_t>(j) + 1]) {
        std::swap(v[static_cast<std::size_t>(j)], v[static_cast<std::size_t>(j) + 1]);
        sign = -sign;
      }
  Key k{};
  k[kInvariants] = 6 - v[0] - v[1] - v[2] + 1;
  return {{k, Rational(sign)}};
}
std::array<int, 3> triple_vectors(int code) {
  std::array<int, 3> v{};
  std::size_t n = 0;
  for (int i = 0; i < 4; ++i)
    if (i != code - 1) v[n++] = i;
  return v;
}

Poly operator+(Poly a, const Poly& b) {
  for (const auto& [k, c] : b) a[k] += c;
  return a;
}
Poly scaled(Poly a, const Rational& c) {
  for (auto& [k, x] : a) x *= c;
  return a;
}
Poly operator*(const Poly& a, const Poly& b);

/// Returns t(A, B, C) t(D, E, F) = det[dot products] (the Gram determinant, theory.md (19.94)).
Poly gram(int code_a, int code_b) {
  const auto u = triple_vectors(code_a), v = triple_vectors(code_b);
  Poly out;
  std::array<int, 3> perm{0, 1, 2};
  do {
    int inversions = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j)
        if (perm[static_cast<std::size_t>(i)] > perm[static_cast<std::size_t>(j)]) ++inversions;
    Poly term = constant(Rational(inversions % 2 == 0 ? 1 : -1));
    for (std::size_t i = 0; i < 3; ++i) term = term * dot(u[i], v[static_cast<std::size_t>(perm[i])]);
    out = out + term;
  } while (std::next_permutation(perm.begin(), perm.end()));
  return out;
}

Poly operator*(const Poly& a, const Poly& b) {
  Poly out;
  for (const auto& [ka, ca] : a)
    for (const auto& [kb, cb] : b) {
      Key k{};
      for (int v = 0; v < kInvariants; ++v) k[static_cast<std::size_t>(v)] = ka[v] + kb[v];
      if (ka[kInvariants] != 0 && kb[kInvariants] != 0) {
        for (const auto& [kg, cg] : gram(ka[kInvariants], kb[kInvariants])) {
          Key e = k;
          for (int v = 0; v < kInvariants; ++v) e[static_cast<std::size_t>(v)] += kg[v];
          out[e] += ca * cb * cg;
        }
        continue;
      }
      k[kInvariants] = ka[kInvariants] + kb[kInvariants];
      out[k] += ca * cb;
    }
  return out;
}

/// A vector of a slot: a plain vector or the cross product x × y.
struct Item {
  bool cross = false;
  int x = 0, y = 0;
};
Poly dot(const Item& p, const Item& q) {
  if (!p.cross && !q.cross) return dot(p.x, q.x);
  if (!p.cross) return triple(p.x, q.x, q.y);
  if (!q.cross) return triple(q.x, p.x, p.y);
  return dot(p.x, q.x) * dot(p.y, q.y) + scaled(dot(p.x, q.y) * dot(p.y, q.x), Rational(-1));
}

/// A family: Σ coefficient · item (rank 1), Σ coefficient · (item item')_sym (rank 2, its traceless part), or a scalar.
struct Family {
  std::vector<std::pair<Poly, Item>> vector;
  std::vector<std::tuple<Poly, Item, Item>> tensor;
  Poly scalar;
  bool chiral = false;
  bool product = false;
};

/// Returns Σ s_i X^i Σ l_j Y^j on the slot (X = c·c, Y = ŵ·ŵ).
Poly multiplier(const std::vector<Rational>& s, const std::vector<Rational>& l, const Poly& x, const Poly& y) {
  Poly sx, ly, power = constant(Rational(1));
  for (const Rational& c : s) {
    sx = sx + scaled(power, c);
    power = power * x;
  }
  power = constant(Rational(1));
  for (const Rational& c : l) {
    ly = ly + scaled(power, c);
    power = power * y;
  }
  return sx * ly;
}

/// Returns f with every coefficient multiplied by m.
Family times(Family f, const Poly& m) {
  for (auto& [c, i] : f.vector) c = c * m;
  for (auto& [c, i, j] : f.tensor) c = c * m;
  if (!f.scalar.empty()) f.scalar = f.scalar * m;
  return f;
}

/// Returns the functions of RoughTrialSpace::full of rank r on slot a (first) or b: products of p + q ≤ top, then by
/// member level m = 1 … members the aligned families (3D) and the lowest chiral families times S_p L_q of
/// p + q = m − 1, and (3D) (cc)° P, c P times S_p L_q of p + q = m − 2 (theory.md §19.22, (19.150), (19.152));
/// `level` receives each appended function's m.
std::vector<Family> full_functions(int d, int rank, bool first, int top, int members, std::vector<int>* level) {
  const int c = first ? kCa : kCb, w = first ? kWa : kWb;
  const Item ci{false, c, c}, wi{false, w, w}, cw{true, c, w};
  const Poly x = dot(c, c), y = dot(w, w), p = dot(c, w), one = constant(Rational(1));
  std::vector<Family> out;
  const auto member = [&](int pp, int qq) {
    const RoughTrialFunction f = rough_sonine_function(d, rank, pp, qq);
    return multiplier(f.s, f.l, x, y);
  };
  Family t_r;
  if (rank == 2) t_r.tensor = {{one, ci, ci}};
  if (rank == 1) t_r.vector = {{one, ci}};
  if (rank == 0) t_r.scalar = one;
  for (int pp = 0; pp <= top; ++pp)
    for (int qq = 0; pp + qq <= top; ++qq) {
      Family f = times(t_r, member(pp, qq));
      f.product = true;
      out.push_back(std::move(f));
    }
  std::vector<Family> bases;
  if (d == 3) {
    if (rank == 2) {
      bases.push_back({{}, {{one, wi, wi}}, {}, false, false});
      bases.push_back({{}, {{p, ci, wi}, {scaled(y, Rational(-1, 3)), ci, ci}}, {}, false, false});
    } else if (rank == 1) {
      bases.push_back({{{p, wi}, {scaled(y, Rational(-1, 3)), ci}}, {}, {}, false, false});
    } else {
      bases.push_back({{}, {}, p * p + scaled(x * y, Rational(-1, 3)), false, false});
    }
  }
  // The p² dependence of the products' tensor and vector: (cc)° P, c P with P = p² − xy/3 (orthogonal to every
  // product: P averages to 0 over the direction of ŵ), members from level 2 on (theory.md (19.152)).
  const Poly pp2 = p * p + scaled(x * y, Rational(-1, 3));
  std::vector<Family> later;
  if (d == 3 && rank == 2) later.push_back({{}, {{pp2, ci, ci}}, {}, false, false});
  if (d == 3 && rank == 1) later.push_back({{{pp2, ci}}, {}, {}, false, false});
  if (rank == 2 && d == 3) {
    bases.push_back({{}, {{one, ci, cw}}, {}, true, false});
    bases.push_back({{}, {{p, wi, cw}}, {}, true, false});
  } else if (rank == 2) {
    bases.push_back({{}, {{scaled(one, Rational(-1)), ci, cw}}, {}, true, false});
  } else if (rank == 1) {
    bases.push_back({{{scaled(one, Rational(d == 3 ? 1 : -1)), cw}}, {}, {}, true, false});
  }
  for (int m = 1; m <= members; ++m) {
    for (const Family& f : bases)
      for (int pp = 0; pp < m; ++pp) {
        out.push_back(times(f, member(pp, m - 1 - pp)));
        if (level != nullptr) level->push_back(m);
      }
    for (const Family& f : later)
      for (int pp = 0; pp < m - 1; ++pp) {
        out.push_back(times(f, member(pp, m - 2 - pp)));
        if (level != nullptr) level->push_back(m);
      }
  }
  return out;
}

/// Returns the families of rank r on slot a (first = true) or b, in gkt_rough_trial_families_mc's order.
std::vector<Family> families(int d, int rank, bool first) {
  const int c = first ? kCa : kCb, w = first ? kWa : kWb;
  const Item ci{false, c, c}, wi{false, w, w}, cw{true, c, w};
  const Poly x = dot(c, c), y = dot(w, w), p = dot(c, w), one = constant(Rational(1));
  const Rational dr(d == 3 ? 3 : 1);
  std::vector<Family> out;
  if (rank == 2) {
    out.push_back({{}, {{one, ci, ci}}, {}, false});
    if (d == 3) {
      out.push_back({{}, {{one, wi, wi}}, {}, false});
      out.push_back({{}, {{p, ci, wi}, {scaled(y, Rational(-1, 3)), ci, ci}}, {}, false});
      out.push_back({{}, {{one, ci, cw}}, {}, true});
      out.push_back({{}, {{p, wi, cw}}, {}, true});
    } else {
      out.push_back({{}, {{scaled(one, Rational(-1)), ci, cw}}, {}, true});  // ŵ(c c⊥)_sym = −(c(c × ŵẑ))_sym
    }
  } else if (rank == 1) {
    out.push_back({{{x + constant(Rational(-(d + 2), 2)), ci}}, {}, {}, false});
    out.push_back({{{y + constant(-dr / Rational(2)), ci}}, {}, {}, false});
    if (d == 3) {
      out.push_back({{{p, wi}, {scaled(y, Rational(-1, 3)), ci}}, {}, {}, false});
      out.push_back({{{one, cw}}, {}, {}, true});
    } else {
      out.push_back({{{scaled(one, Rational(-1)), cw}}, {}, {}, true});  // ŵ c⊥ = −c × ŵẑ
    }
  } else {
    out.push_back({{}, {}, x + constant(Rational(-d, 2)), false});
    out.push_back({{}, {}, y + constant(-dr / Rational(2)), false});
    if (d == 3) out.push_back({{}, {}, p * p + scaled(x * y, Rational(-1, 3)), false});
  }
  return out;
}

/// Returns trial (slot a) contracted with test (slot b).
Poly contraction(int d, int rank, const Family& a, const Family& b) {
  if (rank == 0) return a.scalar * b.scalar;
  Poly out;
  if (rank == 1) {
    for (const auto& [ca, ia] : a.vector)
      for (const auto& [cb, ib] : b.vector) out = out + ca * cb * dot(ia, ib);
    return out;
  }
  Poly trace_a, trace_b;
  for (const auto& [ca, ia, ja] : a.tensor) {
    trace_a = trace_a + ca * dot(ia, ja);
    for (const auto& [cb, ib, jb] : b.tensor)
      out = out + scaled(ca * cb * (dot(ia, ib) * dot(ja, jb) + dot(ia, jb) * dot(ja, ib)), Rational(1, 2));
  }
  for (const auto& [cb, ib, jb] : b.tensor) trace_b = trace_b + cb * dot(ib, jb);
  return out + scaled(trace_a * trace_b, Rational(-1, d));
}

int spin_degree(const Key& e) {
  int n = 2 * e[kYa] + 2 * e[kYb] + e[kPa] + e[kPb] + e[kCW] + e[kWC] + 2 * e[kWW];
  if (e[kInvariants] != 0)
    for (const int v : triple_vectors(e[kInvariants])) n += v % 2;
  return n;
}
int test_degree(const Key& e) {
  int n = 2 * e[kXb] + 2 * e[kYb] + 2 * e[kPb] + e[kCC] + e[kCW] + e[kWC] + e[kWW];
  if (e[kInvariants] != 0)
    for (const int v : triple_vectors(e[kInvariants])) n += v >= 2 ? 1 : 0;
  return n;
}
/// The same monomial on one particle (a = b): exponents of X, Y, P; a triple product of it vanishes.
std::array<int, 3> on_one_slot(const Key& e) {
  return {e[kXa] + e[kXb] + e[kCC], e[kYa] + e[kYb] + e[kWW], e[kPa] + e[kPb] + e[kCW] + e[kWC]};
}
/// Returns ⟨X^i Y^j P^k⟩ over e^{−c²} e^{−ŵ²}: 3D ⟨x^{i+n}⟩⟨y^{j+n}⟩/(2n + 1) for k = 2n (theory.md (19.48)); 2D P = 0.
Rational maxwell_average(int d, const std::array<int, 3>& e) {
  if (e[2] % 2 != 0 || (d == 2 && e[2] != 0)) return Rational(0);
  const int n = e[2] / 2;
  return Rational::rising_half(d, static_cast<unsigned long>(e[0] + n)) *
         Rational::rising_half(d == 3 ? 3 : 1, static_cast<unsigned long>(e[1] + n)) *
         Rational(1, static_cast<unsigned long>(2 * n + 1));
}

bool vanishes_for_disks(const Key& e) {
  if (e[kPa] + e[kPb] + e[kCW] + e[kWC] > 0) return true;
  if (e[kInvariants] == 0) return false;
  int spins = 0;
  for (const int v : triple_vectors(e[kInvariants])) spins += v % 2;
  return spins != 1;
}

/// Averages of one slot pair's monomials: one engine table per (cross exponents, triple), X_a, Y_a, X_b, Y_b last.
class PairAverages {
 public:
  PairAverages(S va, S wa, S vb, S wb) : slots_{va, wa, vb, wb} {}
  RationalPolynomial average(const RoughCollisionParameters<RationalPolynomial>& p, const Key& e) {
    static constexpr std::array<Invariant, 6> cross{kPa, kPb, kCC, kCW, kWC, kWW};
    static constexpr std::array<Invariant, 4> own{kXa, kYa, kXb, kYb};
    std::vector<RoughForm> forms;
    std::vector<int> degrees;
    const auto form = [this](Invariant v) {
      for (int i = 0; i < 4; ++i)
        for (int j = i; j < 4; ++j)
          if (dot_invariant(i, j) == v)
            return rough_dot_form(slots_[static_cast<std::size_t>(i)], slots_[static_cast<std::size_t>(j)]);
      throw std::logic_error("RoughChiralFamilyElements: no such invariant");
    };
    for (const Invariant v : cross)
      if (e[v] > 0) {
        forms.push_back(form(v));
        degrees.push_back(e[v]);
      }
    for (const Invariant v : own)
      if (e[v] > 0) {
        forms.push_back(form(v));
        degrees.push_back(e[v]);
      }
    RoughExponents k{};
    for (std::size_t i = 0; i < degrees.size(); ++i) k[i] = degrees[i];
    const int code = e[kInvariants];
    if (code == 0) return RoughCollisionMoments<RationalPolynomial>(p, forms, degrees).moment(k);
    const auto v = triple_vectors(code);
    const RoughTripleProduct t{slots_[static_cast<std::size_t>(v[0])], slots_[static_cast<std::size_t>(v[1])],
                               slots_[static_cast<std::size_t>(v[2])]};
    return RoughTripleProductMoments<RationalPolynomial>(p, t, forms, degrees).moment(k);
  }

 private:
  std::array<S, 4> slots_;
};

}  // namespace

RoughChiralFamilyElements::RoughChiralFamilyElements(int dimension, const Rational& alpha, const Rational& beta,
                                                     const Rational& kappa)
    : RoughChiralFamilyElements(dimension, alpha, beta, kappa, 0, 1) {}

RoughChiralFamilyElements::RoughChiralFamilyElements(int dimension, const Rational& alpha, const Rational& beta,
                                                     const Rational& kappa, int highest_order, int aligned_order)
    : dimension_(dimension), highest_order_(highest_order) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  if (highest_order < 0) throw std::invalid_argument("order: must be an integer >= 1");
  if (aligned_order < 1) throw std::invalid_argument("aligned_order: must be an integer >= 1");
  const auto parameters = rough_parameters_symbolic_temperature(dimension, alpha, beta, kappa);
  const int d = dimension;
  const bool full = highest_order > 0;
  PairAverages post(S::v1, S::w1, S::v1_post, S::w1_post), other(S::v2, S::w2, S::v1, S::w1),
      other_post(S::v2, S::w2, S::v1_post, S::w1_post);
  std::array<std::vector<Poly>, 3> polys;
  for (int rank = 0; rank <= 2; ++rank) {
    const auto r = static_cast<std::size_t>(rank);
    const int top = rank == 2 ? highest_order - 1 : highest_order;
    const auto trials = full ? full_functions(d, rank, true, top, aligned_order, &level_[r]) : families(d, rank, true);
    const auto tests = full ? full_functions(d, rank, false, top, aligned_order, nullptr) : families(d, rank, false);
    count_[r] = static_cast<int>(trials.size());
    for (const Family& f : trials) {
      chiral_[r].push_back(f.chiral);
      if (full && f.product) ++products_[r];
    }
    for (const Family& test : tests)
      for (const Family& trial : trials) {
        // RoughTrialSpace::full: the product block comes from RoughCollisionElements.
        Poly poly = full && test.product && trial.product ? Poly{} : contraction(d, rank, trial, test);
        Rational n(0), g(0);
        for (const auto& [e, c] : poly) {
          if (c.is_zero()) continue;
          shift_ = std::max(shift_, spin_degree(e));
          if (e[kInvariants] != 0) continue;
          const Rational m = maxwell_average(d, on_one_slot(e));
          n += c * m;
          g += c * m * Rational(test_degree(e));
        }
        product_[r].push_back(n.to_double());
        scaling_[r].push_back(g.to_double());
        polys[r].push_back(std::move(poly));
      }
  }
  // ⟨φ, 𝓛ψ⟩ = ⟨ψ(1)φ(1)⟩ − ⟨ψ(1)φ(1')⟩ + ⟨ψ(2)φ(1)⟩ − ⟨ψ(2)φ(1')⟩; the loss term of a triple product vanishes.
  std::map<Key, std::pair<RationalPolynomial, bool>> cache;
  for (int rank = 0; rank <= 2; ++rank)
    for (const Poly& poly : polys[static_cast<std::size_t>(rank)]) {
      RationalPolynomial even, odd;
      for (const auto& [e, c] : poly) {
        if (c.is_zero() || (d == 2 && vanishes_for_disks(e))) continue;
        auto it = cache.find(e);
        if (it == cache.end()) {
          RationalPolynomial v;
          if (e[kInvariants] == 0) {
            const auto one = on_one_slot(e);
            if (d == 3)
              v = RoughCollisionMoments<RationalPolynomial>(
                      parameters,
                      {rough_dot_form(S::v1, S::v1), rough_dot_form(S::w1, S::w1), rough_dot_form(S::v1, S::w1)},
                      {one[0], one[1], one[2]})
                      .moment({one[0], one[1], one[2]});
            else
              v = RoughCollisionMoments<RationalPolynomial>(
                      parameters, {rough_dot_form(S::v1, S::v1), rough_dot_form(S::w1, S::w1)}, {one[0], one[1]})
                      .moment({one[0], one[1]});
          }
          v -= post.average(parameters, e);
          v += other.average(parameters, e);
          v -= other_post.average(parameters, e);
          it = cache.emplace(e, std::make_pair(shifted_by(v, shift_ - spin_degree(e)), e[kInvariants] != 0)).first;
        }
        add_scaled(it->second.second ? odd : even, it->second.first, c);
      }
      even_[static_cast<std::size_t>(rank)].push_back(std::move(even));
      odd_[static_cast<std::size_t>(rank)].push_back(std::move(odd));
    }
}

std::size_t RoughChiralFamilyElements::at(int rank, int i, int j) const {
  if (rank < 0 || rank > 2) throw std::out_of_range("RoughChiralFamilyElements: rank must be 0, 1 or 2");
  const int n = size(rank);
  if (i < 0 || j < 0 || i >= n || j >= n) throw std::out_of_range("RoughChiralFamilyElements: no such family");
  return static_cast<std::size_t>(i * n + j);
}

int RoughChiralFamilyElements::size(int rank) const {
  if (rank < 0 || rank > 2) throw std::out_of_range("RoughChiralFamilyElements: rank must be 0, 1 or 2");
  return count_[static_cast<std::size_t>(rank)];
}

int RoughChiralFamilyElements::count(int rank) const { return size(rank) - products_[static_cast<std::size_t>(rank)]; }

int RoughChiralFamilyElements::count_up_to(int rank, int members) const {
  if (rank < 0 || rank > 2) throw std::out_of_range("RoughChiralFamilyElements: rank must be 0, 1 or 2");
  const auto& level = level_[static_cast<std::size_t>(rank)];
  if (level.empty()) return count(rank);
  return static_cast<int>(std::count_if(level.begin(), level.end(), [members](int m) { return m <= members; }));
}

bool RoughChiralFamilyElements::chiral(int rank, int i) const {
  return chiral_[static_cast<std::size_t>(rank)][at(rank, i, 0) / static_cast<std::size_t>(size(rank))];
}

int RoughChiralFamilyElements::function_index(int rank, int p, int q) const {
  if (p < 0) {
    if (q < 1 || q > count(rank)) throw std::out_of_range("RoughChiralFamilyElements: no such appended function");
    return products_[static_cast<std::size_t>(rank)] + q - 1;
  }
  const int top = rank == 2 ? highest_order_ - 1 : highest_order_;
  if (q < 0 || p + q > top) throw std::out_of_range("RoughChiralFamilyElements: Sonine index above the table");
  int i = 0;  // products ordered by p, then q ≤ top − p (as RoughAlignedFamilyElements)
  for (int pp = 0; pp < p; ++pp) i += top - pp + 1;
  return i + q;
}

double RoughChiralFamilyElements::element(int rank, int p_test, int q_test, int p_trial, int q_trial,
                                          double tau) const {
  return element(rank, function_index(rank, p_test, q_test), function_index(rank, p_trial, q_trial), tau);
}

double RoughChiralFamilyElements::maxwell_product(int rank, int i, int j) const {
  return maxwell_product_at(rank, function_index(rank, -1, i), function_index(rank, -1, j));
}

double RoughChiralFamilyElements::maxwell_scaling_product(int rank, int i, int j) const {
  return maxwell_scaling_product_at(rank, function_index(rank, -1, i), function_index(rank, -1, j));
}

double RoughChiralFamilyElements::element(int rank, int test, int trial, double tau) const {
  const std::size_t k = at(rank, test, trial);
  const long double lambda = std::sqrt(static_cast<long double>(tau));
  const auto horner = [lambda](const RationalPolynomial& p) {
    long double value = 0;
    for (long j = p.degree(); j >= 0; --j) value = value * lambda + p.coefficient(j).to_double();
    return value;
  };
  const auto r = static_cast<std::size_t>(rank);
  const long double root = std::sqrt(std::numbers::pi_v<long double> / 2);
  const long double value = horner(even_[r][k]) + root * horner(odd_[r][k]);
  return static_cast<double>(value * std::pow(lambda, -static_cast<long double>(shift_)));
}

double RoughChiralFamilyElements::maxwell_product_at(int rank, int i, int j) const {
  return product_[static_cast<std::size_t>(rank)][at(rank, i, j)];
}

double RoughChiralFamilyElements::maxwell_scaling_product_at(int rank, int i, int j) const {
  return scaling_[static_cast<std::size_t>(rank)][at(rank, i, j)];
}

}  // namespace gkt::detail
