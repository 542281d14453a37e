r"""Weak forms of the axisymmetric membrane, assembled element by element in vectorised form.

Unknown: the deformed meridian x(r) = (rho(r), eta(r)) on the Lagrangian radius
r in [0, 1]; lengths in units of R, tensions in E T, pressure Phat = P R/(E T).

Energy (units E T R^2) with P the multiplier of the volume, and for the
penalty contact a plate at height h with penalty kappa and multiplier field l:

    Pi(x, P) = 2 pi int_0^1 w(l1, l2) r dr - P (V(x) - V_I) [+ 2 pi int (1/(2 kappa)) <l + kappa (eta - h)>_+^2 r dr],
    l1 = |x'| = sqrt(rho'^2 + eta'^2),   l2 = rho / r,   V(x) = -pi int_0^1 rho^2 eta' dr.

With t = x'/l1 the unit tangent, d l1 = t . dx', d l2 = d rho / r and
d t = (I - t t) dx'/l1; w_1 = dw/dl1, w_2 = dw/dl2 and the second
derivatives w_ij come from the rubber's law (``laws``).

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

The closed capsule (``pocket.core.geometries.CAPSULE``): the reference meridian is the quarter circle
S in [0, pi/2], r0 = sin S, meshed in r = S / c on [0, 1] (c = pi/2, so that the mesh and its ALE map
are the disc's). With x' = dx/dr, |x'| = c l1 and l2 = rho / r0(r), the energy is
2 pi int w(l1, l2) r0 c dr and the volume -pi int rho^2 eta' dr is the upper half's with the
equatorial plane (the whole capsule's is twice it). The same steps give

    f_0 = 2 pi w_1 t_0 r0,   f_1 = 2 pi w_1 t_1 r0 + pi P rho^2,   g_0 = 2 pi (c w_2 + P rho eta'),
    G = (2 pi r0 / c) [(w_11 - w_1/l1) t t + (w_1/l1) I],   N_00 = 2 pi (c w_22 / r0 + P eta'),

M as above, and with r0' = dr0/dr = c cos(c r) (so that dl2/dr = -l2 r0' / r0)

    F^a_c = 2 pi t_c [(w_1 - l2 w_12) r0' V - w_11 r0 l1 V'],
    G^a_0 = 2 pi c [(w_2 - l1 w_12) V' - w_22 (l2 / r0) r0' V].

The disc is c = 1, r0 = r, r0' = 1: the loop runs one code for both, and on the disc every product or
quotient with c or r0' is by 1.0, exact (its numbers are bit for bit those of the disc's own formulas).
The ALE map may put the first ``flat`` elements on the contact zone (``geometry.place``): V = r / a,
V' = 1 / a on each of them.

On element e (r = r_e + L_e t, t in [0, 1]) with the Gauss rule (w_q, t_q):
int f v' dr = sum_q w_q f v'(t_q) and int g v dr = sum_q w_q L_e g v(t_q),
where v' = dv/dt / L_e. ``evaluate`` runs these sums in one compiled pass
over the elements (``loops``); ``fields`` interpolates the state at the
points (vectorised) for the post-processing and the checks.
Quadrature points lie inside the elements, so r > 0 wherever 1/r appears.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from pocket.core.geometries import DISC, Geometry, formulation

from . import loops
from .geometry import Placement
from .material import Law
from .reference import Reference

__all__ = ["SURFACES", "Contact", "Fields", "Linear", "element_dofs", "evaluate", "fields", "surface"]

#: reference surface -> whether its reference radius is r0 = sin S (a sphere) rather than r0 = S (module docstring)
SURFACES = {"pocket": False, "capsule": True}


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


@dataclasses.dataclass(frozen=True, eq=False)
class Linear:
    """The forms at one state: R, dR/dP, dR/da and the penalty's dF/dx (each (N,)), dF/dh, the plate
    force F (penalty) and the volume V, the least tensions T_1 = w_1 / l2 and T_2 = w_2 / l1 at the
    quadrature points, and the element matrices (n, 2 (p + 1), 2 (p + 1)) of K."""

    residual: np.ndarray
    pressure: np.ndarray
    radius: np.ndarray
    force: np.ndarray
    force_stiffness: float
    plate_force: float
    volume: float
    tension_min: tuple[float, float]
    matrices: np.ndarray


def element_dofs(ref: Reference, u: np.ndarray, elements: int) -> np.ndarray:
    """Element dofs as a read-only strided view of ``u``, shape (n, 2 (p + 1)) (no copy)."""
    u = np.ascontiguousarray(u)
    step = u.strides[0]
    return np.lib.stride_tricks.as_strided(u, shape=(elements, ref.local), strides=(2 * ref.order * step, step),
                                           writeable=False)


def surface(geometry: Geometry) -> tuple[float, bool]:
    """(scale, sphere) of the reference surface ``geometry`` (module docstring): S = scale r on the mesh
    coordinate r in [0, 1], and whether r0 = sin S (the capsule's sphere) rather than r0 = S (the flat disc)."""
    return float(geometry.length), formulation(SURFACES, "fem", geometry)


def fields(ref: Reference, placement: Placement, u: np.ndarray, pressure: float, geometry: Geometry = DISC) -> Fields:
    """The state with nodal dofs ``u`` (shape (2 (p n + 1),)) at the quadrature points, on the reference surface
    ``geometry``."""
    lengths = placement.lengths
    q = ref.weights.size
    values = element_dofs(ref, u, lengths.size) @ ref.interp
    rho, eta = values[:, :q], values[:, q:2 * q]
    drho, deta = values[:, 2 * q:3 * q] / lengths[:, None], values[:, 3 * q:] / lengths[:, None]
    l1 = np.sqrt(drho**2 + deta**2)
    if geometry is DISC:
        return Fields(placement.r, rho, eta, drho, deta, l1, rho / placement.r, lengths, pressure)
    scale, _ = surface(geometry)
    return Fields(placement.r, rho, eta, drho, deta, l1 / scale, rho / geometry.radius(scale * placement.r), lengths,
                  pressure)


def evaluate(law: Law, ref: Reference, placement: Placement, u: np.ndarray, pressure: float,
             contact: Contact | None = None, tangent: bool = True, out: tuple | None = None,
             geometry: Geometry = DISC) -> Linear:
    """The forms of the module docstring at the state (``u``, P) on the reference surface ``geometry``, with the
    element matrices if ``tangent``.

    ``out``: arrays to write them into, (vectors (4, N), matrices (n, s, s)), reused from call to
    call by the caller (a workspace: allocating fresh ones costs more than filling them at 1e5
    elements, as the memory goes back to the system and comes back page by page).
    """
    n, q = placement.lengths.size, ref.weights.size
    height, penalty, multiplier = (0.0, 0.0, 0.0) if contact is None else \
        (contact.height, contact.penalty, contact.multiplier)
    multiplier = np.broadcast_to(np.asarray(multiplier, dtype=float), (n, q))
    vectors, matrices = out if out is not None else (np.empty((4, u.size)), None)
    if matrices is None:
        matrices = np.empty((n if tangent else 0, ref.local, ref.local))
    scale, sphere = surface(geometry)
    flat = 1 if placement.stretch_rate is None else int(np.count_nonzero(placement.stretch_rate > 0.0))
    force_h, force, volume, t1, t2 = loops.element_loop(
        np.ascontiguousarray(u, dtype=float), placement.vertices, ref.t, ref.weights, ref.phi, ref.dphi,
        float(pressure), law.code, law.params, float(height), float(penalty), np.ascontiguousarray(multiplier),
        float(placement.a or 0.0), vectors, matrices, scale, sphere, flat)
    return Linear(vectors[0], vectors[1], vectors[2], vectors[3], float(force_h), float(force), float(volume),
                  (float(t1), float(t2)), matrices)
