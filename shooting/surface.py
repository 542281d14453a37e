r"""Step 2 under a rigid frictionless curved indenter: the shooting problem of every convex surface of revolution.

The indenter's lower surface is z(rho) above its lowest point (``pocket.core.indenters``): a sphere of radius
R_s = K R (a fingertip), z = K - sqrt(K^2 - rho^2), a user's profile, flat on the axis, or any other convex
surface. The sphere is the surface of constant curvature kappa_1 = kappa_2 = 1/K; its closed forms are noted
where they hold.

Derivation
----------
Units and notation as in ``pocket.shooting.equations``: Lagrangian radius r (units R), deformed
meridian (rho, eta), meridian angle psi below the horizontal, tensions t = T / (tau T), pressure
p = P R / (tau T), ' = d/dr. Here eta is measured up from the sheet's pole, which is the surface's
lowest point, so the indenter's lowest point stands at h = -eta(1) above the clamp plane.

Contact zone (0 <= r <= a). The sheet lies on the surface eta = z(rho). Its meridian is the surface's: the
tangent (cos(psi), -sin(psi)) is the surface's (1, z'(rho)) / sqrt(1 + z'^2), so psi = -theta(rho) with
theta = arctan(z'(rho)) the surface's slope angle at the current rho (on a sphere, its polar angle phi).
Differentiating along r with rho' = lambda_1 cos(psi),

    psi' = -theta'(rho) rho' = -z'' / (1 + z'^2) lambda_1 cos(theta) = -lambda_1 kappa_1(rho),

kappa_1 = z'' / (1 + z'^2)^(3/2) the surface's meridional curvature (``Indenter.curvature``; 1/K on a sphere).
This replaces normal equilibrium; rho' = lambda_1 cos(psi), eta' = -lambda_1 sin(psi) (on the surface by
construction), lambda_2 = rho / r and tangential equilibrium (rho t1)' = t2 rho' (a frictionless surface
exerts no tangential force) hold unchanged (``equations.rhs`` with its psi' replaced). Pressure does not
enter. Normal equilibrium, t1 kappa_1 + t2 kappa_2 = p - p_c with the sheet's curvatures those of the surface
seen from the fluid, -kappa_1 and the hoop curvature -kappa_2 = -sin(theta) / rho, only yields the contact
pressure the surface exerts:

    p_c = p + t1 kappa_1(rho) + t2 sin(theta) / rho,   kappa_2 = sin(theta) / rho -> kappa_1(0) at the axis,

in Phat units Phat_c = Phat + (T_1 kappa_1 + T_2 kappa_2) / (E T), on a sphere p + (t1 + t2) / K:
>= p wherever the tensions are positive (a convex surface has kappa_1, kappa_2 >= 0). The volume
v' = pi rho^2 lambda_1 sin(psi) is negative there: the dimple the indenter presses in.

Pole series. With lambda_1 = l_c + A r^2, lambda_2 = l_c + B r^2, psi = -l_c kappa_1(0) r + O(r^3) the
expansions of ``equations.pole_state`` hold with its pole curvature k = l_0 p / (2 t_0) replaced by
k = -l_c kappa_1(0): they used normal equilibrium only through k, and rho' = lambda_1 cos(psi) and
tangential equilibrium give the same two relations for A and B. So the contact zone starts from
``pole_state(l_c, law, -2 t_0 kappa_1(0), r0)`` (``pole_radius`` = 1/kappa_1(0), K on a sphere): the
pressure -2 t_0 kappa_1(0) = p - p_c(0) is the net normal load at the pole, for which the free equations
curve the sheet as the surface does. Its error O(r0^3) does not see the curvature's variation (z is even in
rho, so kappa_1 = kappa_1(0) + O(rho^2)).

How the contact zone is integrated is the surface's (``pocket.shooting.surfaces``: scipy on the indenter's
curvature, a table's compiled spline, or the sphere's compiled constant curvature).

Contact edge (r = a). The sheet leaves the surface: rho, eta and psi are continuous (a smooth surface
exerts no line force, so the meridian has no kink), and so is T_1 (tangential equilibrium across the
edge); the meridional curvature jumps from -kappa_1 to (p - t2 sin(psi) / rho) / t1. The free part
a <= r <= 1 is integrated from the edge state with the fluid pressure, as under the plate.

Tolerance of the sphere's contact zone. Its end state enters the residuals divided by s_0: the free sheet's
tensions, and so its shape, follow the strain lambda_1 - 1 ~ s_0, not lambda_1, and the clamp residual
is (rho(1) - 1) / s_0. Integrated to rtol relative to lambda_1 ~ 1 (the free sheet's tolerance), a
shallow dome's contact zone (s_0 ~ 1e-3 at Phat_I ~ 2e-4) would hand the free sheet an edge stretch
whose strain is wrong by up to rtol / s_0 of itself, and not smoothly: the zone starts at the pole with
steps so small that their error estimates are round-off, so its step sequence, and that error with it,
jumps between neighbouring unknowns (measured: 2e-8 of noise in the residuals, about 1000 times the Newton
tolerance, at Phat_I = 2.3e-4, K = 2.85, where the continuation in the force stalled). So the sphere's
contact zone is integrated to rtol s_0 (``surfaces.contact_tolerance``, its absolute tolerances scaled alike): its
error then enters the residuals at the relative size rtol, as the free sheet's does; never tighter than
``pocket.core.inputs.TOLERANCE_FLOOR``, a few ulps, below which no integration resolves lambda_1,
and never looser than rtol (s_0 >= 1).

Closure. Unknowns x = (q, e, c): q = P / P_I, e = (l_c - 1) / s_0 (``pocket.shooting.contact``), and c the
contact radius relative to the plate's at the same force, a = c sqrt(Fhat / q) / l_c (under the plate
c = 1). Residuals, all of order one:

    (rho(1) - 1) / s_0                       the clamp, rho(1) = 1;
    V / V_I - (fluid law)                    V = -pi int_0^1 rho^2 eta' dr over contact and free parts;
    Fhat_cap / Fhat - 1                      the force,

with the force from the contact cap (the sheet on the surface) as a free body, which holds for any cap
shape: the fluid pushes it up with P pi rho_c^2, the free sheet pulls its edge with T_1 along the
meridian, whose upward component is T_1 sin(theta_c), theta_c = -psi(a), and the indenter pushes it down
with F:

    F = P pi rho_c^2 + 2 pi rho_c T_1 sin(theta_c),   Fhat = q rho_c^2 + 2 rho_c t1_c sin(theta_c) / p_I,

p_I = P_I R / (tau T). eta(1) then gives the indenter's height h = -eta(1). At small force c tends to
sqrt(p / (p + 2 t_0 kappa_1(0))) of the inflated pole (rho_c^2 pi (P + 2 T_0 kappa_1(0)) = F): the start.
The same force is the integral of the contact pressure's vertical component over the curved contact
area, F = int_0^a p_c cos(theta) 2 pi rho lambda_1 dr, and the virtual work (-dU + P dV) / dh along the
path (``tests/test_shooting_sphere.py`` and ``tests/test_shooting_profile.py`` check them). The contact area
is the curved area A_c = 2 pi int_0^rho_c rho sqrt(1 + z'^2) drho (2 pi R_s^2 (1 - cos(phi_c)) on a sphere).

Where the model ends is ``pocket.shooting.surfaceend``: the contact edge would pass the end of the surface (a
sphere's equator; a profile's last row or extent, or a slope turning vertical, theta_c -> pi/2), the
indenter's lowest point would reach the clamp plane, the free sheet would reach the clamp plane, or it would
touch the surface outside the contact zone. Past a profile's extent its curvature is read at the extent
inside a trial step only, so that the margin (extent - rho_c) crosses zero smoothly. Such a state solves with
no failed step, so the compression checks every solved state's edge (``past_its_end``): one at or past the
surface's end at a force past the range end is refused, naming the end (``compression.compression_curve``),
and no returned state has its contact edge past the extent by more than the shots' error at the end. Every
returned state has p_c >= 0 along the contact zone and its free sheet outside the indenter
(``pocket.shooting.surfacestate.check``); a state that breaks either is refused by name.
"""

