"""Numerics behind the homotopy-analysis (HAM) kernels.

The generated kernels (``zener_sym.generated``) call the leaf helpers here, which import nothing
else of the package:

- :mod:`.quadrature`: Gauss-Jacobi quadrature of the square-root integrals (float64);
- :mod:`.chebyshev`: Chebyshev nodes, series, antiderivatives and the ``p3`` helper;
- :mod:`.mp`: their mpmath counterparts.

Built on top of the generated kernels:

- :mod:`.spectral`: per-lambda Chebyshev series of the first-order solution (ham1's fast path);
- :mod:`.higher`: orders beyond the first, with Liao's c0: the paper's homotopy (orders 1-2) and a
  strained-time homotopy (orders 1-8) (the model ``ham``, docs/ham_convergence.md);
- :mod:`.kernel_check`: the numpy kernels against the mpmath ones (``zener-sym regen
  kernel-check``).
"""
