#include "gkt/transport/mixture/mixture.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "gkt/transport/common/pair_correlation.hpp"
#include "transport/common/alpha_polynomial.hpp"

namespace gkt {

namespace {
std::string number(double x) {  // shortest round-trip form
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return {buffer, result.ptr};
}
std::string species_field(const char* field, std::size_t i) { return std::string(field) + "_" + std::to_string(i + 1); }
/// Returns the diameter moments M_l = Σ x_i σ_i^l, l = 0 … 3, of the contact-value closures (16.1).
std::array<double, 4> diameter_moments(const std::vector<Species>& species) {
  std::array<double, 4> m{};
  for (const auto& sp : species) {
    double power = sp.fraction;
    for (double& moment : m) {
      moment += power;
      power *= sp.diameter;
    }
  }
  return m;
}
}  // namespace

void Mixture::validate() const {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  const std::size_t s = size();
  if (s < 2) throw std::invalid_argument("species: a mixture needs at least 2 species, got " + std::to_string(s));
  double sum = 0;
  for (std::size_t i = 0; i < s; ++i) {
    const Species& sp = species[i];
    if (!(sp.mass.value() > 0) || !std::isfinite(sp.mass.value()))
      throw std::invalid_argument(species_field("mass", i) + ": must be a number > 0, got " + number(sp.mass.value()));
    if (!(sp.diameter > 0) || !std::isfinite(sp.diameter))
      throw std::invalid_argument(species_field("diameter", i) + ": must be a number > 0, got " + number(sp.diameter));
    if (!(sp.fraction >= 0 && sp.fraction <= 1))  // 0: a tracer (the limit x_i → 0)
      throw std::invalid_argument(species_field("fraction", i) + ": must be a number in [0, 1], got " +
                                  number(sp.fraction));
    sum += sp.fraction;
  }
  if (std::abs(sum - 1) > 1e-12)
    throw std::invalid_argument("fraction: the species fractions must sum to 1 (within 1e-12), got " + number(sum));
  if (alpha.size() != s * s)
    throw std::invalid_argument("alpha: must be a number or an s x s matrix (s = " + std::to_string(s) + ")");
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j) {
      const double a = restitution(i, j);
      const std::string field = "alpha_" + std::to_string(i + 1) + "_" + std::to_string(j + 1);
      detail::require_restitution(a, field);
      if (a != restitution(j, i))
        throw std::invalid_argument(field + ": the restitution matrix must be symmetric, got " + number(a) + " and " +
                                    number(restitution(j, i)));
    }
  const double phi_max = max_packing_fraction(dimension).to_double();
  if (!(packing_fraction >= 0 && packing_fraction < phi_max))
    throw std::invalid_argument("packing_fraction: must be a number in [0, " + number(phi_max) +
                                ") for dimension = " + std::to_string(dimension) + ", got " + number(packing_fraction));
}

double Mixture::mean_mass() const {
  double m = 0;
  for (const auto& sp : species) m += sp.fraction * sp.mass.value();
  return m;
}

double Mixture::mean_diameter() const {
  double d = 0;
  for (const auto& sp : species) d += sp.fraction * sp.diameter;
  return d;
}

std::vector<double> Mixture::contact_values() const {
  const std::size_t s = size();
  const double phi = packing_fraction, g = 1 - phi;
  const auto [m0, m1, m2, m3] = diameter_moments(species);
  std::vector<double> chi(s * s);
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j) {
      const double si = species[i].diameter, sj = species[j].diameter, sij = 0.5 * (si + sj);
      if (dimension == 3) {  // [boublik1970], [mansoori1971]
        const double r = si * sj * m2 / (sij * m3);
        chi[i * s + j] = 1 / g + 1.5 * phi * r / (g * g) + 0.5 * phi * phi * r * r / (g * g * g);
      } else {  // [jenkins1987]
        const double r = si * sj * m1 / (sij * m2);
        chi[i * s + j] = 1 / g + (9.0 / 16.0) * phi * r / (g * g);
      }
    }
  return chi;
}

std::vector<double> Mixture::contact_value_derivatives() const {
  const std::size_t s = size();
  const double phi = packing_fraction, g = 1 - phi;
  const auto [m0, m1, m2, m3] = diameter_moments(species);
  // χ_ij = F(φ, y) with a = σ_iσ_j/σ_ij: 3D y = φ M2/M3 (φ ∝ Σ n_k σ_k³, y ∝ Σ n_k σ_k²), 2D y = φ M1/M2
  // (φ ∝ Σ n_k σ_k², y ∝ Σ n_k σ_k); n ∂χ/∂n_l = F_φ n ∂φ/∂n_l + F_y n ∂y/∂n_l.
  std::vector<double> out(s * s * s);
  const double top = dimension == 3 ? m3 : m2, y = phi * (dimension == 3 ? m2 / m3 : m1 / m2);
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j) {
      const double si = species[i].diameter, sj = species[j].diameter, a = si * sj / (0.5 * (si + sj));
      double f_phi = 0, f_y = 0;
      if (dimension == 3) {
        f_phi = 1 / (g * g) + 3 * a * y / (g * g * g) + 1.5 * a * a * y * y / (g * g * g * g);
        f_y = 1.5 * a / (g * g) + a * a * y / (g * g * g);
      } else {
        f_phi = 1 / (g * g) + (9.0 / 8.0) * a * y / (g * g * g);
        f_y = (9.0 / 16.0) * a / (g * g);
      }
      for (std::size_t l = 0; l < s; ++l) {
        const double sl = species[l].diameter, sl_top = dimension == 3 ? sl * sl * sl : sl * sl;
        const double sl_y = dimension == 3 ? sl * sl : sl;
        out[(i * s + j) * s + l] = phi / top * (f_phi * sl_top + f_y * sl_y);
      }
    }
  return out;
}

Mixture make_mixture(int dimension, std::vector<Species> species, double alpha, double packing_fraction) {
  Mixture m{dimension, std::move(species), {}, packing_fraction};
  m.alpha.assign(m.size() * m.size(), alpha);
  return m;
}

}  // namespace gkt
