#include "gkt/transport/mixture/mixture_navier_stokes.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "algebra/nearby_rational.hpp"
#include "gkt/collision/collision_moments.hpp"
#include "gkt/operators/linearized_operator.hpp"
#include "gkt/operators/mixture_collisional_transfer.hpp"
#include "gkt/operators/weighted_pair_transfer.hpp"
#include "gkt/transport/common/reference_gas.hpp"
#include "gkt/transport/mixture/revised_enskog_functionals.hpp"
#include "transport/common/galerkin_pieces.hpp"
#include "transport/mixture/cumulant_sources.hpp"

namespace gkt {

namespace {

Eigen::MatrixXd to_matrix(const std::vector<std::vector<double>>& m) {
  Eigen::MatrixXd out(static_cast<Eigen::Index>(m.size()), static_cast<Eigen::Index>(m.size()));
  for (std::size_t p = 0; p < m.size(); ++p)
    for (std::size_t q = 0; q < m.size(); ++q)
      out(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(q)) = m[p][q];
  return out;
}

Eigen::VectorXd to_vector(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

/// Adds the pair (i, j)'s part of −∫ψ_ip · (J_ij[X_i, f_j] + J_ij[f_i, X_j]) (theory.md (17.4)): the
/// loss and gain moments of the engine with the unknown at v1 (X_i, into `self`, moments of `pair`) and at
/// v2 (X_j, into `cross`, moments of `cross_pair`: the same pair unless a wide basis, §17.12, gives the
/// unknown another width than f_j), times the given weights.
void add_pair(Eigen::MatrixXd& self, Eigen::MatrixXd& cross, const CollisionPair& pair, const Rational& alpha, int rank,
              int n_max, std::size_t i, std::size_t j, double weight_self, double weight_other,
              const CollisionPair* cross_pair = nullptr) {
  const auto block = static_cast<Eigen::Index>(n_max + 1);
  const CollisionPair& other = cross_pair ? *cross_pair : pair;
  const auto gain_self = sonine_collision_moments<Rational>(pair, alpha, Slot::v1, Slot::v1_post, rank, n_max);
  const auto loss_self = sonine_collision_moments<Rational>(pair, alpha, Slot::v1, Slot::v1, rank, n_max);
  const auto gain_other = sonine_collision_moments<Rational>(other, alpha, Slot::v2, Slot::v1_post, rank, n_max);
  const auto loss_other = sonine_collision_moments<Rational>(other, alpha, Slot::v2, Slot::v1, rank, n_max);
  const auto I = static_cast<Eigen::Index>(i) * block, J = static_cast<Eigen::Index>(j) * block;
  for (int p = 0; p <= n_max; ++p)
    for (int q = 0; q <= n_max; ++q) {
      self(I + p, I + q) -= weight_self * (gain_self(p, q) - loss_self(p, q)).to_double();
      cross(I + p, J + q) -= weight_other * (gain_other(p, q) - loss_other(p, q)).to_double();
    }
}

/// Rows and columns of the species blocks (block size `full`) restricted to their first `n`.
Eigen::MatrixXd leading_blocks(const Eigen::MatrixXd& m, std::size_t s, int full, int n) {
  const auto S = static_cast<Eigen::Index>(s);
  Eigen::MatrixXd out(S * n, S * n);
  for (Eigen::Index i = 0; i < S; ++i)
    for (Eigen::Index k = 0; k < S; ++k) out.block(i * n, k * n, n, n) = m.block(i * full, k * full, n, n);
  return out;
}

/// The weighted version of add_pair for a reference with cumulants (theory.md §17.11): the partner's
/// f_j carries Σ_k a_k,j S_k(X_j) in the self part, particle 1's f_i carries Σ_k a_k,i S_k(X_i) in the cross part.
void add_weighted_pair(Eigen::MatrixXd& self, Eigen::MatrixXd& cross, const CollisionPair& pair, const Rational& alpha,
                       int rank, int n_max, std::size_t i, std::size_t j, double weight_self, double weight_other,
                       const std::vector<double>& a_i, const std::vector<double>& a_j) {
  const auto block = static_cast<Eigen::Index>(n_max + 1);
  const int k_max = static_cast<int>(a_i.size()) - 1;
  const auto m = weighted_pair_operator_matrices<Rational>(pair, alpha, rank, n_max, k_max);
  const auto I = static_cast<Eigen::Index>(i) * block, J = static_cast<Eigen::Index>(j) * block;
  for (int p = 0; p <= n_max; ++p)
    for (int q = 0; q <= n_max; ++q) {
      double s_self = 0, s_cross = 0;
      for (int k = 0; k <= k_max; ++k) {
        const auto K = static_cast<std::size_t>(k);
        if (a_j[K] != 0) s_self += a_j[K] * m.self[K](p, q).to_double();
        if (a_i[K] != 0) s_cross += a_i[K] * m.cross[K](p, q).to_double();
      }
      self(I + p, I + q) -= weight_self * s_self;
      cross(I + p, J + q) -= weight_other * s_cross;
    }
}

/// Returns T with c' S_p(c'²) = Σ_k T(p, k) c S_k(c²), c' = c/√w, S = S^{(d/2)}, p, k = 0 … n_max: the
/// scaling identity of the Laguerre polynomials, L_p^{(a)}(λx) = Σ_k C(p + a, p − k) λ^k (1 − λ)^{p−k} L_k^{(a)}(x)
/// (λ = 1/w, a = d/2), times √λ; lower triangular, so its leading n × n block maps the leading n rows.
Eigen::MatrixXd basis_rescaling(int d, int n_max, double w) {
  const double lambda = 1 / w, a = d / 2.0;
  Eigen::MatrixXd t = Eigen::MatrixXd::Zero(n_max + 1, n_max + 1);
  for (int p = 0; p <= n_max; ++p)
    for (int k = 0; k <= p; ++k)
      t(p, k) = std::sqrt(lambda) *
                std::exp(std::lgamma(p + a + 1) - std::lgamma(k + a + 1) - std::lgamma(p - k + 1.0)) *
                std::pow(lambda, k) * std::pow(1 - lambda, p - k);
  return t;
}

}  // namespace

/// The solver's state: the operator of every mode in Sonine blocks, built once, and what the sources
/// need (HCS, masses, fractions; the dense gas's pair tables).
struct MixtureNavierStokes::Impl {
  Impl(const Mixture& mixture, int max_order, const MixtureReference& reference);
  /// MixtureNavierStokes::coefficients.
  [[nodiscard]] MixtureTransportValues coefficients(int order, MixtureTruncation truncation) const;
  /// The vector modes' solutions: heat = 𝒜 (∇ln T), density[j] = ℬ^j, each as the unknowns φ̃ of
  /// (17.5)–(17.7) (ℬ^j per ∇n_j) or, per_particle, φ = φ̃/x_i of (17.13) (ℬ^j per ∇ln n_j).
  struct VectorModes {
    Eigen::VectorXd heat;
    std::vector<Eigen::VectorXd> density;
    std::vector<Eigen::VectorXd> force;  ///< per external force F_j (standard scaling only; (18.14))
  };
  /// Solves both vector systems at `order` with the leading blocks of the operator's two parts.
  [[nodiscard]] VectorModes vector_modes(int order, const Eigen::MatrixXd& self, const Eigen::MatrixXd& cross,
                                         bool per_particle) const;
  /// Fills out.drift, out.thermal_drift and, for a binary, out.segregation* from the vector modes
  /// solved per particle (theory.md (17.13)).
  void species_drift(int order, const Eigen::MatrixXd& self, const Eigen::MatrixXd& cross,
                     MixtureTransportValues& out) const;

