r"""A capsule at a given plate height on its second branch, down to P_I = 0: reached by a descent in the pressure.

Two branches. Pressed from the inflated capsule (force control, ``pocket.shooting.capsule``), a capsule at a low
Phat_I reaches the end of its first branch where the meridional tension at the contact edge vanishes
(``CAPSULE_EDGE``: at Phat_I = 0.01, neo-Hookean, a liquid, at a compression of 5.6 %), and at P_I = 0 it has no
first branch at all (the patch under the plate is slack from the first touch). Yet membrane states lie beyond: at a
larger compression the fluid's pressure, raised by the squeeze, tautens the patch again, and the states of a second
branch fill the plate heights H <= H*, H* the height where the edge's tension vanishes again, now from below (the
branch's least compression: H* = 0.793 at P_I = 0, 0.848 at Phat_I = 0.01, neo-Hookean, a liquid). Between the
first branch's end and H* (at a low P_I > 0) no membrane state lies; at a higher P_I the two branches are one.

The route (``capsule_at_height``). The second branch is reached where it joins the first: at the anchor Phat_A =
``ANCHOR`` (0.1), whose range has no end (the neo-Hookean liquid's first branch has none above Phat_I ~ 0.02), the
capsule is pressed from its inflated state (a force-controlled state at Fhat = ``_FORCE``, then height control,
``CapsuleProblem(height=...)``) down to the plate height H_d = min(H, ``H_DEEP``); H_DEEP = 0.5 lies below the
neo-Hookean liquid's H* at every Phat_I, so the states at H_d on the path below all lie on the second branch (where
they do not, a soft gas's, the path stalls and H_d is halved, down to ``_DEEPEST``). There, at fixed H_d, the fluid
sealed in the capsule is changed from that of Phat_A to that of the target Phat_I (a liquid: its volume from
V_I(Phat_A) to V_I(Phat_I), at P_I = 0 the unstressed sphere's 4 pi / 3; a gas: the amount sealed at Phat_I), each
step a new ``CapsuleProblem`` on the capsule inflated at that Phat_I, and then, if H > H_d, the plates are raised to
H at the target Phat_I. Every problem on the way is scaled by the anchor (``CapsuleProblem``'s ``reference``:
q = P / P_A, e = (lambda_0 - 1) / (lambda_A - 1), and the anchor's count of the free part's segments), so that P_I = 0
is posed and a solution's unknowns are the next problem's as they stand.

Each leg is a natural continuation (``_march``): a step's unknowns predicted by the secant through the last two
states, solved by ``pocket.shooting.newton``, the step doubled after a success and halved after a failure. On the
path in Phat_I and on the way up the edge's meridional tension T_1 is watched: a state with T_1 <= 0 at the edge
(its shot goes slack) is refused as a failure, so that the march up stops below H*, its steps halved down to
``_END_STEP``: H* to within twice that (a bisection). A height above it is an OutOfRangeError quoting H*
(``CAPSULE_EDGE``); a march that stalls where the edge's tension has not fallen below ``_EDGE_SLACK`` of the
anchor's is a ConvergenceError.

At P_I = 0 the state's ``pressure_ratio`` and ``force`` (Fhat = F / (P_I pi R^2)) have no value (NaN); the force
is ``extra["force_ETR"]`` = F / (E T R) = pi P rho_c^2 (units E T / R for P), the ``height_ratio`` H over the
unstressed sphere's radius, and ``inflated`` the unstressed sphere.
"""

from __future__ import annotations

import math

import numpy as np

from pocket.core.errors import ConvergenceError, OutOfRangeError, above_the_pocket, capsule_gap
from pocket.core.fluids import as_fluid
from pocket.core.geometries import CAPSULE
from pocket.core.inputs import check_non_negative, check_positive
from pocket.core.solver import FluidLike, MaterialLike
from pocket.core.states import CompressedState

from . import brent, newton
from .capsule import CapsuleProblem
from .continuation import first_state
from .inflation import inflate
from .laws import law_of

__all__ = ["ANCHOR", "H_DEEP", "branch_start", "capsule_at_force", "capsule_at_height"]

