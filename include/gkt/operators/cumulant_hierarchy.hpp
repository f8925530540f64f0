// The cumulant (moment) hierarchy of the scaled Boltzmann equation of the homogeneous cooling
// state, truncated at a_K (docs/theory.md (9.2)–(9.4)), in double: the equations the HCS solver
// zeroes and the time evolution integrates. The operators build it from the bilinear collision
// moments (homogeneous_cooling_state.hpp at constant α, viscoelastic_hierarchy.hpp as a series in δ').
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace gkt {

/// The hierarchy at one restitution. Vectors a hold a_0 = 1, a_1 = 0, a_2 … a_K. The tensors are
/// stored row-major: T(p; k, l) at (p(K+1) + k)(K+1) + l, E(k, l) and C(k, l) at k(K+1) + l.
class CumulantHierarchy {
 public:
  /// Takes T(p; k, l) = ⟨S_k S_l Δ S_p⟩/J0, E(k, l), C(k, l) (sizes (K+1)³, (K+1)², (K+1)²), the
  /// derivative weights w[p][k] = ⟨x S_p' S_k⟩ and the norms N_p (theory.md (9.2)–(9.3)).
  CumulantHierarchy(int dimension, int k_max, std::vector<double> t, std::vector<double> e, std::vector<double> c,
                    std::vector<std::vector<double>> w, std::vector<double> norms);
  /// Returns the spatial dimension d.
  [[nodiscard]] int dimension() const { return dimension_; }
  /// Returns the largest Sonine index K.
  [[nodiscard]] int k_max() const { return k_max_; }
  /// Returns R_1(a) = Σ a_k a_l E(k, l); ζ* = −((d+2)/(2d)) R_1 (9.4).
  [[nodiscard]] double energy_moment(const std::vector<double>& a) const;
  /// Returns ⟨1⟩_a = Σ a_k a_l C(k, l): the collision rate relative to the Maxwellian one.
  [[nodiscard]] double collision_rate(const std::vector<double>& a) const;
  /// Returns ∂R_1/∂a_q and ∂⟨1⟩_a/∂a_q for q = 0..K.
  void gradients(const std::vector<double>& a, std::vector<double>& energy, std::vector<double>& rate) const;
  /// Writes F_p(a), p = 2..K, to f[p − 2] and, if jacobian is not null, ∂F_p/∂a_q to
  /// (*jacobian)[(p − 2)(K − 1) + q − 2].
  void residual(const std::vector<double>& a, std::vector<double>& f, std::vector<double>* jacobian) const;
  /// Returns N_p = ⟨S_p S_p⟩ under the Maxwellian (the mass matrix of ∂_t a_p).
  [[nodiscard]] double norm(int p) const { return norms_[static_cast<std::size_t>(p)]; }

  /// Overwrites T and E with the power series T = Σ_J x^J transfer_series[J], E = Σ_J x^J
  /// energy_series[J] (J = 0 … size − 1, summed in increasing J; theory.md (13.2)): the δ'-dependent
  /// tensors of viscoelastic spheres at x = δ'. Each term has the layout of T resp. E; C, w and N_p
  /// are kept. Allocation-free (the ODE hot path). Throws std::invalid_argument if the two series
  /// differ in length, are empty, or a term's size is not (K+1)³ resp. (K+1)².
  void assign_power_series(double x, std::span<const std::vector<double>> transfer_series,
                           std::span<const std::vector<double>> energy_series);

 private:
  int dimension_, k_max_;
  std::vector<double> t_, e_, c_;
  std::vector<std::vector<double>> w_;
  std::vector<double> norms_;
};

}  // namespace gkt
