r"""The solid's weak forms written as scikit-fem forms, one per term: the definitions that
``pocket.solid.assembly``'s array contractions are checked against (its docstring derives them).
"""


from __future__ import annotations

import numpy as np
from pocket.solid import kinematics as kin
from skfem import BilinearForm, Functional, LinearForm

__all__ = [
    "coupling",
    "residual_p",
    "residual_u",
    "tangent_uu",
    "volume",
    "volume_first",
    "volume_second",
]

def _deformation(w):
    return kin.gradient(w["u"].grad, w["u"][0], w.x[0])


def residual_u(law):
    """R_u[v] of the rubber ``law`` (``laws.derivatives``); w holds ``u`` (vector) and ``p`` (scalar)."""

    @LinearForm
    def form(v, w):
        F = _deformation(w)
        stress = kin.energy_derivatives(F, law)[0] + np.asarray(w["p"]) * kin.jacobian_derivatives(F)[0]
        return np.einsum("a...,a...->...", stress, kin.field_components(v, w.x[0])) * 2.0 * np.pi * w.x[0]

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
    dF_du, dF_v = kin.field_components(du, r), kin.field_components(v, r)
    return np.einsum("ab...,a...,b...->...", table, dF_du, dF_v) * 2.0 * np.pi * r


@BilinearForm
def coupling(du, q, w):
    """K_pu[du, q] = int q cof F : dF[du] 2 pi r (rows: pressure, columns: displacement); w holds ``u``."""
    cof = kin.components(kin.cofactor(_deformation(w)))
    return q * np.einsum("a...,a...->...", cof, kin.field_components(du, w.x[0])) * 2.0 * np.pi * w.x[0]


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
