// Test adapter: the library's DSMC of the homogeneous cooling state of a dilute granular mixture
// (gkt/simulation/homogeneous_dsmc.hpp: no Sonine expansion, no cooling-rate formula), one run
// reduced to batch means with standard errors.
#pragma once

#include <cstdint>
#include <vector>

#include "dsmc.hpp"

namespace gkt::test {

/// Batch means with their standard errors: T_i/T and a2,i = ⟨c⁴⟩_i/(d(d+2)/4) − 1 per species.
struct MixtureHcsSample {
  std::vector<double> temperature_ratio, temperature_ratio_error, a2, a2_error;
};

/// Runs the DSMC with `counts[i]` particles of mass `mass[i]` and diameter `diameter[i]`,
/// restitution alpha[i·s + j]; `relax` collisions per particle of relaxation, then `batches`
/// batches of `per_batch` collisions per particle.
inline MixtureHcsSample run_mixture_hcs_dsmc(int d, const std::vector<int>& counts, const std::vector<double>& mass,
                                             const std::vector<double>& diameter, const std::vector<double>& alpha,
                                             double relax, int batches, double per_batch, std::uint64_t seed) {
  std::vector<gkt::DsmcSpecies> species;
  for (std::size_t a = 0; a < counts.size(); ++a) species.push_back({counts[a], mass[a], diameter[a]});
  const auto run = gkt::run_mixture_hcs_dsmc(d, species, alpha, schedule(0, relax, batches, per_batch, seed));
  const std::size_t s = counts.size();
  MixtureHcsSample out;
  out.temperature_ratio.resize(s);
  out.temperature_ratio_error.resize(s);
  out.a2.resize(s);
  out.a2_error.resize(s);
  for (std::size_t a = 0; a < s; ++a) {
    batch_mean(run.temperature_ratio[a], out.temperature_ratio[a], out.temperature_ratio_error[a]);
    batch_mean(run.a2[a], out.a2[a], out.a2_error[a]);
  }
  return out;
}

}  // namespace gkt::test
