#include "gkt/transport/rough/rough_sonine_cooling_rates.hpp"

#include <stdexcept>
#include <string>

#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/rough_collision_moments.hpp"
#include "transport/rough/rough_sonine_balances.hpp"

namespace gkt {

struct RoughSonineCoolingRates::Impl {
  detail::RoughSonineBalances balances;
  int dimension;
  double kappa;
  int order;
  bool linear;
  std::vector<double> maxwellian;               // ⟨ψ_t⟩_M of the unknowns' tests
  std::vector<std::vector<double>> projection;  // ⟨ψ_t Φ_w⟩_M
  std::vector<int> spin_degree;
  std::vector<double> collision_weight;                // 2⟨Φ_w(1)⟩ over collisions
  std::vector<std::vector<double>> collision_product;  // ⟨Φ_w(1)Φ_v(2)⟩ over collisions (nonlinear scheme)
};

RoughSonineCoolingRates::RoughSonineCoolingRates(int dimension, const Rational& alpha, const Rational& beta,
                                                 const Rational& kappa, int order, RoughSonineAnsatz ansatz,
                                                 RoughSonineScheme scheme) {
  if (order < 1) throw std::invalid_argument("order: must be an integer >= 1, got " + std::to_string(order));
  const bool linear = scheme == RoughSonineScheme::linear;
  impl_ = std::make_unique<Impl>(Impl{detail::RoughSonineBalances(dimension, alpha, beta, kappa, order + 1, !linear,
                                                                  ansatz == RoughSonineAnsatz::oriented),
                                      dimension,
                                      kappa.to_double(),
                                      order,
                                      linear,
                                      {},
                                      {},
                                      {},
                                      {},
                                      {}});
  const auto& b = impl_->balances;
  const std::size_t k = b.unknowns(), na = b.cumulants().size();
  // The tests of the unknowns follow x and y (rough_sonine_balances.hpp).
  for (std::size_t t = 0; t < k; ++t) {
    impl_->maxwellian.push_back(b.maxwellian_moments()[t + 2]);
    impl_->projection.push_back(b.projections()[t + 2]);
    impl_->spin_degree.push_back(t < na ? b.cumulants()[t][1] : b.orientations()[t - na][1] + 1);
  }
  // ⟨x1^i x2^j⟩ over collisions (the velocity-only moments, constant in θ; j = 0 in the linear scheme): the
  // collision rate sees the translational marginal alone, so only the a_p0 change it (theory.md (19.110)).
  const auto params = rough_parameters_symbolic_temperature(dimension, alpha, beta, kappa);
  std::vector<RoughForm> forms{rough_dot_form(RoughSlot::v1, RoughSlot::v1)};
  std::vector<int> degrees{order + 1};
  if (!linear) forms.push_back(rough_dot_form(RoughSlot::v2, RoughSlot::v2)), degrees.push_back(order + 1);
  const RoughCollisionMoments<RationalPolynomial> x12(params, forms, degrees);
  auto pair = [&](int i, int j) { return x12.moment({i, j}).coefficient(0).to_double(); };
  impl_->collision_weight.assign(k, 0.0);
  for (std::size_t w = 0; w < na; ++w) {
    if (b.cumulants()[w][1] != 0) continue;
    double s = 0;
    for (const auto& [e, c] : b.weight_expansion(w)) s += c * pair(e[0], 0);
    impl_->collision_weight[w] = 2 * s;
  }
  if (linear) return;
  impl_->collision_product.assign(k, std::vector<double>(k, 0.0));
  for (std::size_t w = 0; w < na; ++w)
    for (std::size_t v = 0; v < na; ++v) {
      if (b.cumulants()[w][1] != 0 || b.cumulants()[v][1] != 0) continue;
      double s = 0;
      for (const auto& [e, c] : b.weight_expansion(w))
        for (const auto& [f, cf] : b.weight_expansion(v)) s += c * cf * pair(e[0], f[0]);
      impl_->collision_product[w][v] = s;
    }
}

RoughSonineCoolingRates::~RoughSonineCoolingRates() = default;
RoughSonineCoolingRates::RoughSonineCoolingRates(RoughSonineCoolingRates&&) noexcept = default;
RoughSonineCoolingRates& RoughSonineCoolingRates::operator=(RoughSonineCoolingRates&&) noexcept = default;

RoughSonineRates RoughSonineCoolingRates::at(double tau, std::span<const double> unknowns) const {
  const auto& b = impl_->balances;
  if (unknowns.size() != b.unknowns()) throw std::invalid_argument("RoughSonineCoolingRates: wrong number of unknowns");
  const bool linear = impl_->linear;
  const auto r = b.productions(tau, linear);
  const auto f = b.evaluate(r, unknowns, linear);  // F_0 = (z_r − z_t)/2 (not at β = −1), then the balances
  RoughSonineRates out;
  double rx = r(0, 0, 0);
  for (std::size_t p = 0; p < unknowns.size(); ++p) {
    rx += unknowns[p] * (r(p + 1, 0, 0) + r(0, p + 1, 0));
    if (!linear)
      for (std::size_t q = 0; q < unknowns.size(); ++q) rx += unknowns[p] * unknowns[q] * r(p + 1, q + 1, 0);
  }
  out.translational_rate = -2.0 / impl_->dimension * rx;  // as RoughSonineBalances::translational_rate
  const std::size_t off = b.spin_decoupled() ? 0 : 1;
  out.rotational_rate = off ? out.translational_rate + 2 * f[0] : 0.0;
  out.residual.assign(f.begin() + static_cast<std::ptrdiff_t>(off), f.end());
  return out;
}

const std::vector<std::array<int, 2>>& RoughSonineCoolingRates::cumulant_indices() const {
  return impl_->balances.cumulants();
}
const std::vector<std::array<int, 2>>& RoughSonineCoolingRates::orientation_indices() const {
  return impl_->balances.orientations();
}
std::size_t RoughSonineCoolingRates::unknowns() const { return impl_->balances.unknowns(); }
const std::vector<double>& RoughSonineCoolingRates::maxwellian_moments() const { return impl_->maxwellian; }
const std::vector<std::vector<double>>& RoughSonineCoolingRates::projections() const { return impl_->projection; }
const std::vector<int>& RoughSonineCoolingRates::spin_degrees() const { return impl_->spin_degree; }
double RoughSonineCoolingRates::collision_frequency_factor(std::span<const double> unknowns) const {
  double f = 1;
  for (std::size_t w = 0; w < unknowns.size() && w < impl_->collision_weight.size(); ++w)
    f += impl_->collision_weight[w] * unknowns[w];
  const auto& pp = impl_->collision_product;  // empty in the linear scheme
  for (std::size_t w = 0; w < pp.size() && w < unknowns.size(); ++w)
    for (std::size_t v = 0; v < pp[w].size() && v < unknowns.size(); ++v) f += pp[w][v] * unknowns[w] * unknowns[v];
  return f;
}
const std::vector<double>& RoughSonineCoolingRates::correlation_weights() const {
  return impl_->balances.correlation_weights();
}
bool RoughSonineCoolingRates::spin_decoupled() const { return impl_->balances.spin_decoupled(); }
int RoughSonineCoolingRates::dimension() const { return impl_->dimension; }
double RoughSonineCoolingRates::kappa() const { return impl_->kappa; }
int RoughSonineCoolingRates::order() const { return impl_->order; }
RoughSonineScheme RoughSonineCoolingRates::scheme() const {
  return impl_->linear ? RoughSonineScheme::linear : RoughSonineScheme::nonlinear;
}

}  // namespace gkt
