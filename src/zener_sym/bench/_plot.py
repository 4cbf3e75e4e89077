"""matplotlib, imported lazily: it is the optional ``plot`` extra."""


def pyplot():
    try:
        import matplotlib
    except ImportError:
        raise ImportError("charts need matplotlib: pip install 'zener-sym[plot]'") from None
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt
