"""Step 2 of one inflated pocket as a shooting problem: unknowns, shots and residuals.

The indenter is the flat plate here (``pocket.core.indenters``; ``CONTACTS`` maps each
indenter kind this solver poses to its problem, and ``contact_of`` refuses another; the sphere's
is ``pocket.shooting.sphere``, a user's profile's ``pocket.shooting.profile``).
Contact zone (0 <= r <= a): the sheet lies flat on the plate; tangential
equilibrium with no friction and regularity at the axis leave the uniform
equibiaxial stretch rho = lambda_c r, lambda_1 = lambda_2 = lambda_c (the normal
load is carried by the plate). At the contact edge the tension T_1 and the
position are continuous and the meridian is horizontal (a smooth plate cannot
exert a line force), so the free part a <= r <= 1 starts from
rho = lambda_c a, psi = 0, lambda_1 = lambda_c and is integrated to the clamp.

Unknowns x = (q, e): the pressure ratio q = P/P_I and the contact strain relative
to the inflated pole strain s_0 = lambda_0 - 1, e = (lambda_c - 1)/s_0, both of
order one for every Phat_I from 1e-6 up (a shallow dome has s_0 ~ 2e-5 at
Phat_I = 1e-6: lambda_c itself would be 1 to four digits). The force fixes the
contact radius: F = P A_c with A_c = pi (lambda_c a)^2 gives Fhat = q (lambda_c a)^2,
so a = sqrt(Fhat / q) / lambda_c. Residuals, also of order one:

    (rho(1) - 1) / s_0    (the clamp, relative to the pocket's strain)
    V / V_I - 1           (fixed fluid volume; V = -pi int rho^2 eta' dr over the free
                           part alone, eta' = 0 on the contact zone)

or, for a gas sealed at P_I, V / V_I - ((Phat_I + Phat_atm) / (Phat + Phat_atm))^(1/gamma)
(``pocket.core.fluids``: the polytropic law solved for V / V_I, of order one too; for a
liquid the ratio is exactly 1, so that residual is the liquid's bit for bit)

and, for the end of the range (``pocket.shooting.rangeend``), with the force as a
third unknown, psi(1) - theta (the meridian's angle at the clamp).

Residual noise. rho(1) - 1 is a difference of numbers near 1: a few ulps of 1,
divided by s_0, are its floor. The root finders stop at ``residual_tol``: rtol/100,
or 100 ulps / s_0 if that is larger (1e-9 at Phat_I = 1e-6). Shots whose integrator
steps change between nearby unknowns add noise of their own: a contact radius far
below the pole series' start (Fhat ~ 1e-20 and below) gives residuals of 1e-12 to 4e-11
at the inflated state's unknowns (measured at rtol 1e-10), which Newton cannot reduce.
A Newton iteration that stalls below ``residual_floor`` = 10 ``residual_tol`` along a
freshly differenced direction has reached that noise and is accepted (``newton.solve``'s
``floor``): its state is still far within the integration's own error (rtol).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from pocket.core.fluids import LIQUID, Fluid
from pocket.core.indenters import FLAT, Indenter, formulation
from pocket.core.states import InflatedState

from .integrator import OK, STATUS
from .laws import Law
from .shots import Tolerance, shot_edge

__all__ = ["CONTACTS", "Problem", "contact_of"]


@dataclasses.dataclass(frozen=True)
class Problem:
    """The compression of ``inflated`` (its rubber, Phat_I) at ODE tolerance ``rtol``, with ``fluid``
    sealed in it (ambient pressure as Phat_atm), by the flat plate ``indenter``. ``law`` is the inflated
    state's rubber (``pocket.shooting.laws.law_of``)."""

    inflated: InflatedState
    rtol: float
    law: Law
    fluid: Fluid = LIQUID
    indenter: Indenter = FLAT
    _last: dict = dataclasses.field(default_factory=dict, compare=False, repr=False)

    @property
    def label(self) -> str:
        """The pocket in messages: its rubber, Phat_I and (a gas) its fluid."""
        fluid = "" if not self.fluid.is_gas else f", gas at ambient {self.fluid.ambient!r}, gamma {self.fluid.gamma!r}"
        return f"{self.law.label}, pressure = {self.inflated.pressure!r}{fluid}"

    @property
    def key(self) -> tuple:
        """What identifies the pocket's problem (a cache key): rubber, Phat_I, rtol, fluid, indenter."""
        return (self.law.key, self.inflated.pressure, self.rtol, self.fluid, self.indenter)

    @property
    def strain(self) -> float:
        """s_0 = lambda_0 - 1, the scale of every strain of this pocket."""
        return self.inflated.stretch_pole - 1.0

    @property
    def tolerance(self) -> Tolerance:
        return Tolerance.scaled(self.rtol, self.inflated.height, self.inflated.volume)

    @property
    def residual_tol(self) -> float:
        """Accepted max |residual| (module docstring)."""
        return max(1e-2 * self.rtol, 100.0 * np.finfo(float).eps / self.strain)

    @property
    def residual_floor(self) -> float:
        """The residual below which a stalled Newton iteration has reached the noise (module docstring)."""
        return 10.0 * self.residual_tol

    def start(self) -> np.ndarray:
        """Unknowns (q, e) of the inflated state (Fhat -> 0): the guess for the first force."""
        return np.array([1.0, 1.0])

    def stretch(self, e) -> float:
        """lambda_c for the scaled contact strain e."""
        return 1.0 + self.strain * e

    def geometry(self, x, force):
        """(q, lambda_c, a, p) for unknowns x at ``force``, or None outside the model's domain."""
        q, e = x[0], x[1]
        lc = self.stretch(e)
        if not (q > 0.0 and lc > 0.0 and force > 0.0):
            return None
        a = math.sqrt(force / q) / lc
        if not a < 1.0:
            return None
        return q, lc, a, self.law.pressure_factor * self.inflated.pressure * q

    def shoot(self, x, force, store=0):
        """(status, y(1), steps) of the free part for unknowns x at ``force``; None outside the domain.

        The last shot without ``store`` is remembered: the solvers' last evaluation is at their
        solution, whose state is then read without shooting again.
        """
        g = self.geometry(x, force)
        if g is None:
            return None
        key = (float(x[0]), float(x[1]), float(force))
        if not store and self._last.get("key") == key:
            return self._last["shot"]
        _q, lc, a, p = g
        shot = shot_edge(lc, a, self.law, p, self.tolerance, store=store)
        if not store:
            self._last.update(key=key, shot=shot)
        return shot

    def failure(self) -> str:
        """The last shot that did not reach the clamp, in words ('' if none did)."""
        if "failure" not in self._last:
            return ""
        status, q, lc, force = self._last["failure"]
        return (f"the last shot that failed {STATUS[status]} (P/P_I = {q:.10g}, lambda_c = {lc:.10g}, "
                f"force = {force:.10g})")

    def clamp_angle(self, x, force) -> float:
        """psi(1), the meridian's angle at the clamp (pi where the free sheet reaches the clamp plane)."""
        return float(self.shoot(x, force)[1][2])

    @staticmethod
    def close(x, guess, previous) -> bool:
        """Whether a solution x stayed near the predicted ``guess``: within max(1, |previous|) in each
        unknown. A continuation step that jumps further may have landed on another branch."""
        return bool(np.all(np.abs(x - guess) <= np.maximum(1.0, np.abs(previous))))

    def compressed(self, force, x, fluid):
        """(the ``CompressedState`` at ``force`` for the solved unknowns x, its clamp angle psi(1))."""
        from .compression import plate_state

        return plate_state(self, force, x, fluid)

    def end(self, seed):
        """The range end (``pocket.shooting.rangeend.End``) from the solved (force, x) ``seed`` or None."""
        from .rangeend import plate_end

        return plate_end(self, seed)

    def on_branch(self, force):
        """Unknowns x at ``force`` near a fold, found on the end's branch by the clamp angle, or None
        (``pocket.shooting.rangeend.solve_on_branch``)."""
        from .rangeend import solve_on_branch

        return solve_on_branch(self, force)

    def residual(self, x, force, angle=None):
        """The residuals at ``force`` (shape (2,)), with psi(1) - ``angle`` appended if given; None
        where the shot does not reach the clamp or x is outside the domain."""
        shot = self.shoot(x, force)
        if shot is None or shot[0] != OK:
            if shot is not None:
                self._last["failure"] = (shot[0], float(x[0]), self.stretch(x[1]), float(force))
            return None
        y = shot[1]
        pressure = self.inflated.pressure
        out = [(y[0] - 1.0) / self.strain, y[4] / self.inflated.volume - self.fluid.volume_ratio(pressure * x[0],
                                                                                                  pressure)]
        return np.array(out if angle is None else [*out, y[2] - angle])


from .profile import ProfileProblem  # noqa: E402 (it builds on Problem)
from .sphere import SphereProblem  # noqa: E402 (it builds on Problem)

#: indenter kind -> the problem that poses its contact
CONTACTS: dict[str, type[Problem]] = {"flat": Problem, "sphere": SphereProblem, "profile": ProfileProblem}


def contact_of(indenter: Indenter) -> type[Problem]:
    """The problem class posing the contact of ``indenter``; an InputError naming this solver and the
    indenter for a kind it does not pose (``pocket.core.indenters.formulation``)."""
    return formulation(CONTACTS, "shooting", indenter)
