"""From a converged unknown vector to the reported numbers and the nodal profile.

Pole stretch (inflation). Near the axis rho is odd in r, so
rho/r = lambda_0 + b r^2 + c r^4 + ...; the quadratic in r^2 through rho/r at
three consecutive vertices, evaluated at r = 0, gives lambda_0 to O(r^6) plus
the nodal errors divided by r. The three are the first vertices at or beyond
``R_FIT`` from the axis (a nodal value carries round-off of about 1e-16 R,
which rho/r would magnify near the axis). The pole stretch is a point
derivative at the axis, where the axisymmetric forms are singular: its
influence function grows like 1/r, and on uniform meshes the discrete rho/r
near the axis is only O(h^2) accurate (measured), whatever the element order.
Meshes graded towards the axis (``meshes.polar``) restore O(h^2p).

Contact stretch (edge-fitted contact): lambda_c = rho(a)/a, a nodal value at
the edge vertex (the contact zone holds rho = lambda_c r exactly).

Clamp stretch. The derivative of x at the clamp converges only as O(h^p); the
reaction, the residual row of the fixed dofs, is a variationally consistent
flux and converges like the energy, O(h^2p). Integrating the residual by parts
with equilibrium inside, at r = 1 (rho = 1, lambda_2 = 1, w_1 = T1):

    R_rho(clamp) = 2 pi T1 t_rho,    R_eta(clamp) = 2 pi T1 t_eta + pi P,

so T1 = +-|(R_rho, R_eta - pi P)| / (2 pi), its sign that of the vector's
component along the discrete tangent at the clamp (negative: a compressed
clamp, which the state then reports), and lambda_1 solves
T1(lambda_1, 1) = w_1(lambda_1, 1) = T1 (``material.Law.planar_stretch``,
from the element's own slope at the clamp; for Mooney-Rivlin
w_1(l, 1) = (l - l^-3) / 3, monotonic).

Edge tension (edge-fitted contact). The meridional tension at the contact edge, T_1(a+) = T_1(a-) (the
stretches are continuous there), from the contact zone's flux: integrating the zone's rho rows by parts with its
interior in equilibrium, the edge vertex's rho row over the zone's elements alone is the boundary term
2 pi r0 w_1 t_rho at r = a, where the meridian lies flat (t = (1, 0)) and r0 w_1 = r0 lambda_2 T_1 = rho(a) T_1:

    R_rho(edge; contact zone) = 2 pi rho(a) T_1(a),

the pressure entering none of the zone's rho rows (its term P rho eta' vanishes where eta' = 0); by the edge row's
equilibrium it is minus the free part's pull on the zone. Like the clamp's reaction it converges like the energy.
The one-sided derivatives at the edge do not serve: as T_1(a) falls the free meridian leaves the plate with the
curvature P / T_1, a corner sharper than the first free element, whose own slope there swings by more than
T_1(a) itself (measured: on the default capsule mesh at Phat_I = 0.01, Fhat = 0.1, T_1 = 6.6e-4 E T from its slope
at the edge, -7.4e-5 at its middle quadrature point, against 1.31e-4 by the flux and by the shooting solver).

The profile samples every node (vertices and P2 midpoints), so that a line
through its points follows the quadratic meridian to O(h^3/8) rather than
O(h^2/8). Nodal stretches elsewhere: lambda_1 at a vertex the mean of the
one-sided derivatives of the adjacent elements, at a midpoint the element's
own, lambda_2 = rho/r.
"""

from __future__ import annotations

import math

import numpy as np

from pocket.core.states import Profile

from . import kernel
from .geometry import Placement, node_radii
from .model import FITTED, Model, edge, forms, placement, split

__all__ = ["R_FIT", "clamp_stretch", "edge_tension", "node_slope", "pole_stretch", "profile", "reaction",
           "reference_radius", "vertices"]

R_FIT = 1e-4  # smallest radius (units R) of the vertices the pole stretch is fitted to


