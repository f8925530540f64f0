// What `gkt formula` asks a model for: the exact closed form of one coefficient.
#pragma once

#include <string>
#include <variant>

#include "gkt/algebra/rational_function.hpp"
#include "gkt/transport/closed_forms/enskog_closed_form.hpp"
#include "gkt/transport/common/sonine_scheme.hpp"

namespace gkt {

/// The closed form of one coefficient at fixed parameters: a rational function of α (a constant
/// when the model has no α, e.g. the exact elastic Sonine approximants), or for the dense gas
/// Σ R_m(α) m with φ, χ(φ) and φ dχ/dφ symbolic (theory.md §15.7).
struct ClosedForm {
  /// The form: a rational function of α, or the dense-gas sum over Enskog monomials.
  std::variant<RationalFunction, EnskogClosedForm> form;
  /// Spatial dimension d the form was derived for.
  int dimension = 3;
  SonineScheme scheme = SonineScheme::standard;  ///< trial-function weight the form was derived with
};

}  // namespace gkt
