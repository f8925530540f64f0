// libFuzzer target: the per-cell library calls a hydrodynamic solver makes — first_sonine_values,
// enskog_first_sonine_values and BinaryTransportTable::evaluate (dilute and dense tables built once).
// Input bytes: one selector byte (entry point, dimension), then doubles (8 bytes each, native order,
// zero-padded). Contract: each call accepts only arguments inside its documented range and then
// returns finite values with ζ ≥ 0, η > 0, p > 0 (the dense table's documented all-nan answer above
// its φ_max excepted), or throws std::invalid_argument; anything else aborts.
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "gkt/transport/closed_forms/enskog_closed_form.hpp"
#include "gkt/transport/closed_forms/first_sonine_formulas.hpp"
#include "gkt/transport/mixture/mixture_transport_table.hpp"

namespace {

/// Reads the k-th double after the selector byte (missing bytes are zero).
double number(const std::uint8_t* data, std::size_t size, std::size_t k) {
  unsigned char bytes[sizeof(double)] = {};
  const std::size_t at = 1 + k * sizeof(double);
  if (at < size) std::memcpy(bytes, data + at, std::min(sizeof(double), size - at));
  double x;
  std::memcpy(&x, bytes, sizeof x);
  return x;
}

/// Aborts (a finding) unless `condition` holds.
void require(bool condition) {
  if (!condition) std::abort();
}

void require_finite(double x) { require(std::isfinite(x)); }

/// A 3D binary (m2/m1 = 2.5, σ2/σ1 = 1.5, α = 0.8) tabulated at order 1: dilute, or dense up to
/// φ = 0.1 (small grids: built once, before fuzzing starts, under the sanitizers).
const gkt::BinaryTransportTable& table(bool dense) {
  static const auto mixture = gkt::make_mixture(3, {{1.0, 1.0, 0.5, ""}, {2.5, 1.5, 0.5, ""}}, 0.8);
  static const gkt::BinaryTransportTable dilute(mixture, 1, 7);
  static const gkt::BinaryTransportTable packed(mixture, 1, 5, 0.1, 3);
  return dense ? packed : dilute;
}

void check(const gkt::BinaryTransport& t, bool all_nan_allowed) {
  const double values[] = {t.cooling_rate,
                           t.temperature_ratio[0],
                           t.temperature_ratio[1],
                           t.shear_viscosity,
                           t.thermal_conductivity,
                           t.mutual_diffusion[0],
                           t.mutual_diffusion[1],
                           t.mutual_diffusion[2],
                           t.mutual_diffusion[3],
                           t.thermal_diffusion[0],
                           t.thermal_diffusion[1],
                           t.pressure_diffusion[0],
                           t.pressure_diffusion[1],
                           t.dufour[0],
                           t.dufour[1],
                           t.pressure,
                           t.bulk_viscosity,
                           t.cooling_rate_first_order};
  if (all_nan_allowed && std::isnan(values[0])) {
    for (double v : values)
      if (!std::isnan(v)) std::abort();
    return;
  }
  for (double v : values) require_finite(v);
  require(t.cooling_rate >= 0 && t.temperature_ratio[0] > 0 && t.temperature_ratio[1] > 0 && t.shear_viscosity > 0 &&
          t.pressure > 0);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const auto start = std::chrono::steady_clock::now();
  const auto& dilute = table(false);
  const auto& dense = table(true);
  std::fprintf(stderr, "fuzz_per_cell: tables built in %.1f s: %d nodes (error %.2g), %d x %d nodes (error %.2g)\n",
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), dilute.fraction_nodes(),
               dilute.interpolation_error(), dense.fraction_nodes(), dense.packing_nodes(),
               dense.interpolation_error());
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const int selector = data[0] % 4;
  // Dimensions 2 and 3 mostly, sometimes another integer (which must be refused).
  const int dimension = (data[0] >> 2) % 8 == 7 ? static_cast<signed char>(data[0]) : 2 + ((data[0] >> 2) & 1);
  const double a = number(data, size, 0), b = number(data, size, 1), c = number(data, size, 2),
               e = number(data, size, 3);
  const bool valid_dimension = dimension == 2 || dimension == 3, valid_alpha = a > 0 && a <= 1;
  try {
    if (selector == 0) {
      const auto v = gkt::first_sonine_values(dimension, a);
      require(valid_dimension && valid_alpha);  // accepted only inside the documented ranges
      for (double x : {v.a2, v.cooling_rate, v.shear_viscosity, v.thermal_conductivity, v.density_heat_coefficient})
        require_finite(x);
      require(v.cooling_rate >= 0 && v.shear_viscosity > 0);
    } else if (selector == 1) {
      const auto v = gkt::enskog_first_sonine_values(dimension, a, {b, c, e});
      require(valid_dimension && valid_alpha && b >= 0 && b <= (dimension == 3 ? 0.5 : 0.7) && c >= 1 &&
              std::isfinite(c) && e >= 0 && std::isfinite(e));
      for (double x : {v.a2, v.cooling_rate, v.pressure, v.shear_viscosity, v.bulk_viscosity, v.thermal_conductivity,
                       v.density_heat_coefficient, v.cooling_rate_first_order})
        require_finite(x);
      require(v.cooling_rate >= 0 && v.pressure >= 1 && v.shear_viscosity > 0 && v.bulk_viscosity >= 0);
    } else {
      const bool dense = selector == 3;
      const gkt::BinaryTransport t = table(dense).evaluate(a, b, c);
      require(a >= 0 && a <= 1 && b > 0 && std::isfinite(b) && c > 0 && std::isfinite(c));
      check(t, dense);
    }
  } catch (const std::invalid_argument&) {
    // the one acceptable answer to bad input
  }
  return 0;
}