#: Phat_A, the inflation pressure the descent starts from: the neo-Hookean liquid's first branch has no end above
#: Phat_I ~ 0.02 (benchmarks/capsule_low_pressure.py), so at 0.1 it reaches every height, into the second branch
ANCHOR = 0.1
#: the deepest plate height the anchor is pressed to before its pressure is changed: below the second branch's least
#: compression at every Phat_I (H* = 0.793 at P_I = 0, neo-Hookean, a liquid), and nearly taut there (at P_I = 0 the
#: pole's tension is compressive by 0.006 E T at 0.5, positive below about 0.48)
H_DEEP = 0.5
#: the deepest H_d: where the fluid's change at H_d stalls (the edge's tension vanishing on the way: a soft gas, whose
#: pressure the squeeze raises less, has H* below 0.5), H_d is halved, down to this
_DEEPEST = 0.125
_FORCE = 0.01  # Fhat of the anchor's force-controlled state, where its height control starts: the force's
# continuation from the inflated state is cheapest to a small force (a call took 0.15 s from here, 0.25 s from 0.1)
_UNIT = 1.0  # the "force" argument of a height-controlled problem: unused, but its domain needs it > 0
_H_STEP = 0.05  # the first step of a march in height (units R)
_P_STEP = 0.02  # ... and of the march in Phat_I
_P_STALL = 1e-6  # the step in Phat_I at which its march has stalled (where the edge goes slack: ``_DEEPEST``)
_STALL = 1e-9  # the step (relative to the march's length) at which a march that cannot go on has failed
_END_STEP = 1e-6  # the step in height at which the march up stops at H*: its accuracy
_FORCE_RTOL = 1e-12  # the relative width of the height bracket at the force's root (``capsule_at_force``)
_EDGE_SLACK = 1e-2  # the edge's tension, relative to the anchor's inflated tension, below which a stall is at H*


def _march(build, x, start, stop, step, *, taut=False, smallest=None):
    """(t, x): the unknowns continued from ``start`` towards ``stop`` (module docstring), ``build(t)`` the problem
    at t; t is ``stop`` unless a step below ``smallest`` (default ``_STALL`` of the march's length) failed, where
    it is the last t solved. ``taut``: a state whose edge tension is not positive is a failure."""
    smallest = _STALL * abs(stop - start) if smallest is None else smallest
    sign = math.copysign(1.0, stop - start)
    points = [(start, x)]
    t = start
    while t != stop:
        t_try = stop if abs(stop - t) <= step else t + sign * step
        (t0, x0), (t1, x1) = points[-2:] if len(points) > 1 else (points[-1], points[-1])
        guess = x1 if t1 == t0 else x1 + (t_try - t1) * (x1 - x0) / (t1 - t0)
        problem = build(t_try)
        sol = newton.solve(lambda v, p=problem: p.residual(v, _UNIT), guess, tol=problem.residual_tol,
                           floor=problem.residual_floor)
        if sol.success and not (taut and problem.edge_tension(sol.x, _UNIT) <= 0.0):
            points = [*points[-1:], (t_try, sol.x)]
            t, step = t_try, 2.0 * step
        else:
            step *= 0.5
            if step < smallest:
                break
    return t, points[-1][1]


def capsule_at_height(material: MaterialLike, pressure_initial: float, height: float, *, fluid: FluidLike = None,
                      rtol: float = 1e-10) -> CompressedState:
    """The capsule inflated at Phat_I = ``pressure_initial`` >= 0, pressed between two plates to the height H/R =
    ``height``, on its second branch (module docstring).

    Travel control, by the descent from the anchor ``ANCHOR``; ``pocket.shooting.compress_height`` takes this
    route where the first branch does not reach the height.

    Parameters
    ----------
    material : Material or float
        The rubber, a ``pocket.core.materials.Material`` (any stress unit) or a Mooney-Rivlin alpha = C2/C1.
    pressure_initial : float
        Phat_I = P_I R / (E T) >= 0, the inflation pressure the fluid is sealed at (0: the unstressed sphere).
    height : float
        H / R > 0, the plates' height above the equatorial plane.
    fluid : Fluid or str, optional
        None or ``"liquid"`` (fixed volume), or a gas (``pocket.core.fluids.gas``) sealed at Phat_I, its ambient
        pressure in units of E T / R.
    rtol : float, optional
        Relative tolerance of the ODE integration.

    Returns
    -------
    CompressedState
        Pressures in units of E T / R, lengths of R; at P_I = 0 ``force`` and ``pressure_ratio`` are NaN and the
        force is ``extra["force_ETR"]`` = F / (E T R).

    Raises
    ------
    InputError
        For invalid input.
    OutOfRangeError
        For a height above the inflated capsule, or above the second branch's least compression H* (quoted).
    ConvergenceError
        If a solve on the way fails.

    Examples
    --------
    The uninflated neo-Hookean capsule of liquid pressed to 72 % of its radius: its pressure, the force on each plate
    (F = P A_c), and its volume, the unstressed sphere's:

    >>> import math
    >>> from pocket.shooting.descent import capsule_at_height
    >>> state = capsule_at_height(0.0, 0.0, 0.72)
    >>> print(f"P = {state.pressure:.4f} E T / R, F = {state.extra['force_ETR']:.4f} E T R")
    P = 0.0870 E T / R, F = 0.1368 E T R
    >>> print(abs(state.volume - 4.0 * math.pi / 3.0) < 1e-9)
    True
    """
    fluid = as_fluid(fluid)
    problem, x = _descent(material, check_non_negative("pressure", pressure_initial),
                          check_positive("height", height), fluid, rtol)
    return problem.compressed(_UNIT, x, fluid)[0]


