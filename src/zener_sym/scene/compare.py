"""``compare``: every model that accepts an impact, side by side, with its error against exact."""
from __future__ import annotations

import csv
import math
import numbers
from pathlib import Path

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

    def __init__(self, model: str, values: dict, errors: dict):
        self.model = model
        self.values = values
        self.errors = errors

    def __getattr__(self, name):
        values = self.__dict__.get("values", {})
        if name in values:
            return values[name]
        raise AttributeError(f"model {self.__dict__.get('model')!r} gives no {name!r} here; "
                             f"it gives: {', '.join(values) or 'nothing'}")

    def __repr__(self):
        body = ", ".join(f"{k}={v:.6g}" for k, v in self.values.items())
        return f"ComparisonRow(model={self.model!r}, {body})"


class Comparison:
    """Models side by side for one impact (see :func:`compare`). Iterating yields the rows.

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

    def __init__(self, lam: float, quantities: tuple, rows: list, units: dict):
        self.lam = lam
        self.quantities = quantities
        self.rows = rows
        self._units = units

    def __iter__(self):
        return iter(self.rows)

    def __len__(self):
        return len(self.rows)

    def __getitem__(self, model: str) -> ComparisonRow:
        for r in self.rows:
            if r.model == model:
                return r
        raise KeyError(f"no row for model {model!r}; rows: {', '.join(r.model for r in self.rows)}")

    def _header(self, q):
        unit = self._units.get(q)
        return f"{q} [{unit}]" if unit else q

    def to_markdown(self) -> str:
        """A markdown table: one row per model, each cell ``value (relative error)``; a
        quantity the model cannot give is shown as a dash."""
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

    def records(self) -> list:
        """One dict per model: ``model``, each quantity and ``<quantity>_rel_error`` (None where
        absent)."""
        out = []
        for r in self.rows:
            rec = {"model": r.model}
            for q in self.quantities:
                rec[q] = r.values.get(q)
                rec[f"{q}_rel_error"] = r.errors.get(q)
            out.append(rec)
        return out

    def to_csv(self, path) -> Path:
        """Write :meth:`records` as CSV (absent values are empty cells); returns the path."""
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

    def to_pandas(self):
        """The records as a ``pandas.DataFrame`` indexed by model (pandas is optional)."""
        try:
            import pandas as pd
        except ImportError:
            raise ImportError("Comparison.to_pandas needs pandas, an optional dependency: "
                              "pip install pandas") from None
        return pd.DataFrame(self.records()).set_index("model")


def _rel_error(value, ref):
    if value == ref:
        return 0.0
    if ref == 0:
        return None
    return abs(value - ref) / abs(ref)


def compare(lam_or_scene, models=None, quantities=None) -> Comparison:
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

    scene = lam_or_scene if callable(getattr(lam_or_scene, "summary", None)) else None
    if scene is None:
        if isinstance(lam_or_scene, bool) or not isinstance(lam_or_scene, numbers.Real):
            raise ValueError(f"compare takes one lambda (a number >= 0) or a Scene, got "
                             f"{lam_or_scene!r}")
        lam = float(as_lambda(lam_or_scene))
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
        names = [n for n, m in REGISTRY.items() if bool(m.valid(lam))]
    else:
        names = [models] if isinstance(models, str) else list(models)
        for n in names:
            if n not in REGISTRY:
                raise ValueError(f"unknown model {n!r}; allowed: {', '.join(REGISTRY)}")
    names = ["exact"] + [n for n in names if n != "exact"]

    def values_of(name):
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
