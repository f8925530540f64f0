// The HCS tail amplitude 𝒜 of φ ~ 𝒜 c^γ e^{−A c} (docs/theory.md §10.7): the pointwise collision
// integrals conserve mass and give the Maxwellian's energy loss; bad input is rejected. (The amplitude
// itself costs ≈ 10 s of CPU even at N = 6 in 2D: not in the suite; theory.md §10.7.)
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "gkt/transport/monodisperse/hcs_tail_amplitude.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

// ∫ J*[f_M, f_M] d²c = 0 and ∫ c² J* d²c = −ν(1 − α²)/2 (ζ_r = ν(1 − α²)/d for the Maxwellian, ν of
// theory.md (9.4)), from G − ν φ at each c (composite Gauss–Legendre in c on [0, 5.5]).
TEST(HcsTailAmplitude, PointwiseCollisionIntegralsConserveMassAndLoseTheMaxwellianEnergy) {
  const double alpha = 0.5;
  auto log_maxwellian = [](double c) { return -c * c - std::log(kPi); };
  static const double x[4] = {0.0694318442029737, 0.3300094782075719, 0.6699905217924281, 0.9305681557970263};
  static const double w[4] = {0.1739274225687269, 0.3260725774312731, 0.3260725774312731, 0.1739274225687269};
  double mass = 0, energy = 0;
  for (int panel = 0; panel < 22; ++panel)
    for (int i = 0; i < 4; ++i) {
      const double c = 0.25 * (panel + x[i]), wc = 0.25 * w[i];
      const auto gl = gkt::boltzmann_gain_loss(2, alpha, c, log_maxwellian);
      const double j = (gl.gain_ratio - gl.loss) * std::exp(log_maxwellian(c)) * 2 * kPi * c;
      mass += wc * j;
      energy += wc * c * c * j;
    }
  const double nu = std::sqrt(2 * kPi);
  EXPECT_NEAR(mass, 0, 2e-4);
  EXPECT_NEAR(energy, -nu * (1 - alpha * alpha) / 2, 1e-4);
}

TEST(HcsTailAmplitude, RejectsBadInput) {
  EXPECT_THROW(gkt::hcs_tail_amplitude(4, 0.5, 6), std::invalid_argument);
  EXPECT_THROW(gkt::hcs_tail_amplitude(3, 1.0, 6), std::invalid_argument);
  EXPECT_THROW(gkt::hcs_tail_amplitude(3, 0.5, 2), std::invalid_argument);
  EXPECT_THROW(gkt::boltzmann_gain_loss(2, 0.5, -1, [](double c) { return -c * c; }), std::invalid_argument);
}
