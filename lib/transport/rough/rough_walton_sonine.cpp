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
#include "transport/rough/rough_walton_product_moments.hpp"
#include "transport/rough/rough_walton_quadrature.hpp"

namespace gkt {

namespace detail {

RoughCollisionElements rough_walton_collision_elements(int dimension, double alpha, double beta0, double kappa,
                                                       double friction, double tau, int highest_order, int panels,
                                                       const std::vector<WaltonWeightTerm>* weight) {
  check_walton_parameters(dimension, alpha, beta0, kappa, friction);
  if (!(tau > 0) || !std::isfinite(tau)) throw std::invalid_argument("temperature_ratio: must be > 0 and finite");
  if (highest_order < 1 || highest_order > kWaltonHighestOrder)
    throw std::invalid_argument("order: must be an integer in [1, " + std::to_string(kWaltonHighestOrder) + "]");
  if (panels < 1) throw std::invalid_argument("panels: must be >= 1");
  const int d = dimension, k = highest_order, n = k + 1;
  const double eta_n = (1 + alpha) / 2;
  ProductMoments moments(d, tau, eta_n, kappa);
  // L = [⟨ψ(1)ψ'(1)⟩ − ⟨ψ(1)ψ'(1')⟩] + [⟨ψ(2)ψ'(1)⟩ − ⟨ψ(2)ψ'(1')⟩] (theory.md (5.2)), as the engine
  // (rough_sonine_systems.cpp): trial powers (i, j) of slot a, test powers (a, b) of slot b, the tensor part
  // (c_a·c_b)² − X_a X_b/d for rank 2. Each entry a list of (coefficient, moment index).
  using Combination = std::vector<std::pair<double, int>>;
  const auto product = [&](int dot, int r, int xa, int i, int ya, int j, int xb, int a, int yb, int b, int xc, int m,
                           int yc, int l) {
    std::vector<int> f;
    f.insert(f.end(), static_cast<std::size_t>(r), dot);
    f.insert(f.end(), static_cast<std::size_t>(i), xa);
    f.insert(f.end(), static_cast<std::size_t>(j), ya);
    f.insert(f.end(), static_cast<std::size_t>(a), xb);
    f.insert(f.end(), static_cast<std::size_t>(b), yb);
    f.insert(f.end(), static_cast<std::size_t>(m), xc);
    f.insert(f.end(), static_cast<std::size_t>(l), yc);
    return moments.moment(f);
  };
  // Without a weight: the plain L. With one (theory.md (19.44), (19.127)): Φ(2) on the pairs (1, 1), (1, 1') and
  // Φ(1) on (2, 1), (2, 1'), Φ = Σ c x^m y^l.
  const std::vector<WaltonWeightTerm> unit{{0, 0, 1.0}};
  const std::vector<WaltonWeightTerm>& terms = weight ? *weight : unit;
  std::array<std::vector<Combination>, 3> table;
  for (int rank = 0; rank <= 2; ++rank) {
    const int top = rank == 2 ? k - 1 : k;
    const double contraction = rough_contraction_weight(d, rank).to_double();
    table[static_cast<std::size_t>(rank)].assign(static_cast<std::size_t>(n * n * n * n), {});
    for (int i = 0; i <= top; ++i)
      for (int j = 0; i + j <= top; ++j)
        for (int a = 0; a <= top; ++a)
          for (int b = 0; a + b <= top; ++b) {
            Combination& e =
                table[static_cast<std::size_t>(rank)][static_cast<std::size_t>(((i * n + j) * n + a) * n + b)];
            for (const WaltonWeightTerm& t : terms) {
              e.push_back({t.c * contraction,
                           product(kX1, 0, kX1, rank + i + a, kY1, j + b, kX1, 0, kY1, 0, kX2, t.x, kY2, t.y)});
              // (slot a, slot b, sign, weight slot): (1, 1') −, (2, 1) +, (2, 1') −.
              const std::array<std::array<int, 8>, 3> pairs{{{kD11p, kX1, kY1, kX1p, kY1p, -1, kX2, kY2},
                                                             {kD21, kX2, kY2, kX1, kY1, 1, kX1, kY1},
                                                             {kD21p, kX2, kY2, kX1p, kY1p, -1, kX1, kY1}}};
              for (const auto& [dot, xa, ya, xb, yb, sign, xc, yc] : pairs) {
                e.push_back({t.c * sign, product(dot, rank, xa, i, ya, j, xb, a, yb, b, xc, t.x, yc, t.y)});
                if (rank == 2)
                  e.push_back({-t.c * sign / static_cast<double>(d),
                               product(dot, 0, xa, i + 1, ya, j, xb, a + 1, yb, b, xc, t.x, yc, t.y)});
              }
            }
          }
  }
  // (u, G) quadrature with weight Θ(u) u e^{−u²/2} and the density of r = G/s (as rough_walton_productions).
  const std::vector<double> total = integrate_walton_moments(moments, d, alpha, beta0, kappa, friction, tau, panels);
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

std::vector<RoughTransportValues> rough_walton_sonine_transport_about_hcs(int dimension, double alpha, double beta0,
                                                                          double kappa, double friction,
                                                                          const RoughWaltonSonineState& hcs,
                                                                          int highest_order, int panels) {
  detail::check_walton_parameters(dimension, alpha, beta0, kappa, friction);
  if (!hcs.solved || hcs.spin_decoupled || !std::isfinite(hcs.temperature_ratio))
    throw std::invalid_argument("hcs: the Walton HCS is not solved (no realizable root, or the spin decouples)");
  const double tau = hcs.temperature_ratio / kappa;
  // Φ = Σ a_pq S_p(x) S_q(y) as monomials (the HCS's polynomials, theory.md (19.26)).
  int top = 0;
  for (const auto& [p, q] : hcs.indices) top = std::max(top, p + q);
  const auto sx = sonine_table(sonine_twice_m(dimension, 0), top),
             sy = sonine_table(detail::rough_rotational_dimension(dimension) - 2, top);
  std::map<std::pair<int, int>, double> monomials;
  for (std::size_t w = 0; w < hcs.indices.size(); ++w) {
    const auto [p, q] = hcs.indices[w];
    for (int i = 0; i <= p; ++i)
      for (int j = 0; j <= q; ++j)
        monomials[{i, j}] += hcs.cumulants[w] *
                             sx[static_cast<std::size_t>(p)][static_cast<std::size_t>(i)].to_double() *
                             sy[static_cast<std::size_t>(q)][static_cast<std::size_t>(j)].to_double();
  }
  std::vector<detail::WaltonWeightTerm> weight;
  for (const auto& [e, c] : monomials) weight.push_back({e.first, e.second, c});
  const detail::RoughCollisionElements elements =
      detail::rough_walton_collision_elements(dimension, alpha, beta0, kappa, friction, tau, highest_order, panels);
  const detail::RoughCollisionElements weighted = detail::rough_walton_collision_elements(
      dimension, alpha, beta0, kappa, friction, tau, highest_order, panels, &weight);
  detail::RoughCumulantReference reference;
  reference.indices = hcs.indices;
  reference.cumulants = hcs.cumulants;
  reference.cooling_rate = hcs.cooling_rate;
  reference.weighted_sum = &weighted;
  const detail::RoughModeState state{dimension, tau, false, &reference};
  std::vector<RoughTransportValues> out;
  for (int order = 1; order <= highest_order; ++order)
    out.push_back(detail::solve_rough_navier_stokes(elements, state, order, hcs.temperature_ratio));
  return out;
}

}  // namespace gkt