  /// The dense gas's additions to the vector sources (theory.md (18.4)): heat[i·n + p] (∇ln T)
  /// and density[l][i·n + p] (∇n_l), standard scaling; empty in the dilute gas.
  struct TransferSources {
    Eigen::VectorXd heat;
    std::vector<Eigen::VectorXd> density;
  };
  [[nodiscard]] TransferSources transfer_sources(int order, bool per_particle) const;
  /// Cumulant reference, dense (theory.md (17.23)): adds to the ∇n_l sources the partner's n ∂a_m,j/∂n_l terms
  /// L R x_i x_j Σ_m n∂_l a_m,j Σ_k a_k,i ⟨⟨S_k(X1) S_m(X2) σ̂·Δ[c1 S_p]⟩⟩ (scaled as transfer_sources).
  void add_cumulant_density_sources(TransferSources& out, int order, bool per_particle) const;
  /// Cumulant reference, dense (theory.md (17.24)): the f0 ∂f0 collisional heat flux per ∇n_j from the
  /// cumulants' density derivatives, −(1/(4d)) Σ_ik L² R x_i x_k ⟨⟨ΔE_1 (∂_j φ_k(X2) φ_i − φ_k ∂_j φ_i(X1))⟩⟩.
  [[nodiscard]] double cumulant_gradient_heat(std::size_t j) const;
  /// Cumulant reference, dense (theory.md (17.25)): the kinetic rows of the ∇·u mode for species i,
  /// x_i ⟨S_p T_i⟩ [2(p* − 1)/d + ζ_U + gamma_sum] + x_i Σ_k (Σ_l x_l n∂_l a_k,i) ⟨S_p S_k⟩ (ζ_U in column N).
  void add_cumulant_scalar_rows(Eigen::MatrixXd& m, Eigen::VectorXd& rhs, std::size_t i, double gamma_sum) const;
  /// The ∇·u mode (theory.md (18.6)–(18.8)) in the units of the solver: ζ_U, the bulk viscosity's
  /// part from the scalar components of f^(1), and the S_1 coefficients δ_i1 of every species.
  struct ScalarMode {
    double cooling_rate = 0, bulk_viscosity = 0;
    std::vector<double> temperature;
  };
  [[nodiscard]] ScalarMode scalar_mode(int order) const;
  /// The ∇·u mode with 𝒟_i = 0 (GDH's first Sonine drops ϖ_i, [garzo2007mixtureII]): ζ_U is the f0 ∂f0
  /// part of (18.7) alone, GDH's (17.18); the bulk viscosity has no scalar part and every δ_i1 is zero
  /// (theory.md §17.10).
  [[nodiscard]] ScalarMode scalar_mode_without_partial_temperatures() const;
  [[nodiscard]] std::size_t pair_index(std::size_t i, std::size_t j) const { return i * s_ + j; }

