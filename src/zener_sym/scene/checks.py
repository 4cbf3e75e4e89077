"""Validity checks of a scene against the assumptions of Zener's model, as ``ZenerWarning``s.

Each check returns ``(code, message)`` pairs; ``Scene`` and ``SceneResult`` issue them with
``warnings.warn(..., ZenerWarning)`` and list them in their tables. Criteria and sources:

- ``ham-bound``: the HAM solutions need a real frequency omega_0 = sqrt(4k - k^2 lambda^2)/2,
  i.e. lambda < 2/sqrt(k) with k = sqrt(delta_m0) = (lambda + (5/4)^{-3/5})^{-1/3} (paper, Eq. 25
  with its exponent derived from delta_m = (5/4)^{2/5} at lambda = 0, and the bound below Eq. 27).
  lambda^2 k = 4 gives lambda^6 = 64 (lambda + (5/4)^{-3/5}), lambda_HAM ~ 2.4424.
- ``thick-plate``: 2R/H < 0.2. Below this diameter-to-thickness ratio Hunter's half-space model
  agrees with experiment (Koller & Kolsky 1987, Int. J. Solids Struct. 23, 1387, as cited in the
  paper's introduction): the plate responds like a half-space, and the elastic-wave (Hunter)
  loss, which Zener's equation does not contain, dominates the flexural loss.
- ``kirchhoff``: Zener's admittance is Kirchhoff (thin-plate) theory, the long-wave limit k H -> 0
  of the antisymmetric Rayleigh-Lamb branch (e.g. Graff 1975, Wave Motion in Elastic Solids,
  ch. 8). We warn when the flexural wavenumber at the pulse's dominant frequency omega = pi/t_d
  exceeds k H = 1 (threshold: this package's choice).
- ``thin-plate``: the Hertz law (Eq. 8) treats each body as a half-space near the contact, which
  needs the contact radius small compared with the bodies' dimensions (Johnson 1985, Contact
  Mechanics, sec. 4.1); we warn when the maximum contact radius a = sqrt(R delta_max) exceeds H
  (threshold: this package's choice).
- ``large-deflection``: small-deflection plate theory needs the deflection small compared with the
  thickness (Timoshenko & Woinowsky-Krieger 1959, Theory of Plates and Shells, ch. 13, where
  membrane forces take over); we warn when the centre deflection at the end of contact,
  w = alpha I, exceeds H/2 (threshold: this package's choice).
- ``finite-plate`` (only with a bounded plate): the finite-plate criterion
  (:mod:`zener_sym.scene.plate_criterion`) estimates Zener's error on this plate from the
  ``finite-plate`` model measured on a grid of (lambda, beta) for each support; the scene warns
  when it exceeds rtol and the answer is Zener's (without a support, every support is judged).
  It replaces an estimate of the echo's return from the phase speed at one frequency, which
  stayed silent where the first contact itself was already shortened (issue 37).
- ``yield``: onset of yield under Hertz contact when the maximum pressure p0 = 3F/(2 pi a^2)
  reaches 1.60 Y (von Mises, nu = 0.3; Johnson 1985, Contact Mechanics, sec. 6.2; equivalently
  a mean pressure of about 1.1 Y), checked for each body with a yield strength.
"""
from __future__ import annotations

import math
from typing import Protocol

from .materials import Material

__all__ = ["ZenerWarning", "HAM_LAMBDA_BOUND", "ham_k", "ham_lambda_bound", "static_checks",
           "dynamic_checks", "THICK_RATIO", "KH_MAX", "A_OVER_H_MAX", "W_OVER_H_MAX",
           "P0_OVER_Y"]


class ZenerWarning(UserWarning):
    """A scene lies outside (or at the edge of) the assumptions of Zener's model or the HAM.

    Issued by :meth:`Scene.result` (also listed in the result's table and ``warnings``).

    Examples
    --------
    >>> import warnings, zener_sym as zs
    >>> sc = zs.Scene("steel", "glass", radius="1 mm", thickness="0.25 mm", v0="5 m/s")
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     r = sc.result()
    >>> any(issubclass(w.category, zs.ZenerWarning) for w in caught)
    True
    """


class SceneInputs(Protocol):
    """What the checks read of a scene (``zener_sym.Scene`` has it; scene.py imports this
    module, so it is described here rather than imported)."""

    sphere: Material
    plate: Material
    radius: float
    thickness: float
    v0: float

    @property
    def lam(self) -> float: ...

    @property
    def D(self) -> float: ...

    @property
    def alpha(self) -> float: ...

    @property
    def m_star(self) -> float: ...


