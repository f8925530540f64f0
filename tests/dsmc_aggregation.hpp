// Test adapter: the library's DSMC of a homogeneous gas of sticking grains
// (gkt/simulation/homogeneous_dsmc.hpp: run_aggregation_dsmc), independent of the population balance.
#pragma once

#include "dsmc.hpp"

namespace gkt::test {

using gkt::run_aggregation_dsmc;

}  // namespace gkt::test
