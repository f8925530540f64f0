! A cell loop in the style of a two-fluid (Euler-Euler) solver such as MFIX: two solid phases of
! glass-like beads with their own diameters and material density, a restitution matrix, and per
! cell the solids volume fractions eps_s(1:2) and the granular temperature T. The binary's
! transport table is built once; each cell then costs one table evaluation through the C API.
!
! Usage: two_fluid_cells [SCENE.toml]
!   prints one CSV row per cell (state, reduced coefficients, physical coefficients) and, if a
!   path is given, writes the `gkt table` scene of the same binary there, so that
!   compare_with_gkt_table.py can recompute every cell with the command-line program.
program two_fluid_cells
  use, intrinsic :: iso_c_binding, only: c_int, c_double
  use gkt
  implicit none

  integer, parameter :: dp = c_double, cells = 6
  real(dp), parameter :: pi = 3.14159265358979323846_dp
  ! The solids phases: diameters (m), material density (kg/m^3) and the restitution matrix.
  real(dp), parameter :: diameter(2) = [1.0e-3_dp, 1.5e-3_dp], material_density = 2500.0_dp
  real(dp), parameter :: restitution(2, 2) = reshape([0.9_dp, 0.85_dp, 0.85_dp, 0.8_dp], [2, 2])
  real(dp), parameter :: max_packing = 0.4_dp
  integer(c_int), parameter :: order = 1, nodes = 12, packing_nodes = 8
  ! Per cell: solids volume fractions of the two phases and the granular temperature T (J, k_B = 1).
  real(dp), parameter :: eps_s(2, cells) = reshape([0.02_dp, 0.01_dp, 0.10_dp, 0.05_dp, 0.15_dp, 0.15_dp, &
                                                    0.05_dp, 0.20_dp, 0.25_dp, 0.05_dp, 0.00_dp, 0.12_dp], [2, cells])
  real(dp), parameter :: temperature(cells) = [1.0e-9_dp, 2.0e-9_dp, 5.0e-10_dp, 1.0e-9_dp, 3.0e-9_dp, 1.0e-9_dp]

  type(gkt_binary_table) :: table
  type(gkt_binary_transport) :: reduced, physical
  type(gkt_binary_transport) :: batch(cells)
  real(dp) :: mass(2), volume(2), number_density(2), n, x1, phi, error, batch_x1(cells), batch_n(cells)
  integer :: cell
  integer(c_int) :: intervals, solves
  real(dp) :: seconds
  character(len=4096) :: scene

  volume = pi / 6 * diameter**3
  mass = material_density * volume
  call check(gkt_binary_table_create(3_c_int, mass, diameter, restitution, order, nodes, max_packing, packing_nodes, &
                                     table), "gkt_binary_table_create")
  call check(gkt_binary_table_interpolation_error(table, error), "gkt_binary_table_interpolation_error")
  write (*, '(a, es10.3)') '# gkt ' // gkt_version() // ', binary table interpolation error ', error
  call check(gkt_binary_table_build_cost(table, intervals, solves, seconds), "gkt_binary_table_build_cost")
  write (*, '(a, i0, a, i0, a, f0.2, a)') '# built on ', intervals, ' x_1 interval(s) with ', solves, &
    ' mixture solves in ', seconds, ' s'

  if (command_argument_count() >= 1) then
    call get_command_argument(1, scene)
    call write_scene(trim(scene), mass)
  end if

  write (*, '(a)') 'cell,fraction_1,fraction_2,packing_fraction,number_density,temperature,' // &
    'shear_viscosity,thermal_conductivity,cooling_rate,temperature_ratio_1,temperature_ratio_2,' // &
    'mutual_diffusion_1_1,mutual_diffusion_1_2,mutual_diffusion_2_1,mutual_diffusion_2_2,' // &
    'thermal_diffusion_1,thermal_diffusion_2,dufour_1,dufour_2,pressure,bulk_viscosity,cooling_rate_first_order,' // &
    'eta,lambda,zeta,D_11,D_12,D_21,D_22,D_T_1,D_T_2,D_dufour_1,D_dufour_2,p,bulk'
  do cell = 1, cells
    ! The cell's state as the solver holds it, turned into (x_1, n, T) and phi.
    number_density = eps_s(:, cell) / volume
    n = sum(number_density)
    x1 = number_density(1) / n
    phi = sum(eps_s(:, cell))
    call check(gkt_binary_table_evaluate(table, x1, n, temperature(cell), physical), "gkt_binary_table_evaluate")
    call check(gkt_binary_table_evaluate_reduced(table, x1, phi, reduced), "gkt_binary_table_evaluate_reduced")
    write (*, '(i0, 34(",", es25.17e3))') cell, x1, 1 - x1, phi, n, temperature(cell), &
      reduced%shear_viscosity, reduced%thermal_conductivity, reduced%cooling_rate, reduced%temperature_ratio, &
      reduced%mutual_diffusion, reduced%thermal_diffusion, reduced%dufour, reduced%pressure, &
      reduced%bulk_viscosity, reduced%cooling_rate_first_order, &
      physical%shear_viscosity, physical%thermal_conductivity, physical%cooling_rate, physical%mutual_diffusion, &
      physical%thermal_diffusion, physical%dufour, physical%pressure, physical%bulk_viscosity
  end do
  ! The same cells in one call over the solver's arrays: value for value the loop's results.
  do cell = 1, cells
    number_density = eps_s(:, cell) / volume
    batch_n(cell) = sum(number_density)
    batch_x1(cell) = number_density(1) / batch_n(cell)
  end do
  call check(gkt_binary_table_evaluate_cells(table, batch_x1, batch_n, temperature, batch), &
             "gkt_binary_table_evaluate_cells")
  do cell = 1, cells
    call check(gkt_binary_table_evaluate(table, batch_x1(cell), batch_n(cell), temperature(cell), physical), &
               "gkt_binary_table_evaluate")
    if (abs(physical%shear_viscosity - batch(cell)%shear_viscosity) > 0 .or. &
        any(abs(physical%mutual_diffusion - batch(cell)%mutual_diffusion) > 0)) then
      write (*, '(a, i0)') 'two_fluid_cells: the batch differs from the cell loop at cell ', cell
      error stop 1
    end if
  end do
  call gkt_binary_table_destroy(table)

