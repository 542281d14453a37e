r"""What a state reports, from the solved fields: surfaces, stretches, tensions, volumes.

Lines of nodes. The biquadratic nodes lie on a tensor grid of 2 n + 1 radii by 2 m + 1 heights
(n elements along, m through); along each line of the grid a displacement component is the
quadratic of its three nodes in each element, so a line's slope and integrals are exact from them.

- The mid-surface z = 0 (a grid line): rho = r + u_r, eta = u_z. Its stretches are the membrane's
  lambda_1 = |(rho', eta')|, lambda_2 = rho / r (-> rho'(0) on the axis); its volume
  V_mid = int 2 pi rho eta rho' dr (the membrane's volume, under its mid-surface) by 3-point
  Gauss on each element (exact: the integrand is of degree 5).
- Tensions: the membrane's stress resultants are the through-thickness integrals of the first
  Piola stress P = dW + p dJ (``kinematics``), N_1 = int (P e_R) . t dZ (t the mid-surface's unit
  tangent) and N_2 = int P_thth dZ (force per unit reference length); per unit deformed length T_1 = N_1 / lambda_2,
  T_2 = N_2 / lambda_1, in units of E T = 3 mu_0 t R. P is projected onto the biquadratic nodes
  (L2) and integrated by Simpson's rule on each layer (exact for the quadratic in z).
- Incompressibility, two measures of J - 1 = det F - 1. Taylor-Hood holds the weak constraint
  R_p[psi_k] = int psi_k (J - 1) dV = 0 against each bilinear pressure psi_k, which Newton solves
  to its tolerance: ``det_f_constraint_residual`` is max_k |R_p[psi_k]| / int psi_k dV, the
  pressure-weighted mean of J - 1 around node k (relative, like J - 1 itself). Pointwise J - 1 is a
  discretisation error: ``mesh_det_f_error_peak`` is its largest |.| at the quadrature points (~0.4 at
  the clamp's singular corners, whose elements are half a thickness long whatever the mesh, so it
  does not fall with the mesh there; away from the clamp it falls at order ~2, a test shows).
"""

from __future__ import annotations

import numpy as np
from skfem import ElementQuad2

from . import assembly
from . import kinematics as kin
from .model import Model, split

__all__ = ["Fields", "fields"]

_GAUSS = np.polynomial.legendre.leggauss(3)


class Fields:
    """The grid's nodal displacement and the reported profiles of one state (attributes below)."""

    r: np.ndarray          # (2n+1,) radii of the grid
    rho: np.ndarray        # (2n+1,) the mid-surface's deformed radius
    eta: np.ndarray        # (2n+1,) its height
    stretch_1: np.ndarray  # (2n+1,)
    stretch_2: np.ndarray
    tension_1: np.ndarray
    tension_2: np.ndarray
    top_rho: np.ndarray    # (2n+1,) the upper surface's deformed radius and height
    top_eta: np.ndarray
    volume_mid: float
    mesh_det_f_error_peak: float
    det_f_constraint_residual: float


def _slope(r: np.ndarray, f: np.ndarray) -> np.ndarray:
    """df/dr at the grid's nodes (odd ones: element midpoints), from each element's quadratic (at the
    element ends the mean of the two sides' slopes; the ends of the line one-sided)."""
    r0, r2 = r[0:-2:2], r[2::2]
    f0, f1, f2 = f[0:-2:2], f[1:-1:2], f[2::2]
    h = r2 - r0
    left = (-3.0 * f0 + 4.0 * f1 - f2) / h
    mid = (f2 - f0) / h
    right = (f0 - 4.0 * f1 + 3.0 * f2) / h
    out = np.empty_like(f)
    out[1:-1:2] = mid
    out[0], out[-1] = left[0], right[-1]
    out[2:-2:2] = 0.5 * (right[:-1] + left[1:])
    return out


