/** \file
 * The C API of gkt (C99): per-cell transport coefficients of granular gases for hydrodynamic
 * solvers written in C or Fortran (fortran/gkt.f90 binds this header with iso_c_binding).
 *
 * Rules every function follows:
 *  - It returns a gkt_status. GKT_OK (0) means every output was written; on any other status no
 *    output is written (handles stay NULL) and gkt_last_error() holds a one-line message naming
 *    the field and its allowed range, e.g. "alpha: must be a number in (0, 1], got 1.5".
 *  - No C++ exception crosses this header; no value is clamped or defaulted silently.
 *  - Handles (gkt_model, gkt_binary_table) are opaque; create with gkt_*_create, free with
 *    gkt_*_destroy (NULL is accepted). A handle may be read (evaluated) from several threads at
 *    once only where its evaluate function says so.
 *  - Reduced units are those of docs/conventions.md: η* = η/η0, κ* = κ/κ0, μ* = nμ/(Tκ0),
 *    ζ* = ζ/ν0 with ν0 = nT/η0, p* = p/(nT); η0, κ0, D0 are the first-approximation values of an
 *    elastic dilute gas of mass m and diameter σ at n, T (Chapman & Cowling). Physical units are
 *    the caller's: mass, length and energy (k_B = 1: T is an energy), so that time is
 *    length·√(mass/energy).
 *
 * Names: functions gkt_<noun>_<verb>, types gkt_<noun>, status codes GKT_<WORD> (conventions.md
 * "C API").
 */
#ifndef GKT_GKT_H
#define GKT_GKT_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- status codes and errors ------------------------------------------------------------ */

/** What a call did. */
typedef enum gkt_status {
  GKT_OK = 0,               /**< success: every output written */
  GKT_INVALID_ARGUMENT = 1, /**< bad input: an unknown name, a value outside its range, a NULL pointer */
  GKT_OUT_OF_RANGE = 2,     /**< a valid state that a table does not cover (φ above the table's φ_max, x_1 outside
                                 its fraction_range) */
  GKT_INTERNAL_ERROR = 3    /**< anything else the library reported (out of memory, a bug); see the message */
} gkt_status;

/** Returns the message of the last call on this thread that did not return GKT_OK ("" if none);
 *  successful calls leave it unchanged. The pointer stays valid until the next failing call on
 *  this thread. */
const char* gkt_last_error(void);

/** Returns what the error estimates of this thread's last successful gkt_model_evaluate or
 *  gkt_model_evaluate_to_tolerance do not cover, one warning per line (the lines `gkt table` prints
 *  as "warning: …" for the same model, keys and columns; docs/conventions.md, "Warnings"), or "" if
 *  nothing; e.g. the rough model's product trial space at Sonine order >= 2. Every evaluate call
 *  replaces it (a failing one with ""). The pointer stays valid until the next evaluate call on this
 *  thread. */
const char* gkt_last_warnings(void);

/** Returns the name of a status code ("GKT_OK", "GKT_INVALID_ARGUMENT", …; "unknown" otherwise). */
const char* gkt_status_name(gkt_status status);

/** Returns gkt's version, e.g. "0.1.0". */
const char* gkt_version(void);

/* ---- one-component gas: first Sonine closed forms -------------------------------------------- */

/** The dilute first-Sonine set (theory.md (10.8)). Reduced (gkt_first_sonine_values) or physical
 *  (gkt_first_sonine_physical) as each field says. */
typedef struct gkt_first_sonine {
  double a2;              /**< HCS cumulant a2 (dimensionless, both) */
  double cooling_rate;    /**< reduced ζ* = ζ/ν0; physical ζ (1/time) */
  double shear_viscosity; /**< reduced η* = η/η0; physical η (mass/(length·time)) */
  double thermal_conductivity; /**< reduced κ* = κ/κ0; physical κ in q = −κ∇T − μ∇n (1/(length·time) when T is an
                                  energy) */
  double density_heat_coefficient; /**< reduced μ* = nμ/(Tκ0); physical μ in q = −κ∇T − μ∇n (energy·length²/time) */
} gkt_first_sonine;

