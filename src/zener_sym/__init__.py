"""zener-sym: Zener's sphere-plate impact, its homotopy-analysis solution re-derived with SymPy,
and numeric kernels generated from that derivation.

    >>> import zener_sym as zs
    >>> s = zs.summary(1.01, model="exact")
    >>> round(s.e, 6)
    0.180735
"""
from .api import History, Summary, history, lam_for, summary
from .models import REGISTRY, FieldUnavailableError
from .scene.checks import ZenerWarning
from .scene.grains import GrainImpact, grain_impact, viscoelastic_lambda
from .scene.materials import ALUMINIUM, GLASS, PRESETS, STEEL, TABLE1_PLATE, TABLE1_SPHERE, Material
from .scene.scene import Scene, SceneResult
from .scene.select import Selection, select_model
from .scene.compare import Comparison, compare
from .scene.stress_waves import stress_wave_k, stress_wave_loss

__version__ = "0.2.0"


def __getattr__(name):
    # MODELS reflects the registry at the time of asking, so later plug-ins show up.
    if name == "MODELS":
        return tuple(REGISTRY)
    raise AttributeError(f"module 'zener_sym' has no attribute {name!r}")


__all__ = ["summary", "history", "lam_for", "Summary", "History", "MODELS", "FieldUnavailableError",
           "Material", "Scene", "SceneResult", "select_model", "Selection", "ZenerWarning",
           "STEEL", "GLASS", "ALUMINIUM", "TABLE1_SPHERE", "TABLE1_PLATE", "PRESETS",
           "compare", "Comparison", "__version__",
           "viscoelastic_lambda", "grain_impact", "GrainImpact", "stress_wave_k", "stress_wave_loss"]
