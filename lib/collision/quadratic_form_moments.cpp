#include "gkt/collision/quadratic_form_moments.hpp"

#include <cmath>
#include <stdexcept>

#include "collision/generating_series.hpp"

namespace gkt {

SlotVector slot_vector(Slot s) {
  SlotVector v{Rational(0), Rational(0), Rational(0), Rational(0)};
  v[static_cast<std::size_t>(s)] = Rational(1);
  return v;
}

SlotVector collision_vector() { return {Rational(1), Rational(-1), Rational(-1), Rational(1)}; }

SlotVector combine(const SlotVector& a, const SlotVector& b, const Rational& c) {
  SlotVector r = a;
  for (std::size_t i = 0; i < 4; ++i) r[i] += c * b[i];
  return r;
}

VelocityForm dot_form(const SlotVector& a, const SlotVector& b) {
  VelocityForm q{};
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) q[i][j] = (a[i] * b[j] + a[j] * b[i]) / Rational(2);
  return q;
}

template <class Ring>
QuadraticFormMoments<Ring>::QuadraticFormMoments(const CollisionPair& pair, const Ring& alpha,
                                                 const std::vector<VelocityForm>& forms,
                                                 const std::vector<int>& degrees, const Rational& power) {
  pair.validate();
  if (forms.size() > 4 || forms.size() != degrees.size())
    throw std::invalid_argument("QuadraticFormMoments: up to four forms, one degree each");
  std::array<detail::ExactForm, detail::kVariables> dq{};
  detail::Exponents box{};
  for (std::size_t v = 0; v < forms.size(); ++v) {
    if (degrees[v] < 0) throw std::invalid_argument("QuadraticFormMoments: negative degree");
    for (std::size_t a = 0; a < 4; ++a)
      for (std::size_t b = 0; b < 4; ++b) dq[v][a][b] = -forms[v][a][b];  // e^{+x F}: coefficient k! ↔ ⟨F^k⟩
    box[v] = degrees[v];
  }
  const auto f =
      detail::expand_gaussian_collision_integral<Ring>(pair, alpha, detail::reference_form(pair), dq, box, power);
  const double s = power.to_double();
  power_factor_ = std::tgamma(1 + s / 2) * std::pow((f.a0 / f.n2_0).to_double(), s / 2);
  box_ = {box[0], box[1], box[2], box[3]};
  values_.reserve(f.coefficients.size());
  for (int k0 = 0; k0 <= box[0]; ++k0)
    for (int k1 = 0; k1 <= box[1]; ++k1)
      for (int k2 = 0; k2 <= box[2]; ++k2)
        for (int k3 = 0; k3 <= box[3]; ++k3) {
          Ring v = f(k0, k1, k2, k3);
          detail::scale(v, Rational::factorial(static_cast<unsigned long>(k0)) *
                               Rational::factorial(static_cast<unsigned long>(k1)) *
                               Rational::factorial(static_cast<unsigned long>(k2)) *
                               Rational::factorial(static_cast<unsigned long>(k3)));
          values_.push_back(std::move(v));
        }
}

template <class Ring>
Ring QuadraticFormMoments<Ring>::moment(const std::array<int, 4>& k) const {
  std::size_t index = 0;
  for (std::size_t v = 0; v < 4; ++v) {
    if (k[v] < 0 || k[v] > box_[v]) throw std::out_of_range("QuadraticFormMoments: degree outside the expanded box");
    index = index * static_cast<std::size_t>(box_[v] + 1) + static_cast<std::size_t>(k[v]);
  }
  return values_[index];
}

template class QuadraticFormMoments<Rational>;
template class QuadraticFormMoments<RationalPolynomial>;

}  // namespace gkt
