// A solver-side use of an installed gkt: the first-Sonine transport coefficients of the dilute
// smooth inelastic gas at one cell's state (dimension, restitution α), from the per-cell call
// gkt::first_sonine_values (docs/theory.md (10.8); no allocation). Prints one CSV row under the
// canonical column names of `gkt table`, so tools/check_install.sh can compare the two.
//
//   gkt_consumer [DIMENSION ALPHA]      (default: 3 0.8)
#include <cstdlib>
#include <exception>
#include <iomanip>
#include <iostream>
#include <stdexcept>
#include <string>

#include "gkt/transport/closed_forms/first_sonine_formulas.hpp"

int main(int argc, char** argv) {
  if (argc != 1 && argc != 3) {
    std::cerr << "usage: gkt_consumer [DIMENSION ALPHA]\n";
    return 2;
  }
  try {
    const int dimension = argc == 3 ? std::stoi(argv[1]) : 3;
    const double alpha = argc == 3 ? std::stod(argv[2]) : 0.8;
    const gkt::FirstSonineValues v = gkt::first_sonine_values(dimension, alpha);
    std::cout << "dimension,alpha";
    for (const auto& name : gkt::kFirstSonineCoefficients) std::cout << ',' << name;
    std::cout << '\n'
              << dimension << ',' << alpha << std::setprecision(17) << ',' << v.a2 << ',' << v.cooling_rate << ','
              << v.shear_viscosity << ',' << v.thermal_conductivity << ',' << v.density_heat_coefficient << '\n';
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
  return std::cout ? EXIT_SUCCESS : EXIT_FAILURE;
}
