"""Charts in the package's one style (:mod:`zener_sym.plot.style`): ``force_history`` and
``restitution``. Needs the optional ``[plot]`` extra (matplotlib), imported only when drawing."""
from .curves import force_history, restitution
from .style import style_for

__all__ = ["force_history", "restitution", "style_for"]
