r"""The surfaces a curved indenter presents to its contact formulation (``pocket.shooting.surface``), and the one
place that chooses how each is integrated.

Every surface is read through the indenter's height, slope and curvature at rho, and its reach (the largest rho
it stands above). The contact zone's psi' = -lambda_1 kappa_1(rho) is integrated one of three ways:

- ``Surface``, any convex surface of revolution (a profile given as functions, or a new indenter): scipy's
  DOP853 (``solve_ivp``, the method and tolerances of the compiled integrator) with the indenter's curvature,
  a Python function (about 100 times slower than compiled code), stopping at its knots as a table's
  integration does (an event at each, none for functions). Past its reach the curvature is read at the
  reach, so that the margin (reach - rho_c) crosses zero smoothly (``surface``'s docstring);
- ``TableSurface``, a profile given as a table: the compiled integrator (``pocket.shooting.integrator``),
  evaluating the table's spline itself (``equations.table_curvature``). The spline's third derivative jumps at its rows,
  so the curvature's slope jumps there: an 8th-order step across such a knot is only 2nd-order accurate, its
  error unseen by the estimate, and the residuals turn noisy above the Newton tolerance; the integration
  stops at each row (a step shortened to end there) and restarts there;
- ``SphereSurface``, the surface of constant curvature 1/K: the compiled integrator with psi' = -lambda_1 / K,
  to the contact tolerance rtol s_0 (``contact_tolerance``), and its closed forms: the contact pressure
  p + (t1 + t2) / K, the cap's area 2 K^2 (1 - cos(phi_c)), the end at its equator.

``surface_of`` chooses; nothing else asks which indenter it has. The indenter's particular attributes are read
by ``_reach`` and ``_shape`` alone.
"""

from __future__ import annotations

import itertools
import math

import numpy as np

from pocket.core.indenters import Indenter, Profile, Sphere
from pocket.core.inputs import TOLERANCE_FLOOR
from pocket.core.profiles import Shape

from .equations import rhs
from .integrator import FOLD, OK, SLACK, STEPS, integrate
from .shots import PROFILE_STEP, Tolerance
from .tensions import tensions

__all__ = ["SphereSurface", "Surface", "TableSurface", "contact_tolerance", "surface_of"]


class Surface:
    """A convex surface of revolution, the ``indenter``'s, standing above rho <= ``reach`` (units R), integrated
    by scipy with the indenter's curvature (module docstring); ``knots``: radii where its third derivative
    jumps (units R), between which its contact area is summed."""

    end_scale = 1.0  # the end margin is a fraction already (``end_margin``)
    open_end = True  # the shots go on solving past the reach (the curvature is read at the reach there)

    def __init__(self, indenter: Indenter, reach: float, knots: tuple[float, ...] = ()):
        self.indenter, self.reach, self.knots = indenter, reach, knots

    def curvature(self, rho):
        """kappa_1 = z'' / (1 + z'^2)^(3/2) at the radii ``rho`` (units R, any shape; units 1/R), read at the reach
        past it."""
        return self.indenter.curvature(np.minimum(np.asarray(rho, dtype=float), self.reach))

    @property
    def pole_radius(self) -> float:
        """1 / kappa_1(0) (units R; inf for a surface flat to second order on the axis)."""
        kappa = float(self.curvature(0.0))
        return math.inf if kappa == 0.0 else 1.0 / kappa

    def contact(self, problem, y0, r0, a, store):
        """(status, y(a), steps) of the contact zone of ``problem`` from the state ``y0`` at r = ``r0`` to the
        edge r = ``a`` (steps: shape (m, 6), columns [r, rho, eta, psi, lambda_1, v], empty unless ``store``)."""
        from scipy.integrate import solve_ivp  # here: scipy stays off the plate's import path

        code, params = problem.law.code, problem.law.params

        def f(r, y):
            out = np.empty(5)
            rhs(r, y, code, params, 0.0, out)
            out[2] = -y[3] * float(self.curvature(y[0]))
            return out

        tol = problem.tolerance
        r, y, pieces, knots = r0, y0, [], [k for k in self.knots if k > y0[0]]
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

    def pressure(self, rho, t1, t2, base):
        """The contact pressure Phat_c = ``base`` + t1 kappa_1 + t2 kappa_2 at the radii ``rho`` (units R) where
        the tensions are ``t1``, ``t2``; kappa_2 = sin(theta) / rho with the surface's theta there, kappa_1(0)
        on the axis."""
        rho = np.minimum(rho, self.reach)
        k1 = self.curvature(rho)
        slope = self.indenter.slope(rho)
        with np.errstate(invalid="ignore", divide="ignore"):
            k2 = np.where(rho > 0.0, slope / np.sqrt(1.0 + np.square(slope)) / rho, k1)
        return base + t1 * k1 + t2 * k2

    def area(self, edge) -> float:
        """The curved contact area over pi R^2, 2 int_0^rho_c rho sqrt(1 + z'^2) drho, for the contact edge's
        state ``edge`` = [rho, eta, psi, lambda_1, v], summed between the ``knots``, where the integrand is
        smooth (across a table's row its second derivative jumps, and one adaptive quadrature over many rows
        stalls short of its tolerance). At the range end rho_c is the reach to the shots' error, on either
        side: the integral stops at the reach, where the surface ends."""
        slope = self.indenter.slope
        top = min(float(edge[0]), self.reach)
        bounds = [0.0, *(k for k in self.knots if 0.0 < k < top), top]
        from scipy.integrate import quad  # here: scipy stays off the plate's import path

        return 2.0 * sum(quad(lambda r: r * math.sqrt(1.0 + float(slope(r)) ** 2), lo, hi, epsabs=0.0,
                              epsrel=1e-12, limit=200)[0] for lo, hi in itertools.pairwise(bounds))

    def end_margin(self, edge) -> float:
        """How far the contact edge ``edge`` stands from the surface's end, as a fraction: the smaller of
        (reach - rho_c) / reach and (pi/2 - theta_c) / (pi/2)."""
        return min((self.reach - edge[0]) / self.reach, (0.5 * math.pi + edge[2]) / (0.5 * math.pi))


