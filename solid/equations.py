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
    ``jaw`` with its own active set (``jaw``; None: no jaw, the sheet only fixed at the clamp)."""

    pressure: float | None = None
    volume: Callable[[float], tuple[float, float]] | None = None
    active: np.ndarray | None = None
    force: float | None = None
    height: float | None = None
    surface: contact.Surface = contact.PLATE_SURFACE
    jaw: Jaw | None = None

    @property
    def contact(self) -> bool:
        return self.active is not None


def system(model: Model, y: np.ndarray, control: Control):
    """The residual R(y) and the Jacobian (sparse, CSC) restricted to the free unknowns; the index of those."""
    u, p = split(model, y)
    n, size = model.basis_u.N, model.size
    pf = y[size]
    r_u, r_p, k_uu, k_pu = solid(model, u, p)
    volume, dv, d2v = fluid(model, u)
    r_u = r_u - pf * dv
    k_uu = k_uu - pf * d2v
    dv_col = sp.csc_matrix(dv[:, None])
    if control.pressure is not None:
        fluid_row, fluid_res, fluid_diag = sp.csr_matrix((1, n)), pf - control.pressure, 1.0
    else:
        assert control.volume is not None  # a Control holds the pressure or the volume
        target, slope = control.volume(pf)
        fluid_row, fluid_res, fluid_diag = sp.csr_matrix(dv[None, :]), volume - target, -slope
    blocks = [[k_uu, k_pu.T, -dv_col], [k_pu, None, None], [fluid_row, None, sp.csr_matrix([[fluid_diag]])]]
    residual = [r_u, r_p, [fluid_res]]
    if control.active is not None:
        c = contact.rows(model, control.surface, y, control.active)
        m = len(control.active)
        residual[0] = residual[0] + c.E @ y[size + 2:size + 2 + m]
        residual.append([y[size + 1] - control.height] if control.force is None else [c.force - control.force])
        residual.append(c.residual)
        # the plate's row: d/dh and d/dlambda of h - H, or of F - F_given
        plate = (sp.csr_matrix(np.r_[1.0, np.zeros(m)][None, :]) if control.force is None
                 else sp.csr_matrix(np.r_[c.f_h, c.dgdh][None, :]))
        for row in blocks:
            row.extend([None, None])
        blocks[0][4] = c.E
        if c.k_uu is not None:  # a curved indenter: its normal turns with the node and with h
            blocks[0][0] = blocks[0][0] + c.k_uu
            blocks[0][3] = c.k_uh
        blocks.append([None if control.force is None else c.f_u, None, None, plate[:, :1], plate[:, 1:]])
        blocks.append([c.E.T, None, None, sp.csr_matrix(-c.dgdh[:, None]), None])
    jac = sp.bmat(blocks, format="csc")
    res = np.concatenate([np.atleast_1d(np.asarray(part, dtype=float)) for part in residual])
    if control.jaw is not None:
        res, jac = bordered(model, y, control.jaw, res, jac)
    keep = np.concatenate([model.free, np.arange(size, res.size)])
    return res[keep], jac[keep][:, keep], keep
