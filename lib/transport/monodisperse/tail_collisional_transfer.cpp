// Collisional-transfer kernels of the tail scheme on its radial rule (tail_collisional_transfer.hpp;
// docs/theory.md §15.8). Every integrand is written through X = g·σ̂ and XY = (g·σ̂)(G·σ̂): with
// H = (1+α) X σ̂, H·v = (1+α) X (σ̂·v) and X(σ̂·c1) = XY + X²/2, X(σ̂·c2) = XY − X²/2 (c1,2 = G ± g/2).
#include "transport/monodisperse/tail_collisional_transfer.hpp"
#include "transport/monodisperse/tail_quadrature.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>

namespace gkt::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// The σ̂ integrals at one node, the points gathered in blocks whose Sonine recurrences run side by side.
class TransferIntegral {
 public:
  TransferIntegral(int dimension, double alpha, int p_max)
      : d_(dimension), alpha_(alpha), p_max_(p_max), width_(static_cast<std::size_t>(p_max + 1)) {
    sums_.assign(3 * width_, 0.0);
    loss_s_.resize(width_);
    loss_v_.resize(width_);
    loss_t_.resize(width_);
    inverse_.resize(width_);
    for (std::size_t n = 0; n < width_; ++n) inverse_[n] = 1.0 / static_cast<double>(n + 1);
    if (dimension == 3) {
      // Polynomial in s after the azimuth average (degree ≤ 2 p_max + 10 with the weights and H factors);
      // Gauss–Chebyshev in cos φ exact to 2 n_phi − 1 ≥ p_max + 6.
      s_rule_ = gauss_legendre(p_max + 6);
      const int n_phi = p_max / 2 + 4;
      for (int j = 0; j < n_phi; ++j) cos_phi_.push_back(std::cos(kPi * (j + 0.5) / n_phi));
    } else {
      // A trigonometric polynomial of degree ≲ 2 p_max + 8 in the angle of σ̂ on [0, π/2].
      s_rule_ = gauss_legendre(2 * p_max + 16);
      cos_phi_ = {1.0, -1.0};
    }
  }

  void begin(double x1, double x2) {
    x1_ = x1;
    x2_ = x2;
    const double m = d_ / 2.0 - 1;
    sonine_values(p_max_, m, x1, loss_s_.data());
    sonine_values(p_max_, m + 1, x1, loss_v_.data());
    sonine_values(p_max_, m + 2, x1, loss_t_.data());
    std::fill(sums_.begin(), sums_.end(), 0.0);
    scalars_.fill(0.0);
    loss_shear_ = loss_heat_ = loss_scalar_ = 0;
    count_ = 0;
  }

  /// Adds the σ̂ integral at relative speed g with the weight of the angle between c1 and c2.
  void add(double g, double w_angle) {
    const double a1 = 1 + alpha_, x1 = x1_, x2 = x2_, dd = d_;
    const double gg = (x1 - x2) / 2, big_g2 = (2 * x1 + 2 * x2 - g * g) / 4, v12 = (x1 + x2 - g * g) / 2;
    const double perp2 = g * g * big_g2 - gg * gg, g_perp = perp2 > 0 ? std::sqrt(perp2) : 0.0;
    for (std::size_t is = 0; is < s_rule_.x.size(); ++is) {
      double sv = 0, sq = 0, w_s = 0;
      if (d_ == 3) {  // σ̂ = s ĝ + √(1−s²)(cos φ, sin φ): dσ̂ = ds dφ
        sv = s_rule_.x[is];
        sq = std::sqrt(1 - sv * sv);
        w_s = s_rule_.w[is] * w_angle * 2 * kPi / static_cast<double>(cos_phi_.size());
      } else {  // σ̂ = cos θ ĝ ± sin θ ĝ⊥, θ ∈ [0, π/2]: dσ̂ = dθ per sign
        const double theta = 0.5 * kPi * s_rule_.x[is];
        sv = std::cos(theta);
        sq = std::sin(theta);
        w_s = 0.5 * kPi * s_rule_.w[is] * w_angle;
      }
      const double big_x = g * sv, x_sq = big_x * big_x;
      for (const double cp : cos_phi_) {
        const double xy = sv * sv * gg + sv * sq * cp * g_perp;  // (g·σ̂)(G·σ̂)
        const double h_c2 = a1 * (xy - x_sq / 2), h_c1 = a1 * (xy + x_sq / 2), h_g = a1 * xy;
        const double h_c1p = a1 * (xy - alpha_ * x_sq / 2);  // H·c1', c1' = c1 − ((1+α)/2) X σ̂
        const double u = x1 - a1 * xy - (1 - alpha_ * alpha_) * x_sq / 4;
        const double c1p_c2 = v12 - 0.5 * a1 * (xy - x_sq / 2);
        const double w = w_s;
        loss_shear_ += w * (h_c1 * v12 - x1 * h_c2 / dd);
        loss_heat_ += w * h_c1;
        loss_scalar_ += w * h_c2;
        scalars_[kTransferShearFlux] += w * (h_c2 * h_c2 - a1 * a1 * x_sq * x2 / dd);
        scalars_[kTransferHeatFlux] += w * h_g * h_c2;
        scalars_[kTransferShearGradient] += w * big_x * h_c2;
        scalars_[kTransferHeatGradient] += w * big_x * h_g;
        scalars_[kTransferCoolingGradient] += w * x_sq * h_c2;
        scalars_[kTransferCoolingScalar] += w * x_sq * big_x;
        const std::size_t j = count_++;
        energy_[j] = u;
        pre_t_[j] = w * (h_c1p * c1p_c2 - u * h_c2 / dd);
        pre_v_[j] = w * h_c1p;
        pre_s_[j] = w * h_c2;
        if (count_ == kBlock) flush();
      }
    }
  }

