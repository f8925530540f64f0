! The Fortran 2008 module of gkt: the C API (include/gkt/gkt.h) through iso_c_binding, with
! Fortran strings and handles. Every function returns the status of the C call (GKT_OK = 0); on
! any other status gkt_last_error() says which field was refused and why. Units and reductions
! are those of the C header, field by field (docs/conventions.md). Species indices run from 1:
! mutual_diffusion(2*(i-1) + j) is D_ij.
module gkt
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_ptr, c_size_t, c_null_ptr, c_null_char, &
                                         c_associated, c_f_pointer, c_loc
  implicit none
  private

  ! Status codes (gkt_status).
  integer(c_int), parameter, public :: GKT_OK = 0, GKT_INVALID_ARGUMENT = 1, GKT_OUT_OF_RANGE = 2, &
                                       GKT_INTERNAL_ERROR = 3

  !> Dilute first-Sonine set: reduced (a2, zeta*, eta*, kappa*, mu*) or physical, as in gkt.h.
  type, bind(C), public :: gkt_first_sonine
    real(c_double) :: a2, cooling_rate, shear_viscosity, thermal_conductivity, density_heat_coefficient
  end type

  !> A one-component gas in physical units (mass, diameter, number density, temperature as an energy).
  type, bind(C), public :: gkt_gas
    real(c_double) :: mass, diameter, number_density, temperature
  end type

  !> The dense state (phi, chi(phi), phi dchi/dphi).
  type, bind(C), public :: gkt_enskog_state
    real(c_double) :: packing_fraction, chi, phi_dchi
  end type

  !> Dense first-Sonine set, reduced or physical as in gkt.h.
  type, bind(C), public :: gkt_enskog_first_sonine
    real(c_double) :: a2, cooling_rate, pressure, shear_viscosity, bulk_viscosity, thermal_conductivity, &
                      density_heat_coefficient, cooling_rate_first_order
  end type

  !> One coefficient of a registry model: value, error estimate, order, converged (0/1), defined (0/1).
  type, bind(C), public :: gkt_coefficient
    real(c_double) :: value, error
    integer(c_int) :: order, converged, defined
  end type

  !> A binary's Navier-Stokes set (physical or reduced, as in gkt.h).
  type, bind(C), public :: gkt_binary_transport
    real(c_double) :: cooling_rate
    real(c_double) :: temperature_ratio(2)
    real(c_double) :: shear_viscosity
    real(c_double) :: thermal_conductivity
    real(c_double) :: mutual_diffusion(4)
    real(c_double) :: thermal_diffusion(2)
    real(c_double) :: pressure_diffusion(2)
    real(c_double) :: dufour(2)
    real(c_double) :: pressure
    real(c_double) :: bulk_viscosity
    real(c_double) :: cooling_rate_first_order
  end type

  !> A ternary's Navier-Stokes set (physical or reduced, as in gkt.h; D_ij at 3(i-1) + j).
  type, bind(C), public :: gkt_ternary_transport
    real(c_double) :: cooling_rate
    real(c_double) :: temperature_ratio(3)
    real(c_double) :: shear_viscosity
    real(c_double) :: thermal_conductivity
    real(c_double) :: mutual_diffusion(9)
    real(c_double) :: thermal_diffusion(3)
    real(c_double) :: pressure_diffusion(3)
    real(c_double) :: dufour(3)
    real(c_double) :: pressure
    real(c_double) :: bulk_viscosity
    real(c_double) :: cooling_rate_first_order
  end type

  !> A registry model (gkt_model*); free it with gkt_model_destroy.
  type, public :: gkt_model
    type(c_ptr) :: handle = c_null_ptr
  end type

  !> A binary's transport table (gkt_binary_table*); free it with gkt_binary_table_destroy.
  type, public :: gkt_binary_table
    type(c_ptr) :: handle = c_null_ptr
  end type

  !> A ternary's transport table, dilute or dense (gkt_ternary_table*); free it with gkt_ternary_table_destroy.
  type, public :: gkt_ternary_table
    type(c_ptr) :: handle = c_null_ptr
  end type

  public :: gkt_last_error, gkt_last_warnings, gkt_version
  public :: gkt_first_sonine_values, gkt_first_sonine_physical, gkt_enskog_state_at
  public :: gkt_enskog_first_sonine_values, gkt_enskog_first_sonine_values_at, gkt_enskog_first_sonine_physical
  public :: gkt_first_sonine_values_cells, gkt_enskog_first_sonine_values_cells
  public :: gkt_model_create, gkt_model_destroy, gkt_model_set_number, gkt_model_set_choice, gkt_model_evaluate
  public :: gkt_binary_table_create, gkt_binary_table_destroy, gkt_binary_table_interpolation_error
  public :: gkt_binary_table_create_to_tolerance, gkt_binary_table_build_cost
  public :: gkt_binary_table_evaluate, gkt_binary_table_evaluate_reduced, gkt_binary_table_evaluate_cells
  public :: gkt_ternary_table_create, gkt_ternary_table_destroy, gkt_ternary_table_interpolation_error
  public :: gkt_ternary_table_build_cost, gkt_ternary_table_evaluate, gkt_ternary_table_evaluate_reduced
  public :: gkt_ternary_table_create_dense, gkt_ternary_table_evaluate_reduced_dense
  public :: gkt_binary_table_create_about, gkt_ternary_table_create_about

  ! The per-cell calls bind directly: no conversion on the way.
  interface
    function gkt_first_sonine_values(dimension, alpha, out) bind(C, name="gkt_first_sonine_values") result(status)
      import :: c_int, c_double, gkt_first_sonine
      integer(c_int), value :: dimension
      real(c_double), value :: alpha
      type(gkt_first_sonine), intent(out) :: out
      integer(c_int) :: status
    end function
    function gkt_first_sonine_physical(dimension, alpha, gas, out) bind(C, name="gkt_first_sonine_physical") &
        result(status)
      import :: c_int, c_double, gkt_gas, gkt_first_sonine
      integer(c_int), value :: dimension
      real(c_double), value :: alpha
      type(gkt_gas), intent(in) :: gas
      type(gkt_first_sonine), intent(out) :: out
      integer(c_int) :: status
    end function
    function gkt_enskog_state_at(dimension, packing_fraction, out) bind(C, name="gkt_enskog_state_at") result(status)
      import :: c_int, c_double, gkt_enskog_state
      integer(c_int), value :: dimension
      real(c_double), value :: packing_fraction
      type(gkt_enskog_state), intent(out) :: out
      integer(c_int) :: status
    end function
    function gkt_enskog_first_sonine_values(dimension, alpha, packing_fraction, out) &
        bind(C, name="gkt_enskog_first_sonine_values") result(status)
      import :: c_int, c_double, gkt_enskog_first_sonine
      integer(c_int), value :: dimension
      real(c_double), value :: alpha, packing_fraction
      type(gkt_enskog_first_sonine), intent(out) :: out
      integer(c_int) :: status
    end function
    function gkt_enskog_first_sonine_values_at(dimension, alpha, state, out) &
        bind(C, name="gkt_enskog_first_sonine_values_at") result(status)
      import :: c_int, c_double, gkt_enskog_state, gkt_enskog_first_sonine
      integer(c_int), value :: dimension
      real(c_double), value :: alpha
      type(gkt_enskog_state), intent(in) :: state
      type(gkt_enskog_first_sonine), intent(out) :: out
      integer(c_int) :: status
    end function
    function c_first_sonine_values_cells(dimension, cells, alpha, out) bind(C, name="gkt_first_sonine_values_cells") &
        result(status)
      import :: c_int, c_size_t, c_double, gkt_first_sonine
      integer(c_int), value :: dimension
      integer(c_size_t), value :: cells
      real(c_double), intent(in) :: alpha(*)
      type(gkt_first_sonine), intent(inout) :: out(*)
      integer(c_int) :: status
    end function
    function c_enskog_first_sonine_values_cells(dimension, cells, alpha, packing_fraction, out) &
        bind(C, name="gkt_enskog_first_sonine_values_cells") result(status)
      import :: c_int, c_size_t, c_double, gkt_enskog_first_sonine
      integer(c_int), value :: dimension
      integer(c_size_t), value :: cells
      real(c_double), intent(in) :: alpha(*), packing_fraction(*)
      type(gkt_enskog_first_sonine), intent(inout) :: out(*)
      integer(c_int) :: status
    end function
    function c_binary_table_evaluate_cells(table, cells, fraction_1, number_density, temperature, out) &
        bind(C, name="gkt_binary_table_evaluate_cells") result(status)
      import :: c_ptr, c_size_t, c_double, c_int, gkt_binary_transport
      type(c_ptr), value :: table
      integer(c_size_t), value :: cells
      real(c_double), intent(in) :: fraction_1(*), number_density(*), temperature(*)
      type(gkt_binary_transport), intent(out) :: out(*)
      integer(c_int) :: status
    end function
    function gkt_enskog_first_sonine_physical(dimension, alpha, gas, out) &
        bind(C, name="gkt_enskog_first_sonine_physical") result(status)
      import :: c_int, c_double, gkt_gas, gkt_enskog_first_sonine
      integer(c_int), value :: dimension
      real(c_double), value :: alpha
      type(gkt_gas), intent(in) :: gas
      type(gkt_enskog_first_sonine), intent(out) :: out
      integer(c_int) :: status
    end function
  end interface

  ! The C calls behind the Fortran wrappers below (strings, handles, arrays).
  interface
    function c_last_error() bind(C, name="gkt_last_error") result(message)
      import :: c_ptr
      type(c_ptr) :: message
    end function
    function c_last_warnings() bind(C, name="gkt_last_warnings") result(message)
      import :: c_ptr
      type(c_ptr) :: message
    end function
    function c_version() bind(C, name="gkt_version") result(version)
      import :: c_ptr
      type(c_ptr) :: version
    end function
    function c_strlen(s) bind(C, name="strlen") result(length)
      import :: c_ptr, c_size_t
      type(c_ptr), value :: s
      integer(c_size_t) :: length
    end function
    function c_model_create(name, out) bind(C, name="gkt_model_create") result(status)
      import :: c_char, c_ptr, c_int
      character(kind=c_char), intent(in) :: name(*)
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function
    subroutine c_model_destroy(model) bind(C, name="gkt_model_destroy")
      import :: c_ptr
      type(c_ptr), value :: model
    end subroutine
    function c_model_set_number(model, key, value) bind(C, name="gkt_model_set_number") result(status)
      import :: c_ptr, c_char, c_double, c_int
      type(c_ptr), value :: model
      character(kind=c_char), intent(in) :: key(*)
      real(c_double), value :: value
      integer(c_int) :: status
    end function
    function c_model_set_choice(model, key, value) bind(C, name="gkt_model_set_choice") result(status)
      import :: c_ptr, c_char, c_int
      type(c_ptr), value :: model
      character(kind=c_char), intent(in) :: key(*), value(*)
      integer(c_int) :: status
    end function
    function c_model_evaluate(model, count, names, order, out) bind(C, name="gkt_model_evaluate") result(status)
      import :: c_ptr, c_size_t, c_int, gkt_coefficient
      type(c_ptr), value :: model
      integer(c_size_t), value :: count
      type(c_ptr), intent(in) :: names(*)
      integer(c_int), value :: order
      type(gkt_coefficient), intent(out) :: out(*)
      integer(c_int) :: status
    end function
    function c_ternary_table_create(dimension, mass, diameter, alpha, order, nodes, tolerance, out) &
        bind(C, name="gkt_ternary_table_create") result(status)
      import :: c_int, c_double, c_ptr
      integer(c_int), value :: dimension
      real(c_double), intent(in) :: mass(3), diameter(3), alpha(9)
      integer(c_int), value :: order, nodes
      real(c_double), value :: tolerance
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function
    function c_ternary_table_create_dense(dimension, mass, diameter, alpha, order, nodes, max_nodes, tolerance, &
                                          max_packing_fraction, packing_nodes, out) &
        bind(C, name="gkt_ternary_table_create_dense") result(status)
      import :: c_int, c_double, c_ptr
      integer(c_int), value :: dimension
      real(c_double), intent(in) :: mass(3), diameter(3), alpha(9)
      integer(c_int), value :: order, nodes, max_nodes
      real(c_double), value :: tolerance, max_packing_fraction
      integer(c_int), value :: packing_nodes
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function
    function c_ternary_table_create_about(dimension, mass, diameter, alpha, order, nodes, max_nodes, tolerance, &
                                          max_packing_fraction, packing_nodes, reference, hcs_order, out) &
        bind(C, name="gkt_ternary_table_create_about") result(status)
      import :: c_int, c_double, c_ptr, c_char
      integer(c_int), value :: dimension
      real(c_double), intent(in) :: mass(3), diameter(3), alpha(9)
      integer(c_int), value :: order, nodes, max_nodes
      real(c_double), value :: tolerance, max_packing_fraction
      integer(c_int), value :: packing_nodes
      character(kind=c_char), intent(in) :: reference(*)
      integer(c_int), value :: hcs_order
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function
    function c_binary_table_create_about(dimension, mass, diameter, alpha, order, nodes, max_packing_fraction, &
                                         packing_nodes, tolerance, fraction_range, reference, hcs_order, out) &
        bind(C, name="gkt_binary_table_create_about") result(status)
      import :: c_int, c_double, c_ptr, c_char
      integer(c_int), value :: dimension
      real(c_double), intent(in) :: mass(2), diameter(2), alpha(4)
      integer(c_int), value :: order, nodes
      real(c_double), value :: max_packing_fraction
      integer(c_int), value :: packing_nodes
      real(c_double), value :: tolerance
      real(c_double), intent(in) :: fraction_range(2)
      character(kind=c_char), intent(in) :: reference(*)
      integer(c_int), value :: hcs_order
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function
    function c_ternary_table_evaluate_reduced_dense(table, fraction_1, fraction_2, packing_fraction, out) &
        bind(C, name="gkt_ternary_table_evaluate_reduced_dense") result(status)
      import :: c_ptr, c_double, c_int, gkt_ternary_transport
      type(c_ptr), value :: table
      real(c_double), value :: fraction_1, fraction_2, packing_fraction
      type(gkt_ternary_transport), intent(out) :: out
      integer(c_int) :: status
    end function
    function c_ternary_table_build_cost(table, pieces, solves, seconds) &
        bind(C, name="gkt_ternary_table_build_cost") result(status)
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: table
      integer(c_int), intent(out) :: pieces, solves
      real(c_double), intent(out) :: seconds
      integer(c_int) :: status
    end function
    subroutine c_ternary_table_destroy(table) bind(C, name="gkt_ternary_table_destroy")
      import :: c_ptr
      type(c_ptr), value :: table
    end subroutine
    function c_ternary_table_interpolation_error(table, out) bind(C, name="gkt_ternary_table_interpolation_error") &
        result(status)
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: table
      real(c_double), intent(out) :: out
      integer(c_int) :: status
    end function
    function c_ternary_table_evaluate(table, fraction_1, fraction_2, number_density, temperature, out) &
        bind(C, name="gkt_ternary_table_evaluate") result(status)
      import :: c_ptr, c_double, c_int, gkt_ternary_transport
      type(c_ptr), value :: table
      real(c_double), value :: fraction_1, fraction_2, number_density, temperature
      type(gkt_ternary_transport), intent(out) :: out
      integer(c_int) :: status
    end function
    function c_ternary_table_evaluate_reduced(table, fraction_1, fraction_2, out) &
        bind(C, name="gkt_ternary_table_evaluate_reduced") result(status)
      import :: c_ptr, c_double, c_int, gkt_ternary_transport
      type(c_ptr), value :: table
      real(c_double), value :: fraction_1, fraction_2
      type(gkt_ternary_transport), intent(out) :: out
      integer(c_int) :: status
    end function
    function c_binary_table_create(dimension, mass, diameter, alpha, order, nodes, max_packing_fraction, &
                                   packing_nodes, out) bind(C, name="gkt_binary_table_create") result(status)
      import :: c_int, c_double, c_ptr
      integer(c_int), value :: dimension
      real(c_double), intent(in) :: mass(2), diameter(2), alpha(4)
      integer(c_int), value :: order, nodes
      real(c_double), value :: max_packing_fraction
      integer(c_int), value :: packing_nodes
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function
    function c_binary_table_create_to_tolerance(dimension, mass, diameter, alpha, order, nodes, &
                                                max_packing_fraction, packing_nodes, tolerance, fraction_range, out) &
        bind(C, name="gkt_binary_table_create_to_tolerance") result(status)
      import :: c_int, c_double, c_ptr
      integer(c_int), value :: dimension
      real(c_double), intent(in) :: mass(2), diameter(2), alpha(4)
      integer(c_int), value :: order, nodes
      real(c_double), value :: max_packing_fraction
      integer(c_int), value :: packing_nodes
      real(c_double), value :: tolerance
      real(c_double), intent(in) :: fraction_range(2)
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function
    function c_binary_table_build_cost(table, intervals, solves, seconds) bind(C, name="gkt_binary_table_build_cost") &
        result(status)
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: table
      integer(c_int), intent(out) :: intervals, solves
      real(c_double), intent(out) :: seconds
      integer(c_int) :: status
    end function
    subroutine c_binary_table_destroy(table) bind(C, name="gkt_binary_table_destroy")
      import :: c_ptr
      type(c_ptr), value :: table
    end subroutine
    function c_binary_table_interpolation_error(table, out) bind(C, name="gkt_binary_table_interpolation_error") &
        result(status)
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: table
      real(c_double), intent(out) :: out
      integer(c_int) :: status
    end function
    function c_binary_table_evaluate(table, fraction_1, number_density, temperature, out) &
        bind(C, name="gkt_binary_table_evaluate") result(status)
      import :: c_ptr, c_double, c_int, gkt_binary_transport
      type(c_ptr), value :: table
      real(c_double), value :: fraction_1, number_density, temperature
      type(gkt_binary_transport), intent(out) :: out
      integer(c_int) :: status
    end function
    function c_binary_table_evaluate_reduced(table, fraction_1, packing_fraction, out) &
        bind(C, name="gkt_binary_table_evaluate_reduced") result(status)
      import :: c_ptr, c_double, c_int, gkt_binary_transport
      type(c_ptr), value :: table
      real(c_double), value :: fraction_1, packing_fraction
      type(gkt_binary_transport), intent(out) :: out
      integer(c_int) :: status
    end function
  end interface

