"""Numerical primitives: one module per topic, each primitive defined once.

- :mod:`.chebyshev`: Chebyshev points, coefficients (DCT-II), trimming, monomial conversion, and
  the pointwise evaluators (Clenshaw, Horner) that take each point's coefficient row by index.
- :mod:`.maps`: the smoothstep map v^2 (3 - 2 v), its slope and its inverse.
- :mod:`.integrate`: integrals over a contact with the smoothstep map (Gauss-Legendre per point,
  or one Chebyshev antiderivative per row).
- :mod:`.roots`: the first sign change of a vectorised function, by scan and bisection.
- :mod:`.elementary`: P3(x) = (sin x - x cos x) / x^3 and the sine's first half wave, stably.
- :mod:`.sqrt_integrals`: the square-root integrals K_g of the first-order HAM solution by
  Gauss-Jacobi quadrature, and the K_s series.
- :mod:`.mp`: the mpmath twins (P3, the contact integral).
- :mod:`.blocks`: the memory layout of a history (blocks of points, one allocation).

The package imports nothing of zener_sym outside itself, so every layer above can use it
(tests/test_architecture.py checks it).
"""
