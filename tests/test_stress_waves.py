"""Hunter's and Reed's half-space stress-wave loss (derivation/stress_waves.py,
scene/stress_waves.py, Fig. 14), each against a route computed here.

The independent routes: the half-space constant h as the imaginary part of one contour integral
(no branch splitting, no Rayleigh residue), and the loss of Hunter's half-sine straight from the
frequency integral W = (1/pi) int omega Im G |F^|^2 d omega with the Hertz quantities in SI
units (Eqs. 3-5 and the Hertz energy balance), without the paper's scaling.
"""
import math
from pathlib import Path

import mpmath
import numpy as np
import pytest
from scipy.integrate import quad

import zener_sym as zs
from zener_sym.figures import data as D
from zener_sym.scene.stress_waves import PULSES, radiation_constant, stress_wave_k, stress_wave_loss

ROOT = Path(__file__).resolve().parents[1]
S, P = zs.TABLE1_SPHERE, zs.TABLE1_PLATE


def _h_contour(nu, depth=0.3, top=4.0):
    """Im int_0^inf K(s) ds, K = s a / (4 s^2 a b - (2 s^2 - 1)^2), a = sqrt(s^2 - c2^2/c1^2),
    b = sqrt(s^2 - 1), on s = x - i depth sin(pi x / top): below the real axis numpy's principal
    square roots are the outgoing branches, and the path passes below the Rayleigh pole. Beyond
    x = top the integrand is real."""
    k2 = (1 - 2 * nu) / (2 * (1 - nu))
    w = math.pi / top

    def f(x):
        s = complex(x, -depth * math.sin(w * x))
        a, b = np.sqrt(s * s - k2), np.sqrt(s * s - 1)
        return (s * a / (4 * s * s * a * b - (2 * s * s - 1) ** 2) * complex(1, -depth * w * math.cos(w * x))).imag

    return quad(f, 0.0, top, epsabs=0.0, epsrel=1e-12, limit=400)[0]


@pytest.mark.parametrize("nu", [-0.2, 0.0, 0.21, 0.25, 0.3, 0.45])
def test_radiation_constant_against_a_contour_integral(nu):
    h, _ = radiation_constant(nu)
    assert h == pytest.approx(_h_contour(nu), rel=1e-9)


def test_miller_pursey_partition():
    # Miller & Pursey (1955), nu = 1/4: 67.4% of the energy in the Rayleigh wave
    _, rayleigh = radiation_constant(0.25)
    assert round(100 * rayleigh, 1) == 67.4


def _hertz_si(sphere, plate, R, v0):
    """m1, E*, delta_m from the Hertz energy balance m1 V0^2 / 2 = (8/15) E* sqrt(R) delta_m^{5/2}."""
    m1 = 4.0 / 3.0 * math.pi * R**3 * sphere.rho
    es = 1.0 / ((1 - sphere.nu**2) / sphere.E + (1 - plate.nu**2) / plate.E)
    dm = (15.0 * m1 * v0**2 / (16.0 * es * math.sqrt(R))) ** 0.4
    return m1, es, dm


def _xi_hunter_frequency(sphere, plate, R, v0):
    """xi of Hunter's sine pulse from the frequency integral, at 20 digits."""
    m1, _, dm = _hertz_si(sphere, plate, R, v0)
    om = 1.068 * v0 / dm                   # Eq. (4)
    T, Fm = math.pi / om, m1 * dm * om**2  # half period, amplitude of Eq. (5)
    rho, c2 = plate.rho, math.sqrt(plate.E / (2 * (1 + plate.nu) * plate.rho))
    h = _h_contour(plate.nu)
    with mpmath.workdps(20):
        T, Fm = mpmath.mpf(T), mpmath.mpf(Fm)

        def F2(w):  # |int_0^T Fm sin(pi t / T) e^{i w t} dt|^2 = (pi T Fm sinc((pi - x)/2) / (pi + x))^2,
            x = w * T  # x = w T; the sinc form has no cancellation at x = pi
            return (mpmath.pi * T * Fm * mpmath.sinc((mpmath.pi - x) / 2) / (mpmath.pi + x)) ** 2

        def integrand(w):  # (1/pi) omega Im G |F^|^2, Im G = omega h / (2 pi rho c2^3)
            return w * (w * h / (2 * mpmath.pi * rho * c2**3)) * F2(w) / mpmath.pi

        per = 2 * mpmath.pi / T
        W = mpmath.nsum(lambda n: mpmath.quad(integrand, [n * per, (n + 1) * per]), [0, mpmath.inf])
        return float(W / (m1 * v0**2 / 2))


