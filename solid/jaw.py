r"""The clamp's upper jaw: a rigid, frictionless obstacle with a rounded edge, touched by the upper surface.

The sheet is clamped between two rigid jaws at r >= R. As the pocket inflates it leaves the clamp bent
upwards and wraps around the upper jaw's edge, its upper surface on the inside of the bend. Without the jaw
the solid's upper corner is free: its nodes move past r = R above the sheet, into what would be the jaw,
and the corner element folds (``mesh``, ``newton``). With it (the option ``clamp_radius``, rc in
thicknesses T; default ``DEFAULT_CLAMP_RADIUS``, 0 for no jaw) the upper surface's nodes may not enter the jaw.

Geometry (units R, t = T/R, a = rc t the edge's radius). The jaw's lower face is z = t/2 for r >= 1 (the
flat sheet's upper surface, clamped there); its edge is the quarter circle of radius a tangent to that face
at r = 1, centre c = (1, t/2 + a), from (1, t/2) to (1 - a, t/2 + a), and above it the jaw's side face
r = 1 - a. The jaw is the quadrant {r >= 1 - a, z >= t/2} with its corner rounded so. The gap of an
upper-surface node x = (rho, z) is its signed distance to the jaw's boundary (>= 0 outside), by the region
it lies in:

    edge (rho <= 1, z <= t/2 + a):  g = d - a,        grad_x g = n = (x - c) / d,  d2g/dx2 = (I - n n^T) / d,
    side (rho <= 1, z > t/2 + a):   g = 1 - a - rho,  grad_x g = (-1, 0),          d2g/dx2 = 0,
    face (rho > 1):                 g = t/2 - z,      grad_x g = (0, -1),          d2g/dx2 = 0,

d = |x - c|.

In the edge's sector (below and left of c) the nearest point of the circle is on the quarter circle, so g
is there the distance to the jaw; g and grad_x g are continuous across rho = 1 (for z <= t/2 + a both give
t/2 - z and (0, -1)) and across z = t/2 + a (for rho <= 1 - a both give 1 - a - rho and (-1, 0)): the
contact force lambda grad_x g is normal to the jaw and its direction does not jump (the curvature does). Deep
inside the jaw (rho > 1, z > t/2 + a) g is not the distance, but no node of a state is there.

The rows are the indenter's (``contact``: ``contact.node_terms``) with no height: the jaw is fixed, has no
force row and its gap has no h. The jaw's multipliers mu_k >= 0 (units mu_0 R^2, the jaw pushing the node
with the force mu_k grad_x g, out of the jaw) are one per candidate node, every upper-surface node but the clamped one,
appended after the indenter's unknowns: y = [u, p, p_f, (h, lambda_1 .. lambda_m), mu_1 .. mu_J]. An
active node's row is -g_k = 0 (its force mu_k E_k in the equilibrium, its curvature -mu_k d2g_k/du2 in the
tangent), an inactive node's is mu_k = 0 (its columns empty), so the unknowns' layout does not change
with the jaw's active set: inflation's secant steps straddle a change of it. The active set is updated
between Newton solves by the indenter's rules (``newton.contact``): a node with mu_k < 0 leaves, an inactive
node inside the jaw (g_k < -SWEEP_TOL) joins.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import scipy.sparse as sp

from . import contact

__all__ = ["Jaw", "bordered", "candidates", "first", "local", "multipliers", "updated"]


@dataclasses.dataclass(frozen=True)
class Jaw:
    """The upper jaw of edge radius ``radius`` (units R) and its ``active`` candidates (bool, (J,); None: none
    active)."""

    radius: float
    active: np.ndarray | None = None

    def mask(self, model) -> np.ndarray:
        """The active candidates (bool, (J,))."""
        return np.zeros(candidates(model).size, bool) if self.active is None else np.asarray(self.active)


def candidates(model) -> np.ndarray:
    """The upper-surface nodes (indices of ``model.top_z``) that may touch the jaw: all but the clamped ones."""
    return np.flatnonzero(model.top_r < 1.0)


def local(rho: np.ndarray, z: np.ndarray, top: float, radius: float):
    """At nodes (rho, z) (m,): the gap g (m,) to the jaw whose lower face is z = ``top`` and whose edge has the
    radius ``radius`` (units R), grad_x g (m, 2) and d2g/dx2 (m, 2, 2) (module docstring).

    Examples
    --------
    A node one radius below the edge's centre touches it; one on the face's plane beyond r = 1 too:

    >>> import numpy as np
    >>> g, grad, hess = local(np.array([1.0, 1.5]), np.array([0.0, 0.0]), 0.0, 0.1)
    >>> print(g, grad.tolist())
    [0. 0.] [[0.0, -1.0], [0.0, -1.0]]
    """
    centre = top + radius
    g, grad, hess = np.empty(rho.size), np.zeros((rho.size, 2)), np.zeros((rho.size, 2, 2))
    edge, side, face = (rho <= 1.0) & (z <= centre), (rho <= 1.0) & (z > centre), rho > 1.0
    d_r, d_z = rho[edge] - 1.0, z[edge] - centre
    d = np.hypot(d_r, d_z)
    n = np.stack([d_r / d, d_z / d], axis=1)
    g[edge], grad[edge] = d - radius, n
    hess[edge] = (np.eye(2)[None] - n[:, :, None] * n[:, None, :]) / d[:, None, None]
    g[side], grad[side, 0] = 1.0 - radius - rho[side], -1.0
    g[face], grad[face, 1] = top - z[face], -1.0
    return g, grad, hess


def _gaps(model, jaw: Jaw, y: np.ndarray):
    """The candidates' gap, gradient and Hessian (``local``) at the state y."""
    nodes = candidates(model)
    rho, z = contact.positions(model, y, nodes)
    return local(rho, z, 0.5 * model.thickness, jaw.radius)


