// The check that a rough free-cooling trajectory has reached a Sonine homogeneous cooling state (theory.md §19.13,
// §19.24): shared by the linear- and nonlinear-scheme evolution tests.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "gkt/evolution/rough_cooling_evolution.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_state.hpp"

namespace gkt::test {

/// Expects ζ*, every cumulant a_pq, every orientation coefficient b_pq (to 1e-8) and, in 3D, C (to 1e-9) of the
/// trajectory's sample `end` to equal those of the cooling state `steady`; θ is the caller's (β = −1 has none).
inline void expect_sample_at_cooling_state(const RoughEvolutionSample& end, const RoughSonineCoolingState& steady,
                                           int dimension, const std::string& where) {
  EXPECT_NEAR(end.cooling_rate, steady.cooling_rate, 1e-8) << where;
  ASSERT_EQ(end.cumulants.size(), steady.cumulants.size());
  for (std::size_t w = 0; w < steady.cumulants.size(); ++w)
    EXPECT_NEAR(end.cumulants[w], steady.cumulants[w], 1e-8)
        << where << " a" << steady.indices[w][0] << steady.indices[w][1];
  ASSERT_EQ(end.orientation_coefficients.size(), steady.orientation_coefficients.size());
  for (std::size_t o = 0; o < steady.orientation_coefficients.size(); ++o)
    EXPECT_NEAR(end.orientation_coefficients[o], steady.orientation_coefficients[o], 1e-8) << where;
  if (dimension == 3) {
    EXPECT_NEAR(end.orientation_correlation, steady.orientation_correlation, 1e-9) << where;
  }
}

}  // namespace gkt::test
