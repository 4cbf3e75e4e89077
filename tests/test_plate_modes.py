"""The bounded plate's modes (zener_sym.plate.modes) against independent routes: mpmath roots of
the unscaled Bessel frequency equations at 40 digits, mpmath quadrature of the mode shapes for
the modal mass, published frequency parameters, Timoshenko's static deflection coefficient, a
brute-force enumeration of the Navier modes, and the infinite plate's admittance (Zener's
dashpot lambda) as the plate grows."""
from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest

from zener_sym.plate.modal import ModalPlate
from zener_sym.plate.modes import (MAX_MODES, dimensionless_modes, modal_plate,
                                   plate_constants)

CIRCLE = ("clamped", "simply-supported")


def _mp_root(support: str, nu: float, n: int) -> mpmath.mpf:
    """The n-th root of the unscaled frequency equation (30 digits), in the ratio form of the
    boundary conditions (the package solves a scaled product form), bracketed by mpmath's own
    Bessel zeros: clamped J1/J0 = -I1/I0 in (-1, 0) between j_{0,n} and j_{1,n}; simply
    supported J1/J0 > 0 between j_{1,n-1} and j_{0,n}."""
    with mpmath.workdps(30):
        J = lambda k, x: mpmath.besselj(k, x)  # noqa: E731
        I = lambda k, x: mpmath.besseli(k, x)  # noqa: E731,E741
        # W = J0(kr) + C I0(kr), W(b) = 0, and W'(b) = 0 (clamped) or the radial moment
        # W'' + nu W'/r = 0 at r = b (simply supported)
        rhs = 0 if support == "clamped" else 2 / (1 - mpmath.mpf(nu))
        f = lambda x: J(1, x) / J(0, x) + I(1, x) / I(0, x) - rhs * x  # noqa: E731
        eps = mpmath.mpf(10) ** -15
        if support == "clamped":
            a, b = mpmath.besseljzero(0, n) + eps, mpmath.besseljzero(1, n)
        else:
            a = mpmath.besseljzero(1, n - 1) if n > 1 else mpmath.mpf("0.1")
            b = mpmath.besseljzero(0, n) - eps
        fa = f(a)
        assert fa * f(b) < 0
        for _ in range(64):  # bisection (to pi 2^-64): slow, but it cannot leave the bracket
            mid = (a + b) / 2
            if f(mid) * fa > 0:
                a = mid
            else:
                b = mid
        return (a + b) / 2


def test_clamped_circle_published_frequencies():
    # Leissa, Vibration of Plates (1969), Table 2.1: (k b)^2 of the clamped circle
    Omega, _ = dimensionless_modes(3, support="clamped")
    assert np.allclose(Omega, [10.2158, 39.771, 89.104], rtol=2e-5)


def test_simply_supported_circle_frequencies():
    # Leissa (1969) Table 2.3, nu = 0.3: 4.935, 29.72, 74.16. (The figures 4.977 and 29.76
    # belong to nu near 1/3: mpmath gives 4.984 and 29.758 there.)
    Omega, _ = dimensionless_modes(3, support="simply-supported", nu=0.3)
    assert np.allclose(Omega, [4.935, 29.72, 74.16], rtol=2e-4)
    third, _ = dimensionless_modes(2, support="simply-supported", nu=1 / 3)
    assert np.allclose(third, [4.984, 29.758], rtol=2e-4)


@pytest.mark.parametrize("support,nu", [("clamped", 0.3), ("simply-supported", 0.3),
                                        ("simply-supported", -0.9), ("simply-supported", 0.49)])
def test_circle_roots_against_mpmath_up_to_thousands(support, nu):
    n = 3000
    Omega, _ = dimensionless_modes(n, support=support, nu=nu)
    x = np.sqrt(Omega)
    for i in (0, 1, 99, 2999):
        ref = _mp_root(support, nu, i + 1)
        assert abs(x[i] - float(ref)) <= 4e-15 * float(ref), (i, x[i], ref)
    gaps = np.diff(x)[1:]  # consecutive roots pi apart, asymptotically
    assert np.all(gaps > 0.9 * np.pi) and np.all(gaps < 1.1 * np.pi)


