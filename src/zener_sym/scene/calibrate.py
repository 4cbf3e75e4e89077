"""The dissipative constant A of viscoelastic grains from measured coefficients of restitution.

A grain contact with dissipative constant A [s] has Zener's lambda = A c(v0), with
c(v0) = (rho/m_eff)^{2/5} v0^{1/5} (``zener_sym.derivation.viscoelastic``; rho, m_eff from
:func:`~zener_sym.scene.grains.grain_contact`), and its coefficient of restitution is e(lambda) of
Eq. (10) with the chosen end of contact. So

- one measured e at one speed gives A = lambda(e) / c(v0) (:func:`dissipation_for`, with
  lambda(e) from ``zener_sym.lam_from_summary``);
- pairs (v0_i, e_i) give A by least squares, min over A of sum_i ((e_i - e(A c(v0_i))) / sigma_i)^2
  (:func:`fit_dissipation`). The fit runs in p = ln A (A stays positive, and e depends on A only
  through lambda, so the problem is as well scaled at A = 1e-12 s as at 1 s). Its Jacobian is
  de_i/dp = e'(lambda_i) lambda_i, e' = de/dlambda from the exact tables (not finite
  differences), for either end of contact;
- for Zener's plate, lambda is proportional to H^{-2} (derived Eq. 11), so the thickness that
  gives a measured e, or a measured contact duration t_d, is H (lam / lambda(e))^{1/2}
  (:func:`thickness_for`; t_d = T tau_d(lambda) with T independent of H, and tau_d is monotone
  in lambda on the plate).

The grains are given as in :func:`~zener_sym.grain_impact` (``sphere, radius, mass``, then
``sphere2, radius2, mass2`` or ``wall``), the measured arrays by keyword only, speed first
(``v0=..., e=...``). The old call forms (``dissipation_for(e, v0, R1, m1, material1)``,
``fit_dissipation(v0, e, R1, m1, material1)``) still work for one release, with a
``DeprecationWarning`` (:mod:`zener_sym.scene.legacy`).

e(v0) data constrain only the product A (rho/m_eff)^{2/5}: Young's modulus enters e only
through rho, so it cannot be fitted beside A from e alone (a contact-time measurement would
constrain it); it is fixed by the material given, and the fitted A scales as E*^{-2/5} with it.
"""
from __future__ import annotations

import csv
import io
import math
import os
import re
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, overload

import numpy as np

from ..api import lam_from_summary, summary
from ..exact.force_end import check_contact_end
from ..exact.inverse import reachable
from ..exact.solver import LAMBDA_MAX
from ..exact.table import summary_derivative
from ..typing import FloatArray, RealArrayLike, RealLike
from .grains import GrainContact, _pos_array, grain_contact
from .legacy import accepts_old_call
from .materials import Material
from .scene import Scene
from .units import UNITS, si_value

if TYPE_CHECKING:  # annotations only: matplotlib is optional (the plot extra)
    from matplotlib.figure import Figure

__all__ = ["dissipation_for", "thickness_for", "fit_dissipation", "DissipationFit",
           "read_measurements", "Measurements"]

#: Confidence level of the reported interval.
CONFIDENCE = 0.95


def _rate(contact: GrainContact, v0: RealArrayLike) -> FloatArray:
    """c(v0) = lambda / A = (rho/m_eff)^{2/5} v0^{1/5} [1/s]."""
    rate: FloatArray = (contact.rho / contact.m_eff) ** 0.4 * np.asarray(v0, dtype=float) ** 0.2
    return rate


def _e_array(e: object, name: str = "e") -> FloatArray:
    arr = np.asarray(e, dtype=float) if not isinstance(e, (bool, str)) else None
    if arr is None or arr.dtype.kind not in "fiu":
        raise ValueError(f"{name} (coefficient of restitution) must be a number in (0, 1], got "
                         f"{e!r}")
    bad = ~np.isfinite(arr) | (arr <= 0.0) | (arr > 1.0)
    if bad.any():
        raise ValueError(f"{name} (coefficient of restitution) must lie in (0, 1], got "
                         f"{arr[bad].ravel()[0].item()!r}; allowed: 0 < {name} <= 1")
    return arr


@overload
def dissipation_for(sphere: Material | str, radius: float | str, mass: float, *, v0: RealLike,
                    e: RealLike, sphere2: Material | str | None = None,
                    radius2: float | str | None = None, mass2: float | None = None,
                    wall: Material | str | None = None, contact_end: str = "force") -> float: ...