/** Computes the dilute first-Sonine set at restitution α in reduced units (standard scheme, van
 *  Noije–Ernst a2; the generated closed forms, ~10² flops, no allocation). dimension 2 or 3,
 *  α in (0, 1]. Thread-safe. */
gkt_status gkt_first_sonine_values(int dimension, double alpha, gkt_first_sonine* out);

/** Computes the dilute first-Sonine set in reduced units at the `cells` restitutions of the
 *  caller's array: out[i] as gkt_first_sonine_values(dimension, alpha[i], &out[i]), equal bit for
 *  bit. Every α is checked before any cell is evaluated: on a bad one nothing is written and the
 *  message names its index from 0 ("alpha[3]: must be a number in (0, 1], got 1.5"). alpha and out
 *  must not be NULL (also when cells = 0). Thread-safe, no allocation. */
gkt_status gkt_first_sonine_values_cells(int dimension, size_t cells, const double* alpha, gkt_first_sonine* out);

/** The state of a one-component gas in physical units. */
typedef struct gkt_gas {
  double mass;           /**< particle mass m > 0 */
  double diameter;       /**< particle diameter σ > 0 */
  double number_density; /**< n > 0 (particles per volume; per area in 2D) */
  double temperature;    /**< granular temperature T > 0 (an energy, k_B = 1) */
} gkt_gas;

/** Computes the dilute first-Sonine set at α for the gas in physical units: η = η*η0, κ = κ*κ0,
 *  μ = μ*Tκ0/n, ζ = ζ*nT/η0 (η0, κ0 of the gas's m, σ, T). Every field of gas must be > 0 and
 *  finite. Thread-safe. */
gkt_status gkt_first_sonine_physical(int dimension, double alpha, const gkt_gas* gas, gkt_first_sonine* out);

/** The dense (Enskog) state at one packing fraction. */
typedef struct gkt_enskog_state {
  double packing_fraction; /**< φ = n v_d σ^d (3D: πnσ³/6, 2D: πnσ²/4) */
  double chi;              /**< contact value χ(φ) of the pair correlation */
  double phi_dchi;         /**< φ dχ/dφ */
} gkt_enskog_state;

/** Computes (φ, χ(φ), φ dχ/dφ) in double with Carnahan–Starling (3D) or Henderson (2D); equal to
 *  the exact rational closure to 1e-14 relative. φ in [0, 0.5] (3D), [0, 0.7] (2D). Thread-safe. */
gkt_status gkt_enskog_state_at(int dimension, double packing_fraction, gkt_enskog_state* out);

/** The dense first-Sonine set (theory.md §15.7). Reduced or physical as each field says; ν0, η0,
 *  κ0 are the dilute reference values also in the dense gas (conventions.md). */
typedef struct gkt_enskog_first_sonine {
  double a2;                       /**< HCS cumulant a2 (dimensionless, both) */
  double cooling_rate;             /**< reduced ζ* = ζ/ν0; physical ζ (1/time) */
  double pressure;                 /**< reduced p* = p/(nT); physical p (energy/volume) */
  double shear_viscosity;          /**< reduced η* = η/η0; physical η */
  double bulk_viscosity;           /**< reduced κ_b/η0; physical bulk viscosity (P ∋ −κ_b I∇·u) */
  double thermal_conductivity;     /**< reduced κ* = κ/κ0; physical κ in q = −κ∇T − μ∇n */
  double density_heat_coefficient; /**< reduced μ* = nμ/(Tκ0); physical μ */
  double cooling_rate_first_order; /**< ζ_U in ζ = ζ0 + ζ_U ∇·u (dimensionless, both) */
} gkt_enskog_first_sonine;

/** Computes the dense first-Sonine set at α and packing fraction φ in reduced units, χ from
 *  gkt_enskog_state_at (φ = 0 is the dilute gas). α in (0, 1], φ as gkt_enskog_state_at.
 *  Thread-safe, no allocation. */
