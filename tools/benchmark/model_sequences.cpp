// Prints the long Sonine sequences that theory.md §6 ("The other models' scans") replays the tolerance
// scans of hard-spheres, rough, mixture and viscoelastic on: orders well past each model's cap, from the
// transport layer each model reads, one CSV line per value (%.17g): model,state,column,order,value.
//
//   build/bin/gkt_model_sequences > model_sequences.csv
//   build/bin/gkt_model_sequences rough > rough_sequences.csv   (one model only)
//   python3 tools/model_truncation_survey.py model_sequences.csv
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/mixture_navier_stokes.hpp"
#include "gkt/transport/mixture/tracer_diffusion.hpp"
#include "gkt/transport/monodisperse/hard_spheres.hpp"
#include "gkt/transport/rough/rough_sonine_transport.hpp"
#include "gkt/transport/viscoelastic/viscoelastic_transport.hpp"

namespace {
void row(const char* model, const std::string& state, const char* column, int order, double value) {
  std::printf("%s,%s,%s,%d,%.17g\n", model, state.c_str(), column, order, value);
  std::fflush(stdout);
}
}  // namespace

int main(int argc, char** argv) {
  // One model only (argv[1]), or every model.
  const auto wanted = [&](const char* model) { return argc < 2 || std::strcmp(argv[1], model) == 0; };
  std::printf("model,state,column,order,value\n");
  for (const int d : {2, 3}) {
    if (!wanted("hard-spheres")) break;  // the model's cap is 40; orders to 43
    gkt::HardSphereSonineSystem hs(d);
    const char* names[] = {"shear_viscosity", "thermal_conductivity", "self_diffusion"};
    for (int c = 0; c < 3; ++c)
      for (int n = 1; n <= 43; ++n)
        row("hard-spheres", "d=" + std::to_string(d), names[c], n,
            hs.reduced_coefficient(static_cast<gkt::HardSphereCoefficient>(c), n).to_double());
  }
  if (wanted("viscoelastic")) {  // viscoelastic: the series to the transport layer's N = 8 (model cap 6), summed at δ'
    std::vector<gkt::ViscoelasticTransportSeries> series;
    for (int n = 1; n <= 8; ++n) series.push_back(gkt::viscoelastic_transport_series(n));
    for (const double x : {0.05, 0.1, 0.2})
      for (int n = 1; n <= 8; ++n) {
        const gkt::ViscoelasticState s = gkt::viscoelastic_state(series[static_cast<std::size_t>(n) - 1], x);
        const std::string state = "delta_prime=" + std::to_string(x);
        row("viscoelastic", state, "a2", n, s.a2);
        row("viscoelastic", state, "cooling_rate", n, s.cooling_rate);
        row("viscoelastic", state, "shear_viscosity", n, s.shear_viscosity);
        row("viscoelastic", state, "thermal_conductivity", n, s.thermal_conductivity);
        row("viscoelastic", state, "density_heat_coefficient", n, s.density_heat_coefficient);
      }
  }
  // mixture: dilute binaries, orders to 16 (model cap 12, operator to 14)
  struct Binary {
    double mass, diameter, x, alpha;
  };
  for (const Binary& b : {Binary{2, 1.2, 0.5, 0.8}, Binary{4, 1, 0.3, 0.7}, Binary{0.5, 0.8, 0.5, 0.9}}) {
    if (!wanted("mixture")) break;
    const gkt::Mixture m = gkt::make_mixture(3, {{1.0, 1.0, 1 - b.x, "1"}, {b.mass, b.diameter, b.x, "2"}}, b.alpha);
    const std::string state = "m2=" + std::to_string(b.mass) + " s2=" + std::to_string(b.diameter) +
                              " x2=" + std::to_string(b.x) + " alpha=" + std::to_string(b.alpha);
    const gkt::MixtureNavierStokes ns(m, 16);
    for (int n = 1; n <= 16; ++n) {
      const gkt::MixtureTransportValues v = ns.coefficients(n);
      row("mixture", state, "shear_viscosity", n, v.shear_viscosity);
      row("mixture", state, "thermal_conductivity", n, v.thermal_conductivity);
      row("mixture", state, "mutual_diffusion_12", n, v.mutual_diffusion[1]);
      row("mixture", state, "thermal_diffusion_1", n, v.thermal_diffusion[0]);
      row("mixture", state, "dufour_1", n, v.dufour[0]);
    }
  }
  for (const double mass : {0.5, 2.0, 10.0}) {  // tracer diffusion, orders to 24 (model cap 12)
    if (!wanted("mixture")) break;
    const gkt::TracerDiffusion t({3, mass, 1.2, 0.8, 0.8}, 24);
    for (int n = 1; n <= 24; ++n)
      row("mixture", "tracer m0/m=" + std::to_string(mass), "tracer_diffusion", n, t.coefficient(n));
  }
  // rough: Maxwellian reference, orders to 11 (model cap 8, tables to 10); 3D (0.9, −0.5) added with the window
  // check of theory.md §19.23
  struct Rough {
    int d;
    gkt::Rational alpha, beta;
  };
  for (const Rough& r :
       {Rough{3, gkt::Rational(9, 10), gkt::Rational(1, 2)}, Rough{3, gkt::Rational(7, 10), gkt::Rational(0)},
        Rough{2, gkt::Rational(8, 10), gkt::Rational(1, 2)}, Rough{3, gkt::Rational(9, 10), gkt::Rational(-1, 2)}}) {
    if (!wanted("rough")) break;
    const gkt::Rational kappa = r.d == 3 ? gkt::Rational(2, 5) : gkt::Rational(1, 2);
    const gkt::RoughSonineTransport t(r.d, r.alpha, r.beta, kappa, 11);
    const std::string state =
        "d=" + std::to_string(r.d) + " alpha=" + r.alpha.to_decimal_string() + " beta=" + r.beta.to_decimal_string();
    for (int n = 1; n <= 11; ++n) {
      const gkt::RoughTransportValues v = t.at_maxwellian_state(n);
      row("rough", state, "shear_viscosity", n, v.shear_viscosity);
      row("rough", state, "bulk_viscosity", n, v.bulk_viscosity);
      row("rough", state, "thermal_conductivity", n, v.thermal_conductivity);
      row("rough", state, "density_heat_coefficient", n, v.density_heat_coefficient);
      row("rough", state, "cooling_rate_first_order", n, v.cooling_rate_first_order);
    }
  }
  return 0;
}