@overload
def dissipation_for(sphere: Material | str, radius: float | str, mass: float, *,
                    v0: RealArrayLike, e: RealArrayLike, sphere2: Material | str | None = None,
                    radius2: float | str | None = None, mass2: float | None = None,
                    wall: Material | str | None = None,
                    contact_end: str = "force") -> float | FloatArray: ...


@accepts_old_call(("e", "v0", "R1", "m1", "material1"),
                  "dissipation_for(sphere, radius, mass, v0=..., e=..., ...)")
def dissipation_for(sphere: Material | str, radius: float | str, mass: float, *,
                    v0: RealArrayLike, e: RealArrayLike, sphere2: Material | str | None = None,
                    radius2: float | str | None = None, mass2: float | None = None,
                    wall: Material | str | None = None,
                    contact_end: str = "force") -> float | FloatArray:
    """The dissipative constant A [s] that gives the coefficient of restitution ``e`` at the
    normal impact speed ``v0``: A = lambda(e) / ((rho/m_eff)^{2/5} v0^{1/5}).

    Parameters
    ----------
    sphere, radius, mass, sphere2, radius2, mass2, wall
        The grains, as in :func:`~zener_sym.grain_impact` (two spheres, or a sphere on a wall).
    v0 : float or array_like
        Normal relative impact speed(s) [m/s], > 0; keyword-only, as is ``e``.
    e : float or array_like
        Measured coefficient(s) of restitution, 0 < e <= 1 (e = 1 gives A = 0); broadcast
        against ``v0``.
    contact_end : {"force", "delta"}
        End of contact (default the grains' force-free end).

    Returns
    -------
    float or numpy.ndarray
        A in seconds, of the broadcast shape.

    Raises
    ------
    ValueError
        For e outside (0, 1], a non-positive speed, bad grain inputs, or an e below what
        lambda <= 1000 gives (the reachable range is in the message).

    Warns
    -----
    DeprecationWarning
        For the old call form ``dissipation_for(e, v0, R1, m1, material1, ...)``, which still
        works for one release (:mod:`zener_sym.scene.legacy`).

    Examples
    --------
    >>> import zener_sym as zs
    >>> A = zs.dissipation_for("glass", "1 mm", 1e-5, v0=1.0, e=0.8, wall="steel")
    >>> r = zs.grain_impact("glass", "1 mm", 1e-5, A=A, v0=1.0, wall="steel")
    >>> round(r.e, 12)
    0.8
    """
    ce = check_contact_end(contact_end)
    e_ = _e_array(e)
    v_ = _pos_array(v0, "v0", "m/s", "impact speed")
    contact = grain_contact(sphere, radius, mass, sphere2=sphere2, radius2=radius2, mass2=mass2,
                            wall=wall)
    e_b, v_b = np.broadcast_arrays(e_, v_)
    A: FloatArray = (np.asarray(lam_from_summary(e=e_b, contact_end=ce), dtype=float)
                     / _rate(contact, v_b))
    return float(A) if A.ndim == 0 else A