gkt_status gkt_enskog_first_sonine_values(int dimension, double alpha, double packing_fraction,
                                          gkt_enskog_first_sonine* out);

/** The same at a state the caller supplies (its own χ closure): packing_fraction in [0, 1),
 *  chi > 0, all finite. Thread-safe. */
gkt_status gkt_enskog_first_sonine_values_at(int dimension, double alpha, const gkt_enskog_state* state,
                                             gkt_enskog_first_sonine* out);

/** Computes the dense first-Sonine set in reduced units at the `cells` states (alpha[i],
 *  packing_fraction[i]) of the caller's arrays: out[i] as gkt_enskog_first_sonine_values, equal
 *  bit for bit. Every cell is checked before any is evaluated: on a bad one nothing is written and
 *  the message names its index from 0 ("packing_fraction[3]: …"). No pointer may be NULL (also
 *  when cells = 0). Thread-safe, no allocation. */
gkt_status gkt_enskog_first_sonine_values_cells(int dimension, size_t cells, const double* alpha,
                                                const double* packing_fraction, gkt_enskog_first_sonine* out);

/** Computes the dense first-Sonine set for the gas in physical units: φ = n v_d σ^d (must lie in
 *  the range of gkt_enskog_state_at), then η = η*η0, κ_b = κ_b*η0, κ = κ*κ0, μ = μ*Tκ0/n,
 *  ζ = ζ*nT/η0, p = p*nT. Thread-safe. */
gkt_status gkt_enskog_first_sonine_physical(int dimension, double alpha, const gkt_gas* gas,
                                            gkt_enskog_first_sonine* out);

/* ---- any model, any order: the model registry -------------------------------------------------- */

/** A transport model of the registry ("hard-spheres", "smooth-inelastic", "viscoelastic",
 *  "mixture"; `gkt models` lists them) with its parameter point. Not thread-safe: one handle per
 *  thread (evaluation keeps solved state for reuse). */
typedef struct gkt_model gkt_model;

/** Creates the model called name (parameters unset: each takes its documented default) into
 *  *out. GKT_INVALID_ARGUMENT for an unknown name (the message lists the valid ones). */
gkt_status gkt_model_create(const char* name, gkt_model** out);

/** Frees a model (NULL is ignored). */
void gkt_model_destroy(gkt_model* model);

/** Sets the numeric parameter key (a scene key of conventions.md: "alpha", "dimension",
 *  "packing_fraction", "mass_2", "alpha_1_2", …) to value, read like the scene number of the same
 *  shortest decimal (0.9 is 9/10). GKT_INVALID_ARGUMENT for a key the model does not have (the
 *  message lists the valid keys), a choice key, or a value outside the key's range. */
gkt_status gkt_model_set_number(gkt_model* model, const char* key, double value);

/** Sets the choice parameter key ("hcs", "scheme", "pair_correlation") to value; refused like
 *  gkt_model_set_number for an unknown key or a value not among the choices. */
gkt_status gkt_model_set_choice(gkt_model* model, const char* key, const char* value);

/** One coefficient as the model computed it (the columns of `gkt table`). */
typedef struct gkt_coefficient {
  double value;  /**< reduced as in conventions.md for its canonical name; NaN if it does not exist at this order */
  double error;  /**< estimated truncation error, same units; NaN if not estimated, +inf if the value does not exist */
  int order;     /**< Sonine order used */
  int converged; /**< 1 if the estimate converged (below the tolerance when one was asked for), else 0 */
  int defined;   /**< 1 if the value exists at this order, else 0 */
} gkt_coefficient;

/** Computes the count coefficients names[0 … count−1] (canonical names of conventions.md) at
 *  Sonine order `order` (1 … the model's maximum) into out[0 … count−1]. GKT_INVALID_ARGUMENT for
 *  an unknown coefficient name, an order out of range, or parameters the model refuses together
 *  (e.g. mixture fractions that do not sum to 1). */
gkt_status gkt_model_evaluate(gkt_model* model, size_t count, const char* const* names, int order,
                              gkt_coefficient* out);

