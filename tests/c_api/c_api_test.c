/* The C API from C99 (compiled with -std=c99 -Wall -Wextra -pedantic -Werror): every function on a
 * valid state against what must hold there (elastic limits, the reference values of
 * docs/conventions.md written out here, exact identities of the mixture), and every error path:
 * status code, a message naming the field, outputs untouched. The values against the C++ calls
 * one for one are in tests/test_c_api.cpp. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gkt/gkt.h"

static int failures = 0;

#define CHECK(cond)                                                            \
  do {                                                                         \
    if (!(cond)) {                                                             \
      fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
      ++failures;                                                              \
    }                                                                          \
  } while (0)

/* True if |a − b| ≤ tolerance·max(1, |b|). */
static int close_to(double a, double b, double tolerance) {
  const double scale = fabs(b) > 1 ? fabs(b) : 1;
  return fabs(a - b) <= tolerance * scale;
}

/* Checks that a call failed with status and a message starting with prefix. */
static void expect_error(gkt_status got, gkt_status status, const char* prefix, int line) {
  if (got != status || strncmp(gkt_last_error(), prefix, strlen(prefix)) != 0) {
    fprintf(stderr, "c_api_test.c:%d: expected %s \"%s…\", got %s \"%s\"\n", line, gkt_status_name(status), prefix,
            gkt_status_name(got), gkt_last_error());
    ++failures;
  }
}
#define EXPECT_ERROR(call, status, prefix) expect_error((call), (status), (prefix), __LINE__)

static const double pi = 3.14159265358979323846;

/* η0 of a 3D gas, conventions.md: (5/(16σ²))√(mT/π). */
static double eta0_3d(double m, double sigma, double t) { return 5.0 / (16.0 * sigma * sigma) * sqrt(m * t / pi); }