@pytest.mark.parametrize("support", CIRCLE)
def test_no_root_missed(support):
    """Count the sign changes of the unscaled equation on a fine grid: one root per mode."""
    Omega, _ = dimensionless_modes(40, support=support, nu=0.3)
    x = np.linspace(0.05, math.sqrt(Omega[-1]) + 0.5, 200_001)
    from scipy import special
    j0, j1, i0, i1 = special.j0(x), special.j1(x), special.i0e(x), special.i1e(x)
    if support == "clamped":
        g = j0 * i1 + j1 * i0
    else:
        g = 0.7 * (j1 * i0 + j0 * i1) - 2 * x * j0 * i0
    assert np.count_nonzero(np.diff(np.sign(g)) != 0) == 40


@pytest.mark.parametrize("support,nu", [("clamped", 0.3), ("simply-supported", 0.3),
                                        ("simply-supported", 0.0)])
def test_circle_participation_by_quadrature(support, nu):
    """psi = W(0)^2 b^2 / int_0^b 2 pi r W^2 dr, the modal mass by mpmath quadrature of the
    mode shape W = J0(kr) - (J0(kb)/I0(kb)) I0(kr) (not the closed Lommel form)."""
    Omega, psi = dimensionless_modes(4, support=support, nu=nu)
    with mpmath.workdps(30):
        for O, p in zip(Omega, psi):
            x = mpmath.sqrt(O)
            C = -mpmath.besselj(0, x) / mpmath.besseli(0, x)
            W = lambda r: mpmath.besselj(0, x * r) + C * mpmath.besseli(0, x * r)  # noqa: E731
            M = mpmath.quad(lambda r: 2 * mpmath.pi * r * W(r) ** 2, [0, 0.5, 1])
            assert abs(p - float(W(0) ** 2 / M)) <= 1e-12 * p


def _circle_tail(support: str, nu: float, Omega: np.ndarray) -> float:
    """sum_{n > N} psi_n / Omega_n^2 from the asymptotics psi_n ~ x_n / 2, x_n spaced by pi:
    int_{x_N + pi/2}^inf (x/2) x^-4 dx / pi (the static tail the package leaves to C_res)."""
    xe = math.sqrt(Omega[-1]) + math.pi / 2
    return 1.0 / (4.0 * math.pi * xe**2)


@pytest.mark.parametrize("support,nu", [("clamped", 0.3), ("simply-supported", 0.3),
                                        ("simply-supported", -0.5), ("simply-supported", 0.45)])
def test_static_compliance_is_the_modal_sum(support, nu):
    """The closed forms b^2/(16 pi D) and (3 + nu) b^2/(16 pi (1 + nu) D) (Timoshenko's plate
    under a central point load) against the modal sum of psi/Omega^2 plus its tail."""
    Omega, psi = dimensionless_modes(20000, support=support, nu=nu)
    S = plate_constants(support=support, nu=nu).S
    closed = 1 / (16 * math.pi) if support == "clamped" else (3 + nu) / (16 * math.pi * (1 + nu))
    assert S == pytest.approx(closed, rel=1e-14)
    total = float(np.sum(psi / Omega**2)) + _circle_tail(support, nu, Omega)
    assert total == pytest.approx(closed, rel=1e-10)


def _navier(n: int, s: float, xi: float, eta: float):
    """Brute force: every (m, k) below a generous bound, Omega and psi from their definitions."""
    m, k = np.meshgrid(np.arange(1, 400.0), np.arange(1, 400.0), indexing="ij")
    Omega = np.pi**2 * (m**2 / s + k**2 * s)
    psi = 4 * np.sin(m * np.pi * xi) ** 2 * np.sin(k * np.pi * eta) ** 2
    keep = psi > 1e-20
    Omega, psi = Omega[keep], psi[keep]
    order = np.argsort(Omega, kind="stable")[:n]
    return Omega[order], psi[order]


