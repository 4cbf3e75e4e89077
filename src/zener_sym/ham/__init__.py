"""Numerics behind the homotopy-analysis (HAM) kernels.

The kernels: the generated formulas (``zener_sym.generated.ham0_*``, ``ham1_*``) wrapped in
plain runtime code, once per backend (the numerical primitives come from ``zener_sym.numerics``):

- :mod:`.runtime_numpy`: ``ham0``, ``ham1`` in float64 numpy (checks, broadcasting, square-root
  integrals by Gauss-Jacobi quadrature, roots, contact integrals);
- :mod:`.runtime_mpmath`: ``ham0``, ``ham1`` at any precision (guard digits, 2F1 closed forms,
  findroot).

Built on top of the generated kernels:

- :mod:`.spectral`: per-lambda Chebyshev series of the first-order solution (ham1's fast path);
- :mod:`.higher`: orders beyond the first, with Liao's c0: the paper's homotopy (orders 1-2) and a
  strained-time homotopy (orders 1-8) (the model ``ham``, docs/ham_convergence.md);
- :mod:`.kernel_check`: the numpy kernels against the mpmath ones (``python -m
  zener_sym.ham.kernel_check``).
"""