static void one_component(void) {
  gkt_first_sonine v, untouched;
  gkt_enskog_first_sonine e, e0;
  gkt_enskog_state s;
  const gkt_gas gas = {2.0, 0.5, 3.0, 0.7};
  double eta0, kappa0;

  /* The elastic gas: a2 = ζ* = μ* = 0, η* = κ* = 1 at first Sonine. */
  CHECK(gkt_first_sonine_values(3, 1.0, &v) == GKT_OK);
  CHECK(close_to(v.a2, 0, 1e-14) && close_to(v.cooling_rate, 0, 1e-14) &&
        close_to(v.density_heat_coefficient, 0, 1e-14));
  CHECK(close_to(v.shear_viscosity, 1, 1e-14) && close_to(v.thermal_conductivity, 1, 1e-14));

  /* Physical = reduced × the reference values of conventions.md, written out here. */
  CHECK(gkt_first_sonine_values(3, 0.8, &v) == GKT_OK);
  CHECK(v.a2 < 0 && v.cooling_rate > 0 && v.shear_viscosity > 1); /* a2 < 0 for α² > 1/2 */
  {
    gkt_first_sonine p;
    CHECK(gkt_first_sonine_physical(3, 0.8, &gas, &p) == GKT_OK);
    eta0 = eta0_3d(gas.mass, gas.diameter, gas.temperature);
    kappa0 = 15.0 / 4.0 * eta0 / gas.mass;
    CHECK(close_to(p.a2, v.a2, 1e-15));
    CHECK(close_to(p.shear_viscosity / eta0, v.shear_viscosity, 1e-13));
    CHECK(close_to(p.thermal_conductivity / kappa0, v.thermal_conductivity, 1e-13));
    CHECK(close_to(p.density_heat_coefficient * gas.number_density / (gas.temperature * kappa0),
                   v.density_heat_coefficient, 1e-13));
    CHECK(close_to(p.cooling_rate * eta0 / (gas.number_density * gas.temperature), v.cooling_rate, 1e-13));
  }

  /* χ(φ) of Carnahan–Starling and Henderson, written out here. */
  CHECK(gkt_enskog_state_at(3, 0.3, &s) == GKT_OK);
  CHECK(close_to(s.chi, (1 - 0.15) / pow(0.7, 3), 1e-14) && s.packing_fraction == 0.3);
  CHECK(close_to(s.phi_dchi, 0.3 * (2.5 - 0.3) / pow(0.7, 4), 1e-14));
  CHECK(gkt_enskog_state_at(2, 0.3, &s) == GKT_OK);
  CHECK(close_to(s.chi, (1 - 7.0 / 16 * 0.3) / pow(0.7, 2), 1e-14));

  /* The dense set at φ = 0 is the dilute one with p* = 1; at φ > 0 the caller's state gives the same. */
  CHECK(gkt_enskog_first_sonine_values(3, 0.8, 0.0, &e0) == GKT_OK);
  CHECK(close_to(e0.shear_viscosity, v.shear_viscosity, 1e-12) && close_to(e0.pressure, 1, 1e-15));
  CHECK(close_to(e0.cooling_rate, v.cooling_rate, 1e-12) && close_to(e0.bulk_viscosity, 0, 1e-15));
  CHECK(gkt_enskog_first_sonine_values(3, 0.8, 0.3, &e) == GKT_OK);
  CHECK(gkt_enskog_state_at(3, 0.3, &s) == GKT_OK);
  CHECK(gkt_enskog_first_sonine_values_at(3, 0.8, &s, &e0) == GKT_OK);
  CHECK(memcmp(&e, &e0, sizeof e) == 0);
  CHECK(close_to(e.pressure, 1 + 2 * 1.8 * 0.3 * s.chi, 1e-13)); /* p* = 1 + 2(1+α)φχ */
  {
    const double phi = gas.number_density * pi / 6 * pow(gas.diameter, 3);
    gkt_enskog_first_sonine p;
    CHECK(gkt_enskog_first_sonine_values(3, 0.8, phi, &e) == GKT_OK);
    CHECK(gkt_enskog_first_sonine_physical(3, 0.8, &gas, &p) == GKT_OK);
    CHECK(close_to(p.pressure, e.pressure * gas.number_density * gas.temperature, 1e-13));
    CHECK(close_to(p.bulk_viscosity, e.bulk_viscosity * eta0, 1e-13));
    CHECK(close_to(p.shear_viscosity, e.shear_viscosity * eta0, 1e-13));
    CHECK(p.cooling_rate_first_order == e.cooling_rate_first_order);
  }

  /* Every refusal: status, message naming the field, output untouched. */
  memset(&untouched, 0x5a, sizeof untouched);
  v = untouched;
  EXPECT_ERROR(gkt_first_sonine_values(3, 0.0, &v), GKT_INVALID_ARGUMENT, "alpha: must be a number in (0, 1]");
  EXPECT_ERROR(gkt_first_sonine_values(3, 1.5, &v), GKT_INVALID_ARGUMENT, "alpha: must be a number in (0, 1]");
  EXPECT_ERROR(gkt_first_sonine_values(3, nan(""), &v), GKT_INVALID_ARGUMENT, "alpha:");
  EXPECT_ERROR(gkt_first_sonine_values(4, 0.9, &v), GKT_INVALID_ARGUMENT, "dimension: must be 2 or 3");
  EXPECT_ERROR(gkt_first_sonine_values(3, 0.9, NULL), GKT_INVALID_ARGUMENT, "out: must not be NULL");
  CHECK(memcmp(&v, &untouched, sizeof v) == 0);
  {
    gkt_gas bad = gas;
    bad.mass = 0;
    EXPECT_ERROR(gkt_first_sonine_physical(3, 0.9, &bad, &v), GKT_INVALID_ARGUMENT,
                 "mass: must be a finite number > 0");
    bad = gas;
    bad.diameter = -1;
    EXPECT_ERROR(gkt_first_sonine_physical(3, 0.9, &bad, &v), GKT_INVALID_ARGUMENT, "diameter:");
    bad = gas;
    bad.number_density = 0;
    EXPECT_ERROR(gkt_first_sonine_physical(3, 0.9, &bad, &v), GKT_INVALID_ARGUMENT, "number_density:");
    bad = gas;
    bad.temperature = -0.5;
    EXPECT_ERROR(gkt_enskog_first_sonine_physical(3, 0.9, &bad, &e), GKT_INVALID_ARGUMENT, "temperature:");
    bad = gas;
    bad.number_density = 100; /* φ = 100 π/48 > 0.5 */
    EXPECT_ERROR(gkt_enskog_first_sonine_physical(3, 0.9, &bad, &e), GKT_INVALID_ARGUMENT, "number_density:");
    EXPECT_ERROR(gkt_first_sonine_physical(3, 0.9, NULL, &v), GKT_INVALID_ARGUMENT, "gas: must not be NULL");
  }
  CHECK(memcmp(&v, &untouched, sizeof v) == 0);
  EXPECT_ERROR(gkt_enskog_state_at(3, 0.55, &s), GKT_INVALID_ARGUMENT,
               "packing_fraction: must be a number in [0, 0.5]");
  EXPECT_ERROR(gkt_enskog_state_at(2, 0.75, &s), GKT_INVALID_ARGUMENT,
               "packing_fraction: must be a number in [0, 0.7]");
  EXPECT_ERROR(gkt_enskog_state_at(3, -0.01, &s), GKT_INVALID_ARGUMENT, "packing_fraction:");
  EXPECT_ERROR(gkt_enskog_first_sonine_values(3, 1.01, 0.2, &e), GKT_INVALID_ARGUMENT, "alpha:");
  EXPECT_ERROR(gkt_enskog_first_sonine_values(3, 0.9, 0.6, &e), GKT_INVALID_ARGUMENT, "packing_fraction:");
  s.chi = 0;
  EXPECT_ERROR(gkt_enskog_first_sonine_values_at(3, 0.9, &s, &e), GKT_INVALID_ARGUMENT,
               "chi: must be a finite number > 0");
  s.chi = 1;
  s.packing_fraction = 1;
  EXPECT_ERROR(gkt_enskog_first_sonine_values_at(3, 0.9, &s, &e), GKT_INVALID_ARGUMENT, "packing_fraction:");

  /* A successful call leaves the last error as it was. */
  CHECK(gkt_first_sonine_values(2, 0.9, &v) == GKT_OK);
  CHECK(strncmp(gkt_last_error(), "packing_fraction:", 17) == 0);
}

