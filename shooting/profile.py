r"""Step 2 under a user's convex profile z(rho), flat on the axis: the shooting problem.

Derivation
----------
Units, notation and unknowns as under the sphere (``pocket.shooting.sphere``), of which this is the
generalisation: the sphere is the profile of constant curvature kappa_1 = kappa_2 = 1/K.

Contact zone (0 <= r <= a). The sheet lies on the surface eta = z(rho) (eta measured up from the
pole, the surface's lowest point). Its meridian is the surface's: the tangent (cos(psi), -sin(psi))
is the surface's (1, z'(rho)) / sqrt(1 + z'^2), so psi = -theta(rho) with theta = arctan(z'(rho))
the surface's slope angle at the current rho. Differentiating along r with rho' = lambda_1 cos(psi),

    psi' = -theta'(rho) rho' = -z'' / (1 + z'^2) lambda_1 cos(theta) = -lambda_1 kappa_1(rho),

kappa_1 = z'' / (1 + z'^2)^(3/2) the surface's meridional curvature (``Indenter.curvature``). This
replaces normal equilibrium; rho' = lambda_1 cos(psi), eta' = -lambda_1 sin(psi) (on the surface by
construction), lambda_2 = rho / r and tangential equilibrium (rho t1)' = t2 rho' (a frictionless
surface exerts no tangential force) hold unchanged (``equations.rhs`` with its psi' replaced).
Normal equilibrium, t1 kappa_1 + t2 kappa_2 = p - p_c with the sheet's curvatures those of the surface
seen from the fluid, -kappa_1 and the hoop curvature -kappa_2 = -sin(theta) / rho, only yields the
contact pressure:

    p_c = p + t1 kappa_1(rho) + t2 sin(theta) / rho,   kappa_2 = sin(theta) / rho -> kappa_1(0) at the axis,

>= p wherever the tensions are positive (a convex surface has kappa_1, kappa_2 >= 0). On a sphere
kappa_1 = kappa_2 = 1/K and this is the sphere's p + (t1 + t2) / K.

Pole series. psi = -lambda_c kappa_1(0) r + O(r^3): the sphere's series with 1/K replaced by the pole
curvature kappa_1(0) (``pole_radius`` = 1/kappa_1(0)); the contact zone starts from
``pole_state(l_c, law, -2 t_0 kappa_1(0), r0)``, whose error O(r0^3) does not see the curvature's
variation (z is even in rho, so kappa_1 = kappa_1(0) + O(rho^2)).

Contact edge and closure: as under the sphere. rho, eta, psi and T_1 are continuous; the free sheet
is integrated from the edge state with the fluid pressure; the force is the contact cap's balance,
F = P pi rho_c^2 + 2 pi rho_c T_1 sin(theta_c), theta_c = -psi(a), which holds for any cap shape (the
sphere's pushes down, the fluid up, the free sheet pulls the edge along the meridian). The same force
is the integral of the contact pressure's vertical component, F = int p_c cos(theta) dA
(``tests/test_shooting_profile.py`` checks both). The contact area is the curved area
A_c = 2 pi int_0^rho_c rho sqrt(1 + z'^2) drho.

The contact zone of a table is integrated by the compiled integrator (``pocket.shooting.integrator``), which
evaluates the table's spline itself (``equations.table_curvature``); a profile given as functions by
scipy's DOP853 (``solve_ivp``, the same method and tolerances), since its curvature is the user's Python
function (about 100 times slower). A table's spline has a third derivative that jumps at its rows, so the
curvature's slope jumps there: an 8th-order step across such a knot is only 2nd-order accurate, its error
unseen by the estimate, and the residuals turn noisy above the Newton tolerance. Both integrations
therefore stop at each row (rho = rho_k: a step shortened to end there, or an event) and restart there.

Where the model ends (``pocket.shooting.sphereend``, the same search): the contact edge would pass the
end of the profile (its last row or its ``extent``, or a slope turning vertical, theta_c -> pi/2), the
indenter's lowest point would reach the clamp plane, the free sheet would reach the clamp plane, or it
would touch the profile outside the contact zone. Past the profile's extent its curvature is read at
the extent inside a trial step only, so that the margin (extent - rho_c) crosses zero smoothly. Such a
state solves with no failed step, so the compression checks every solved state's edge: one at or past the
profile's end at a force past the range end is refused, naming the end (``compression.compression_curve``),
and no returned state has its contact edge past the extent by more than the shots' error at the end.
"""

from __future__ import annotations

import dataclasses
import itertools
import math

import numpy as np

from .equations import pole_state, rhs
from .integrator import FOLD, OK, SLACK, STEPS, integrate
from .shots import PROFILE_STEP, R_POLE
from .sphere import SphereProblem
from .tensions import tensions

__all__ = ["PROFILE_END", "PROFILE_POLE", "PROFILE_TOUCH", "ProfileProblem"]

#: the ends of the model particular to a profile
PROFILE_END = "the sheet would wrap past the end of the profile (its last radius, or where it turns vertical)"
PROFILE_POLE = "the profile's lowest point, and the sheet's pole on it, would reach the clamp plane"
PROFILE_TOUCH = "the free sheet would touch the profile outside the contact zone"


