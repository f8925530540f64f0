// Test adapter: the library's DSMC of the homogeneous cooling state (gkt/simulation/
// homogeneous_dsmc.hpp; Bird's scheme, independent of the Sonine engine), one run reduced to batch
// means with standard errors. Velocities are rescaled to unit temperature between samples (the
// scaled HCS is invariant under rescaling; for a speed-dependent restitution at fixed δ' too, since
// it sees u = σ̂·g/√(2T/m)).
#pragma once

#include <cstdint>
#include <vector>

#include "gkt/simulation/homogeneous_dsmc.hpp"

namespace gkt::test {

/// Returns the mean of batch values and its standard error (batches taken as independent).
inline void batch_mean(const std::vector<double>& x, double& mean, double& error) {
  const auto e = gkt::mean_and_error(x);
  mean = e.mean;
  error = e.error;
}

/// Returns the schedule of one run: `relax` collisions per particle of relaxation, `batches`
/// batches of `per_batch` collisions per particle.
inline gkt::DsmcSchedule schedule(int particles, double relax, int batches, double per_batch, std::uint64_t seed) {
  gkt::DsmcSchedule s;
  s.particles = particles;
  s.relaxation = relax;
  s.batches = batches;
  s.per_batch = per_batch;
  s.seed = seed;
  return s;
}

/// Sample means of the reduced moments ⟨c^4⟩, ⟨c^6⟩ (c = v/√(2T/m)) with batch-mean errors.
struct HcsMoments {
  double c4 = 0, c4_error = 0, c6 = 0, c6_error = 0;
};

/// Runs the library DSMC with restitution `restitution` and returns the batch-mean moments.
inline HcsMoments run_hcs_dsmc(int d, const gkt::SmoothRestitution& restitution, int particles, double relax,
                               int batches, double per_batch, std::uint64_t seed) {
  const auto run = gkt::run_smooth_hcs_dsmc(d, restitution, schedule(particles, relax, batches, per_batch, seed));
  HcsMoments m;
  batch_mean(run.c4, m.c4, m.c4_error);
  batch_mean(run.c6, m.c6, m.c6_error);
  return m;
}

/// Constant restitution α.
inline HcsMoments run_hcs_dsmc(int d, double alpha, int particles, double relax, int batches, double per_batch,
                               std::uint64_t seed) {
  gkt::SmoothRestitution r;
  r.alpha = alpha;
  return run_hcs_dsmc(d, r, particles, relax, batches, per_batch, seed);
}

}  // namespace gkt::test
