r"""The axisymmetric membrane equations in meridian-angle form, and their pole series.

Derivation (from the paper's eqs (2), (4)-(6); Yang & Feng 1970)
----------------------------------------------------------------
Lagrangian radius r (units of R), deformed meridian (rho(r), eta(r)), tangent angle
psi measured below the horizontal, so that with ' = d/dr

    rho' = lambda_1 cos(psi),    eta' = -lambda_1 sin(psi),    lambda_2 = rho / r.

Stress resultants: t1 = T_1 / (tau T) and t2 from the rubber's strain energy, with their
derivatives (``pocket.shooting.tensions``: tau = 2 C1 for Mooney-Rivlin, the paper's eq (6),
where t1 = (l1/l2 - 1/(l1^3 l2^3)) (1 + alpha l2^2); mu_0 for the other laws). Every law is
isotropic: t2(l1, l2) = t1(l2, l1).

Normal equilibrium, eq (4a), with kappa_1 = d psi/ds = psi'/lambda_1 and
kappa_2 = sin(psi)/rho (these are eq (5) written with the angle), gives

    psi' = lambda_1 (p - t2 sin(psi) / rho) / t1,    p = P R / (tau T) = (3 mu_0 / tau) Phat,

since E = 3 mu_0 (for Mooney-Rivlin p = P R / (2 C1 T) = 3 (1 + alpha) Phat, E = 6 (1 + alpha) C1).
Tangential equilibrium, eq (4b), is d(rho T1)/d rho = T2,
i.e. (rho t1)' = t2 rho', i.e. t1' = (t2 - t1) rho'/rho. With the chain rule and
lambda_2' = (rho' - lambda_2)/r:

    lambda_1' = [(t2 - t1) rho'/rho - dt1/dl2 * lambda_2'] / (dt1/dl1).

The enclosed volume V = -pi int rho^2 eta' dr (valid for any meridian) is carried as
the fifth unknown v' = pi rho^2 lambda_1 sin(psi). State y = [rho, eta, psi, lambda_1, v].

Typos found in the paper. Eq (7) is the lambda_1 equation above written with
w = rho' (it checks: ``tests/test_shooting_equations.py``) and eq (8) is lambda_2'.
Eq (9), the w equation, has ``(1/2) Phat (1 + alpha)`` where normal equilibrium
gives ``3 (1 + alpha) Phat r~`` (= p r~): as printed there is no regular solution at the
pole. The (lambda_1, lambda_2, w) form also contains sqrt(lambda_1^2 - w^2), which
vanishes where the meridian is horizontal (pole, contact edge) and then admits a
flat spurious solution; the angle form used here has no such trap.

Pole series (derived here, checked in the tests). With lambda_1 = l0 + a r^2,
lambda_2 = l0 + b r^2, psi = k r + O(r^3): normal equilibrium at the pole gives
2 kappa t0 = p with kappa = k / l0, so k = l0 p / (2 t0); rho' = lambda_1 cos(psi)
at O(r^2) gives a = 3 b + l0 k^2 / 2; tangential equilibrium at O(r) gives
a (3A - B) + b (3B - A) = 0 with A = dt1/dl1, B = dt1/dl2 at (l0, l0), hence
b = -l0 k^2 (3A - B) / (16 A). That step uses dt2/dl2 = A and dt2/dl1 = B at (l0, l0), which
isotropy gives (t2(l1, l2) = t1(l2, l1)): the series holds for every law here
(``tests/test_shooting_laws.py`` measures its order for each).
"""

from __future__ import annotations

import functools

import numpy as np

from pocket.core.compiled import compiled

from .tensions import tensions, tensions_compiled

__all__ = ["derivatives", "pole_state", "reference", "rhs", "rhs_on", "table_curvature"]


@functools.partial(compiled, inline="always")
def reference(r, sphere):
    """(r0, dr0/dS): the reference radius of the material point at arc length ``r`` and its slope, on the flat
    disc (r0 = S: ``sphere`` False) or on the unit sphere (r0 = sin S, a capsule: ``sphere`` True)."""
    if sphere:
        return np.sin(r), np.cos(r)
    return r, 1.0


@functools.partial(compiled, inline="always")
def rhs_on(r, radius, slope, y, code, params, p, out):
    """``rhs`` on a reference surface whose material point at arc length ``r`` lies at the reference radius
    ``radius`` = r0(S) with slope ``slope`` = r0'(S) (``reference``): lambda_2 = rho / r0 and
    lambda_2' = (rho' - lambda_2 r0') / r0; nothing else sees the surface."""
    rho, psi, l1 = y[0], y[2], y[3]
    l2 = rho / radius
    s, c = np.sin(psi), np.cos(psi)
    t1, t2, a11, a12 = tensions_compiled(l1, l2, code, params)
    drho = l1 * c
    dl2 = (drho - l2 * slope) / radius
    out[0] = drho
    out[1] = -l1 * s
    out[2] = l1 * (p - t2 * s / rho) / t1
    out[3] = ((t2 - t1) * drho / rho - a12 * dl2) / a11
    out[4] = np.pi * rho * rho * l1 * s


