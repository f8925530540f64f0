// One axis of gkt's per-cell interpolation tables (binary and ternary mixture tables): the
// Chebyshev–Lobatto points of an interval and barycentric interpolation on them ([berrut2004]).
#pragma once

#include <span>
#include <vector>

namespace gkt {

/// Chebyshev–Lobatto points of [low, high] and their barycentric weights (−1)^k, halved at the ends
/// ([berrut2004] eq. 5.2); a single node when the interval is degenerate (high = low).
struct ChebyshevAxis {
  std::vector<double> nodes;    ///< the points, from low to high
  std::vector<double> weights;  ///< their barycentric weights
  /// Builds `count` ≥ 2 points on [low, high] (one point when high = low).
  ChebyshevAxis(int count, double low, double high);
  /// Returns the point at angle π·position/(K − 1) of the axis (position may be fractional).
  [[nodiscard]] double at_angle(double position) const;
  /// Fills the first K entries of w (w.size() ≥ K) with the barycentric factors at t, normalised
  /// to sum 1 (one-hot at a node).
  void factors(double t, std::span<double> w) const;
};

}  // namespace gkt
