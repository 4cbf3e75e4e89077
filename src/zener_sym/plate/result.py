"""What the finite-plate solver returns: one row per contact, and the impact's outcome."""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..typing import FloatArray

__all__ = ["PlateContact", "PlateImpact", "CONTACT_FIELDS"]

#: The fields of one contact that are extrapolated and carry an error estimate.
CONTACT_FIELDS = ("start", "end", "max_force_time", "max_force", "impulse", "speed_after",
                  "plate_energy")


@dataclass(frozen=True)
class PlateContact:
    """One contact, in Zener's scales (tau = t / t_0, F-bar = F / (k delta_0^{3/2})).

    Attributes
    ----------
    start, end : float
        tau at the contact's start (delta = 0 and rising) and end (delta back to 0).
    max_force_time, max_force : float
        tau and F-bar at the force's maximum (``max_force_N`` of the CLI's contacts, in Zener's
        scales).
    impulse : float
        The contact's impulse (integral of F-bar over the contact), in units of m v_0.
    speed_after : float
        The ball's speed after the contact, in units of v_0, positive away from the plate.
    plate_energy : float
        The plate's energy at the contact's end, as a fraction of the ball's initial kinetic
        energy m v_0^2 / 2.
    """

    start: float
    end: float
    max_force_time: float
    max_force: float
    impulse: float
    speed_after: float
    plate_energy: float


@dataclass(frozen=True)
class PlateImpact:
    """The sphere's impact on a modal plate: every contact, to the proved end.

    Attributes
    ----------
    contacts : tuple of PlateContact
        One row per contact, in time order.
    e : float
        The coefficient of restitution: the ball's speed after the last contact over v_0.
    plate_energy : float
        The plate's energy at the last separation, as a fraction of the initial kinetic energy
        (undamped: it stays so forever; with a loss factor it decays afterwards).
    error : float
        Estimated absolute error of ``e`` (the difference of two Richardson extrapolations).
    errors : tuple of dict
        Per contact, the estimated absolute error of each field of ``CONTACT_FIELDS``.
    end_time : float
        tau at which the end was proved: the ball, moving away, is beyond
        sqrt(2 E_p C_N) >= any deflection the free plate can reach.
    h : float
        The finest step of the grid (tau units; the extrapolation used h, 2h and 4h).
    n_modes : int
        Modes in the model (those above are the static correction C_res).
    loss : float
        The modal loss factor eta.
    rtol : float
        The requested relative tolerance on e.
    force_time, force : ndarray
        The force history on the finest grid (not extrapolated): the node times of every
        contact followed by its end, and the force there (0 at each start and end); the solver's
        force is linear between them and 0 between contacts.
    """

    contacts: tuple[PlateContact, ...]
    e: float
    plate_energy: float
    error: float
    errors: tuple[dict[str, float], ...]
    end_time: float
    h: float
    n_modes: int
    loss: float
    rtol: float
    force_time: FloatArray = field(default_factory=lambda: np.zeros(0), compare=False,
                                   repr=False)
    force: FloatArray = field(default_factory=lambda: np.zeros(0), compare=False, repr=False)

    @property
    def n_contacts(self) -> int:
        """How many contacts (sub-impacts) the impact had."""
        return len(self.contacts)