  /// Writes the node's 3 (p_max + 1) + kTransferValues values times `measure` to `out` (not yet normalised).
  void finish(double measure, double* out) {
    flush();
    for (std::size_t p = 0; p < width_; ++p) {
      out[p] = (sums_[p] - loss_shear_ * loss_t_[p]) * measure;
      out[width_ + p] = (sums_[width_ + p] - loss_heat_ * loss_v_[p]) * measure;
      out[2 * width_ + p] = (sums_[2 * width_ + p] - loss_scalar_ * loss_s_[p]) * measure;
    }
    for (std::size_t v = 0; v < kTransferValues; ++v) out[3 * width_ + v] = scalars_[v] * measure;
  }

 private:
  static constexpr std::size_t kBlock = 64;

  void flush() {
    if (count_ == 0) return;
    const double m = d_ / 2.0 - 1;
    std::array<double, kBlock> s_prev{}, s{}, v{}, t{};
    for (std::size_t j = 0; j < count_; ++j) s[j] = v[j] = t[j] = 1;
    for (int p = 0; p <= p_max_; ++p) {
      const auto pu = static_cast<std::size_t>(p);
      double at = 0, av = 0, as = 0;
      for (std::size_t j = 0; j < count_; ++j) {
        at += pre_t_[j] * t[j];
        av += pre_v_[j] * v[j];
        as += pre_s_[j] * s[j];
      }
      sums_[pu] += at;
      sums_[width_ + pu] += av;
      sums_[2 * width_ + pu] += as;
      if (p == p_max_) break;
      // S_{p+1} = ((2p + 1 + m − u) S_p − (p + m) S_{p−1})/(p + 1); S^{(m+1)}_p = Σ_{q ≤ p} S^{(m)}_q.
      const double a = 2 * p + 1 + m, b = p + m, inv = inverse_[pu];
      for (std::size_t j = 0; j < count_; ++j) {
        const double sn = ((a - energy_[j]) * s[j] - b * s_prev[j]) * inv;
        s_prev[j] = s[j];
        s[j] = sn;
        v[j] += sn;
        t[j] += v[j];
      }
    }
    count_ = 0;
  }

  int d_;
  double alpha_;
  int p_max_;
  std::size_t width_;
  Rule s_rule_;
  std::vector<double> cos_phi_, sums_, loss_s_, loss_v_, loss_t_, inverse_;
  std::array<double, kTransferValues> scalars_{};
  double x1_ = 0, x2_ = 0, loss_shear_ = 0, loss_heat_ = 0, loss_scalar_ = 0;
  std::size_t count_ = 0;
  std::array<double, kBlock> energy_{}, pre_t_{}, pre_v_{}, pre_s_{};
};

}  // namespace

