r"""Finite elements in r for the axisymmetric Kirchhoff plate on the unit disc (the second method's
space discretisation; no modal expansion anywhere).

The plate is the unit disc 0 <= s <= 1 (s = r/b) with unit flexural rigidity and unit mass per
area. Its axisymmetric bending energy and kinetic energy are

    U = (1/2) int_0^1 [ w_ss^2 + (w_s/s)^2 + 2 nu w_ss w_s / s ] 2 pi s ds,
    T = (1/2) int_0^1 w_t^2 2 pi s ds,

the first being (1/2) int [(w_ss + w_s/s)^2 - 2 (1 - nu) w_ss w_s / s] dA: the total curvature
squared less (1 - nu) times twice the Gaussian curvature kappa_r kappa_theta. The Gaussian term
integrates to nu w_s(1)^2 / 2 times 2 pi (w_s(0) = 0 by regularity), so it only matters where
the edge may rotate: it is what makes the simply supported edge's natural condition the vanishing
moment M_r = -(w_ss + nu w_s / s) = 0. A point force F at the centre does the work F w(0).

Elements: Hermite cubics on each [s_i, s_{i+1}], degrees of freedom (w, w_s) at every node,
ordered (w_0, w_s0, w_1, w_s1, ...). The constraints are removed: w_s(0) = 0 (regular centre),
w(1) = 0 (both supports) and w_s(1) = 0 (clamped). After removing w_s(0), every remaining shape
function on the first element has zero slope at s = 0, so w_s / s is a polynomial there and the
Gauss rule is exact; on the other elements 1/s is analytic on the element and 16 Gauss points
integrate it to round-off. The centre deflection is the first unknown.
"""
from __future__ import annotations

import dataclasses

import numpy as np
import scipy.linalg
import scipy.sparse

from ..typing import FloatArray

__all__ = ["SUPPORTS", "AxisymmetricPlateFE", "plate_fe", "graded_nodes", "upper_band"]

#: The edge supports of the circular plate.
SUPPORTS = ("clamped", "simply-supported")

_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(16)


def graded_nodes(n_elements: int, grading: float = 2.0) -> FloatArray:
    """Nodes 0 = s_0 < ... < s_n = 1, refined towards the centre, where the point load's
    deflection has its s^2 log s singularity: s_i = (i/n)^grading near 0, blended into uniform
    spacing so that no element is much longer than 1/n.

    Parameters
    ----------
    n_elements : int
        Number of elements n >= 2.
    grading : float
        Exponent >= 1 of the centre refinement (1: uniform).

    Returns
    -------
    ndarray, shape (n + 1,)
    """
    if int(n_elements) != n_elements or n_elements < 2:
        raise ValueError(f"n_elements must be an integer >= 2, got {n_elements!r}")
    if not grading >= 1.0:
        raise ValueError(f"grading must be >= 1, got {grading!r}")
    t = np.linspace(0.0, 1.0, int(n_elements) + 1)
    # t1 (t/t1)^g on the inner tenth of the index range, continued by its tangent line (slope g)
    t1 = 0.1
    s = np.where(t < t1, t1 * (t / t1) ** grading, t1 + grading * (t - t1))
    return np.asarray(s / s[-1], dtype=float)


def _hermite(xi: FloatArray, h: float) -> tuple[FloatArray, FloatArray, FloatArray]:
    """The four Hermite cubics on an element of length h at local points xi in [0, 1], with their
    first and second derivatives in s (rows: w_a, slope_a, w_b, slope_b)."""
    n = np.array([1 - 3 * xi**2 + 2 * xi**3, h * (xi - 2 * xi**2 + xi**3),
                  3 * xi**2 - 2 * xi**3, h * (-xi**2 + xi**3)])
    d1 = np.array([-6 * xi + 6 * xi**2, h * (1 - 4 * xi + 3 * xi**2),
                   6 * xi - 6 * xi**2, h * (-2 * xi + 3 * xi**2)]) / h
    d2 = np.array([-6 + 12 * xi, h * (-4 + 6 * xi), 6 - 12 * xi, h * (-2 + 6 * xi)]) / h**2
    return n, d1, d2