def multipliers(model, y: np.ndarray) -> np.ndarray:
    """The jaw's multipliers mu (J,) of the state y (the last J unknowns)."""
    return y[y.size - candidates(model).size:]


def bordered(model, y: np.ndarray, jaw: Jaw, res: np.ndarray, blocks) -> np.ndarray:
    """The residual (over [u, p, p_f, (h, lambda)], in that order, before the clamp's dofs are removed) bordered
    by the jaw's rows; their Jacobian's blocks added to ``blocks`` (``equations``: ``add(row, col, block)``)
    (module docstring)."""
    nodes, active, mu = candidates(model), jaw.mask(model), multipliers(model, y)
    size = res.size
    g, grad, hess = _gaps(model, jaw, y)
    on = np.flatnonzero(active)
    E, k_uu = contact.node_terms(model, nodes[on], mu[on], grad[on], hess[on])
    border = sp.coo_matrix(E)
    border = sp.coo_matrix((border.data, (border.row, on[border.col])), shape=(E.shape[0], active.size))
    blocks.add(0, 0, k_uu)
    blocks.add(0, size, border)
    blocks.add(size, 0, border.T)
    blocks.add(size, size, sp.diags((~active).astype(float)))
    return np.concatenate([res + np.pad(border @ mu, (0, size - E.shape[0])), np.where(active, -g, mu)])


def updated(model, y: np.ndarray, jaw: Jaw, loose: float) -> Jaw | None:
    """The jaw with the active set the state y asks for (``newton.contact``'s rules: a negative mu leaves,
    an inactive node with g < -``loose`` joins), or None if the set holds."""
    active = jaw.mask(model)
    g = _gaps(model, jaw, y)[0]
    mu = multipliers(model, y)
    new = np.where(active, mu >= 0.0, g < -loose)
    return None if np.array_equal(new, active) else dataclasses.replace(jaw, active=new)


def first(model, y: np.ndarray, jaw: Jaw, loose: float) -> Jaw:
    """The jaw with the candidates within ``loose`` of it at the state y active: the set of a converged state
    (its active nodes on the jaw, g = 0 to the tolerance) from y alone; a node that only grazes it is
    settled by the next solve (``newton.contact``)."""
    return dataclasses.replace(jaw, active=_gaps(model, jaw, y)[0] <= loose)
