"""Where the elements are: the reference mesh and its ALE map to the contact edge.

A mesh is its reference vertices 0 = xi_0 < xi_1 < ... < xi_n = 1. Without a
contact edge the elements sit where the reference puts them (r = xi). With the
edge-fitted contact of ``fitted`` the first element is the contact zone and
vertex 1 follows the Lagrangian contact radius a, by the piecewise-affine map

    r(xi; a) = a xi / xi_1                              (xi <= xi_1: contact zone [0, a])
    r(xi; a) = a + (1 - a) (xi - xi_1) / (1 - xi_1)     (xi >= xi_1: free part [a, 1]).

Each element stays affine, so the solution is smooth inside every element for
every a: the curvature jump of the meridian at the edge sits on a vertex. The
mesh velocity V = dr/da at fixed xi is linear in r on each side,

    V = r / a,  V' = 1/a            in the contact zone,
    V = (1 - r)/(1 - a),  V' = -1/(1 - a)   on the free part,

and the element lengths scale as dL_e/da = L_e V'. (``kernel`` turns V into the
derivative of the residual with respect to a.) One contact element suffices:
there the solution is the uniform equibiaxial stretch rho = lambda_c r, eta = h,
which P1 and P2 represent exactly, so every other element resolves the free part.

On a curved indenter (``obstacle``) the contact zone is not uniform: vertex k follows a instead,
r = a xi / xi_k on the first k elements (``contact_elements``: a quarter of the mesh), so that
V = r / a and V' = 1/a on all of them.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from .reference import Reference

__all__ = ["Placement", "contact_elements", "evaluate", "node_radii", "place"]


@dataclasses.dataclass(frozen=True, eq=False)
class Placement:
    """The physical elements.

    vertices: r at the vertices, shape (n + 1,); lengths: L_e, shape (n,);
    r: radii of the quadrature points, shape (n, Q); a: the contact radius the
    first vertex follows (None: no ALE map); velocity: dr/da at the
    quadrature points, shape (n, Q), and stretch_rate: V' = (dL_e/da)/L_e,
    shape (n,) (both None without the map).
    """

    vertices: np.ndarray
    lengths: np.ndarray
    r: np.ndarray
    a: float | None = None
    velocity: np.ndarray | None = None
    stretch_rate: np.ndarray | None = None


def _vertices(xi: np.ndarray, a: float, k: int) -> np.ndarray:
    r = a + (1.0 - a) * (xi - xi[k]) / (1.0 - xi[k])
    if k > 1:
        r[1:k] = a * (xi[1:k] / xi[k])
    r[0], r[k], r[-1] = 0.0, a, 1.0
    return r


def contact_elements(elements: int) -> int:
    """The number k of elements a curved indenter's contact zone [0, a] holds (``obstacle``): a quarter of
    the mesh, at least one."""
    return max(1, elements // 4)


def place(xi: np.ndarray, ref: Reference, a: float | None = None, k: int = 1) -> Placement:
    """The elements of the reference mesh ``xi``, fitted to the contact radius ``a`` if given, vertex ``k``
    following it (the first ``k`` elements map onto the contact zone [0, a], r = a xi / xi_k there)."""
    vertices = xi if a is None else _vertices(xi, a, k)
    lengths = np.diff(vertices)
    r = vertices[:-1, None] + lengths[:, None] * ref.t[None, :]
    if a is None:
        return Placement(vertices, lengths, r)
    rate = np.full(lengths.shape, -1.0 / (1.0 - a))
    rate[:k] = 1.0 / a
    velocity = (1.0 - r) / (1.0 - a)
    velocity[:k] = r[:k] / a
    return Placement(vertices, lengths, r, a, velocity, rate)


def node_radii(placement: Placement, ref: Reference) -> np.ndarray:
    """r at every node (vertices and, for P2, midpoints), in global node order, shape (p n + 1,)."""
    p, v = ref.order, placement.vertices
    out = np.empty(p * (v.size - 1) + 1)
    out[::p] = v
    if p == 2:
        out[1::2] = 0.5 * (v[:-1] + v[1:])
    return out


def evaluate(placement: Placement, ref: Reference, u: np.ndarray, points: np.ndarray) -> np.ndarray:
    """The finite-element function with nodal dofs ``u`` (shape (2 (p n + 1),)) at ``points``, shape (k, 2)."""
    p, v = ref.order, placement.vertices
    e = np.clip(np.searchsorted(v, points, side="right") - 1, 0, v.size - 2)
    t = (points - v[e]) / placement.lengths[e]
    nodal = u.reshape(-1, 2)[p * e[:, None] + np.arange(p + 1)]  # (k, p + 1, 2)
    return np.einsum("ka,kac->kc", ref.values(t), nodal)