/* The batched calls over 101 cells equal the single-cell calls bit for bit, in 2D and 3D; a bad
 * cell anywhere (here in the middle) is refused naming its index, and no cell of out is written. */
#define CELLS 101
static void one_component_cells(void) {
  static double alpha[CELLS], phi[CELLS];
  static gkt_first_sonine v[CELLS], one;
  static gkt_enskog_first_sonine e[CELLS], e_one, e_sentinel[CELLS];
  static gkt_first_sonine sentinel[CELLS];
  int dimension;
  size_t i;
  for (i = 0; i < CELLS; ++i) {
    alpha[i] = 0.05 + 0.95 * (double)i / (CELLS - 1);         /* 0.05 … 1 */
    phi[i] = 0.49 * (double)((i * 37) % CELLS) / (CELLS - 1); /* 0 … 0.49, scrambled */
  }
  for (dimension = 2; dimension <= 3; ++dimension) {
    CHECK(gkt_first_sonine_values_cells(dimension, CELLS, alpha, v) == GKT_OK);
    CHECK(gkt_enskog_first_sonine_values_cells(dimension, CELLS, alpha, phi, e) == GKT_OK);
    for (i = 0; i < CELLS; ++i) {
      CHECK(gkt_first_sonine_values(dimension, alpha[i], &one) == GKT_OK);
      CHECK(memcmp(&one, &v[i], sizeof one) == 0);
      CHECK(gkt_enskog_first_sonine_values(dimension, alpha[i], phi[i], &e_one) == GKT_OK);
      CHECK(memcmp(&e_one, &e[i], sizeof e_one) == 0);
    }
  }
  CHECK(gkt_first_sonine_values_cells(3, 0, alpha, v) == GKT_OK); /* no cells: nothing to do */

  /* A bad cell in the middle: the status, its index in the message, out untouched. */
  memset(sentinel, 0x5a, sizeof sentinel);
  memset(e_sentinel, 0x5a, sizeof e_sentinel);
  memcpy(v, sentinel, sizeof v);
  memcpy(e, e_sentinel, sizeof e);
  alpha[57] = 1.5;
  EXPECT_ERROR(gkt_first_sonine_values_cells(3, CELLS, alpha, v), GKT_INVALID_ARGUMENT,
               "alpha[57]: must be a number in (0, 1], got 1.5");
  EXPECT_ERROR(gkt_enskog_first_sonine_values_cells(2, CELLS, alpha, phi, e), GKT_INVALID_ARGUMENT,
               "alpha[57]: must be a number in (0, 1]");
  alpha[57] = nan("");
  EXPECT_ERROR(gkt_first_sonine_values_cells(2, CELLS, alpha, v), GKT_INVALID_ARGUMENT, "alpha[57]:");
  alpha[57] = 0.9;
  phi[50] = 0.55; /* above 0.5 in 3D, allowed in 2D */
  EXPECT_ERROR(gkt_enskog_first_sonine_values_cells(3, CELLS, alpha, phi, e), GKT_INVALID_ARGUMENT,
               "packing_fraction[50]: must be a number in [0, 0.5] for dimension = 3, got 0.55");
  phi[50] = -0.01;
  EXPECT_ERROR(gkt_enskog_first_sonine_values_cells(2, CELLS, alpha, phi, e), GKT_INVALID_ARGUMENT,
               "packing_fraction[50]: must be a number in [0, 0.7]");
  phi[50] = 0.3;
  EXPECT_ERROR(gkt_first_sonine_values_cells(4, CELLS, alpha, v), GKT_INVALID_ARGUMENT, "dimension: must be 2 or 3");
  EXPECT_ERROR(gkt_enskog_first_sonine_values_cells(1, CELLS, alpha, phi, e), GKT_INVALID_ARGUMENT, "dimension:");
  EXPECT_ERROR(gkt_first_sonine_values_cells(3, CELLS, NULL, v), GKT_INVALID_ARGUMENT, "alpha: must not be NULL");
  EXPECT_ERROR(gkt_first_sonine_values_cells(3, CELLS, alpha, NULL), GKT_INVALID_ARGUMENT, "out: must not be NULL");
  EXPECT_ERROR(gkt_enskog_first_sonine_values_cells(3, CELLS, alpha, NULL, e), GKT_INVALID_ARGUMENT,
               "packing_fraction: must not be NULL");
  CHECK(memcmp(v, sentinel, sizeof v) == 0);
  CHECK(memcmp(e, e_sentinel, sizeof e) == 0);
  /* The repaired arrays are accepted again. */
  CHECK(gkt_enskog_first_sonine_values_cells(3, CELLS, alpha, phi, e) == GKT_OK);
  CHECK(memcmp(e, e_sentinel, sizeof e) != 0);
}

