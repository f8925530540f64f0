// Prints the long sequences that theory.md §6 replays the tolerance scans on (turning-point rule (6.3)):
// the smooth-inelastic model's values at Sonine orders 1 … 23 (dilute, standard scheme, nonlinear HCS:
// a2, a3, ζ* from the HCS keeping a_2 … a_{N+1}, η*, κ*, μ* at order N about it) and the tail scheme's
// (power-law space) at resolutions 1 … 24, one CSV line per value, %.17g.
//
//   build/bin/gkt_truncation_sequences 2 0.5 0.6 0.7 > sequences_2d.csv
//   python3 tools/truncation_survey.py sequences_2d.csv sequences_3d.csv
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"
#include "gkt/transport/monodisperse/tail_galerkin.hpp"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: gkt_truncation_sequences DIMENSION ALPHA...\n");
    return 2;
  }
  const int d = std::atoi(argv[1]);
  constexpr int kSonine = 23;
  gkt::HomogeneousCoolingState hcs(d);
  gkt::NavierStokesSolver ns(d);
  std::printf(
      "scheme,dimension,alpha,order,a2,a3,cooling_rate,shear_viscosity,thermal_conductivity,"
      "density_heat_coefficient\n");
  for (int i = 2; i < argc; ++i) {
    const double alpha = std::atof(argv[i]);
    const gkt::Rational exact = gkt::Rational::parse(argv[i]);
    for (int n = 1; n <= kSonine; ++n) {
      const gkt::HcsState s = hcs.solve(exact, n + 1, gkt::HcsScheme::nonlinear);
      if (!s.solved) continue;
      const gkt::NavierStokesValues v = ns.solve(exact, n, s.a);
      std::printf("sonine,%d,%s,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", d, argv[i], n, s.a[2],
                  s.a.size() > 3 ? s.a[3] : 0.0, s.cooling_rate, v.shear_viscosity, v.thermal_conductivity,
                  v.density_heat_coefficient);
      std::fflush(stdout);
    }
    const auto tail = gkt::tail_galerkin_sequence(d, alpha, gkt::kTailGalerkinMaxOrder, gkt::TailTrialSpace::power_law);
    for (const auto& t : tail)
      if (t.solved)
        std::printf("tail,%d,%s,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", d, argv[i], t.order, t.a2, t.a3,
                    t.cooling_rate, t.shear_viscosity, t.thermal_conductivity, t.density_heat_coefficient);
    std::fflush(stdout);
  }
  return 0;
}