def test_half_sine_transform_used_above():
    # the |F^|^2 of _xi_hunter_frequency against a direct numerical Fourier integral
    T, Fm = 2.0e-6, 3.0
    for w in (1e5, math.pi / T, 7.7e6):
        re = quad(lambda t: Fm * math.sin(math.pi * t / T) * math.cos(w * t), 0, T, limit=200)[0]
        im = quad(lambda t: Fm * math.sin(math.pi * t / T) * math.sin(w * t), 0, T, limit=200)[0]
        x = w * T
        closed = float((T * Fm / (math.pi + x) * mpmath.sinc((math.pi - x) / 2)) ** 2 * math.pi**2)
        assert re * re + im * im == pytest.approx(closed, rel=1e-10)


def test_hunter_k_against_the_frequency_integral_and_the_scaling():
    k = stress_wave_k(S, P, "hunter")
    x1 = _xi_hunter_frequency(S, P, 0.9e-3, 1.0)
    x8 = _xi_hunter_frequency(S, P, 0.9e-3, 8.0)
    x8_big = _xi_hunter_frequency(S, P, 5e-3, 8.0)   # R drops out
    assert x1 == pytest.approx(k, rel=1e-9)
    assert math.log(x8 / x1) / math.log(8.0) == pytest.approx(0.6, rel=1e-9)
    assert x8_big == pytest.approx(x8, rel=1e-9)
    assert stress_wave_loss(S, P, 8.0, "hunter") == pytest.approx(x8, rel=1e-9)


def test_reed_k_from_the_time_integral():
    # W = h / (2 pi rho c2^3) int F'^2 dt (Parseval of the frequency form, checked for the sine
    # above) with Reed's F = (4/3) E* sqrt(R) delta_m^{3/2} sin^{3/2}(1.068 V0 t / delta_m), Eq. (6)
    R, v0 = 0.9e-3, 3.0
    m1, es, dm = _hertz_si(S, P, R, v0)
    om = 1.068 * v0 / dm
    Fm = 4.0 / 3.0 * es * math.sqrt(R) * dm**1.5
    dF2 = quad(lambda t: (1.5 * Fm * om * math.sqrt(math.sin(om * t)) * math.cos(om * t)) ** 2,
               0.0, math.pi / om, epsabs=0.0, epsrel=1e-12)[0]
    c2 = math.sqrt(P.E / (2 * (1 + P.nu) * P.rho))
    W = _h_contour(P.nu) / (2 * math.pi * P.rho * c2**3) * dF2
    assert W / (m1 * v0**2 / 2) == pytest.approx(stress_wave_loss(S, P, v0, "reed"), rel=1e-9)


def test_derivation_module_passes_and_agrees():
    from zener_sym.derivation import stress_waves as dsw

    ctx = dsw.derive()
    assert ctx.log.ok, [s for s in ctx.log.steps if not s.passed]
    t = dsw.TABLE1
    for p in PULSES:
        k = dsw.k_coefficient(p, t["E1"], t["nu1"], t["rho1"], t["E2"], t["nu2"], t["rho2"])
        assert float(k) == pytest.approx(stress_wave_k(S, P, p), rel=1e-12)


def test_fig14_csv_agrees_with_the_derivation():
    """The committed docs/figures/fig14.csv against the derivation's k (mpmath, from
    derivation/stress_waves.py) times V0^{3/5}: a route that shares no code with the figure's
    (the CSV holds 10 significant digits)."""
    from zener_sym.derivation import stress_waves as dsw

    rows = D.from_csv((ROOT / "docs" / "figures" / "fig14.csv").read_text(encoding="utf-8"))
    t = dsw.TABLE1
    for pulse in ("hunter", "reed"):
        mine = [r for r in rows if r[1] == pulse]
        assert {r[0] for r in mine} == set(D.FIGURES[14].panels)
        v0 = np.array([r[2] for r in mine])
        xi = np.array([r[3] for r in mine])
        k = float(dsw.k_coefficient(pulse, t["E1"], t["nu1"], t["rho1"], t["E2"], t["nu2"],
                                    t["rho2"]))
        assert np.allclose(xi, k * v0**0.6, rtol=1e-9, atol=0)
        assert all(r[4] is None for r in mine)  # a different loss: no error against the Zener loss


@pytest.mark.parametrize("call, says", [
    (lambda: stress_wave_k(S, P, "lamb"), "allowed: hunter, reed, hertz"),
    (lambda: stress_wave_loss(S, P, -1.0), "v0 must be finite and >= 0"),
    (lambda: stress_wave_loss(S, P, float("nan")), "v0 must be finite and >= 0"),
    (lambda: radiation_constant(0.5), "-1 < nu < 0.5"),
    (lambda: stress_wave_k("glass", P), "sphere must be a Material"),
])
def test_bad_input(call, says):
    with pytest.raises(ValueError, match=says.replace("(", r"\(")):
        call()