def thickness_for(scene: Scene, e: RealLike | None = None, *,
                  contact_time: float | str | None = None) -> float:
    """The plate thickness [m] at which ``scene`` (all else kept) has the coefficient of
    restitution ``e``, or the contact duration ``contact_time``, on Zener's plate (end of
    contact at delta = 0).

    lambda = alpha m*/T with alpha proportional to H^{-2} and T independent of H (derived
    Eq. 11), so H = H_scene (lambda_scene / lambda)^{1/2}, lambda the one with that e (or with
    tau_d = contact_time / T: tau_d grows monotonically with lambda on the plate, so a duration
    gives one lambda). The thin-plate reading needs H well above the contact radius;
    ``Scene(...).warnings`` says when it is not.

    Parameters
    ----------
    scene : Scene
        The sphere, plate material and speed (its thickness is the starting point only).
    e : float, optional
        Measured coefficient of restitution, 0 < e < 1 (e = 1 needs an infinitely thick plate).
    contact_time : float or str, optional
        Instead of ``e`` (keyword-only): the measured contact duration t_d, in seconds or with a
        unit (``"25 us"``), above Hertz's duration on a rigid half-space (an infinitely thick
        plate) and at most the duration at lambda = 1000. Impact-echo measurements give it more
        readily than e. Give exactly one of ``e`` and ``contact_time``.

    Returns
    -------
    float
        The thickness H [m].

    Raises
    ------
    ValueError
        For both or neither of ``e`` and ``contact_time``, e outside (0, 1) or below what
        lambda <= 1000 gives, or a duration outside the reachable range (given in seconds in
        the message).

    Examples
    --------
    >>> import zener_sym as zs
    >>> sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
    >>> H = zs.thickness_for(sc, 0.5)
    >>> sc2 = zs.Scene("steel", "glass", radius="1 mm", thickness=H, v0="1 m/s")
    >>> round(zs.summary(sc2.lam).e, 12)
    0.5
    >>> H = zs.thickness_for(sc, contact_time="12 us")
    >>> sc3 = zs.Scene("steel", "glass", radius="1 mm", thickness=H, v0="1 m/s")
    >>> round(sc3.result(model="exact").contact_duration_s * 1e6, 9)
    12.0
    """
    if not isinstance(scene, Scene):
        raise ValueError(f"scene must be a zener_sym.Scene, got {type(scene).__name__}")
    if (e is None) == (contact_time is None):
        raise ValueError(f"give exactly one of e (coefficient of restitution) and contact_time "
                         f"(e.g. '25 us'), got e={e!r}, contact_time={contact_time!r}")
    if contact_time is not None:
        lam = _lam_for_contact_time(scene, si_value(contact_time, "time", "contact_time"))
    else:
        e_ = float(_e_array(e))
        if e_ == 1.0:
            raise ValueError("e = 1 needs lambda = 0, an infinitely thick plate; allowed: "
                             "0 < e < 1")
        lam = float(lam_from_summary(e=e_, contact_end="delta"))
    return scene.thickness * math.sqrt(scene.lam / lam)


def _lam_for_contact_time(scene: Scene, t_d: float) -> float:
    """The plate's lambda whose contact lasts ``t_d`` seconds in ``scene`` (T kept: it does not
    depend on the thickness); ValueError, in seconds, for a duration no thickness gives."""
    T = scene.T
    lo, hi = reachable("tau_d", contact_end="delta")
    if not T * lo < t_d <= T * hi:
        raise ValueError(f"contact_time = {t_d:.6g} s is not reachable in this scene: allowed "
                         f"{T * lo:.6g} s < contact_time <= {T * hi:.6g} s (the shortest is "
                         f"Hertz's, on an infinitely thick plate; the longest at lambda = "
                         f"{LAMBDA_MAX:g})")
    return float(lam_from_summary(tau_d=t_d / T, contact_end="delta"))


@dataclass
class Measurements:
    """Pairs (v0_i, e_i) read by :func:`read_measurements`: speeds in m/s, e, optional sigma_e,
    and the unit the file gave the speeds in."""

    v0: FloatArray
    e: FloatArray
    sigma: FloatArray | None
    unit: str
    comments: list[str] = field(default_factory=list)


#: Header of the speed column: "v0" or "v", then the unit as "_m_s", " [m/s]" or " (m/s)".
_V_HEADER = re.compile(r"^\s*(v0|v)\s*(?:\[(?P<b>[^\]]*)\]|\((?P<p>[^)]*)\)|_(?P<u>[a-z_]+))?\s*$",
                       re.IGNORECASE)
_E_HEADERS = ("e",)
_SIGMA_HEADERS = ("sigma_e", "e_err", "de", "sigma")


def _speed_unit(header: str) -> str | None:
    m = _V_HEADER.match(header)
    if not m:
        return None
    unit = m.group("b") or m.group("p") or (m.group("u") or "").replace("_", "/", 1)
    unit = unit.strip()
    allowed = ", ".join(UNITS["speed"])
    if not unit:
        raise ValueError(f"column {header.strip()!r} has no unit; name it e.g. 'v0_m_s' or "
                         f"'v0 [m/s]' (allowed units: {allowed})")
    if unit not in UNITS["speed"]:
        raise ValueError(f"column {header.strip()!r}: unit {unit!r} is not one of {allowed}")
    return unit