def _line_volume(r: np.ndarray, rho: np.ndarray, eta: np.ndarray) -> float:
    """int 2 pi rho eta rho' dr over the line, each component the quadratic of its element's nodes."""
    x, w = _GAUSS
    total = 0.0
    for k in range(0, r.size - 2, 2):
        a, b = r[k], r[k + 2]
        s = 0.5 * (x + 1.0)  # in [0, 1]
        shape = np.array([2 * (s - 0.5) * (s - 1.0), -4 * s * (s - 1.0), 2 * s * (s - 0.5)])
        dshape = np.array([4 * s - 3.0, -8 * s + 4.0, 4 * s - 1.0]) / (b - a)
        p, e = rho[k:k + 3] @ shape, eta[k:k + 3] @ shape
        total += 0.5 * (b - a) * np.sum(w * 2.0 * np.pi * p * e * (rho[k:k + 3] @ dshape))
    return float(total)


def _levels(x: np.ndarray, tol: float = 1e-10) -> np.ndarray:
    """The index of each coordinate's level among the distinct values of ``x`` (values within ``tol`` of the one
    before are one level: a node shared by two elements may be placed by each to a rounding apart, and rounding
    to fixed decimals splits such a pair where it straddles a rounding boundary)."""
    ordered = np.sort(x)
    starts = ordered[np.concatenate([[True], np.diff(ordered) > tol])]
    return np.searchsorted(starts, x + tol, side="right") - 1


def _grid(model: Model):
    """The scalar biquadratic basis and its dofs arranged as the grid (heights, radii)."""
    scalar = model.basis_u.with_element(ElementQuad2())
    loc = scalar.doflocs
    radial = _levels(loc[0])
    order = np.lexsort((radial, _levels(loc[1])))
    return scalar, order.reshape(-1, radial.max() + 1)


def fields(model: Model, y: np.ndarray) -> Fields:
    """The reported fields of the state y (``Fields``)."""
    u, p = split(model, y)
    scalar, grid = _grid(model)
    ur, uz = u[model.basis_u.split_indices()[0]], u[model.basis_u.split_indices()[1]]
    r, z = scalar.doflocs[0, grid[0]], scalar.doflocs[1, grid[:, 0]]
    mid = grid[(grid.shape[0] - 1) // 2]
    out = Fields()
    out.r = r
    out.rho, out.eta = r + ur[mid], uz[mid]
    d_rho, d_eta = _slope(r, out.rho), _slope(r, out.eta)
    out.stretch_1 = np.hypot(d_rho, d_eta)
    with np.errstate(invalid="ignore", divide="ignore"):
        out.stretch_2 = np.where(r > 0.0, out.rho / np.where(r > 0.0, r, 1.0), d_rho)
    out.top_rho, out.top_eta = r + ur[grid[-1]], z[-1] + uz[grid[-1]]
    out.volume_mid = _line_volume(r, out.rho, out.eta)
    uq = model.basis_u.interpolate(u)
    F = kin.gradient(uq.grad, uq[0], model.basis_u.global_coordinates()[0])
    change = kin.jacobian(F) - 1.0
    out.mesh_det_f_error_peak = float(np.abs(change).max())
    tab = model.tables
    weak = assembly.pressure_moments(tab, change) / assembly.pressure_moments(tab, np.ones_like(change))
    out.det_f_constraint_residual = float(np.abs(weak).max())
    pressure = np.asarray(model.basis_p.interpolate(p))
    P = kin.energy_derivatives(F, model.law)[0] + pressure * kin.jacobian_derivatives(F)[0]
    nodal = {key: scalar.project(P[a])[grid] for key, a in {"rR": 0, "zR": 2, "hoop": 4}.items()}
    simpson = np.zeros(z.size)  # Simpson's rule on each layer [z_2k, z_2k+2], its midpoint z_2k+1
    layer = z[2::2] - z[0:-2:2]
    simpson[0:-2:2] += layer / 6.0
    simpson[1::2] += 4.0 * layer / 6.0
    simpson[2::2] += layer / 6.0
    tangent = np.array([d_rho, d_eta]) / out.stretch_1
    n1 = simpson @ (nodal["rR"] * tangent[0] + nodal["zR"] * tangent[1])
    n2 = simpson @ nodal["hoop"]
    scale = 3.0 * model.thickness  # E T in units mu_0 R
    out.tension_1 = n1 / out.stretch_2 / scale
    out.tension_2 = n2 / out.stretch_1 / scale
    return out
