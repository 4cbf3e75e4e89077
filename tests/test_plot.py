"""The chart style and the public plot functions."""
import doctest
import os
import subprocess
import sys

import numpy as np
import pytest

import zener_sym as zs

pytest.importorskip("matplotlib")
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from zener_sym.plot import calibration, curves, force_history, restitution, style  # noqa: E402


@pytest.mark.parametrize("module", [style, curves, calibration])
def test_docstring_examples_run(module):
    res = doctest.testmod(module, optionflags=doctest.ELLIPSIS)
    assert res.attempted > 0 and res.failed == 0


def test_every_model_has_its_own_fixed_style():
    missing = [m for m in zs.MODELS if m not in style.MODEL_STYLES]
    assert not missing
    colours = [style.style_for(m)["color"] for m in zs.MODELS]
    assert len(set(colours)) == len(colours)
    # fixed: a model's style is its table entry, and an unknown name gets the same style in
    # another process with another hash seed, after other names were styled there first
    assert style.style_for("ham1")["color"] == style.MODEL_STYLES["ham1"][0]
    code = ("from zener_sym.plot import style; [style.style_for(n) for n in ('a', 'b', 'c')]; "
            "print(repr(style.style_for('something new')))")
    env = {**os.environ, "PYTHONHASHSEED": "12345"}
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                         check=True).stdout
    assert out.strip() == repr(style.style_for("something new"))
    assert style.style_for("exact, solve_ivp DOP853")["color"] == style.METHOD_STYLES["DOP853"][0]


def test_missing_matplotlib_names_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    with pytest.raises(ImportError, match=r"\[plot\]"):
        style.pyplot()


def test_force_history_lambda_draws_the_api_values():
    ax = force_history(0.5, model=("ham1", "linear"))
    lines = ax.get_lines()
    assert [ln.get_label() for ln in lines][0] == style.MODEL_STYLES["exact"][3]
    tau = lines[1].get_xdata()
    assert np.allclose(lines[1].get_ydata(), zs.history(0.5, tau, model="ham1").force)
    assert ax.get_legend() is not None
    plt.close("all")


def test_force_history_scene_in_microseconds_and_newtons():
    sc = zs.Scene("steel", "glass", 1e-3, 2e-3, 1.0)
    ax = force_history(sc, model="ham1")
    assert "µs" in ax.get_xlabel() and "N" in ax.get_ylabel()
    t_us = ax.get_lines()[0].get_xdata()
    res = sc.result(model="exact", warn=False)
    assert np.allclose(ax.get_lines()[0].get_ydata(), res.force(t_us * 1e-6))
    plt.close("all")


def test_force_history_bad_input():
    with pytest.raises(ValueError):
        force_history([0.1, 0.2])
    with pytest.raises(ValueError):
        force_history(0.1, model=())
    with pytest.raises(ValueError, match="unknown model"):
        force_history(0.1, model="nope")
    plt.close("all")


def test_restitution_curves_stop_at_each_models_bound():
    fig, ax = plt.subplots()
    out = restitution(models=("exact", "raman", "linear"), ax=ax)
    assert out is ax
    ex, ra, li = ax.get_lines()
    assert np.allclose(ex.get_ydata(), zs.summary(ex.get_xdata()).e)
    assert ra.get_xdata().max() < 1 / 1.73 and li.get_xdata().max() <= 2.4
    plt.close(fig)


def test_figure_legend_from_handles_alone_takes_their_labels():
    # handles without labels raised a TypeError from len(None) (found by typing, issue 26);
    # an axes' legend takes the handles' own labels, and so does a figure's now
    fig, (a, b) = plt.subplots(1, 2)
    la, = a.plot([0, 1], [0, 1], label="first")
    lb, = b.plot([0, 1], [1, 0], label="second")
    b.plot([0, 1], [1, 1], label="not listed")
    for ncol in (None, 1):
        leg = style.legend_outside(fig, handles=[lb, la], ncol=ncol)
        assert [t.get_text() for t in leg.get_texts()] == ["second", "first"]
        assert leg.legend_handles[0].get_color() == lb.get_color()
    leg = style.legend_outside(fig, handles=[la], labels=["renamed"])
    assert [t.get_text() for t in leg.get_texts()] == ["renamed"]
    plt.close(fig)
