"""``compare``: every model that accepts an impact, side by side, with its error against exact."""
from __future__ import annotations

import csv
import math
import numbers
import os
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any, cast

import numpy as np

from ..typing import RealLike

if TYPE_CHECKING:  # for annotations only: scene.py's Scene imports this module's users
    from .scene import Scene

__all__ = ["compare", "Comparison", "ComparisonRow"]


class ComparisonRow:
    """One model's values and relative errors against the exact model.

    Attributes
    ----------
    model : str
    values : dict
        quantity -> value; a quantity the model cannot give is absent.
    errors : dict
        quantity -> |value - exact| / |exact| (0 where both are 0; absent where the model gives
        no value or the exact value is 0 and the model's is not).
    """

    def __init__(self, model: str, values: dict[str, float], errors: dict[str, float]) -> None:
        self.model = model
        self.values = values
        self.errors = errors

    def __getattr__(self, name: str) -> float:
        values = self.__dict__.get("values", {})
        if name in values:
            return float(values[name])
        raise AttributeError(f"model {self.__dict__.get('model')!r} gives no {name!r} here; "
                             f"it gives: {', '.join(values) or 'nothing'}")

    def __repr__(self) -> str:
        body = ", ".join(f"{k}={v:.6g}" for k, v in self.values.items())
        return f"ComparisonRow(model={self.model!r}, {body})"


