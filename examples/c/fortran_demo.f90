! fortran_demo.f90: the C kernels called from Fortran through examples/c/zener_sym.f90.
!     cc -std=c99 -O2 -c zener_sym.c
!     gfortran -O2 zener_sym.f90 fortran_demo.f90 zener_sym.o -lm -o fortran_demo
! Prints, for lambda = 0.3 at both ends of contact, the summary, the history at four times and
! the lambda whose restitution is that summary's e (the inverse); then the first-order HAM
! summary and a call outside the range (ZS_EDOM).
program fortran_demo
  use, intrinsic :: iso_c_binding, only: c_double, c_int, c_size_t
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
  use zener_sym
  implicit none
  type(zs_summary_t) :: s
  real(c_double) :: tau(4), delta(4), velocity(4), force(4), impulse(4)
  integer(c_int) :: rc, ends(2)
  integer :: k, i

  ends = [ZS_DELTA, ZS_FORCE]
  do k = 1, 2
    rc = zs_summary(0.3_c_double, ends(k), s)
    write (*, '(a, i1, a, i1)') 'summary end ', ends(k), ' rc ', rc
    write (*, '(11es25.16e3)') s%lam, s%delta_m, s%tau_dc, s%tau_d, s%tau_dr, s%eta, s%e, &
                               s%F_m, s%impulse, s%int_F2, s%xi
    tau = [0.25_c_double, 0.5_c_double, 1.0_c_double, 2.0_c_double] * s%tau_dc
    rc = zs_history(0.3_c_double, ends(k), 4_c_size_t, tau, delta, velocity, force, impulse)
    write (*, '(a, i1)') 'history rc ', rc
    do i = 1, 4
      write (*, '(5es25.16e3)') tau(i), delta(i), velocity(i), force(i), impulse(i)
    end do
    write (*, '(a, es25.16e3)') 'lam_for_e ', zs_lam_for_e(s%e, ends(k))
  end do
  rc = zs_ham1_summary(0.3_c_double, s)
  write (*, '(a, i1, 2es25.16e3)') 'ham1 rc ', rc, s%e, s%tau_d
  rc = zs_summary(-1.0_c_double, ZS_DELTA, s)
  write (*, '(a, i1, a, l1)') 'outside rc ', rc, ' e is NaN ', ieee_is_nan(s%e)
end program fortran_demo
