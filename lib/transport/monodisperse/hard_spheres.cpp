#include "gkt/transport/monodisperse/hard_spheres.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "gkt/operators/linearized_operator.hpp"

namespace gkt {

namespace {
struct Setup {
  OperatorPart part;
  int rank;
  int first;  // first Sonine index kept (1 for heat: S_0 c is momentum, conserved)
};
constexpr std::array<Setup, 3> kSetups{
    {{OperatorPart::full, 2, 0}, {OperatorPart::full, 1, 1}, {OperatorPart::tracer, 1, 0}}};
}  // namespace

HardSphereSonineSystem::HardSphereSonineSystem(int dimension) : dimension_(dimension) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
}

void HardSphereSonineSystem::ensure_built(std::size_t c, int n_max) {
  if (n_max <= built_[c]) return;
  // Only the matrix asked for is built; with headroom, so that stepping through orders one
  // by one does not rebuild each time.
  const int target = std::max(n_max, std::min(2 * built_[c], kHardSphereMaxOrder + 3));
  matrices_[c] =
      linearized_operator_matrix<Rational>(dimension_, Rational(1), kSetups[c].part, kSetups[c].rank, target);
  built_[c] = target;
}

Rational HardSphereSonineSystem::reduced_coefficient(HardSphereCoefficient c, int order) {
  if (order < 1 || order > kHardSphereMaxOrder + 3)
    throw std::invalid_argument("order: must be in [1, " + std::to_string(kHardSphereMaxOrder) + "], got " +
                                std::to_string(order));
  const auto k = static_cast<std::size_t>(c);
  auto& cache = values_[k];
  if (cache.size() >= static_cast<std::size_t>(order)) return cache[static_cast<std::size_t>(order) - 1];
  const Setup& s = kSetups[k];
  ensure_built(k, s.first + order);
  // Reduction to the elastic first-Sonine reference (docs/theory.md eq. 5.4–5.6):
  // η* = (d−1)(L⁻¹)_00, κ* = (d−1)(L⁻¹)_11, D* = (L⁻¹)_00.
  const Rational factor = c == HardSphereCoefficient::self_diffusion ? Rational(1) : Rational(dimension_ - 1);
  for (int n = static_cast<int>(cache.size()) + 1; n <= order; ++n)
    cache.push_back(factor * solve_first_component(matrices_[k], s.first, n));
  return cache[static_cast<std::size_t>(order) - 1];
}

TruncationEstimate HardSphereSonineSystem::estimate(HardSphereCoefficient c, int order) {
  if (order < 1 || order > kHardSphereMaxOrder)
    throw std::invalid_argument("order: must be in [1, " + std::to_string(kHardSphereMaxOrder) + "], got " +
                                std::to_string(order));
  const auto k = static_cast<std::size_t>(c);
  auto& cache = estimates_[k];
  const auto slot = static_cast<std::size_t>(order) - 1;
  if (cache.size() <= slot) cache.resize(slot + 1);
  if (!cache[slot]) {
    ensure_built(k, kSetups[k].first + order + 2);
    // Rule (6.3) of docs/theory.md §6, shared by every Sonine scan: order + 3 only where the changes change sign.
    cache[slot] = estimate_truncation_checked(
        reduced_coefficient(c, order), reduced_coefficient(c, order + 1), reduced_coefficient(c, order + 2),
        [&] { return std::optional<Rational>(reduced_coefficient(c, order + 3)); });
  }
  return *cache[slot];
}

double reference_shear_viscosity(int dimension, double mass, double temperature, double diameter) {
  const double d = dimension;
  return (d + 2) * std::tgamma(d / 2) / (8 * std::pow(std::numbers::pi, (d - 1) / 2)) * std::pow(diameter, 1 - d) *
         std::sqrt(mass * temperature);
}

double reference_thermal_conductivity(int dimension, double mass, double temperature, double diameter) {
  const double d = dimension;
  return d * (d + 2) / (2 * (d - 1)) * reference_shear_viscosity(dimension, mass, temperature, diameter) / mass;
}

double reference_self_diffusion(int dimension, double mass, double temperature, double diameter, double density) {
  const double d = dimension;
  return d * std::tgamma(d / 2) / (4 * std::pow(std::numbers::pi, (d - 1) / 2)) * std::sqrt(temperature / mass) /
         (density * std::pow(diameter, d - 1));
}

}  // namespace gkt