THICK_RATIO = 0.2   # 2R/H below which the plate acts as a half-space (Koller & Kolsky 1987)
KH_MAX = 1.0        # flexural k H above which Kirchhoff theory is doubtful (our threshold)
A_OVER_H_MAX = 1.0  # contact radius over thickness (our threshold)
W_OVER_H_MAX = 0.5  # deflection over thickness (our threshold)
P0_OVER_Y = 1.60    # Hertz p0 at first yield, von Mises, nu = 0.3 (Johnson 1985, sec. 6.2)

_C0 = 1.25 ** -0.6  # (5/4)^{-3/5}: makes k = (5/4)^{1/5} = sqrt(delta_m) at lambda = 0


def ham_k(lam: float) -> float:
    """k = (lambda + (5/4)^{-3/5})^{-1/3} (paper Eq. 25, exponent derived)."""
    return float((lam + _C0) ** (-1.0 / 3.0))


def ham_lambda_bound() -> float:
    """The lambda at which lambda = 2/sqrt(k(lambda)): root of lambda^6 = 64 (lambda + c0)."""
    lo, hi = 1.0, 4.0  # f(lo) < 0 < f(hi); f is increasing on [1, 4]

    def f(x: float) -> float:
        return x**6 - 64.0 * (x + _C0)

    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) < 0 else (lo, mid)
    return 0.5 * (lo + hi)


HAM_LAMBDA_BOUND = ham_lambda_bound()


def static_checks(scene: SceneInputs) -> list[tuple[str, str]]:
    """Checks that need only the scene's inputs."""
    out = []
    lam = scene.lam
    bound = _ham_bound()
    if lam >= bound:
        out.append(("ham-bound", f"lambda = {lam:.4g} is at or beyond the HAM bound 2/sqrt(k) = "
                    f"{bound:.6g}: the homotopy solutions do not apply (omega_0 is not real); "
                    f"only direct integration (model 'exact') is valid"))
    ratio = 2.0 * scene.radius / scene.thickness
    if ratio < THICK_RATIO:
        out.append(("thick-plate", f"diameter/thickness 2R/H = {ratio:.3g} < {THICK_RATIO}: the "
                    "plate acts as a half-space (Koller & Kolsky 1987); Hunter's elastic-wave "
                    "loss, absent from Zener's model, dominates"))
    return out


def dynamic_checks(scene: SceneInputs, t_d: float, delta_max: float, F_max: float, impulse: float
                   ) -> list[tuple[str, str]]:
    """Checks that need the contact duration [s], maximum compression [m], maximum force [N]
    and final impulse (dimensionless I_bar at the end of contact)."""
    out = []
    H, R = scene.thickness, scene.radius
    plate = scene.plate
    omega = math.pi / t_d
    c_phase = math.sqrt(omega) * (scene.D / (plate.rho * H)) ** 0.25
    kH = omega / c_phase * H
    if kH > KH_MAX:
        out.append(("kirchhoff", f"flexural wavenumber x thickness k H = {kH:.3g} > {KH_MAX:g} at "
                    f"the pulse frequency pi/t_d: the plate is too thick for Kirchhoff "
                    f"(thin-plate) theory, on which Zener's admittance rests"))
    a = math.sqrt(R * delta_max)
    if a > A_OVER_H_MAX * H:
        out.append(("thin-plate", f"contact radius a = {a:.3g} m exceeds the plate thickness H = "
                    f"{H:.3g} m: the plate is too thin for the Hertz half-space contact law and "
                    f"the point-load plate model"))
    w = scene.alpha * scene.m_star * scene.v0 * impulse
    if w > W_OVER_H_MAX * H:
        out.append(("large-deflection", f"plate deflection w = {w:.3g} m exceeds H/2 = "
                    f"{H / 2:.3g} m: small-deflection plate theory does not hold (membrane "
                    f"stiffening)"))
    if F_max > 0 and delta_max > 0:
        p0 = 3.0 * F_max / (2.0 * math.pi * R * delta_max)  # a^2 = R delta
        for who, mat in (("sphere", scene.sphere), ("plate", scene.plate)):
            Y = mat.yield_strength
            if Y is not None and p0 >= P0_OVER_Y * Y:
                out.append(("yield", f"maximum Hertz pressure p0 = {p0:.3g} Pa >= 1.60 Y = "
                            f"{P0_OVER_Y * Y:.3g} Pa of the {who} ({mat.name}): the {who} yields "
                            f"(Johnson 1985, sec. 6.2); the elastic model overestimates e"))
    return out


def _ham_bound() -> float:
    # A registered HAM model's own bound wins (it is what select_model obeys); else the derived one.
    from ..models import REGISTRY

    for name in ("ham1", "ham0"):
        m = REGISTRY.get(name)
        if m is not None and m.lam_bound is not None:
            return float(m.lam_bound)
    return HAM_LAMBDA_BOUND
