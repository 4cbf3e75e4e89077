"""zener-sym: Zener's sphere-plate impact, its homotopy-analysis solution re-derived with SymPy,
and numeric kernels generated from that derivation.

What ``dir(zener_sym)`` lists is ``__all__``, the documented public names (PEP 562 ``__dir__``);
the subpackages (``zener_sym.exact``, ``zener_sym.models``, ...) stay importable by their full
names.

    >>> import zener_sym as zs
    >>> s = zs.summary(1.01, model="exact")
    >>> round(s.e, 6)
    0.180735
"""
from __future__ import annotations

from . import models as _models
from .api import History, Summary, history, lam_for, lam_from_summary, summary
from .models import FieldUnavailableError
from .scene.calibrate import DissipationFit, dissipation_for, fit_dissipation, thickness_for
from .scene.checks import ZenerWarning
from .scene.compare import Comparison, compare
from .scene.grains import GrainImpact, grain_impact, lam_from_dissipation, viscoelastic_lambda
from .scene.materials import ALUMINIUM, GLASS, PRESETS, STEEL, TABLE1_PLATE, TABLE1_SPHERE, Material
from .scene.scene import Scene, SceneResult
from .scene.select import Selection, select_model
from .scene.stress_waves import stress_wave_k, stress_wave_loss

__version__ = "0.2.0"

#: Deprecated names, importable for one more release (each warns): not in ``__all__``.
DEPRECATED = ("lam_for", "viscoelastic_lambda")

__all__ = ["summary", "history", "lam_from_summary", "Summary", "History", "MODELS",
           "FieldUnavailableError",
           "Material", "Scene", "SceneResult", "select_model", "Selection", "ZenerWarning",
           "STEEL", "GLASS", "ALUMINIUM", "TABLE1_SPHERE", "TABLE1_PLATE", "PRESETS",
           "compare", "Comparison", "__version__",
           "lam_from_dissipation", "grain_impact", "GrainImpact", "stress_wave_k",
           "stress_wave_loss",
           "dissipation_for", "thickness_for", "fit_dissipation", "DissipationFit"]


def __getattr__(name: str) -> tuple[str, ...]:
    # MODELS reflects the registry at the time of asking, so later plug-ins show up.
    if name == "MODELS":
        return tuple(_models.REGISTRY)
    raise AttributeError(f"module 'zener_sym' has no attribute {name!r}")


def __dir__() -> list[str]:
    # What tab completion and dir() show is what is documented (issue 26): the public names,
    # not the modules imported along the way (api, params, scene, ...).
    return sorted(__all__)
