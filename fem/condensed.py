r"""Static condensation of the P2 midpoint dofs before the banded solve (``banded``).

The midpoint dofs belong to one element each and are eliminated element by
element: with v the element's vertex dofs and m its midpoint dofs,

    S_e = K_vv - K_vm K_mm^-1 K_mv,  B_v <- B_v - K_vm K_mm^-1 B_m,
    C_v <- C_v - C_m K_mm^-1 K_mv,   D <- D - sum_e C_m K_mm^-1 B_m,

the right-hand sides alike, and after the vertex solve
x_m = K_mm^-1 (r_m - K_mv x_v - B_m y). The vertex band has half the dofs and
half-bandwidth 3 instead of 5: the LU costs about a sixth. K_mm (2 x 2, the
midpoint's stiffness at fixed vertices) is regular while the meridian is in
tension; an element where it is not sends the solve to the full band. The
element loops are compiled (``loops.condense``, ``condense_rhs``, ``expand``).
"""

from __future__ import annotations

import numpy as np

from . import loops
from .banded import Bordered, Buffers, band, refined

__all__ = ["Condensed", "system"]


class Condensed:
    """The P2 system with the midpoint dofs condensed out element by element (module docstring;
    the loops are compiled: ``loops.condense``, ``condense_rhs``, ``expand``).

    ``matrices`` (n, 6, 6): constrained element matrices, local dofs (vertex, midpoint, vertex)
    times (rho, eta); B (N, m), C (m, N), D (m, m) as for ``Bordered``. ``regular`` says whether
    every element's midpoint block could be inverted (else use the full band).
    """

    def __init__(self, matrices: np.ndarray, B: np.ndarray, C: np.ndarray, D: np.ndarray, workspace=None):
        self.matrices, self.B, self.C, self.D = matrices, B, C, D
        self._c = np.ascontiguousarray(C)
        n, m = matrices.shape[0], B.shape[1]
        buffer, nv = Buffers(workspace), 2 * n + 2
        vertex_band, b_v, c_v = buffer("band", (nv, 10)), buffer("b_v", (nv, m)), buffer("c_v", (m, nv))
        self.inv, self.x, self.y = buffer("inv", (n, 2, 2)), buffer("x", (n, 2, 4)), buffer("y", (n, 2, m))
        self.regular, d = loops.condense(matrices, np.ascontiguousarray(B), self._c, vertex_band, b_v, c_v, self.inv,
                                         self.x, self.y)
        if self.regular:
            self.reduced = Bordered(vertex_band.T, 3, b_v, c_v, D + d, workspace)

    def apply(self, x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The whole (uncondensed) matrix times (x, y)."""
        n, size = self.matrices.shape[:2]
        local = np.lib.stride_tricks.as_strided(x, shape=(n, size), strides=(4 * x.strides[0], x.strides[0]))
        products = (self.matrices @ local[:, :, None])[:, :, 0]
        out = np.zeros_like(x)
        for a in range(size):
            out[a: a + 4 * n: 4] += products[:, a]
        return out + self.B @ y, self.C @ x + self.D @ y

    def eliminate(self, r: np.ndarray, s: np.ndarray):
        """(x, y, cancellation) through the vertex system, or None if its band is singular."""
        r_v, s_v, z = loops.condense_rhs(np.ascontiguousarray(r), np.ascontiguousarray(s, dtype=float),
                                         self.matrices, self._c, self.inv)
        out = self.reduced.eliminate(r_v, s_v)
        if out is None:
            return None
        x_v, y, cancellation = out
        return loops.expand(x_v, y, z, self.x, self.y), y, cancellation

    def solve(self, r: np.ndarray, s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(x, y) solving the whole system for (r, s), checked with the element matrices when the
        elimination cancelled; the full band (``Bordered``) if the vertex band is singular."""
        with np.errstate(all="ignore"):
            first = self.eliminate(r, s)
            out = None if first is None else refined(first, self.eliminate, self.apply, r, s)
        return Bordered(band(self.matrices, 4, 5), 5, self.B, self.C, self.D).solve(r, s) if out is None else out


def system(matrices: np.ndarray, order: int, B: np.ndarray, C: np.ndarray, D: np.ndarray, workspace=None):
    """The bordered system of constrained element matrices: condensed for P2 (when it can be), else banded.

    ``workspace``: a dict whose arrays the condensation writes over (the system is then valid until
    the next one built on the same workspace)."""
    if order == 2:
        condensed = Condensed(matrices, B, C, D, workspace)
        if condensed.regular:
            return condensed
    kl = 2 * order + 1
    return Bordered(band(matrices, 2 * order, kl), kl, B, C, D)