/** The same with each coefficient at the smallest order whose estimated error is below tolerance
 *  (in (0, 1]); one that reaches none has converged = 0 at its optimal truncation. (`gkt table`
 *  then re-evaluates the whole row at the largest of these orders; call gkt_model_evaluate with it
 *  to do the same.) */
gkt_status gkt_model_evaluate_to_tolerance(gkt_model* model, size_t count, const char* const* names, double tolerance,
                                           gkt_coefficient* out);

/* ---- binary mixtures: the per-cell transport table ---------------------------------------------- */

/** A binary's Navier–Stokes table (theory.md §17.8, dense §18.10), solved once at creation on
 *  Chebyshev–Lobatto nodes of x_1 (and φ), x_1 split into subintervals until a requested accuracy
 *  holds at every point checked, and interpolated per cell without allocation.
 *  Evaluation is thread-safe (the table is read only). */
typedef struct gkt_binary_table gkt_binary_table;

/** Builds the table of two species: mass[i] > 0, diameter[i] > 0 (any consistent units; only
 *  ratios enter the reduced values; each mass is converted once to the short rational it rounds,
 *  0.1 -> 1/10, as a scene's decimal is read: docs/architecture.md §4), the restitution matrix alpha[2i + j]
 * (symmetric, each in (0, 1]; row- or column-major alike), Sonine order in [1, 12], nodes in [3, 64] points in x_1 ∈
 * [0, 1]; max_packing_fraction in [0, 0.5) (3D) or [0, 0.7) (2D), 0 for a dilute table; and packing_nodes in [3, 64]
 * points in φ (used only when max_packing_fraction > 0). The table meets an interpolation error of 1e-3 (relative to
 * max(1, |value|) of the reduced coefficients) at every point checked, or is refused: GKT_INVALID_ARGUMENT, the message
 * naming the error reached and the x_1 interval (e.g. a pole of the order-N solution). Costs a few mixture solves per
 * node (seconds for a dense table; see gkt_binary_table_build_cost). */
gkt_status gkt_binary_table_create(int dimension, const double mass[2], const double diameter[2], const double alpha[4],
                                   int order, int nodes, double max_packing_fraction, int packing_nodes,
                                   gkt_binary_table** out);

/** Builds the table as gkt_binary_table_create, to the interpolation error `tolerance` in (0, 1]
 *  instead of 1e-3 (nodes and packing_nodes are then the starting points per axis and interval),
 *  over the compositions fraction_range = {x_low, x_high}, 0 <= x_low < x_high <= 1 (NULL: [0, 1];
 *  e.g. below a pole of the order-N solution that makes the full range refused). Evaluating the
 *  table at an x_1 in [0, 1] outside that range returns GKT_OUT_OF_RANGE. */
gkt_status gkt_binary_table_create_to_tolerance(int dimension, const double mass[2], const double diameter[2],
                                                const double alpha[4], int order, int nodes,
                                                double max_packing_fraction, int packing_nodes, double tolerance,
                                                const double fraction_range[2], gkt_binary_table** out);

/** Builds the table as gkt_binary_table_create_to_tolerance about the reference f^(0) `reference`
 *  (theory.md §17.14): "maxwellian" (GDH's; gkt_binary_table_create_to_tolerance; hcs_order ignored), or
 *  "linear" / "nonlinear", the HCS of that scheme with its cumulants a_2 … a_K in f^(0), K = hcs_order in
 *  [2, 6] (the mixture model's reference_state = "hcs" with that hcs and hcs_order). The tolerance is
 *  enforced against direct solves about the same reference; each node costs ~20 times a Maxwellian one
 *  (docs/performance.md). GKT_INVALID_ARGUMENT naming reference or hcs_order otherwise. */
gkt_status gkt_binary_table_create_about(int dimension, const double mass[2], const double diameter[2],
                                         const double alpha[4], int order, int nodes, double max_packing_fraction,
                                         int packing_nodes, double tolerance, const double fraction_range[2],
                                         const char* reference, int hcs_order, gkt_binary_table** out);