def _descent(material, pressure_initial, height, fluid, rtol) -> tuple[CapsuleProblem, np.ndarray]:
    """(the height-controlled problem at ``height``, its solved unknowns): ``capsule_at_height``'s route."""
    law = law_of(material)
    target = inflate(material, pressure_initial, geometry=CAPSULE, rtol=rtol)
    if height > target.height:
        raise above_the_pocket(height, target.height)
    anchor = inflate(material, ANCHOR, geometry=CAPSULE, rtol=rtol)

    def problem(inflated, at):
        return CapsuleProblem(inflated, rtol, law, fluid, height=at, reference=anchor)

    def sealed(pressure):  # the capsule inflated at Phat_I = pressure, at the fixed height H_d
        return problem(inflate(material, pressure, geometry=CAPSULE, rtol=rtol), deep)

    deep, (top, x) = min(height, H_DEEP), _touched(anchor, law, fluid, rtol)
    while True:  # the anchor pressed to H_d, then its fluid changed there; H_d halved where that march stalls
        x = _pressed(anchor, law, fluid, rtol, x, top, deep)
        reached, lowered = _march(sealed, x, ANCHOR, pressure_initial, _P_STEP, taut=True, smallest=_P_STALL)
        if reached == pressure_initial:
            break
        if deep <= _DEEPEST:
            raise ConvergenceError(f"capsule at height = {height!r}: the march in Phat_I from {ANCHOR} towards "
                                   f"{pressure_initial!r} at H/R = {deep!r} stalled at Phat_I = {reached:.10g}",
                                   load=reached)
        top, deep = deep, max(_DEEPEST, 0.5 * deep)
    x = lowered
    if height > deep:
        reached, x = _march(lambda h: problem(target, h), x, deep, height, _H_STEP, taut=True, smallest=_END_STEP)
        if reached != height:
            raise _lower_end(problem(target, reached), x, height, anchor)
    return problem(target, height), x


def _force(state: CompressedState) -> float:
    """The force on each plate of a capsule's ``state``: Fhat, or at P_I = 0 F / (E T R)."""
    return state.force if state.pressure_initial > 0.0 else float(state.extra["force_ETR"])


def branch_start(material: MaterialLike, pressure_initial: float, *, fluid: FluidLike = None,
                 rtol: float = 1e-10) -> tuple[float, float]:
    """Where the capsule's branch reached deep starts: (H*, the force there), its least compression and least
    force (Fhat, or at P_I = 0 F / (E T R)), H* located by the march up from H_d to within ``_END_STEP``.

    Most of the time of a state at a force (``capsule_at_force``): a curve of forces locates it once and passes it
    on.

    Examples
    --------
    >>> height, force = branch_start(0.0, 0.0)
    >>> print(f"H* = {height:.5f}, F = {force:.5f} E T R")
    H* = 0.79308, F = 0.06423 E T R
    """
    fluid = as_fluid(fluid)
    top = inflate(material, pressure_initial, geometry=CAPSULE, rtol=rtol).height
    try:
        capsule_at_height(material, pressure_initial, top, fluid=fluid, rtol=rtol)
    except OutOfRangeError as err:
        if err.bound is None:
            raise
        start = err.bound
    else:
        raise ConvergenceError(f"capsule at Phat_I = {pressure_initial!r}: a state at its inflated height on the "
                               "branch reached deep, which should start below it", load=top)
    return start, _force(capsule_at_height(material, pressure_initial, start, fluid=fluid, rtol=rtol))


def _touched(anchor, law, fluid, rtol) -> tuple[float, np.ndarray]:
    """(H/R, the unknowns of height control): the ``anchor`` capsule at Fhat = ``_FORCE``, by the force's
    continuation from its inflated state."""
    start = CapsuleProblem(anchor, rtol, law, fluid)
    force, x = first_state(start, _FORCE)
    top = -start.shoot(x, force)[1][1]
    x = x.copy()
    x[2] *= math.sqrt(force)  # c = a / sqrt(Fhat) -> a, the unknown of height control
    return top, x


