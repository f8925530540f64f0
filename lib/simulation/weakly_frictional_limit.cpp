// The GNB ordering 1 − α² = r η_t, η_t → 0 (weakly_frictional_limit.hpp; docs/theory.md §19.32).
// Fokker–Planck coefficients of the scaled spin y, per collision in units of η_t²/κ² ((19.205)–(19.206)):
//   drift −a y² + a1 y + c0, second moment b y² + c1 y,
// c0 = ⟨|ŵ_⊥|²⟩ (2/3 spheres, 1 disks), c1 = 4⟨(ŵ1_⊥·ŵ2)²⟩ (8/9, 4), b = 4⟨|ŵ_⊥|⁴⟩ (32/15, 4), a = λb/2.
#include "gkt/simulation/weakly_frictional_limit.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace gkt {

namespace {

struct FokkerPlanckConstants {
  double c0, c1, b;
};

void check_dimension(int d) {
  if (d != 2 && d != 3) throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(d));
}

FokkerPlanckConstants constants(int d) {
  check_dimension(d);
  if (d == 3) return {2.0 / 3, 8.0 / 9, 32.0 / 15};
  return {1, 4, 4};
}

/// ⟨yⁿ⟩, n = 1, 2, 3, of the density (19.207) with drift slope a1 and cutoff λ > 0.
struct RawMoments {
  double y1, y2, y3;
};

RawMoments raw_moments(const FokkerPlanckConstants& k, double cutoff, double a1) {
  const double a = cutoff * k.b / 2, p = a1 + a * k.c1 / k.b;
  const double mu = 2 / k.b * (p - k.c0 * k.b / k.c1) - 1, small = 2 * k.c0 / k.c1 - 1;
  // trapezoid in s = ln y: the integrand decays like y^{small+1} at 0 and e^{−λy} at ∞
  const double h = 1e-2, top = std::log(50 / cutoff) + 4;
  double norm = 0, m1 = 0, m2 = 0, m3 = 0, shift = 0;
  bool first = true;
  for (double s = -60; s < top; s += h) {
    const double y = std::exp(s);
    const double log_weight = (small + 1) * s + mu * std::log(k.b * y + k.c1) - cutoff * y;
    if (first) {  // largest log weight is near y ~ 1: scale by the value at y = 1 to avoid overflow
      shift = mu * std::log(k.b + k.c1) - cutoff;
      first = false;
    }
    const double weight = std::exp(log_weight - shift);
    norm += weight;
    m1 += weight * y;
    m2 += weight * y * y;
    m3 += weight * y * y * y;
  }
  return {m1 / norm, m2 / norm, m3 / norm};
}

}  // namespace

WeaklyFrictionalHcs weakly_frictional_hcs(int d, double r, double kappa) {
  check_dimension(d);
  if (!(r >= 0 && std::isfinite(r)))
    throw std::invalid_argument("r: (1 − α²)/η_t must be a finite number >= 0, got " + std::to_string(r));
  if (!(kappa > 0 && kappa <= 1))
    throw std::invalid_argument("kappa: must be a number in (0, 1], got " + std::to_string(kappa));
  const double dr = d == 3 ? 3 : 1;
  WeaklyFrictionalHcs hcs;
  hcs.critical_ratio = 2 * (d - 1) * (d / (dr * kappa) - 1);  // (19.203)
  if (std::abs(r - hcs.critical_ratio) < 1e-12)
    throw std::invalid_argument("r: at r = r_c = " + std::to_string(hcs.critical_ratio) +
                                " neither branch of (19.201)–(19.202) holds");
  hcs.hot_spins = r > hcs.critical_ratio;
  if (hcs.hot_spins) {
    hcs.scaled_temperature_ratio = (r - hcs.critical_ratio) / (2 * (d - 1));  // (19.202)
  } else {
    const double q = dr * kappa * (r + 2 * (d - 1)) / (2 * d * (d - 1));  // (19.201)
    hcs.scaled_temperature_ratio = 1 / (1 - q);
  }
  return hcs;
}

WeaklyFrictionalSpinMoments weakly_frictional_spin_moments(int d, double cutoff) {
  const FokkerPlanckConstants k = constants(d);
  if (!(cutoff >= 0 && std::isfinite(cutoff)))
    throw std::invalid_argument("cutoff: λ must be a finite number >= 0, got " + std::to_string(cutoff));
  WeaklyFrictionalSpinMoments m;
  if (cutoff == 0) {  // (19.208): ⟨drift⟩ = a1 + c0 = 0, tail y^{−21/8} (spheres), y^{−5/2} (disks)
    m.drift_slope = -k.c0;
    m.y2 = m.y3 = std::numeric_limits<double>::infinity();
    return m;
  }
  // ⟨y⟩ grows with a1; the stationary ⟨drift⟩ = 0 with ⟨y⟩ = 1 fixes a1 (bisection)
  double lo = -k.c0 - 20, hi = cutoff * k.b / 2 + k.c0 + 20;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (raw_moments(k, cutoff, mid).y1 > 1 ? hi : lo) = mid;
  }
  m.drift_slope = 0.5 * (lo + hi);
  const RawMoments raw = raw_moments(k, cutoff, m.drift_slope);
  m.y2 = raw.y2 / (raw.y1 * raw.y1);
  m.y3 = raw.y3 / (raw.y1 * raw.y1 * raw.y1);
  return m;
}

double weakly_frictional_spin_tail_exponent(int d) {
  const FokkerPlanckConstants k = constants(d);
  return 2 + 2 * k.c0 / k.b;  // (19.208)
}

}  // namespace gkt