/** Writes the cost of the table's build: the x_1 intervals it settled on, the mixture solves it
 *  made (nodes, error and validation points) and the wall-clock seconds. */
gkt_status gkt_binary_table_build_cost(const gkt_binary_table* table, int* intervals, int* solves, double* seconds);

/** Frees a table (NULL is ignored). */
void gkt_binary_table_destroy(gkt_binary_table* table);

/** Writes the largest relative interpolation error measured at creation (between the nodes and at
 *  independent validation points against direct solves). */
gkt_status gkt_binary_table_interpolation_error(const gkt_binary_table* table, double* out);

/** The Navier–Stokes set of a binary at one state; species indices 0, 1 (C) = 1, 2 (Fortran,
 *  conventions.md). Flux laws (theory.md (17.1), (18.11)): j_i = −Σ_j (m_i m_j n_j/ρ) D_ij ∇ln n_j
 *  − ρ D^T_i ∇ln T, q = −λ∇T − T² Σ_j D''_j ∇ln n_j, P = pI − η(…) − κ_b I∇·u, ζ = ζ0 + ζ_U∇·u.
 *  Reduced by the reference gas of m̄ = Σ x_i m_i, σ̄ = Σ x_i σ_i at n, T. */
typedef struct gkt_binary_transport {
  double cooling_rate;             /**< reduced ζ* = ζ/ν0 (ν0 = nT/η0); physical ζ (1/time) */
  double temperature_ratio[2];     /**< T_i/T (both) */
  double shear_viscosity;          /**< reduced η/η0; physical η */
  double thermal_conductivity;     /**< reduced λ/κ0; physical λ */
  double mutual_diffusion[4];      /**< D_ij at 2i + j: reduced D_ij/(n D0); physical D_ij (n × diffusivity) */
  double thermal_diffusion[2];     /**< reduced D^T_i/D0; physical D^T_i (diffusivity) */
  double pressure_diffusion[2];    /**< reduced D^p_i/D0; physical D^p_i (diffusivity) */
  double dufour[2];                /**< reduced D''_j T/κ0; physical D''_j */
  double pressure;                 /**< reduced p/(nT); physical p */
  double bulk_viscosity;           /**< reduced κ_b/η0; physical κ_b (0 when dilute) */
  double cooling_rate_first_order; /**< ζ_U (dimensionless, both; 0 when dilute) */
} gkt_binary_transport;

/** Evaluates the table at mole fraction x_1 = fraction_1 in [0, 1], number density n > 0 and
 *  temperature T > 0 in physical units (the units of the masses and diameters given at creation).
 *  A dilute table treats any n as dilute; a dense one returns GKT_OUT_OF_RANGE when
 *  φ = n v_d Σ x_i σ_i^d exceeds its max_packing_fraction. Thread-safe, no allocation. */
gkt_status gkt_binary_table_evaluate(const gkt_binary_table* table, double fraction_1, double number_density,
                                     double temperature, gkt_binary_transport* out);

/** Evaluates the table at `cells` states of the caller's arrays (out[i] from fraction_1[i],
 *  number_density[i], temperature[i], physical units as gkt_binary_table_evaluate). Every state is
 *  checked before any is evaluated: on a bad one nothing is written and the message names its
 *  index ("fraction_1[3]: …"). Thread-safe, no allocation. */
gkt_status gkt_binary_table_evaluate_cells(const gkt_binary_table* table, size_t cells, const double* fraction_1,
                                           const double* number_density, const double* temperature,
                                           gkt_binary_transport* out);

/** Evaluates the table at x_1 = fraction_1 in [0, 1] and packing fraction φ in reduced units (the
 *  columns of `gkt table` for a binary mixture scene, hcs = "maxwellian"). φ must be 0 for a dilute
 *  table and in [0, max_packing_fraction] for a dense one. Thread-safe, no allocation. */
gkt_status gkt_binary_table_evaluate_reduced(const gkt_binary_table* table, double fraction_1, double packing_fraction,
                                             gkt_binary_transport* out);

