"""Stand-in models for the selection tests: exact, perturbed by a known relative error."""
import time

from zener_sym.models import REGISTRY
from zener_sym.models.base import Model


class Perturbed(Model):
    """Exact results times (1 + eps) (lam untouched); optionally slowed down by ``sleep`` s."""

    options = ()

    def __init__(self, name, eps, lam_bound=None, sleep=0.0):
        self.name, self.eps, self.lam_bound, self.sleep = name, eps, lam_bound, sleep
        ex = REGISTRY["exact"]
        self.summary_fields, self.history_fields = ex.summary_fields, ex.history_fields
        self.description = f"exact x (1 + {eps:g}) (test stand-in)"

    def _summary(self, lam, **options):
        time.sleep(self.sleep)
        out = REGISTRY["exact"]._summary(lam)
        return {k: (v if k == "lam" else v * (1 + self.eps)) for k, v in out.items()}

    def _history(self, lam, tau, **options):
        out = REGISTRY["exact"]._history(lam, tau)
        return {k: v * (1 + self.eps) for k, v in out.items()}
