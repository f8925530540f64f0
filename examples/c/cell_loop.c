/* A solver's cell loop in C99 over gkt's C API: a one-component granular gas of 1 mm glass beads,
 * dense (Enskog), restitution α = 0.9; per cell the solids volume fraction φ and the granular
 * temperature T (J, k_B = 1) give the first-Sonine shear viscosity, conductivity, pressure and
 * cooling rate in SI units. A binary mixture goes through gkt_binary_table_* the same way
 * (examples/fortran/two_fluid_cells.f90). Build: link gkt_c (CMake target) or -lgkt_c -lgkt and
 * gkt's dependencies. */
#include <stdio.h>

#include "gkt/gkt.h"

int main(void) {
  const double pi = 3.14159265358979323846, alpha = 0.9, diameter = 1e-3, material_density = 2500;
  const double mass = material_density * pi / 6 * diameter * diameter * diameter;
  const double phi[5] = {0.01, 0.1, 0.2, 0.3, 0.45};
  const double temperature[5] = {1e-9, 2e-9, 1e-9, 5e-10, 1e-10};
  gkt_enskog_first_sonine v;
  int cell;

  printf("cell,packing_fraction,temperature,shear_viscosity,thermal_conductivity,pressure,cooling_rate\n");
  for (cell = 0; cell < 5; ++cell) {
    /* The cell's number density from its volume fraction: φ = n π σ³/6. */
    const gkt_gas gas = {mass, diameter, phi[cell] / (pi / 6 * diameter * diameter * diameter), temperature[cell]};
    if (gkt_enskog_first_sonine_physical(3, alpha, &gas, &v) != GKT_OK) {
      fprintf(stderr, "cell_loop: cell %d: %s\n", cell, gkt_last_error());
      return 1;
    }
    printf("%d,%g,%g,%.6e,%.6e,%.6e,%.6e\n", cell, phi[cell], temperature[cell], v.shear_viscosity,
           v.thermal_conductivity, v.pressure, v.cooling_rate);
  }

  /* Bad input is an error with a message naming the field, never a clamp: φ = 0.6 is too dense. */
  {
    const gkt_gas too_dense = {mass, diameter, 0.6 / (pi / 6 * diameter * diameter * diameter), 1e-9};
    const gkt_status status = gkt_enskog_first_sonine_physical(3, alpha, &too_dense, &v);
    printf("# phi = 0.6: %s: %s\n", gkt_status_name(status), gkt_last_error());
    return status == GKT_INVALID_ARGUMENT ? 0 : 1;
  }
}
