! zener_sym.f90: Fortran 2003 bindings (bind(C)) of the C99 kernels in generated/c/zener_sym.h.
!
! Compile generated/c/zener_sym.c with a C compiler and this module with your Fortran code:
!     cc -std=c99 -O2 -c zener_sym.c
!     gfortran -O2 -c zener_sym.f90 && gfortran my_code.f90 zener_sym.o -lm
! Arguments are the dimensionless quantities of Zener's equation (10) (lam = lambda, tau, delta);
! every function returns ZS_EDOM and NaN outputs for an input outside its range, as in C.
! Outputs are arrays the caller allocates (n elements); every one is written.
module zener_sym
  use, intrinsic :: iso_c_binding, only: c_double, c_int, c_size_t
  implicit none
  private
  public :: zs_summary_t, zs_summary, zs_history, zs_lam_for_e, zs_ham0_history, &
            zs_ham1_history, zs_ham1_summary
  integer(c_int), parameter, public :: ZS_DELTA = 0, ZS_FORCE = 1, ZS_OK = 0, ZS_EDOM = 1

  ! the C struct zs_summary_t, field for field
  type, bind(C) :: zs_summary_t
    real(c_double) :: lam, delta_m, tau_dc, tau_d, tau_dr, eta, e, F_m, impulse, int_F2, xi
  end type

  interface
    integer(c_int) function zs_summary(lam, contact_end, out) bind(C, name="zs_summary")
      import :: c_double, c_int, zs_summary_t
      real(c_double), value :: lam
      integer(c_int), value :: contact_end
      type(zs_summary_t), intent(out) :: out
    end function

    integer(c_int) function zs_history(lam, contact_end, n, tau, delta, velocity, force, &
                                       impulse) bind(C, name="zs_history")
      import :: c_double, c_int, c_size_t
      real(c_double), value :: lam
      integer(c_int), value :: contact_end
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: tau(*)
      real(c_double), intent(out) :: delta(*), velocity(*), force(*), impulse(*)
    end function

    real(c_double) function zs_lam_for_e(e, contact_end) bind(C, name="zs_lam_for_e")
      import :: c_double, c_int
      real(c_double), value :: e
      integer(c_int), value :: contact_end
    end function

    integer(c_int) function zs_ham0_history(lam, n, tau, delta, force) &
        bind(C, name="zs_ham0_history")
      import :: c_double, c_int, c_size_t
      real(c_double), value :: lam
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: tau(*)
      real(c_double), intent(out) :: delta(*), force(*)
    end function

    integer(c_int) function zs_ham1_history(lam, n, tau, delta, force) &
        bind(C, name="zs_ham1_history")
      import :: c_double, c_int, c_size_t
      real(c_double), value :: lam
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: tau(*)
      real(c_double), intent(out) :: delta(*), force(*)
    end function

    integer(c_int) function zs_ham1_summary(lam, out) bind(C, name="zs_ham1_summary")
      import :: c_double, c_int, zs_summary_t
      real(c_double), value :: lam
      type(zs_summary_t), intent(out) :: out
    end function
  end interface
end module zener_sym
