#include "gkt/transport/rough/rough_walton_sonine_hcs.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_walton_cumulants.hpp"
#include "transport/rough/rough_sonine_balances.hpp"
#include "transport/rough/rough_walton_product_moments.hpp"
#include "transport/rough/rough_walton_quadrature.hpp"

namespace gkt {

namespace {

using detail::RoughSonineBalances;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The linear scheme at one τ: the Walton averages by quadrature, a(τ) = −J⁻¹F(τ, 0) from the cumulant balances,
/// G_0 = ζ_t − ζ_r balance at a(τ) and the translational rate z_t there (theory.md (19.120)–(19.122)).
struct Point {
  double g0 = 0, rate = 0;
  std::vector<double> a;
};

Point linear_point(const RoughSonineBalances& b, int d, double alpha, double beta0, double kappa, double friction,
                   double tau, int panels) {
  using E3 = std::array<int, 3>;
  using Counts = std::array<int, 9>;  // how often each form of `kind` enters the product
  using detail::kX1, detail::kY1, detail::kF1, detail::kX2, detail::kY2, detail::kF2, detail::kX1p, detail::kY1p,
      detail::kF1p;
  detail::ProductMoments moments(d, tau, (1 + alpha) / 2, kappa);
  // Register every monomial the balances ask for (pass 1), integrate, then read them back (pass 2). A monomial
  // x^i y^j f^{2e} (f = c·ŵ, the orientation ansatz, theory.md §19.29) is i, j and 2e factors of the forms x, y, f.
  std::map<Counts, int> index;
  const auto id = [&](const Counts& e) {
    if (const auto it = index.find(e); it != index.end()) return it->second;
    std::vector<int> forms;
    const Counts kind{kX1, kY1, kF1, kX2, kY2, kF2, kX1p, kY1p, kF1p};
    for (std::size_t f = 0; f < kind.size(); ++f) forms.insert(forms.end(), static_cast<std::size_t>(e[f]), kind[f]);
    return index[e] = moments.moment(forms);
  };
  const auto gain_exponents = [](const E3& u, const E3& v, const E3& t) {
    return Counts{u[0], u[1], 2 * u[2], v[0], v[1], 2 * v[2], t[0], t[1], 2 * t[2]};
  };
  const auto loss_exponents = [](const E3& u, const E3& v, const E3& t) {
    return Counts{u[0] + t[0], u[1] + t[1], 2 * (u[2] + t[2]), v[0], v[1], 2 * v[2], 0, 0, 0};
  };
  const auto registering = [&](const auto& exponents) {
    return [&, exponents](const E3& u, const E3& v, const E3& t) {
      id(exponents(u, v, t));
      return 0.0;
    };
  };
  (void)b.productions_from(registering(gain_exponents), registering(loss_exponents));
  const std::vector<double> total =
      detail::integrate_walton_moments(moments, d, alpha, beta0, kappa, friction, tau, panels);
  const auto reading = [&](const auto& exponents) {
    return [&, exponents](const E3& u, const E3& v, const E3& t) {
      return total[static_cast<std::size_t>(index.at(exponents(u, v, t)))];
    };
  };
  const RoughSonineBalances::Productions r = b.productions_from(reading(gain_exponents), reading(loss_exponents));
  // The balances are linear in a: columns of J from unit vectors (as rough_sonine_cooling_state).
  const std::size_t k = b.unknowns();
  std::vector<double> a(k, 0.0);
  const auto f0 = b.evaluate(r, a, true);
  Eigen::MatrixXd j(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k));
  Eigen::VectorXd g(static_cast<Eigen::Index>(k)), j0(static_cast<Eigen::Index>(k));
  for (std::size_t p = 0; p < k; ++p) {
    a.assign(k, 0.0);
    a[p] = 1;
    const auto fp = b.evaluate(r, a, true);
    for (std::size_t q = 0; q < k; ++q)
      j(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(p)) = fp[q + 1] - f0[q + 1];
    j0(static_cast<Eigen::Index>(p)) = fp[0] - f0[0];
  }
  for (std::size_t q = 0; q < k; ++q) g(static_cast<Eigen::Index>(q)) = f0[q + 1];
  const Eigen::VectorXd x = j.fullPivLu().solve(-g);
  Point pt;
  pt.a.assign(x.data(), x.data() + x.size());
  pt.g0 = f0[0] + j0.dot(x);
  pt.rate = b.translational_rate(r, pt.a, true);
  return pt;
}

/// Returns a20, a02, a11 of `a` (in the balances' order) realizable by rough_cumulants_realizable, every a finite.
bool realizable(const RoughSonineBalances& b, int d, const std::vector<double>& a) {
  double a20 = 0, a02 = 0, a11 = 0;
  for (std::size_t p = 0; p < b.cumulants().size(); ++p) {
    if (!std::isfinite(a[p])) return false;
    const auto [i, j] = b.cumulants()[p];
    if (i == 2 && j == 0) a20 = a[p];
    if (i == 0 && j == 2) a02 = a[p];
    if (i == 1 && j == 1) a11 = a[p];
  }
  return rough_cumulants_realizable(d, a20, a02, a11);
}

}  // namespace

