"""A compiled Dormand-Prince 8(5,3) integrator for the membrane equations.

It is scipy's ``DOP853`` (the same tableau, stored in ``pocket.shooting.tableau``; the same
error norm and step-size control as ``scipy/integrate/_ivp/rk.py``), compiled with
numba and specialised to ``pocket.shooting.equations.rhs``: a shooting solve calls it
thousands of times, and the Python version costs about 100x more per call
(``benchmarks/bench_shooting.py``). ``tests/test_shooting_integrator.py`` checks it
against ``solve_ivp(method="DOP853")``. The absolute tolerance may differ per
component, so that small quantities (the height and angle of a shallow dome, its
volume) are resolved relative to their own size. Given a grid of points, it returns the state there by each
step's dense output, DOP853's 7th-order interpolant (three more evaluations of the equations in a step that holds
a point), instead of storing its steps: a profile at any resolution for about the cost of the shot itself, whose
steps the grid does not change.

Integration stops early, with a status, where the membrane model stops making
sense: the meridian reaches the axis (rho <= 0), its angle leaves (-pi/2, psi_max)
(curled back past the horizontal, or turned up into the sheet), or the meridional
tension vanishes (t1 <= 0, wrinkling), or the stretches leave the law's domain (Gent's
locking, I1 - 3 >= Jm); or where the integration itself fails (too many steps, a step
below the resolution of r). The law enters as its kernel code and parameters
(``pocket.shooting.tensions``), passed on to ``rhs``.

Wrinkling, and why SLACK is a status and not a state. With T_1 = 0 normal
equilibrium, psi' = lambda_1 (p - t2 sin(psi) / rho) / t1, has no finite solution
under pressure, and a compressive T_1 would wrinkle the sheet radially: a tension-field
membrane, outside this model. So a shot that goes slack is a trial outside the
model's domain, which the root finders step back from (inflation reads it as too
much pressure for the pole stretch; Newton halves its step), and a solve that cannot
get past it fails with a ConvergenceError naming it (``Contact.failure``). Every
returned state comes from a final shot that reached the clamp with t1 > 0 at each
step. A compressive T_2 does not stop the equations (t2 is only a load in them):
such a state would be returned, flagged ``wrinkled`` with a warning (its smallest
tensions from ``shots.tension_minima``). None was found: over Mooney-Rivlin alpha
in [-0.95, 5] up to the pressure maximum and the range end, a softening Yeoh, Ogden
with negative exponents and Gent near locking, liquid and gas, T_2 stayed positive,
smallest at the clamp, where lambda_2 = 1 and T_2 > 0 for lambda_1 > 1 for every
stable law; for alpha < 0 Mooney-Rivlin needs 1 + alpha lambda_1^2 > 0 there, and the
first branch ends first (alpha = -0.5: lambda_1(1) <= 1.11 < 1/sqrt(0.5)).
"""

from __future__ import annotations

import functools

import numpy as np

from pocket.core.compiled import compiled

from . import tableau
from .equations import derivatives, reference
from .tensions import inside_compiled, tensions_compiled

__all__ = ["AXIS", "FOLD", "LOCKED", "NUMERICAL", "OK", "SLACK", "SMALL_STEP", "STATUS", "STEPS", "integrate"]

OK, AXIS, FOLD, SLACK, STEPS, SMALL_STEP, LOCKED = 0, 1, 2, 3, 4, 5, 6
STATUS = {
    OK: "reached the clamp",
    AXIS: "the meridian reached the axis (rho <= 0)",
    FOLD: "the meridian folded (its angle psi left (-pi/2, psi_max))",
    SLACK: "the meridional tension vanished (t1 <= 0)",
    STEPS: "too many steps",
    SMALL_STEP: "step size underflow",
    LOCKED: "the stretches reached the law's locking limit (I1 - 3 >= Jm)",
}

#: the failures of the integration itself, as opposed to a meridian outside the model
NUMERICAL = (STEPS, SMALL_STEP)

_NS = tableau.N_STAGES
_LANDING = 1e-13  # a step ends on a knot when within this of it (units R); a slip of that size is harmless
_EXPONENT = -1.0 / 8.0
_NO_GRID = np.empty(0)  # (and no knots: the compiled loop only reads these)
_NO_TABLE = (np.empty(0), np.empty((4, 0)))
_NO_STEPS = np.empty((0, 6))


@functools.partial(compiled, inline="always")
def _status(y, code, params, r, psi_max, sphere, slack):
    l2 = y[0] / reference(r, sphere)[0]
    if not (y[0] > 0.0):
        return AXIS
    if not (-0.5 * np.pi < y[2] < psi_max):
        return FOLD
    if not (y[3] > 0.0):
        return SLACK
    if not inside_compiled(y[3], l2, code, params):
        return LOCKED
    if not slack and not (tensions_compiled(y[3], l2, code, params)[0] > 0.0):
        return SLACK
    return OK


