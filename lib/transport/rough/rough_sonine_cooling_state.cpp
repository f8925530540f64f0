#include "gkt/transport/rough/rough_sonine_cooling_state.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "transport/rough/rough_sonine_balances.hpp"

namespace gkt {

namespace {

using detail::RoughSonineBalances;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The linear scheme at fixed τ: a(τ) = −J⁻¹F(τ, 0) over the cumulant balances, F_0 at a(τ), and
/// det J (its sign changes at the poles of a(τ), theory.md §19.6).
struct LinearPoint {
  double g0 = 0, det = 0;
  std::vector<double> a;
};

LinearPoint linear_point(const RoughSonineBalances& b, double tau) {
  const std::size_t k = b.unknowns();
  const auto r = b.productions(tau, true);
  std::vector<double> a(k, 0.0);
  const auto f0 = b.evaluate(r, a, true);
  const std::size_t off = b.spin_decoupled() ? 0 : 1;
  Eigen::MatrixXd j(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k));
  Eigen::VectorXd g(static_cast<Eigen::Index>(k)), j0(static_cast<Eigen::Index>(k));
  for (std::size_t p = 0; p < k; ++p) {
    a.assign(k, 0.0);
    a[p] = 1;
    const auto fp = b.evaluate(r, a, true);  // linear in a: the column is fp − f0
    for (std::size_t q = 0; q < k; ++q)
      j(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(p)) = fp[q + off] - f0[q + off];
    j0(static_cast<Eigen::Index>(p)) = off ? fp[0] - f0[0] : 0;
  }
  for (std::size_t q = 0; q < k; ++q) g(static_cast<Eigen::Index>(q)) = f0[q + off];
  const Eigen::VectorXd x = j.fullPivLu().solve(-g);
  LinearPoint pt;
  pt.det = j.determinant();
  pt.a.assign(x.data(), x.data() + x.size());
  pt.g0 = off ? f0[0] + j0.dot(x) : 0;
  return pt;
}

/// Returns the Maxwellian ln τ: the root of F_0(τ, 0) (bisection in ln τ, as the first-Sonine solver).
double maxwellian_log_tau(const RoughSonineBalances& b) {
  const std::vector<double> zero(b.unknowns(), 0.0);
  auto g0 = [&](double lt) { return b.residual(std::exp(lt), zero, true)[0]; };
  double lo = 0, hi = 0;
  while (g0(lo) > 0 && lo > -80) lo -= 1;
  while (g0(hi) < 0 && hi < 80) hi += 1;
  if (g0(lo) > 0 || g0(hi) < 0) throw std::runtime_error("rough HCS: no temperature ratio found");
  for (int it = 0; it < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(lo)); ++it) {
    const double mid = 0.5 * (lo + hi);
    (g0(mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

bool realizable(const RoughSonineBalances& b, int d, const std::vector<double>& a) {
  double a20 = 0, a02 = 0, a11 = 0;
  for (std::size_t p = 0; p < b.cumulants().size(); ++p) {
    const auto [i, j] = b.cumulants()[p];
    if (i == 2 && j == 0) a20 = a[p];
    if (i == 0 && j == 2) a02 = a[p];
    if (i == 1 && j == 1) a11 = a[p];
  }
  for (const double x : a)
    if (!std::isfinite(x)) return false;
  return rough_cumulants_realizable(d, a20, a02, a11);
}

/// The linear scheme: scan ln τ over ±4 around the Maxwellian root in steps of 1/64 for sign changes
/// of F_0(τ, a(τ)) where det J keeps its sign, nearest first, bisect, keep the first realizable root
/// (theory.md §19.6, generalised to K cumulants). Returns false if none.
bool solve_linear(const RoughSonineBalances& b, int d, double center, double& log_tau, std::vector<double>& a) {
  if (b.spin_decoupled()) {
    a = linear_point(b, 1.0).a;
    log_tau = 0;
    return true;
  }
  const double step = 1.0 / 64, span = 4;
  struct Bracket {
    double lo, hi, distance;
  };
  std::vector<Bracket> brackets;
  LinearPoint prev = linear_point(b, std::exp(center - span));
  for (double lt = center - span + step; lt <= center + span + step / 2; lt += step) {
    const LinearPoint cur = linear_point(b, std::exp(lt));
    const bool sign_change = (prev.g0 < 0) != (cur.g0 < 0);
    const bool pole = (prev.det < 0) != (cur.det < 0);
    if (sign_change && !pole) brackets.push_back({lt - step, lt, std::abs(lt - step / 2 - center)});
    prev = cur;
  }
  std::stable_sort(brackets.begin(), brackets.end(),
                   [](const Bracket& x, const Bracket& y) { return x.distance < y.distance; });
  for (Bracket br : brackets) {
    const bool rising = linear_point(b, std::exp(br.lo)).g0 < 0;
    for (int it = 0; it < 200 && br.hi - br.lo > 1e-15 * std::max(1.0, std::abs(br.lo)); ++it) {
      const double mid = 0.5 * (br.lo + br.hi);
      ((linear_point(b, std::exp(mid)).g0 < 0) == rising ? br.lo : br.hi) = mid;
    }
    log_tau = 0.5 * (br.lo + br.hi);
    a = linear_point(b, std::exp(log_tau)).a;
    if (realizable(b, d, a)) return true;
  }
  return false;
}

/// The nonlinear scheme: damped Newton in u = (ln τ, a) (a only when the spin decouples), central
/// differences for the Jacobian (the residual is a cubic in a). Returns false unless |F| < 1e-10.
bool solve_nonlinear(const RoughSonineBalances& b, int d, double& log_tau, std::vector<double>& a) {
  const bool with_tau = !b.spin_decoupled();
  const std::size_t k = a.size(), n = k + (with_tau ? 1 : 0);
  auto unpack = [&](const Eigen::VectorXd& u, double& lt, std::vector<double>& x) {
    lt = with_tau ? u(0) : 0.0;
    x.assign(u.data() + (with_tau ? 1 : 0), u.data() + u.size());
  };
  auto residual = [&](const Eigen::VectorXd& u) {
    double lt = 0;
    std::vector<double> x;
    unpack(u, lt, x);
    const auto f = b.residual(std::exp(lt), x, false);
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(f.data(), static_cast<Eigen::Index>(f.size())));
  };
  Eigen::VectorXd u(static_cast<Eigen::Index>(n));
  if (with_tau) u(0) = log_tau;
  for (std::size_t p = 0; p < k; ++p) u(static_cast<Eigen::Index>(p + (with_tau ? 1 : 0))) = a[p];
  Eigen::VectorXd f = residual(u);
  for (int it = 0; it < 100 && f.lpNorm<Eigen::Infinity>() > 1e-14; ++it) {
    Eigen::MatrixXd j(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    for (Eigen::Index c = 0; c < static_cast<Eigen::Index>(n); ++c) {
      const double h = 1e-6 * std::max(1.0, std::abs(u(c)));
      Eigen::VectorXd up = u, down = u;
      up(c) += h;
      down(c) -= h;
      j.col(c) = (residual(up) - residual(down)) / (2 * h);
    }
    const Eigen::VectorXd step = j.fullPivLu().solve(-f);
    double lambda = 1;
    bool improved = false;
    for (int halving = 0; halving < 30; ++halving, lambda /= 2) {
      const Eigen::VectorXd trial = u + lambda * step;
      const Eigen::VectorXd ft = residual(trial);
      if (ft.allFinite() && ft.lpNorm<Eigen::Infinity>() < f.lpNorm<Eigen::Infinity>()) {
        u = trial;
        f = ft;
        improved = true;
        break;
      }
    }
    if (!improved) break;
  }
  unpack(u, log_tau, a);
  return f.lpNorm<Eigen::Infinity>() < 1e-10 && realizable(b, d, a);
}

}  // namespace

double RoughSonineCoolingState::cumulant(int p, int q) const {
  if (!solved || (spin_decoupled && q > 0)) return kNaN;
  for (std::size_t i = 0; i < indices.size(); ++i)
    if (indices[i][0] == p && indices[i][1] == q) return cumulants[i];
  return 0;
}

double RoughSonineCoolingState::orientation_coefficient(int p, int q) const {
  if (!solved || std::isnan(orientation_correlation)) return kNaN;
  for (std::size_t i = 0; i < orientation_indices.size(); ++i)
    if (orientation_indices[i][0] == p && orientation_indices[i][1] == q) return orientation_coefficients[i];
  return 0;
}

RoughSonineCoolingState rough_sonine_cooling_state(int dimension, const Rational& alpha, const Rational& beta,
                                                   const Rational& kappa, int order, RoughSonineScheme scheme) {
  return rough_sonine_cooling_state(dimension, alpha, beta, kappa, order, scheme, RoughSonineAnsatz::isotropic);
}

RoughSonineCoolingState rough_sonine_cooling_state(int dimension, const Rational& alpha, const Rational& beta,
                                                   const Rational& kappa, int order, RoughSonineScheme scheme,
                                                   RoughSonineAnsatz ansatz) {
  if (order < 1) throw std::invalid_argument("order: must be an integer >= 1, got " + std::to_string(order));
  const bool nonlinear = scheme == RoughSonineScheme::nonlinear;
  const bool oriented = ansatz == RoughSonineAnsatz::oriented;
  const RoughSonineBalances b(dimension, alpha, beta, kappa, order + 1, nonlinear, oriented);
  RoughSonineCoolingState s;
  s.order = order;
  s.indices = b.cumulants();
  s.orientation_indices = b.orientations();
  s.spin_decoupled = b.spin_decoupled();
  if (dimension != 3) s.orientation_correlation = kNaN;  // ŵ ⟂ the plane of c: c·ŵ ≡ 0
  const double center = s.spin_decoupled ? 0 : maxwellian_log_tau(b);
  double log_tau = center;
  std::vector<double> a(b.unknowns(), 0.0);
  bool ok = solve_linear(b, dimension, center, log_tau, a);
  if (nonlinear) {
    // From the linear solution of this order; failing that, from the nonlinear solution of the order
    // below (its cumulants, the new ones 0) — continuation in the order — or from the Maxwellian.
    if (!ok) {
      log_tau = center;
      a.assign(b.unknowns(), 0.0);
    }
    ok = solve_nonlinear(b, dimension, log_tau, a);
    if (!ok && order > 1) {
      const RoughSonineCoolingState below =
          rough_sonine_cooling_state(dimension, alpha, beta, kappa, order - 1, scheme, ansatz);
      if (below.solved) {
        log_tau = s.spin_decoupled ? 0 : std::log(below.temperature_ratio / kappa.to_double());
        const std::size_t na = s.indices.size();
        for (std::size_t p = 0; p < na; ++p) a[p] = below.cumulant(s.indices[p][0], s.indices[p][1]);
        for (std::size_t o = 0; o < s.orientation_indices.size(); ++o)
          a[na + o] = below.orientation_coefficient(s.orientation_indices[o][0], s.orientation_indices[o][1]);
        ok = solve_nonlinear(b, dimension, log_tau, a);
      }
    }
  }
  if (!ok) {
    s.solved = false;
    s.temperature_ratio = s.cooling_rate = s.orientation_correlation = kNaN;
    s.cumulants.assign(s.indices.size(), kNaN);
    s.orientation_coefficients.assign(s.orientation_indices.size(), kNaN);
    return s;
  }
  const double d = dimension;
  s.cumulants.assign(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(s.indices.size()));
  s.orientation_coefficients.assign(a.begin() + static_cast<std::ptrdiff_t>(s.indices.size()), a.end());
  for (std::size_t o = 0; o < s.orientation_coefficients.size(); ++o)
    s.orientation_correlation += b.correlation_weights()[o] * s.orientation_coefficients[o];
  s.temperature_ratio =
      s.spin_decoupled ? std::numeric_limits<double>::infinity() : std::exp(log_tau) * kappa.to_double();
  s.cooling_rate = (d + 2) / 4 * b.translational_rate(std::exp(log_tau), a, !nonlinear);
  return s;
}

}  // namespace gkt