def read_measurements(source: str | os.PathLike[str]) -> Measurements:
    """Measured pairs from a CSV file (path) or text: a header naming the speed column with its
    unit (``v0_m_s``, ``v0 [cm/s]``, ``v0 (mm/s)``; units m/s, cm/s, mm/s, km/h), the column
    ``e``, and optionally one uncertainty column of e (``sigma_e``, ``e_err``, ``de``). Lines
    starting with ``#`` are comments (kept in ``comments``).

    Raises
    ------
    ValueError
        For a missing or unit-less speed column, a missing ``e`` column, a cell that is not a
        number, or a file that cannot be read.
    """
    if isinstance(source, str) and "\n" in source:
        text, where = source, "data"
    else:
        try:
            with open(source, encoding="utf-8") as fh:
                text = fh.read()
        except OSError as exc:
            raise ValueError(f"cannot read {str(source)!r}: {exc.strerror or exc}") from None
        where = str(source)
    comments = [ln[1:].strip() for ln in text.splitlines() if ln.lstrip().startswith("#")]
    rows = [r for r in csv.reader(io.StringIO(text))
            if r and not r[0].lstrip().startswith("#") and any(c.strip() for c in r)]
    if not rows:
        raise ValueError(f"{where}: no header and no data")
    header = rows[0]
    iv = ie = isg = None
    unit = None
    for i, h in enumerate(header):
        name = h.strip().lower()
        u = _speed_unit(h)
        if u is not None:
            if iv is not None:
                raise ValueError(f"{where}: two speed columns ({header[iv].strip()!r}, "
                                 f"{h.strip()!r}); give one")
            iv, unit = i, u
        elif name in _E_HEADERS:
            ie = i
        elif name in _SIGMA_HEADERS:
            isg = i
    if iv is None:
        raise ValueError(f"{where}: no speed column; the header needs e.g. 'v0_m_s' or "
                         f"'v0 [m/s]' (got {', '.join(repr(h.strip()) for h in header)})")
    if ie is None:
        raise ValueError(f"{where}: no column 'e' (got "
                         f"{', '.join(repr(h.strip()) for h in header)})")
    cols: dict[str, list[float]] = {k: [] for k in ("v", "e", "s")}
    for n, row in enumerate(rows[1:], start=2):
        for key, idx in (("v", iv), ("e", ie), ("s", isg)):
            if idx is None:
                continue
            try:
                cols[key].append(float(row[idx]))
            except (IndexError, ValueError):
                cell = row[idx] if idx < len(row) else ""
                raise ValueError(f"{where}: data row {n - 1}, column {header[idx].strip()!r}: "
                                 f"{cell!r} is not a number") from None
    if not cols["v"]:
        raise ValueError(f"{where}: a header but no data rows")
    assert unit is not None  # set with the speed column, found above
    factor = UNITS["speed"][unit]
    return Measurements(v0=np.array(cols["v"]) * factor, e=np.array(cols["e"]),
                        sigma=np.array(cols["s"]) if isg is not None else None, unit=unit,
                        comments=comments)