/* ---- ternary mixtures: the per-cell transport table ---------------------------------------------- */

/** A ternary's Navier–Stokes table (theory.md §17.8, "Ternary tables"; dense, φ as a third axis,
 *  §18.10): solved once at creation on Chebyshev–Lobatto nodes of the Duffy square (x_1 = u,
 *  x_2 = (1 − u) v) (× φ), the square split into rectangles until a requested accuracy holds at every
 *  point checked, and interpolated per cell without allocation. Evaluation is thread-safe (the table
 *  is read only). */
typedef struct gkt_ternary_table gkt_ternary_table;

/** Builds the table of three species: mass[i] > 0, diameter[i] > 0 (any consistent units; each
 *  mass converted once to the short rational it rounds, as for gkt_binary_table_create), the
 *  restitution matrix alpha[3i + j] (symmetric, each in (0, 1]: α_ij for every pair, as the
 *  mixture model's alpha_i_j keys), Sonine order in [1, 12], nodes in [3, 33] points per axis to
 *  start from, and the interpolation error `tolerance` in (0, 1] (relative to max(1, |value|) of
 *  the reduced coefficients; 1e-3 is the level of the first-Sonine truncation error) that the
 *  table meets at every point checked, or is refused: GKT_INVALID_ARGUMENT, the message naming
 *  the error reached, where, and the region of x_1 and x_2/(1 − x_1) (e.g. a pole of the order-N
 *  solution). Costs one mixture solve per node and check point (seconds; see
 *  gkt_ternary_table_build_cost). */
gkt_status gkt_ternary_table_create(int dimension, const double mass[3], const double diameter[3],
                                    const double alpha[9], int order, int nodes, double tolerance,
                                    gkt_ternary_table** out);

/** Builds the dense ternary's table: as gkt_ternary_table_create, with the packing fraction φ as a
 *  third axis, packing_nodes in [3, 33] Chebyshev–Lobatto points of φ ∈ [0, max_packing_fraction] to
 *  start from, refined with the other axes up to max_nodes in [nodes, 33] per axis (33 in
 *  gkt_ternary_table_create) before a rectangle is split; max_packing_fraction in [0, 0.5) (3D) or
 *  [0, 0.7) (2D), 0 for the dilute table of gkt_ternary_table_create. The tolerance holds over the whole
 *  (x_1, x_2, φ) box or the table is refused (GKT_INVALID_ARGUMENT, the message naming the error
 *  reached, the point and the region of x_1, x_2/(1 − x_1) and φ). Costs one dense mixture solve per
 *  node and check point: about 20 s for tolerance 5e-2 at order 1 (docs/performance.md). */
gkt_status gkt_ternary_table_create_dense(int dimension, const double mass[3], const double diameter[3],
                                          const double alpha[9], int order, int nodes, int max_nodes, double tolerance,
                                          double max_packing_fraction, int packing_nodes, gkt_ternary_table** out);

/** Builds the table as gkt_ternary_table_create_dense about the reference f^(0) `reference` and hcs_order,
 *  as gkt_binary_table_create_about (theory.md §17.14; each node ~30 times a Maxwellian one). */
gkt_status gkt_ternary_table_create_about(int dimension, const double mass[3], const double diameter[3],
                                          const double alpha[9], int order, int nodes, int max_nodes, double tolerance,
                                          double max_packing_fraction, int packing_nodes, const char* reference,
                                          int hcs_order, gkt_ternary_table** out);

/** Writes the cost of the table's build: the rectangles (pieces) it settled on, the mixture solves
 *  it made (nodes, error and validation points) and the wall-clock seconds. */
gkt_status gkt_ternary_table_build_cost(const gkt_ternary_table* table, int* pieces, int* solves, double* seconds);

/** Frees a table (NULL is ignored). */
void gkt_ternary_table_destroy(gkt_ternary_table* table);

/** Writes the largest relative interpolation error measured at creation (between the nodes and at
 *  independent validation points against direct solves). */
