#include "gkt/transport/rough/rough_walton_sonine.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "gkt/algebra/sonine.hpp"
#include "transport/rough/rough_walton_elements.hpp"
#include "transport/rough/rough_walton_quadrature.hpp"

namespace gkt {

namespace {

/// The nine forms of the elements: x1 = c1², y1 = ŵ1², x2, y2, x1' = c1'², y1' = ŵ1'², and the dot products
/// c1·c1', c2·c1, c2·c1' (theory.md §19.20).
enum Form { kX1, kY1, kX2, kY2, kX1p, kY1p, kD11p, kD21, kD21p, kForms };

/// One form q = εᵀAε + (Bp)ᵀε + pᵀQp on the conditioned Gaussian ε ~ N(0, C), p = (u, G, H), H = η_t G.
struct QuadraticForm {
  Eigen::MatrixXd a, b;
  Eigen::Matrix3d q;
};

/// The moments of products of the nine forms at fixed τ, from their joint cumulants (theory.md (19.71), (19.80)):
/// each cumulant is a constant plus pᵀMp, computed once; a moment is Σ_{T ∋ first} κ(T) E[rest] over sub-multisets.
class ProductMoments {
 public:
  ProductMoments(int d, double tau, double eta_n, double kappa) {
    const detail::ConditionedGaussian g = detail::condition(d, tau);
    const int n = g.n, dr = d == 3 ? 3 : 1, w1 = 2 * d, w2 = 2 * d + dr;
    c_.resize(n, n);
    Eigen::MatrixXd gain = Eigen::MatrixXd::Zero(n, 3);
    for (int i = 0; i < n; ++i) {
      gain(i, 0) = g.gain[static_cast<std::size_t>(i)][0];
      gain(i, 1) = g.gain[static_cast<std::size_t>(i)][1];
      for (int j = 0; j < n; ++j) c_(i, j) = g.cov[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    }
    // A slot: selector L (k × n) and the collision's shift D (k × 3); its vector is L X − D p, X = gain p + ε.
    struct Slot {
      Eigen::MatrixXd l, shift;
    };
    const auto slot = [&](int first, int size) {
      Slot s{Eigen::MatrixXd::Zero(size, n), Eigen::MatrixXd::Zero(size, 3)};
      for (int k = 0; k < size; ++k) s.l(k, first + k) = 1;
      return s;
    };
    const Slot v1 = slot(0, d), v2 = slot(d, d), s1 = slot(w1, dr), s2 = slot(w2, dr);
    Slot v1p = v1, s1p = s1;
    v1p.shift(0, 0) = eta_n;                   // −η_n u σ̂ (σ̂ = e0)
    v1p.shift(1, 2) = 1;                       // −η_t G e1 = −H e1
    s1p.shift(d == 3 ? 2 : 0, 2) = 1 / kappa;  // −(H/κ) σ̂ × e1 (disks: the scalar)
    // q = (L_a ε + P_a p)ᵀ w (L_b ε + P_b p), P = L·gain − D.
    const auto form = [&](const Slot& x, const Slot& y, double w) {
      const Eigen::MatrixXd px = x.l * gain - x.shift, py = y.l * gain - y.shift;
      QuadraticForm f;
      f.a = 0.5 * w * (x.l.transpose() * y.l + y.l.transpose() * x.l);
      f.b = w * (y.l.transpose() * px + x.l.transpose() * py);
      const Eigen::Matrix3d q = w * px.transpose() * py;
      f.q = 0.5 * (q + q.transpose());
      return f;
    };
    forms_ = {form(v1, v1, 1),         form(s1, s1, 1 / tau), form(v2, v2, 1), form(s2, s2, 1 / tau), form(v1p, v1p, 1),
              form(s1p, s1p, 1 / tau), form(v1, v1p, 1),      form(v2, v1, 1), form(v2, v1p, 1)};
  }

  /// Registers the moment of a multiset of forms (any order); returns its index in evaluate()'s output.
  int moment(std::vector<int> forms) {
    std::sort(forms.begin(), forms.end());
    if (const auto it = moment_index_.find(forms); it != moment_index_.end()) return it->second;
    if (forms.empty()) {  // the empty product: 1 (no terms)
      moments_.emplace_back();
      return moment_index_[forms] = static_cast<int>(moments_.size()) - 1;
    }
    // Sub-multisets T containing forms[0]: counts t_f ≤ m_f, t_first ≥ 1; weight = the number of position subsets.
    std::array<int, kForms> mult{};
    for (int f : forms) ++mult[static_cast<std::size_t>(f)];
    const int first = forms[0];
    std::vector<Term> terms;
    std::array<int, kForms> take{};
    const auto binomial = [](int m, int k) {
      double r = 1;
      for (int i = 1; i <= k; ++i) r = r * (m - k + i) / i;
      return r;
    };
    const auto recurse = [&](auto&& self, int f) -> void {
      if (f == kForms) {
        if (take[static_cast<std::size_t>(first)] == 0) return;
        std::vector<int> t, rest;
        double count = 1;
        for (int g = 0; g < kForms; ++g) {
          const int m = mult[static_cast<std::size_t>(g)], k = take[static_cast<std::size_t>(g)];
          count *= g == first ? binomial(m - 1, k - 1) : binomial(m, k);
          for (int i = 0; i < k; ++i) t.push_back(g);
          for (int i = k; i < m; ++i) rest.push_back(g);
        }
        terms.push_back({count, cumulant(t), rest.empty() ? -1 : moment(rest)});
        return;
      }
      for (int k = 0; k <= mult[static_cast<std::size_t>(f)]; ++k) {
        take[static_cast<std::size_t>(f)] = k;
        self(self, f + 1);
      }
      take[static_cast<std::size_t>(f)] = 0;
    };
    recurse(recurse, 0);
    moments_.push_back(std::move(terms));
    return moment_index_[forms] = static_cast<int>(moments_.size()) - 1;
  }

  /// Fills `out` with every registered moment at p = (u, G, H).
  void evaluate(const Eigen::Vector3d& p, std::vector<double>& out) const {
    cumulant_values_.resize(constant_.size());
    for (std::size_t i = 0; i < constant_.size(); ++i) cumulant_values_[i] = constant_[i] + p.dot(quadratic_[i] * p);
    out.resize(moments_.size());
    for (std::size_t m = 0; m < moments_.size(); ++m) {
      double sum = moments_[m].empty() ? 1.0 : 0.0;
      for (const Term& t : moments_[m])
        sum += t.count * cumulant_values_[static_cast<std::size_t>(t.cumulant)] *
               (t.rest < 0 ? 1.0 : out[static_cast<std::size_t>(t.rest)]);
      out[m] = sum;
    }
  }

 private:
  struct Term {
    double count;
    int cumulant, rest;
  };

  /// Registers the joint cumulant of a sorted multiset: (19.71) with the linear terms Bp,
  ///   κ_1 = tr(AC) + pᵀQp,  κ_n = (2^{n−1}/n) Σ_orderings tr(A C ⋯ A C) + 2^{n−3} Σ_orderings (Bp)ᵀ C A C ⋯ A C (Bp),
  /// summed over the distinct orderings of the multiset, each counted Π m_f! times.
  int cumulant(const std::vector<int>& forms) {
    if (const auto it = cumulant_index_.find(forms); it != cumulant_index_.end()) return it->second;
    const std::size_t n = forms.size();
    double constant = 0;
    Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
    if (n == 1) {
      const QuadraticForm& f = forms_[static_cast<std::size_t>(forms[0])];
      constant = (f.a * c_).trace();
      m = f.q;
    } else {
      double repeats = 1;
      for (std::size_t i = 0, run = 1; i < n; ++i) {
        run = (i > 0 && forms[i] == forms[i - 1]) ? run + 1 : 1;
        repeats *= static_cast<double>(run);
      }
      const double trace_scale = std::ldexp(1.0, static_cast<int>(n) - 1) / static_cast<double>(n) * repeats;
      const double mean_scale = std::ldexp(1.0, static_cast<int>(n) - 3) * repeats;
      std::vector<int> s = forms;
      do {
        // Middle chain C A_s1 C ⋯ A_s(n−2) C; the trace closes it with A_s0 and A_s(n−1).
        Eigen::MatrixXd middle = c_;
        for (std::size_t i = 1; i + 1 < n; ++i) middle = middle * forms_[static_cast<std::size_t>(s[i])].a * c_;
        const QuadraticForm &head = forms_[static_cast<std::size_t>(s[0])],
                            &tail = forms_[static_cast<std::size_t>(s[n - 1])];
        constant += trace_scale * (head.a * middle * tail.a * c_).trace();
        m += mean_scale * head.b.transpose() * middle * tail.b;
      } while (std::next_permutation(s.begin(), s.end()));
    }
    constant_.push_back(constant);
    quadratic_.push_back(0.5 * (m + m.transpose()));
    return cumulant_index_[forms] = static_cast<int>(constant_.size()) - 1;
  }

  Eigen::MatrixXd c_;
  std::vector<QuadraticForm> forms_;
  std::map<std::vector<int>, int> cumulant_index_, moment_index_;
  std::vector<double> constant_;
  std::vector<Eigen::Matrix3d> quadratic_;
  std::vector<std::vector<Term>> moments_;
  mutable std::vector<double> cumulant_values_;
};

}  // namespace

namespace detail {

RoughCollisionElements rough_walton_collision_elements(int dimension, double alpha, double beta0, double kappa,
                                                       double friction, double tau, int highest_order, int panels) {
  check_walton_parameters(dimension, alpha, beta0, kappa, friction);
  if (!(tau > 0) || !std::isfinite(tau)) throw std::invalid_argument("temperature_ratio: must be > 0 and finite");
  if (highest_order < 1 || highest_order > kWaltonHighestOrder)
    throw std::invalid_argument("order: must be an integer in [1, " + std::to_string(kWaltonHighestOrder) + "]");
  if (panels < 1) throw std::invalid_argument("panels: must be >= 1");
  const int d = dimension, k = highest_order, n = k + 1;
  const double eta_n = (1 + alpha) / 2, eta0 = (1 + beta0) * kappa / (2 * (1 + kappa)), s = std::sqrt(1 + tau);
  const double m = std::isinf(friction) ? friction : friction * (1 + alpha) / 2;
  const double c = std::isinf(m) ? 0 : (m == 0 ? std::numeric_limits<double>::infinity() : eta0 / m);
  ProductMoments moments(d, tau, eta_n, kappa);
  // L = [⟨ψ(1)ψ'(1)⟩ − ⟨ψ(1)ψ'(1')⟩] + [⟨ψ(2)ψ'(1)⟩ − ⟨ψ(2)ψ'(1')⟩] (theory.md (5.2)), as the engine
  // (rough_sonine_systems.cpp): trial powers (i, j) of slot a, test powers (a, b) of slot b, the tensor part
  // (c_a·c_b)² − X_a X_b/d for rank 2. Each entry a list of (coefficient, moment index).
  using Combination = std::vector<std::pair<double, int>>;
  const auto product = [&](int dot, int r, int xa, int i, int ya, int j, int xb, int a, int yb, int b) {
    std::vector<int> f;
    f.insert(f.end(), static_cast<std::size_t>(r), dot);
    f.insert(f.end(), static_cast<std::size_t>(i), xa);
    f.insert(f.end(), static_cast<std::size_t>(j), ya);
    f.insert(f.end(), static_cast<std::size_t>(a), xb);
    f.insert(f.end(), static_cast<std::size_t>(b), yb);
    return moments.moment(f);
  };
  std::array<std::vector<Combination>, 3> table;
  for (int rank = 0; rank <= 2; ++rank) {
    const int top = rank == 2 ? k - 1 : k;
    const double weight = rough_contraction_weight(d, rank).to_double();
    table[static_cast<std::size_t>(rank)].assign(static_cast<std::size_t>(n * n * n * n), {});
    for (int i = 0; i <= top; ++i)
      for (int j = 0; i + j <= top; ++j)
        for (int a = 0; a <= top; ++a)
          for (int b = 0; a + b <= top; ++b) {
            Combination& e =
                table[static_cast<std::size_t>(rank)][static_cast<std::size_t>(((i * n + j) * n + a) * n + b)];
            e.push_back({weight, product(kX1, 0, kX1, rank + i + a, kY1, j + b, kX1, 0, kY1, 0)});
            // (slot a, slot b, sign): (1, 1') −, (2, 1) +, (2, 1') −.
            const std::array<std::array<int, 6>, 3> pairs{
                {{kD11p, kX1, kY1, kX1p, kY1p, -1}, {kD21, kX2, kY2, kX1, kY1, 1}, {kD21p, kX2, kY2, kX1p, kY1p, -1}}};
            for (const auto& [dot, xa, ya, xb, yb, sign] : pairs) {
              e.push_back({sign, product(dot, rank, xa, i, ya, j, xb, a, yb, b)});
              if (rank == 2)
                e.push_back({-sign / static_cast<double>(d), product(dot, 0, xa, i + 1, ya, j, xb, a + 1, yb, b)});
            }
          }
  }
  // (u, G) quadrature with weight Θ(u) u e^{−u²/2} and the density of r = G/s (as rough_walton_productions): the
  // sticking–sliding kink u = cG and the G where it leaves the u-range are panel edges.
  std::vector<double> value, total;
  const double upper = 12, edge = c > 0 && std::isfinite(c) ? std::min(upper / (c * s), upper) : upper;
  for (const auto& [lo, hi] : {std::pair{0.0, edge}, std::pair{edge, upper}})
    for_each_gauss_legendre_node(lo, hi, panels, [&](double r, double r_weight) {
      const double big_g = s * r;
      const double density = (d == 3 ? r : std::sqrt(2 / std::numbers::pi)) * std::exp(-r * r / 2);
      const double kink = big_g > 0 ? std::min(c * big_g, upper) : 0.0;
      for (const auto& [u_lo, u_hi] : {std::pair{0.0, kink}, std::pair{kink, upper}})
        for_each_gauss_legendre_node(u_lo, u_hi, panels, [&](double u, double u_weight) {
          const double eta_t = (big_g == 0 || u >= c * big_g) ? eta0 : m * u / big_g;
          moments.evaluate(Eigen::Vector3d(u, big_g, eta_t * big_g), value);
          const double w = r_weight * density * u_weight * u * std::exp(-u * u / 2);
          total.resize(value.size(), 0.0);
          for (std::size_t q = 0; q < value.size(); ++q) total[q] += w * value[q];
        });
    });
  // Contract with the Sonine coefficients (trial: S^(d/2−1+r), L; test the same), in double.
  std::array<std::vector<double>, 3> elements;
  const long twice_spin = rough_rotational_dimension(d) - 2;
  for (int rank = 0; rank <= 2; ++rank) {
    const int top = rank == 2 ? k - 1 : k;
    const auto sx = sonine_table(sonine_twice_m(d, rank), top), sy = sonine_table(twice_spin, top);
    std::vector<double> t(static_cast<std::size_t>(n * n * n * n), 0.0);
    for (std::size_t e = 0; e < t.size(); ++e)
      for (const auto& [coefficient, index] : table[static_cast<std::size_t>(rank)][e])
        t[e] += coefficient * total[static_cast<std::size_t>(index)];
    auto& out = elements[static_cast<std::size_t>(rank)];
    const int w = top + 1;  // the engine's layout: index ((p w + q) w + p') w + q', w = top + 1
    out.assign(static_cast<std::size_t>(w * w * w * w), 0.0);
    for (int p = 0; p <= top; ++p)
      for (int q = 0; p + q <= top; ++q)
        for (int pt = 0; pt <= top; ++pt)
          for (int qt = 0; pt + qt <= top; ++qt) {
            double sum = 0;
            for (int i = 0; i <= p; ++i)
              for (int j = 0; j <= q; ++j)
                for (int a = 0; a <= pt; ++a)
                  for (int b = 0; b <= qt; ++b)
                    sum += sx[p][i].to_double() * sy[q][j].to_double() * sx[pt][a].to_double() * sy[qt][b].to_double() *
                           t[static_cast<std::size_t>(((i * n + j) * n + a) * n + b)];
            out[static_cast<std::size_t>(((p * w + q) * w + pt) * w + qt)] = sum;
          }
  }
  return RoughCollisionElements(k, tau, elements);
}

}  // namespace detail

std::vector<RoughTransportValues> rough_walton_sonine_transport(int dimension, double alpha, double beta0, double kappa,
                                                                double friction, double temperature_ratio,
                                                                int highest_order, int panels) {
  detail::check_walton_parameters(dimension, alpha, beta0, kappa, friction);
  const bool decoupled = friction == 0 || beta0 == -1;
  if (!decoupled && (!(temperature_ratio > 0) || !std::isfinite(temperature_ratio)))
    throw std::invalid_argument("temperature_ratio: must be > 0 and finite");
  // Decoupled: no translational element depends on τ (η_t = 0), any τ will do.
  const double tau = decoupled ? 1.0 : temperature_ratio / kappa;
  const detail::RoughCollisionElements elements =
      detail::rough_walton_collision_elements(dimension, alpha, beta0, kappa, friction, tau, highest_order, panels);
  const detail::RoughModeState state{dimension, tau, decoupled, nullptr};
  std::vector<RoughTransportValues> out;
  for (int order = 1; order <= highest_order; ++order)
    out.push_back(detail::solve_rough_navier_stokes(
        elements, state, order, decoupled ? std::numeric_limits<double>::infinity() : temperature_ratio));
  return out;
}

}  // namespace gkt
