"""Continuation in the force, as every compression of this solver is solved: each force from the last two states
(``pocket.shooting.compression``'s module docstring tells the method: damped Newton-Broyden steps seeded by secant
extrapolation, halved on failure, the range end consulted where a step fails). A problem that gives its Jacobian
(``Contact.jacobian``: the capsule's) has each force's iteration start from it at the prediction instead of from
the last force's; a problem may predict in a variable of its own and with a polynomial of another degree
(``Contact.predictor``, ``Contact.PREDICTOR_DEGREE``: the capsule's quartic in log F).

A problem is a ``pocket.shooting.contact.Contact`` (a pocket's contact with its indenter, or a closed capsule between
two plates); this module knows nothing of which: a problem's own ``end`` may seed itself with ``first_state``.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from pocket.core.errors import ConvergenceError, beyond_range

from . import newton
from .end import end_of

__all__ = ["Branch", "advance", "band", "beyond", "first_state", "past_the_profile"]

_MIN_STEP = 1e-9  # smallest force step, relative to the force, before a solve is declared failed
_KEPT = 5  # the most solved points a branch keeps (``Branch.guess`` reads up to a problem's degree + 1)
_FOLD_STEP = 1e-3  # near a fold of the force (within 10 such steps of it), the step below which the state is
# sought on the end's branch (``Contact.on_branch``)


def band(rtol):
    """Distance of psi(1) below pi inside which a state consults the range end (rad)."""
    return max(1e-6, 1e4 * rtol)


def beyond(force, problem, seed):
    """The range end of ``problem`` (``end.End``); OutOfRangeError if ``force`` is past it."""
    end = end_of(problem, seed)
    if force > end.force:
        where = (end.reason if not end.fold else
                 f"the force has a maximum, with the sheet's angle at the clamp at {end.angle:.6g} rad")
        refusal = beyond_range(f"force = {force!r}", f"force = {end.force:.10g} ({problem.label})", where)
        refusal.end, refusal.bound = f"force = {end.force:.10g}", end.force
        raise refusal
    return end


def past_the_profile(problem, force, x) -> None:
    """OutOfRangeError (``beyond``, its end sought from inside the range) if ``force`` is past the range end and
    its solved state x has the contact edge at or past the end of a profile (``Contact.past_its_end`` within
    ``band``). Past its extent a profile's curvature is read at the extent (``pocket.shooting.surface``), so such
    a state solves with no failed step: this is what keeps it from being returned."""
    if problem.past_its_end(force, x, band(problem.rtol)):
        beyond(force, problem, None)


def _on_branch(problem, force):
    """newton.Solution at ``force`` seeded on the branch by its clamp angle (near a fold), or None."""
    x = problem.on_branch(force)
    if x is None:
        return None
    sol = newton.solve(lambda v: problem.residual(v, force), x, tol=problem.residual_tol,
                       floor=problem.residual_floor)
    return sol if sol.success else None


@dataclasses.dataclass(frozen=True)
class Branch:
    """Where a continuation stands: the last solved (force, x), up to ``_KEPT``, the last Jacobian, and the sign
    of det dR/dx on the first branch (it changes at a fold of the force: a state with the other
    sign lies past the fold, on another branch)."""

    points: tuple
    jacobian: np.ndarray | None = None
    orientation: float = 0.0

    def guess(self, force, variable=None, degree=2):
        """Prediction of x at ``force``: the polynomial through the last ``degree`` + 1 points (of a lower degree
        where there are fewer; two: the secant), those at a positive force (the inflated state at 0 is no point of
        the curve in the unknowns of a compression: a capsule's contact radius is c sqrt(Fhat)), in the force or in
        ``variable(force)`` if given (a problem's ``Contact.predictor`` and ``Contact.PREDICTOR_DEGREE``)."""
        points = [(f, x) for f, x in self.points[-degree - 1:] if f > 0.0]
        if not points:
            return self.points[-1][1]
        at = (lambda f: f) if variable is None else variable
        t, ts = at(force), [at(f) for f, _ in points]
        guess = np.zeros_like(points[-1][1])
        for j, (tj, (_, xj)) in enumerate(zip(ts, points, strict=True)):  # Lagrange's form
            weight = math.prod((t - tk) / (tj - tk) for k, tk in enumerate(ts) if k != j)
            guess = guess + weight * xj
        return guess

    def then(self, force, x, jacobian, orientation):
        return Branch(points=(*self.points[1 - _KEPT:], (force, x)), jacobian=jacobian,
                       orientation=self.orientation or orientation)


def _orientation(problem, sol, force, branch):
    """sign det J at a solution: by differences (or the problem's own ``jacobian``) for the first state of a
    branch, or when the Broyden-updated J (an approximation) disagrees with the branch."""
    sign = 0.0 if sol.jacobian is None else np.sign(np.linalg.det(sol.jacobian))
    if sign != branch.orientation or not branch.orientation:
        jac = None if problem.jacobian is None else problem.jacobian(sol.x, force, sol.f)
        jac = newton.differences(lambda v: problem.residual(v, force), sol.x, sol.f) if jac is None else jac
        sign = 0.0 if jac is None else np.sign(np.linalg.det(jac))
    return sign


def advance(problem, branch, force):
    """Continue ``branch`` (a ``Branch``) to ``force``; returns the branch there."""
    f0, x0 = branch.points[-1]
    step, end, unknown = force - f0, None, ""
    while f0 < force:
        f_try = min(f0 + step, force)
        guess = branch.guess(f_try, problem.predictor, problem.PREDICTOR_DEGREE)
        derivative = None if problem.jacobian is None else \
            lambda x, f, f_try=f_try: problem.jacobian(x, f_try, f)
        sol = newton.solve(lambda x, f=f_try: problem.residual(x, f), guess, tol=problem.residual_tol,
                           floor=problem.residual_floor, jacobian=branch.jacobian if derivative is None else None,
                           derivative=derivative)
        if sol.success and problem.close(sol.x, guess, x0) and \
                problem.clamp_angle(sol.x, f_try) <= math.pi + band(problem.rtol):
            sign = _orientation(problem, sol, f_try, branch)
            if not branch.orientation or sign == branch.orientation:
                branch = branch.then(f_try, sol.x, sol.jacobian, sign)
                f0, x0 = f_try, sol.x
                step = min(2.0 * step, force - f0) if f0 < force else step
                continue
        if not unknown:
            try:
                end = beyond(force, problem, (f0, x0) if f0 > 0.0 else None)
            except ConvergenceError as err:  # keep stepping (the force may still be reached), once
                end, unknown = None, f"; locating the end of the range failed too: {err}"
        step *= 0.5
        branch = dataclasses.replace(branch, jacobian=None)
        near_fold = end is not None and end.fold and f_try >= (1.0 - 10.0 * _FOLD_STEP) * end.force
        if step < (_FOLD_STEP if near_fold else _MIN_STEP) * force:
            found = _on_branch(problem, force) if end is not None else None
            if found is not None:
                return branch.then(force, found.x, found.jacobian, 0.0)
            raise _failed(problem, sol, f_try, f0, force, unknown)
    return branch


def first_state(problem, force):
    """(force, x): the state of ``problem`` at ``force``, continued from the inflated state as ``compression_curve``
    continues (a problem's ``end`` seeds itself with it)."""
    return advance(problem, Branch(points=((0.0, problem.start()),)), force).points[-1]


def _failed(problem, sol, f_try, f0, force, more):
    """The ConvergenceError of a continuation step that could not be taken: where, from where, why."""
    q, e = sol.x[:2]
    why = sol.message if not sol.success else "the solution left the branch (past pi, a fold, or a jump)"
    last = problem.failure()
    lc = problem.stretch(e)
    margin = problem.law.lock_margin(lc, lc)
    locking = (f"; the contact zone is within {margin:.1e} of the rubber's locking (1 - (I1 - 3)/Jm), where "
               "the tensions, and so the residuals' noise, grow without bound" if margin < 1e-2 else "")
    return ConvergenceError(
        f"compression failed at force = {f_try:.10g} (continuing from force = {f0:.10g} towards {force!r}, "
        f"{problem.label}): {why}; max |residual| = "
        f"{sol.residual:.3g} at P/P_I = {q:.10g}, lambda_c = {lc:.10g}" + locking + (f"; {last}" if last else "")
        + more, load=f_try, iterations=sol.evaluations, residual=sol.residual)