@dataclass
class DissipationFit:
    """Result of :func:`fit_dissipation`.

    Attributes
    ----------
    A : float
        Fitted dissipative constant [s].
    A_se : float
        Its standard error [s] (A times the standard error of ln A).
    A_ci : tuple of float
        The 95 % confidence interval of A [s], exp(ln A -+ q se(ln A)) with q Student's t
        quantile (n - 1 degrees of freedom) when the scatter is estimated from the residuals, the
        normal quantile when ``sigma`` was given.
    v0, e, sigma : numpy.ndarray
        The data (speeds in m/s); ``sigma`` None when not given.
    lam : numpy.ndarray
        Zener's lambda of each point at the fitted A.
    e_fit, residuals : numpy.ndarray
        e of the model at the fitted A and e - e_fit.
    s : float
        Scatter of e: sqrt(sum r_i^2 / (n - 1)) (r weighted by 1/sigma when given: then s = 1
        for data scattered as stated).
    contact_end : str
    contact : GrainContact
        m_eff, rho, R_eff, E* of the grains.
    dof : int
        n - 1.
    nfev : int
        Model evaluations of the least-squares solver.
    sigma_from : str
        ``"given"`` or ``"residuals"``: where the error scale came from.
    se_lnA : float
        Standard error of ln A.
    quantile : float
        The quantile q of the interval (Student's t or normal).
    confidence : float
        The interval's confidence level, 0.95.

    Examples
    --------
    >>> import zener_sym as zs
    >>> fit = zs.fit_dissipation("glass", "1 mm", 1e-5, v0=[0.5, 1.0, 2.0], e=[0.82, 0.80, 0.77],
    ...                          wall="steel")
    >>> f"{fit.A:.3g} s", fit.dof, fit.sigma_from
    ('2.4e-07 s', 2, 'residuals')
    >>> p = fit.predict(5.0)
    >>> p["e_low"] < p["e"] < p["e_high"]
    True
    """

    A: float
    A_se: float
    A_ci: tuple[float, float]
    v0: FloatArray
    e: FloatArray
    sigma: FloatArray | None
    lam: FloatArray
    e_fit: FloatArray
    residuals: FloatArray
    s: float
    contact_end: str
    contact: GrainContact
    dof: int
    nfev: int
    sigma_from: str
    se_lnA: float = field(repr=False)
    quantile: float = field(repr=False)
    confidence: float = CONFIDENCE

    def predict(self, v0: RealArrayLike) -> dict[str, float | FloatArray]:
        """e and the contact time at other speeds, with the e interval that A's interval gives.

        Parameters
        ----------
        v0 : float or array_like
            Normal impact speed(s) [m/s], > 0.

        Returns
        -------
        dict
            ``v0``, ``lam``, ``e``, ``e_low``, ``e_high`` (e at the upper and lower end of A's
            interval; e falls as A grows), ``contact_duration_s`` (T tau_d, T =
            (m_eff/rho)^{2/5} v0^{-1/5}), each an array (a float for a scalar ``v0``).

        Raises
        ------
        ValueError
            For a non-positive speed, or one at which lambda would exceed 1000.

        Examples
        --------
        >>> import zener_sym as zs
        >>> fit = zs.fit_dissipation("glass", "1 mm", 1e-5, v0=[0.5, 1.0, 2.0],
        ...                          e=[0.82, 0.80, 0.77], wall="steel")
        >>> p = fit.predict(5.0)
        >>> round(p["e"], 4), round(p["e_low"], 4), round(p["e_high"], 4)
        (0.7356, 0.728, 0.743)
        >>> round(p["lam"] / float(fit.lam[0]), 6), round((5.0 / 0.5) ** 0.2, 6)  # lambda ~ v0^(1/5)
        (1.584893, 1.584893)
        """
        v = _pos_array(v0, "v0", "m/s", "impact speed")
        c = _rate(self.contact, v)
        lam_hi = self.A_ci[1] * c
        if np.any(lam_hi > LAMBDA_MAX):
            raise ValueError(f"at v0 = {float(np.max(v)):.6g} m/s the upper end of A's interval "
                             f"gives lambda = {float(np.max(lam_hi)):.6g} > {LAMBDA_MAX:g}, the "
                             f"exact model's range")
        lam = self.A * c
        s = summary(lam, model="exact", contact_end=self.contact_end)
        lo = summary(lam_hi, model="exact", contact_end=self.contact_end).e
        hi = summary(self.A_ci[0] * c, model="exact", contact_end=self.contact_end).e
        T = (self.contact.m_eff / self.contact.rho) ** 0.4 * v ** -0.2
        out: dict[str, float | FloatArray] = {
            "v0": v, "lam": lam, "e": s.e, "e_low": lo, "e_high": hi,
            "contact_duration_s": T * np.asarray(s.tau_d)}
        if np.ndim(v) == 0:
            out = {k: float(x) for k, x in out.items()}
        return out

    def summary(self) -> str:
        """The fit as text a person reads: A, its interval, the scatter, the grains and a table
        of the points.

        Returns
        -------
        str

        Examples
        --------
        >>> import zener_sym as zs
        >>> fit = zs.fit_dissipation("glass", "1 mm", 1e-5, v0=[0.5, 1.0, 2.0],
        ...                          e=[0.82, 0.80, 0.77], wall="steel")
        >>> print(fit.summary().splitlines()[0])
        dissipative constant A = 2.40221e-07 s  (standard error 1.98e-09 s, 0.82%)
        """
        n = self.v0.size
        lines = [
            f"dissipative constant A = {self.A:.6g} s  (standard error {self.A_se:.3g} s, "
            f"{self.A_se / self.A:.2%})",
            f"{self.confidence:.0%} confidence interval: [{self.A_ci[0]:.6g}, "
            f"{self.A_ci[1]:.6g}] s",
            f"{n} points, v0 {self.v0.min():.4g} .. {self.v0.max():.4g} m/s, "
            f"lambda {self.lam.min():.4g} .. {self.lam.max():.4g}; contact end "
            f"{self.contact_end!r}",
            (f"scatter of e: {self.s:.3g} (rms of the residuals, {self.dof} degrees of freedom; "
             f"interval from Student's t)" if self.sigma_from == "residuals" else
             f"weighted scatter: {self.s:.3g} (1 when the data scatter as the sigma given; "
             f"interval from the sigma given)"),
            f"grains: m_eff = {self.contact.m_eff:.6g} kg, rho = {self.contact.rho:.6g} "
            f"N/m^(3/2), R_eff = {self.contact.R_eff:.6g} m, E* = {self.contact.E_star:.6g} Pa",
            "",
            f"{'v0 [m/s]':>12} {'e':>9} {'e fit':>9} {'residual':>10} {'lambda':>10}",
        ]
        for v, e, ef, r, la in zip(self.v0, self.e, self.e_fit, self.residuals, self.lam):
            lines.append(f"{v:12.6g} {e:9.5f} {ef:9.5f} {r:+10.2e} {la:10.4g}")
        return "\n".join(lines)

    def __str__(self) -> str:
        return self.summary()

    def plot(self, path: str | os.PathLike[str] | None = None, *, title: str | None = None,
             data_label: str = "measured") -> Figure:
        """Chart: the data (with error bars when sigma was given), the fitted e(v0) and the band
        of A's interval; below, the residuals. Needs matplotlib (the ``plot`` extra).

        Parameters
        ----------
        path : str or Path, optional
            Where to save (its suffix picks the format); the figure is returned either way.
        title : str, optional
            The chart's title.
        data_label : str
            Legend entry of the points (default ``"measured"``).

        Returns
        -------
        matplotlib.figure.Figure

        Examples
        --------
        >>> import matplotlib
        >>> matplotlib.use("Agg")
        >>> import zener_sym as zs
        >>> fit = zs.fit_dissipation("glass", "1 mm", 1e-5, v0=[0.5, 1.0, 2.0],
        ...                          e=[0.82, 0.80, 0.77], wall="steel")
        >>> fig = fit.plot()
        >>> len(fig.axes)                    # e(v0) above, the residuals below
        2
        """
        from ..plot.calibration import fit_chart

        fig: Figure = fit_chart(self, path=path, title=title, data_label=data_label)
        return fig