@functools.partial(compiled, inline="always")
def _interpolant(K, y, ynew, r, hh, code, params, p, wrap, breaks, coef, sphere, AX, CX, D, terms):
    """The step's 7th-order interpolant (scipy's ``Dop853DenseOutput``) into ``terms`` (shape (7, n)): the three
    more stages into K[13:] first."""
    n = y.size
    ytmp = np.empty(n)
    for s in range(_NS + 1, _NS + 4):
        for i in range(n):
            acc = 0.0
            for j in range(s):
                acc += AX[s - _NS - 1, j] * K[j, i]
            ytmp[i] = y[i] + hh * acc
        derivatives(r + CX[s - _NS - 1] * hh, ytmp, code, params, p, wrap, breaks, coef, sphere, K[s])
    for i in range(n):
        delta = ynew[i] - y[i]
        terms[0, i] = delta
        terms[1, i] = hh * K[0, i] - delta
        terms[2, i] = 2.0 * delta - hh * (K[_NS, i] + K[0, i])
        for m in range(4):
            acc = 0.0
            for j in range(_NS + 4):
                acc += D[m, j] * K[j, i]
            terms[3 + m, i] = hh * acc


@functools.partial(compiled, inline="always")
def _dense(terms, y, x, out):
    """Write y_old + the interpolant ``terms`` at x = (r - r_old) / h into ``out``: Horner's scheme in x and
    1 - x alternately, from the highest term (scipy's ``Dop853DenseOutput._call_impl``)."""
    for i in range(y.size):
        acc = 0.0
        for m in range(6, -1, -1):
            acc += terms[m, i]
            acc *= x if m % 2 == 0 else 1.0 - x
        out[i] = y[i] + acc


@compiled
def _integrate(y0, r0, r1, code, params, p, wrap, breaks, coef, knots, rtol, atol, h0, hmax, psi_max, sphere, slack,
               store, grid, A, B, C, E3, E5, AX, CX, D):
    n = y0.size
    K = np.empty((_NS + 4, n))
    terms = np.empty((7, n))
    y = y0.copy()
    ynew = np.empty(n)
    ytmp = np.empty(n)
    f = np.empty(n)
    derivatives(r0, y, code, params, p, wrap, breaks, coef, sphere, f)
    r = r0
    k = 0  # the next knot ahead (``integrate``)
    while k < knots.size and knots[k] <= y[0] + _LANDING:
        k += 1
    h = h0
    nstore = 0
    g = 0  # the next point of ``grid`` ahead
    while g < grid.size and grid[g] <= r:
        store[g, 0] = grid[g]
        store[g, 1:] = y
        g += 1
    nstore = g
    if store.shape[0] > 0 and grid.size == 0:
        store[0, 0] = r
        store[0, 1:] = y
        nstore = 1
    maxsteps = 100000 if store.shape[0] == 0 or grid.size > 0 else store.shape[0] - 1
    for _ in range(maxsteps):
        if r >= r1:
            return OK, r, y, nstore
        rejected = False
        while True:
            min_step = 10.0 * (np.nextafter(r, np.inf) - r)
            if h < min_step:
                return SMALL_STEP, r, y, nstore
            h = min(h, hmax)
            rnew = min(r + h, r1)
            hh = rnew - r
            K[0, :] = f
            for s in range(1, _NS):
                for i in range(n):
                    acc = 0.0
                    for j in range(s):
                        acc += A[s, j] * K[j, i]
                    ytmp[i] = y[i] + hh * acc
                derivatives(r + C[s] * hh, ytmp, code, params, p, wrap, breaks, coef, sphere, K[s])
            for i in range(n):
                acc = 0.0
                for j in range(_NS):
                    acc += B[j] * K[j, i]
                ynew[i] = y[i] + hh * acc
            derivatives(rnew, ynew, code, params, p, wrap, breaks, coef, sphere, K[_NS])
            e5 = 0.0
            e3 = 0.0
            for i in range(n):
                scale = atol[i] + max(abs(y[i]), abs(ynew[i])) * rtol
                a5 = 0.0
                a3 = 0.0
                for j in range(_NS + 1):
                    a5 += K[j, i] * E5[j]
                    a3 += K[j, i] * E3[j]
                e5 += (a5 / scale) ** 2
                e3 += (a3 / scale) ** 2
            err = 0.0 if e5 == 0.0 and e3 == 0.0 else hh * e5 / np.sqrt((e5 + 0.01 * e3) * n)
            if err < 1.0 and np.isfinite(err) and k < knots.size and ynew[0] > knots[k] + _LANDING > y[0]:
                h = hh * (knots[k] - y[0]) / (ynew[0] - y[0])  # a knot inside the step: end it there instead
                continue
            if err < 1.0 and np.isfinite(err):
                factor = 10.0 if err == 0.0 else min(10.0, 0.9 * err**_EXPONENT)
                if rejected:
                    factor = min(1.0, factor)
                h = hh * factor if rnew < r1 else h
                break
            factor = 0.2 if not np.isfinite(err) else max(0.2, 0.9 * err**_EXPONENT)
            h = hh * factor
            rejected = True
        if g < grid.size and grid[g] <= rnew:
            _interpolant(K, y, ynew, r, hh, code, params, p, wrap, breaks, coef, sphere, AX, CX, D, terms)
        while g < grid.size and grid[g] <= rnew:
            store[g, 0] = grid[g]
            _dense(terms, y, (grid[g] - r) / hh, store[g, 1:])
            g += 1
        nstore = max(nstore, g)
        r = rnew
        y[:] = ynew
        f[:] = K[_NS]
        while k < knots.size and knots[k] <= y[0] + _LANDING:
            k += 1
        if nstore > 0 and grid.size == 0:
            store[nstore, 0] = r
            store[nstore, 1:] = y
            nstore += 1
        status = _status(y, code, params, r, psi_max, sphere, slack)
        if status != OK:
            return status, r, y, nstore
    return STEPS, r, y, nstore


