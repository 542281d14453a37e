"""Newton's method on the bordered equations (``equations``), and the contact's active set around it.

Converged when the largest displacement increment is below ``tol`` (units R): Newton converges
quadratically here, so the last increment bounds the error. The active set (``contact``)
is updated between Newton solves: a node whose force lambda_k < 0 leaves it, a free node inside the
indenter (its gap g_k < 0, ``contact``) joins it, until neither happens.

Where it fails. Newton is not globalised (no line search, no arc length): the one failure measured along a load
path is not one a globalisation of the same equations can pass. Pressing a Mooney-Rivlin pocket (alpha = 0.3,
Phat_I = 0.3, T/R = 0.0125, 64 x 4 elements, measured before the mesh followed the contact edge) towards
Fhat = 9, with the contact's active set fixed at its 73
nodes, the discrete path turns at Fhat = 5.43283: the smallest singular value of the tangent falls as
sqrt(F* - F) (4.6e-8 at Fhat = 5.432, 2.6e-8 at 5.4326: F* = 5.4329), its singular vector the pressure at the
clamp's upper corner and the radial displacement of the corner element's inner edge (``mesh``: that element then
has det F from 0.04 to 2.7 at its quadrature points, its smallest stretch 0.07). Followed by arc length the path
turns back in force and in the plate's height at once (a snap-back) and runs down to Fhat = 1.87 before it rises
again with the corner folded otherwise (its active set held, the plate 1 % lower at the same force). Newton at
any force beyond F* wanders there (steps of 2e-5 to 1e-4 R that do not fall, the corner's radial displacement
between 0.70 and 0.71 T), and so do its globalisations, with no root nearby to converge to: damped by
Deuflhard's natural monotonicity test its damping fell below 1e-3, pseudo-transient continuation oscillated for
200 iterations; under height control likewise. A march that fails so says where it stopped (``compression``);
the corner's elements set where the path turns (``mesh``): on the default 24 x 4 with the contact edge followed
the march stops at Fhat = 5.4302 (on 16 x 4 earlier, at 5.01, where an iterate inverts an element though the
path goes on: a force 1e-2 beyond solves by another path of steps).
All this without the clamp's upper jaw (``clamp_radius = 0``). With it (``jaw``, the default) the corner's node
cannot move past r = 1 above the sheet: the same pocket, its upper surface wrapped around a jaw's edge of radius
T/2 or T, reaches Fhat = 9 at every corner mesh from 1 T to T/16.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import scipy.sparse.linalg as spl

from pocket.core.errors import ConvergenceError

from .contact import gaps
from .equations import Control, system
from .jaw import updated
from .model import Model

__all__ = ["MAX_ITERATIONS", "MAX_SWEEPS", "SWEEP_STEP", "SWEEP_TOL", "contact", "solve"]

MAX_ITERATIONS = 25
#: active-set updates before giving up
MAX_SWEEPS = 60
#: how far inside the indenter (above the plate: a gap below minus this) a free node must be to join the
#: active set (units R)
SWEEP_TOL = 1e-7
#: Newton's tolerance while the active set changes (units R): the last step below 1e-3 R leaves an error
#: ~1e-6 R (quadratic convergence), enough to choose the next set; each set that holds is then solved to the
#: tolerance and checked again. Measured on the 10-force headline curve: 203 Newton iterations at 1e-7,
#: 158 at 1e-4, 136 at 1e-3, the same states to 1e-15.
SWEEP_STEP = 1e-3
#: the scale of the bordered unknowns (p_f, h, lambda) in the linear solve. Their rows (the contact's entries
#: 1, the fluid's V') would otherwise win SuperLU's partial-pivoting choices over the rubber's small entries
#: (the pressure's are ~ an element's volume) and break the fill-reducing order, which eliminates the dense
#: border last. Exact: D J D (D^-1 step) = D R. Measured on the headline pocket (64 x 2 elements, 20 contact
#: nodes): L + U hold 72k nonzeros instead of 387k, the solve takes a quarter of the time; scales 1e-6 and
#: 1e-10 change neither.
BORDER_SCALE = 1e-3
#: SuperLU's column order. COLAMD, not the minimum degree on J + J^T: the same steps (to 1e-13 in the states),
#: and on the solid's larger or thicker meshes far less fill. Measured curves, 2 cores: sample 4's pocket (T/R =
#: 0.08, Fhat 0.08 to 0.32) on 96 x 4 elements 2.3 s instead of 11.2 s (L + U 0.34 M nonzeros instead of 2.1 M),
#: on 48 x 8 with corner elements T/8 6.4 s instead of 11.6 s; the headline pocket on 48 x 8 11.5 s instead of
#: 27.9 s; on the default mesh the headline curve 1.83 s instead of 1.73 s.
ORDERING = "COLAMD"


def solve(model: Model, y: np.ndarray, control: Control, tol: float) -> tuple[np.ndarray, int]:
    """The state solving the equations of ``control`` from the guess ``y``; (y, iterations). A
    ConvergenceError if Newton does not converge."""
    y = y.copy()
    n = model.basis_u.N
    for iteration in range(1, MAX_ITERATIONS + 1):
        res, jac, keep = system(model, y, control)
        if not np.all(np.isfinite(res)):  # an iterate with J <= 0 somewhere: the isochoric invariants fail
            raise ConvergenceError("an iterate turned an element inside out (det F <= 0)", iterations=iteration)
        try:
            step = _linear_solve(jac, res, np.where(keep < model.size, 1.0, BORDER_SCALE))
        except RuntimeError as err:  # a singular factor
            raise ConvergenceError(f"singular tangent: {err}", iterations=iteration) from err
        if not np.all(np.isfinite(step)):
            raise ConvergenceError("singular tangent", iterations=iteration, residual=float(np.abs(res).max()))
        y[keep] -= step
        du = np.abs(step[keep < n]).max()
        if du < tol:
            return y, iteration
        if du > 1.0:  # a step longer than the sheet: diverging
            break
    raise ConvergenceError(f"Newton did not converge in {iteration} iterations (last displacement step "
                           f"{du:.3g} R)", iterations=iteration, residual=float(np.abs(res).max()))


def _linear_solve(jac, res: np.ndarray, scale: np.ndarray) -> np.ndarray:
    """The Newton step J^-1 R, solved as D J D x = D R with D = diag(``scale``) (``BORDER_SCALE``)."""
    jac = jac.tocsc(copy=True)
    jac.data *= scale[jac.indices] * np.repeat(scale, np.diff(jac.indptr))  # row scale times column scale
    return scale * spl.spsolve(jac, scale * res, permc_spec=ORDERING)


def _is_disc(nodes: np.ndarray) -> bool:
    """Whether the upper-surface nodes ``nodes`` (sorted) are a disc: 1 .. n - 1, with or without the pole's."""
    return bool(np.array_equal(nodes[nodes > 0], np.arange(1, nodes.max() + 1)))