def _trend(v0: FloatArray, e: FloatArray, w: FloatArray) -> float:
    """Weighted least-squares slope of e against ln v0."""
    x = np.log(v0)
    xm = np.sum(w * x) / np.sum(w)
    em = np.sum(w * e) / np.sum(w)
    return float(np.sum(w * (x - xm) * (e - em)) / np.sum(w * (x - xm) ** 2))


def _fit_data(v0: RealArrayLike, e: RealArrayLike,
              sigma: RealArrayLike | None) -> tuple[FloatArray, FloatArray, FloatArray | None]:
    """The measured pairs (and sigma, one per point) as 1-d arrays, checked: equal lengths,
    enough points, not all elastic, and e not rising with speed (:func:`fit_dissipation`'s
    refusals that need no model)."""
    v_ = np.atleast_1d(_pos_array(v0, "v0", "m/s", "impact speed")).astype(float)
    e_ = np.atleast_1d(_e_array(e)).astype(float)
    if v_.ndim != 1 or e_.ndim != 1:
        raise ValueError(f"v0 and e must be 1-d sequences, got shapes {v_.shape} and {e_.shape}")
    if v_.size != e_.size:
        raise ValueError(f"v0 and e must have equal lengths, got {v_.size} speeds and "
                         f"{e_.size} values of e")
    s_ = None
    if sigma is not None:
        s_ = np.atleast_1d(_pos_array(sigma, "sigma", "units of e", "standard deviation of e"))
        if s_.size == 1:
            s_ = np.full(e_.size, float(s_.ravel()[0]))
        if s_.shape != e_.shape:
            raise ValueError(f"sigma must be one number or one per point ({e_.size}), got "
                             f"{s_.size}")
    n_min = 1 if s_ is not None else 2
    if e_.size < n_min:
        raise ValueError(f"{e_.size} point(s) for 1 parameter (A): the fit needs at least "
                         f"{n_min} ({'with' if s_ is not None else 'without'} sigma; without it "
                         f"the scatter comes from the residuals)")
    if np.all(e_ == 1.0):
        raise ValueError("every e is 1: the contact is elastic, A = 0; nothing to fit")
    if np.unique(v_).size >= 2:
        slope = _trend(v_, e_, np.ones_like(e_) if s_ is None else 1.0 / s_**2)
        if slope > 0.0:
            raise ValueError(f"e rises with speed (least-squares slope of e against ln v0: "
                             f"{slope:+.3g}); the viscoelastic e falls with speed for every "
                             f"A > 0, so no A fits these data")
    return v_, e_, s_


