"""matplotlib, imported lazily: it is the optional ``plot`` extra (see zener_sym.plot.style)."""


def pyplot():
    from ..plot.style import pyplot as _pyplot

    return _pyplot(headless=True)