@dataclasses.dataclass
class _Bracket:
    """The search for a disc's edge (``_bisect``): the largest disc edge known too small (``low``), the smallest
    known too large (``high``, None: none yet), and the updates of the set made so far."""

    low: int = 0
    high: int | None = None
    updates: int = 0


def _bisect(active: np.ndarray, new: np.ndarray, joining: np.ndarray, all_pressing: bool, bracket: _Bracket):
    """The next active set: the disc of the nodes before n, n halfway in ``bracket`` (updated here if the set
    ``active`` just solved is a disc: too small if a node beyond its edge is above the plate, too large if none is
    and a force in it other than the pole's is negative), while the bracket leaves an edge inside it; else the
    rules' set ``new``. The first update takes the rules' set if it is a disc inside the bracket: from a good guess
    (a state carried to the next load with the edge it is predicted to have, ``edgemesh.ahead``) it is the next
    node or two, where a halving would go far back. A disc is the nodes 1 .. n - 1 with or without the pole's
    (whose consistent force, at r = 0, is zero to the discretisation: it may leave), which keeps its place in
    ``new``; the disc of one node is the pole's. The bracket only closes in, so the bisection ends."""
    if _is_disc(active):
        edge = active.max() + 1
        if joining.size and joining.max() >= edge:
            bracket.low = max(bracket.low, edge)
        elif not all_pressing:
            bracket.high = edge if bracket.high is None else min(bracket.high, edge)
    bracket.updates += 1
    if bracket.high is None or bracket.high - bracket.low < 2:
        return new
    if bracket.updates == 1 and _is_disc(new) and bracket.low < new.max() + 1 < bracket.high:
        return new
    disc = np.union1d(new[:1][new[:1] == 0], np.arange(1, (bracket.low + bracket.high) // 2))
    return disc if disc.size else np.zeros(1, dtype=int)


def contact(model: Model, y: np.ndarray, control: Control, tol: float) -> tuple[np.ndarray, Control, int]:
    """The state in contact with the plate and its active set, from the guess ``y`` whose contact forces are
    those of ``control.active``; (y, control with the final active set, Newton iterations).

    While the set changes, Newton stops at ``SWEEP_STEP``; a set that holds there is solved to ``tol`` and
    checked again, so the set returned is the one the converged state satisfies. Every node with a negative
    force leaves at once (but one, the pole's, if all would), every node inside the indenter (above the plate)
    joins. The contact of a flat plate, a sphere or a convex profile is a disc: while the sets tried are the
    first n nodes from the pole, n is bisected between the largest set found too small (a node beyond it inside the
    indenter) and the smallest found too large (a negative force in it), instead of the one or two nodes the
    rules above remove per update after an overshoot (``_bisect``); ``control.known`` nodes from the pole, if
    given, are taken as touching (the bisection's lower end: a wrong hint only ends the bisection early, the rules
    then settle the set). The clamp's upper jaw's set, if ``control``
    has one (``jaw``), is updated alongside by the same rules (without the bisection), and settled alone when
    there is no indenter (``control.active`` None: inflation). A node joins the jaw's set once it is
    ``SWEEP_TOL`` inside, whatever ``tol``: the inflation path's loosely solved states (``inflation.PATH_TOL``,
    1e-3 R, 8 % of T at T/R = 0.0125) would otherwise let the corner's nodes sink that far into the jaw, which
    folds short corner elements; the indenter's threshold is ``tol`` where it is looser (its states are solved to
    the caller's).
    """
    total, loose = 0, max(tol, SWEEP_TOL)
    bracket, step = _Bracket(low=max(control.known - 1, 0)), max(tol, SWEEP_STEP)
    for sweep in range(MAX_SWEEPS):
        y, iterations = solve(model, y, control, step if sweep < MAX_SWEEPS - 1 else tol)
        total += iterations
        held = None if control.jaw is None else updated(model, y, control.jaw, SWEEP_TOL)
        moved = None if control.active is None else _indenter(model, y, control, loose, bracket)
        if moved is None and held is None:
            if step <= tol:
                return y, dataclasses.replace(control, known=0), total
            step = tol  # the set holds: Newton to the tolerance, and the set checked once more there
            continue
        step = max(tol, SWEEP_STEP)
        if moved is not None:
            y, control = moved
        if held is not None:
            control = dataclasses.replace(control, jaw=held)
    raise ConvergenceError(f"the contact's active set did not settle in {MAX_SWEEPS} updates")


def _indenter(model: Model, y: np.ndarray, control: Control, loose: float, bracket: _Bracket):
    """The state and control with the indenter's next active set (``contact``'s rules, ``_bisect``), or None
    if the set of ``control`` holds at y."""
    size = model.size
    active = np.asarray(control.active)
    lam = y[size + 2:size + 2 + active.size]
    gap = gaps(model, control.surface, y)
    keep = lam >= 0.0
    if not keep.any():
        keep[np.argmax(lam)] = True
    joining = np.setdiff1d(np.flatnonzero(gap < -loose), active)
    if keep.all() and joining.size == 0:
        return None
    new = _bisect(active, np.union1d(active[keep], joining), joining, bool(keep[active > 0].all()), bracket)
    forces = dict(zip(active[keep], lam[keep], strict=True))
    y = np.concatenate([y[:size + 2], [forces.get(k, 0.0) for k in new], y[size + 2 + active.size:]])
    return y, dataclasses.replace(control, active=new)
