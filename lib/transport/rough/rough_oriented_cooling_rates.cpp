#include "gkt/transport/rough/rough_oriented_cooling_rates.hpp"

#include <stdexcept>

#include "transport/rough/rough_sonine_balances.hpp"

namespace gkt {

struct RoughOrientedCoolingRates::Impl {
  detail::RoughSonineBalances balances;
  double kappa;
  /// Positions of a20, a02, a11 among the balances' cumulants (ordered by p + q, then q), b00 after them.
  std::array<std::size_t, 3> index{};
};

RoughOrientedCoolingRates::RoughOrientedCoolingRates(const Rational& alpha, const Rational& beta,
                                                     const Rational& kappa) {
  if (beta == Rational(-1))
    throw std::invalid_argument("beta: the orientation term needs beta > -1 (at -1 the spin decouples), got -1");
  impl_ = std::make_unique<Impl>(
      Impl{detail::RoughSonineBalances(3, alpha, beta, kappa, 2, false, true), kappa.to_double(), {}});
  const auto& c = impl_->balances.cumulants();
  if (c.size() != 3 || impl_->balances.orientations().size() != 1)
    throw std::logic_error("RoughOrientedCoolingRates: unexpected first-Sonine unknowns");
  const std::array<std::array<int, 2>, 3> wanted{{{2, 0}, {0, 2}, {1, 1}}};
  for (std::size_t w = 0; w < 3; ++w)
    for (std::size_t p = 0; p < 3; ++p)
      if (c[p] == wanted[w]) impl_->index[w] = p;
}

RoughOrientedCoolingRates::~RoughOrientedCoolingRates() = default;
RoughOrientedCoolingRates::RoughOrientedCoolingRates(RoughOrientedCoolingRates&&) noexcept = default;
RoughOrientedCoolingRates& RoughOrientedCoolingRates::operator=(RoughOrientedCoolingRates&&) noexcept = default;

RoughOrientedBalances RoughOrientedCoolingRates::at(double tau, const std::array<double, 4>& a) const {
  const auto& b = impl_->balances;
  std::array<double, 4> unknowns{};
  for (std::size_t w = 0; w < 3; ++w) unknowns[impl_->index[w]] = a[w];
  unknowns[3] = a[3];
  const auto r = b.productions(tau, true);
  const auto f = b.evaluate(r, unknowns, true);  // F_0 = (z_r − z_t)/2, the cumulant balances, then P's
  RoughOrientedBalances out;
  out.translational_rate = b.translational_rate(tau, unknowns, true);
  out.rotational_rate = out.translational_rate + 2 * f[0];
  for (std::size_t w = 0; w < 3; ++w) out.residual[w] = f[1 + impl_->index[w]];
  out.residual[3] = f[4];
  return out;
}

std::array<double, 4> RoughOrientedCoolingRates::base_moments() const { return {15.0 / 4, 15.0 / 4, 9.0 / 4, 5.0 / 4}; }

double RoughOrientedCoolingRates::correlation_weight() const { return impl_->balances.correlation_weights().front(); }

double RoughOrientedCoolingRates::kappa() const { return impl_->kappa; }

}  // namespace gkt
