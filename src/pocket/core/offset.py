r"""The sheet's lower surface, where the fluid is: the membrane's mid-surface offset by half its thickness.

A membrane state gives the mid-surface (rho(r), eta(r)) and its stretches; its ``volume`` V is under
the mid-surface, from the clamp plane z = 0. The fluid lies under the lower surface, which meets the
clamp at its lower corner (R, -T/2) and, away from the clamp, lies half the deformed thickness
lambda_3 T/2 below the mid-surface. Lengths in units of R, volumes in R^3; t = T/R is the thickness of
the clamped flat sheet (T / lambda_p^2 for a sheet clamped with a prestretch lambda_p, whose stretches
are relative to the clamped sheet).

The lower surface
-----------------
With x(r) = (rho, eta) the meridian, s = |x'| = lambda_1 its metric and n = (eta', -rho') / s its unit
normal towards the fluid (n = (0, -1) at the pole), the lower surface is

    x_l(r) = x(r) + d(r) n(r),    d = lambda_3 t / 2,   lambda_3 = 1 / (lambda_1 lambda_2).

At the clamp C = (1, 0) it ends at P = C + d_c n_c (d_c = lambda_3c t / 2), inside the clamp radius by
d_c sin(psi_c) and above the corner Q = (1, -t/2) (psi_c the meridian's slope angle below the
horizontal at the clamp). A membrane has a slope jump there; a solid sheet turns through a bending
layer of length ~T whose shape a membrane cannot give. The lower surface is closed by the straight
segment P Q, so that it passes through the clamp's lower corner as the solid sheet's does; another
closure inside the triangle C P Q changes the volume by less than the triangle's, O(t^2) below.
V_lower is the volume under x_l and P Q, from the plane z = -t/2.

The volume, and its first order
-------------------------------
The map (r, xi) -> x + xi n has the volume element (1 - xi k_1)(1 - xi k_2) dxi dA, whatever d(r) is
(k_1 = x'' . n / s^2 and k_2 = -n_rho / rho the principal curvatures, positive towards the fluid: 1/a
on a sphere of radius a; dA the deformed area), so the band between the mid-surface and x_l, closed at
the clamp by the normal segment C P, has the volume

    B = int dA int_0^d (1 - xi k_1)(1 - xi k_2) dxi = int (d - d^2 (k_1 + k_2)/2 + d^3 k_1 k_2 / 3) dA.

With dA = lambda_1 lambda_2 dA_0 (dA_0 = 2 pi r dr) its first term is int (t/2) dA_0 = (t/2) pi exactly:
the lower half of the sheet keeps its volume. The region under x_l from z = -t/2 is the region under
the mid-surface from z = 0, plus the slab of volume pi t / 2 between the two planes, less the band,
less the triangle C P Q turned about the axis (area d_c sin(psi_c) t/4 at the mean radius
1 - d_c sin(psi_c)/3, Pappus). The first-order terms cancel exactly:

    V_lower - V = int (d^2 (k_1 + k_2)/2 - d^3 k_1 k_2 / 3) dA - 2 pi (1 - d_c sin(psi_c)/3) d_c sin(psi_c) t/4
                = (pi t^2 / 4) [ int_0^1 lambda_3 (k_1 + k_2) r dr - lambda_3c sin(psi_c) ] + O(t^3).

Measured from its own clamp plane, the fluid under the lower surface of an incompressible sheet has the
mid-surface's volume to first order in T/R; only the curvature and clamp terms, O(t^2), separate them
(they vanish at every order on a uniformly stretched spherical cap, whose offset is a concentric cap).
Those terms are the offset's own: any incompressible sheet whose clamp holds its edge face keeps the
volume pi t / 2 of its lower half, so the volume under its lower surface from z = -t/2 equals the
volume under its material mid-surface from z = 0 exactly (the solid's ``volume`` and ``volume_mid``
agree to its discrete incompressibility). An offset by lambda_3 t/2 along the normal, thickness taken
at the mid-surface's stretches, holds that volume only to first order. A membrane's O(t) difference
from the solid is therefore not where its volume is measured: it is the solid's mid-surface itself.

Computed as written: the exact cancellation is kept by computing V_lower - V from the last formula's
first line (the state's V is its solver's), with dA = pi t r dr / d exact from lambda_3; only the
curvatures come from the samples, through not-a-knot cubic splines of x(r) and lambda_3(r) (curvature
error O(h^2) where the profile is smooth, O(h) near a contact edge's curvature jump, times t^2),
integrated by 4-point Gauss-Legendre on each interval. The offset folds where d k_1 or d k_2 reaches 1
(a radius of curvature below half the thickness): there is no lower surface of this form there, and
that is an OutOfRangeError.
"""

