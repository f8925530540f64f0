#include <stdio.h>

#include "gkt/gkt.h"

int main(void) {
  gkt_enskog_first_sonine v; /* dense gas, α = 0.9, φ = 0.3: reduced a2, ζ*, p*, η*, bulk, κ*, μ*, ζ_U */
  if (gkt_enskog_first_sonine_values(3, 0.9, 0.3, &v) != GKT_OK) {
    fprintf(stderr, "%s\n", gkt_last_error()); /* the refused field and its allowed range */
    return 1;
  }
  const gkt_gas gas = {1.3e-6, 1e-3, 5.7e8, 1e-9};    /* m (kg), σ (m), n (1/m³), T (J): physical units */
  gkt_enskog_first_sonine_physical(3, 0.9, &gas, &v); /* η in Pa·s, p in Pa, ζ in 1/s */
  printf("eta = %g Pa s, p = %g Pa\n", v.shear_viscosity, v.pressure);

  const double mass[2] = {1, 2.5}, diameter[2] = {1, 1.5}, alpha[4] = {0.9, 0.85, 0.85, 0.8};
  gkt_binary_table* table; /* a binary: built once (seconds), then ~0.2 µs per cell */
  gkt_binary_table_create(3, mass, diameter, alpha, 1, 12, 0.4, 6, &table);
  gkt_binary_transport cell;
  gkt_binary_table_evaluate(table, 0.3, 0.1, 1.0, &cell); /* x_1, n, T → η, λ, D_ij, D^T_i, ζ, T_i/T, … */
  if (gkt_binary_table_evaluate(table, 1.2, 0.1, 1.0, &cell) != GKT_OK)
    printf("%s\n", gkt_last_error()); /* fraction_1: must be a number in [0, 1], got 1.2 */
  gkt_binary_table_destroy(table);

  gkt_model* model; /* any model, any order, parameters by name ("alhpa" is refused) */
  gkt_model_create("smooth-inelastic", &model);
  gkt_model_set_number(model, "alpha", 0.9);
  const char* names[] = {"shear_viscosity"};
  gkt_coefficient eta;
  gkt_model_evaluate(model, 1, names, 4, &eta); /* η* at Sonine order 4, with its error estimate */
  printf("eta* = %.10f +- %.1e\n", eta.value, eta.error);
  gkt_model_destroy(model);
  return 0;
}