@dataclass(frozen=True)
class _Problem:
    """The least-squares problem in p = ln A: e_i against e(exp(p) c_i), weighted by inv_s."""

    e: FloatArray
    c: FloatArray
    inv_s: FloatArray
    contact_end: str

    @property
    def p_max(self) -> float:
        """ln A at which the fastest point reaches lambda = LAMBDA_MAX."""
        return math.log(LAMBDA_MAX / float(self.c.max()))

    def lams(self, p: FloatArray | list[float]) -> FloatArray:
        # at the bound exp(ln(1000/c)) c may round 1 ulp above 1000
        return np.minimum(math.exp(p[0]) * self.c, LAMBDA_MAX)

    def e_model(self, p: FloatArray | list[float]) -> FloatArray:
        return np.asarray(summary(self.lams(p), model="exact", contact_end=self.contact_end).e,
                          dtype=float)

    def residuals(self, p: FloatArray) -> FloatArray:
        r: FloatArray = (self.e - self.e_model(p)) * self.inv_s
        return r

    def jacobian(self, p: FloatArray | list[float]) -> FloatArray:
        lam = self.lams(p)
        de = summary_derivative(lam, field="e", contact_end=self.contact_end)
        return (-de * lam * self.inv_s)[:, None]

    def start(self) -> float:
        """The median of the one-point inversions (each e clipped into the reachable range)."""
        e_floor = float(summary(LAMBDA_MAX, model="exact", contact_end=self.contact_end).e)
        lam0 = np.asarray(lam_from_summary(e=np.clip(self.e, e_floor * (1 + 1e-12), 1.0),
                                           contact_end=self.contact_end))
        a0 = lam0 / self.c
        p0 = math.log(float(np.median(a0[a0 > 0]))) if np.any(a0 > 0) else self.p_max - 10.0
        return min(p0, self.p_max - 1e-9)


def _solve(problem: _Problem, v0: FloatArray) -> tuple[float, int]:
    """ln A of the least-squares fit and the solver's evaluations; ValueError when it does not
    converge or stops at the model's bound lambda = LAMBDA_MAX."""
    from scipy.optimize import least_squares

    p_max = problem.p_max
    sol = least_squares(problem.residuals, [problem.start()], jac=problem.jacobian,
                        bounds=([-np.inf], [p_max]), method="trf", x_scale=[1.0], xtol=1e-15,
                        ftol=1e-15, gtol=1e-15, max_nfev=200)
    if sol.status <= 0:
        raise ValueError(f"the fit did not converge ({sol.message}); A reached "
                         f"{math.exp(sol.x[0]):.6g} s after {sol.nfev} evaluations")
    p = float(sol.x[0])
    if sol.active_mask[0] != 0 or p_max - p < 1e-6:
        raise ValueError(f"these e are lower than lambda <= {LAMBDA_MAX:g} gives at "
                         f"v0 = {float(v0[np.argmax(problem.c)]):.6g} m/s: the best A is at the "
                         f"model's bound {math.exp(p_max):.6g} s")
    return p, int(sol.nfev)


def _interval(J: FloatArray, rw: FloatArray, sigma_given: bool) -> tuple[float, float, float]:
    """(scatter s, standard error of ln A, quantile q) from the Jacobian J in ln A and the
    weighted residuals rw: Student's t with n - 1 degrees of freedom when the scatter comes from
    the residuals, the normal quantile when sigma was given."""
    from scipy.stats import norm, t as student_t

    JtJ = float(J @ J)
    if not JtJ > 0.0:
        raise ValueError("the data do not constrain A (de/dA = 0 at every point)")
    dof = rw.size - 1
    if not sigma_given:
        scat = math.sqrt(float(rw @ rw) / dof)
        return scat, scat / math.sqrt(JtJ), float(student_t.ppf(0.5 + CONFIDENCE / 2, dof))
    scat = math.sqrt(float(rw @ rw) / max(dof, 1))  # one point: fitted exactly, 0
    return scat, 1.0 / math.sqrt(JtJ), float(norm.ppf(0.5 + CONFIDENCE / 2))