static void models(void) {
  gkt_model* model = NULL;
  gkt_coefficient c[2];
  const char* names[2] = {"shear_viscosity", "a2"};
  const char* bad_name[1] = {"shear_viscocity"};
  gkt_first_sonine v;

  EXPECT_ERROR(gkt_model_create("smooth-inelastc", &model), GKT_INVALID_ARGUMENT, "model: unknown model");
  CHECK(model == NULL);
  CHECK(gkt_model_create("smooth-inelastic", &model) == GKT_OK && model != NULL);
  CHECK(gkt_model_set_number(model, "alpha", 0.8) == GKT_OK);
  CHECK(gkt_model_set_choice(model, "hcs", "linear") == GKT_OK);
  /* Order 1 with the linear HCS is the first-Sonine closed form. */
  CHECK(gkt_model_evaluate(model, 2, names, 1, c) == GKT_OK);
  CHECK(gkt_first_sonine_values(3, 0.8, &v) == GKT_OK);
  CHECK(close_to(c[0].value, v.shear_viscosity, 1e-12) && close_to(c[1].value, v.a2, 1e-12));
  CHECK(c[0].order == 1 && c[0].defined == 1 && c[0].error >= 0);
  /* The linear HCS is first Sonine only; the nonlinear one converges to a tolerance at some order. */
  EXPECT_ERROR(gkt_model_evaluate_to_tolerance(model, 1, names, 1e-3, c), GKT_INVALID_ARGUMENT, "hcs:");
  CHECK(gkt_model_set_choice(model, "hcs", "nonlinear") == GKT_OK);
  CHECK(gkt_model_evaluate_to_tolerance(model, 1, names, 1e-3, c) == GKT_OK);
  CHECK(c[0].converged == 1 && c[0].error < 1e-3 && c[0].order >= 1 && close_to(c[0].value, v.shear_viscosity, 0.05));

  CHECK(strcmp(gkt_last_warnings(), "") == 0); /* the smooth gas's errors cover everything */

  EXPECT_ERROR(gkt_model_set_number(model, "alhpa", 0.8), GKT_INVALID_ARGUMENT, "alhpa: unknown parameter of model");
  EXPECT_ERROR(gkt_model_set_number(model, "alpha", 0.0), GKT_INVALID_ARGUMENT,
               "alpha: must be a number in (0, 1], got 0");
  EXPECT_ERROR(gkt_model_set_number(model, "alpha", 1.2), GKT_INVALID_ARGUMENT,
               "alpha: must be a number in (0, 1], got 1.2");
  EXPECT_ERROR(gkt_model_set_number(model, "alpha", nan("")), GKT_INVALID_ARGUMENT, "alpha:");
  EXPECT_ERROR(gkt_model_set_number(model, "dimension", 2.5), GKT_INVALID_ARGUMENT, "dimension:");
  EXPECT_ERROR(gkt_model_set_number(model, "packing_fraction", -0.1), GKT_INVALID_ARGUMENT, "packing_fraction:");
  EXPECT_ERROR(gkt_model_set_number(model, "scheme", 1), GKT_INVALID_ARGUMENT, "scheme: must be one of");
  EXPECT_ERROR(gkt_model_set_choice(model, "scheme", "modifed"), GKT_INVALID_ARGUMENT, "scheme: must be one of");
  EXPECT_ERROR(gkt_model_set_choice(model, "shceme", "modified"), GKT_INVALID_ARGUMENT, "shceme: unknown parameter");
  EXPECT_ERROR(gkt_model_set_choice(model, "alpha", "high"), GKT_INVALID_ARGUMENT, "alpha: must be a number");
  EXPECT_ERROR(gkt_model_evaluate(model, 1, bad_name, 1, c), GKT_INVALID_ARGUMENT,
               "coefficients: unknown coefficient 'shear_viscocity'");
  EXPECT_ERROR(gkt_model_evaluate(model, 1, names, 0, c), GKT_INVALID_ARGUMENT, "order: must be an integer in [1, 22]");
  /* The model's range [1, 22] covers the tail scheme's resolutions; the Sonine schemes stop at 20. */
  EXPECT_ERROR(gkt_model_evaluate(model, 1, names, 21, c), GKT_INVALID_ARGUMENT,
               "order: must be an integer in [1, 20] for scheme = \"standard\"");
  EXPECT_ERROR(gkt_model_evaluate(model, 0, names, 1, c), GKT_INVALID_ARGUMENT, "count:");
  EXPECT_ERROR(gkt_model_evaluate_to_tolerance(model, 1, names, 0.0, c), GKT_INVALID_ARGUMENT, "tolerance:");
  EXPECT_ERROR(gkt_model_evaluate(NULL, 1, names, 1, c), GKT_INVALID_ARGUMENT, "model: must not be NULL");
  gkt_model_destroy(model);

  /* The rough gas's Navier-Stokes columns at a Sonine order in the product trial space: their error leaves out
   * the families beyond the products, which gkt table warns about once per table (docs/conventions.md,
   * "Warnings"); the C API gives the same lines. At order 1 (first approximation, error not estimated) there is
   * none; a failing call leaves none (trial_space = "full" at order 1 is refused, as by gkt table). */
  model = NULL;
  CHECK(gkt_model_create("rough", &model) == GKT_OK);
  CHECK(gkt_model_set_number(model, "alpha", 0.9) == GKT_OK && gkt_model_set_number(model, "beta", 0.5) == GKT_OK);
  {
    const char* eta[1] = {"shear_viscosity"};
    CHECK(gkt_model_evaluate(model, 1, eta, 2, c) == GKT_OK);
    CHECK(strncmp(gkt_last_warnings(), "trial_space: the _error of shear_viscosity covers", 49) == 0);
    CHECK(strchr(gkt_last_warnings(), '\n') == NULL); /* one line */
    CHECK(gkt_model_evaluate(model, 1, eta, 1, c) == GKT_OK);
    CHECK(strcmp(gkt_last_warnings(), "") == 0);
    CHECK(gkt_model_evaluate(model, 1, eta, 2, c) == GKT_OK && gkt_last_warnings()[0] != '\0');
    EXPECT_ERROR(gkt_model_evaluate(model, 1, eta, 0, c), GKT_INVALID_ARGUMENT, "order:");
    CHECK(strcmp(gkt_last_warnings(), "") == 0);
    CHECK(gkt_model_set_choice(model, "trial_space", "full") == GKT_OK);
    EXPECT_ERROR(gkt_model_evaluate(model, 1, eta, 1, c), GKT_INVALID_ARGUMENT, "trial_space:");
    CHECK(strcmp(gkt_last_warnings(), "") == 0);
  }
  gkt_model_destroy(model);

  /* A mixture whose fractions do not sum to 1 is refused at evaluation, naming the fractions. */
  CHECK(gkt_model_create("mixture", &model) == GKT_OK);
  CHECK(gkt_model_set_number(model, "species", 2) == GKT_OK);
  EXPECT_ERROR(gkt_model_set_number(model, "species", 5), GKT_INVALID_ARGUMENT, "species:");
  CHECK(gkt_model_set_number(model, "mass_1", 1) == GKT_OK && gkt_model_set_number(model, "mass_2", 2) == GKT_OK);
  CHECK(gkt_model_set_number(model, "diameter_1", 1) == GKT_OK &&
        gkt_model_set_number(model, "diameter_2", 1) == GKT_OK);
  CHECK(gkt_model_set_number(model, "fraction_1", 0.3) == GKT_OK);
  CHECK(gkt_model_set_number(model, "fraction_2", 0.3) == GKT_OK);
  EXPECT_ERROR(gkt_model_set_number(model, "fraction_1", 1.5), GKT_INVALID_ARGUMENT, "fraction_1:");
  {
    const char* ratio[1] = {"temperature_ratio_1"};
    EXPECT_ERROR(gkt_model_evaluate(model, 1, ratio, 1, c), GKT_INVALID_ARGUMENT, "fraction");
  }
  gkt_model_destroy(model);
  gkt_model_destroy(NULL);
}

