r"""The weak forms: the solid's residual and tangent, and the fluid's volume with its derivatives.

Solid (units: stresses of mu_0, lengths of R; the axisymmetric measure dV = 2 pi r dr dz). The
Lagrangian of the mixed displacement-pressure formulation is

    L(u, p) = int [W(Ib1, Ib2) + p (J - 1)] 2 pi r dr dz

(W at the isochoric invariants, ``kinematics``), so that, in the five components of dF,

    R_u[v] = int (dW + p dJ) . dF[v] 2 pi r,                 R_p[q] = int q (J - 1) 2 pi r,
    K_uu[du, v] = int dF[du] . (d^2 W + p d^2 J) . dF[v] 2 pi r,   K_pu[du, q] = int q dJ . dF[du] 2 pi r.

These forms are the definitions: ``assembly`` evaluates the stress dW + p dJ and the 5 x 5 tangent
d^2 W + p d^2 J once per Newton iteration at the quadrature points and assembles the same sums by array
contractions (a test compares the two).

Fluid. The fluid fills the cavity between the deformed lower surface (rho, zeta)(r), rho = r + u_r,
zeta = -t/2 + u_z, and its flat reference plane zeta = -t/2; its volume is

    V(u) = int_0^1 2 pi rho u_z rho' dr       (rho' = d rho / dr = 1 + du_r/dr on the lower surface),

the volume swept by the surface above the plane (rho = 1, u_z = 0 at the clamp, rho = 0 on the axis).
Its variations (symmetric in dv, du, as a second derivative must be):

    V'[v]     = int 2 pi (v_r u_z rho' + rho v_z rho' + rho u_z v_r') dr,
    V''[v, w] = int 2 pi (v_r w_z rho' + v_r u_z w_r' + w_r v_z rho' + rho v_z w_r'
                          + w_r u_z v_r' + rho w_z v_r') dr.

The fluid at pressure p_f does the work p_f dV on the sheet (a follower load: exactly the
derivative of p_f V), so its terms in the equilibrium are -p_f V'[v] and -p_f V''[v, w].
"""

from __future__ import annotations

import numpy as np
from skfem import BilinearForm, Functional, LinearForm

from . import kinematics as kin

__all__ = ["components", "residual_u", "residual_p", "tangent_uu", "coupling", "volume",
           "volume_first", "volume_second"]

def components(field, r) -> np.ndarray:
    """The five components (5, ...) of dF of a vector field (a skfem DiscreteField) at radius r."""
    g = field.grad
    return np.array([g[0, 0], g[0, 1], g[1, 0], g[1, 1], field[0] / r])


def _deformation(w):
    return kin.gradient(w["u"].grad, w["u"][0], w.x[0])


def residual_u(law):
    """R_u[v] of the rubber ``law`` (``laws.derivatives``); w holds ``u`` (vector) and ``p`` (scalar)."""

    @LinearForm
    def form(v, w):
        F = _deformation(w)
        stress = kin.energy_derivatives(F, law)[0] + np.asarray(w["p"]) * kin.jacobian_derivatives(F)[0]
        return np.einsum("a...,a...->...", stress, components(v, w.x[0])) * 2.0 * np.pi * w.x[0]

    return form


@LinearForm
def residual_p(q, w):
    """R_p[q] = int q (J - 1) 2 pi r; w holds ``u``."""
    return q * (kin.jacobian(_deformation(w)) - 1.0) * 2.0 * np.pi * w.x[0]


@BilinearForm
def tangent_uu(du, v, w):
    """K_uu[du, v] with the tangent d^2 W + p d^2 J tabulated in w["table"] (5, 5, e, q)."""
    r = w.x[0]
    table = np.asarray(w["table"])
    return np.einsum("ab...,a...,b...->...", table, components(du, r), components(v, r)) * 2.0 * np.pi * r


@BilinearForm
def coupling(du, q, w):
    """K_pu[du, q] = int q cof F : dF[du] 2 pi r (rows: pressure, columns: displacement); w holds ``u``."""
    cof = kin.components(kin.cofactor(_deformation(w)))
    return q * np.einsum("a...,a...->...", cof, components(du, w.x[0])) * 2.0 * np.pi * w.x[0]


def _surface(w):
    u = w["u"]
    return w.x[0] + u[0], u[1], 1.0 + u.grad[0, 0]


@Functional
def volume(w):
    """V(u) on the lower surface's facets; w holds ``u``."""
    rho, uz, drho = _surface(w)
    return 2.0 * np.pi * rho * uz * drho


@LinearForm
def volume_first(v, w):
    """V'[v]."""
    rho, uz, drho = _surface(w)
    return 2.0 * np.pi * (v[0] * uz * drho + rho * v[1] * drho + rho * uz * v.grad[0, 0])


@BilinearForm
def volume_second(dw, v, w):
    """V''[dw, v] (symmetric)."""
    rho, uz, drho = _surface(w)
    vr, vz, dvr = v[0], v[1], v.grad[0, 0]
    wr, wz, dwr = dw[0], dw[1], dw.grad[0, 0]
    return 2.0 * np.pi * (vr * wz * drho + vr * uz * dwr + wr * vz * drho + rho * vz * dwr + wr * uz * dvr
                          + rho * wz * dvr)