@pytest.mark.parametrize("s,impact", [(1.0, (0.5, 0.5)), (2.0, (0.3, 0.6)),
                                      (0.37, (1 / 3, 0.25)), (1.0, (0.1, 0.77))])
def test_rectangle_modes_by_enumeration(s, impact):
    Omega, psi = dimensionless_modes(300, shape="rectangle", support="simply-supported",
                                     aspect=s, impact=impact)
    ref_O, ref_p = _navier(300, s, *impact)
    assert np.allclose(Omega, ref_O, rtol=1e-13)
    # ties (equal Omega) may come in another order: compare psi within each frequency
    for O in np.unique(np.round(ref_O, 6)):
        a = np.sort(psi[np.isclose(Omega, O, rtol=1e-10)])
        b = np.sort(ref_p[np.isclose(ref_O, O, rtol=1e-10)])
        assert np.allclose(a, b, rtol=1e-12)


def test_rectangle_centre_has_odd_modes_only():
    Omega, psi = dimensionless_modes(8, shape="rectangle", support="simply-supported")
    assert np.allclose(Omega / np.pi**2, [2, 10, 10, 18, 26, 26, 34, 34])
    assert np.allclose(psi, 4.0)


def test_rectangle_static_compliance():
    # Timoshenko & Woinowsky-Krieger, Table 23: w = 0.01160 P a^2 / D at a square's centre
    assert plate_constants(shape="rectangle", support="simply-supported").S == \
        pytest.approx(0.01160, abs=5e-6)
    S = plate_constants(shape="rectangle", support="simply-supported", aspect=2.0,
                        impact=(0.3, 0.6)).S
    # the same plate turned by 90 degrees
    S_turned = plate_constants(shape="rectangle", support="simply-supported", aspect=0.5,
                               impact=(0.6, 0.3)).S
    assert S == pytest.approx(S_turned, rel=1e-13)
    # the double series by brute force, its tail by the integral of psi/Omega^2 with mean psi = 1
    # over the modes beyond the bound (mode density 1/(4 pi) in Omega)
    m, k = np.meshgrid(np.arange(1, 3001.0), np.arange(1, 3001.0), indexing="ij")
    Omega = np.pi**2 * (m**2 / 2.0 + k**2 * 2.0)
    psi = 4 * np.sin(m * np.pi * 0.3) ** 2 * np.sin(k * np.pi * 0.6) ** 2
    inside = Omega < np.pi**2 * 2999**2 / 2
    total = float(np.sum(psi[inside] / Omega[inside] ** 2))
    total += 1.0 / (4 * np.pi * np.pi**2 * 2999**2 / 2)
    assert S == pytest.approx(total, rel=1e-6)


@pytest.mark.parametrize("kw", [dict(support="clamped"), dict(support="simply-supported"),
                                dict(shape="rectangle", support="simply-supported"),
                                dict(shape="rectangle", support="simply-supported", aspect=1.7,
                                     impact=(0.31, 0.42))])
def test_large_plate_is_zeners_dashpot(kw):
    """As beta -> 0 the plate's admittance at the impact point, Y(p) = sum_n c_n p/(p^2 +
    omega_n^2) (the Laplace transform of the modal kernel sum c_n cos(omega_n tau)), tends to
    Zener's dashpot lambda (Eq. 10), for every shape and support."""
    lam = 1.3
    for beta, tol in ((1e-3, 0.05), (1e-4, 0.015)):
        plate = modal_plate(lam, beta, n_modes=40000, **kw)
        p = 1.0
        Y = float(np.sum(plate.c * p / (p**2 + plate.omega**2)))
        assert Y == pytest.approx(lam, rel=tol), (beta, Y)