  int dimension_;
  MixtureCoolingState state_;
  MixtureCoolingSensitivity sensitivity_;
  // Cumulant reference (theory.md §17.11): a_k,i at [i][k] (empty when Maxwellian), n ∂a_k,i/∂n_j at
  // [i·s + j][k], and the source averages of the k ≥ 2 terms.
  std::vector<std::vector<double>> cumulants_, cumulant_sensitivity_;
  detail::CumulantSources cumulant_sources_;
  int max_order_;
  std::size_t s_;
  std::size_t major_ = 0;  // the first most abundant species: its rows carry the conservation constraints
  double nu0_ = 0;         // ν0 = nT/η0 = 4√2 c_d/(d+2) in the units n = σ̄ = m̄ = √(2T/m̄) = 1
  double zeta_ = 0;        // ζ = ζ* ν0 in those units
  std::vector<double> theta_, mass_, fraction_;  // θ_k = m_k/γ_k, m_k/m̄, x_k
  // The vector trial functions' θ_k/w_k (θ_k unless a wide basis, theory.md §17.12) and, per species with
  // w_k ≠ 1, the map of its test rows from the scaling θ_k to θ_k/w_k (basis_rescaling; empty when w_k = 1).
  std::vector<double> basis_theta_;
  std::vector<Eigen::MatrixXd> row_rescaling_;
  /// Rows of species i of a vector source in the tests of its basis (a wide basis, §17.12): T_i v_i.
  void rescale_rows(Eigen::VectorXd& v, int n) const {
    for (std::size_t i = 0; i < row_rescaling_.size(); ++i)
      if (row_rescaling_[i].size() > 0) {
        const auto I = static_cast<Eigen::Index>(i) * n;
        v.segment(I, n) = (row_rescaling_[i].topLeftCorner(n, n) * v.segment(I, n)).eval();
      }
  }
  // Rows (i, p), columns (k, q), index i·n + p. The vector operator is kept in two parts: the
  // species-diagonal one (X_i against f_j, weight x_j) and the cross one (f_i against X_j) without its
  // weight, x_i per particle of the unknown's species or x_j per particle of the row's (17.4), (17.13).
  Eigen::MatrixXd vector_self_, vector_cross_, tensor_operator_, scalar_operator_;
  Eigen::MatrixXd vector_d_, vector_m_, tensor_d_, scalar_d_;  // one-species ζ pieces D(p, q), M(p, q)
  Eigen::VectorXd vector_flux_, tensor_flux_;                  // ⟨x² S_q⟩ of the two modes
  // Dense gas (theory.md §18), per ordered pair i·s + j: rate_ = σ_ij^{d−1} χ_ij c_d w_ij (the operator's
  // collision rate), length_ = n σ̄^d σ_ij/σ̄ (the transfer length in the solver's units), the pair's
  // restitution and transfer averages; dchi_ = n ∂ln χ_ij/∂n_l at (i·s + j)·s + l; p* and
  // pressure_derivative_[l] = ∂p/∂n_l/T (1 when dilute).
  bool dense_ = false;
  std::vector<double> rate_, length_, alpha_;
  std::vector<PairTransferMoments> transfer_;
  // Cumulant reference, dense (theory.md §17.11): the pairs' weighted transfer averages (transfer_ holds them
  // contracted with a_k,i, a_l,j) and the scalar mode's source averages.
  std::vector<WeightedPairTransferMoments> weighted_transfer_;
  detail::ScalarCumulantSources scalar_cumulant_sources_;
  std::vector<double> dchi_, pressure_derivative_;
  // The revised-Enskog functionals I_ℓij at (i·s + j)·s + ℓ (theory.md (18.18)–(18.20); s ≥ 3 with the
  // lens-centroid closure of §18.12): empty (zero) when dilute or all diameters are equal.
  std::vector<double> functionals_;
  double pressure_ = 1;
};

MixtureNavierStokes::Impl::Impl(const Mixture& mixture, int max_order, const MixtureReference& reference)
    : dimension_(mixture.dimension), max_order_(max_order), s_(mixture.size()) {
  mixture.validate();
  if (max_order < 1) throw std::invalid_argument("order: must be >= 1");
  const std::vector<double>& width = reference.basis_width;
  if (!width.empty()) {
    if (width.size() != s_)
      throw std::invalid_argument("basis_width: needs one value per species (" + std::to_string(s_) + "), got " +
                                  std::to_string(width.size()));
    for (double w : width)
      if (!(w >= 0.6 && w <= 16)) throw std::invalid_argument("basis_width: every w_i must be in [0.6, 16]");
    if (reference.scheme != MixtureHcsScheme::maxwellian)
      throw std::invalid_argument("basis_width: needs the Maxwellian reference (reference_state = \"maxwellian\")");
    if (mixture.packing_fraction > 0)
      throw std::invalid_argument("basis_width: dilute gas only (packing_fraction = 0)");
  }
  const bool with_cumulants = reference.scheme != MixtureHcsScheme::maxwellian;
  state_ = mixture_cooling_state(mixture, reference.scheme, reference.hcs_order);
  if (with_cumulants) {
    if (!state_.solved) throw std::invalid_argument("reference_state: the HCS with cumulants did not converge");
    cumulants_ = state_.cumulants;
    sensitivity_ = mixture_cooling_sensitivity(mixture, reference, &cumulant_sensitivity_);
    cumulant_sources_ = detail::cumulant_sources(mixture.dimension, max_order, max_order - 1, reference.hcs_order);
    if (mixture.packing_fraction > 0)
      scalar_cumulant_sources_ = detail::scalar_cumulant_sources(mixture.dimension, max_order + 1, reference.hcs_order);
  } else {
    sensitivity_ = mixture_cooling_sensitivity(mixture, state_);
  }
  const int d = mixture.dimension;
  const double c_d = geometric_factor(d);
  // Units n = 1, m̄ = 1, σ̄ = 1, velocity √(2T/m̄) = 1 (so T = 1/2): θ_k = m_k/γ_k. Lengths along a
  // gradient are in mean free paths 1/(n σ̄^{d−1}), so a collisional transfer over σ_ij carries
  // n σ̄^d σ_ij/σ̄ (theory.md (18.3)).
  double diameter_moment = 0;
  for (std::size_t k = 0; k < s_; ++k) {
    mass_.push_back(mixture.species[k].mass.value() / mixture.mean_mass());
    theta_.push_back(mass_[k] / state_.temperature_ratio[k]);
    fraction_.push_back(mixture.species[k].fraction);
    diameter_moment += fraction_[k] * std::pow(mixture.species[k].diameter / mixture.mean_diameter(), d);
    const double w = width.empty() ? 1.0 : width[k];
    basis_theta_.push_back(theta_[k] / w);
    row_rescaling_.push_back(w == 1 ? Eigen::MatrixXd() : basis_rescaling(d, max_order + 1 - 1, w));
  }
  nu0_ = unit_reference_gas(d).collision_frequency;
  zeta_ = state_.cooling_rate * nu0_;
  dense_ = mixture.packing_fraction > 0;
  const double n_star = mixture.packing_fraction / (unit_sphere_volume(d) * diameter_moment);  // n σ̄^d
  const std::vector<double> chi = mixture.contact_values();
  const int nv = max_order + 1, nt = max_order, ns = max_order + 2;
  const auto S = static_cast<Eigen::Index>(s_);
  vector_self_ = Eigen::MatrixXd::Zero(S * nv, S * nv);
  vector_cross_ = vector_self_;
  tensor_operator_ = Eigen::MatrixXd::Zero(S * nt, S * nt);
  if (dense_) scalar_operator_ = Eigen::MatrixXd::Zero(S * ns, S * ns);
  for (std::size_t i = 0; i < s_; ++i)
    for (std::size_t j = 0; j < s_; ++j) {
      // The moments depend on the mass ratio and the width ratio only: the pair is built with
      // m_j = θ_j = 1. m_i/m_j is exact (the species carry their masses exactly). The vector mode's
      // cross moments need √(θ_i/θ_j) rational: the computed double becomes the continued-fraction
      // convergent with denominator ≤ 2^26 within 1e-12 relative (else the exact double), 3 times
      // faster than 53-bit dyadic rationals (docs/performance.md).
      const Rational r = detail::nearby_rational(std::sqrt(theta_[i] / theta_[j]), 1L << 26);
      const Rational mass_ratio = mixture.species[i].mass.exact() / mixture.species[j].mass.exact();
      const CollisionPair pair{d, mass_ratio, Rational(1), r * r, Rational(1)};
      const Rational alpha = Rational::from_double(mixture.restitution(i, j));
      const double sigma = 0.5 * (mixture.species[i].diameter + mixture.species[j].diameter) / mixture.mean_diameter();
      const double rate =
          std::pow(sigma, d - 1) * c_d * std::sqrt(1 / theta_[i] + 1 / theta_[j]) * chi[pair_index(i, j)];
      rate_.push_back(rate);
      length_.push_back(n_star * sigma);
      alpha_.push_back(mixture.restitution(i, j));
      if (with_cumulants) {
        add_weighted_pair(vector_self_, vector_cross_, pair, alpha, 1, nv - 1, i, j, rate * fraction_[j], rate,
                          cumulants_[i], cumulants_[j]);
        add_weighted_pair(tensor_operator_, tensor_operator_, pair, alpha, 2, nt - 1, i, j, rate * fraction_[j],
                          rate * fraction_[i], cumulants_[i], cumulants_[j]);
      } else if (!width.empty()) {
        // Wide basis (theory.md §17.12): the unknown X_i (self part) at θ_i/w_i against f_j at θ_j, tests in
        // the unknown's scaling; f_i at θ_i against the unknown X_j at θ_j/w_j (cross part), tests in θ_i's
        // scaling, mapped to θ_i/w_i's below. Each part carries its pair's relative thermal speed.
        auto pair_of = [&](double theta_1, double theta_2) {
          const Rational q = detail::nearby_rational(std::sqrt(theta_1 / theta_2), 1L << 26);
          return CollisionPair{d, mass_ratio, Rational(1), q * q, Rational(1)};
        };
        const CollisionPair self_pair = pair_of(basis_theta_[i], theta_[j]);
        const CollisionPair cross_pair = pair_of(theta_[i], basis_theta_[j]);
        const double unit = std::pow(sigma, d - 1) * c_d * chi[pair_index(i, j)];
        Eigen::MatrixXd unused = Eigen::MatrixXd::Zero(vector_self_.rows(), vector_self_.cols());
        add_pair(vector_self_, unused, self_pair, alpha, 1, nv - 1, i, j,
                 unit * std::sqrt(1 / basis_theta_[i] + 1 / theta_[j]) * fraction_[j], 0.0);
        add_pair(unused, vector_cross_, cross_pair, alpha, 1, nv - 1, i, j, 0.0,
                 unit * std::sqrt(1 / theta_[i] + 1 / basis_theta_[j]));
        add_pair(tensor_operator_, tensor_operator_, pair, alpha, 2, nt - 1, i, j, rate * fraction_[j],
                 rate * fraction_[i]);
      } else {
        add_pair(vector_self_, vector_cross_, pair, alpha, 1, nv - 1, i, j, rate * fraction_[j], rate);
        add_pair(tensor_operator_, tensor_operator_, pair, alpha, 2, nt - 1, i, j, rate * fraction_[j],
                 rate * fraction_[i]);
      }
      if (dense_ && with_cumulants) {  // theory.md (17.22)–(17.23)
        add_weighted_pair(scalar_operator_, scalar_operator_, pair, alpha, 0, ns - 1, i, j, rate * fraction_[j],
                          rate * fraction_[i], cumulants_[i], cumulants_[j]);
        weighted_transfer_.push_back(
            weighted_pair_transfer_moments(d, mass_ratio, r, alpha, ns - 1, reference.hcs_order, mass_[i], theta_[j]));
        transfer_.push_back(contracted_pair_transfer(weighted_transfer_.back(), cumulants_[i], cumulants_[j]));
      } else if (dense_) {
        add_pair(scalar_operator_, scalar_operator_, pair, alpha, 0, ns - 1, i, j, rate * fraction_[j],
                 rate * fraction_[i]);
        transfer_.push_back(pair_transfer_moments(d, mass_ratio, r, alpha, ns - 1, mass_[i], theta_[j]));
      }
    }
  for (std::size_t i = 0; i < s_; ++i)  // the cross rows of a wide species into its basis's tests
    if (row_rescaling_[i].size() > 0)
      vector_cross_.middleRows(static_cast<Eigen::Index>(i) * nv, nv) =
          (row_rescaling_[i] * vector_cross_.middleRows(static_cast<Eigen::Index>(i) * nv, nv)).eval();
  const auto vp = detail::rounded(detail::vector_pieces(d, nv - 1, 0));
  const auto tp = detail::rounded(detail::tensor_pieces(d, nt - 1, 0));
  vector_d_ = to_matrix(vp.d);
  vector_m_ = to_matrix(vp.m);
  tensor_d_ = to_matrix(tp.d);
  vector_flux_ = to_vector(vp.flux);
  tensor_flux_ = to_vector(tp.flux);
  // The most abundant species' rows carry the conservation constraints (17.7), (18.6).
  major_ = static_cast<std::size_t>(std::max_element(fraction_.begin(), fraction_.end()) - fraction_.begin());
  pressure_derivative_.assign(s_, 1.0);  // p = nT when dilute
  if (!dense_) return;
  scalar_d_ = to_matrix(detail::rounded(detail::scalar_pieces(d, ns - 1, 0)).d);
  const std::vector<double> dchi = mixture.contact_value_derivatives();
  for (std::size_t k = 0; k < dchi.size(); ++k) dchi_.push_back(dchi[k] / chi[k / s_]);
  functionals_ = revised_enskog_functionals(mixture);
  if (std::all_of(functionals_.begin(), functionals_.end(), [](double v) { return v == 0.0; })) functionals_.clear();
  // p = nT + B_2 Σ_ij μ_ji (1+α_ij) σ_ij^d χ_ij n_i n_j T_i, B_2 = π^{(d−1)/2} Γ(3/2)/Γ(d/2 + 1) (18.2);
  // its derivative at fixed T also moves χ_ij and γ_i.
  const double b2 = std::pow(std::numbers::pi, (d - 1) / 2.0) * std::tgamma(1.5) / std::tgamma(d / 2.0 + 1);
  const std::vector<double>& gamma = state_.temperature_ratio;
  for (std::size_t i = 0; i < s_; ++i)
    for (std::size_t j = 0; j < s_; ++j) {
      const std::size_t P = pair_index(i, j);
      const double sigma = length_[P] / n_star;
      const double w =
          n_star * b2 * mass_[j] / (mass_[i] + mass_[j]) * (1 + alpha_[P]) * std::pow(sigma, d) * chi[P] * gamma[i];
      pressure_ += w * fraction_[i] * fraction_[j];
      for (std::size_t l = 0; l < s_; ++l)
        pressure_derivative_[l] +=
            w * ((i == l ? fraction_[j] : 0.0) + (j == l ? fraction_[i] : 0.0) +
                 fraction_[i] * fraction_[j] * (dchi_[P * s_ + l] + sensitivity_.temperature_ratio[i * s_ + l]));
    }
}

MixtureNavierStokes::Impl::VectorModes MixtureNavierStokes::Impl::vector_modes(int order, const Eigen::MatrixXd& self,
                                                                               const Eigen::MatrixXd& cross,
                                                                               bool per_particle) const {
  // Standard scaling (17.4)–(17.7): rows as integrated, unknowns φ̃, cross part weighted by the row's
  // x_i, ℬ^j per ∇n_j. Per particle (17.13): rows / x_i, unknowns φ = φ̃/x_i, so the cross part carries
  // the column's x_j, the 𝒜 source loses x_i, the constraint weights x_k and ℬ^j is per ∇ln n_j
  // (sources × x_j/x_i). The two are the same system for x > 0; only the second stays finite for a
  // tracer row, only the first for a tracer's ∇n_j.
  const int n = order + 1;
  const auto S = static_cast<Eigen::Index>(s_);
  Eigen::VectorXd weight(S * n);  // x_i on the rows (or columns) of species i
  for (Eigen::Index i = 0; i < S; ++i) weight.segment(i * n, n).setConstant(fraction_[static_cast<std::size_t>(i)]);
  const Eigen::MatrixXd op = per_particle ? Eigen::MatrixXd(self + cross * weight.asDiagonal())
                                          : Eigen::MatrixXd(self + weight.asDiagonal() * cross);
  const Eigen::MatrixXd dv = vector_d_.topLeftCorner(n, n), mv = vector_m_.topLeftCorner(n, n);
  // 𝒜: ζ(D − ½M); ℬ: ζD; external forces (standard scaling only; the mode carries 1/T more than ℬ,
  // so −ζT∂_T adds ζM, (18.14)): ζ(D + M).
  Eigen::MatrixXd ka = op, kb = op, kf = per_particle ? Eigen::MatrixXd() : op;
  for (Eigen::Index i = 0; i < S; ++i) {
    ka.block(i * n, i * n, n, n) += zeta_ * (dv - 0.5 * mv);
    kb.block(i * n, i * n, n, n) += zeta_ * dv;
    if (!per_particle) kf.block(i * n, i * n, n, n) += zeta_ * (dv + mv);
  }
  // Total momentum Σ_k m_k ∫V X_k = 0 replaces the p = 0 row of the most abundant species: that row
  // is otherwise the momentum balance, a combination of the others (theory.md (17.7)).
  const auto major = static_cast<Eigen::Index>(major_);
  for (Eigen::MatrixXd* k : {&ka, &kb, &kf}) {
    if (k->size() == 0) continue;
    k->row(major * n).setZero();
    for (Eigen::Index j = 0; j < S; ++j) {
      const auto J = static_cast<std::size_t>(j);
      (*k)(major * n, j * n) = (per_particle ? fraction_[J] : 1.0) * mass_[J] / std::sqrt(basis_theta_[J]);
    }
  }
  VectorModes out;
  const TransferSources transfer = transfer_sources(order, per_particle);
  Eigen::VectorXd sa(S * n);
  for (std::size_t i = 0; i < s_; ++i)  // (17.5), (18.4): −x_i θ_i^{−1/2} ⟨x S_p (x − d/2 − θ_i p*)⟩, x − d/2 = 1 − S_1
    sa.segment(static_cast<Eigen::Index>(i) * n, n) = -(per_particle ? 1.0 : fraction_[i]) / std::sqrt(theta_[i]) *
                                                      ((1 - theta_[i] * pressure_) * mv.col(0) - mv.col(1));
  // Cumulant reference (theory.md (17.20)): the k ≥ 2 terms of f_i^(0) = f_M,i Σ_k a_k,i S_k(X_i).
  auto cumulant_term = [&](const std::vector<std::vector<double>>& table, const std::vector<double>& a, int p) {
    double acc = 0;
    for (std::size_t k = 2; k < a.size(); ++k) acc += a[k] * table[static_cast<std::size_t>(p)][k];
    return acc;
  };
  const detail::CumulantSources& cs = cumulant_sources_;
  if (!cumulants_.empty())
    for (std::size_t i = 0; i < s_; ++i)
      for (int p = 0; p < n; ++p)
        sa(static_cast<Eigen::Index>(i) * n + p) -= (per_particle ? 1.0 : fraction_[i]) / std::sqrt(theta_[i]) *
                                                    (cumulant_term(cs.temperature, cumulants_[i], p) +
                                                     theta_[i] * pressure_ * cumulant_term(cs.drift, cumulants_[i], p));
  if (dense_) sa += transfer.heat;
  rescale_rows(sa, n);
  sa(major * n) = 0;
  out.heat = ka.partialPivLu().solve(sa);
  const auto lu = kb.partialPivLu();
  for (std::size_t j = 0; j < s_; ++j) {
    Eigen::VectorXd sb(S * n);
    // (17.6), (18.4): −θ_i^{−1/2}[δ_ij M(p,0) + x_i (∂_j ln γ_i ⟨x S_p (x − d/2)⟩ − θ_i ∂_j p/T M(p,0))]
    // + ∂ζ/∂n_j M φ̃^𝒜_i (per particle: x_j instead of x_i, and x_j ∂ζ/∂n_j).
    const double dzeta = sensitivity_.cooling_rate[j] * nu0_ * (per_particle ? fraction_[j] : 1.0);
    const double dp = pressure_derivative_[j];
    for (std::size_t i = 0; i < s_; ++i) {
      const auto I = static_cast<Eigen::Index>(i) * n;
      const double g = sensitivity_.temperature_ratio[i * s_ + j], x = per_particle ? fraction_[j] : fraction_[i];
      Eigen::VectorXd source =
          -1 / std::sqrt(theta_[i]) *
          ((i == j ? 1.0 : 0.0) * mv.col(0) + x * (g * (mv.col(0) - mv.col(1)) - theta_[i] * dp * mv.col(0)));
      if (row_rescaling_[i].size() > 0) source = (row_rescaling_[i].topLeftCorner(n, n) * source).eval();
      sb.segment(I, n) = source + dzeta * (mv * out.heat.segment(I, n));
      if (!cumulants_.empty())
        for (int p = 0; p < n; ++p) {
          const std::vector<double>& a = cumulants_[i];
          double da = 0;  // n ∂a_k,i/∂n_j ⟨x S_p S_k⟩
          for (std::size_t k = 2; k < a.size(); ++k)
            da += cumulant_sensitivity_[i * s_ + j][k] * cs.weight[static_cast<std::size_t>(p)][k];
          sb(I + p) -=
              1 / std::sqrt(theta_[i]) *
              ((i == j ? 1.0 : 0.0) * cumulant_term(cs.weight, a, p) +
               x * (g * cumulant_term(cs.temperature, a, p) + da + theta_[i] * dp * cumulant_term(cs.drift, a, p)));
        }
    }
    if (dense_) sb += transfer.density[j];
    sb(major * n) = 0;
    out.density.push_back(lu.solve(sb));
  }
  if (per_particle) return out;
  // External forces (18.14): −(F_i/m_i)·∂_V f_i and the force in ∂_t^(1)u give the source
  // 2θ_i V f_i (δ_ij/m_i − n_j/ρ) per F_j, rows 2√θ_i x_i M(p,0)(δ_ij/m_i − x_j).
  const auto lf = kf.partialPivLu();
  for (std::size_t j = 0; j < s_; ++j) {
    Eigen::VectorXd sf(S * n);
    for (std::size_t i = 0; i < s_; ++i)
      sf.segment(static_cast<Eigen::Index>(i) * n, n) =
          2 * std::sqrt(theta_[i]) * fraction_[i] * ((i == j ? 1 / mass_[i] : 0.0) - fraction_[j]) * mv.col(0);
    if (!cumulants_.empty())
      for (std::size_t i = 0; i < s_; ++i)
        for (int p = 0; p < n; ++p)
          sf(static_cast<Eigen::Index>(i) * n + p) -= 2 * std::sqrt(theta_[i]) * fraction_[i] *
                                                      ((i == j ? 1 / mass_[i] : 0.0) - fraction_[j]) *
                                                      cumulant_term(cs.drift, cumulants_[i], p);
    rescale_rows(sf, n);
    sf(major * n) = 0;
    out.force.push_back(lf.solve(sf));
  }
  return out;
}

MixtureNavierStokes::Impl::TransferSources MixtureNavierStokes::Impl::transfer_sources(int order,
                                                                                       bool per_particle) const {
  // (18.4): the K_i of the Enskog operator's gradient expansion projected on c_i S_p(X_i), per pair
  // L_ij R_ij x_i x_j ⟨⟨σ̂·Δ[c1 S_p]·(∂ ln f_j + ½ ∂ ln χ_ij + ½ Σ_ℓ I_ℓij ∂n_ℓ/n_j)⟩⟩ (18.21); per particle the rows
  // are divided by x_i and the density modes are per ∇ln n_l (× x_l).
  TransferSources out;
  if (!dense_) return out;
  const int n = order + 1;
  const auto S = static_cast<Eigen::Index>(s_);
  out.heat = Eigen::VectorXd::Zero(S * n);
  out.density.assign(s_, out.heat);
  for (std::size_t i = 0; i < s_; ++i)
    for (std::size_t j = 0; j < s_; ++j) {
      const std::size_t P = pair_index(i, j);
      const PairTransferMoments& t = transfer_[P];
      const double f = length_[P] * rate_[P] * (per_particle ? 1.0 : fraction_[i]);
      const auto I = static_cast<Eigen::Index>(i) * n;
      for (int p = 0; p < n; ++p) {
        const auto row = I + p;
        const auto P_ = static_cast<std::size_t>(p);
        out.heat(row) += f * fraction_[j] * t.source_temperature[P_];
        for (std::size_t l = 0; l < s_; ++l) {
          const double g = sensitivity_.temperature_ratio[j * s_ + l];
          double v = (j == l ? t.source_density[P_] : 0.0) +
                     fraction_[j] * (g * t.source_temperature[P_] + 0.5 * dchi_[P * s_ + l] * t.source_density[P_]);
          if (!functionals_.empty()) v += 0.5 * functionals_[P * s_ + l] * t.source_density[P_];  // (18.21)
          out.density[l](row) += f * (per_particle ? fraction_[l] : 1.0) * v;
        }
      }
    }
  if (!weighted_transfer_.empty()) add_cumulant_density_sources(out, order, per_particle);
  return out;
}

void MixtureNavierStokes::Impl::add_cumulant_density_sources(TransferSources& out, int order, bool per_particle) const {
  const int n = order + 1;
  for (std::size_t i = 0; i < s_; ++i)
    for (std::size_t j = 0; j < s_; ++j) {
      const std::size_t P = pair_index(i, j);
      const WeightedPairTransferMoments& w = weighted_transfer_[P];
      const double f = length_[P] * rate_[P] * (per_particle ? 1.0 : fraction_[i]) * fraction_[j];
      for (std::size_t l = 0; l < s_; ++l) {
        const std::vector<double>& da = cumulant_sensitivity_[j * s_ + l];  // n ∂a_m,j/∂n_l
        for (int p = 0; p < n; ++p) {
          double v = 0;
          for (int m = 2; m <= w.k_max; ++m)
            for (int k = 0; k <= w.k_max; ++k)
              v += da[static_cast<std::size_t>(m)] * cumulants_[i][static_cast<std::size_t>(k)] *
                   w.source_density[w.index(p, k, m)];
          out.density[l](static_cast<Eigen::Index>(i) * n + p) += f * (per_particle ? fraction_[l] : 1.0) * v;
        }
      }
    }
}

double MixtureNavierStokes::Impl::cumulant_gradient_heat(std::size_t j) const {
  double q = 0;
  for (std::size_t i = 0; i < s_; ++i)
    for (std::size_t k = 0; k < s_; ++k) {
      const std::size_t P = pair_index(i, k);
      const WeightedPairTransferMoments& w = weighted_transfer_[P];
      const std::vector<double>&da_i = cumulant_sensitivity_[i * s_ + j], &da_k = cumulant_sensitivity_[k * s_ + j];
      double v = 0;
      for (int a = 0; a <= w.k_max; ++a)
        for (int b = 0; b <= w.k_max; ++b) {
          const auto A = static_cast<std::size_t>(a), B = static_cast<std::size_t>(b);
          v += (cumulants_[i][A] * da_k[B] - da_i[A] * cumulants_[k][B]) * w.energy[w.index(a, b)];
        }
      q -= length_[P] * length_[P] * rate_[P] / (4 * dimension_) * fraction_[i] * fraction_[k] * v;
    }
  return q;
}

void MixtureNavierStokes::Impl::add_cumulant_scalar_rows(Eigen::MatrixXd& m, Eigen::VectorXd& rhs, std::size_t i,
                                                         double gamma_sum) const {
  const auto nq = static_cast<Eigen::Index>(m.rows() - 1) / static_cast<Eigen::Index>(s_), N = m.rows() - 1;
  const std::vector<double>& a = cumulants_[i];
  const detail::ScalarCumulantSources& cs = scalar_cumulant_sources_;
  for (Eigen::Index p = 0; p < nq; ++p) {
    const auto row = static_cast<Eigen::Index>(i) * nq + p;
    const auto P = static_cast<std::size_t>(p) + 1;  // rows S_1 … S_{N+1}
    double u = 0, w = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      double da = 0;  // Σ_l x_l n ∂a_k,i/∂n_l
      for (std::size_t l = 0; l < s_; ++l) da += fraction_[l] * cumulant_sensitivity_[i * s_ + l][k];
      u += a[k] * cs.temperature[P][k];
      w += da * cs.weight[P][k];
    }
    m(row, N) = -fraction_[i] * u;
    rhs(row) = fraction_[i] * (u * (2 * (pressure_ - 1) / dimension_ + gamma_sum) + w);
  }
}

MixtureNavierStokes::Impl::ScalarMode MixtureNavierStokes::Impl::scalar_mode(int order) const {
  // Unknowns δ_iq (q = 1 … N+1, 𝒟_i = f̂_i Σ_q δ_iq S_q(X_i)) and ζ_U; rows S_p(X_i) of
  // (ℒ + ζ D⁰) 𝒟 = x_i (X − d/2)[2(p* − 1)/d + ζ_U + Σ_l x_l ∂_l ln γ_i] f̂_i + (1/d) Σ_j K^scalar (18.6);
  // the S_1 row of the most abundant species is the total-energy constraint Σ_i γ_i δ_i1 = 0, and the
  // last row is ζ_U = ζ11[δ] + ζ10 (18.7).
  const int d = dimension_, nq = order + 1, full = max_order_ + 2;
  const auto S = static_cast<Eigen::Index>(s_), N = S * nq;
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(N + 1, N + 1);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(N + 1);
  for (Eigen::Index i = 0; i < S; ++i) {
    const auto I = static_cast<std::size_t>(i);
    for (Eigen::Index k = 0; k < S; ++k)
      m.block(i * nq, k * nq, nq, nq) = scalar_operator_.block(i * full + 1, k * full + 1, nq, nq);
    m.block(i * nq, i * nq, nq, nq) += zeta_ * scalar_d_.block(1, 1, nq, nq);
    double gamma_sum = 0;
    for (std::size_t l = 0; l < s_; ++l) gamma_sum += fraction_[l] * sensitivity_.temperature_ratio[I * s_ + l];
    // ⟨S_p (X − d/2)⟩ = −d/2 δ_p1 (S_1 = d/2 − X).
    if (cumulants_.empty()) {
      m(i * nq, N) = fraction_[I] * d / 2.0;
      rhs(i * nq) = -fraction_[I] * d / 2.0 * (2 * (pressure_ - 1) / d + gamma_sum);
    } else {
      add_cumulant_scalar_rows(m, rhs, I, gamma_sum);
    }
    for (std::size_t j = 0; j < s_; ++j) {
      const std::size_t P = pair_index(I, j);
      const double f = length_[P] * rate_[P] * fraction_[I] * fraction_[j] * 2 * std::sqrt(theta_[j]) / d;
      for (int p = 0; p < nq; ++p) rhs(i * nq + p) += f * transfer_[P].source_scalar[static_cast<std::size_t>(p) + 1];
    }
  }
  const auto major = static_cast<Eigen::Index>(major_);
  m.row(major * nq).setZero();
  rhs(major * nq) = 0;
  for (Eigen::Index k = 0; k < S; ++k) m(major * nq, k * nq) = state_.temperature_ratio[static_cast<std::size_t>(k)];
  // ζ = (1/d) Σ_ij (1 − α²) m_i μ_ji R_ij ⟨⟨(σ̂·g)² [x_i 𝒟_j + x_j 𝒟_i]⟩⟩ + the f0 ∂f0 part (18.7).
  m(N, N) = 1;
  for (std::size_t i = 0; i < s_; ++i)
    for (std::size_t j = 0; j < s_; ++j) {
      const std::size_t P = pair_index(i, j);
      const PairTransferMoments& t = transfer_[P];
      const double w = (1 - alpha_[P] * alpha_[P]) * mass_[i] * mass_[j] / (mass_[i] + mass_[j]) * rate_[P] / d;
      for (int q = 0; q < nq; ++q) {
        const auto Q = static_cast<std::size_t>(q) + 1;
        m(N, static_cast<Eigen::Index>(j) * nq + q) -= w * fraction_[i] * t.cooling_partner[Q];
        m(N, static_cast<Eigen::Index>(i) * nq + q) -= w * fraction_[j] * t.cooling_self[Q];
      }
      rhs(N) += w * length_[P] * fraction_[i] * fraction_[j] * t.cooling_gradient / d;
    }
  const Eigen::VectorXd x = m.partialPivLu().solve(rhs);
  // Bulk viscosity from the scalar part: κ_D = −(1/(2d)) Σ_ij m_i μ_ji (1+α) L R ⟨⟨(σ̂·g)[x_i 𝒟_j + x_j 𝒟_i]⟩⟩.
  double bulk = 0;
  for (std::size_t i = 0; i < s_; ++i)
    for (std::size_t j = 0; j < s_; ++j) {
      const std::size_t P = pair_index(i, j);
      const PairTransferMoments& t = transfer_[P];
      const double w = mass_[i] * mass_[j] / (mass_[i] + mass_[j]) * (1 + alpha_[P]) * length_[P] * rate_[P];
      for (int q = 0; q < nq; ++q) {
        const auto Q = static_cast<std::size_t>(q) + 1;
        bulk -= w / (2 * d) *
                (fraction_[i] * t.pressure_partner[Q] * x(static_cast<Eigen::Index>(j) * nq + q) +
                 fraction_[j] * t.pressure_self[Q] * x(static_cast<Eigen::Index>(i) * nq + q));
      }
    }
  ScalarMode out{x(N), bulk, {}};
  for (Eigen::Index i = 0; i < S; ++i) out.temperature.push_back(x(i * nq));
  return out;
}

MixtureNavierStokes::Impl::ScalarMode MixtureNavierStokes::Impl::scalar_mode_without_partial_temperatures() const {
  ScalarMode out{0, 0, std::vector<double>(s_, 0.0)};
  for (std::size_t i = 0; i < s_; ++i)
    for (std::size_t j = 0; j < s_; ++j) {
      const std::size_t P = pair_index(i, j);
      const double w =
          (1 - alpha_[P] * alpha_[P]) * mass_[i] * mass_[j] / (mass_[i] + mass_[j]) * rate_[P] / dimension_;
      out.cooling_rate += w * length_[P] * fraction_[i] * fraction_[j] * transfer_[P].cooling_gradient / dimension_;
    }
  return out;
}

MixtureTransportValues MixtureNavierStokes::Impl::coefficients(int order, MixtureTruncation truncation) const {
  if (order < 1 || order > max_order_)
    throw std::invalid_argument("order: must be an integer in [1, " + std::to_string(max_order_) + "]");
  const bool published = truncation == MixtureTruncation::published;
  if (published &&
      std::any_of(row_rescaling_.begin(), row_rescaling_.end(), [](const auto& t) { return t.size() > 0; }))
    throw std::invalid_argument("basis_width: the published (GDH) truncation is defined in the standard basis only");
  if (published && order != 1)
    throw std::invalid_argument("order: the published (GDH) first Sonine truncation exists at order = 1 only, got " +
                                std::to_string(order));
  const int d = dimension_;
  const std::size_t s = s_;
  const auto S = static_cast<Eigen::Index>(s);
  const ReferenceGas ref = unit_reference_gas(d);  // η0, κ0, D0 of (m̄, σ̄) in these units
  const double eta0 = ref.viscosity, kappa0 = ref.conductivity, d0 = ref.self_diffusion;
  const double temperature = 0.5;

  // Vector modes (theory.md (17.5)–(17.6)): unknowns φ̃_kq, X_k = (f_k/n_k) Σ_q φ̃_kq c_k S_q(θ_k V²).
  const int n = order + 1;
  Eigen::MatrixXd self = leading_blocks(vector_self_, s, max_order_ + 1, n);
  Eigen::MatrixXd cross = leading_blocks(vector_cross_, s, max_order_ + 1, n);
  // [garzo2007mixtureII] (theory.md §17.10): the mass-flux rows (c S_0) see their own trial function only.
  if (published)
    for (Eigen::Index i = 0; i < S; ++i)
      for (Eigen::Index k = 0; k < S; ++k)
        for (Eigen::Index q = 1; q < n; ++q) self(i * n, k * n + q) = cross(i * n, k * n + q) = 0;
  const VectorModes modes = vector_modes(order, self, cross, false);
  const Eigen::VectorXd& a = modes.heat;

  MixtureTransportValues out;
  out.pressure_derivative = pressure_derivative_;
  out.mutual_diffusion.assign(s * s, 0.0);
  out.thermal_diffusion.assign(s, 0.0);
  out.pressure_diffusion.assign(s, 0.0);
  out.dufour.assign(s, 0.0);
  // Number flux of species i of a vector-mode solution: ∫V·X_i/d = θ_i^{−1/2} M(0,0) φ̃_i0/d (17.9).
  auto number_flux = [&](const Eigen::VectorXd& v, std::size_t i) {
    return vector_m_(0, 0) / (d * std::sqrt(basis_theta_[i])) * v(static_cast<Eigen::Index>(i) * n);
  };
  const Eigen::VectorXd fv = vector_flux_.head(n);
  double lambda = 0;
  for (std::size_t i = 0; i < s; ++i) {
    const auto I = static_cast<Eigen::Index>(i) * n;
    out.thermal_diffusion[i] = -mass_[i] * number_flux(a, i) / d0;  // (17.9)
    lambda -= mass_[i] * std::pow(basis_theta_[i], -1.5) * fv.dot(a.segment(I, n)) / (2 * d * temperature);
  }
  // Collisional heat flux (18.9): −(1/(2d)) Σ_ij L R [x_i ⟨⟨(σ̂·c2)ΔE_1 X_j⟩⟩ + x_j ⟨⟨(σ̂·c1)ΔE_1 X_i⟩⟩] from
  // f0 f^(1), and −(1/(4d)) Σ_ij L² R x_i x_j ⟨⟨ΔE_1 (∂ ln f_j − ∂ ln f_i)⟩⟩ from f0 ∂f0.
  auto collisional_heat = [&](const Eigen::VectorXd& v) {
    double q = 0;
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) {
        const std::size_t P = pair_index(i, j);
        const PairTransferMoments& t = transfer_[P];
        for (int k = 0; k < n; ++k) {
          const auto K = static_cast<std::size_t>(k);
          q -= length_[P] * rate_[P] / (2 * d) *
               (fraction_[i] * t.heat_flux_partner[K] * v(static_cast<Eigen::Index>(j) * n + k) +
                fraction_[j] * t.heat_flux_self[K] * v(static_cast<Eigen::Index>(i) * n + k));
        }
      }
    return q;
  };
  auto gradient_heat = [&](std::size_t i, std::size_t j) {
    const std::size_t P = pair_index(i, j);
    return -length_[P] * length_[P] * rate_[P] / (4 * d);
  };
  if (dense_) {
    double q = collisional_heat(a);
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) {
        const PairTransferMoments& t = transfer_[pair_index(i, j)];
        q += gradient_heat(i, j) * fraction_[i] * fraction_[j] * (t.energy_partner - t.energy_self);
      }
    lambda -= q / temperature;
  }
  out.thermal_conductivity = lambda / kappa0;
  for (std::size_t j = 0; j < s; ++j) {
    const Eigen::VectorXd& b = modes.density[j];
    double heat = 0;
    for (std::size_t i = 0; i < s; ++i) {
      const auto I = static_cast<Eigen::Index>(i) * n;
      out.mutual_diffusion[i * s + j] = -number_flux(b, i) / (mass_[j] * d0);  // (17.9)
      heat += 0.5 * mass_[i] * std::pow(basis_theta_[i], -1.5) * fv.dot(b.segment(I, n)) / d;
    }
    if (dense_) {
      heat += collisional_heat(b);
      if (!weighted_transfer_.empty()) heat += cumulant_gradient_heat(j);  // (17.24)
      for (std::size_t i = 0; i < s; ++i)
        for (std::size_t k = 0; k < s; ++k) {
          const PairTransferMoments& t = transfer_[pair_index(i, k)];
          const double gi = sensitivity_.temperature_ratio[i * s + j], gk = sensitivity_.temperature_ratio[k * s + j];
          double v = (k == j ? fraction_[i] : 0.0) * t.energy - (i == j ? fraction_[k] : 0.0) * t.energy +
                     fraction_[i] * fraction_[k] *
                         (gk * (t.energy_partner - 0.5 * d * t.energy) - gi * (t.energy_self - 0.5 * d * t.energy));
          if (!functionals_.empty())  // (18.22): the off-midpoint contact value, I_jik/x_k per ∇n_j
            v += fraction_[i] * functionals_[pair_index(i, k) * s + j] * t.energy;
          heat += gradient_heat(i, k) * v;
        }
    }
    out.dufour[j] = -fraction_[j] * heat / (temperature * kappa0);  // (17.10)
  }
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j)
      out.pressure_diffusion[i] += mass_[i] * mass_[j] * fraction_[j] * out.mutual_diffusion[i * s + j];
  // D^F_ij = −m_i × the number flux of species i per F_j, reduced by m̄ n D0/T (18.14).
  out.mobility.assign(s * s, 0.0);
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j)
      out.mobility[i * s + j] = -mass_[i] * number_flux(modes.force[j], i) * temperature / d0;
  // GDH's Σ_i L_ij: q ∋ −Σ_j L_j F_j, the kinetic heat flux (17.10) of the force mode plus, dense, its
  // collisional transfer (18.9) (the f0 ∂f0 part has no force term), reduced by κ0 (18.15).
  out.heat_mobility.assign(s, 0.0);
  for (std::size_t j = 0; j < s; ++j) {
    const Eigen::VectorXd& e = modes.force[j];
    double heat = 0;
    for (std::size_t i = 0; i < s; ++i)
      heat +=
          0.5 * mass_[i] * std::pow(basis_theta_[i], -1.5) * fv.dot(e.segment(static_cast<Eigen::Index>(i) * n, n)) / d;
    if (dense_) heat += collisional_heat(e);
    out.heat_mobility[j] = -heat / kappa0;
  }

  species_drift(order, self, cross, out);

  // Shear mode: X_k = (f_k/n_k) Σ_q φ̃_kq Y_2(c_k) S_q, source −2 x_i ((d−1)/d) ⟨x² S_p⟩ (17.11).
  const int nt = order;
  Eigen::MatrixXd kc = leading_blocks(tensor_operator_, s, max_order_, nt);
  const Eigen::VectorXd ft = tensor_flux_.head(nt);
  Eigen::VectorXd sc(S * nt);
  for (std::size_t i = 0; i < s; ++i) {
    const auto I = static_cast<Eigen::Index>(i) * nt;
    kc.block(I, I, nt, nt) += zeta_ * tensor_d_.topLeftCorner(nt, nt);
    sc.segment(I, nt) = -2 * fraction_[i] * (d - 1.0) / d * ft;
    if (!cumulants_.empty())  // (17.20): ⟨x² S_p (S_k − S_k')⟩ of the k ≥ 2 terms
      for (int p = 0; p < nt; ++p)
        for (std::size_t k = 2; k < cumulants_[i].size(); ++k)
          sc(I + p) -= 2 * fraction_[i] * (d - 1.0) / d * cumulants_[i][k] *
                       cumulant_sources_.shear[static_cast<std::size_t>(p)][k];
  }
  if (dense_)  // (18.5): L R x_i x_j 2√θ_j ⟨⟨Δ[Y(c1) S_p] : σ̂c2⟩⟩
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) {
        const std::size_t P = pair_index(i, j);
        const double f = length_[P] * rate_[P] * fraction_[i] * fraction_[j] * 2 * std::sqrt(theta_[j]);
        for (int p = 0; p < nt; ++p)
          sc(static_cast<Eigen::Index>(i) * nt + p) += f * transfer_[P].source_shear[static_cast<std::size_t>(p)];
      }
  const Eigen::VectorXd c = kc.partialPivLu().solve(sc);
  double eta = 0;
  for (std::size_t i = 0; i < s; ++i) {
    const double partial =
        -mass_[i] / theta_[i] * ft.dot(c.segment(static_cast<Eigen::Index>(i) * nt, nt)) / (d * (d + 2.0));
    out.shear_viscosity_kinetic.push_back(partial / eta0);
    eta += partial;
  }
  if (dense_) {
    // (18.8): the f0 f^(1) part −(1/(2(d−1)(d+2))) Σ_ij m_i μ_ji (1+α) L R [x_i ⟨⟨(σ̂·g)σ̂σ̂:Y(c2) 𝒞_j⟩⟩ + …] and
    // the f0 ∂f0 part −(1/(4d(d+2))) Σ_ij m_i μ_ji (1+α) L² R x_i x_j ⟨⟨(σ̂·g)σ̂·(2θ_j v2 − 2θ_i v1)⟩⟩, whose
    // (d+2)/d multiple is the bulk viscosity's f0 ∂f0 part.
    double gradient = 0;
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) {
        const std::size_t P = pair_index(i, j);
        const PairTransferMoments& t = transfer_[P];
        const double w = mass_[i] * mass_[j] / (mass_[i] + mass_[j]) * (1 + alpha_[P]) * length_[P] * rate_[P];
        for (int q = 0; q < nt; ++q) {
          const auto Q = static_cast<std::size_t>(q);
          eta -= w / (2 * (d - 1.0) * (d + 2)) *
                 (fraction_[i] * t.shear_flux_partner[Q] * c(static_cast<Eigen::Index>(j) * nt + q) +
                  fraction_[j] * t.shear_flux_self[Q] * c(static_cast<Eigen::Index>(i) * nt + q));
        }
        gradient -= w * length_[P] * fraction_[i] * fraction_[j] * t.shear_gradient / (4.0 * d * (d + 2));
      }
    eta += gradient;
    const ScalarMode scalar = published ? scalar_mode_without_partial_temperatures() : scalar_mode(order);
    out.bulk_viscosity = ((d + 2.0) / d * gradient + scalar.bulk_viscosity) / eta0;
    out.cooling_rate_first_order = scalar.cooling_rate;
    out.pressure = pressure_;
    // n_i T_i^(1) = (m_i/d) ∫V² 𝒟_i = −(γ_i/2) δ_i1 (T = 1/2), so T_i^(1)/T = −γ_i δ_i1/x_i per unit ∇·u.
    for (std::size_t i = 0; i < s; ++i)
      out.temperature_first_order.push_back(
          fraction_[i] > 0
              ? (published ? 0.0 : -state_.temperature_ratio[i] * scalar.temperature[i] / fraction_[i] * nu0_)
              : std::nan(""));
  }
  out.shear_viscosity = eta / eta0;
  return out;
}

