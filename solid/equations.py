r"""The bordered equations of a state: the rubber, the fluid's row and the plate's contact rows.

Unknowns y = [u, p, p_f, h, lambda_1 .. lambda_m]: the displacement and the incompressibility
pressure (``model``), the fluid's pressure p_f (units mu_0), and, in contact, the plate's height h
(units R, above the clamp plane) and the contact forces lambda_k >= 0 at the upper-surface nodes
k of the active set (units mu_0 R^2, the plate pushing down). With the Lagrangian

    L = int [W + p (J - 1)] 2 pi r - p_f (V(u) - V_f) - sum_k lambda_k g_k(u, h),

g_k the gap of node k to the indenter (``contact``: on the flat plate g_k = h - z_k, z_k = t/2 + u_z at
node k; on a sphere the distance to its surface), the equations are its stationarity in u and p, and

    fluid:    p_f - P                    (pressure given), or
              V(u) - V_f(p_f)            (the fluid's volume at its pressure: a constant for a liquid,
                                          the polytropic law for a gas, ``pocket.core.fluids``);
    contact:  -g_k(u, h) = 0             for each active node k (no penalty: the nodes lie on the indenter);
    plate:    sum_k lambda_k dg_k/dh - F (force control: the indenter's reaction is the force; on the
                                          plate dg_k/dh = 1), or
              h - H = 0                  (height control).

The contact's terms, with a sphere's curvature, are derived in ``contact``. Without contact the plate's height
is not an unknown (the vector stops at p_f). With the clamp's upper jaw (``jaw``, optional) its multipliers
follow, one per candidate node, and its rows border the rest. The Jacobian is the bordered matrix of these
rows; the clamp's and the axis's dofs are removed (``Model.free``).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

import numpy as np
import scipy.sparse as sp

from . import contact
from .jaw import Jaw, bordered
from .model import Model, fluid, solid, split

__all__ = ["Control", "system"]


@dataclasses.dataclass(frozen=True)
class Control:
    """What is held: the fluid's ``pressure`` (units mu_0), or its ``volume(p_f) -> (V, dV/dp_f)``; in contact,
    the ``active`` upper-surface nodes (indices of ``Model.top_z``) and the plate's ``force`` (mu_0 R^2) or
    ``height`` (R); the indenter's ``surface`` (``contact``: the flat plate or a sphere); the clamp's upper
    ``jaw`` with its own active set (``jaw``; None: no jaw, the sheet only fixed at the clamp); ``known``, a hint
    for the search of the active set (``newton.contact``): the first ``known`` upper-surface nodes, a disc, touch
    the indenter at this load (0: none known)."""

    pressure: float | None = None
    volume: Callable[[float], tuple[float, float]] | None = None
    active: np.ndarray | None = None
    force: float | None = None
    height: float | None = None
    surface: contact.Surface = contact.PLATE_SURFACE
    jaw: Jaw | None = None
    known: int = 0

    @property
    def contact(self) -> bool:
        return self.active is not None


class _Blocks:
    """The Jacobian's blocks, each a sparse matrix placed at a (row, column) offset, gathered as one list of
    triplets and built once, on the kept unknowns only (``build``): no block matrix is formed and sliced."""

    def __init__(self):
        self.rows, self.cols, self.vals = [], [], []

    def add(self, row: int, col: int, block) -> None:
        """Place ``block`` (any scipy sparse matrix) with its (0, 0) at (``row``, ``col``)."""
        coo = sp.coo_matrix(block)
        self.rows.append(coo.row + row)
        self.cols.append(coo.col + col)
        self.vals.append(coo.data)

    def build(self, keep: np.ndarray, size: int) -> sp.csc_matrix:
        """The CSC matrix of the blocks' sum on the unknowns ``keep`` (in that order) of the ``size`` in all."""
        index = np.full(size, -1)
        index[keep] = np.arange(keep.size)
        rows, cols = index[np.concatenate(self.rows)], index[np.concatenate(self.cols)]
        kept = (rows >= 0) & (cols >= 0)
        return sp.csc_matrix((np.concatenate(self.vals)[kept], (rows[kept], cols[kept])), shape=(keep.size,) * 2)


def system(model: Model, y: np.ndarray, control: Control):
    """The residual R(y) and the Jacobian (sparse, CSC) restricted to the free unknowns; the index of those."""
    u, p = split(model, y)
    n, size = model.basis_u.N, model.size
    pf = y[size]
    r_u, r_p, k_uu, k_pu = solid(model, u, p)
    volume, dv, d2v = fluid(model, u)
    r_u = r_u - pf * dv
    blocks = _Blocks()
    blocks.add(0, 0, k_uu)
    blocks.add(0, 0, -pf * d2v)
    blocks.add(0, n, k_pu.T)
    blocks.add(n, 0, k_pu)
    blocks.add(0, size, sp.coo_matrix(-dv[:, None]))
    if control.pressure is not None:
        fluid_res, fluid_diag = pf - control.pressure, 1.0
    else:
        assert control.volume is not None  # a Control holds the pressure or the volume
        target, slope = control.volume(pf)
        fluid_res, fluid_diag = volume - target, -slope
        blocks.add(size, 0, sp.coo_matrix(dv[None, :]))
    blocks.add(size, size, sp.coo_matrix([[fluid_diag]]))
    residual = [r_u, r_p, [fluid_res]]
    if control.active is not None:
        c = contact.rows(model, control.surface, y, control.active)
        m = len(control.active)
        residual[0] = residual[0] + c.E @ y[size + 2:size + 2 + m]
        residual.append([y[size + 1] - control.height] if control.force is None else [c.force - control.force])
        residual.append(c.residual)
        blocks.add(0, size + 2, c.E)
        blocks.add(size + 2, 0, c.E.T)
        blocks.add(size + 2, size + 1, sp.coo_matrix(-c.dgdh[:, None]))
        if c.k_uu is not None:  # a curved indenter: its normal turns with the node and with h
            blocks.add(0, 0, c.k_uu)
            blocks.add(0, size + 1, c.k_uh)
        # the plate's row: d/dh and d/dlambda of h - H, or of F - F_given
        if control.force is None:
            blocks.add(size + 1, size + 1, sp.coo_matrix([[1.0]]))
        else:
            if c.f_u is not None:
                blocks.add(size + 1, 0, c.f_u)
            blocks.add(size + 1, size + 1, sp.coo_matrix([[c.f_h]]))
            blocks.add(size + 1, size + 2, sp.coo_matrix(c.dgdh[None, :]))
    res = np.concatenate([np.atleast_1d(np.asarray(part, dtype=float)) for part in residual])
    if control.jaw is not None:
        res = bordered(model, y, control.jaw, res, blocks)
    keep = np.concatenate([model.free, np.arange(size, res.size)])
    return res[keep], blocks.build(keep, res.size), keep