def _element(sa: float, sb: float, nu: float) -> tuple[FloatArray, FloatArray]:
    """Element stiffness and mass (4 x 4) of [sa, sb], the 2 pi s weight included."""
    h = sb - sa
    xi = 0.5 * (_GAUSS_X + 1.0)
    s = sa + h * xi
    wq = 0.5 * h * _GAUSS_W * 2.0 * np.pi * s
    n, d1, d2 = _hermite(xi, h)
    q = d1 / s  # w_s / s
    k = (d2 * wq) @ d2.T + (q * wq) @ q.T + nu * ((d2 * wq) @ q.T + (q * wq) @ d2.T)
    m = (n * wq) @ n.T
    return k, m


@dataclasses.dataclass(frozen=True)
class AxisymmetricPlateFE:
    """The assembled unit-disc plate, M w_tt + K w = F e_0 (unit rigidity, mass per area, radius).

    Attributes
    ----------
    nodes : ndarray
        The mesh nodes in s = r/b.
    support : str
        The edge support.
    nu : float
        Poisson's ratio.
    stiffness, mass : scipy.sparse.csr_matrix
        K and M (symmetric, bandwidth 3), constraints removed; unknown 0 is the centre deflection.
    """

    nodes: FloatArray
    support: str
    nu: float
    stiffness: scipy.sparse.csr_matrix
    mass: scipy.sparse.csr_matrix

    @property
    def n_dof(self) -> int:
        """Number of unknowns; the centre deflection is unknown 0."""
        return int(self.stiffness.shape[0])

    def static_compliance(self) -> float:
        """e_0^T K^-1 e_0: the centre deflection under a unit centre load."""
        rhs = np.zeros(self.n_dof)
        rhs[0] = 1.0
        return float(scipy.linalg.solveh_banded(upper_band(self.stiffness), rhs)[0])

    def frequencies(self, count: int) -> FloatArray:
        """The lowest ``count`` axisymmetric angular frequencies (k b)^2 of the discrete plate."""
        vals = scipy.linalg.eigh(self.stiffness.toarray(), self.mass.toarray(),
                                 eigvals_only=True, subset_by_index=[0, count - 1])
        return np.asarray(np.sqrt(vals), dtype=float)


def upper_band(a: scipy.sparse.spmatrix, width: int = 3) -> FloatArray:
    """A symmetric banded matrix in LAPACK's upper band storage (``scipy.linalg.solveh_banded``:
    row ``width - o`` holds the o-th superdiagonal)."""
    n = a.shape[0]
    out = np.zeros((width + 1, n))
    for off in range(width + 1):
        out[width - off, off:] = a.diagonal(off)
    return out


def plate_fe(support: str, nu: float = 0.3, n_elements: int = 200,
             grading: float = 2.0) -> AxisymmetricPlateFE:
    """Assemble the Hermite-cubic plate on the unit disc with the support's constraints removed.

    Parameters
    ----------
    support : {"clamped", "simply-supported"}
        The edge support at s = 1.
    nu : float
        Poisson's ratio, -1 < nu < 0.5 (enters the simply supported edge only).
    n_elements : int
        Number of elements.
    grading : float
        Centre refinement exponent of :func:`graded_nodes`.

    Returns
    -------
    AxisymmetricPlateFE
    """
    if support not in SUPPORTS:
        raise ValueError(f"unknown support {support!r}; allowed: {', '.join(SUPPORTS)}")
    if not -1.0 < nu < 0.5:
        raise ValueError(f"nu (Poisson's ratio) must satisfy -1 < nu < 0.5, got {nu!r}")
    nodes = graded_nodes(n_elements, grading)
    rows, cols, kv, mv = [], [], [], []
    idx = np.add.outer(np.arange(4), np.zeros(4, dtype=int))
    for e in range(len(nodes) - 1):
        k, m = _element(float(nodes[e]), float(nodes[e + 1]), nu)
        rows.append((2 * e + idx).ravel())
        cols.append((2 * e + idx.T).ravel())
        kv.append(k.ravel())
        mv.append(m.ravel())
    n_full = 2 * len(nodes)
    r, c = np.concatenate(rows), np.concatenate(cols)
    keep = np.ones(n_full, dtype=bool)
    keep[1] = False  # w_s(0) = 0: regular centre
    keep[n_full - 2] = False  # w(1) = 0
    if support == "clamped":
        keep[n_full - 1] = False  # w_s(1) = 0
    sel = np.flatnonzero(keep)

    def assemble(v: list[FloatArray]) -> scipy.sparse.csr_matrix:
        full = scipy.sparse.csr_matrix((np.concatenate(v), (r, c)), shape=(n_full, n_full))
        return full[sel][:, sel].tocsr()

    return AxisymmetricPlateFE(nodes, support, float(nu), assemble(kv), assemble(mv))