void MixtureNavierStokes::Impl::species_drift(int order, const Eigen::MatrixXd& self, const Eigen::MatrixXd& cross,
                                              MixtureTransportValues& out) const {
  // (17.13): every quantity stays finite as a species becomes a tracer.
  const int d = dimension_;
  const int n = order + 1;
  const VectorModes modes = vector_modes(order, self, cross, true);
  // Specific fluxes ∫V·X_i/x_i = θ_i^{−1/2} M(0,0) φ_i0: heat[i] (∇ln T), density[i][j] (∇ln n_j).
  std::vector<double> heat(s_);
  std::vector<std::vector<double>> density(s_, std::vector<double>(s_));
  for (std::size_t i = 0; i < s_; ++i) {
    const auto I = static_cast<Eigen::Index>(i) * n;
    heat[i] = modes.heat(I) / std::sqrt(basis_theta_[i]);
    for (std::size_t j = 0; j < s_; ++j) density[i][j] = modes.density[j](I) / std::sqrt(basis_theta_[i]);
  }
  // w_i = (1/d) M(0,0) × the specific fluxes, in units of D0.
  const double to_drift = vector_m_(0, 0) / d / unit_reference_gas(d).self_diffusion;
  out.drift.assign(s_ * s_, 0.0);
  out.thermal_drift.assign(s_, 0.0);
  for (std::size_t i = 0; i < s_; ++i) {
    out.thermal_drift[i] = to_drift * heat[i];
    for (std::size_t j = 0; j < s_; ++j) out.drift[i * s_ + j] = to_drift * density[i][j];
  }
  if (s_ != 2) return;
  // j_i = 0: Σ_j density[i][j] ∂ln n_j + heat[i] ∂ln T = 0; ∂p = −ρg with P_l = ∂p/∂n_l/T (1 dilute):
  // x_i P_i ∂ln n_i + x_k P_k ∂ln n_k = −(p* + g*) ∂ln T, g* = ρg/(n ∂T) (theory.md (17.15), (18.10)).
  // Then ∂ln n_i = A (p* + g*) − B and ∂ln(n_i/n) = ∂ln n_i (1 − x_i (1 − P_i/P_k)) + (p* + g*)/P_k = −Λ_i.
  out.segregation.assign(s_, std::nan(""));
  out.segregation_gravity = out.segregation;
  for (std::size_t i = 0; i < 2; ++i) {
    const std::size_t k = 1 - i;
    if (fraction_[k] == 0) continue;
    const double pi = pressure_derivative_[i], pk = pressure_derivative_[k];
    const double denominator = density[i][i] - density[i][k] * fraction_[i] * pi / (fraction_[k] * pk);
    const double a = density[i][k] / (fraction_[k] * pk) / denominator, b = heat[i] / denominator;
    const double c = 1 - fraction_[i] * (1 - pi / pk);
    out.segregation[i] = -(a * pressure_ - b) * c - pressure_ / pk;
    out.segregation_gravity[i] = -a * c - 1 / pk;
  }
}

