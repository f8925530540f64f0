! The ternary table through the Fortran module (fortran/gkt.f90): built from alpha(3, 3), the
! physical set equals the reduced one times the values at T = n = 1 scaled as gkt.h says (p = nT), a
! state off the triangle is refused naming fraction_2, and the build cost is reported. The dense table
! (gkt_ternary_table_create_dense, phi in [0, 0.1]) carries the dense coefficients (p* > 1, kappa_b > 0),
! its physical p is p* nT, a state above phi_max and a phi outside [0, 0.1] are GKT_OUT_OF_RANGE, and a
! tolerance it cannot meet (the order-1 pole of a 10:1 mass ratio, no refinement; dilute through the
! same call, as the refusal of a dense table costs ~20 s of splitting) is refused in one line.
program ternary_test
  use, intrinsic :: iso_c_binding, only: c_int, c_double
  use gkt
  implicit none
  type(gkt_ternary_table) :: table, dense
  type(gkt_binary_table) :: about
  type(gkt_ternary_transport) :: physical, reduced, unit
  real(c_double) :: alpha(3, 3), dense_alpha(3, 3), error, seconds, n
  integer(c_int) :: pieces, solves
  integer :: failures
  character(len=:), allocatable :: message

  failures = 0
  alpha = reshape([0.9_c_double, 0.85_c_double, 0.75_c_double, 0.85_c_double, 0.8_c_double, 0.8_c_double, &
                   0.75_c_double, 0.8_c_double, 0.7_c_double], [3, 3])
  call check(gkt_ternary_table_create(3_c_int, [1.0_c_double, 2.0_c_double, 3.5_c_double], &
                                      [1.0_c_double, 1.3_c_double, 0.8_c_double], alpha, 1_c_int, 5_c_int, &
                                      5e-2_c_double, table) == GKT_OK, 'create')
  call check(gkt_ternary_table_interpolation_error(table, error) == GKT_OK .and. error <= 5e-2_c_double, 'error')
  call check(gkt_ternary_table_build_cost(table, pieces, solves, seconds) == GKT_OK .and. pieces >= 1 .and. &
             solves >= 25, 'build cost')
  call check(gkt_ternary_table_evaluate_reduced(table, 0.2_c_double, 0.5_c_double, reduced) == GKT_OK, 'reduced')
  call check(gkt_ternary_table_evaluate(table, 0.2_c_double, 0.5_c_double, 1.0_c_double, 1.0_c_double, unit) == GKT_OK, &
             'unit state')
  call check(gkt_ternary_table_evaluate(table, 0.2_c_double, 0.5_c_double, 4.0_c_double, 1.0_c_double, physical) &
             == GKT_OK, 'physical')
  ! At fixed T, eta does not depend on n, D_ij scales as n * D0 with D0 ~ 1/n, zeta as n.
  call check(abs(physical%shear_viscosity - unit%shear_viscosity) <= 1e-14_c_double * unit%shear_viscosity, 'eta(n)')
  call check(abs(physical%cooling_rate - 4 * unit%cooling_rate) <= 1e-14_c_double * abs(physical%cooling_rate), 'zeta(n)')
  call check(abs(physical%pressure - 4) <= 1e-15_c_double, 'p = nT')
  call check(abs(reduced%pressure - 1) <= 0 .and. reduced%temperature_ratio(3) > 0, 'reduced set')
  call check(gkt_ternary_table_evaluate(table, 0.6_c_double, 0.5_c_double, 1.0_c_double, 1.0_c_double, physical) &
             == GKT_INVALID_ARGUMENT, 'off the triangle refused')
  message = gkt_last_error()
  call check(index(message, 'fraction_2:') == 1, 'field named: ' // message)
  call gkt_ternary_table_destroy(table)
  deallocate (message)

  dense_alpha = reshape([0.9_c_double, 0.85_c_double, 0.8_c_double, 0.85_c_double, 0.8_c_double, 0.8_c_double, &
                         0.8_c_double, 0.8_c_double, 0.85_c_double], [3, 3])
  call check(gkt_ternary_table_create_dense(3_c_int, [1.0_c_double, 1.2_c_double, 1.4_c_double], &
                                            [1.0_c_double, 1.1_c_double, 0.95_c_double], dense_alpha, 1_c_int, &
                                            3_c_int, 3_c_int, 5e-2_c_double, 0.1_c_double, 3_c_int, dense) == GKT_OK, &
             'create dense')
  call check(gkt_ternary_table_interpolation_error(dense, error) == GKT_OK .and. error <= 5e-2_c_double, 'dense error')
  call check(gkt_ternary_table_evaluate_reduced_dense(dense, 0.2_c_double, 0.5_c_double, 0.07_c_double, reduced) &
             == GKT_OK, 'dense reduced')
  call check(reduced%pressure > 1.1_c_double .and. reduced%bulk_viscosity > 0 .and. &
             abs(reduced%cooling_rate_first_order) > 0, 'dense set')
  ! phi = n v_d sum_i x_i sigma_i^3 (3D: v_d = pi/6) = 0.07.
  n = 0.07_c_double / (acos(-1.0_c_double) / 6 * (0.2_c_double + 0.5_c_double * 1.1_c_double**3 + &
                                                  0.3_c_double * 0.95_c_double**3))
  call check(gkt_ternary_table_evaluate(dense, 0.2_c_double, 0.5_c_double, n, 2.0_c_double, physical) == GKT_OK, &
             'dense physical')
  call check(abs(physical%pressure - reduced%pressure * n * 2) <= 1e-12_c_double * n * 2, 'p = p* n T')
  call check(gkt_ternary_table_evaluate(dense, 0.2_c_double, 0.5_c_double, 2 * n, 2.0_c_double, physical) &
             == GKT_OUT_OF_RANGE, 'above phi_max refused')
  message = gkt_last_error()
  call check(index(message, 'number_density: the packing fraction') == 1, 'field named: ' // message)
  deallocate (message)
  call check(gkt_ternary_table_evaluate_reduced_dense(dense, 0.2_c_double, 0.5_c_double, 0.3_c_double, reduced) &
             == GKT_OUT_OF_RANGE, 'bad phi refused')
  message = gkt_last_error()
  call check(index(message, 'packing_fraction: must be in [0, 0.1]') == 1, 'field named: ' // message)
  deallocate (message)
  call gkt_ternary_table_destroy(dense)
  call check(gkt_ternary_table_create_dense(3_c_int, [1.0_c_double, 10.0_c_double, 1.0_c_double], &
                                            [1.0_c_double, 1.0_c_double, 1.0_c_double], &
                                            reshape([(0.8_c_double, pieces = 1, 9)], [3, 3]), 1_c_int, 3_c_int, &
                                            3_c_int, 5e-2_c_double, 0.0_c_double, 3_c_int, dense) &
             == GKT_INVALID_ARGUMENT, 'unmet tolerance refused')
  message = gkt_last_error()
  call check(index(message, 'tolerance: the interpolation error ') == 1 .and. index(message, new_line('a')) == 0, &
             'one-line refusal: ' // message)
  deallocate (message)

  ! About the cumulant HCS (gkt_*_table_create_about): identical species build (their values do not depend on x_1),
  ! an unknown reference is refused naming it.
  call check(gkt_binary_table_create_about(3_c_int, [1.0_c_double, 1.0_c_double], [1.0_c_double, 1.0_c_double], &
                                           reshape([(0.7_c_double, pieces = 1, 4)], [2, 2]), 1_c_int, 3_c_int, &
                                           0.0_c_double, 3_c_int, 1e-9_c_double, [0.0_c_double, 1.0_c_double], &
                                           'nonlinear', 2_c_int, about) == GKT_OK, 'create about the HCS')
  call check(gkt_binary_table_interpolation_error(about, error) == GKT_OK .and. error <= 1e-9_c_double, 'about error')
  call gkt_binary_table_destroy(about)
  call check(gkt_ternary_table_create_about(3_c_int, [1.0_c_double, 2.0_c_double, 3.5_c_double], &
                                            [1.0_c_double, 1.3_c_double, 0.8_c_double], alpha, 1_c_int, 3_c_int, &
                                            3_c_int, 5e-2_c_double, 0.0_c_double, 3_c_int, 'hcs', 2_c_int, dense) &
             == GKT_INVALID_ARGUMENT, 'unknown reference refused')
  message = gkt_last_error()
  call check(index(message, 'reference: must be') == 1, 'field named: ' // message)
  deallocate (message)

  if (failures > 0) then
    print '(a, i0, a)', 'ternary_test: ', failures, ' check(s) failed'
    error stop 1
  end if
  print '(a)', 'ternary_test: ok'

contains

  subroutine check(condition, what)
    logical, intent(in) :: condition
    character(len=*), intent(in) :: what
    if (.not. condition) then
      print '(a)', 'check failed: ' // what
      failures = failures + 1
    end if
  end subroutine

end program
