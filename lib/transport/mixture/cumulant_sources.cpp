#include "transport/mixture/cumulant_sources.hpp"

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/sonine.hpp"

namespace gkt::detail {

CumulantSources cumulant_sources(int d, int n_vector, int n_tensor, int k_max) {
  using Poly = std::vector<Rational>;
  auto multiply = [](const Poly& a, const Poly& b) {
    Poly out(a.size() + b.size() - 1, Rational(0));
    for (std::size_t i = 0; i < a.size(); ++i)
      for (std::size_t j = 0; j < b.size(); ++j) out[i + j] += a[i] * b[j];
    return out;
  };
  auto add = [](Poly a, const Poly& b, const Rational& scale) {
    if (a.size() < b.size()) a.resize(b.size(), Rational(0));
    for (std::size_t i = 0; i < b.size(); ++i) a[i] += scale * b[i];
    return a;
  };
  auto derivative = [](const Poly& a) {
    Poly out(a.size() > 1 ? a.size() - 1 : 1, Rational(0));
    for (std::size_t i = 1; i < a.size(); ++i) out[i - 1] = Rational(static_cast<long>(i)) * a[i];
    return out;
  };
  const Rational half_d(d, 2);
  auto average = [&](const Poly& a) {  // ⟨x^n⟩ = (d/2)_n
    Rational acc(0), moment(1);
    for (std::size_t n = 0; n < a.size(); ++n) {
      acc += a[n] * moment;
      moment *= half_d + Rational(static_cast<long>(n));
    }
    return acc.to_double();
  };
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
      w.push_back(average(multiply(xs, sk)));
      t.push_back(average(multiply(xs, add(multiply(x_minus, sk), multiply(x, dk), Rational(-1)))));
      f.push_back(average(multiply(xs, add(dk, sk, Rational(-1)))));
    }
    out.weight.push_back(std::move(w));
    out.temperature.push_back(std::move(t));
    out.drift.push_back(std::move(f));
  }
  for (const auto& sp : ten) {
    std::vector<double> v;
    const Poly xxs = multiply(multiply(x, x), sp);
    for (const auto& sk : sca) v.push_back(average(multiply(xxs, add(sk, derivative(sk), Rational(-1)))));
    out.shear.push_back(std::move(v));
  }
  return out;
}

}  // namespace gkt::detail
