"""What every contact problem of step 2 shares, whatever presses on the pocket: its inflated state, tolerances
and noise, the fluid's closure and the cache of the last shot.

Each indenter's formulation builds on ``Contact``: the flat plate's (``pocket.shooting.plate``) and that of
every curved indenter (``pocket.shooting.surface``). A formulation poses unknowns x whose first two are
(q, e): the pressure ratio q = P/P_I and the contact strain relative to the inflated pole strain
s_0 = lambda_0 - 1, e = (lambda_c - 1)/s_0, both of order one for every Phat_I from 1e-6 up (a shallow dome
has s_0 ~ 2e-5 at Phat_I = 1e-6: lambda_c itself would be 1 to four digits). Its first two residuals are
common too, also of order one:

    (rho(1) - 1) / s_0    (the clamp, relative to the pocket's strain)
    V / V_I - 1           (fixed fluid volume)

or, for a gas sealed at P_I, V / V_I - ((Phat_I + Phat_atm) / (Phat + Phat_atm))^(1/gamma)
(``pocket.core.fluids``: the polytropic law solved for V / V_I, of order one too; for a
liquid the ratio is exactly 1, so that residual is the liquid's bit for bit); a formulation appends
its own (``_closure``) and, for the end of the range, psi(1) - theta (the meridian's angle at the clamp).

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
import functools
from collections.abc import Callable
from typing import ClassVar

import numpy as np

from pocket.core.errors import ConvergenceError
from pocket.core.fluids import LIQUID, Fluid
from pocket.core.indenters import PLATE, Indenter
from pocket.core.states import InflatedState

from .integrator import OK, STATUS
from .laws import Law
from .shots import Tolerance

__all__ = ["Contact", "final_shots"]


@dataclasses.dataclass(frozen=True)
class Contact:
    """The compression of ``inflated`` (its rubber, Phat_I) at ODE tolerance ``rtol``, with ``fluid``
    sealed in it (ambient pressure as Phat_atm), by ``indenter``. ``law`` is the inflated state's rubber
    (``pocket.shooting.laws.law_of``). A formulation supplies ``geometry``, ``_shot`` and ``_closure``."""

    inflated: InflatedState
    rtol: float
    law: Law
    fluid: Fluid = LIQUID
    indenter: Indenter = PLATE
    _last: dict = dataclasses.field(default_factory=dict, compare=False, repr=False)

    #: None, or a formulation's ``jacobian(x, force, f)``: dR/dx at x (f the residuals there) cheaper than the
    #: residual's differences (or None where it has none). A continuation then starts each force's Newton
    #: iteration from it at the predicted x, instead of from the Jacobian carried from the last force.
    jacobian: ClassVar[Callable[..., np.ndarray | None] | None] = None
    #: the degree of a continuation's prediction, a polynomial in ``predictor`` through the last states
    PREDICTOR_DEGREE = 2

    @staticmethod
    def predictor(force: float) -> float:
        """The variable in which a continuation predicts the unknowns (``PREDICTOR_DEGREE``): the force itself; a
        formulation may choose another (the capsule's log F)."""
        return force

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

    @functools.cached_property
    def tolerance(self) -> Tolerance:
        """The shots' integration tolerances (computed once: every shot reads them)."""
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
        """The unknowns of the inflated state (Fhat -> 0): the guess for the first force."""
        raise NotImplementedError

    def geometry(self, x, force):
        """(q, lambda_c, a, p) for unknowns x at ``force``, or None outside the model's domain."""
        raise NotImplementedError

    def _shot(self, geometry, store):
        """The shot (status, y(1), ...) at ``geometry`` = (q, lambda_c, a, p), storing up to ``store`` steps."""
        raise NotImplementedError

    def _closure(self, x, force, shot) -> tuple:
        """The formulation's residuals after the common two, for the ``shot`` that reached the clamp."""
        raise NotImplementedError

    def compressed(self, force, x, fluid):
        """(the ``CompressedState`` at ``force`` for the solved unknowns x, its clamp angle psi(1))."""
        raise NotImplementedError

    def end(self, seed):
        """The range end (``pocket.shooting.end.End``) from the solved (force, x) ``seed`` or None."""
        raise NotImplementedError

    def on_branch(self, force):
        """Unknowns x at ``force`` near a fold, found on the end's branch, or None."""
        raise NotImplementedError

    def stretch(self, e) -> float:
        """lambda_c for the scaled contact strain e."""
        return 1.0 + self.strain * e

    def shoot(self, x, force, store=0):
        """The formulation's shot (``_shot``: status, y(1), ... ) for unknowns x at ``force``; None outside
        the domain (``geometry``).

        The last shot without ``store`` is remembered: the solvers' last evaluation is at their
        solution, whose state is then read without shooting again.
        """
        g = self.geometry(x, force)
        if g is None:
            return None
        key = (*map(float, x), float(force))
        if not store and self._last.get("key") == key:
            return self._last["shot"]
        shot = self._shot(g, store)
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

    def past_its_end(self, force, x, band) -> bool:
        """Whether the solved state x at ``force`` has its contact edge within ``band`` of, or past, the end of
        an indenter whose shots go on solving there (none here: the plate has no end)."""
        return False

    def residual(self, x, force, angle=None):
        """The residuals at ``force`` (module docstring, then the formulation's ``_closure``), with
        psi(1) - ``angle`` appended if given; None where a shot does not reach its end or x is outside
        the domain."""
        shot = self.shoot(x, force)
        if shot is None or shot[0] != OK:
            if shot is not None:
                self._last["failure"] = (shot[0], float(x[0]), self.stretch(x[1]), float(force))
            return None
        y = shot[1]
        pressure = self.inflated.pressure
        out = [(y[0] - 1.0) / self.strain, y[4] / self.inflated.volume - self.fluid.volume_ratio(pressure * x[0],
                                                                                                  pressure),
               *self._closure(x, force, shot)]
        return np.array(out if angle is None else [*out, y[2] - angle])


def final_shots(force, status, profile_status) -> None:
    """A ConvergenceError if the final shot at ``force`` (its ``status``) or the shot storing its profile
    did not reach the clamp."""
    for what, code in (("final", status), ("profile", profile_status)):
        if code != OK:
            raise ConvergenceError(f"compression at force = {force!r}: the {what} shot {STATUS[code]}", load=force)
