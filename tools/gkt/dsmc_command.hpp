// `gkt dsmc`: the direct simulation Monte Carlo of a homogeneous granular gas (the library's
// gkt/simulation/homogeneous_dsmc.hpp) from a scene, averaged over independent runs.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "table_writer.hpp"

namespace gkt::cli {

/// How the runs are carried out; none of it changes the output.
struct DsmcRunOptions {
  int jobs = 1;                                                       ///< runs simulated in parallel
  std::function<void(std::size_t done, std::size_t total)> progress;  ///< called as runs finish (main thread)
  std::function<bool()> stop;  ///< polled before each run starts: true leaves the rest unstarted
};

/// Returns the table of a DSMC scene (overrides applied): one row of canonical coefficients with
/// `<name>_error` columns (mean and standard error over the independent runs), or with
/// [output] distribution = true the speed histogram, or with haff = true T(t)/T0 against Haff's law.
/// Throws std::invalid_argument naming the field on bad input. Sets `interrupted` (no rows) when
/// options.stop asked to stop before every run was done.
Table dsmc(toml::table scene, const DsmcRunOptions& options, bool& interrupted);

}  // namespace gkt::cli