from __future__ import annotations

import numpy as np

from .errors import InputError, OutOfRangeError
from .inputs import check_finite, quote

__all__ = ["check_thickness", "volume_correction"]

#: Gauss-Legendre points on [0, 1] and their weights, per sample interval
_NODES, _WEIGHTS = (np.polynomial.legendre.leggauss(4)[0] + 1.0) / 2.0, np.polynomial.legendre.leggauss(4)[1] / 2.0


def check_thickness(name: str, value) -> float:
    """T/R in (0, 0.5): a thicker 'sheet' is a block, and the pocket's geometry assumes T < R / 2."""
    t = check_finite(name, value)
    if not 0.0 < t < 0.5:
        raise InputError(f"{name} = {quote(value)}, but the thickness ratio T/R must lie in (0, 0.5)")
    return t


def _curvatures(x, r: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """k_1, k_2 (towards the fluid, units 1/R) and sin(psi) of the meridian spline ``x`` at the radii ``r``
    (shape (m,), all > 0)."""
    (rho, _), (rho1, eta1), (rho2, eta2) = x(r).T, x(r, 1).T, x(r, 2).T
    s = np.hypot(rho1, eta1)
    return (rho2 * eta1 - eta2 * rho1) / s**3, -eta1 / (s * rho), -eta1 / s


def volume_correction(profile, thickness_ratio: float) -> float:
    """(V_lower - V) / R^3: what the fluid's volume under the sheet's lower surface (the mid-surface offset
    by lambda_3 t/2 towards the fluid, closed by a straight segment to the clamp's lower corner (1, -t/2),
    from the plane z = -t/2) exceeds the volume V under the mid-surface ``profile``
    (``pocket.core.states.Profile``) from z = 0, for the clamped flat sheet's t = T/R = ``thickness_ratio``
    in (0, 0.5) (module docstring): O(t^2). An OutOfRangeError where the offset would fold."""
    t = check_thickness("thickness_ratio", thickness_ratio)
    from scipy.interpolate import CubicSpline

    r = np.asarray(profile.r, dtype=float)
    if r.size < 4 or r[0] != 0.0 or r[-1] != 1.0 or np.any(np.diff(r) <= 0.0):
        raise ValueError(f"a profile's {r.size} radii must increase from 0 to 1, at least 4 of them")
    x = CubicSpline(r, np.column_stack([profile.rho, profile.eta]))
    h = np.diff(r)
    at = (r[:-1, None] + h[:, None] * _NODES).ravel()
    d = CubicSpline(r, profile.stretch_3)(at) * t / 2.0
    k1, k2, _ = _curvatures(x, at)
    fold = np.maximum(d * k1, d * k2)
    if np.any(fold >= 1.0):
        i = int(np.argmax(fold))
        raise OutOfRangeError(f"the sheet's lower surface folds at r = {at[i]:.4g} R: a radius of curvature "
                              f"{d[i] / fold[i]:.4g} R is below half the thickness ({d[i]:.4g} R)")
    area = np.pi * t * at / d  # dA / dr = lambda_1 lambda_2 2 pi r = 2 pi r / lambda_3 = pi t r / d
    band = float(np.sum((h[:, None] * _WEIGHTS).ravel() * (d**2 * (k1 + k2) / 2.0 - d**3 * k1 * k2 / 3.0) * area))
    inside = profile.stretch_3[-1] * t / 2.0 * _curvatures(x, r[-1:])[2][0]  # d_c sin(psi_c)
    return band - 2.0 * np.pi * (1.0 - inside / 3.0) * inside * t / 4.0