MixtureNavierStokes::MixtureNavierStokes(const Mixture& mixture, int max_order, MixtureReference reference)
    : impl_(std::make_unique<Impl>(mixture, max_order, reference)) {}
MixtureNavierStokes::~MixtureNavierStokes() = default;
MixtureNavierStokes::MixtureNavierStokes(const MixtureNavierStokes& other)
    : impl_(other.impl_ ? std::make_unique<Impl>(*other.impl_) : nullptr) {}
MixtureNavierStokes& MixtureNavierStokes::operator=(const MixtureNavierStokes& other) {
  if (this != &other) impl_ = other.impl_ ? std::make_unique<Impl>(*other.impl_) : nullptr;
  return *this;
}
MixtureNavierStokes::MixtureNavierStokes(MixtureNavierStokes&&) noexcept = default;
MixtureNavierStokes& MixtureNavierStokes::operator=(MixtureNavierStokes&&) noexcept = default;

MixtureTransportValues MixtureNavierStokes::coefficients(int order) const {
  return impl_->coefficients(order, MixtureTruncation::complete);
}
MixtureTransportValues MixtureNavierStokes::coefficients(int order, MixtureTruncation truncation) const {
  return impl_->coefficients(order, truncation);
}
int MixtureNavierStokes::max_order() const { return impl_->max_order_; }
const MixtureCoolingState& MixtureNavierStokes::cooling_state() const { return impl_->state_; }
const MixtureCoolingSensitivity& MixtureNavierStokes::cooling_sensitivity() const { return impl_->sensitivity_; }
const std::vector<std::vector<double>>& MixtureNavierStokes::cumulant_sensitivity() const {
  return impl_->cumulant_sensitivity_;
}

}  // namespace gkt