gkt_status gkt_ternary_table_interpolation_error(const gkt_ternary_table* table, double* out);

/** The Navier–Stokes set of a ternary at one state; species indices 0, 1, 2 (C) = 1, 2, 3
 *  (conventions.md); matrices at 3i + j. Flux laws and reductions as gkt_binary_transport (the
 *  reference gas of m̄ = Σ x_i m_i, σ̄ = Σ x_i σ_i at n, T). */
typedef struct gkt_ternary_transport {
  double cooling_rate;             /**< reduced ζ* = ζ/ν0 (ν0 = nT/η0); physical ζ (1/time) */
  double temperature_ratio[3];     /**< T_i/T (both) */
  double shear_viscosity;          /**< reduced η/η0; physical η */
  double thermal_conductivity;     /**< reduced λ/κ0; physical λ */
  double mutual_diffusion[9];      /**< D_ij at 3i + j: reduced D_ij/(n D0); physical D_ij (n × diffusivity) */
  double thermal_diffusion[3];     /**< reduced D^T_i/D0; physical D^T_i (diffusivity) */
  double pressure_diffusion[3];    /**< reduced D^p_i/D0; physical D^p_i (diffusivity) */
  double dufour[3];                /**< reduced D''_j T/κ0; physical D''_j */
  double pressure;                 /**< reduced p/(nT) (1 when dilute); physical p (nT when dilute) */
  double bulk_viscosity;           /**< reduced κ_b/η0; physical κ_b (0 when dilute) */
  double cooling_rate_first_order; /**< ζ_U (dimensionless, both; 0 when dilute) */
} gkt_ternary_transport;

/** Evaluates the table at mole fractions x_1 = fraction_1 in [0, 1], x_2 = fraction_2 in
 *  [0, 1 − x_1] (x_3 = 1 − x_1 − x_2), number density n > 0 and temperature T > 0 in physical units
 *  (the units of the masses and diameters given at creation). A dilute table treats any n as dilute;
 *  a dense one returns GKT_OUT_OF_RANGE when φ = n v_d Σ x_i σ_i^d exceeds its max_packing_fraction.
 *  Thread-safe, no allocation. */
gkt_status gkt_ternary_table_evaluate(const gkt_ternary_table* table, double fraction_1, double fraction_2,
                                      double number_density, double temperature, gkt_ternary_transport* out);

/** Evaluates the table at `cells` states of the caller's arrays (out[i] from fraction_1[i],
 *  fraction_2[i], number_density[i], temperature[i], as gkt_ternary_table_evaluate). Every state is
 *  checked before any is evaluated: on a bad one nothing is written and the message names its
 *  index ("fraction_2[3]: …"). Thread-safe, no allocation. */
gkt_status gkt_ternary_table_evaluate_cells(const gkt_ternary_table* table, size_t cells, const double* fraction_1,
                                            const double* fraction_2, const double* number_density,
                                            const double* temperature, gkt_ternary_transport* out);

/** Evaluates the table at (x_1, x_2) and φ = 0 in reduced units (the columns of `gkt table` for a
 *  dilute ternary mixture scene, hcs = "maxwellian"). Thread-safe, no allocation. */
gkt_status gkt_ternary_table_evaluate_reduced(const gkt_ternary_table* table, double fraction_1, double fraction_2,
                                              gkt_ternary_transport* out);

/** Evaluates the table at (x_1, x_2) and packing fraction φ in reduced units (the columns of `gkt
 *  table` for a ternary mixture scene at that packing_fraction, hcs = "maxwellian"). φ must be 0 for a
 *  dilute table and in [0, max_packing_fraction] for a dense one (GKT_OUT_OF_RANGE above it).
 *  Thread-safe, no allocation. */
gkt_status gkt_ternary_table_evaluate_reduced_dense(const gkt_ternary_table* table, double fraction_1,
                                                    double fraction_2, double packing_fraction,
                                                    gkt_ternary_transport* out);

#ifdef __cplusplus
}
#endif

#endif /* GKT_GKT_H */
