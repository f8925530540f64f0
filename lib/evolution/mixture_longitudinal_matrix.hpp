// Private: the longitudinal-mode matrix of a mixture's HCS as an Eigen matrix, for the critical
// wave number search in hcs_stability.cpp and for the tests' eigenvalue checks.
#pragma once

#include <Eigen/Dense>

#include "gkt/evolution/hcs_stability.hpp"

namespace gkt {

/// Returns the (s+2)×(s+2) matrix of the longitudinal modes (ρ_1 … ρ_s, θ, w∥), ρ_i = δn_i/n_i:
/// ∂_τ X = M X at k* (theory.md (17.14), dense (18.13)).
Eigen::MatrixXcd mixture_longitudinal_matrix(const MixtureStabilityInput& in, double k);

}  // namespace gkt
