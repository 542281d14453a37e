"""The reference element: Lagrange P1/P2 shape functions and Gauss quadrature on t in [0, 1].

An element [r_e, r_e + L_e] is the affine image r = r_e + L_e t of [0, 1]. Its
local nodes are ordered along r: (vertex, vertex) for P1, (vertex, midpoint,
vertex) for P2, so that node ``a`` of element ``e`` is the global node
p e + a and the 2 (p + 1) local dofs (rho, eta per node, interleaved) are the
contiguous global dofs 2 p e .. 2 p e + 2 p + 1. That layout is what makes the
tangent banded (half-bandwidth 2p + 1) and lets the assembly add whole element
arrays with strided slices.

The shape functions are scikit-fem's (``ElementLineP1``/``ElementLineP2``,
reordered along r) and the rule is scikit-fem's Gauss-Legendre rule with p + 1
points (exact for polynomials of degree 2p + 1): its error in the energy is
O(h^(2p+2)), below the O(h^(2p)) discretisation error of smooth functionals.

``interp`` maps the element dofs (n, 2 (p + 1)) to rho, eta, drho/dt, deta/dt
at the Q points in one matrix product (``kernel.fields``).
"""

from __future__ import annotations

import dataclasses

import numpy as np
from skfem import ElementLineP1, ElementLineP2
from skfem.quadrature import get_quadrature

__all__ = ["Reference", "reference"]

_ALONG_R = {1: (ElementLineP1, (0, 1)), 2: (ElementLineP2, (0, 2, 1))}  # skfem's order: vertices, then midpoint


@dataclasses.dataclass(frozen=True, eq=False)
class Reference:
    """Tables of the reference element of order ``order``.

    t, weights: quadrature points and weights on [0, 1], shape (Q,).
    phi, dphi: shape functions and their t-derivatives at the points, shape (Q, p + 1).
    nodes: the local nodes' positions in t, shape (p + 1,).
    interp: the table of the module docstring, shape (2 (p + 1), 4 Q).
    """

    order: int
    t: np.ndarray
    weights: np.ndarray
    phi: np.ndarray
    dphi: np.ndarray
    nodes: np.ndarray
    interp: np.ndarray

    @property
    def local(self) -> int:
        """Local dofs per element: 2 (p + 1)."""
        return 2 * (self.order + 1)

    def values(self, t: np.ndarray) -> np.ndarray:
        """Shape functions at arbitrary points t of [0, 1], shape (len(t), p + 1)."""
        element, along = _ALONG_R[self.order]
        e = element()
        return np.stack([e.lbasis(np.atleast_2d(t), i)[0] for i in along], axis=-1)


def reference(order: int) -> Reference:
    """The reference tables of P``order`` (1 or 2)."""
    element, along = _ALONG_R[order]
    e = element()
    points, weights = get_quadrature(e.refdom, 2 * order + 1)
    weights = np.asarray(weights, dtype=float)
    phi = np.stack([e.lbasis(points, i)[0] for i in along], axis=-1)
    dphi = np.stack([e.lbasis(points, i)[1][0] for i in along], axis=-1)
    nodes = np.asarray(e.doflocs)[list(along), 0]
    q, k = weights.size, order + 1
    interp = np.zeros((2 * k, 4 * q))
    for c in range(2):
        interp[c::2, c * q:(c + 1) * q] = phi.T
        interp[c::2, (2 + c) * q:(3 + c) * q] = dphi.T
    return Reference(order, points[0].copy(), weights, phi, dphi, nodes, interp)