def vertices(model: Model, y: np.ndarray, mode: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(r, rho, eta) at the mesh vertices."""
    u, _ = split(model, y)
    step = 2 * model.order
    return placement(model, y, mode).vertices, u[0::step], u[1::step]


def reaction(model: Model, y: np.ndarray, mode: str, multiplier=0.0) -> np.ndarray:
    """The residual R at every nodal dof, fixed ones included (their reactions)."""
    return forms(model, y, mode, multiplier).residual


def reference_radius(model: Model, r: np.ndarray) -> np.ndarray:
    """r0 at the mesh coordinates r: r itself on the flat disc, sin(pi r / 2) on the capsule's sphere (``kernel``)."""
    geometry = model.geometry
    return geometry.radius(r if geometry.length == 1.0 else geometry.length * r)


def pole_stretch(model: Model, y: np.ndarray, mode: str) -> float:
    """lambda_0 from rho/r0 at three vertices near the axis, extrapolated in r^2 (module docstring; rho/r0 is even
    in r on the sphere as on the disc)."""
    r, rho, _ = vertices(model, y, mode)
    k = max(int(np.searchsorted(r, R_FIT)), 1)
    k = min(k, r.size - 3)
    x, s = r[k: k + 3] ** 2, rho[k: k + 3] / reference_radius(model, r[k: k + 3])
    return float(s[0] * x[1] * x[2] / ((x[0] - x[1]) * (x[0] - x[2]))
                 + s[1] * x[0] * x[2] / ((x[1] - x[0]) * (x[1] - x[2]))
                 + s[2] * x[0] * x[1] / ((x[2] - x[0]) * (x[2] - x[1])))


def clamp_stretch(model: Model, y: np.ndarray, mode: str, rows: np.ndarray) -> float:
    """Meridional stretch at the clamp from the reaction ``rows`` (``reaction``; module docstring)."""
    flux = np.array([rows[-2], rows[-1] - np.pi * y[model.dofs]])
    u, _ = split(model, y)
    p, length = model.order, placement(model, y, mode).lengths[-1]
    nodal = u.reshape(-1, 2)[-(p + 1):]  # the last element's nodes, along r
    slope = (nodal[-1] - nodal[-2]) / length if p == 1 else (nodal[0] + 3 * nodal[2] - 4 * nodal[1]) / length
    sign = 1.0 if flux @ slope >= 0.0 else -1.0
    tension = sign * float(np.hypot(*flux)) / (2 * np.pi)
    return model.law.planar_stretch(tension, float(np.hypot(*slope)))


def edge_tension(model: Model, y: np.ndarray) -> float:
    """T_1 (units E T) at the contact edge of the converged FITTED state y, from the contact zone's flux (module
    docstring): the edge vertex's rho row over the zone's ``model.flat`` elements, over 2 pi rho(a); NaN where
    rho(a) <= 0 (a degenerate state, which the states' own checks refuse)."""
    u, scalars = split(model, y)
    whole, k = placement(model, y, FITTED), model.flat
    assert whole.velocity is not None, "a FITTED placement follows the edge"
    assert whole.stretch_rate is not None, "a FITTED placement follows the edge"
    zone = Placement(whole.vertices[: k + 1], whole.lengths[:k], whole.r[:k], whole.a, whole.velocity[:k],
                     whole.stretch_rate[:k])
    at = edge(model)
    rows = kernel.evaluate(model.law, model.ref, zone, u[: at + 2], float(scalars[0]), tangent=False,
                           geometry=model.geometry).residual
    radius = float(u[at])
    return float(rows[at]) / (2.0 * np.pi * radius) if radius > 0.0 else math.nan


def profile(model: Model, y: np.ndarray, mode: str, *, pole: float, clamp: float,
            contact_radius: float = 0.0) -> Profile:
    """The profile at every node (vertices and, for P2, midpoints): stretches, tensions (units E T) and
    contact flag; ``pole``, ``clamp``: the stretch at r = 0 (equibiaxial) and the meridional one at r = 1."""
    u, _ = split(model, y)
    r = node_radii(placement(model, y, mode), model.ref)
    rho, eta = u[0::2].copy(), u[1::2].copy()
    l1 = node_slope(model, y, mode)
    l2 = np.empty_like(r)
    l2[1:] = rho[1:] / r[1:]
    l1[0] = l2[0] = pole
    l1[-1] = clamp
    if mode == "fitted":  # the flat zone is equibiaxial, lambda_c = pole, up to the edge vertex
        inside = r <= contact_radius
        l1[inside] = l2[inside] = pole
    t1, t2 = model.law.tensions(l1, l2)
    return Profile(r, rho, eta, l1, l2, t1, t2, r <= contact_radius if contact_radius > 0 else r < 0)


def node_slope(model: Model, y: np.ndarray, mode: str) -> np.ndarray:
    """|x'| at the nodes: at a vertex the mean of the two adjacent elements' one-sided values, at a P2
    midpoint the element's own (the secant slope of its quadratic)."""
    u, _ = split(model, y)
    p, n = model.order, model.elements
    nodal = u.reshape(-1, 2)[p * np.arange(n)[:, None] + np.arange(p + 1)]  # (n, p + 1, 2)
    lengths = placement(model, y, mode).lengths[:, None]
    secant = np.hypot(*((nodal[:, -1] - nodal[:, 0]) / lengths).T)
    if p == 1:
        left = right = secant
    else:
        v0, vm, v1 = nodal[:, 0], nodal[:, 1], nodal[:, 2]
        left = np.hypot(*((-3 * v0 - v1 + 4 * vm) / lengths).T)
        right = np.hypot(*((v0 + 3 * v1 - 4 * vm) / lengths).T)
    slope = np.empty(p * n + 1)
    slope[0], slope[-1] = left[0], right[-1]
    slope[p: -1: p] = 0.5 * (right[:-1] + left[1:])
    if p == 2:
        slope[1::2] = secant
    return slope