@dataclasses.dataclass(frozen=True)
class ProfileProblem(SphereProblem):
    """The compression of ``inflated`` by the profile ``indenter`` (module docstring); fields as ``Problem``."""

    NAME, END, POLE, TOUCH = "profile", PROFILE_END, PROFILE_POLE, PROFILE_TOUCH

    @property
    def shape(self):
        """The profile, a ``pocket.core.profiles.Shape``."""
        return dict(self.indenter.params)["shape"]

    @property
    def radius(self) -> float:
        raise AttributeError("a profile has no single radius")

    @property
    def reach(self) -> float:
        """The largest rho (units R) the profile stands above: its extent."""
        return self.shape.extent

    @property
    def pole_radius(self) -> float:
        """1 / kappa_1(0) (units R; inf for a profile flat to second order on the axis)."""
        kappa = float(self.curvature(0.0))
        return math.inf if kappa == 0.0 else 1.0 / kappa

    @property
    def scales(self) -> dict[str, float]:
        """As the sphere's; the profile's end margin is already a fraction (``end_margin``)."""
        return {**super().scales, self.END: 1.0}

    def curvature(self, rho):
        """kappa_1 = z'' / (1 + z'^2)^(3/2) at the radii ``rho`` (units R, any shape; units 1/R), read at
        the extent past it (module docstring)."""
        rho = np.minimum(np.asarray(rho, dtype=float), self.shape.extent)
        shape = self.shape
        return shape.second(rho) / (1.0 + np.square(shape.slope(rho))) ** 1.5

    def _contact(self, lc, a, store):
        """(status, y(a), steps) of the contact zone from the pole to the edge r = a (steps: shape (m, 6),
        columns [r, rho, eta, psi, lambda_1, v], empty unless ``store``)."""
        start = self._pole(lc)[1]
        if a <= 2.0 * R_POLE:  # the series alone: its error O(a^3) is below the integration's
            y = pole_state(lc, self.law, start, a)
            return OK, y, np.array([[a, *y]])
        tol = self.tolerance
        if self.shape.pieces is not None:  # a table: the compiled integrator, stopping at its rows
            status, _, y, steps = integrate(pole_state(lc, self.law, start, R_POLE), R_POLE, self.law, 0.0,
                                            rtol=tol.rtol, atol=tol.atol, store=store, r_end=a,
                                            table=self.shape.pieces, max_step=PROFILE_STEP if store else np.inf)
            return status, y, steps
        code, params = self.law.code, self.law.params

        def f(r, y):
            out = np.empty(5)
            rhs(r, y, code, params, 0.0, out)
            out[2] = -y[3] * float(self.curvature(y[0]))
            return out

        r, y = R_POLE, pole_state(lc, self.law, start, R_POLE)
        pieces, knots = [], [k for k in self.shape.knots if k > y[0]]
        from scipy.integrate import solve_ivp  # here: scipy stays off the plate's import path

        while True:
            event = None
            if knots:
                def event(_, v, k=knots[0]):
                    return v[0] - k
                event.terminal, event.direction = True, 1.0
            sol = solve_ivp(f, (r, a), y, method="DOP853", rtol=tol.rtol, atol=tol.atol, events=event,
                            max_step=PROFILE_STEP if store else np.inf)
            pieces.append(np.column_stack([sol.t, sol.y.T])[(1 if pieces else 0):])
            if sol.status != 1:  # a, or a failure
                break
            r, y = float(sol.t_events[0][0]), sol.y_events[0][0]
            pieces[-1] = np.vstack([pieces[-1], [r, *y]])
            knots.pop(0)
        y = sol.y[:, -1]
        steps = np.concatenate(pieces) if store else np.empty((0, 6))
        if not (sol.success and np.all(np.isfinite(y))):
            return STEPS, y, steps
        if any(np.min(piece[:, 3]) <= -0.5 * math.pi for piece in pieces):
            return FOLD, y, steps
        t1 = tensions(y[3], y[0] / a, code, params)[0]
        return (OK if t1 > 0.0 else SLACK), y, steps

    def contact_pressure(self, profile, q) -> np.ndarray:
        """Phat_c = Phat + t1 kappa_1 + t2 kappa_2 (module docstring) at each point of ``profile``, at pressure
        ratio ``q``; kappa_2 = sin(theta) / rho with the surface's theta at the point's rho (the sheet lies on it),
        kappa_1(0) on the axis."""
        rho = np.minimum(profile.rho, self.shape.extent)
        k1 = self.curvature(rho)
        slope = self.shape.slope(rho)
        with np.errstate(invalid="ignore", divide="ignore"):
            k2 = np.where(rho > 0.0, slope / np.sqrt(1.0 + np.square(slope)) / rho, k1)
        return self.inflated.pressure * q + profile.tension_1 * k1 + profile.tension_2 * k2

    def contact_area(self, edge) -> float:
        """The curved contact area over pi R^2, 2 int_0^rho_c rho sqrt(1 + z'^2) drho, for the contact edge's
        state ``edge`` = [rho, eta, psi, lambda_1, v], summed between the table's rows (``Shape.knots``), where
        the integrand is smooth (across a row its second derivative jumps, and one adaptive quadrature over many
        rows stalls short of its tolerance). At the range end rho_c is the extent to the shots' error, on either
        side: the integral stops at the extent, where the profile ends."""
        slope = self.shape.slope
        top = min(float(edge[0]), self.shape.extent)
        bounds = [0.0, *(k for k in self.shape.knots if 0.0 < k < top), top]
        from scipy.integrate import quad  # here: scipy stays off the plate's import path

        return 2.0 * sum(quad(lambda r: r * math.sqrt(1.0 + float(slope(r)) ** 2), lo, hi, epsabs=0.0,
                              epsrel=1e-12, limit=200)[0] for lo, hi in itertools.pairwise(bounds))

    def end_margin(self, edge) -> float:
        """How far the contact edge ``edge`` stands from the profile's end, as a fraction: the smaller of
        (extent - rho_c) / extent and (pi/2 - theta_c) / (pi/2)."""
        extent = self.shape.extent
        return min((extent - edge[0]) / extent, (0.5 * math.pi + edge[2]) / (0.5 * math.pi))
