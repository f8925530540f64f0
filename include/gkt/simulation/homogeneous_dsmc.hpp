// Direct simulation Monte Carlo of the spatially homogeneous inelastic Boltzmann equation (Bird
// 1994, ch. 11; Brey, Ruiz-Montero & Cubero 1996 for the scaled homogeneous cooling state):
// N particles in a volume V = N/n (n = 1, diameter σ̄ = 1, mass m̄ = 1, k_B = 1), pairs drawn
// uniformly and accepted with probability σ_ij^{d−1}|g|/(σ_max^{d−1} g_max), g_max = 2 max|v|
// (a majorant kept exact between rescalings), σ̂ drawn with density ∝ (σ̂·ĝ)_+. Each candidate
// advances the clock by 2/((N−1) β_d σ_max^{d−1} g_max), β_d = ∫dσ̂ Θ(σ̂·ĝ)(σ̂·ĝ) (π in 3D, 2 in
// 2D): no time step, so no time-step bias (docs/theory.md §21). Velocities are rescaled to a
// fixed temperature after every N accepted collisions and after each batch, with the centre-of-mass
// momentum removed at each rescaling; the physical temperature and time are kept through the
// accumulated scale factor. One call is one run; independent runs use dsmc_run_seed(seed, run).
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace gkt {

/// How long a run lasts and what it records.
struct DsmcSchedule {
  int particles = 0;             ///< N, at least 2 (all species together)
  double relaxation = 0;         ///< collisions per particle before the first batch, ≥ 0
  int batches = 0;               ///< number of samples, ≥ 1
  double per_batch = 0;          ///< collisions per particle per batch, > 0
  std::uint64_t seed = 0;        ///< seed of this run's RandomStream
  int histogram_bins = 0;        ///< bins of the speed histogram of c = |v|/√(2T/m) (0: none)
  double histogram_width = 0.1;  ///< bin width in c
};

/// A sample mean and its standard error.
struct DsmcEstimate {
  /// The sample mean and its standard error.
  /// @{
  double mean = 0, error = 0;
  /// @}
};

/// Returns the mean of `values` and its standard error √(s²/n), the values taken as independent
/// (error 0 for a single value); throws std::invalid_argument if `values` is empty.
DsmcEstimate mean_and_error(std::span<const double> values);

/// The clock of a run, read at the end of each batch: time t ν0(T0) and T(t)/T0, where T0 is the
/// temperature at the end of the relaxation and ν0(T) = nT/η0(T) (docs/conventions.md). With a
/// constant α the trace follows Haff's law T/T0 = (1 + ζ* t ν0(T0)/2)^{−2} once a2 has relaxed.
struct DsmcTrace {
  /// Per batch: the time t ν0(T0) and the temperature ratio T(t)/T0.
  /// @{
  std::vector<double> time, temperature;
  /// @}
};

/// The restitution of smooth grains: α constant (series empty), or the viscoelastic series
/// ε(u) = 1 + Σ_k h_k (δ' u^{1/5})^k at fixed δ' (u = σ̂·g/√(2T/m) at the current temperature: the
/// scaled HCS at fixed δ', Brilliantov & Pöschel 2004 §8; docs/theory.md §13).
struct SmoothRestitution {
  double alpha = 1;            ///< constant restitution in (0, 1] (ignored when series is given)
  std::vector<double> series;  ///< h_1, h_2, … (ViscoelasticRestitution::series())
  double delta_prime = 0;      ///< δ' ≥ 0
  /// Returns the restitution of a collision with normal speed u (units √(2T/m)).
  [[nodiscard]] double at(double u) const;
};

/// One run of a smooth one-component gas: per batch ⟨c⁴⟩, ⟨c⁶⟩ (c = v/√(2T/m)) and the cooling
/// rate ζ* = −Δln T/Δ(ν0 t) over the batch; the clock; the speed histogram (fraction of the
/// sampled particles per bin, all batches together).
struct SmoothDsmcRun {
  /// Per batch: ⟨c⁴⟩, ⟨c⁶⟩ (c = v/√(2T/m)) and the reduced cooling rate ζ*.
  /// @{
  std::vector<double> c4, c6, cooling_rate;
  /// @}
  /// The clock of the run.
  DsmcTrace trace;
  /// Fraction of the sampled particles per speed bin, all batches together (empty without bins).
  std::vector<double> speed_histogram;
};

/// Runs the DSMC of smooth disks (d = 2) or spheres (d = 3); throws std::invalid_argument naming
/// the field on a bad dimension, restitution, schedule or contact value. `pair_correlation` is the
/// contact value χ(φ) ≥ 1 of the dense gas: in a homogeneous state the Enskog collision operator is
/// χ times Boltzmann's (docs/theory.md (15.1), §21.7), so every collision takes 1/χ of the dilute
/// time; the clock and ζ* stay in units of the dilute ν0 (ζ* = χ ζ*_dilute), a2 and a3 do not change.
SmoothDsmcRun run_smooth_hcs_dsmc(int d, const SmoothRestitution& restitution, const DsmcSchedule& schedule,
                                  double pair_correlation = 1);

/// One species of a mixture: its number of particles, mass and diameter (units m̄, σ̄ of the
/// mixture are fixed by the caller: the clock uses m̄ = Σ x_i m_i and σ̄ = Σ x_i σ_i).
struct DsmcSpecies {
  /// Number of particles of this species.
  int count = 0;
  /// Mass and diameter of this species.
  /// @{
  double mass = 1, diameter = 1;
  /// @}
};

/// One run of a mixture: per species and batch T_i/T and a2,i = ⟨c⁴⟩_i/(d(d+2)/4) − 1
/// (c² = m_i v²/(2T_i)); per batch ζ* (ν0 of the one-component gas of mass m̄ and diameter σ̄).
struct MixtureDsmcRun {
  /// Per species and batch ([species][batch]): T_i/T and a2,i.
  /// @{
  std::vector<std::vector<double>> temperature_ratio, a2;  ///< [species][batch]
  /// @}
  /// Per batch: the reduced cooling rate ζ*.
  std::vector<double> cooling_rate;
  /// The clock of the run.
  DsmcTrace trace;
};

/// Runs the DSMC of a mixture with restitution alpha[i·s + j] (symmetric, each in (0, 1]);
/// `schedule.particles` is ignored (the counts give N); throws std::invalid_argument on bad input.
MixtureDsmcRun run_mixture_hcs_dsmc(int d, const std::vector<DsmcSpecies>& species, const std::vector<double>& alpha,
                                    const DsmcSchedule& schedule);

/// Rough spheres (d = 3) or disks (d = 2; spin along z): normal restitution α, tangential β
/// (constant, or Walton's β(γ) = min{β, −1 + ((1+κ)/κ)(1+α) μ_f cot γ} for a finite friction μ_f,
/// docs/theory.md §19.10), reduced moment of inertia κ = 4I/(mσ²).
struct RoughDsmcParameters {
  /// Normal restitution α, tangential restitution β and reduced moment of inertia κ = 4I/(mσ²).
  /// @{
  double alpha = 1, beta = -1, kappa = 0.4;
  /// @}
  double friction = std::numeric_limits<double>::infinity();  ///< μ_f ≥ 0; +∞: constant β
  double initial_temperature_ratio = 1;                       ///< θ = T_r/T_t of the initial Maxwellians
  /// Uniform dilatation ∇·u = ε ν0(T_t) (ε = dilatation): peculiar velocities shrink as
  /// dV/dt = −(∇·u/d)V, the spins are untouched (docs/theory.md §19.7).
  double dilatation = 0;
};

/// One run of rough grains: per batch θ = T_r/T_t, the cumulants a20, a02, a11 (docs/theory.md
/// §19.6), the spin's sixth-moment ratio a03 (§19.32), the orientation correlation C = ⟨(v·w)²/(v²w²)⟩ (§19.8) and ζ*
/// (ν0 of T_t, so the translational cooling rate); the clock of T_t; the histogram of the translational speed.
struct RoughDsmcRun {
  /// Per batch: θ = T_r/T_t, the cumulants a20, a02, a11, a03 = ⟨w⁶⟩ d_r²/(⟨w²⟩³(d_r+2)(d_r+4)) − 1
  /// (0 for a Maxwellian spin), the orientation correlation C and ζ*.
  /// @{
  std::vector<double> temperature_ratio, a20, a02, a11, a03, orientation, cooling_rate;
  /// @}
  /// The clock of the translational temperature T_t.
  DsmcTrace trace;
  /// Fraction of the sampled particles per translational speed bin, all batches together.
  std::vector<double> speed_histogram;
};

/// Runs the DSMC of rough grains; throws std::invalid_argument naming the field on bad input.
RoughDsmcRun run_rough_hcs_dsmc(int d, const RoughDsmcParameters& parameters, const DsmcSchedule& schedule);

/// The state of a gas of sticking grains at one sample time, and the events of the window since the
/// previous sample.
struct AggregationDsmcSample {
  double number = 0;       ///< N(t)/N(0)
  double temperature = 0;  ///< θ = Σ k v²/(d N) (total momentum zero; monomer mass 1)
  /// Events since the previous sample: sticking collisions and all collisions.
  /// @{
  double sticks = 0, collisions = 0;  ///< events since the previous sample
  /// @}
};

/// Runs one replica of `particles` monomers (mass 1, diameter 1) at θ = 1, number density 1, to
/// the increasing `times` (units σ/√(T/m)); a cluster of k monomers has diameter k^{1/d}. A pair
/// sticks when its energy (criterion 0: ½μ_ij g², 1: ½μ_ij (σ̂·g)²) is below critical_energy
/// μ_ij/μ_11 (docs/theory.md §20.1), merging with mass and momentum conserved; otherwise it
/// rebounds with restitution α. Null collisions at the rate of a majorant with exponential waiting
/// times (exact in continuous time). Throws std::invalid_argument naming the field on bad input.
std::vector<AggregationDsmcSample> run_aggregation_dsmc(int d, double alpha, double critical_energy, int criterion,
                                                        int particles, const std::vector<double>& times,
                                                        std::uint64_t seed);

}  // namespace gkt