static void binary_table(void) {
  const double mass[2] = {1, 3}, diameter[2] = {1, 1.4}, alpha[4] = {0.9, 0.8, 0.8, 0.7};
  gkt_binary_table* table = NULL;
  gkt_binary_transport p, r, untouched;
  double error = -1, n, t, x1, mbar, sbar, eta0, d0, m_sum;
  int i, j;

  CHECK(gkt_binary_table_create(3, mass, diameter, alpha, 1, 16, 0.0, 3, &table) == GKT_OK && table != NULL);
  CHECK(gkt_binary_table_interpolation_error(table, &error) == GKT_OK && error >= 0 && error < 1e-6);
  {
    /* One interval of 16 nodes: 16 nodes, 15 midpoints and 8 validation points solved. */
    int intervals = -1, solves = -1;
    double seconds = -1;
    CHECK(gkt_binary_table_build_cost(table, &intervals, &solves, &seconds) == GKT_OK);
    CHECK(intervals == 1 && solves == 16 + 15 + 8 && seconds > 0);
    EXPECT_ERROR(gkt_binary_table_build_cost(table, &intervals, NULL, &seconds), GKT_INVALID_ARGUMENT,
                 "solves: must not be NULL");
  }
  {
    gkt_binary_table* refused = NULL;
    EXPECT_ERROR(gkt_binary_table_create_to_tolerance(3, mass, diameter, alpha, 1, 16, 0.0, 3, 0.0, NULL, &refused),
                 GKT_INVALID_ARGUMENT, "tolerance: must be a number in (0, 1], got 0");
    CHECK(refused == NULL);
  }
  {
    /* A table of x_1 in [0.2, 0.6] refuses the valid x_1 = 0.7 as out of its range. */
    const double range[2] = {0.2, 0.6}, bad_range[2] = {0.6, 0.2};
    gkt_binary_table* part = NULL;
    gkt_binary_transport v;
    CHECK(gkt_binary_table_create_to_tolerance(3, mass, diameter, alpha, 1, 8, 0.0, 3, 1e-3, range, &part) == GKT_OK);
    CHECK(gkt_binary_table_evaluate(part, 0.4, 1.0, 1.0, &v) == GKT_OK && v.shear_viscosity > 0);
    EXPECT_ERROR(gkt_binary_table_evaluate(part, 0.7, 1.0, 1.0, &v), GKT_OUT_OF_RANGE,
                 "fraction_1: must be in [0.2, 0.6] (the table's fraction_range), got 0.7");
    EXPECT_ERROR(gkt_binary_table_evaluate_reduced(part, 0.1, 0.0, &v), GKT_OUT_OF_RANGE,
                 "fraction_1: must be in [0.2");
    gkt_binary_table_destroy(part);
    part = NULL;
    EXPECT_ERROR(gkt_binary_table_create_to_tolerance(3, mass, diameter, alpha, 1, 8, 0.0, 3, 1e-3, bad_range, &part),
                 GKT_INVALID_ARGUMENT, "fraction_range: must be [x_low, x_high]");
    CHECK(part == NULL);
  }

  /* Physical against reduced × the reference gas of (m̄, σ̄), written out here. */
  x1 = 0.3, n = 0.02, t = 2.5;
  CHECK(gkt_binary_table_evaluate(table, x1, n, t, &p) == GKT_OK);
  CHECK(gkt_binary_table_evaluate_reduced(table, x1, 0.0, &r) == GKT_OK);
  mbar = x1 * mass[0] + (1 - x1) * mass[1];
  sbar = x1 * diameter[0] + (1 - x1) * diameter[1];
  eta0 = eta0_3d(mbar, sbar, t);
  d0 = 3.0 / (8.0 * n * sbar * sbar) * sqrt(t / (pi * mbar));
  CHECK(close_to(p.shear_viscosity / eta0, r.shear_viscosity, 1e-13));
  CHECK(close_to(p.thermal_conductivity / (15.0 / 4.0 * eta0 / mbar), r.thermal_conductivity, 1e-13));
  CHECK(close_to(p.cooling_rate * eta0 / (n * t), r.cooling_rate, 1e-13));
  CHECK(close_to(p.pressure, n * t, 1e-13) && close_to(r.pressure, 1, 1e-14));
  for (i = 0; i < 4; ++i) CHECK(close_to(p.mutual_diffusion[i] / (n * d0), r.mutual_diffusion[i], 1e-13));
  for (i = 0; i < 2; ++i) {
    CHECK(close_to(p.thermal_diffusion[i] / d0, r.thermal_diffusion[i], 1e-13));
    CHECK(p.temperature_ratio[i] == r.temperature_ratio[i]);
  }
  /* Exact identities (conventions.md): Σ_i D^T_i = 0, Σ_i m_i D_ij = 0, Σ_i x_i T_i/T = 1. */
  CHECK(close_to(r.thermal_diffusion[0] + r.thermal_diffusion[1], 0, 1e-10));
  for (j = 0; j < 2; ++j) {
    m_sum = mass[0] * r.mutual_diffusion[j] + mass[1] * r.mutual_diffusion[2 + j];
    CHECK(close_to(m_sum, 0, 1e-10));
  }
  CHECK(close_to(x1 * r.temperature_ratio[0] + (1 - x1) * r.temperature_ratio[1], 1, 1e-6)); /* interpolated */

  memset(&untouched, 0x5a, sizeof untouched);
  p = untouched;
  EXPECT_ERROR(gkt_binary_table_evaluate(table, -0.1, n, t, &p), GKT_INVALID_ARGUMENT,
               "fraction_1: must be a number in [0, 1]");
  EXPECT_ERROR(gkt_binary_table_evaluate(table, 1.1, n, t, &p), GKT_INVALID_ARGUMENT, "fraction_1:");
  EXPECT_ERROR(gkt_binary_table_evaluate(table, nan(""), n, t, &p), GKT_INVALID_ARGUMENT, "fraction_1:");
  EXPECT_ERROR(gkt_binary_table_evaluate(table, x1, 0.0, t, &p), GKT_INVALID_ARGUMENT,
               "number_density: must be a finite number > 0");
  EXPECT_ERROR(gkt_binary_table_evaluate(table, x1, -1.0, t, &p), GKT_INVALID_ARGUMENT, "number_density:");
  EXPECT_ERROR(gkt_binary_table_evaluate(table, x1, n, 0.0, &p), GKT_INVALID_ARGUMENT, "temperature:");
  EXPECT_ERROR(gkt_binary_table_evaluate_reduced(table, x1, 0.1, &p), GKT_OUT_OF_RANGE,
               "packing_fraction: must be in [0, 0]");
  EXPECT_ERROR(gkt_binary_table_evaluate(NULL, x1, n, t, &p), GKT_INVALID_ARGUMENT, "table: must not be NULL");
  CHECK(memcmp(&p, &untouched, sizeof p) == 0);
  {
    /* A batch equals the single calls; a bad cell is named by its index and nothing is written. */
    const double xs[3] = {0.1, 0.5, 0.9}, ns[3] = {0.01, 0.02, 0.03}, ts[3] = {1, 2, 3}, bad_ts[3] = {1, -2, 3};
    gkt_binary_transport batch[3], single;
    CHECK(gkt_binary_table_evaluate_cells(table, 3, xs, ns, ts, batch) == GKT_OK);
    for (i = 0; i < 3; ++i) {
      CHECK(gkt_binary_table_evaluate(table, xs[i], ns[i], ts[i], &single) == GKT_OK);
      CHECK(memcmp(&single, &batch[i], sizeof single) == 0);
    }
    batch[0] = untouched;
    EXPECT_ERROR(gkt_binary_table_evaluate_cells(table, 3, xs, ns, bad_ts, batch), GKT_INVALID_ARGUMENT,
                 "temperature[1]: must be a finite number > 0");
    CHECK(memcmp(&batch[0], &untouched, sizeof untouched) == 0);
    EXPECT_ERROR(gkt_binary_table_evaluate_cells(table, 3, NULL, ns, ts, batch), GKT_INVALID_ARGUMENT, "fraction_1:");
  }
  gkt_binary_table_destroy(table);
  gkt_binary_table_destroy(NULL);

  /* A dense table refuses states above its φ_max with GKT_OUT_OF_RANGE. */
  table = NULL;
  CHECK(gkt_binary_table_create(3, mass, diameter, alpha, 1, 4, 0.2, 3, &table) == GKT_OK);
  CHECK(gkt_binary_table_evaluate_reduced(table, 0.5, 0.15, &r) == GKT_OK && r.pressure > 1 && r.bulk_viscosity > 0);
  EXPECT_ERROR(gkt_binary_table_evaluate_reduced(table, 0.5, 0.25, &r), GKT_OUT_OF_RANGE, "packing_fraction:");
  EXPECT_ERROR(gkt_binary_table_evaluate(table, 0.5, 1.0, 1.0, &r), GKT_OUT_OF_RANGE,
               "number_density: the packing fraction");
  {
    const double xs[2] = {0.5, 0.5}, ns[2] = {0.1, 1.0}, ts[2] = {1, 1};
    gkt_binary_transport batch[2];
    EXPECT_ERROR(gkt_binary_table_evaluate_cells(table, 2, xs, ns, ts, batch), GKT_OUT_OF_RANGE,
                 "number_density[1]: the packing fraction");
  }
  gkt_binary_table_destroy(table);

  /* Refused builds: NULL handle out, message naming the field. */
  {
    const double bad_mass[2] = {1, 0}, asymmetric[4] = {0.9, 0.8, 0.7, 0.7}, outside[4] = {0.9, 0.8, 0.8, 1.2};
    table = NULL;
    EXPECT_ERROR(gkt_binary_table_create(3, bad_mass, diameter, alpha, 1, 8, 0, 3, &table), GKT_INVALID_ARGUMENT,
                 "mass_2:");
    EXPECT_ERROR(gkt_binary_table_create(3, mass, diameter, asymmetric, 1, 8, 0, 3, &table), GKT_INVALID_ARGUMENT,
                 "alpha: the restitution matrix must be symmetric");
    EXPECT_ERROR(gkt_binary_table_create(3, mass, diameter, outside, 1, 8, 0, 3, &table), GKT_INVALID_ARGUMENT,
                 "alpha_2_2: must be a number in (0, 1]");
    EXPECT_ERROR(gkt_binary_table_create(4, mass, diameter, alpha, 1, 8, 0, 3, &table), GKT_INVALID_ARGUMENT,
                 "dimension:");
    EXPECT_ERROR(gkt_binary_table_create(3, mass, diameter, alpha, 0, 8, 0, 3, &table), GKT_INVALID_ARGUMENT, "order:");
    EXPECT_ERROR(gkt_binary_table_create(3, mass, diameter, alpha, 1, 2, 0, 3, &table), GKT_INVALID_ARGUMENT, "nodes:");
    EXPECT_ERROR(gkt_binary_table_create(3, mass, diameter, alpha, 1, 8, 0.5, 3, &table), GKT_INVALID_ARGUMENT,
                 "max_packing_fraction:");
    EXPECT_ERROR(gkt_binary_table_create(3, mass, diameter, alpha, 1, 8, 0, 3, NULL), GKT_INVALID_ARGUMENT, "out:");
    CHECK(table == NULL);
  }
}

int main(void) {
  CHECK(strlen(gkt_version()) > 0);
  CHECK(strcmp(gkt_status_name(GKT_OUT_OF_RANGE), "GKT_OUT_OF_RANGE") == 0);
  one_component();
  one_component_cells();
  models();
  binary_table();
  if (failures > 0) {
    fprintf(stderr, "c_api_test: %d check(s) failed\n", failures);
    return 1;
  }
  printf("c_api_test: ok\n");
  return 0;
}