contains

  !> Stops with the C API's message unless status is GKT_OK.
  subroutine check(status, what)
    integer(c_int), intent(in) :: status
    character(len=*), intent(in) :: what
    if (status /= GKT_OK) then
      write (*, '(a)') 'two_fluid_cells: ' // what // ': ' // gkt_last_error()
      error stop 1
    end if
  end subroutine

  !> Writes the `gkt table` scene of this binary (fractions and packing fraction set per cell).
  subroutine write_scene(path, mass)
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: mass(2)
    integer :: unit, i
    open (newunit=unit, file=path, status='replace', action='write')
    write (unit, '(a)') 'model = "mixture"'
    write (unit, '(a)') 'dimension = 3'
    write (unit, '(a, i0)') 'order = ', order
    write (unit, '(a)') 'hcs = "maxwellian"  # the transport table expands about the Maxwellian HCS'
    write (unit, '(2(a, es25.17e3), a)') 'alpha = [[', restitution(1, 1), ',', restitution(1, 2), '],'
    write (unit, '(2(a, es25.17e3), a)') '         [', restitution(2, 1), ',', restitution(2, 2), ']]'
    write (unit, '(a)') 'packing_fraction = 0'
    do i = 1, 2
      write (unit, '(a)') '[[species]]'
      write (unit, '(a, es25.17e3)') 'mass = ', mass(i)
      write (unit, '(a, es25.17e3)') 'diameter = ', diameter(i)
      write (unit, '(a)') 'fraction = 0.5'
    end do
    close (unit)
  end subroutine

end program two_fluid_cells
