! The dilute ternary table through the Fortran module (fortran/gkt.f90): built from alpha(3, 3),
! the physical set equals the reduced one times the values at T = n = 1 scaled as gkt.h says
! (p = nT), a state off the triangle is refused naming fraction_2, and the build cost is reported.
program ternary_test
  use, intrinsic :: iso_c_binding, only: c_int, c_double
  use gkt
  implicit none
  type(gkt_ternary_table) :: table
  type(gkt_ternary_transport) :: physical, reduced, unit
  real(c_double) :: alpha(3, 3), error, seconds
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