class Comparison:
    """Models side by side for one impact (see :func:`compare`). Iterating yields the rows.

    Parameters
    ----------
    lam : float
        Zener's lambda of the impact.
    quantities : tuple of str
        The quantities compared, in column order.
    rows : list of ComparisonRow
        One per model, the exact model first.
    units : dict of str to str
        Unit of each SI quantity, for the column headers (empty for a lambda).

    Attributes
    ----------
    lam : float
    quantities : tuple of str
    rows : list of ComparisonRow
        The exact model first, then the others in registry order.

    Examples
    --------
    >>> import zener_sym as zs
    >>> c = zs.compare(0.5, models=["hertz"], quantities=["tau_d"])
    >>> len(c), c["hertz"].tau_d > c["exact"].tau_d * 0.5
    (2, True)
    >>> print(c.to_markdown().splitlines()[2])
    | model | tau_d |
    """

    def __init__(self, lam: float, quantities: tuple[str, ...], rows: list[ComparisonRow],
                 units: dict[str, str]) -> None:
        self.lam = lam
        self.quantities = quantities
        self.rows = rows
        self._units = units

    def __iter__(self) -> Iterator[ComparisonRow]:
        return iter(self.rows)

    def __len__(self) -> int:
        return len(self.rows)

    def __getitem__(self, model: str) -> ComparisonRow:
        for r in self.rows:
            if r.model == model:
                return r
        raise KeyError(f"no row for model {model!r}; rows: {', '.join(r.model for r in self.rows)}")

    def _header(self, q: str) -> str:
        unit = self._units.get(q)
        return f"{q} [{unit}]" if unit else q

    def to_markdown(self) -> str:
        """A markdown table: one row per model, each cell ``value (relative error)``; a
        quantity the model cannot give is shown as a dash.

        Returns
        -------
        str
            A line naming lambda, a blank line, then the table.

        Examples
        --------
        >>> import zener_sym as zs
        >>> c = zs.compare(0.5, models=["hertz"], quantities=["tau_d", "e"])
        >>> print(c.to_markdown())
        lambda = 0.5; relative error against exact in parentheses
        <BLANKLINE>
        | model | tau_d | e |
        |---|---|---|
        | exact | 3.62444 | 0.436895 |
        | hertz | 3.21807 (0.11) | 1 (1.3) |
        """
        head = ["model"] + [self._header(q) for q in self.quantities]
        lines = [f"lambda = {self.lam:.6g}; relative error against exact in parentheses", "",
                 "| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
        for r in self.rows:
            cells = [r.model]
            for q in self.quantities:
                if q not in r.values:
                    cells.append("—")
                    continue
                err = r.errors.get(q)
                tail = "" if r.model == "exact" else (" (n/a)" if err is None else f" ({err:.2g})")
                cells.append(f"{r.values[q]:.6g}{tail}")
            lines.append("| " + " | ".join(cells) + " |")
        return "\n".join(lines)

    def records(self) -> list[dict[str, Any]]:
        """One dict per model: ``model``, each quantity and ``<quantity>_rel_error`` (None where
        absent).

        Returns
        -------
        list of dict
            In row order (the exact model first).

        Examples
        --------
        >>> import zener_sym as zs
        >>> c = zs.compare(0.5, models=["hertz"], quantities=["tau_d", "e"])
        >>> rec = c.records()[1]
        >>> rec["model"], round(rec["tau_d"], 4), round(rec["tau_d_rel_error"], 4)
        ('hertz', 3.2181, 0.1121)
        """
        out = []
        for r in self.rows:
            rec: dict[str, Any] = {"model": r.model}
            for q in self.quantities:
                rec[q] = r.values.get(q)
                rec[f"{q}_rel_error"] = r.errors.get(q)
            out.append(rec)
        return out

    def to_csv(self, path: str | os.PathLike[str]) -> Path:
        """Write :meth:`records` as CSV (absent values are empty cells, floats with 17
        significant digits).

        Parameters
        ----------
        path : str or path-like
            The file to write (replaced if it exists).

        Returns
        -------
        pathlib.Path
            ``path``.

        Raises
        ------
        ValueError
            When the file cannot be written (the reason is in the message).

        Examples
        --------
        >>> import zener_sym as zs
        >>> c = zs.compare(0.5, models=["hertz"], quantities=["tau_d", "e"])
        >>> import pathlib, tempfile
        >>> out = c.to_csv(pathlib.Path(tempfile.mkdtemp()) / "compare.csv")
        >>> out.read_text().splitlines()[0]
        'model,tau_d,tau_d_rel_error,e,e_rel_error'
        """
        path = Path(path)
        recs = self.records()
        try:
            with open(path, "w", newline="", encoding="utf-8") as fh:
                w = csv.DictWriter(fh, fieldnames=list(recs[0]))
                w.writeheader()
                for rec in recs:
                    w.writerow({k: ("" if v is None else (f"{v:.17g}" if isinstance(v, float)
                                                          else v)) for k, v in rec.items()})
        except OSError as exc:
            raise ValueError(f"cannot write {path}: {exc.strerror}") from None
        return path

    def to_pandas(self) -> Any:  # a pandas.DataFrame: pandas is optional and has no stubs here
        """The records as a ``pandas.DataFrame`` indexed by model (pandas is optional).

        Returns
        -------
        pandas.DataFrame
            One row per model; the columns of :meth:`records`.

        Raises
        ------
        ImportError
            When pandas is not installed (``pip install pandas``).

        Examples
        --------
        >>> import zener_sym as zs
        >>> c = zs.compare(0.5, models=["hertz"], quantities=["tau_d", "e"])
        >>> df = c.to_pandas()
        >>> list(df.index), list(df.columns)
        (['exact', 'hertz'], ['tau_d', 'tau_d_rel_error', 'e', 'e_rel_error'])
        """
        try:
            import pandas as pd  # type: ignore[import-untyped]  # optional, no stubs installed
        except ImportError:
            raise ImportError("Comparison.to_pandas needs pandas, an optional dependency: "
                              "pip install pandas") from None
        return pd.DataFrame(self.records()).set_index("model")


def _rel_error(value: float, ref: float) -> float | None:
    if value == ref:
        return 0.0
    if ref == 0:
        return None
    return abs(value - ref) / abs(ref)


def compare(lam_or_scene: RealLike | Scene, models: str | Sequence[str] | None = None,
            quantities: str | Sequence[str] | None = None) -> Comparison:
    """Every model that accepts this impact, side by side, with its relative error against exact.

    Parameters
    ----------
    lam_or_scene : float or Scene
        One lambda (a scalar), or a ``zener_sym.Scene`` (SI quantities).
    models : sequence of str, optional
        Model names (default: every registered model whose validity includes this lambda).
    quantities : sequence of str, optional
        Fields to show (default: every summary field for a lambda; every SI and dimensionless
        field of ``SceneResult`` for a scene).

    Returns
    -------
    Comparison
        Iterating yields one row per model with ``.model`` and the fields it gives; also
        ``to_markdown()``, ``to_csv(path)`` and ``to_pandas()``.

    Raises
    ------
    ValueError
        For a lambda that is not one finite number >= 0, an unknown model or quantity, or a
        model asked for by name whose validity excludes this lambda.

    Examples
    --------
    >>> import zener_sym as zs
    >>> c = zs.compare(1.0, models=["exact", "ham1"], quantities=["e", "tau_d"])
    >>> [row.model for row in c]
    ['exact', 'ham1']
    >>> round(c["ham1"].errors["tau_d"], 3)      # ham1's contact duration, relative error
    0.042
    """
    from ..api import summary
    from ..models import REGISTRY, SUMMARY_FIELDS
    from ..params import as_lambda
    from .scene import SCENE_FIELDS

    scene = (cast("Scene", lam_or_scene) if callable(getattr(lam_or_scene, "summary", None))
             else None)
    units: dict[str, str]
    if scene is None:
        if isinstance(lam_or_scene, bool) or not isinstance(lam_or_scene, numbers.Real):
            raise ValueError(f"compare takes one lambda (a number >= 0) or a Scene, got "
                             f"{lam_or_scene!r}")
        lam = float(as_lambda(cast(float, lam_or_scene)))
        allowed_q = tuple(f for f in SUMMARY_FIELDS if f != "lam")
        units = {}
    else:
        lam = float(scene.lam)
        allowed_q = tuple(f for f, _, _ in SCENE_FIELDS)
        units = {f: u for f, u, _ in SCENE_FIELDS if u != "-"}
    if quantities is None:
        quantities = allowed_q
    else:
        quantities = (quantities,) if isinstance(quantities, str) else tuple(quantities)
        for q in quantities:
            if q not in allowed_q:
                raise ValueError(f"unknown quantity {q!r}; allowed: {', '.join(allowed_q)}")
    if models is None:
        names = [n for n, m in REGISTRY.items() if bool(m.valid(np.asarray(lam)))]
    else:
        names = [models] if isinstance(models, str) else list(models)
        for n in names:
            if n not in REGISTRY:
                raise ValueError(f"unknown model {n!r}; allowed: {', '.join(REGISTRY)}")
    names = ["exact"] + [n for n in names if n != "exact"]

    def values_of(name: str) -> dict[str, float]:
        if scene is not None:
            r = scene.result(model=name, warn=False)
            got = {q: getattr(r, q) for q in quantities}
        else:
            s = summary(lam, model=name)
            got = {q: getattr(s, q) for q in quantities if q in s.fields}
        return {q: float(v) for q, v in got.items() if v is not None and math.isfinite(v)}

    ref = values_of("exact")
    rows = []
    for name in names:
        vals = ref if name == "exact" else values_of(name)
        errs = {q: e for q, v in vals.items()
                if q in ref and (e := _rel_error(v, ref[q])) is not None}
        rows.append(ComparisonRow(name, vals, errs))
    return Comparison(lam, quantities, rows, units)
