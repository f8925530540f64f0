// The two weights in which the Chapman–Enskog unknowns are expanded (docs/theory.md §10.2, §10.5).
#pragma once

namespace gkt {

/// How the unknowns of the Chapman–Enskog equations are expanded (theory.md §10.2, §10.5).
enum class SonineScheme {
  standard,  ///< f_M × Sonine polynomials (Maxwellian weight; [brey1998], [garzo1999])
  modified,  ///< f_HCS × Sonine polynomials (HCS weight; [garzo2007modified])
};

}  // namespace gkt
