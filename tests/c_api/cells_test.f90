! The batched one-component calls through the Fortran module (fortran/gkt.f90): 64 cells equal the
! single-cell calls bit for bit, and a bad cell is refused naming its index from 0 with out untouched; the rough
! model's product-space caveat reaches Fortran through gkt_last_warnings.
program cells_test
  use, intrinsic :: iso_c_binding, only: c_int, c_double
  use, intrinsic :: iso_fortran_env, only: int64
  use gkt
  implicit none
  integer, parameter :: cells = 64
  real(c_double) :: alpha(cells), phi(cells)
  type(gkt_first_sonine) :: v(cells), one, sentinel(cells)
  type(gkt_enskog_first_sonine) :: e(cells), e_one
  type(gkt_model) :: rough
  type(gkt_coefficient) :: eta
  integer :: i, failures
  character(len=:), allocatable :: message

  failures = 0
  do i = 1, cells
    alpha(i) = 0.1_c_double + 0.9_c_double * real(i - 1, c_double) / real(cells - 1, c_double)
    phi(i) = 0.45_c_double * real(mod(7 * i, cells), c_double) / real(cells, c_double)
  end do
  call check(gkt_first_sonine_values_cells(3_c_int, alpha, v) == GKT_OK, 'first_sonine cells')
  call check(gkt_enskog_first_sonine_values_cells(3_c_int, alpha, phi, e) == GKT_OK, 'enskog cells')
  do i = 1, cells
    call check(gkt_first_sonine_values(3_c_int, alpha(i), one) == GKT_OK, 'first_sonine single')
    call check(all(transfer(one, [0_int64]) == transfer(v(i), [0_int64])), 'first_sonine equal')
    call check(gkt_enskog_first_sonine_values(3_c_int, alpha(i), phi(i), e_one) == GKT_OK, 'enskog single')
    call check(all(transfer(e_one, [0_int64]) == transfer(e(i), [0_int64])), 'enskog equal')
  end do

  sentinel = gkt_first_sonine(-7, -7, -7, -7, -7)
  v = sentinel
  phi(33) = 0.6_c_double
  call check(gkt_enskog_first_sonine_values_cells(3_c_int, alpha, phi, e) == GKT_INVALID_ARGUMENT, 'phi refused')
  message = gkt_last_error()
  call check(index(message, 'packing_fraction[32]:') == 1, 'index named: ' // message)
  alpha(40) = 2
  call check(gkt_first_sonine_values_cells(2_c_int, alpha, v) == GKT_INVALID_ARGUMENT, 'alpha refused')
  message = gkt_last_error()
  call check(index(message, 'alpha[39]:') == 1, 'index named: ' // message)
  call check(all(transfer(v, [0_int64]) == transfer(sentinel, [0_int64])), 'out untouched')
  call check(gkt_model_create('rough', rough) == GKT_OK, 'rough model')
  call check(gkt_model_evaluate(rough, 'shear_viscosity', 2_c_int, eta) == GKT_OK, 'rough order 2')
  message = gkt_last_warnings()
  call check(index(message, 'trial_space: the _error of shear_viscosity') == 1, 'caveat: ' // message)
  call check(gkt_model_evaluate(rough, 'shear_viscosity', 1_c_int, eta) == GKT_OK, 'rough order 1')
  message = gkt_last_warnings()
  call check(len(message) == 0, 'no caveat at order 1: ' // message)
  call gkt_model_destroy(rough)
  deallocate (message)  ! main-program variables are never freed implicitly: LeakSanitizer would report it

  if (failures > 0) then
    print '(a, i0, a)', 'cells_test: ', failures, ' check(s) failed'
    error stop 1
  end if
  print '(a)', 'cells_test: ok'

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