class TableSurface(Surface):
    """A profile given as a table, ``shape``: integrated by the compiled integrator on its spline, stopping at
    each row (module docstring)."""

    def __init__(self, indenter: Indenter, shape: Shape):
        super().__init__(indenter, shape.extent, shape.knots)
        self.pieces = shape.pieces

    def contact(self, problem, y0, r0, a, store):
        tol = problem.tolerance
        status, _, y, steps = integrate(y0, r0, problem.law, 0.0, rtol=tol.rtol, atol=tol.atol, store=store,
                                        r_end=a, table=self.pieces, max_step=PROFILE_STEP if store else np.inf)
        return status, y, steps


class SphereSurface(Surface):
    """The sphere of radius K = ``reach``: constant curvature 1/K, integrated by the compiled integrator to the
    contact tolerance, with its closed forms (module docstring)."""

    end_scale = 0.5 * math.pi  # the end margin is an angle (``end_margin``)
    open_end = False  # the contact zone's shot stops at the equator (``integrator.FOLD``)

    @property
    def pole_radius(self) -> float:
        """K."""
        return self.reach

    def contact(self, problem, y0, r0, a, store):
        tol = contact_tolerance(problem)
        status, _, y, steps = integrate(y0, r0, problem.law, 0.0, rtol=tol.rtol, atol=tol.atol, store=store,
                                        r_end=a, wrap=1.0 / self.reach, max_step=PROFILE_STEP if store else np.inf)
        return status, y, steps

    def pressure(self, rho, t1, t2, base):
        """Phat_c = ``base`` + (t1 + t2) / K (kappa_1 = kappa_2 = 1/K)."""
        return base + (t1 + t2) / self.reach

    def area(self, edge) -> float:
        """The curved area of the cap the sheet wraps, over pi R^2: 2 K^2 (1 - cos(phi_c)), phi_c = -psi(a)."""
        return 4.0 * (self.reach * math.sin(0.5 * edge[2])) ** 2

    def end_margin(self, edge) -> float:
        """How far the contact edge stands from the sphere's equator: pi/2 - phi_c (rad)."""
        return 0.5 * math.pi + edge[2]


def contact_tolerance(problem) -> Tolerance:
    """The sphere's contact zone's integration tolerances: ``problem.tolerance`` scaled by the pole strain s_0, to
    rtol s_0 within [``TOLERANCE_FLOOR``, rtol] (``pocket.shooting.surface``, "Tolerance of the sphere's contact
    zone")."""
    tol = problem.tolerance
    rtol = min(tol.rtol, max(tol.rtol * problem.strain, TOLERANCE_FLOOR))
    return Tolerance(rtol, tol.atol * (rtol / tol.rtol))


def surface_of(indenter: Indenter) -> Surface:
    """The surface of the curved ``indenter`` with its way of integration (module docstring): the sphere's closed
    forms, a table's compiled spline, or scipy on the indenter's curvature for any other."""
    if isinstance(indenter, Sphere):
        return SphereSurface(indenter, indenter.reach)
    if isinstance(indenter, Profile) and indenter.shape.pieces is not None:
        return TableSurface(indenter, indenter.shape)
    return Surface(indenter, indenter.reach, indenter.knots)
