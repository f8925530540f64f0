#include "gkt/transport/closed_forms/enskog_closed_form.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gkt {

EnskogClosedForm EnskogClosedForm::term(const RationalFunction& r, const EnskogMonomial& m) {
  EnskogClosedForm f;
  f.accumulate(m, r);
  return f;
}

void EnskogClosedForm::accumulate(const EnskogMonomial& m, const RationalFunction& r) {
  if (r.numerator.is_zero()) return;
  const auto it = terms_.find(m);
  if (it == terms_.end()) {
    terms_.emplace(m, r);
    return;
  }
  it->second = it->second + r;
  if (it->second.numerator.is_zero()) terms_.erase(it);
}

double EnskogClosedForm::evaluate(const Rational& alpha, double phi, double chi, double phi_dchi) const {
  double sum = 0;
  for (const auto& [m, r] : terms_)
    sum += r.evaluate(alpha).to_double() * std::pow(phi, m.phi) * std::pow(chi, m.chi) *
           std::pow(phi_dchi, m.phi_dchi) * std::pow(std::numbers::pi, -m.inv_pi);
  return sum;
}

RationalFunction EnskogClosedForm::dilute_limit() const {
  RationalFunction sum{RationalPolynomial(0L), RationalPolynomial(1L)};
  for (const auto& [m, r] : terms_) {
    if (m.phi != 0 || m.phi_dchi != 0) continue;
    if (m.inv_pi != 0) throw std::domain_error("EnskogClosedForm: a dilute term with a power of π");
    sum = sum + r;
  }
  return sum;
}

bool EnskogClosedForm::equals(const EnskogClosedForm& other) const {
  if (terms_.size() != other.terms_.size()) return false;
  for (const auto& [m, r] : terms_) {
    const auto it = other.terms_.find(m);
    if (it == other.terms_.end() || !r.equals(it->second)) return false;
  }
  return true;
}

EnskogClosedForm operator+(const EnskogClosedForm& a, const EnskogClosedForm& b) {
  EnskogClosedForm s = a;
  for (const auto& [m, r] : b.terms_) s.accumulate(m, r);
  return s;
}

EnskogClosedForm operator-(const EnskogClosedForm& a, const EnskogClosedForm& b) {
  const RationalFunction minus_one{RationalPolynomial(-1L), RationalPolynomial(1L)};
  EnskogClosedForm s = a;
  for (const auto& [m, r] : b.terms_) s.accumulate(m, minus_one * r);
  return s;
}

EnskogClosedForm operator*(const EnskogClosedForm& a, const EnskogClosedForm& b) {
  EnskogClosedForm p;
  for (const auto& [ma, ra] : a.terms_)
    for (const auto& [mb, rb] : b.terms_)
      p.accumulate({ma.phi + mb.phi, ma.chi + mb.chi, ma.phi_dchi + mb.phi_dchi, ma.inv_pi + mb.inv_pi}, ra * rb);
  return p;
}

EnskogClosedForm operator/(const EnskogClosedForm& a, const EnskogClosedForm& b) {
  if (b.terms_.size() != 1)
    throw std::domain_error("EnskogClosedForm: division by a sum of " + std::to_string(b.terms_.size()) + " terms");
  const auto& [mb, rb] = *b.terms_.begin();
  EnskogClosedForm q;
  for (const auto& [ma, ra] : a.terms_)
    q.accumulate({ma.phi - mb.phi, ma.chi - mb.chi, ma.phi_dchi - mb.phi_dchi, ma.inv_pi - mb.inv_pi}, ra / rb);
  return q;
}

}  // namespace gkt
