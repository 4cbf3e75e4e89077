"""Code emitted by ``zener-sym regen kernels`` from ``zener_sym.derivation``. Never edit by hand.

Installed as ``zener_sym.generated``.
"""
