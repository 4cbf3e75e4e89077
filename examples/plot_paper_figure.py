"""
One of the paper's figures
==========================

``zener-sym figures`` redraws the paper's Figs. 3-15 against the exact solution
(docs/figures.md). Each figure is a :class:`~zener_sym.figures.data.FigureSpec` in
:data:`zener_sym.figures.FIGURES`: its ``compute`` gives the curves as rows
``(panel, series, x, y, error)``, and :func:`zener_sym.figures.draw.draw` draws them in the package
style. Here Fig. 15, the coefficient of restitution, on the coarse grid the tests use.
"""
from zener_sym.figures import FIGURES
from zener_sym.figures.draw import draw
from zener_sym.plot import style

spec = FIGURES[15]
print(spec.caption)
rows = spec.compute(True)  # coarse=True: fewer points, same curves
print(f"{len(rows)} rows; series: {sorted({r[1] for r in rows})}")

with style.rc() as plt:
    fig = draw(spec, rows, plt)