def _pressed(anchor, law, fluid, rtol, x, top, deep) -> np.ndarray:
    """The unknowns of the ``anchor`` capsule (scaled by itself) pressed from H/R = ``top`` (its unknowns x) down to
    ``deep``, by the march in height."""
    reached, x = _march(lambda h: CapsuleProblem(anchor, rtol, law, fluid, height=h), x, top, deep, _H_STEP)
    if reached != deep:
        raise ConvergenceError(f"capsule at Phat_I = {ANCHOR}: the march in height from H/R = {top:.10g} towards "
                               f"{deep!r} stalled at H/R = {reached:.10g}", load=reached)
    return x


def _lower_end(problem, x, height, anchor) -> OutOfRangeError | ConvergenceError:
    """The error of a march up that stopped at ``problem``'s height with the unknowns x: an OutOfRangeError quoting
    H* where the edge's tension has vanished there (``_EDGE_SLACK``), else a ConvergenceError."""
    tension = problem.edge_tension(x, _UNIT)
    if tension <= _EDGE_SLACK * 0.5 * anchor.pressure * anchor.stretch_pole:
        start = f"height = {problem.height:.7g}"
        refusal = capsule_gap(f"height = {height!r}", start)
        refusal.end, refusal.bound = start, problem.height
        return refusal
    return ConvergenceError(f"{problem.label}: the march in height towards {height!r} stalled at H/R = "
                            f"{problem.height:.10g}, the contact edge's tension {tension:.3g} E T", load=problem.height)


def capsule_at_force(material: MaterialLike, pressure_initial: float, force: float, end: str | None = None, *,
                     fluid: FluidLike = None, rtol: float = 1e-10,
                     start: tuple[float, float] | None = None) -> CompressedState:
    """The capsule's state at the force ``force`` on its second branch: Fhat where Phat_I = ``pressure_initial``
    > 0, past the ``end`` of its first branch (as that branch's refusal words it, ``"force = ..."``); at P_I = 0,
    where Fhat is undefined and the second branch is the only one, F / (E T R) (``end`` None).

    On the second branch the force falls as the plates rise, to its least at the branch's start H*: a force below
    that lies between the branches (an OutOfRangeError quoting both ends, ``capsule_gap``); above it, its height is
    the root of F(H) - force by Brent's method (``pocket.shooting.brent``) between H* and a height halved from it
    until the force there exceeds the one asked, each F(H) a state of ``capsule_at_height``. The state returned is
    the one solved at the root: its force (``force``, or ``extra["force_ETR"]`` at P_I = 0) the one found, within
    the root's relative 1e-12 of ``force``. ``start``: the branch's start as ``branch_start`` gives it, where a
    curve of forces has located it already (else it is located here).

    Examples
    --------
    A neo-Hookean capsule at Phat_I = 0.01 ends its first branch at Fhat = 0.1495; at Fhat = 3 it lies deep:

    >>> state = capsule_at_force(0.0, 0.01, 3.0, "force = 0.1495")
    >>> print(f"{state.force:.10f}", f"{state.height:.4f}")
    3.0000000000 0.7665

    The uninflated capsule pressed by F = 0.5 E T R:

    >>> state = capsule_at_force(0.0, 0.0, 0.5)
    >>> print(f"{state.extra['force_ETR']:.10f}", f"{state.height:.4f}")
    0.5000000000 0.5583
    """
    name = "force" if pressure_initial > 0.0 else "force_ETR"
    highest, smallest = branch_start(material, pressure_initial, fluid=fluid, rtol=rtol) if start is None else start

    def excess(height):
        return _force(capsule_at_height(material, pressure_initial, height, fluid=fluid, rtol=rtol)) - force

    least = smallest - force
    if least > 0.0:
        raise capsule_gap(f"{name} = {force!r}", f"{name} = {smallest:.10g} (height = {highest:.10g})", end)
    low = 0.5 * highest
    while (above := excess(low)) < 0.0:
        if low < _DEEPEST * 0.5:
            raise ConvergenceError(f"capsule at Phat_I = {pressure_initial!r}: no state up to {name} = {force!r} down "
                                   f"to the plate height {low:.3g}", load=force)
        low *= 0.5
    height = brent.root(excess, low, highest, fa=above, fb=least, rtol=_FORCE_RTOL)
    return capsule_at_height(material, pressure_initial, height, fluid=fluid, rtol=rtol)
