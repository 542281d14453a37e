"""From a converged unknown vector to the reported numbers and the nodal profile.

Pole stretch. Near the axis rho is odd in r, rho = lambda_0 r + c r^3 + ..., so
rho/r = lambda_0 + c r^2 + O(r^4): the values at the first two mesh vertices,
extrapolated in r^2 to r = 0, give lambda_0 (or lambda_c in contact) to
O(h^4) plus the (superconvergent) nodal error divided by h.

Clamp stretch. The derivative of x at the clamp converges only as O(h^p); the
reaction, the residual row of the fixed dofs, is a variationally consistent
flux and converges like the energy, O(h^2p). Integrating the residual by parts
with equilibrium inside, at r = 1 (rho = 1, lambda_2 = 1, w_1 = T1):

    R_rho(clamp) = 2 pi T1 t_rho,    R_eta(clamp) = 2 pi T1 t_eta + pi P,

so T1 = |(R_rho, R_eta - pi P)| / (2 pi), and lambda_1 solves
T1(lambda_1, 1) = (lambda_1 - lambda_1^-3) / 3 = T1 (monotonic).

Nodal stretches elsewhere: lambda_1 the mean of the one-sided derivatives of
the adjacent elements, lambda_2 = rho/r.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
from scipy.optimize import brentq

from pocket.core.states import Profile

from . import forms
from .model import Model, full, parameters, plate_pressure

__all__ = [
    "nodal",
    "pole_stretch",
    "clamp_stretch",
    "volume",
    "plate_force",
    "contact_area_active",
    "profile",
]


def nodal(model: Model, y: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(r, rho, eta) at the mesh vertices."""
    u = full(model, y)
    dofs = model.basis.nodal_dofs
    return model.basis.mesh.p[0], u[dofs[0]], u[dofs[1]]


def pole_stretch(model: Model, y: np.ndarray) -> float:
    """lambda at the pole from rho/r at the first two vertices, extrapolated in r^2."""
    r, rho, _ = nodal(model, y)
    (r1, r2), (l1, l2) = r[1:3], rho[1:3] / r[1:3]
    return float((r2**2 * l1 - r1**2 * l2) / (r2**2 - r1**2))


def clamp_stretch(model: Model, y: np.ndarray, lam) -> float:
    """Meridional stretch at the clamp from the reaction (module docstring)."""
    w = parameters(model, y, lam)
    rows = forms.residual.assemble(model.basis, **forms.residual_coefficients(model.material, SimpleNamespace(**w)))
    clamp = model.basis.get_dofs(lambda x: x[0] == 1.0).nodal
    tension = np.hypot(rows[clamp["u^1"][0]], rows[clamp["u^2"][0]] - np.pi * y[-2]) / (2 * np.pi)
    return float(brentq(lambda a: (a - a**-3) / 3.0 - tension, 0.5, 1e3, xtol=1e-15, rtol=1e-15))


def volume(model: Model, y: np.ndarray) -> float:
    """V(x)."""
    return float(forms.volume.assemble(model.basis, **parameters(model, y, 0.0)))


def plate_force(model: Model, y: np.ndarray, lam) -> float:
    """Plate reaction F = 2 pi int p_N r dr (units E T R)."""
    return float(forms.contact_force.assemble(model.basis, **parameters(model, y, lam)))


def contact_area_active(model: Model, y: np.ndarray, lam) -> float:
    """Deformed area of the active set, 2 pi int chi rho rho' dr (edge resolved to O(h))."""
    u = model.basis.interpolate(full(model, y))
    _, chi = plate_pressure(model, y, lam)
    return float(np.sum(2 * np.pi * chi * u[0] * u.grad[0, 0] * model.basis.dx))


def profile(model: Model, y: np.ndarray, lam, contact_radius: float = 0.0) -> Profile:
    """Nodal profile: stretches, tensions (units E T) and contact flag."""
    r, rho, eta = nodal(model, y)
    l1 = _vertex_slope(model, y)
    l2 = np.empty_like(r)
    l2[1:] = rho[1:] / r[1:]
    l1[0] = l2[0] = pole_stretch(model, y)
    l1[-1] = clamp_stretch(model, y, lam)
    t1, t2 = model.material.tensions(l1, l2)
    return Profile(r, rho, eta, l1, l2, t1, t2, r <= contact_radius if contact_radius > 0 else r < 0)


def _vertex_slope(model: Model, y: np.ndarray) -> np.ndarray:
    """|x'| at the vertices, the mean of the two adjacent elements' one-sided values."""
    u = full(model, y)
    t = model.basis.mesh.t
    h = np.diff(model.basis.mesh.p[0])[None, :]
    ends = []
    for c in range(2):
        v0, v1 = u[model.basis.nodal_dofs[c][t[0]]], u[model.basis.nodal_dofs[c][t[1]]]
        if model.order == 1:
            left = right = (v1 - v0) / h[0]
        else:
            vm = u[model.basis.interior_dofs[c]]
            left, right = (-3 * v0 - v1 + 4 * vm) / h[0], (v0 + 3 * v1 - 4 * vm) / h[0]
        ends.append((left, right))
    left = np.hypot(ends[0][0], ends[1][0])
    right = np.hypot(ends[0][1], ends[1][1])
    slope = np.empty(model.basis.mesh.p.shape[1])
    slope[0], slope[-1] = left[0], right[-1]
    slope[1:-1] = 0.5 * (right[:-1] + left[1:])
    return slope