double transfer_normalisation(int dimension, int power) {
  const double d = dimension, n = 1 + power;
  const double hemisphere =
      dimension == 3 ? 2 * kPi / (n + 1) : std::sqrt(kPi) * std::tgamma((n + 1) / 2) / std::tgamma(n / 2 + 1);
  // ⟨g^n⟩ over f_M(c1) f_M(c2): g is Gaussian with variance 1/2 per component doubled, exp(−g²/2).
  return hemisphere * std::pow(2.0, n / 2) * std::tgamma((d + n) / 2) / std::tgamma(d / 2);
}

TransferKernel collisional_transfer_kernel(int dimension, double alpha, int p_max,
                                           const std::vector<TransferNode>& nodes) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  TransferKernel k;
  k.p_max = p_max;
  const std::size_t stride = k.stride(), width = static_cast<std::size_t>(p_max + 1);
  k.values.assign(nodes.size() * stride, 0.0);
  const Rule g_rule = gauss_legendre(p_max + 8), theta_rule = gauss_legendre(2 * p_max + 24);
  // Per column: 1/N_s of its average (sources and fluxes s = −1; gradients 0; cooling +1, +2).
  std::vector<double> norm(stride, 1 / transfer_normalisation(dimension, -1));
  norm[3 * width + kTransferShearGradient] = norm[3 * width + kTransferHeatGradient] =
      1 / transfer_normalisation(dimension, 0);
  norm[3 * width + kTransferCoolingGradient] = 1 / transfer_normalisation(dimension, 1);
  norm[3 * width + kTransferCoolingScalar] = 1 / transfer_normalisation(dimension, 2);
  auto range = [&](std::size_t first, std::size_t last) {
    TransferIntegral sigma(dimension, alpha, p_max);
    for (std::size_t node = first; node < last; ++node) {
      const double c1 = nodes[node].c1, c2 = nodes[node].c2, x1 = c1 * c1, x2 = c2 * c2;
      sigma.begin(x1, x2);
      if (dimension == 3) {  // ∫_{−1}^{1} dμ = ∫ g dg/(c1 c2): polynomial in g
        const double lo = std::fabs(c1 - c2), hi = c1 + c2;
        for (std::size_t i = 0; i < g_rule.x.size(); ++i) {
          const double g = lo + (hi - lo) * g_rule.x[i];
          sigma.add(g, g_rule.w[i] * (hi - lo) * g / (c1 * c2));
        }
      } else {  // ∫_0^π dθ, θ = η sinh v (as the tail kernel, theory.md §10.6)
        const double eta = std::max(std::fabs(std::log(c1 / c2)), 1e-12), v_max = std::asinh(kPi / eta);
        for (std::size_t i = 0; i < theta_rule.x.size(); ++i) {
          const double v = v_max * theta_rule.x[i], theta = eta * std::sinh(v);
          const double g = std::sqrt(std::max(0.0, x1 + x2 - 2 * c1 * c2 * std::cos(theta)));
          sigma.add(g, theta_rule.w[i] * v_max * eta * std::cosh(v));
        }
      }
      // ∫d^d c1 d^d c2 of isotropic functions: 3D (4π)(2π) c1² c2² ∫dμ; 2D (2π) c1 c2 · 2∫_0^π dθ.
      const double measure = dimension == 3 ? nodes[node].weight * (4 * kPi) * (2 * kPi) * x1 * x2
                                            : nodes[node].weight * 4 * kPi * c1 * c2;
      double* out = &k.values[node * stride];
      sigma.finish(measure, out);
      for (std::size_t i = 0; i < stride; ++i) out[i] *= norm[i];
    }
  };
  const std::size_t n = nodes.size();
  const std::size_t threads = n < 4096 ? 1 : std::clamp(std::thread::hardware_concurrency(), 1U, 8U);
  std::vector<std::thread> pool;
  std::size_t started = 1;
  try {
    for (; started < threads; ++started) pool.emplace_back(range, started * n / threads, (started + 1) * n / threads);
  } catch (const std::system_error&) {  // no thread to be had: the rest here
  }
  range(0, n / threads);
  for (std::size_t i = started; i < threads; ++i) range(i * n / threads, (i + 1) * n / threads);
  for (auto& t : pool) t.join();
  return k;
}

}  // namespace gkt::detail
