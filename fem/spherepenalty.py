r"""The penalty contact with a curved indenter: its terms, added to the membrane's forms on a fixed mesh.

The indenter's surface (``surfaces``) lies at eta = h + z(rho). The gap is measured vertically,
d = eta - h - z(rho) (positive: the sheet inside the indenter), and with the multiplier field l
the contact pressure per unit of the surface's plan area is p_N = <l + kappa d>_+, as for the plate
(``kernel``), whose energy term becomes

    2 pi int (1 / (2 kappa)) <l + kappa d>_+^2 r dr.

With n = (-z', 1) (d's gradient in (rho, eta)), chi = [l + kappa d > 0]:

    R(v) += 2 pi int p_N (n . v) r dr,
    K(du, v) += 2 pi int (kappa chi (n . du)(n . v) - p_N z'' du_0 v_0) r dr,
    F = 2 pi int p_N r dr,   dF/dx = 2 pi kappa chi n r,   dF/dh = -2 pi int kappa chi r dr,

and dR/dh = -dF/dx. At the flat plate (z = 0) these are ``kernel``'s terms. A point past the
surface's reach (a sphere's equator) is under no surface and out of contact. The vertical gap's
penetration is what ``penalty`` reports and removes by Uzawa updates.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from . import kernel
from .geometry import Placement
from .reference import Reference

__all__ = ["add", "gap"]


def gap(surface, rho: np.ndarray, eta: np.ndarray, height: float) -> np.ndarray:
    """d = eta - h - z(rho) (units R), -inf past the surface's reach."""
    inside = rho < surface.reach
    out = np.full(np.shape(rho), -np.inf)
    out[inside] = eta[inside] - height - surface.height(rho[inside])
    return out


def add(ref: Reference, placement: Placement, u: np.ndarray, pressure: float, contact: kernel.Contact, surface,
        linear: kernel.Linear, tangent: bool) -> kernel.Linear:
    """``linear`` (the membrane's forms without contact) with the curved penalty's terms added (module
    docstring): R, dF/dx and the element matrices in place, F and dF/dh in the returned copy."""
    w = kernel.fields(ref, placement, u, pressure)
    d = gap(surface, w.rho, w.eta, contact.height)
    trial = np.asarray(contact.multiplier, dtype=float) + contact.penalty * d
    chi = trial > 0.0
    p_n = np.where(chi, trial, 0.0)
    rho = np.where(chi, w.rho, 0.0)
    slope, second = surface.slope(rho), surface.second(rho)
    measure = ref.weights * w.lengths[:, None] * 2.0 * np.pi * w.r  # 2 pi r dr at the points, (n, Q)
    stiff = contact.penalty * chi * measure
    p, n = ref.order, w.lengths.size
    local = np.zeros((n, p + 1, 2, 2))  # [element, node, (R, dF/dx), (rho, eta)]
    for value, k in ((p_n * measure, 0), (stiff, 1)):
        local[:, :, k, 0] = (-value * slope) @ ref.phi
        local[:, :, k, 1] = value @ ref.phi
    for k, rows in enumerate((linear.residual, linear.force)):
        for a in range(p + 1):
            np.add.at(rows.reshape(-1, 2), p * np.arange(n) + a, local[:, a, k])
    if tangent:
        normal = np.stack([-slope, np.ones_like(slope)], axis=-1)  # (n, Q, 2)
        block = (np.einsum("eq,eqc,eqd->eqcd", stiff, normal, normal)
                 - np.einsum("eq,eq,cd->eqcd", p_n * measure, second, np.diag([1.0, 0.0])))
        matrices = np.einsum("eqcd,qa,qb->eacbd", block, ref.phi, ref.phi).reshape(n, 2 * (p + 1), 2 * (p + 1))
        linear.matrices[:] += matrices
    return dataclasses.replace(linear, plate_force=float(np.sum(p_n * measure)), force_stiffness=-float(stiff.sum()))