def test_modal_plate_scales():
    Omega, psi = dimensionless_modes(50, support="simply-supported", nu=0.25)
    p = modal_plate(0.7, 0.02, support="simply-supported", n_modes=50, nu=0.25)
    assert isinstance(p, ModalPlate) and p.shape == "circle" and p.support == "simply-supported"
    assert np.allclose(p.omega, 0.02 * Omega, rtol=1e-15)
    assert np.allclose(p.c, 8 * 0.7 * 0.02 * psi, rtol=1e-15)
    assert p.static == pytest.approx(8 * 0.7 * (3.25 / (16 * math.pi * 1.25)) / 0.02, rel=1e-14)
    more = modal_plate(0.7, 0.02, support="simply-supported", n_modes=500, nu=0.25)
    assert 0 < more.residual < p.residual


def test_plate_constants():
    c = plate_constants(support="simply-supported", nu=0.3)
    assert c.Omega1 == pytest.approx(4.935, rel=1e-4)
    r = plate_constants(shape="rectangle", support="simply-supported", aspect=2.0)
    assert r.Omega1 == pytest.approx(np.pi**2 * (1 / 2 + 2), rel=1e-14)


@pytest.mark.parametrize("kw,match", [
    (dict(support="pinned"), "unknown support 'pinned'; allowed: 'clamped', 'simply-supported'"),
    (dict(support="clamped", shape="square"), "unknown shape 'square'"),
    (dict(support="clamped", shape="rectangle"), "only 'simply-supported'"),
    (dict(support="clamped", impact=(0.9, 0.9)), "outside the circle"),
    (dict(support="clamped", impact=(0.6, 0.5)), "centre"),
    (dict(support="clamped", aspect=2.0), "a circle has none"),
    (dict(shape="rectangle", support="simply-supported", impact=(1.2, 0.5)),
     "outside the plate"),
    (dict(shape="rectangle", support="simply-supported", impact=(0.0, 0.5)),
     "outside the plate"),
    (dict(shape="rectangle", support="simply-supported", impact=(0.5,)), "a pair"),
    (dict(shape="rectangle", support="simply-supported", aspect=-1.0), "aspect"),
    (dict(shape="rectangle", support="simply-supported", aspect=2e3), r"0.001 <= a/b <= 1000"),
    (dict(shape="rectangle", support="simply-supported", impact=(0.5, 1e-5)),
     r"0.0001 <= x/a, y/b <= 0.9999"),
    (dict(support="simply-supported", nu=0.5), r"-1 < nu < 0.5"),
    (dict(support="simply-supported", nu=-1.0), r"-1 < nu < 0.5"),
    (dict(support="simply-supported", nu=float("nan")), r"-1 < nu < 0.5"),
    (dict(support="clamped", n_modes=0), f"1 <= n_modes <= {MAX_MODES}"),
    (dict(support="clamped", n_modes=MAX_MODES + 1), f"1 <= n_modes <= {MAX_MODES}"),
    (dict(support="clamped", n_modes=2.5), "must be an integer"),
    (dict(support="clamped", n_modes=True), "must be an integer"),
])
def test_refusals(kw, match):
    kw = {"n_modes": 10, **kw}
    with pytest.raises(ValueError, match=match):
        modal_plate(1.0, 0.1, **kw)


@pytest.mark.parametrize("lam,beta", [(-1.0, 0.1), (float("inf"), 0.1), (1.0, 0.0),
                                      (1.0, float("nan")), ("1", 0.1)])
def test_refusals_lam_beta(lam, beta):
    with pytest.raises(ValueError, match="lam|beta"):
        modal_plate(lam, beta, support="clamped", n_modes=5)


def test_simply_supported_circle_near_nu_minus_one():
    """As nu -> -1 the first root falls to 0 as x^4 = 96 (1 + nu)/(5 + nu) (the series of the
    frequency equation, G = -(1 + nu) x + (5 + nu) x^5/96 + ...); the others stay put."""
    nu = -0.999999
    Omega, psi = dimensionless_modes(3, support="simply-supported", nu=nu)
    assert Omega[0] == pytest.approx(math.sqrt(96 * (1 + nu) / (5 + nu)), rel=1e-5)
    for i in (1, 2):
        assert math.sqrt(Omega[i]) == pytest.approx(float(_mp_root("simply-supported", nu, i + 1)),
                                                    rel=1e-13)
    assert np.all(psi > 0)
