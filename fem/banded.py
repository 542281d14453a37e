r"""The bordered Newton system: a banded block and a few dense rows and columns, solved in O(N).

The system is

    [ A  B ] [x]   [r]
    [ C  D ] [y] = [s],

A (N x N) banded with half-bandwidths kl = ku (the stiffness, with the rows and
columns of prescribed dofs replaced by the identity), B (N x m) and C (m x N)
the couplings to the m <= 3 scalar unknowns (pressure, plate height, contact
radius), D (m x m). Block elimination with A's banded LU (LAPACK gbtrf with
partial pivoting; cost O(N kl^2) and storage O(N kl)):

    A [z, W] = [r, B],   S = D - C W,   S y = s - C z,   x = z - W y.

The bordered matrix is regular at a pressure maximum even where A alone is
nearly singular (A is the stiffness at fixed pressure), and the elimination
then loses digits in x = z - W y (W y much larger than x); when that
cancellation exceeds 1e4, the solve is checked against the whole matrix and
refined by one or two steps (the correction reuses both factorisations). An exactly
singular A, or a refinement that does not converge, falls back to a sparse
LU of the whole bordered matrix (SuperLU); a singular bordered matrix is
``SingularSystem``.

Assembly (``band``): element e's matrix (s x s) sits at the global dofs
t e .. t e + s - 1 (s = 2 (p + 1) dofs per element, period t = 2 p). The band
is stored column-major, so an element's block is one contiguous stretch of
memory, and is written with s strided slices. Prescribed dofs (``constrain``)
have their rows and columns cleared and a unit diagonal in every element that
holds them, so that the assembled row is the identity (times 1 or 2).

P2 midpoints are condensed out first (``condensed``). With a workspace the
large arrays are reused from one linearisation to the next (``Buffers``).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from scipy.linalg import lapack

__all__ = ["Bordered", "Buffers", "SingularSystem", "band", "constrain", "matvec", "refined"]

_REFINE = 2  # iterative-refinement steps at most
_ACCURATE = 1e-8  # residual of the linear solve, relative to the right-hand side, that needs no refinement
_CANCELLATION = 1e4  # x = z - W y losing more digits than this is checked and refined


class SingularSystem(ArithmeticError):
    """The bordered matrix is singular (to working precision)."""


def matvec(band: np.ndarray, kl: int, ku: int, x: np.ndarray) -> np.ndarray:
    """A x for A in LAPACK band storage ``band[kl + ku + i - j, j] = A[i, j]``."""
    n = x.shape[0]
    out = np.zeros_like(x)
    for d in range(-kl, ku + 1):  # A[i, i + d]
        row = band[kl + ku - d]
        if d >= 0:
            out[: n - d] += row[d:, None] * x[d:] if x.ndim == 2 else row[d:] * x[d:]
        else:
            out[-d:] += row[: n + d, None] * x[: n + d] if x.ndim == 2 else row[: n + d] * x[: n + d]
    return out


def band(matrices: np.ndarray, period: int, kl: int) -> np.ndarray:
    """The band of element matrices (n, s, s) placed every ``period`` dofs, gbtrf storage (3 kl + 1, N),
    column-major (N = period n + s - period)."""
    n, size, _ = matrices.shape
    rows, diagonal = 3 * kl + 1, 2 * kl
    out = np.zeros((n + 1, period, rows))  # [group of columns, column in group, row]
    for m in range(size):
        first, column = (0, m) if m < period else (1, m - period)
        out[first: first + n, column, diagonal - m: diagonal - m + size] += matrices[:, :, m]
    return out.reshape(-1, rows)[: period * n + size - period].T


def constrain(matrices: np.ndarray, period: int, dofs) -> np.ndarray:
    """Element matrices with the rows and columns of the global ``dofs`` cleared and a unit diagonal."""
    n, size, _ = matrices.shape
    g = np.asarray(dofs, dtype=int).ravel()
    # every (element, local dof) holding a global dof: the elements g // period, g // period - 1, ...
    e = (g // period)[None, :] - np.arange(-(-size // period) + 1)[:, None]
    local = g[None, :] - period * e
    held = (e >= 0) & (e < n) & (local < size)
    e, local = e[held], local[held]
    matrices[e, local, :] = 0.0
    matrices[e, :, local] = 0.0
    matrices[e, local, local] = 1.0
    return matrices


def refined(first, eliminate, apply, r: np.ndarray, s: np.ndarray):
    """(x, y) from ``first`` = ``eliminate(r, s)`` = (x, y, cancellation), checked against ``apply`` and
    refined when the elimination cancelled more than _CANCELLATION; None if it does not reach 1e-8."""
    x, y, cancellation = first
    if cancellation < _CANCELLATION and np.all(np.isfinite(x)) and np.all(np.isfinite(y)):
        return x, y
    scale = max(np.abs(r).max(initial=0.0), np.abs(s).max(initial=0.0), 1e-300)
    for _ in range(_REFINE + 1):
        ax, cy = apply(x, y)
        e_r, e_s = r - ax, s - cy
        error = max(np.abs(e_r).max(initial=0.0), np.abs(e_s).max(initial=0.0))
        if error <= _ACCURATE * scale:
            return x, y
        dx, dy, _ = eliminate(e_r, e_s)
        x, y = x + dx, y + dy
    ax, cy = apply(x, y)
    ok = np.all(np.isfinite(x)) and np.all(np.isfinite(y))
    return (x, y) if ok and max(np.abs(r - ax).max(), np.abs(s - cy).max(initial=0.0)) <= 1e-8 * scale else None


@dataclasses.dataclass(eq=False)
class Bordered:
    """The system above: ``band`` (A in gbtrf storage, (2 kl + ku + 1, N)), B (N, m), C (m, N), D (m, m).

    With a ``workspace`` (a dict) the band is factored in place and the solves written into the
    workspace's arrays: the band is then consumed, and checking a solve is left to the caller.
    """

    band: np.ndarray
    kl: int
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    workspace: dict | None = None

    def __post_init__(self):
        self._lu = None

    def apply(self, x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The matrix times (x, y) (before the band is factored in place)."""
        return matvec(self.band, self.kl, self.kl, x) + self.B @ y, self.C @ x + self.D @ y

    def _factor(self, r: np.ndarray):
        """Factor A and solve A [W, z] = [B, r] in one sweep; returns the LU (False if A is singular) and z."""
        if self._lu is not None:
            return self._lu, None
        lu, piv, info = lapack.dgbtrf(self.band, self.kl, self.kl, overwrite_ab=self.workspace is not None)
        if info != 0:
            self._lu = False
            return False, None
        self._lu = (lu, piv)
        m = self.B.shape[1]
        block = Buffers(self.workspace)("rhs", (m + 1, r.size)).T  # column-major (N, m + 1)
        block[:, :m], block[:, m] = self.B, r
        both, _ = lapack.dgbtrs(lu, self.kl, self.kl, block, piv, overwrite_b=1)
        self._w, z = both[:, :m], both[:, m]
        self._schur = self.D - self.C @ self._w
        if not np.all(np.isfinite(self._schur)) or np.linalg.cond(self._schur) > 1e15:
            self._lu = False
        return self._lu, z

    def _a_solve(self, rhs: np.ndarray) -> np.ndarray:
        lu, piv = self._lu
        out, _info = lapack.dgbtrs(lu, self.kl, self.kl, rhs, piv)
        return out

    def eliminate(self, r: np.ndarray, s: np.ndarray):
        """(x, y, cancellation) by block elimination, or None if A is singular; cancellation =
        max |W y| / max |x|, large when A is nearly singular (the result then needs checking)."""
        lu, z = self._factor(r)
        if not lu:
            return None
        z = self._a_solve(r) if z is None else z
        y = np.linalg.solve(self._schur, s - self.C @ z)
        wy = self._w @ y
        x = z - wy
        return x, y, np.abs(wy).max(initial=0.0) / max(np.abs(x).max(initial=0.0), 1e-300)

    def solve(self, r: np.ndarray, s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(x, y) solving the system for the right-hand side (r, s)."""
        with np.errstate(all="ignore"):
            first = self.eliminate(r, s)
            out = None if first is None else refined(first, self.eliminate, self.apply, r, s)
            return self._sparse(r, s) if out is None else out

    def _sparse(self, r, s):
        """SuperLU of the whole bordered matrix (the fallback)."""
        n, kl = self.band.shape[1], self.kl
        offsets = np.arange(-kl, kl + 1)
        diagonals = [self.band[2 * kl - d, max(d, 0): n + min(d, 0)] for d in offsets]
        a = sp.diags(diagonals, offsets, shape=(n, n), format="csc")
        full = sp.bmat([[a, sp.csc_matrix(self.B)], [sp.csc_matrix(self.C), sp.csc_matrix(self.D)]], format="csc")
        try:
            lu = spla.splu(full)
        except RuntimeError as err:  # "Factor is exactly singular"
            raise SingularSystem(str(err)) from None
        out = lu.solve(np.concatenate([r, s]))
        if not np.all(np.isfinite(out)):
            raise SingularSystem("the bordered tangent is singular")
        return out[:n], out[n:]


class Buffers:
    """Arrays by name from a workspace dict, reused while their shape holds (fresh ones without a dict)."""

    def __init__(self, workspace: dict | None):
        self.workspace = workspace

    def __call__(self, name: str, shape: tuple) -> np.ndarray:
        if self.workspace is None:
            return np.empty(shape)
        array = self.workspace.get(name)
        if array is None or array.shape != shape:
            array = self.workspace[name] = np.empty(shape)
        return array