double RoughWaltonSonineState::cumulant(int p, int q) const {
  if (!solved || spin_decoupled) return kNaN;
  for (std::size_t i = 0; i < indices.size(); ++i)
    if (indices[i][0] == p && indices[i][1] == q) return cumulants[i];
  return 0;
}

double RoughWaltonSonineState::orientation_coefficient(int p, int q) const {
  if (!solved || spin_decoupled || std::isnan(orientation_correlation)) return kNaN;
  for (std::size_t i = 0; i < orientation_indices.size(); ++i)
    if (orientation_indices[i][0] == p && orientation_indices[i][1] == q) return orientation_coefficients[i];
  return 0;
}

std::vector<RoughWaltonSonineState> rough_walton_sonine_cooling_states(int dimension, double alpha, double beta0,
                                                                       double kappa, double friction, int highest_order,
                                                                       int panels, RoughSonineAnsatz ansatz) {
  detail::check_walton_parameters(dimension, alpha, beta0, kappa, friction);
  if (highest_order < 1 || highest_order > kWaltonHcsHighestOrder)
    throw std::invalid_argument("order: must be an integer in [1, " + std::to_string(kWaltonHcsHighestOrder) +
                                "], got " + std::to_string(highest_order));
  if (panels < 1) throw std::invalid_argument("panels: must be >= 1");
  // The start: the first-Sonine root of §19.19 (its scan finds the root nearest the Maxwellian one).
  const RoughWaltonCumulantState first = rough_walton_linear_cooling_state(dimension, alpha, beta0, kappa, friction);
  std::vector<RoughWaltonSonineState> out;
  bool below_solved = first.linear_scheme_solved && !first.spin_decoupled;
  double start = below_solved ? std::log(first.temperature_ratio / kappa) : kNaN;
  for (int order = 1; order <= highest_order; ++order) {
    // The oriented ansatz (theory.md §19.29) for spheres whose spin is coupled; disks have no orientation variable.
    const RoughSonineBalances b(dimension, order + 1, false,
                                ansatz == RoughSonineAnsatz::oriented && !first.spin_decoupled);
    RoughWaltonSonineState s;
    s.order = order;
    s.indices = b.cumulants();
    s.orientation_indices = b.orientations();
    if (dimension == 2) s.orientation_correlation = kNaN;
    s.spin_decoupled = first.spin_decoupled;
    s.maxwellian_temperature_ratio = first.maxwellian_temperature_ratio;
    s.maxwellian_cooling_rate = first.maxwellian_cooling_rate;
    const auto fail = [&] {
      s.solved = false;
      s.temperature_ratio = first.spin_decoupled ? std::numeric_limits<double>::infinity() : kNaN;
      s.cooling_rate = kNaN;
      s.cumulants.assign(s.indices.size(), kNaN);
      s.orientation_coefficients.assign(s.orientation_indices.size(), kNaN);
      s.orientation_correlation = kNaN;
      below_solved = false;
      out.push_back(s);
    };
    if (!below_solved) {
      fail();
      continue;
    }
    // Secant (with the better of the last two kept) in ln τ on G_0(ln τ), from the root of the order below and a
    // point 1/64 above it; the roots of successive orders lie within ~1e-2 of each other (theory.md §19.25).
    const auto at = [&](double lt) {
      return linear_point(b, dimension, alpha, beta0, kappa, friction, std::exp(lt), panels);
    };
    double x0 = start, x1 = start + 1.0 / 64;
    Point p0 = at(x0), p1 = at(x1);
    bool converged = false;
    for (int it = 0; it < 40; ++it) {
      if (p1.g0 == p0.g0) break;
      const double x2 = x1 - p1.g0 * (x1 - x0) / (p1.g0 - p0.g0);
      if (!std::isfinite(x2) || std::abs(x2 - start) > 1) break;
      x0 = x1;
      p0 = p1;
      x1 = x2;
      p1 = at(x1);
      if (std::abs(x1 - x0) < 1e-12) {
        converged = true;
        break;
      }
    }
    if (!converged || !realizable(b, dimension, p1.a)) {
      fail();
      continue;
    }
    s.temperature_ratio = std::exp(x1) * kappa;
    s.cooling_rate = (dimension + 2) / 4.0 * p1.rate;
    const auto nc = static_cast<std::ptrdiff_t>(s.indices.size());
    s.cumulants.assign(p1.a.begin(), p1.a.begin() + nc);
    s.orientation_coefficients.assign(p1.a.begin() + nc, p1.a.end());
    for (std::size_t o = 0; o < s.orientation_coefficients.size(); ++o)  // (19.28)
      s.orientation_correlation += b.correlation_weights()[o] * s.orientation_coefficients[o];
    start = x1;
    out.push_back(s);
  }
  return out;
}

}  // namespace gkt