@accepts_old_call(("v0", "e", "R1", "m1", "material1"),
                  "fit_dissipation(sphere, radius, mass, v0=..., e=..., ...)")
def fit_dissipation(sphere: Material | str, radius: float | str, mass: float, *,
                    v0: RealArrayLike, e: RealArrayLike, sigma: RealArrayLike | None = None,
                    sphere2: Material | str | None = None, radius2: float | str | None = None,
                    mass2: float | None = None, wall: Material | str | None = None,
                    contact_end: str = "force") -> DissipationFit:
    """Fit the dissipative constant A [s] to measured pairs (v0_i, e_i) by least squares.

    Minimises sum_i ((e_i - e(lambda_i)) / sigma_i)^2 over A, lambda_i = A (rho/m_eff)^{2/5}
    v0_i^{1/5}, with e(lambda) of the exact model and the Jacobian from its tables (module
    docstring). Young's modulus is fixed by the materials given: e(v0) data alone cannot
    separate it from A.

    Parameters
    ----------
    sphere, radius, mass, sphere2, radius2, mass2, wall
        The grains, as in :func:`~zener_sym.grain_impact`.
    v0, e : array_like
        Normal impact speeds [m/s] (> 0) and coefficients of restitution (0 < e <= 1), equal
        lengths; keyword-only, so that the two arrays cannot be swapped unseen.
    sigma : float or array_like, optional
        Standard deviation of each e (> 0). Given, the residuals are weighted by 1/sigma and the
        interval uses it as stated; left out, the scatter is estimated from the residuals
        (Student's t, n - 1 degrees of freedom; needs two points or more).
    contact_end : {"force", "delta"}
        End of contact (default the grains' force-free end).

    Returns
    -------
    DissipationFit

    Raises
    ------
    ValueError
        For unequal lengths, e outside (0, 1], a non-positive speed or sigma, fewer points than
        the fit needs, e that all equal 1 (A = 0), e that rises with speed (no A fits: the
        model's e falls with speed for every A > 0), e below what lambda <= 1000 gives, or a
        solver that does not converge.

    Warns
    -----
    DeprecationWarning
        When called as ``fit_dissipation(v0, e, R1, m1, material1, ...)``: translated and fitted
        all the same, until the next release drops that form.

    Examples
    --------
    >>> import numpy as np, zener_sym as zs
    >>> v = np.array([0.5, 1.0, 2.0, 4.0])
    >>> A = 2e-7
    >>> e = [zs.grain_impact("glass", "1 mm", 1e-5, A=A, v0=x, wall="steel").e for x in v]
    >>> fit = zs.fit_dissipation("glass", "1 mm", 1e-5, v0=v, e=e, wall="steel")
    >>> abs(fit.A / A - 1) < 1e-9
    True
    """
    ce = check_contact_end(contact_end)
    v_, e_, s_ = _fit_data(v0, e, sigma)
    contact = grain_contact(sphere, radius, mass, sphere2=sphere2, radius2=radius2, mass2=mass2,
                            wall=wall)
    inv_s = np.ones_like(e_) if s_ is None else 1.0 / s_
    problem = _Problem(e=e_, c=_rate(contact, v_), inv_s=inv_s, contact_end=ce)
    p, nfev = _solve(problem, v_)
    A = math.exp(p)
    e_fit = problem.e_model([p])
    r = e_ - e_fit
    scat, se, q = _interval(problem.jacobian([p])[:, 0], r * inv_s, s_ is not None)
    ci = (A * math.exp(-q * se), A * math.exp(q * se))
    return DissipationFit(A=A, A_se=A * se, A_ci=ci, v0=v_, e=e_, sigma=s_,
                          lam=problem.lams([p]), e_fit=e_fit, residuals=r, s=scat,
                          contact_end=ce, contact=contact, dof=e_.size - 1, nfev=nfev,
                          sigma_from="given" if s_ is not None else "residuals",
                          se_lnA=se, quantile=q)
