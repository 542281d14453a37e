r"""Weak forms of the axisymmetric membrane, assembled element by element in vectorised form.

Unknown: the deformed meridian x(r) = (rho(r), eta(r)) on the Lagrangian radius
r in [0, 1]; lengths in units of R, tensions in E T, pressure Phat = P R/(E T).

Energy (units E T R^2) with P the multiplier of the volume, and for the
penalty contact a plate at height h with penalty kappa and multiplier field l:

    Pi(x, P) = 2 pi int_0^1 w(l1, l2) r dr - P (V(x) - V_I) [+ 2 pi int (1/(2 kappa)) <l + kappa (eta - h)>_+^2 r dr],
    l1 = |x'| = sqrt(rho'^2 + eta'^2),   l2 = rho / r,   V(x) = -pi int_0^1 rho^2 eta' dr.

With t = x'/l1 the unit tangent, d l1 = t . dx', d l2 = d rho / r and
d t = (I - t t) dx'/l1; w_1 = dw/dl1, w_2 = dw/dl2 and the second
derivatives w_ij come from ``material``.

Residual (first variation, direction v = (v_0, v_1) = (v_rho, v_eta)):

    R(v) = int (f_c v_c' + g_c v_c) dr,
    f_0 = 2 pi w_1 t_0 r,   f_1 = 2 pi w_1 t_1 r + pi P rho^2,
    g_0 = 2 pi w_2 + 2 pi P rho eta',   g_1 = 2 pi p_N r,   p_N = <l + kappa (eta - h)>_+ .

Tangent (second variation, trial du, test v): with G_cd = df_d/dx'_c,
M_cd = df_d/dx_c = dg_c/dx'_d and N_cd = dg_d/dx_c,

    K(du, v) = int (G_cd du_c' v_d' + M_cd du_c v_d' + M_dc du_c' v_d + N_cd du_c v_d) dr,
    G = 2 pi r [(w_11 - w_1/l1) t t + (w_1/l1) I],
    M_00 = 2 pi w_12 t_0,   M_01 = 2 pi (w_12 t_1 + P rho),   M_1d = 0,
    N_00 = 2 pi (w_22 / r + P eta'),   N_11 = 2 pi kappa chi r,   chi = [l + kappa (eta - h) > 0].

Derivatives of R with respect to the scalar unknowns:

    dR/dP (v) = -dV(v) = pi int (2 rho eta' v_0 + rho^2 v_1') dr,
    dR/dh (v) = -2 pi int kappa chi v_1 r dr,
    plate force F = 2 pi int p_N r dr,  dF/dx = -dR/dh,  dF/dh = -2 pi int kappa chi r dr.

Derivative with respect to the contact radius a of the edge-fitted mesh
(``geometry``): the nodal values stay, the nodes move with velocity V(r) and
the element lengths change as dL/da = L V'. For an integrand
I(x, x', r; v, v') dr this moves x' and v' by -x' V' and -v' V', r by V, and
dr by V' dr, so

    dR/da (v) = int (F^a_c v_c' + G^a_c v_c) dr,
    F^a_c = -(df_c/dx'_d) x'_d V' + (df_c/dr) V,
    G^a_c = -(dg_c/dx'_d) x'_d V' + (dg_c/dr) V + g_c V'.

With G t = 2 pi r w_11 t (so (df_c/dx'_d) x'_d = 2 pi r w_11 l1 t_c),
df_c/dr = 2 pi t_c (w_1 - l2 w_12) and dg_0/dr = -2 pi w_22 l2 / r, the
pressure terms cancel (the volume does not depend on how the curve is
parametrised) and

    F^a_c = 2 pi t_c [(w_1 - l2 w_12) V - w_11 r l1 V'],
    G^a_0 = 2 pi [(w_2 - l1 w_12) V' - w_22 (l2 / r) V],   G^a_1 = 0 (no penalty with the fitted mesh).

On element e (r = r_e + L_e t, t in [0, 1]) with the Gauss rule (w_q, t_q):
int f v' dr = sum_q w_q f v'(t_q) and int g v dr = sum_q w_q L_e g v(t_q),
where v' = dv/dt / L_e. Every field is an (elements, points) array, element
vectors and matrices come out of small matrix products with the reference
tables, and ``assemble`` adds them into the global vector or the banded
matrix with strided slices (``reference`` explains the dof layout).
Quadrature points lie inside the elements, so r > 0 wherever 1/r appears.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from .geometry import Placement
from .material import MooneyRivlin
from .reference import Reference

__all__ = ["Fields", "Contact", "fields", "derivatives", "residual_vector", "tangent_matrices", "pressure_vector",
           "radius_vector", "penalty_vectors", "volume", "plate_force", "assemble", "band_add"]

TWO_PI = 2.0 * np.pi


@dataclasses.dataclass(frozen=True)
class Contact:
    """The penalty plate: height h, penalty kappa, multiplier field l (scalar or shape (n, Q))."""

    height: float
    penalty: float
    multiplier: object = 0.0


@dataclasses.dataclass(frozen=True, eq=False)
class Fields:
    """The state at the quadrature points (each (n, Q) unless said): r, rho, eta, their
    r-derivatives drho, deta, the stretches l1, l2, the element lengths L (n,), pressure P."""

    r: np.ndarray
    rho: np.ndarray
    eta: np.ndarray
    drho: np.ndarray
    deta: np.ndarray
    l1: np.ndarray
    l2: np.ndarray
    lengths: np.ndarray
    pressure: float


def _nodal(ref: Reference, u: np.ndarray, elements: int) -> np.ndarray:
    """Element nodal values, shape (n, p + 1, 2)."""
    p = ref.order
    return u.reshape(-1, 2)[p * np.arange(elements)[:, None] + np.arange(p + 1)]


def fields(ref: Reference, placement: Placement, u: np.ndarray, pressure: float) -> Fields:
    """The state with nodal dofs ``u`` (shape (2 (p n + 1),)) at the quadrature points."""
    lengths = placement.lengths
    x = _nodal(ref, u, lengths.size)
    rho, eta = x[:, :, 0] @ ref.phi.T, x[:, :, 1] @ ref.phi.T
    drho, deta = (x[:, :, 0] @ ref.dphi.T) / lengths[:, None], (x[:, :, 1] @ ref.dphi.T) / lengths[:, None]
    l1 = np.sqrt(drho**2 + deta**2)
    return Fields(placement.r, rho, eta, drho, deta, l1, rho / placement.r, lengths, pressure)


def derivatives(material: MooneyRivlin, w: Fields) -> tuple:
    """(w_1, w_2, w_11, w_12, w_22) at the quadrature points (``material``)."""
    return material.derivatives(w.l1, w.l2)


def _penalty(w: Fields, contact: Contact | None):
    """(p_N, chi) at the quadrature points; zeros without a plate."""
    if contact is None:
        return 0.0, 0.0
    trial = contact.multiplier + contact.penalty * (w.eta - contact.height)
    chi = trial > 0.0
    return np.where(chi, trial, 0.0), chi


def _vector(ref: Reference, lengths, f0, f1, g0, g1) -> np.ndarray:
    """Element vectors sum_q w_q (f_c v_c'(t_q) + L g_c v_c(t_q)), shape (n, 2 (p + 1))."""
    wq = ref.weights
    out = np.empty((lengths.size, ref.local))
    scale = lengths[:, None] * wq
    out[:, 0::2] = (f0 * wq) @ ref.dphi + (g0 * scale) @ ref.phi
    out[:, 1::2] = (f1 * wq) @ ref.dphi + (g1 * scale if np.ndim(g1) else np.zeros_like(scale)) @ ref.phi
    return out


def residual_vector(ref: Reference, w: Fields, d: tuple, contact: Contact | None = None):
    """Element vectors of R (module docstring), shape (n, 2 (p + 1)); ``d`` from ``derivatives``."""
    w1, w2 = d[:2]
    p_n, _ = _penalty(w, contact)
    f0 = TWO_PI * w1 * w.drho / w.l1 * w.r
    f1 = TWO_PI * w1 * w.deta / w.l1 * w.r + np.pi * w.pressure * w.rho**2
    g0 = TWO_PI * (w2 + w.pressure * w.rho * w.deta)
    g1 = TWO_PI * p_n * w.r if contact is not None else 0.0
    return _vector(ref, w.lengths, f0, f1, g0, g1)


def pressure_vector(ref: Reference, w: Fields) -> np.ndarray:
    """Element vectors of dR/dP = -dV (module docstring)."""
    zero = np.zeros_like(w.r)
    return _vector(ref, w.lengths, zero, np.pi * w.rho**2, TWO_PI * w.rho * w.deta, 0.0)


def radius_vector(ref: Reference, placement: Placement, w: Fields, d: tuple) -> np.ndarray:
    """Element vectors of dR/da, the derivative along the ALE map (module docstring)."""
    w1, w2, w11, w12, w22 = d
    v, dv = placement.velocity, placement.stretch_rate[:, None]
    common = TWO_PI * ((w1 - w.l2 * w12) * v - w11 * w.r * w.l1 * dv) / w.l1
    g0 = TWO_PI * ((w2 - w.l1 * w12) * dv - w22 * w.l2 / w.r * v)
    return _vector(ref, w.lengths, common * w.drho, common * w.deta, g0, 0.0)


def penalty_vectors(ref: Reference, w: Fields, contact: Contact) -> tuple[np.ndarray, float]:
    """(element vectors of dF/dx = -dR/dh, dF/dh) of the penalty plate."""
    _, chi = _penalty(w, contact)
    stiff = TWO_PI * contact.penalty * chi * w.r
    zero = np.zeros_like(w.r)
    return _vector(ref, w.lengths, zero, zero, zero, stiff), -float(np.sum(stiff * w.lengths[:, None] * ref.weights))


def plate_force(ref: Reference, w: Fields, contact: Contact) -> float:
    """Penalty plate force F = 2 pi int p_N r dr (units E T R)."""
    p_n, _ = _penalty(w, contact)
    return float(np.sum(TWO_PI * p_n * w.r * w.lengths[:, None] * ref.weights))


def volume(ref: Reference, w: Fields) -> float:
    """V = -pi int rho^2 eta' dr (units R^3)."""
    return float(-np.pi * np.sum(w.rho**2 * w.deta * w.lengths[:, None] * ref.weights))


def tangent_matrices(ref: Reference, w: Fields, d: tuple, contact: Contact | None = None):
    """Element matrices of K (module docstring), shape (n, 2 (p + 1), 2 (p + 1))."""
    w1, _, w11, w12, w22 = d
    t0, t1 = w.drho / w.l1, w.deta / w.l1
    along, across = TWO_PI * (w11 - w1 / w.l1) * w.r, TWO_PI * w1 / w.l1 * w.r
    g00, g01, g11 = along * t0 * t0 + across, along * t0 * t1, along * t1 * t1 + across
    m00, m01 = TWO_PI * w12 * t0, TWO_PI * (w12 * t1 + w.pressure * w.rho)
    n00 = TWO_PI * (w22 / w.r + w.pressure * w.deta)
    _, chi = _penalty(w, contact)
    n11 = TWO_PI * contact.penalty * chi * w.r if contact is not None else None
    wq, length = ref.weights, w.lengths[:, None]
    k = ref.order + 1
    t = ref.tables

    def block(*terms):
        coefficients = np.concatenate([c * wq for c, _ in terms], axis=1)
        return (coefficients @ np.concatenate([t[name] for _, name in terms], axis=0)).reshape(-1, k, k)

    out = np.empty((w.lengths.size, 2 * k, 2 * k))
    # [test c, trial d]: G_dc dv_c' du_d' / L + M_dc dv_c' du_d + M_cd v_c du_d' + L N_dc v_c du_d
    out[:, 0::2, 0::2] = block((g00 / length, "dd"), (m00, "dp"), (m00, "pd"), (n00 * length, "pp"))
    out[:, 0::2, 1::2] = block((g01 / length, "dd"), (m01, "pd"))
    out[:, 1::2, 0::2] = block((g01 / length, "dd"), (m01, "dp"))
    terms = [(g11 / length, "dd")] + ([(n11 * length, "pp")] if n11 is not None else [])
    out[:, 1::2, 1::2] = block(*terms)
    return out


def assemble(ref: Reference, element_vectors: np.ndarray) -> np.ndarray:
    """The global vector (length 2 (p n + 1)) of element vectors of shape (n, 2 (p + 1))."""
    p, n = ref.order, element_vectors.shape[0]
    out = np.zeros((p * n + 1, 2))
    for a in range(p + 1):
        out[a: a + p * n: p] += element_vectors[:, 2 * a: 2 * a + 2]
    return out.ravel()


def band_add(ref: Reference, matrices: np.ndarray, band: np.ndarray, diagonal_row: int) -> None:
    """Add element matrices (n, 2 (p + 1), 2 (p + 1)) into LAPACK band storage.

    ``band[diagonal_row + i - j, j]`` holds A[i, j] (``diagonal_row`` = kl + ku for
    ``dgbtrf``). Element e's block starts at global dof 2 p e.
    """
    p, n = ref.order, matrices.shape[0]
    size = ref.local
    columns = np.ascontiguousarray(matrices.transpose(2, 1, 0))  # [m, l, e]: one contiguous block per column
    for m in range(size):
        top = diagonal_row - m
        band[top: top + size, m: m + 2 * p * n: 2 * p] += columns[m]
