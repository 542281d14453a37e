r"""Step 2 under a rigid frictionless sphere of radius R_s = K R (a fingertip): the shooting problem.

Derivation
----------
Units and notation as in ``pocket.shooting.equations``: Lagrangian radius r (units R), deformed
meridian (rho, eta), meridian angle psi below the horizontal, tensions t = T / (tau T), pressure
p = P R / (tau T), ' = d/dr. Here eta is measured up from the sheet's pole, which is the sphere's
lowest point, so the indenter's lowest point stands at h = -eta(1) above the clamp plane.

Contact zone (0 <= r <= a). The sheet lies on the sphere's lower cap: the point r sits at the
sphere's polar angle phi(r) (from the downward vertical), rho = K sin(phi), eta = K (1 - cos(phi)),
and its meridian is the sphere's, psi = -phi: going outward the sheet rises with the sphere, both
principal curvatures -1/K against the free dome's positive ones. Then rho' = K cos(phi) phi' must
equal lambda_1 cos(psi), so

    psi' = -phi' = -lambda_1 / K,

which replaces normal equilibrium; the other equations of the free sheet hold unchanged:
rho' = lambda_1 cos(psi), eta' = -lambda_1 sin(psi) (both on the sphere by construction),
lambda_2 = rho / r, and tangential equilibrium (rho t1)' = t2 rho', for a frictionless sphere
exerts no tangential force: it is the same lambda_1 equation (``equations.derivatives`` with
wrap = 1/K). Pressure does not enter. Normal equilibrium, t1 kappa_1 + t2 kappa_2 = p - p_c with
kappa_1 = kappa_2 = -1/K, only yields the contact pressure the sphere exerts:

    p_c = p + (t1 + t2) / K,    in Phat units  Phat_c = Phat + (T_1 + T_2) / (E T K),

larger than the fluid pressure: p_c >= 0 holds wherever the tensions are positive. The volume
v' = pi rho^2 lambda_1 sin(psi) is negative there: the dimple the sphere presses in.

Pole series. With lambda_1 = l_c + A r^2, lambda_2 = l_c + B r^2, psi = -(l_c / K) r + O(r^3) the
expansions of ``equations.pole_state`` hold with its pole curvature k = l_0 p / (2 t_0) replaced by
k = -l_c / K: they used normal equilibrium only through k, and rho' = lambda_1 cos(psi) and tangential
equilibrium give the same two relations for A and B. So the contact zone starts from
``pole_state(l_c, law, -2 t_0 / K, r0)``: the pressure -2 t_0 / K = p - p_c(0) is the net normal load at
the pole, for which the free equations curve the sheet as the sphere does.

Contact edge (r = a). The sheet leaves the sphere: rho, eta and psi are continuous (a smooth sphere
exerts no line force, so the meridian has no kink), and so is T_1 (tangential equilibrium across the
edge); the meridional curvature jumps from -1/K to (p - t2 sin(psi) / rho) / t1. The free part
a <= r <= 1 is integrated from the edge state with the fluid pressure, as under the plate.

Tolerance of the contact zone. Its end state enters the residuals divided by s_0: the free sheet's
tensions, and so its shape, follow the strain lambda_1 - 1 ~ s_0, not lambda_1, and the clamp residual
is (rho(1) - 1) / s_0. Integrated to rtol relative to lambda_1 ~ 1 (the free sheet's tolerance), a
shallow dome's contact zone (s_0 ~ 1e-3 at Phat_I ~ 2e-4) would hand the free sheet an edge stretch
whose strain is wrong by up to rtol / s_0 of itself, and not smoothly: the zone starts at the pole with
steps so small that their error estimates are round-off, so its step sequence, and that error with it,
jumps between neighbouring unknowns (measured: 2e-8 of noise in the residuals, about 1000 times the Newton tolerance,
at Phat_I = 2.3e-4, K = 2.85, where the continuation in the force stalled). So the contact zone is
integrated to rtol s_0 (and its absolute tolerances scaled alike): its error then enters the
residuals at the relative size rtol, as the free sheet's does; never tighter than
``pocket.core.inputs.TOLERANCE_FLOOR``, a few ulps, below which no integration resolves lambda_1,
and never looser than rtol (s_0 >= 1).

Closure. Unknowns x = (q, e, c): q = P / P_I, e = (l_c - 1) / s_0 (the pole stretch relative to the
inflated pole strain s_0, as under the plate), and c the contact radius relative to the plate's at
the same force, a = c sqrt(Fhat / q) / l_c (under the plate c = 1). Residuals, all of order one:

    (rho(1) - 1) / s_0                       the clamp, rho(1) = 1;
    V / V_I - (fluid law)                    V = -pi int_0^1 rho^2 eta' dr over contact and free parts;
    Fhat_cap / Fhat - 1                      the force,

with the force from the contact cap (the sheet on the sphere) as a free body: the fluid pushes it up
with P pi rho_c^2, the free sheet pulls its edge with T_1 along the meridian, whose upward component
is T_1 sin(phi_c), and the sphere pushes it down with F:

    F = P pi rho_c^2 + 2 pi rho_c T_1 sin(phi_c),   Fhat = q rho_c^2 + 2 rho_c t1_c sin(phi_c) / p_I,

p_I = P_I R / (tau T). eta(1) then gives the indenter's height h = -eta(1). At small force c tends to
sqrt(p / (p + 2 t_0 / K)) of the inflated pole (rho_c^2 pi (P + 2 T_0 / R_s) = F): the start.
The same force is the integral of the contact pressure's vertical component over the curved contact
area, F = int_0^a p_c cos(phi) 2 pi rho lambda_1 dr, and the virtual work (-dU + P dV) / dh along the
path (``tests/test_shooting_sphere.py`` checks both).

Where the model ends is ``pocket.shooting.sphereend``. Every returned state has p_c >= 0 along the
contact zone and its free sheet outside the sphere (``check``); a state that breaks either is refused
by name.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from pocket.core.errors import CLAMP_PLANE, OutOfRangeError
from pocket.core.inputs import TOLERANCE_FLOOR
from pocket.core.states import CompressedState

from .equations import pole_state
from .integrator import OK, integrate
from .problem import Problem
from .shots import PROFILE_STEP, PSI_MAX_EDGE, R_POLE, Tolerance, profile_from_steps, tension_minima
from .tensions import tensions

__all__ = ["EQUATOR", "POLE", "TOUCH", "SphereProblem"]

#: the ends of the model particular to a sphere (``pocket.shooting.sphereend``)
EQUATOR = "the sheet would wrap past the sphere's equator"
POLE = "the sphere's lowest point, and the sheet's pole on it, would reach the clamp plane"
TOUCH = "the free sheet would touch the sphere outside the contact zone"


@dataclasses.dataclass(frozen=True)
class SphereProblem(Problem):
    """The compression of ``inflated`` by the sphere ``indenter`` (module docstring); fields as ``Problem``."""

    #: what the messages call the indenter, and the names of the ends of the model under it
    NAME, END, POLE, TOUCH = "sphere", EQUATOR, POLE, TOUCH

    @property
    def radius(self) -> float:
        """K = R_s / R."""
        return self.indenter.number("radius")

    @property
    def reach(self) -> float:
        """The largest rho (units R) the indenter's surface stands above: K."""
        return self.radius

    @property
    def pole_radius(self) -> float:
        """The surface's radius of curvature on the axis (units R): K."""
        return self.radius

    @property
    def scales(self) -> dict[str, float]:
        """What each margin of ``margins`` is divided by to compare them: the angles by pi/2 and pi,
        the lengths by the inflated dome's height."""
        height = self.inflated.height
        return {self.END: 0.5 * math.pi, CLAMP_PLANE: math.pi, self.POLE: height, self.TOUCH: height}

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

    @property
    def contact_tolerance(self) -> Tolerance:
        """The contact zone's integration tolerances: ``tolerance`` scaled by the pole strain s_0, to rtol s_0
        within [``TOLERANCE_FLOOR``, rtol] (module docstring)."""
        tol = self.tolerance
        rtol = min(tol.rtol, max(tol.rtol * self.strain, TOLERANCE_FLOOR))
        return Tolerance(rtol, tol.atol * (rtol / tol.rtol))

    def _contact(self, lc, a, store):
        """(status, y(a), steps) of the contact zone from the pole to the edge r = a."""
        start = self._pole(lc)[1]
        if a <= 2.0 * R_POLE:  # the series alone: its error O(a^3) is below the integration's
            y = pole_state(lc, self.law, start, a)
            return OK, y, np.array([[a, *y]])
        tol = self.contact_tolerance
        status, _, y, steps = integrate(pole_state(lc, self.law, start, R_POLE), R_POLE, self.law, 0.0,
                                        rtol=tol.rtol, atol=tol.atol, store=store, r_end=a, wrap=1.0 / self.radius,
                                        max_step=PROFILE_STEP if store else np.inf)
        return status, y, steps

    def shoot(self, x, force, store=0):
        """(status, y(1), (contact steps, free steps), y(a)) for unknowns x at ``force``; None outside
        the domain. The last shot without ``store`` is remembered (``Problem.shoot``)."""
        g = self.geometry(x, force)
        if g is None:
            return None
        key = (*map(float, x), float(force))
        if not store and self._last.get("key") == key:
            return self._last["shot"]
        _q, lc, a, p = g
        status, edge, inner = self._contact(lc, a, store)
        shot = (status, edge, (inner, np.empty((0, 6))), edge)
        if status == OK:
            tol = self.tolerance
            status, _, y, outer = integrate(edge, a, self.law, p, rtol=tol.rtol, atol=tol.atol, store=store,
                                            max_step=PROFILE_STEP if store else np.inf, psi_max=PSI_MAX_EDGE)
            shot = (status, y, (inner, outer), edge)
        if not store:
            self._last.update(key=key, shot=shot)
        return shot

    def cap_force(self, q, a, edge) -> float:
        """Fhat of the contact cap as a free body (module docstring): pressure ratio ``q``, contact radius
        ``a`` and the state at the contact edge ``edge`` = [rho, eta, psi, lambda_1, v]."""
        rho = edge[0]
        t1 = tensions(edge[3], rho / a, self.law.code, self.law.params)[0]
        return q * rho * rho + 2.0 * rho * t1 * math.sin(-edge[2]) / (self.law.pressure_factor * self.inflated.pressure)

    def residual(self, x, force, angle=None):
        """The residuals at ``force`` (shape (3,)), with psi(1) - ``angle`` appended if given; None
        where a shot does not reach its end or x is outside the domain."""
        shot = self.shoot(x, force)
        if shot is None or shot[0] != OK:
            if shot is not None:
                self._last["failure"] = (shot[0], float(x[0]), self.stretch(x[1]), float(force))
            return None
        y, edge = shot[1], shot[3]
        pressure = self.inflated.pressure
        cap = self.cap_force(x[0], self.geometry(x, force)[2], edge)
        out = [(y[0] - 1.0) / self.strain, y[4] / self.inflated.volume - self.fluid.volume_ratio(pressure * x[0],
                                                                                                  pressure),
               cap / force - 1.0]
        return np.array(out if angle is None else [*out, y[2] - angle])

    def solved(self, force, x):
        """The solved state's pieces at ``force``: (profile, contact pressure at its points (NaN off
        contact), free steps, y(1), y(a)); a ConvergenceError if its final shots do not reach the clamp."""
        from .compression import final_shots  # the plate's reading of a final shot, shared

        q, lc, a, _p = self.geometry(x, force)
        status, y, _, edge = self.shoot(x, force)
        stored = self.shoot(x, force, store=20000)
        final_shots(force, status, stored[0])
        inner, outer = stored[2]
        profile = profile_from_steps(np.concatenate([inner, outer[1:]]), self.law, lc)
        on = profile.r <= a
        pc = np.where(on, self.contact_pressure(profile, q), np.nan)
        return dataclasses.replace(profile, contact=on), pc, outer[1:], y, edge

    def contact_pressure(self, profile, q) -> np.ndarray:
        """Phat_c = Phat + (T_1 + T_2) / (E T K) at each point of ``profile`` (shape of its arrays; only the
        contact zone's values mean something) at pressure ratio ``q``."""
        return self.inflated.pressure * q + (profile.tension_1 + profile.tension_2) / self.radius

    def contact_area(self, edge) -> float:
        """The curved area of the cap the sheet wraps, over pi R^2: 2 K^2 (1 - cos(phi_c)), for the contact
        edge's state ``edge`` = [rho, eta, psi, lambda_1, v] (phi_c = -psi)."""
        return 4.0 * (self.radius * math.sin(0.5 * edge[2])) ** 2

    def end_margin(self, edge) -> float:
        """How far the contact edge ``edge`` (its state) stands from the sphere's equator: pi/2 - phi_c (rad)."""
        return 0.5 * math.pi + edge[2]

    def margins(self, force, x) -> dict[str, float]:
        """How far the solved state at ``force`` stands from each end of the model (positive inside it):
        {EQUATOR: pi/2 - phi_c (rad), CLAMP_PLANE: pi - psi(1) (rad), POLE: the height h (units R),
        TOUCH: the free sheet's smallest gap below the sphere where it is negative beyond ``gap_allowed``,
        else inf (units R; ``pocket.shooting.sphereend``)}."""
        profile, _, _, y, edge = self.solved(force, x)
        gap = self.gap(profile, -y[1])
        inside = float(np.min(gap)) if gap.size else math.inf  # zero at the edge by tangency: only < 0 counts
        return {self.END: self.end_margin(edge), CLAMP_PLANE: math.pi - y[2], self.POLE: -y[1],
                self.TOUCH: inside if inside < -self.gap_allowed(-y[1]) else math.inf}

    def compressed(self, force, x, fluid) -> tuple[CompressedState, float]:
        """The compressed state at ``force`` (as given, ``fluid`` too) for the solved unknowns x, checked
        (``check``), and its clamp angle psi(1)."""
        q, lc, a, p = self.geometry(x, force)
        profile, pc, outer, y, edge = self.solved(force, x)
        height = -y[1]
        self.check(profile, pc, height, force)
        low = tension_minima(profile, outer, self.law, p, self.tolerance)
        inflated = self.inflated
        pressure = inflated.pressure * q
        t0 = tensions(lc, lc, self.law.code, self.law.params)[0] * self.law.tension_scale
        state = CompressedState(
            pressure_initial=inflated.pressure, force=force, pressure=pressure,
            pressure_ratio=q, contact_area=self.contact_area(edge),
            contact_radius=a, stretch_contact=lc, height=height, height_ratio=height / inflated.height,
            volume=y[4], profile=profile, inflated=inflated, solver="shooting", material=inflated.material,
            fluid=fluid, tension_1_min=low[0], tension_2_min=low[1], indenter=self.indenter,
            contact_radius_deformed=float(edge[0]), contact_pressure_pole=pressure + 2.0 * t0 / self.pole_radius,
            contact_pressure_edge=float(pc[profile.contact][-1]), contact_pressure=pc,
        )
        return state, float(y[2])

    def gap(self, profile, height) -> np.ndarray:
        """The free sheet's distance below the sphere (units R; negative where it would be inside it),
        at each profile point off the contact zone with rho < K (elsewhere the sphere is not above it).
        ``height``: the sphere's lowest point above the clamp plane (the profile's eta = 0)."""
        free = ~profile.contact & (profile.rho < self.reach)
        surface = height + self.indenter.height(profile.rho[free])
        return surface - profile.eta[free]

    def gap_allowed(self, height) -> float:
        """How far (units R) the free sheet may seem inside the indenter at ``height`` before it is: the shots'
        resolution of the gap, 1e3 rtol of the larger of h and H0."""
        return 1e3 * self.rtol * max(height, self.inflated.height)

    def check(self, profile, contact_pressure, height, force) -> None:
        """Refuse, by name, a state (its ``profile``, the ``contact_pressure`` at its points, ``height``)
        with a negative contact pressure or its free sheet inside the sphere (OutOfRangeError): neither
        is a state of this model."""
        pc = contact_pressure[profile.contact]
        if np.any(pc < 0.0):
            i = int(np.argmin(pc))
            raise OutOfRangeError(f"force = {force!r} ({self.label}): the contact pressure would be negative "
                                  f"({pc[i]:.6g}) at r = {profile.r[profile.contact][i]:.6g}: the sheet would pull "
                                  f"on the {self.NAME}")
        gap = self.gap(profile, height)
        if gap.size and np.min(gap) < -self.gap_allowed(height):
            raise OutOfRangeError(f"force = {force!r} ({self.label}): {self.TOUCH} (the free sheet would lie "
                                  f"{-np.min(gap):.3g} R inside it)")

    def end(self, seed):
        """The range end of this pocket under the sphere (``pocket.shooting.sphereend``)."""
        from .sphereend import end_of_sphere

        return end_of_sphere(self, seed)

    def on_branch(self, force):
        """Unknowns x at ``force`` near a fold, found on the end's branch (``pocket.shooting.sphereend``)."""
        from .sphereend import on_branch

        return on_branch(self, force)
