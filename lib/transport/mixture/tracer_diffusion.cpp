#include "gkt/transport/mixture/tracer_diffusion.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "algebra/nearby_rational.hpp"
#include "gkt/collision/collision_moments.hpp"
#include "gkt/operators/linearized_operator.hpp"
#include "gkt/transport/common/reference_gas.hpp"
#include "gkt/transport/mixture/mixture_cooling_state.hpp"
#include "transport/common/alpha_polynomial.hpp"
#include "transport/common/galerkin_pieces.hpp"
#include "transport/mixture/cumulant_sources.hpp"

namespace gkt {

namespace {

Mixture as_mixture(const Tracer& t) {
  Mixture m{t.dimension, {{t.mass_ratio, t.diameter_ratio, 0.0, "tracer"}, {1.0, 1.0, 1.0, "host"}}, {}, 0.0};
  m.alpha = {1.0, t.alpha_tracer, t.alpha_tracer, t.alpha_host};  // α_00 never enters (x0 = 0)
  return m;
}

}  // namespace

void Tracer::validate() const {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  if (!(mass_ratio.value() > 0) || !std::isfinite(mass_ratio.value()))
    throw std::invalid_argument("mass_ratio: must be a number > 0");
  if (!(diameter_ratio > 0) || !std::isfinite(diameter_ratio))
    throw std::invalid_argument("diameter_ratio: must be a number > 0");
  detail::require_restitution(alpha_tracer, "alpha_tracer");
  detail::require_restitution(alpha_host, "alpha_host");
}

TracerDiffusion::TracerDiffusion(const Tracer& tracer, int max_order, MixtureReference reference)
    : max_order_(max_order) {
  tracer.validate();
  if (max_order < 1) throw std::invalid_argument("order: must be >= 1");
  if (!reference.basis_width.empty())
    throw std::invalid_argument("basis_width: MixtureNavierStokes only (the tracer's basis is the standard one)");
  const MixtureCoolingState hcs = mixture_cooling_state(as_mixture(tracer), reference.scheme, reference.hcs_order);
  const bool with_cumulants = reference.scheme != MixtureHcsScheme::maxwellian;
  if (with_cumulants && !hcs.solved)
    throw std::invalid_argument("reference_state: the HCS with cumulants did not converge");
  const int d = tracer.dimension;
  gamma_ = hcs.temperature_ratio[0];
  theta0_ = tracer.mass_ratio.value() / gamma_;  // θ = m/(2T) in units of the host's √(2T/m)
  // [garzo2004tracer]; (16.8)–(16.9): M(p, q) = ζ̂ D(p, q) + w L(p, q) in units of n σ^{d−1} √(2T/m), with L the
  // Boltzmann–Lorentz operator (loss − gain, normalised by J0) in the tracer's basis c S_p.
  const CollisionPair pair{d, tracer.mass_ratio.exact(), Rational(1), Rational::from_double(theta0_), Rational(1)};
  const Rational alpha = Rational::from_double(tracer.alpha_tracer);
  const int n = max_order - 1;
  const auto gain = sonine_collision_moments<Rational>(pair, alpha, Slot::v1, Slot::v1_post, 1, n);
  const auto loss = sonine_collision_moments<Rational>(pair, alpha, Slot::v1, Slot::v1, 1, n);
  const auto pieces = detail::vector_pieces(d, n, 0);
  // c = π^{(d−1)/2}/Γ(d/2) = K_d/π^d carries every geometric factor below.
  const double c = geometric_factor(d);
  const double w = std::pow(0.5 * (1 + tracer.diameter_ratio), d - 1) * c * std::sqrt(1 / theta0_ + 1);
  // The host's ζ in units of n σ^{d−1} √(2T/m): ζ* ν0 with ν0 = nT/η0 in those units.
  const double zeta = hcs.cooling_rate * unit_reference_gas(d).collision_frequency;
  // D0* = (√2 π^{(d−1)/2}/(θ0 Γ(d/2))) (M⁻¹)_00 (16.10); the tracer's velocity unit is 1/√θ0.
  prefactor_ = std::sqrt(2.0) * c / theta0_;
  matrix_.assign(static_cast<std::size_t>(max_order), std::vector<double>(static_cast<std::size_t>(max_order)));
  source_.assign(static_cast<std::size_t>(max_order), 0.0);
  source_[0] = 1;
  if (!with_cumulants) {
    for (int p = 0; p < max_order; ++p)
      for (int q = 0; q < max_order; ++q)
        matrix_[p][q] = zeta * pieces.d[p][q].to_double() + w * (loss(p, q) - gain(p, q)).to_double();
    return;
  }
  // Cumulant reference (theory.md §17.11): the host's f carries Σ_k a_k,h S_k(X2) in the Lorentz
  // operator, the tracer's f⁰ = f_M,0 Σ_k a_k,0 S_k(X1) in the source −v·∇f⁰ = −(v/n0) f⁰ ∇n0.
  const std::vector<double>&host = hcs.cumulants[1], &own = hcs.cumulants[0];
  // The weighted moments also hold the cross part, whose contraction needs √θ0 rational: the width
  // becomes the square of a continued-fraction convergent of √θ0 (within 1e-12, as in MixtureNavierStokes).
  const Rational root = detail::nearby_rational(std::sqrt(theta0_), 1L << 26);
  const CollisionPair rational_pair{d, tracer.mass_ratio.exact(), Rational(1), root * root, Rational(1)};
  const auto weighted =
      weighted_pair_operator_matrices<Rational>(rational_pair, alpha, 1, n, static_cast<int>(host.size()) - 1);
  for (int p = 0; p < max_order; ++p)
    for (int q = 0; q < max_order; ++q) {
      double lorentz = 0;
      for (std::size_t k = 0; k < host.size(); ++k)
        if (host[k] != 0) lorentz -= host[k] * weighted.self[k](p, q).to_double();
      matrix_[p][q] = zeta * pieces.d[p][q].to_double() + w * lorentz;
    }
  const auto averages = detail::cumulant_sources(d, n, 0, static_cast<int>(own.size()) - 1);
  for (int p = 0; p < max_order; ++p)
    for (std::size_t k = 2; k < own.size(); ++k)
      source_[static_cast<std::size_t>(p)] += own[k] * averages.weight[static_cast<std::size_t>(p)][k] / (0.5 * d);
}

double TracerDiffusion::coefficient(int order) const {
  if (order < 1 || order > max_order_)
    throw std::invalid_argument("order: must be an integer in [1, " + std::to_string(max_order_) + "]");
  Eigen::MatrixXd m(order, order);
  for (int p = 0; p < order; ++p)
    for (int q = 0; q < order; ++q) m(p, q) = matrix_[p][q];
  Eigen::VectorXd e(order);
  for (int p = 0; p < order; ++p) e(p) = source_[static_cast<std::size_t>(p)];
  const double inverse00 = m.partialPivLu().solve(e)(0);
  return prefactor_ * inverse00;
}

TruncationEstimate TracerDiffusion::estimate(int order) const {
  // Rule (6.3) of docs/theory.md §6: order + 3 where the changes change sign, if the operator has it.
  return estimate_truncation_checked(Rational::from_double(coefficient(order)),
                                     Rational::from_double(coefficient(order + 1)),
                                     Rational::from_double(coefficient(order + 2)), [&]() -> std::optional<Rational> {
                                       if (order + 3 > max_order_) return std::nullopt;
                                       return Rational::from_double(coefficient(order + 3));
                                     });
}

}  // namespace gkt
