"""Error envelopes of the HAM models against direct integration, and the model comparison table.

``envelopes()`` measures, over a lambda grid, the largest relative error of ham0 and ham1 against
the exact model for F_m, tau_d, e, impulse and delta_m, and the largest error of the force
history over the contact (max |F_model - F_exact| over a tau grid covering both contacts, relative
to the exact F_m). The table in docs/ham.md (between :data:`BEGIN` and :data:`END`) is the
artefact ``ham-envelopes`` of ``zener-sym regen``.
"""
from __future__ import annotations

import time
from collections.abc import Sequence
from typing import Final, TypedDict

import numpy as np

from ..typing import FloatArray, RealArrayLike
from .format import seconds

__all__ = ["envelopes", "envelope_markdown", "comparison_markdown", "update_doc", "FIELDS",
           "LAMBDAS", "Envelopes"]

FIELDS: tuple[str, ...] = ("F_m", "tau_d", "e", "impulse", "delta_m")
#: lambda grid of the envelopes: [0, 2.4] in steps of 0.1
LAMBDAS: FloatArray = np.round(np.linspace(0.0, 2.4, 25), 10)

#: The models measured (a Final tuple of literals: the keys of :class:`Envelopes`).
_MODELS: Final = ("ham0", "ham1")

#: A lambda range (lo, hi), both ends included.
Range = tuple[float, float]
#: field -> (largest relative error on a range, the lambda where it occurs)
RangeEnvelope = dict[str, tuple[float, float]]


class Envelopes(TypedDict):
    """What :func:`envelopes` measures: per model, per lambda range, per field the largest
    relative error and where it occurs; ``_per_lambda`` has every error on the grid."""

    ham0: dict[Range, RangeEnvelope]
    ham1: dict[Range, RangeEnvelope]
    _per_lambda: dict[str, dict[str, FloatArray]]


def _rel(a: FloatArray, b: FloatArray) -> FloatArray:
    return np.abs(a - b) / np.abs(b)


def envelopes(lams: RealArrayLike = LAMBDAS,
              ranges: Sequence[Range] = ((0.0, 1.0), (0.0, 2.0), (0.0, 2.4)),
              n_tau: int = 400) -> Envelopes:
    """Per model and lambda range: the max relative error of each field and of the force history.

    Returns
    -------
    Envelopes
        {model: {(lo, hi): {field: (max error, lambda where it occurs)}}}, plus "_per_lambda":
        {model: {field: array of errors}}.
    """
    from ..api import history, summary

    lams = np.asarray(lams, dtype=np.float64)
    ex = summary(lams, model="exact")
    out: Envelopes = {"_per_lambda": {}, "ham0": {}, "ham1": {}}
    sums = {m: summary(lams, model=m) for m in _MODELS}
    T = 1.05 * np.maximum(ex.tau_d, np.maximum(sums["ham0"].tau_d, sums["ham1"].tau_d))
    tau = T[:, None] * np.linspace(0.0, 1.0, n_tau)  # one grid per lambda, both contacts
    fe = history(lams[:, None], tau, model="exact").force
    for model in _MODELS:
        s = sums[model]
        per = {f: _rel(getattr(s, f), getattr(ex, f)) for f in FIELDS}
        fm = history(lams[:, None], tau, model=model).force
        per["force history"] = np.max(np.abs(fm - fe), axis=1) / ex.F_m
        out["_per_lambda"][model] = per
        for lo, hi in ranges:
            m = (lams >= lo) & (lams <= hi)
            out[model][(lo, hi)] = {f: (float(np.max(v[m])), float(lams[m][np.argmax(v[m])]))
                                    for f, v in per.items()}
    return out


def envelope_markdown(env: Envelopes | None = None) -> str:
    """The envelopes as the markdown table of docs/ham.md (measured now unless ``env`` given)."""
    env = envelopes() if env is None else env
    fields = FIELDS + ("force history",)
    lines = ["| model | lambda range | " + " | ".join(fields) + " |",
             "|" + "---|" * (len(fields) + 2)]
    for model in _MODELS:
        for rng, vals in env[model].items():
            cells = [f"{100 * vals[f][0]:.2f}% (at {vals[f][1]:g})" for f in fields]
            lines.append(f"| {model} | [{rng[0]:g}, {rng[1]:g}] | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def comparison_markdown(lams: RealArrayLike = (0.0, 0.11, 1.01, 1.51, 1.99)) -> str:
    """Relative errors of every model against exact at the paper's lambdas (report section)."""
    from ..api import summary
    from ..models import FieldUnavailableError

    t0 = time.perf_counter()
    lams = np.asarray(lams, dtype=float)
    ex = summary(lams, model="exact")
    fields = ("F_m", "tau_d", "e", "impulse", "delta_m", "xi")
    rows: list[list[str]] = []
    for model in ("ham0", "ham1", "hertz", "hunter", "reed", "oneway"):
        for i, lam in enumerate(lams):
            try:
                s = summary(lam, model=model)
            except ValueError as exc:
                rows.append([model, f"{lam:g}"] + [f"n/a ({exc.__class__.__name__})"] + [""] * (len(fields) - 1))
                continue
            cells = []
            for f in fields:
                try:
                    v = getattr(s, f)
                except FieldUnavailableError:
                    cells.append("-")
                    continue
                ref = getattr(ex, f)[i]
                cells.append(f"{v:.5g} ({100 * (v - ref) / abs(ref):+.2f}%)" if abs(ref) > 1e-12
                             else f"{v:.3g}")
            rows.append([model, f"{lam:g}"] + cells)
    head = "| model | lambda | " + " | ".join(fields) + " |\n|" + "---|" * (len(fields) + 2) + "\n"
    body = "\n".join("| " + " | ".join(r) + " |" for r in rows)
    exrow = "\n".join(f"| exact | {lam:g} | " + " | ".join(f"{getattr(ex, f)[i]:.6g}" for f in fields) + " |"
                      for i, lam in enumerate(lams))
    dt = time.perf_counter() - t0
    return ("## Model comparison\n\nEach model against direct integration (exact) at the paper's "
            "lambdas: value (relative error). `-`: the model does not give the field; `n/a`: lambda "
            "outside the model's range (oneway needs xi = 2 lambda int F_Hertz^2 <= 1). hertz, "
            "hunter and reed ignore lambda. The HAM models' xi is 2I - I^2 (Eq. 69) with their "
            "own impulse I; for the exact solution I = 1 + e, so xi = 1 - e^2 lies in [0, 1], "
            "but an approximate impulse breaks that identity, and xi turns negative where the "
            f"model's I exceeds 2 (ham1 near lambda = 0, where its I is 2.07). ({seconds(dt)})\n\n"
            + head + exrow + "\n" + body)


BEGIN = "<!-- ham-envelopes:begin (zener-sym regen ham-envelopes) -->"
END = "<!-- ham-envelopes:end -->"


def update_doc(text: str, table: str) -> str:
    """``text`` (docs/ham.md) with the block between :data:`BEGIN` and :data:`END` replaced by
    ``table``; ValueError when the markers are missing."""
    if BEGIN not in text or END not in text:
        raise ValueError(f"the document lacks the marker lines {BEGIN!r} / {END!r}")
    i, j = text.index(BEGIN) + len(BEGIN), text.index(END)
    return text[:i] + "\n" + table + "\n" + text[j:]
