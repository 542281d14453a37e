"""Weak forms of the axisymmetric membrane: residual, consistent tangent, volume, contact.

Unknown: the deformed meridian x(r) = (rho(r), eta(r)) on the Lagrangian radius
r in [0, 1]; all lengths in units of R, tensions in E T, pressure Phat = P R/(E T).

Energy (units E T R^2), pressure P the multiplier of the volume constraint and
a frictionless plate at height h with a penalty kappa and multiplier field l:

    Pi(x, P, h) = 2 pi int_0^1 w(l1, l2) r dr - P (V(x) - V_I) + Pi_c(x, h),
    l1 = |x'| = sqrt(rho'^2 + eta'^2),   l2 = rho / r,
    V(x) = -pi int_0^1 rho^2 eta' dr,
    Pi_c = 2 pi int_0^1 (1/(2 kappa)) <l + kappa (eta - h)>_+^2 r dr.

With t = x'/l1 the unit tangent, the variations of the stretches are
d l1 = t . dx',  d l2 = d rho / r, and  d t = (I - t t) dx' / l1.  Hence,
with w_1 = dw/dl1 = l2 T1, w_2 = dw/dl2 = l1 T2 (module ``material``):

Residual (first variation in the direction v = (v_rho, v_eta)):

    R(v) = 2 pi int [w_1 (t . v') r + w_2 v_rho] dr        (the 1/r cancels)
           + pi P int (2 rho eta' v_rho + rho^2 v_eta') dr    (= -P dV(v))
           + 2 pi int p_N v_eta r dr,          p_N = <l + kappa (eta - h)>_+ .

Tangent (second variation, directions du and v):

    K(du, v) = 2 pi int { [w_11 (t.du')(t.v') + (w_1/l1)(du'.v' - (t.du')(t.v'))] r
                          + w_12 [du_rho (t.v') + (t.du') v_rho] + w_22 du_rho v_rho / r } dr
             + pi P int (2 eta' du_rho v_rho + 2 rho du_eta' v_rho + 2 rho du_rho v_eta') dr
             + 2 pi int kappa chi du_eta v_eta r dr,      chi = [l + kappa (eta - h) > 0].

Border of the bordered system (P and h as extra unknowns):

    dR/dP (v) = -dV(v) = pi int (2 rho eta' v_rho + rho^2 v_eta') dr,
    dR/dh (v) = -2 pi int kappa chi v_eta r dr,
    plate force F = 2 pi int p_N r dr (units E T R),  dF/dx = -dR/dh,
    dF/dh = -2 pi int kappa chi r dr.

Collecting terms, both are assembled from coefficient fields computed once per
assembly (the material law is then evaluated once, not once per pair of basis
functions): ``residual_coefficients`` and ``tangent_coefficients``.

Quadrature points lie inside the elements, so r > 0 wherever 1/r appears.
"""

from __future__ import annotations

import numpy as np
from skfem import BilinearForm, Functional, LinearForm

__all__ = [
    "residual_coefficients",
    "tangent_coefficients",
    "residual",
    "tangent",
    "volume",
    "volume_gradient",
    "contact_force",
    "contact_force_gradient",
    "contact_force_stiffness",
    "contact_pressure",
]


def _kinematics(w):
    """Stretches, unit tangent and radius at the quadrature points."""
    r = w.r
    rho, drho, deta = w.u[0], w.u.grad[0, 0], w.u.grad[1, 0]
    l1 = np.sqrt(drho**2 + deta**2)
    return r, rho, l1, rho / r, drho / l1, deta / l1


def contact_pressure(w):
    """(p_N, chi): plate pressure per reference area and its active-set indicator."""
    trial = w.lam + w.kappa * (w.u[1] - w.h)
    chi = trial > 0.0
    return np.where(chi, trial, 0.0), chi


def residual_coefficients(material, w) -> dict:
    """R(v) = int (f_a v_a' + g_a v_a) dr: the fields f, g (a = rho, eta) at the quadrature points."""
    r, rho, l1, l2, t0, t1 = _kinematics(w)
    w1, w2 = material.gradient(l1, l2)
    deta = w.u.grad[1, 0]
    p_n, _ = contact_pressure(w)
    two_pi = 2.0 * np.pi
    return dict(
        f0=two_pi * w1 * t0 * r,
        f1=two_pi * w1 * t1 * r + np.pi * w.P * rho**2,
        g0=two_pi * w2 + two_pi * w.P * rho * deta,
        g1=two_pi * p_n * r,
    )


def tangent_coefficients(material, w) -> dict:
    """K(du, v) = int (G_ab du_a' v_b' + M_ab du_a v_b' + M_ba du_a' v_b + N_ab du_a v_b) dr.

    The fields G (symmetric), M and N (diagonal) at the quadrature points,
    collected from the tangent of the module docstring.
    """
    r, rho, l1, l2, t0, t1 = _kinematics(w)
    w1, _ = material.gradient(l1, l2)
    w11, w12, w22 = material.hessian(l1, l2)
    _, chi = contact_pressure(w)
    two_pi = 2.0 * np.pi
    along, across = two_pi * (w11 - w1 / l1) * r, two_pi * w1 / l1 * r
    return dict(
        G00=along * t0 * t0 + across,
        G01=along * t0 * t1,
        G11=along * t1 * t1 + across,
        M00=two_pi * w12 * t0,
        M01=two_pi * (w12 * t1 + w.P * rho),
        N00=two_pi * (w22 / r + w.P * w.u.grad[1, 0]),
        N11=two_pi * w.kappa * chi * r,
    )


@LinearForm
def residual(v, w):
    """R(v) from the fields of ``residual_coefficients``."""
    return w.f0 * v.grad[0, 0] + w.f1 * v.grad[1, 0] + w.g0 * v[0] + w.g1 * v[1]


@BilinearForm
def tangent(du, v, w):
    """K(du, v) from the fields of ``tangent_coefficients``."""
    d0, d1, e0, e1 = du.grad[0, 0], du.grad[1, 0], v.grad[0, 0], v.grad[1, 0]
    return (
        w.G00 * d0 * e0
        + w.G01 * (d0 * e1 + d1 * e0)
        + w.G11 * d1 * e1
        + du[0] * (w.M00 * e0 + w.M01 * e1)
        + v[0] * (w.M00 * d0 + w.M01 * d1)
        + w.N00 * du[0] * v[0]
        + w.N11 * du[1] * v[1]
    )


@Functional
def volume(w):
    """V = -pi int rho^2 eta' dr."""
    return -np.pi * w.u[0] ** 2 * w.u.grad[1, 0]


@LinearForm
def volume_gradient(v, w):
    """dV(v) = -pi int (2 rho eta' v_rho + rho^2 v_eta') dr."""
    rho, deta = w.u[0], w.u.grad[1, 0]
    return -np.pi * (2.0 * rho * deta * v[0] + rho**2 * v.grad[1, 0])


@Functional
def contact_force(w):
    """Plate force F = 2 pi int p_N r dr, in units of E T R."""
    p_n, _ = contact_pressure(w)
    return 2.0 * np.pi * p_n * w.x[0]


@LinearForm
def contact_force_gradient(v, w):
    """dF/dx (v) = 2 pi int kappa chi v_eta r dr  (also -dR/dh)."""
    _, chi = contact_pressure(w)
    return 2.0 * np.pi * w.kappa * chi * v[1] * w.x[0]


@Functional
def contact_force_stiffness(w):
    """dF/dh = -2 pi int kappa chi r dr."""
    _, chi = contact_pressure(w)
    return -2.0 * np.pi * w.kappa * chi * w.x[0]