def integrate(y0, r0, law, p, *, rtol, atol=None, store=0, h0=None, max_step=np.inf, psi_max=np.pi, r_end=1.0,
              wrap=0.0, table=None, sphere=False, slack=False, grid=None):
    """Integrate the membrane equations from r0 to ``r_end`` (the clamp r = 1 unless given).

    y0: state [rho, eta, psi, lambda_1, v] at r0, shape (5,). law: a ``pocket.shooting.laws.Law``.
    p: pressure in units of tau T / R (``Law.pressure_factor`` Phat). rtol: DOP853 relative tolerance; atol: absolute
    tolerance, a float or one per component, shape (5,) (default rtol / 100). store: if > 0,
    keep every accepted step, up to ``store`` points. h0: first step (default: a hundredth
    of r0, or 1e-6). max_step: largest step in r (a finer profile; accuracy is set by rtol).
    psi_max: the meridian angle at which the meridian counts as folded (status FOLD). wrap: 0 for the
    free sheet, or the curvature 1/R_s (units 1/R) of a sphere the sheet lies on (``equations.derivatives``);
    on a sphere, psi reaching -pi/2 is the sheet reaching its equator (status FOLD). table: None, or the
    spline (breakpoints in s = rho^2, coefficients) of a profile table the sheet lies on
    (``pocket.core.profiles.Shape.pieces``, ``equations.table_curvature``). Its curvature's slope jumps at
    each row rho_k = sqrt(s_k): an 8th-order step across one is only 2nd-order accurate with an error its
    estimate does not see, so a step that would cross a row is shortened to end on it (secant in rho,
    within ``_LANDING``) and the next starts there, on the row's own piece. sphere: the reference surface is
    the unit sphere (a capsule, r0 = sin r: ``equations.reference``) rather than the flat disc (r0 = r). slack: a
    vanishing or compressive t1 does not stop the integration (a flat contact zone on a plate, p = 0 and psi = 0:
    no equation divides by t1 there; such a state is flagged wrinkled, ``pocket.core.states``).

    grid: None, or increasing points r (shape (m,)) at which to return the state instead of at the steps: by the
    steps' dense output (DOP853's 7th-order interpolant, Hairer's CONTD8, as scipy's ``dense_output``; three
    more evaluations of the equations in each step holding a point, none in the others), with the steps the
    shot takes without it (so its y_end is the same); points at or before r0 get y0.

    Returns (status, r_end, y_end, steps) where steps has shape (m, 6) with
    columns [r, rho, eta, psi, lambda_1, v] (empty unless ``store`` or ``grid``; with ``grid``, its points
    reached).
    """
    atol = np.asarray(rtol * 1e-2 if atol is None else atol, dtype=float)
    if atol.shape != (5,):  # a float for every component (the compiled loop only reads it)
        atol = np.full(5, atol)
    h0 = max(1e-2 * r0, 1e-6) if h0 is None else h0
    grid = _NO_GRID if grid is None else np.asarray(grid, dtype=float)
    buf = np.empty((grid.size, 6)) if grid.size else np.empty((store, 6)) if store else _NO_STEPS
    breaks, coef = _NO_TABLE if table is None else table
    status, r_end, y_end, m = _integrate(
        np.asarray(y0, dtype=float), float(r0), float(r_end), law.code, law.params, float(p), float(wrap),
        breaks, coef, _NO_GRID if table is None else np.sqrt(breaks), float(rtol), atol,
        float(h0), float(max_step), float(psi_max), bool(sphere), bool(slack), buf, grid, tableau.A, tableau.B,
        tableau.C, tableau.E3, tableau.E5, tableau.A_EXTRA, tableau.C_EXTRA, tableau.D,
    )
    return int(status), float(r_end), y_end, buf[:m]
