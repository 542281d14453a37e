"""Step 2, compression at fixed volume by a rigid frictionless indenter, force given.

The indenter is an argument (``pocket.core.indenters``): this solver poses the flat plate,
its default (``pocket.shooting.plate``), and every curved indenter it has an entry for, a sphere or
a user's profile (``pocket.shooting.surface``, whose problem the continuation below solves the same
way), and refuses another kind (``pocket.shooting.problem.CONTACTS``).

The shooting problem (unknowns, residuals, their scaling) is ``pocket.shooting.contact`` and the
indenter's formulation; the fluid sealed in the pocket (a liquid: fixed volume; a gas: the
polytropic law) enters only its volume residual.
Each force is solved by the damped Newton-Broyden method of
``pocket.shooting.newton``, by continuation in the force from the inflated state:
forces are taken in increasing order, each seeded by secant extrapolation from
the last two states and the last Jacobian. A step that does not converge is
halved (and the step grows again after successes). Near a fold of the force
(the end of the range for some alpha < 0, ``pocket.shooting.plateend``) continuation in
the force stalls; there the state is found on the branch by its clamp angle instead.
A solve fails, with a ConvergenceError saying at which force, from which force, with
what residual and why, only when both fail and the step is below 1e-9 of the force.

The model's range ends at the force Fhat_end where the free sheet reaches the
clamp plane (``pocket.shooting.plateend``; psi(1) = pi; under a curved indenter also the ends
of ``pocket.shooting.surfaceend``). A force above it is an
OutOfRangeError quoting Fhat_end, the same number whatever force was asked; a
force up to it is solved. Fhat_end is computed (once, cached) only when it can
matter: when a step fails, or when a state's clamp angle psi(1) comes within
1e-6 rad (or 1e4 rtol) of pi, or its indenter's lowest point lies below the clamp plane, or its
contact edge comes within 1e-6 (or 1e4 rtol) of the end of a profile (``pocket.shooting.surface``:
there the shots go on solving past the profile's last radius, so nothing else would stop them).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from pocket.core.errors import ConvergenceError, InputError, beyond_range
from pocket.core.fluids import as_fluid
from pocket.core.geometries import posed
from pocket.core.indenters import as_indenter
from pocket.core.inputs import check_force, check_positive
from pocket.core.states import CompressedState

from . import newton
from .capsule import CapsuleProblem
from .contact import Contact
from .end import end_of
from .inflation import GEOMETRIES, inflate
from .laws import law_of
from .problem import problem_of

__all__ = ["compress", "compression_curve", "first_state"]

_MIN_STEP = 1e-9  # smallest force step, relative to the force, before a solve is declared failed
_FOLD_STEP = 1e-3  # near a fold of the force (within 10 such steps of it), the step below which the state is
# sought on the end's branch (``Contact.on_branch``)


def _band(rtol):
    """Distance of psi(1) below pi inside which a state consults the range end (rad)."""
    return max(1e-6, 1e4 * rtol)


def _beyond(force, problem, seed):
    """The range end of ``problem`` (``end.End``); OutOfRangeError if ``force`` is past it."""
    end = end_of(problem, seed)
    if force > end.force:
        where = (end.reason if not end.fold else
                 f"the force has a maximum, with the sheet's angle at the clamp at {end.angle:.6g} rad")
        raise beyond_range(f"force = {force!r}", f"force = {end.force:.10g} ({problem.label})", where)
    return end


def _past_the_profile(problem, force, x) -> None:
    """OutOfRangeError (``_beyond``, its end sought from inside the range) if ``force`` is past the range end and
    its solved state x has the contact edge at or past the end of a profile (``Contact.past_its_end`` within
    ``_band``). Past its extent a profile's curvature is read at the extent (``pocket.shooting.surface``), so such
    a state solves with no failed step: this is what keeps it from being returned."""
    if problem.past_its_end(force, x, _band(problem.rtol)):
        _beyond(force, problem, None)


def _on_branch(problem, force):
    """newton.Solution at ``force`` seeded on the branch by its clamp angle (near a fold), or None."""
    x = problem.on_branch(force)
    if x is None:
        return None
    sol = newton.solve(lambda v: problem.residual(v, force), x, tol=problem.residual_tol,
                       floor=problem.residual_floor)
    return sol if sol.success else None


@dataclasses.dataclass(frozen=True)
class _Branch:
    """Where a continuation stands: the last two solved (force, x), the last Jacobian, and the sign
    of det dR/dx on the first branch (it changes at a fold of the force: a state with the other
    sign lies past the fold, on another branch)."""

    points: tuple
    jacobian: np.ndarray | None = None
    orientation: float = 0.0

    def guess(self, force):
        """Secant prediction of x at ``force`` from the last two points."""
        (f0, x0) = self.points[-1]
        if len(self.points) < 2 or self.points[-2][0] <= 0.0:
            return x0
        f_prev, x_prev = self.points[-2]
        return x0 + (force - f0) * (x0 - x_prev) / (f0 - f_prev)

    def then(self, force, x, jacobian, orientation):
        return _Branch(points=(self.points[-1], (force, x)), jacobian=jacobian,
                       orientation=self.orientation or orientation)


def _orientation(problem, sol, force, branch):
    """sign det J at a solution: by differences for the first state of a branch, or when the
    Broyden-updated J (an approximation) disagrees with the branch."""
    sign = 0.0 if sol.jacobian is None else np.sign(np.linalg.det(sol.jacobian))
    if sign != branch.orientation or not branch.orientation:
        jac = newton.differences(lambda v: problem.residual(v, force), sol.x, sol.f)
        sign = 0.0 if jac is None else np.sign(np.linalg.det(jac))
    return sign


def _advance(problem, branch, force):
    """Continue ``branch`` (a ``_Branch``) to ``force``; returns the branch there."""
    f0, x0 = branch.points[-1]
    step, end, unknown = force - f0, None, ""
    while f0 < force:
        f_try = min(f0 + step, force)
        guess = branch.guess(f_try)
        sol = newton.solve(lambda x, f=f_try: problem.residual(x, f), guess, tol=problem.residual_tol,
                           floor=problem.residual_floor, jacobian=branch.jacobian)
        if sol.success and problem.close(sol.x, guess, x0) and \
                problem.clamp_angle(sol.x, f_try) <= math.pi + _band(problem.rtol):
            sign = _orientation(problem, sol, f_try, branch)
            if not branch.orientation or sign == branch.orientation:
                branch = branch.then(f_try, sol.x, sol.jacobian, sign)
                f0, x0 = f_try, sol.x
                step = min(2.0 * step, force - f0) if f0 < force else step
                continue
        if not unknown:
            try:
                end = _beyond(force, problem, (f0, x0) if f0 > 0.0 else None)
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
    return _advance(problem, _Branch(points=((0.0, problem.start()),)), force).points[-1]


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


def _uncompressed(problem: Contact, force: float, fluid) -> CompressedState:
    """Fhat = 0: the inflated state itself, seen as a compressed state with no contact."""
    inflated = problem.inflated
    state = CompressedState(
        pressure_initial=inflated.pressure, force=force,
        pressure=inflated.pressure, pressure_ratio=1.0, contact_area=0.0, contact_radius=0.0,
        stretch_contact=inflated.stretch_pole, height=inflated.height, height_ratio=1.0,
        volume=inflated.volume, profile=inflated.profile, inflated=inflated, solver="shooting",
        material=inflated.material, fluid=fluid, tension_1_min=inflated.tension_1_min,
        tension_2_min=inflated.tension_2_min, indenter=problem.indenter,
    )
    return problem.untouched(state) if isinstance(problem, CapsuleProblem) else state


def compression_curve(material, pressure_initial, forces, *, fluid=None, indenter=None, geometry=None, rtol=1e-10,
                      progress=None) -> list[CompressedState]:
    """Compress the inflated pocket at each force Fhat = F / (P_I pi R^2) of ``forces``, by continuation.

    The pocket is inflated at Phat_I (``inflate``), its fluid sealed, then pressed by the indenter; the
    forces are taken in increasing order, each state seeded by those before it.

    Parameters
    ----------
    material : Material or float
        The rubber, a ``pocket.core.materials.Material`` (any stress unit) or a Mooney-Rivlin alpha = C2/C1.
    pressure_initial : float
        Phat_I = P_I R / (E T) > 0, the inflation pressure the fluid is sealed at.
    forces : sequence of float
        Fhat = F / (P_I pi R^2) >= 0 of each state, in any order.
    fluid : Fluid or str, optional
        None or ``"liquid"`` (fixed volume), or a gas (``pocket.core.fluids.gas``) with its ambient pressure
        in the model's units, Phat_atm = P_atm R / (E T).
    indenter : Indenter, optional
        None (the flat plate) or a ``pocket.core.indenters.Indenter`` this solver poses (``Sphere``,
        ``Profile``), lengths in units of R.
    geometry : Geometry or str, optional
        The reference surface: None (the flat clamped disc) or one this solver poses (``GEOMETRIES``).
    rtol : float, optional
        Relative tolerance of the ODE integration, at most 1e-4.
    progress : callable, optional
        ``progress(done, total)``, called after each force (``total`` = len(forces)).

    Returns
    -------
    list of CompressedState
        In the order of ``forces``, each echoing its inputs exactly.

    Raises
    ------
    InputError
        For invalid input (an indenter or geometry this solver does not pose, a negative force, no force).
    OutOfRangeError
        For a force past the end of the model's range (``range_end``), or a Phat_I above the pressure maximum.
    ConvergenceError
        If a solve fails; it says at which force.

    Examples
    --------
    >>> from pocket import shooting
    >>> states = shooting.compression_curve(47 / 160, 0.31, [0.1, 0.19])
    >>> print([f"{s.pressure_ratio:.4f}" for s in states])
    ['1.1564', '1.2944']

    The fluid's volume is held:

    >>> print(all(abs(s.volume - s.inflated.volume) < 1e-9 for s in states))
    True
    """
    geometry, _ = posed(GEOMETRIES, "shooting", geometry)
    law = law_of(material)
    pressure_initial = check_positive("pressure", pressure_initial)
    fluid = as_fluid(fluid)
    indenter = as_indenter(indenter)
    forces = [check_force(f) for f in np.atleast_1d(np.asarray(forces, dtype=object))]
    if not forces:
        raise InputError("no force given")
    problem = problem_of(geometry, indenter)(inflate(material, pressure_initial, geometry=geometry, rtol=rtol), rtol,
                                           law, fluid, indenter)
    if isinstance(problem, CapsuleProblem):
        problem.conditioned()
    counts = {f: forces.count(f) for f in forces}
    states, done = {}, 0
    branch = _Branch(points=((0.0, problem.start()),))
    for f in sorted(counts):
        if f == 0.0:
            states[f] = _uncompressed(problem, f, fluid)
        else:
            branch = _advance(problem, branch, f)
            _past_the_profile(problem, f, branch.points[-1][1])
            states[f], clamp_angle = problem.compressed(f, branch.points[-1][1], fluid)
            # a solved state past an end: an indenter's lowest point below the clamp plane (a taut, prestretched
            # sheet under a small sphere gets there with no failed step), or the free sheet at the clamp plane
            if states[f].height < 0.0:  # no seed: the end is sought from inside the range
                _beyond(f, problem, None)
            if clamp_angle >= math.pi - _band(rtol):
                _beyond(f, problem, branch.points[-1])
        done += counts[f]
        if progress is not None:
            progress(done, len(forces))
    return [states[f] for f in forces]


def compress(material, pressure_initial, force, *, fluid=None, indenter=None, geometry=None,
             rtol=1e-10) -> CompressedState:
    """Compress the pocket inflated at Phat_I = ``pressure_initial`` by the force Fhat = F / (P_I pi R^2).

    One state of ``compression_curve``.

    Parameters
    ----------
    material : Material or float
        The rubber, a ``pocket.core.materials.Material`` (any stress unit) or a Mooney-Rivlin alpha = C2/C1.
    pressure_initial : float
        Phat_I = P_I R / (E T) > 0.
    force : float
        Fhat = F / (P_I pi R^2) >= 0.
    fluid, indenter, geometry, rtol
        As for ``compression_curve``.

    Returns
    -------
    CompressedState
        Pressures in units of E T / R, lengths of R, the deformed contact area A_c in units of pi R^2.

    Raises
    ------
    InputError
        For invalid input.
    OutOfRangeError
        For a force past the end of the model's range (``range_end``).
    ConvergenceError
        If the solve fails.

    Examples
    --------
    The paper's headline pocket (alpha = 47/160, Phat_I = 0.31) at Fhat = 0.19:

    >>> from pocket import shooting
    >>> state = shooting.compress(47 / 160, 0.31, 0.19)
    >>> print(round(state.pressure_ratio, 3))
    1.294

    The flat plate carries the force by the pressure on the contact area, F = P A_c, that is
    Fhat Phat_I = Phat A_c / (pi R^2):

    >>> print(abs(state.force * state.pressure_initial - state.pressure * state.contact_area) < 1e-9)
    True

    A sphere of radius R_s = R / 2 (``pocket.core.indenters.Sphere``) and air (``pocket.core.fluids.gas``,
    the ambient pressure in units of E T / R):

    >>> from pocket.core.fluids import gas
    >>> from pocket.core.indenters import Sphere
    >>> pressed = shooting.compress(47 / 160, 0.31, 0.19, indenter=Sphere(0.5), fluid=gas(10.0, 1.4))
    >>> print(pressed.pressure > state.inflated.pressure, pressed.volume < state.volume)
    True True
    """
    return compression_curve(material, pressure_initial, [force], fluid=fluid, indenter=indenter, geometry=geometry,
                             rtol=rtol)[0]