contains

  !> Returns a C string as a Fortran string ("" for a null pointer).
  function from_c(s) result(text)
    type(c_ptr), intent(in) :: s
    character(len=:), allocatable :: text
    character(kind=c_char), pointer :: chars(:)
    integer :: i, n
    if (.not. c_associated(s)) then
      text = ""
      return
    end if
    n = int(c_strlen(s))
    call c_f_pointer(s, chars, [n])
    allocate (character(len=n) :: text)
    do i = 1, n
      text(i:i) = chars(i)
    end do
  end function

  !> Returns the Fortran string, trimmed, as a null-terminated C string.
  pure function to_c(text) result(chars)
    character(len=*), intent(in) :: text
    character(kind=c_char, len=:), allocatable :: chars
    chars = trim(text)//c_null_char
  end function

  !> Returns the message of this thread's last failing call ("" if none).
  function gkt_last_error() result(message)
    character(len=:), allocatable :: message
    message = from_c(c_last_error())
  end function

  !> Returns what the error estimates of this thread's last gkt_model_evaluate do not cover, one line each ("" if
  !> nothing; the warnings `gkt table` prints).
  function gkt_last_warnings() result(message)
    character(len=:), allocatable :: message
    message = from_c(c_last_warnings())
  end function

  !> Returns gkt's version, e.g. "0.1.0".
  function gkt_version() result(version)
    character(len=:), allocatable :: version
    version = from_c(c_version())
  end function

  !> Creates the registry model called name (e.g. "smooth-inelastic") into model.
  function gkt_model_create(name, model) result(status)
    character(len=*), intent(in) :: name
    type(gkt_model), intent(out) :: model
    integer(c_int) :: status
    status = c_model_create(to_c(name), model%handle)
  end function

  !> Frees the model (a model never created is ignored).
  subroutine gkt_model_destroy(model)
    type(gkt_model), intent(inout) :: model
    call c_model_destroy(model%handle)
    model%handle = c_null_ptr
  end subroutine

  !> Sets the numeric parameter key (a scene key, e.g. "alpha") to value; unknown keys are refused.
  function gkt_model_set_number(model, key, value) result(status)
    type(gkt_model), intent(in) :: model
    character(len=*), intent(in) :: key
    real(c_double), intent(in) :: value
    integer(c_int) :: status
    status = c_model_set_number(model%handle, to_c(key), value)
  end function

  !> Sets the choice parameter key (e.g. "scheme") to value; unknown keys or values are refused.
  function gkt_model_set_choice(model, key, value) result(status)
    type(gkt_model), intent(in) :: model
    character(len=*), intent(in) :: key, value
    integer(c_int) :: status
    status = c_model_set_choice(model%handle, to_c(key), to_c(value))
  end function

  !> Computes the coefficient called name (reduced as in conventions.md) at Sonine order `order`.
  function gkt_model_evaluate(model, name, order, coefficient) result(status)
    type(gkt_model), intent(in) :: model
    character(len=*), intent(in) :: name
    integer(c_int), intent(in) :: order
    type(gkt_coefficient), intent(out) :: coefficient
    integer(c_int) :: status
    character(kind=c_char, len=:), allocatable, target :: c_name
    type(c_ptr) :: names(1)
    type(gkt_coefficient) :: out(1)
    c_name = to_c(name)
    names(1) = c_loc(c_name)
    status = c_model_evaluate(model%handle, 1_c_size_t, names, order, out)
    coefficient = out(1)
  end function

  !> Builds the binary's table: masses (each converted once to the short rational it rounds, 0.1 -> 1/10,
  !> as gkt.h says), diameters, the symmetric restitution matrix alpha(2, 2),
  !> Sonine order, nodes in x_1, max_packing_fraction (0: dilute) and packing_nodes in phi.
  function gkt_binary_table_create(dimension, mass, diameter, alpha, order, nodes, max_packing_fraction, &
                                   packing_nodes, table) result(status)
    integer(c_int), intent(in) :: dimension, order, nodes, packing_nodes
    real(c_double), intent(in) :: mass(2), diameter(2), alpha(2, 2), max_packing_fraction
    type(gkt_binary_table), intent(out) :: table
    integer(c_int) :: status
    status = c_binary_table_create(dimension, mass, diameter, reshape(alpha, [4]), order, nodes, &
                                   max_packing_fraction, packing_nodes, table%handle)
  end function

  !> Builds the table as gkt_binary_table_create, to the interpolation error `tolerance` in (0, 1]
  !> (1e-3 there) over the compositions fraction_range = [x_low, x_high] within [0, 1].
  function gkt_binary_table_create_to_tolerance(dimension, mass, diameter, alpha, order, nodes, max_packing_fraction, &
                                                packing_nodes, tolerance, fraction_range, table) result(status)
    integer(c_int), intent(in) :: dimension, order, nodes, packing_nodes
    real(c_double), intent(in) :: mass(2), diameter(2), alpha(2, 2), max_packing_fraction, tolerance, fraction_range(2)
    type(gkt_binary_table), intent(out) :: table
    integer(c_int) :: status
    status = c_binary_table_create_to_tolerance(dimension, mass, diameter, reshape(alpha, [4]), order, nodes, &
                                                max_packing_fraction, packing_nodes, tolerance, fraction_range, &
                                                table%handle)
  end function

  !> Builds the table as gkt_binary_table_create_to_tolerance about the reference f0 `reference`:
  !> "maxwellian", or "linear" / "nonlinear", the HCS of that scheme with a_2 ... a_K, K = hcs_order in [2, 6] (gkt.h).
  function gkt_binary_table_create_about(dimension, mass, diameter, alpha, order, nodes, max_packing_fraction, &
                                         packing_nodes, tolerance, fraction_range, reference, hcs_order, table) &
      result(status)
    integer(c_int), intent(in) :: dimension, order, nodes, packing_nodes, hcs_order
    real(c_double), intent(in) :: mass(2), diameter(2), alpha(2, 2), max_packing_fraction, tolerance, fraction_range(2)
    character(len=*), intent(in) :: reference
    type(gkt_binary_table), intent(out) :: table
    integer(c_int) :: status
    status = c_binary_table_create_about(dimension, mass, diameter, reshape(alpha, [4]), order, nodes, &
                                         max_packing_fraction, packing_nodes, tolerance, fraction_range, &
                                         reference // c_null_char, hcs_order, table%handle)
  end function

  !> Builds the table as gkt_ternary_table_create_dense about the reference f0 `reference` and hcs_order (gkt.h).
  function gkt_ternary_table_create_about(dimension, mass, diameter, alpha, order, nodes, max_nodes, tolerance, &
                                          max_packing_fraction, packing_nodes, reference, hcs_order, table) &
      result(status)
    integer(c_int), intent(in) :: dimension, order, nodes, max_nodes, packing_nodes, hcs_order
    real(c_double), intent(in) :: mass(3), diameter(3), alpha(3, 3), tolerance, max_packing_fraction
    character(len=*), intent(in) :: reference
    type(gkt_ternary_table), intent(out) :: table
    integer(c_int) :: status
    status = c_ternary_table_create_about(dimension, mass, diameter, reshape(alpha, [9]), order, nodes, max_nodes, &
                                          tolerance, max_packing_fraction, packing_nodes, reference // c_null_char, &
                                          hcs_order, table%handle)
  end function

  !> Writes the table's build cost: x_1 intervals, mixture solves and wall-clock seconds.
  function gkt_binary_table_build_cost(table, intervals, solves, seconds) result(status)
    type(gkt_binary_table), intent(in) :: table
    integer(c_int), intent(out) :: intervals, solves
    real(c_double), intent(out) :: seconds
    integer(c_int) :: status
    status = c_binary_table_build_cost(table%handle, intervals, solves, seconds)
  end function

  !> Frees the table (a table never created is ignored).
  subroutine gkt_binary_table_destroy(table)
    type(gkt_binary_table), intent(inout) :: table
    call c_binary_table_destroy(table%handle)
    table%handle = c_null_ptr
  end subroutine

  !> Writes the largest relative interpolation error measured at creation (between the nodes and at
  !> independent validation points).
  function gkt_binary_table_interpolation_error(table, error) result(status)
    type(gkt_binary_table), intent(in) :: table
    real(c_double), intent(out) :: error
    integer(c_int) :: status
    status = c_binary_table_interpolation_error(table%handle, error)
  end function

  !> Evaluates the table at mole fraction x_1, number density n and temperature T (physical units).
  function gkt_binary_table_evaluate(table, fraction_1, number_density, temperature, out) result(status)
    type(gkt_binary_table), intent(in) :: table
    real(c_double), intent(in) :: fraction_1, number_density, temperature
    type(gkt_binary_transport), intent(out) :: out
    integer(c_int) :: status
    status = c_binary_table_evaluate(table%handle, fraction_1, number_density, temperature, out)
  end function

  !> Evaluates the table at the states (fraction_1(i), number_density(i), temperature(i)) of
  !> size(fraction_1) cells into out(i), physical units; every state is checked first (the message
  !> of a bad one names its index, from 0).
  function gkt_binary_table_evaluate_cells(table, fraction_1, number_density, temperature, out) result(status)
    type(gkt_binary_table), intent(in) :: table
    real(c_double), intent(in) :: fraction_1(:), number_density(size(fraction_1)), temperature(size(fraction_1))
    type(gkt_binary_transport), intent(out) :: out(size(fraction_1))
    integer(c_int) :: status
    status = c_binary_table_evaluate_cells(table%handle, int(size(fraction_1), c_size_t), fraction_1, number_density, &
                                           temperature, out)
  end function

  !> Builds the dilute ternary's table: masses (converted as for the binary), diameters, the
  !> symmetric restitution matrix alpha(3, 3), Sonine order, nodes per axis to start from and the
  !> interpolation error `tolerance` in (0, 1] it meets or is refused (gkt.h).
  function gkt_ternary_table_create(dimension, mass, diameter, alpha, order, nodes, tolerance, table) result(status)
    integer(c_int), intent(in) :: dimension, order, nodes
    real(c_double), intent(in) :: mass(3), diameter(3), alpha(3, 3), tolerance
    type(gkt_ternary_table), intent(out) :: table
    integer(c_int) :: status
    status = c_ternary_table_create(dimension, mass, diameter, reshape(alpha, [9]), order, nodes, tolerance, &
                                    table%handle)
  end function

  !> Builds the dense ternary's table: as gkt_ternary_table_create with the packing fraction phi as a
  !> third axis, packing_nodes points of phi in [0, max_packing_fraction] to start from (0: dilute),
  !> every axis refined up to max_nodes before a rectangle is split; the tolerance holds over the
  !> whole (x_1, x_2, phi) box or the table is refused (gkt.h).
  function gkt_ternary_table_create_dense(dimension, mass, diameter, alpha, order, nodes, max_nodes, tolerance, &
                                          max_packing_fraction, packing_nodes, table) result(status)
    integer(c_int), intent(in) :: dimension, order, nodes, max_nodes, packing_nodes
    real(c_double), intent(in) :: mass(3), diameter(3), alpha(3, 3), tolerance, max_packing_fraction
    type(gkt_ternary_table), intent(out) :: table
    integer(c_int) :: status
    status = c_ternary_table_create_dense(dimension, mass, diameter, reshape(alpha, [9]), order, nodes, max_nodes, &
                                          tolerance, max_packing_fraction, packing_nodes, table%handle)
  end function

  !> Writes the table's build cost: rectangles of the Duffy square, mixture solves and wall-clock seconds.
  function gkt_ternary_table_build_cost(table, pieces, solves, seconds) result(status)
    type(gkt_ternary_table), intent(in) :: table
    integer(c_int), intent(out) :: pieces, solves
    real(c_double), intent(out) :: seconds
    integer(c_int) :: status
    status = c_ternary_table_build_cost(table%handle, pieces, solves, seconds)
  end function

  !> Frees the table (a table never created is ignored).
  subroutine gkt_ternary_table_destroy(table)
    type(gkt_ternary_table), intent(inout) :: table
    call c_ternary_table_destroy(table%handle)
    table%handle = c_null_ptr
  end subroutine

  !> Writes the largest relative interpolation error measured at creation.
  function gkt_ternary_table_interpolation_error(table, error) result(status)
    type(gkt_ternary_table), intent(in) :: table
    real(c_double), intent(out) :: error
    integer(c_int) :: status
    status = c_ternary_table_interpolation_error(table%handle, error)
  end function

  !> Evaluates the table at mole fractions x_1, x_2 (x_3 = 1 - x_1 - x_2), number density n and
  !> temperature T (physical units).
  function gkt_ternary_table_evaluate(table, fraction_1, fraction_2, number_density, temperature, out) result(status)
    type(gkt_ternary_table), intent(in) :: table
    real(c_double), intent(in) :: fraction_1, fraction_2, number_density, temperature
    type(gkt_ternary_transport), intent(out) :: out
    integer(c_int) :: status
    status = c_ternary_table_evaluate(table%handle, fraction_1, fraction_2, number_density, temperature, out)
  end function

  !> Evaluates the table at (x_1, x_2) in reduced units.
  function gkt_ternary_table_evaluate_reduced(table, fraction_1, fraction_2, out) result(status)
    type(gkt_ternary_table), intent(in) :: table
    real(c_double), intent(in) :: fraction_1, fraction_2
    type(gkt_ternary_transport), intent(out) :: out
    integer(c_int) :: status
    status = c_ternary_table_evaluate_reduced(table%handle, fraction_1, fraction_2, out)
  end function

  !> Evaluates the table at (x_1, x_2) and packing fraction phi in reduced units (phi = 0 for a dilute
  !> table, in [0, max_packing_fraction] for a dense one).
  function gkt_ternary_table_evaluate_reduced_dense(table, fraction_1, fraction_2, packing_fraction, out) &
      result(status)
    type(gkt_ternary_table), intent(in) :: table
    real(c_double), intent(in) :: fraction_1, fraction_2, packing_fraction
    type(gkt_ternary_transport), intent(out) :: out
    integer(c_int) :: status
    status = c_ternary_table_evaluate_reduced_dense(table%handle, fraction_1, fraction_2, packing_fraction, out)
  end function

  !> Computes the dilute first-Sonine set in reduced units at the size(alpha) restitutions alpha(i)
  !> into out(i), equal to gkt_first_sonine_values cell by cell; every alpha is checked first (the
  !> message of a bad one names its index, from 0) and on a refusal out is left as it was.
  function gkt_first_sonine_values_cells(dimension, alpha, out) result(status)
    integer(c_int), intent(in) :: dimension
    real(c_double), intent(in) :: alpha(:)
    type(gkt_first_sonine), intent(inout) :: out(size(alpha))
    integer(c_int) :: status
    status = c_first_sonine_values_cells(dimension, int(size(alpha), c_size_t), alpha, out)
  end function

  !> Computes the dense first-Sonine set in reduced units at the size(alpha) states (alpha(i),
  !> packing_fraction(i)) into out(i), equal to gkt_enskog_first_sonine_values cell by cell; every
  !> cell is checked first (the message names its index, from 0), out left as it was on a refusal.
  function gkt_enskog_first_sonine_values_cells(dimension, alpha, packing_fraction, out) result(status)
    integer(c_int), intent(in) :: dimension
    real(c_double), intent(in) :: alpha(:), packing_fraction(size(alpha))
    type(gkt_enskog_first_sonine), intent(inout) :: out(size(alpha))
    integer(c_int) :: status
    status = c_enskog_first_sonine_values_cells(dimension, int(size(alpha), c_size_t), alpha, packing_fraction, out)
  end function

  !> Evaluates the table at mole fraction x_1 and packing fraction phi in reduced units.
  function gkt_binary_table_evaluate_reduced(table, fraction_1, packing_fraction, out) result(status)
    type(gkt_binary_table), intent(in) :: table
    real(c_double), intent(in) :: fraction_1, packing_fraction
    type(gkt_binary_transport), intent(out) :: out
    integer(c_int) :: status
    status = c_binary_table_evaluate_reduced(table%handle, fraction_1, packing_fraction, out)
  end function

end module gkt