from __future__ import annotations

import dataclasses
import functools
import math

import numpy as np

from pocket.core.states import CompressedState

from . import surfaceend, surfacestate
from .contact import Contact
from .equations import pole_state
from .integrator import OK, integrate
from .shots import PROFILE_STEP, PSI_MAX_EDGE, R_POLE
from .surfaces import Surface, surface_of
from .tensions import tensions

__all__ = ["SurfaceProblem", "words"]


def words(name: str) -> tuple[str, str]:
    """What the messages call two ends of the model under the indenter called ``name``: its lowest point
    reaching the clamp plane, and the free sheet touching it outside the contact zone."""
    return (f"the {name}'s lowest point, and the sheet's pole on it, would reach the clamp plane",
            f"the free sheet would touch the {name} outside the contact zone")


@dataclasses.dataclass(frozen=True)
class SurfaceProblem(Contact):
    """The compression of ``inflated`` by the curved ``indenter`` (module docstring); fields as ``Contact``."""

    #: what the messages call the indenter, and the names of the ends of the model under it
    NAME, END = "indenter", "the sheet would wrap past the end of the indenter's surface"
    POLE, TOUCH = words("indenter")

    @functools.cached_property
    def surface(self) -> Surface:
        """The indenter's surface, with its way of integration (``pocket.shooting.surfaces.surface_of``)."""
        return surface_of(self.indenter)

    @property
    def pole_radius(self) -> float:
        """The surface's radius of curvature on the axis, 1/kappa_1(0) (units R; K on a sphere)."""
        return self.surface.pole_radius

    def _pole(self, lc):
        """(t_0, contact start pressure -2 t_0 / K_0) at pole stretch ``lc`` (kernel units; K_0 = ``pole_radius``)."""
        t0 = tensions(lc, lc, self.law.code, self.law.params)[0]
        return t0, -2.0 * t0 / self.pole_radius

    def start(self) -> np.ndarray:
        """Unknowns (q, e, c) of the inflated state (Fhat -> 0), the guess for the first force."""
        lc = self.inflated.stretch_pole
        p = self.law.pressure_factor * self.inflated.pressure
        return np.array([1.0, 1.0, math.sqrt(p / (p - self._pole(lc)[1]))])

    def geometry(self, x, force):
        """(q, lambda_c, a, p) for unknowns x = (q, e, c) at ``force``, or None outside the domain."""
        q, e, c = x[0], x[1], x[2]
        lc = self.stretch(e)
        if not (q > 0.0 and lc > 0.0 and c > 0.0 and force > 0.0):
            return None
        a = c * math.sqrt(force / q) / lc
        if not a < 1.0:
            return None
        return q, lc, a, self.law.pressure_factor * self.inflated.pressure * q

    def _contact(self, lc, a, store):
        """(status, y(a), steps) of the contact zone from the pole to the edge r = a."""
        start = self._pole(lc)[1]
        if a <= 2.0 * R_POLE:  # the series alone: its error O(a^3) is below the integration's
            y = pole_state(lc, self.law, start, a)
            return OK, y, np.array([[a, *y]])
        return self.surface.contact(self, pole_state(lc, self.law, start, R_POLE), R_POLE, a, store)

    def _shot(self, geometry, store):
        """(status, y(1), (contact steps, free steps), y(a)) at ``geometry`` = (q, lambda_c, a, p)."""
        _q, lc, a, p = geometry
        status, edge, inner = self._contact(lc, a, store)
        shot = (status, edge, (inner, np.empty((0, 6))), edge)
        if status == OK:
            tol = self.tolerance
            status, _, y, outer = integrate(edge, a, self.law, p, rtol=tol.rtol, atol=tol.atol, store=store,
                                            max_step=PROFILE_STEP if store else np.inf, psi_max=PSI_MAX_EDGE)
            shot = (status, y, (inner, outer), edge)
        return shot

    def cap_force(self, q, a, edge) -> float:
        """Fhat of the contact cap as a free body (module docstring): pressure ratio ``q``, contact radius
        ``a`` and the state at the contact edge ``edge`` = [rho, eta, psi, lambda_1, v]."""
        rho = edge[0]
        t1 = tensions(edge[3], rho / a, self.law.code, self.law.params)[0]
        return q * rho * rho + 2.0 * rho * t1 * math.sin(-edge[2]) / (self.law.pressure_factor * self.inflated.pressure)

    def _closure(self, x, force, shot) -> tuple:
        """The force residual Fhat_cap / Fhat - 1 (module docstring)."""
        return (self.cap_force(x[0], self.geometry(x, force)[2], shot[3]) / force - 1.0,)

    @property
    def scales(self) -> dict[str, float]:
        """What each margin of ``margins`` is divided by to compare them: the end's by the surface's
        ``end_scale``, the clamp angle by pi, the lengths by the inflated dome's height."""
        return surfacestate.scales(self)

    def margins(self, force, x) -> dict[str, float]:
        """How far the solved state at ``force`` stands from each end of the model (positive inside it;
        ``pocket.shooting.surfacestate.margins``)."""
        return surfacestate.margins(self, force, x)

    def past_its_end(self, force, x, band) -> bool:
        """Whether the solved state x at ``force`` has its contact edge within ``band`` of the end of a surface
        whose shots go on solving past it (module docstring)."""
        return self.surface.open_end and self.surface.end_margin(self.shoot(x, force)[3]) <= band

    def check(self, profile, contact_pressure, height, force) -> None:
        """Refuse a state with a negative contact pressure or its free sheet inside the indenter
        (``pocket.shooting.surfacestate.check``)."""
        surfacestate.check(self, profile, contact_pressure, height, force)

    def compressed(self, force, x, fluid) -> tuple[CompressedState, float]:
        """The compressed state at ``force`` (as given, ``fluid`` too) for the solved unknowns x, checked, and its
        clamp angle psi(1) (``pocket.shooting.surfacestate.state``)."""
        return surfacestate.state(self, force, x, fluid)

    def end(self, seed):
        """The range end of this pocket under the indenter (``pocket.shooting.surfaceend``)."""
        return surfaceend.end_of_surface(self, seed)

    def on_branch(self, force):
        """Unknowns x at ``force`` near a fold, found on the end's branch (``pocket.shooting.surfaceend``)."""
        return surfaceend.on_branch(self, force)
