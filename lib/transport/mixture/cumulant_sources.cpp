#include "transport/mixture/cumulant_sources.hpp"

#include <algorithm>

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/sonine.hpp"

namespace gkt::detail {

namespace {

using Poly = std::vector<Rational>;

Poly multiply(const Poly& a, const Poly& b) {
  Poly out(a.size() + b.size() - 1, Rational(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) out[i + j] += a[i] * b[j];
  return out;
}

Poly add(Poly a, const Poly& b, const Rational& scale) {
  if (a.size() < b.size()) a.resize(b.size(), Rational(0));
  for (std::size_t i = 0; i < b.size(); ++i) a[i] += scale * b[i];
  return a;
}

Poly derivative(const Poly& a) {
  Poly out(a.size() > 1 ? a.size() - 1 : 1, Rational(0));
  for (std::size_t i = 1; i < a.size(); ++i) out[i - 1] = Rational(static_cast<long>(i)) * a[i];
  return out;
}

/// ⟨a(x)⟩ over x^{d/2−1}e^{−x}/Γ(d/2): ⟨x^n⟩ = (d/2)_n.
double average(int d, const Poly& a) {
  const Rational half_d(d, 2);
  Rational acc(0), moment(1);
  for (std::size_t n = 0; n < a.size(); ++n) {
    acc += a[n] * moment;
    moment *= half_d + Rational(static_cast<long>(n));
  }
  return acc.to_double();
}

}  // namespace

CumulantSources cumulant_sources(int d, int n_vector, int n_tensor, int k_max) {
  const Rational half_d(d, 2);
  const Poly x{Rational(0), Rational(1)}, x_minus{-half_d, Rational(1)};
  const auto vec = sonine_table(sonine_twice_m(d, 1), n_vector);
  const auto ten = sonine_table(sonine_twice_m(d, 2), n_tensor);
  const auto sca = sonine_table(sonine_twice_m(d, 0), k_max);
  CumulantSources out;
  for (const auto& sp : vec) {
    std::vector<double> w, t, f;
    const Poly xs = multiply(x, sp);
    for (const auto& sk : sca) {
      const Poly dk = derivative(sk);
      w.push_back(average(d, multiply(xs, sk)));
      t.push_back(average(d, multiply(xs, add(multiply(x_minus, sk), multiply(x, dk), Rational(-1)))));
      f.push_back(average(d, multiply(xs, add(dk, sk, Rational(-1)))));
    }
    out.weight.push_back(std::move(w));
    out.temperature.push_back(std::move(t));
    out.drift.push_back(std::move(f));
  }
  for (const auto& sp : ten) {
    std::vector<double> v;
    const Poly xxs = multiply(multiply(x, x), sp);
    for (const auto& sk : sca) v.push_back(average(d, multiply(xxs, add(sk, derivative(sk), Rational(-1)))));
    out.shear.push_back(std::move(v));
  }
  return out;
}

ScalarCumulantSources scalar_cumulant_sources(int d, int n_scalar, int k_max) {
  const Poly x{Rational(0), Rational(1)}, x_minus{Rational(-d, 2), Rational(1)};
  const auto sca = sonine_table(sonine_twice_m(d, 0), std::max(n_scalar, k_max));
  ScalarCumulantSources out;
  for (int p = 0; p <= n_scalar; ++p) {
    std::vector<double> w, t;
    for (int k = 0; k <= k_max; ++k) {
      const Poly& sp = sca[static_cast<std::size_t>(p)];
      const Poly& sk = sca[static_cast<std::size_t>(k)];
      w.push_back(average(d, multiply(sp, sk)));
      t.push_back(average(d, multiply(sp, add(multiply(x_minus, sk), multiply(x, derivative(sk)), Rational(-1)))));
    }
    out.weight.push_back(std::move(w));
    out.temperature.push_back(std::move(t));
  }
  return out;
}

}  // namespace gkt::detail
