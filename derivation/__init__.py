"""SymPy re-derivation of the homotopy-analysis solution of Zener's impact equation.

Installed as ``zener_sym.derivation``. Offline code: nothing in the runtime path imports it.
"""
