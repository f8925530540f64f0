#include "gkt/operators/cumulant_hierarchy.hpp"

#include <stdexcept>
#include <string>

namespace gkt {

CumulantHierarchy::CumulantHierarchy(int dimension, int k_max, std::vector<double> t, std::vector<double> e,
                                     std::vector<double> c, std::vector<std::vector<double>> w,
                                     std::vector<double> norms)
    : dimension_(dimension),
      k_max_(k_max),
      t_(std::move(t)),
      e_(std::move(e)),
      c_(std::move(c)),
      w_(std::move(w)),
      norms_(std::move(norms)) {}

double CumulantHierarchy::energy_moment(const std::vector<double>& a) const {
  const int kn = k_max_ + 1;
  double r = 0;
  for (int k = 0; k < kn; ++k)
    for (int l = 0; l < kn; ++l) r += a[k] * a[l] * e_[static_cast<std::size_t>(k) * kn + l];
  return r;
}

double CumulantHierarchy::collision_rate(const std::vector<double>& a) const {
  const int kn = k_max_ + 1;
  double r = 0;
  for (int k = 0; k < kn; ++k)
    for (int l = 0; l < kn; ++l) r += a[k] * a[l] * c_[static_cast<std::size_t>(k) * kn + l];
  return r;
}

void CumulantHierarchy::gradients(const std::vector<double>& a, std::vector<double>& energy,
                                  std::vector<double>& rate) const {
  const int kn = k_max_ + 1;
  energy.assign(static_cast<std::size_t>(kn), 0.0);
  rate.assign(static_cast<std::size_t>(kn), 0.0);
  for (int k = 0; k < kn; ++k)
    for (int l = 0; l < kn; ++l) {
      energy[k] += a[l] * (e_[static_cast<std::size_t>(k) * kn + l] + e_[static_cast<std::size_t>(l) * kn + k]);
      rate[k] += a[l] * (c_[static_cast<std::size_t>(k) * kn + l] + c_[static_cast<std::size_t>(l) * kn + k]);
    }
}

void CumulantHierarchy::residual(const std::vector<double>& a, std::vector<double>& f,
                                 std::vector<double>* jacobian) const {
  // theory.md (9.3): F_p = R[S_p](a) − (2/d) R_1(a) ⟨x S_p'⟩_a, p = 2..K.
  const int kn = k_max_ + 1, unknowns = k_max_ - 1;
  auto t = [&](int p, int k, int l) { return t_[(static_cast<std::size_t>(p) * kn + k) * kn + l]; };
  auto e = [&](int k, int l) { return e_[static_cast<std::size_t>(k) * kn + l]; };
  const double two_over_d = 2.0 / dimension_;
  double r1 = 0;
  std::vector<double> dr1(static_cast<std::size_t>(kn), 0.0);
  for (int k = 0; k < kn; ++k)
    for (int l = 0; l < kn; ++l) {
      r1 += a[k] * a[l] * e(k, l);
      dr1[k] += a[l] * (e(k, l) + e(l, k));
    }
  f.assign(static_cast<std::size_t>(unknowns), 0.0);
  for (int p = 2; p <= k_max_; ++p) {
    double rp = 0, wp = 0;
    for (int k = 0; k < kn; ++k) {
      wp += a[k] * w_[p][k];
      for (int l = 0; l < kn; ++l) rp += a[k] * a[l] * t(p, k, l);
    }
    f[static_cast<std::size_t>(p - 2)] = rp - two_over_d * r1 * wp;
    if (jacobian != nullptr)
      for (int q = 2; q <= k_max_; ++q) {
        double drp = 0;
        for (int l = 0; l < kn; ++l) drp += a[l] * (t(p, q, l) + t(p, l, q));
        (*jacobian)[static_cast<std::size_t>(p - 2) * unknowns + (q - 2)] =
            drp - two_over_d * (dr1[q] * wp + r1 * w_[p][q]);
      }
  }
}

void CumulantHierarchy::assign_power_series(double x, std::span<const std::vector<double>> transfer_series,
                                            std::span<const std::vector<double>> energy_series) {
  if (transfer_series.empty() || transfer_series.size() != energy_series.size())
    throw std::invalid_argument(
        "cumulant hierarchy: the transfer and energy series must be non-empty and of equal "
        "length, got " +
        std::to_string(transfer_series.size()) + " and " + std::to_string(energy_series.size()));
  for (std::size_t j = 0; j < transfer_series.size(); ++j)
    if (transfer_series[j].size() != t_.size() || energy_series[j].size() != e_.size())
      throw std::invalid_argument("cumulant hierarchy: series term " + std::to_string(j) +
                                  " does not match the truncation K = " + std::to_string(k_max_));
  t_ = transfer_series[0];  // same sizes: std::vector copy-assignment reuses the storage
  e_ = energy_series[0];
  double power = 1;
  for (std::size_t order = 1; order < transfer_series.size(); ++order) {
    power *= x;
    for (std::size_t i = 0; i < t_.size(); ++i) t_[i] += power * transfer_series[order][i];
    for (std::size_t i = 0; i < e_.size(); ++i) e_[i] += power * energy_series[order][i];
  }
}

}  // namespace gkt