@functools.partial(compiled, inline="always")
def rhs(r, y, code, params, p, out):
    """Write dy/dr into ``out`` (shape (5,)) for y = [rho, eta, psi, lambda_1, v], the law ``code``
    with ``params`` (``pocket.shooting.tensions``) at pressure ``p`` (units tau T / R), on the flat disc
    (r0 = r: ``rhs_on`` with slope 1, whose products by 1.0 are exact)."""
    rhs_on(r, r, 1.0, y, code, params, p, out)


@functools.partial(compiled, inline="always")
def table_curvature(rho, breaks, coef):
    """The meridional curvature kappa_1 = z'' / (1 + z'^2)^(3/2) (units 1/R) at ``rho`` of a profile table whose
    spline z = g(s), s = rho^2, has ``breaks`` (shape (n,)) and ``coef`` (shape (4, n - 1), scipy's PPoly
    layout: ``pocket.core.profiles.Shape.pieces``), read at the table's extent past it (as
    ``Surface.curvature``): z' = 2 rho g'(s), z'' = 2 g'(s) + 4 s g''(s), the piece found as PPoly finds it
    (the one starting at or below s; the last past the end)."""
    s = min(rho * rho, breaks[-1])
    lo, hi = 0, breaks.size - 2  # bisection for the last piece starting at or below s (np.searchsorted would
    while lo < hi:  # pull numba's array typing into a process that only loads cached code)
        mid = (lo + hi + 1) // 2
        if breaks[mid] <= s:
            lo = mid
        else:
            hi = mid - 1
    i = lo
    d = s - breaks[i]
    g1 = (3.0 * coef[0, i] * d + 2.0 * coef[1, i]) * d + coef[2, i]
    g2 = 6.0 * coef[0, i] * d + 2.0 * coef[1, i]
    slope = 2.0 * np.sqrt(s) * g1
    return (2.0 * g1 + 4.0 * s * g2) / (1.0 + slope * slope) ** 1.5


@functools.partial(compiled, inline="always")
def derivatives(r, y, code, params, p, wrap, breaks, coef, sphere, out):
    """``rhs_on`` the reference surface (``reference``: the disc, or the sphere if ``sphere``) for the free sheet
    (``wrap`` = 0, ``breaks`` empty), or for the sheet lying on a sphere of
    curvature ``wrap`` = 1/R_s > 0 (units 1/R): there psi' = -lambda_1 / R_s replaces normal equilibrium
    (``pocket.shooting.surface``), the other four equations unchanged; or on a profile table (``breaks`` and
    ``coef`` its spline, ``table_curvature``): psi' = -lambda_1 kappa_1(rho) (``pocket.shooting.surface``)."""
    radius, slope = reference(r, sphere)
    rhs_on(r, radius, slope, y, code, params, p, out)
    if breaks.size > 0:
        out[2] = -y[3] * table_curvature(y[0], breaks, coef)
    elif wrap > 0.0:
        out[2] = -y[3] * wrap


def pole_state(l0: float, law, p: float, r0: float, sphere: bool = False) -> np.ndarray:
    """State y at r = r0 from the pole series (error O(r0^4) in the stretches, O(r0^3) in psi).

    ``l0`` is the pole stretch lambda_0, ``law`` a ``pocket.shooting.laws.Law``, ``p`` the pressure
    in units of tau T / R, ``sphere`` whether the reference surface is the unit sphere (a capsule: r0(S) = sin S,
    where the series' k^2 becomes k^2 - 1, the -1 from the -S^3/6 of sin S) rather than the flat disc.
    Returns y = [rho, eta, psi, lambda_1, v], shape (5,); eta is measured from the pole.
    """
    t0, _, a, b = tensions(l0, l0, law.code, law.params)
    k = l0 * p / (2.0 * t0) if p != 0.0 else 0.0  # p = 0: a flat contact zone, whose tension may vanish
    kk = k * k - (1.0 if sphere else 0.0)
    cb = -l0 * kk * (3.0 * a - b) / (16.0 * a)
    ca = 3.0 * cb + 0.5 * l0 * kk
    rho = (np.sin(r0) if sphere else r0) * (l0 + cb * r0 * r0)
    # eta' = -lambda_1 sin(psi) ~ -l0 k r, v' = pi rho^2 lambda_1 sin(psi) ~ pi l0^3 k r^3
    eta = -0.5 * l0 * k * r0 * r0
    v = 0.25 * np.pi * l0**3 * k * r0**4
    return np.array([rho, eta, k * r0, l0 + ca * r0 * r0, v])
