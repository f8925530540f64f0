// Test adapter: the library's DSMC of the homogeneous cooling state of rough spheres (d = 3) or
// disks (d = 2) (gkt/simulation/homogeneous_dsmc.hpp, independent of the engine), one run reduced
// to batch means with standard errors. v and w are rescaled by one common factor to ⟨v²⟩ = d/2
// after every N collisions (the HCS, and θ, are invariant under common rescaling).
#pragma once

#include <cstdint>
#include <limits>

#include "dsmc.hpp"

namespace gkt::test {

/// Batch means and standard errors of θ = T_r/T_t, the cumulants a20, a02, a11, a03 and C.
struct RoughHcsSample {
  double theta = 0, theta_error = 0, a20 = 0, a20_error = 0, a02 = 0, a02_error = 0, a11 = 0, a11_error = 0;
  double a03 = 0, a03_error = 0;                  ///< spin sixth-moment ratio (§19.32)
  double orientation = 0, orientation_error = 0;  ///< C = ⟨(v·w)²/(v²w²)⟩ (d = 3)
};

/// Runs the DSMC from Maxwellians at θ = theta_start; a finite `friction` is Walton's μ_f, a nonzero
/// `dilatation` the uniform ∇·u = ε ν0(T_t).
inline RoughHcsSample run_rough_hcs_dsmc(int d, double alpha, double beta, double kappa, double theta_start,
                                         int particles, double relax, int batches, double per_batch, std::uint64_t seed,
                                         double friction = std::numeric_limits<double>::infinity(),
                                         double dilatation = 0) {
  gkt::RoughDsmcParameters p;
  p.alpha = alpha;
  p.beta = beta;
  p.kappa = kappa;
  p.friction = friction;
  p.initial_temperature_ratio = theta_start;
  p.dilatation = dilatation;
  const auto run = gkt::run_rough_hcs_dsmc(d, p, schedule(particles, relax, batches, per_batch, seed));
  RoughHcsSample s;
  batch_mean(run.temperature_ratio, s.theta, s.theta_error);
  batch_mean(run.a20, s.a20, s.a20_error);
  batch_mean(run.a02, s.a02, s.a02_error);
  batch_mean(run.a11, s.a11, s.a11_error);
  batch_mean(run.a03, s.a03, s.a03_error);
  batch_mean(run.orientation, s.orientation, s.orientation_error);
  return s;
}

}  // namespace gkt::test
