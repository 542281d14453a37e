r"""Identify a rubber law's parameters from a user's tests of the clamped sheet: least squares on the model.

The unknowns are the coordinates of the law's keys not held fixed (``pocket.apps.fit.keys``: the values,
Ogden's terms in their shares of mu_0), scaled so that the problem is well conditioned: x_k =
coordinate_k / s_k with s_k the start's mu_0 (times T: ``pocket.apps.fit.model``) for a stress,
max(|start value|, 1) for a number. scipy's ``least_squares`` (trust region reflective, within the
keys' bounds) minimises (1/2) sum r_i(x)^2 over the residuals of ``pocket.apps.fit.model.residuals``.

Jacobian. The solvers resolve their states to ~1e-10 relative, so J is taken by forward differences
of step h = 1e-6 in x (truncation error O(h) ~ 1e-6, rounding O(1e-10 / h) ~ 1e-4 relative: ample
for a Gauss-Newton step and for the covariance). A forward step that leaves the bounds, or reaches
a trial set with a datum without state (a residual ``PENALTY``), is taken backward instead, so no
derivative is ever taken across the penalty.

Starts. Every start of ``pocket.apps.fit.start`` is evaluated once; those with a state for every datum
are ranked by cost. For the laws with many parameters (``PROBED``) and for a fitted prestretch (whose
starts are each shape at several prestretches, ``PRESTRETCHES``), the best ``RUNS`` each run ``_PROBE``
evaluations (enough to leave a start's neighbourhood and show its basin: a Yeoh or Ogden start can lead
into a valley or a local minimum where trust-region steps crawl) and the lowest of them runs on to
convergence on all the data; the other laws run from their best start. The starts are ranked and probed on
each test thinned to ``_SAMPLE`` rows spread over its range (a curve's shape, which decides the basin,
shows in ten points; a 30-point bulge test costs a third), and each run is capped at
``_MAX_EVALUATIONS`` evaluations (a fit that meets the cap says so). Bounds make trf's steps short near
them, so a law without finite bounds (Ogden) uses Levenberg-Marquardt. A result with any datum without
state is never reported: if no start has all its states, or the run ends outside the model's range, the
fit is a ``ConvergenceError`` saying so.

The statistics of the result are in ``pocket.apps.fit.stats``, its intervals by the profile likelihood in
``pocket.apps.fit.intervals`` (each trial of a profile a least-squares re-fit of the other unknowns with one held:
``_Profile``). ``search`` is the fit from its starts on, which a test of another kind shares
(``pocket.apps.fit.capsuletest``).
"""

from __future__ import annotations

import dataclasses
import math
import time
from collections.abc import Callable

import numpy as np

from pocket.core.errors import ConvergenceError, InputError
from pocket.core.materials import Material

from .checks import modulus_warnings
from .intervals import intervals
from .keys import PRESTRETCH, Key, Subject, key_named, keys
from .model import PENALTY, Setup, predict, residuals
from .start import starts
from .stats import Statistics, normal_inverse, statistics

__all__ = ["PRESTRETCHES", "PROBED", "RUNS", "Fit", "Problem", "fit", "free_keys", "search"]

#: starts probed (the best by their cost), for the laws ``PROBED``
RUNS = 4
#: the laws with many parameters, whose starts are probed; the others run from their best start
PROBED = ("yeoh", "ogden")
_STEP = 1e-6  # forward-difference step in the scaled unknowns (module docstring)
_TOL = 1e-8  # least_squares' ftol, xtol and gtol: the step at which the solvers' 1e-10 noise is not yet felt
_MAX_EVALUATIONS = 60  # least_squares' evaluations per run (each Jacobian costs p more)
_PROBE = 6  # evaluations each start runs before the best of them continues
_PROFILE_EVALUATIONS = 20  # least_squares' evaluations of each re-fit with a key held (``pocket.apps.fit.intervals``)
_PROFILE_TOL = 1e-5  # their tolerances: tau^2 = (RSS(theta) - RSS) / s^2 needs RSS(theta) to ~1e-3 relative
_SAMPLE = 10  # rows per test where starts are ranked and probed: enough to show a curve's shape and its basin
#: the prestretches each start shape is tried at when the prestretch is fitted (a slack sheet to a taut one)
PRESTRETCHES = (1.0, 1.05, 1.2)


@dataclasses.dataclass(frozen=True)
class Fit:
    r"""A fit's result (``fit``).

    Attributes
    ----------
    setup : Setup
        What was fitted (``pocket.apps.fit.model.Setup``).
    material : Material
        The fitted rubber, its stresses in the setup's unit: Pa, or N/m without a thickness.
    free : tuple of str
        The fitted keys' names.
    fixed : dict
        The keys held, name -> value.
    statistics : Statistics
        Standard errors, correlations, intervals (``pocket.apps.fit.stats.Statistics``).
    values : list
        The model's values at the data (as ``pocket.apps.fit.model.predict``).
    residuals : numpy.ndarray
        Shape (n,).
    calls : int
        The solver calls (the profile intervals' included).
    seconds : float
        The wall-clock time.
    starts : int
        The starts evaluated.
    penalised : int
        The trial sets of the least-squares runs with some datum without state (a profile's trials not counted).

    Examples
    --------
    A bulge test made by the model from a known neo-Hookean sheet, mu = 0.4 MPa, T = 1 mm, R = 20 mm:

    >>> import pathlib, tempfile
    >>> from pocket import shooting
    >>> from pocket.apps.fit.case import Request
    >>> from pocket.apps.fit.leastsquares import fit
    >>> from pocket.core.materials import Material
    >>> phats = [0.1, 0.2, 0.3, 0.4]
    >>> states = shooting.inflation_curve(Material("neo-hookean", {"mu": 1.0}), phats)
    >>> rows = [f"{p * 3 * 0.4e6 * 1e-3 / 0.02},{s.height * 0.02}" for p, s in zip(phats, states)]
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = pathlib.Path(folder) / "bulge.csv"
    ...     _ = path.write_text("pressure [Pa],height [m]\n" + "\n".join(rows) + "\n")
    ...     result = fit(Request((path,), "neo-hookean", 0.02, 1e-3).setup(), "neo-hookean")
    >>> print(result.free, result.residuals.shape, result.statistics.rms < 1e-6)
    ('mu',) (4,) True
    """

    setup: Setup
    material: Material
    free: tuple[str, ...]
    fixed: dict
    statistics: Statistics
    values: list
    residuals: np.ndarray
    calls: int
    seconds: float
    starts: int
    penalised: int

    def predicted(self, setup: Setup) -> list:
        """The fitted model's values at ``setup``'s data (``pocket.apps.fit.model.predict``): the figure's curves."""
        return predict(setup, self.material)[0]

    def law_keys(self) -> tuple[Key, ...]:
        """All keys of the fitted law (``pocket.apps.fit.keys.keys``): what the report reads each key's unit from."""
        return keys(self.material.law, len(self.material["mu"]) if self.material.law == "ogden" else 1)


class Problem:
    """The residual function of the scaled unknowns x, with its Jacobian and counters: ``values`` (the model at
    the data) and ``compare`` (the residuals) are those of ``pocket.apps.fit.model``; a test of another kind
    subclasses it (``pocket.apps.fit.capsuletest``)."""

    #: whether least_squares may stop on a small gradient (its gtol, absolute in the trust-region method): the
    #: relative residuals make the gradient's size the fit's; residuals of another scale turn it off
    gradient_test = True

    def __init__(self, setup: Setup, base: Subject, free: list[Key], scales: np.ndarray, count: dict):
        self.setup, self.base, self.free, self.scales, self.count = setup, base, free, scales, count
        self.lower = np.array([k.lower for k in free]) / scales
        self.upper = np.array([k.upper for k in free]) / scales
        self._last: tuple[bytes, np.ndarray, list] | None = None  # the last evaluation: x, r, the model's values
        self._jac: tuple[bytes, np.ndarray] | None = None  # the last Jacobian (least_squares' at its result)

    def x(self, material: Subject) -> np.ndarray:
        """The scaled unknowns of ``material``."""
        return np.array([k.coordinate(material) for k in self.free]) / self.scales

    def material(self, x) -> Subject:
        m = self.base
        for key, value in zip(self.free, np.asarray(x) * self.scales, strict=True):
            m = key.moved(m, value)
        return m

    def gradient(self, x) -> np.ndarray:
        """d(key values)/dx (p x p) at ``x``: diag(scales) where each key is its own coordinate, else by
        central differences of the keys' values (the coordinates are smooth closed forms: error ~1e-10)."""
        if all(k.unknown is None for k in self.free):
            return np.diag(self.scales)
        x = np.asarray(x, dtype=float)
        out = np.empty((x.size, x.size))
        for j in range(x.size):
            step = np.zeros(x.size)
            step[j] = 1e-6 * max(abs(x[j]), 1.0)
            up, down = self.material(x + step), self.material(x - step)
            out[:, j] = [(k.get(up) - k.get(down)) / (2.0 * step[j]) for k in self.free]
        return out

    def __call__(self, x) -> np.ndarray:
        return self.evaluate(x)[0]

    def values(self, material: Subject) -> tuple[list, int]:
        """The model's values at the data for the trial ``material`` and the solver calls made
        (``pocket.apps.fit.model.predict``)."""
        try:
            return predict(self.setup, material)
        except InputError:  # a Gent prestretch past the trial Jm's locking: outside the admissible set
            return predict(self.setup, None)  # no state anywhere, no solver called

    def compare(self, values: list) -> np.ndarray:
        """The residuals of the model's ``values`` (``pocket.apps.fit.model.residuals``), with ``PENALTY``
        where a datum has no state."""
        return residuals(self.setup, values)

    def evaluate(self, x) -> tuple[np.ndarray, list]:
        """The residuals at ``x`` and the model's values (``values``)."""
        x = np.asarray(x, dtype=float)
        if self._last is not None and self._last[0] == x.tobytes():
            return self._last[1], self._last[2]
        values, calls = self.values(self.material(x))
        r = self.compare(values)
        self.count["calls"] += calls
        self.count["penalised"] += bool(np.any(r == PENALTY))
        self._last = (x.tobytes(), r, values)
        return r, values

    def jacobian(self, x) -> np.ndarray:
        x = np.asarray(x, dtype=float)
        if self._jac is not None and self._jac[0] == x.tobytes():
            return self._jac[1]
        r0, values = self.evaluate(x)
        jac = np.empty((r0.size, x.size))
        for k in range(x.size):
            for h in (_STEP, -_STEP):
                step = x.copy()
                step[k] += h
                if not self.lower[k] <= step[k] <= self.upper[k]:
                    continue
                r = self(step)
                if not np.any(r == PENALTY):
                    break
            else:
                raise ConvergenceError(f"the fit's Jacobian: {self.free[k].name} can be moved neither up nor down "
                                       "by a relative 1e-6 without leaving the model's range")
            jac[:, k] = (r - r0) / h
        self._last, self._jac = (x.tobytes(), r0, values), (x.tobytes(), jac)
        return jac


def _fixed_material(material: Subject, fixed: dict, all_keys) -> Subject:
    for name, value in fixed.items():
        material = key_named(all_keys, name, "--fix").put(material, value)
    return material


def fit(setup: Setup, law: str, *, terms: int = 1, fixed: dict | None = None, start: dict | None = None,
        prestretch: bool = False) -> Fit:
    r"""Fit a rubber law to a user's tests of the clamped sheet, by nonlinear least squares on the solver.

    Parameters
    ----------
    setup : Setup
        The tests and the sheet (``pocket.apps.fit.model.Setup``; ``Request.setup``).
    law : str
        The law (``pocket.core.materials.LAWS``).
    terms : int, optional
        Ogden's terms.
    fixed : dict, optional
        Key -> value held (stresses in the setup's unit: Pa, or N/m without a thickness).
    start : dict, optional
        Key -> value that replaces the start's (for every start).
    prestretch : bool, optional
        Fit the clamped sheet's prestretch (key ``prestretch``); else it is held at 1, or at its value in
        ``fixed``.

    Returns
    -------
    Fit

    Raises
    ------
    InputError
        For fewer data than unknowns + 1, or an unknown key (before any solve).
    ConvergenceError
        If no start, or no result, has a state for every datum.

    Examples
    --------
    The sheet behind a bulge test made by the model (neo-Hookean, mu = 0.4 MPa, T = 1 mm, R = 20 mm) is
    recovered:

    >>> import pathlib, tempfile
    >>> from pocket import shooting
    >>> from pocket.apps.fit.case import Request
    >>> from pocket.apps.fit.leastsquares import fit
    >>> from pocket.core.materials import Material
    >>> phats = [0.1, 0.2, 0.3, 0.4]
    >>> states = shooting.inflation_curve(Material("neo-hookean", {"mu": 1.0}), phats)
    >>> rows = [f"{p * 3 * 0.4e6 * 1e-3 / 0.02},{s.height * 0.02}" for p, s in zip(phats, states)]
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = pathlib.Path(folder) / "bulge.csv"
    ...     _ = path.write_text("pressure [Pa],height [m]\n" + "\n".join(rows) + "\n")
    ...     result = fit(Request((path,), "neo-hookean", 0.02, 1e-3).setup(), "neo-hookean")
    >>> print(f"mu = {result.material['mu'] / 1e6:.6f} MPa")
    mu = 0.400000 MPa
    """
    clock = time.perf_counter()
    fixed, start = dict(fixed or {}), dict(start or {})
    all_keys = keys(law, terms)
    if prestretch and PRESTRETCH in fixed:
        raise InputError(f"--fix {PRESTRETCH}={fixed[PRESTRETCH]!r} holds the prestretch that --fit-prestretch "
                         "asks to fit: give one of them")
    if PRESTRETCH in fixed and not fixed[PRESTRETCH] >= 1.0:
        raise InputError(f"--fix {PRESTRETCH} = {fixed[PRESTRETCH]!r}, but a prestretch of the clamped sheet "
                         "must be >= 1")
    free = free_keys(setup, all_keys, fixed, start, () if prestretch else (PRESTRETCH,))
    prestretches = (fixed[PRESTRETCH],) if PRESTRETCH in fixed else (start[PRESTRETCH],) if PRESTRETCH in start \
        else PRESTRETCHES if prestretch else (1.0,)
    shapes = starts(setup, law, terms, prestretches)
    return search(setup, law, shapes, all_keys, free, fixed, start, law in PROBED or prestretch, scaled, clock)


def free_keys(setup: Setup, all_keys, fixed: dict, start: dict, held: tuple = ()) -> list[Key]:
    """The keys of ``all_keys`` a fit varies: those neither in ``fixed`` nor named in ``held``; an InputError for a
    key of ``fixed`` or ``start`` not among ``all_keys``, for no key left, or for fewer data than keys + 1."""
    for name in (*fixed, *start):
        key_named(all_keys, name, "--fix" if name in fixed else "start")
    free = [k for k in all_keys if k.name not in fixed and k.name not in held]
    if not free:
        raise InputError("--fix holds every parameter of the law: there is nothing left to fit")
    if setup.count <= len(free):
        raise InputError(f"{setup.count} data, but fitting {len(free)} parameters ({', '.join(k.name for k in free)}) "
                         f"needs at least {len(free) + 1}")
    return free


def search(setup: Setup, law: str, shapes, all_keys, free: list[Key], fixed: dict, start: dict, probed: bool,
           make: Callable[..., Problem], clock: float) -> Fit:
    """The least-squares fit of the keys ``free`` from the starts ``shapes`` (per shape, the trial sets to try in
    turn, the first with a state for every datum kept), each with the values of ``start`` and ``fixed`` put in
    (keys of ``all_keys``): the starts ranked, the best probed (``probed``) or run, its statistics and intervals
    (module docstring). ``make(setup, trial, free, count)`` is the scaled ``Problem`` of a trial set; ``clock``
    the ``time.perf_counter()`` the fit began at. The result's ``material`` is the trial set fitted."""
    ranked: list = []
    count, tried = {"calls": 0, "penalised": 0}, 0
    sample = _thinned(setup) if probed else setup  # where the starts are ranked and probed
    for shape in shapes:
        for material in shape:
            try:
                material = _fixed_material(_fixed_material(material, start, all_keys), fixed, all_keys)
            except InputError:  # a Gent start whose Jm the held prestretch exceeds: not a start
                continue
            if any(material == seen for _, seen in ranked):  # shapes made one by the values given
                break
            problem = make(sample, material, free, count)
            r = problem(problem.x(material))
            tried += 1
            if not np.any(r == PENALTY):
                ranked.append((float(r @ r), material))
                break
    if not ranked:
        raise ConvergenceError(f"no start of the {law} fit has a state for every datum (tried {tried}): the data "
                               "may lie beyond this law's range (a pressure maximum, a force past the range end)")
    ranked.sort(key=lambda pair: pair[0])
    count["penalised"] = 0  # from here on: trial sets of the runs (a start without all states is just skipped)
    probes = []
    for _, material in ranked[:RUNS if probed else 1]:  # each start a few steps, where its basin shows
        problem = make(sample, material, free, count)
        x, status, evaluations = run(problem, problem.x(material), _PROBE if probed else _MAX_EVALUATIONS)
        r = problem(x)
        if not np.any(r == PENALTY):
            probes.append((float(r @ r), x, problem, status, evaluations))
    if not probes:
        raise ConvergenceError(f"the {law} fit ended outside the model's range from every start")
    _, x, problem, status, evaluations = min(probes, key=lambda probe: probe[0])
    if probed:  # the best probe runs on, on all the data
        problem = type(problem)(setup, problem.base, problem.free, problem.scales, count)
        x, status, evaluations = run(problem, x, _MAX_EVALUATIONS)
    r, values = problem.evaluate(x)
    if np.any(r == PENALTY):
        raise ConvergenceError(f"the {law} fit ended outside the model's range")
    notes = [] if status > 0 else [f"the fit stopped after {evaluations} evaluations without meeting its "
                                   "tolerances: the parameters may be ill-determined"]
    notes += modulus_warnings(setup, problem.material(x).mu0)
    jac = problem.jacobian(x)
    material = problem.material(x)
    stats = statistics(setup, material, free, problem.gradient(x), r, jac)
    profile = _Profile(problem, x, float(r @ r) / stats.dof, normal_inverse(jac))
    stats = intervals(stats, free, profile)
    if notes:
        stats = dataclasses.replace(stats, warnings=(*notes, *stats.warnings))
    return Fit(setup, material, tuple(k.name for k in free), fixed, stats, values, r, count["calls"],
               time.perf_counter() - clock, tried, count["penalised"])


class _Profile:
    """The profile statistic (``pocket.apps.fit.intervals``) of the fit ``problem`` at its optimum ``x``, residual
    variance ``s2`` and (J^T J)^-1 ``inverse``: called with a key's index k, the function held value -> tau^2.
    Each held value re-fits the other unknowns from the nearest held value already solved, moved along their
    regression on the held one, inverse[:, k] / inverse[k, k] (the linearised conditional optimum)."""

    def __init__(self, problem: Problem, x, s2: float, inverse):
        self.problem, self.x, self.s2, self.inverse = problem, x, s2, inverse
        self.rss, self.base = float(problem(x) @ problem(x)), problem.material(x)

    def __call__(self, k: int):
        solved = {self.x[k]: np.delete(self.x, k)}  # held x_k -> the others' optimum
        return lambda value: self._tau2(k, value, solved)

    def _tau2(self, k: int, value: float, solved: dict) -> float:
        p, others = self.problem, [j for j in range(self.x.size) if j != k]
        count = {"calls": 0, "penalised": 0}  # a profile reaches past the model's range by design: not counted
        sub = type(p)(p.setup, p.free[k].put(self.base, value), [p.free[j] for j in others], p.scales[others],
                       count)
        held = value / p.scales[k]
        near = min(solved, key=lambda h: abs(h - held))
        start = solved[near] + self.inverse[others, k] / self.inverse[k, k] * (held - near)
        try:
            if np.any(sub(start) == PENALTY):  # the shift left the model's range: the nearest optimum instead
                start = solved[near]
            xo = run(sub, start, _PROFILE_EVALUATIONS, _PROFILE_TOL)[0] if others else start
            r = sub(xo)
        except ConvergenceError:  # no state on either side of the start: no re-fit from here
            return math.inf
        finally:
            p.count["calls"] += count["calls"]
        if np.any(r == PENALTY):
            return math.inf
        solved[held] = xo
        return (float(r @ r) - self.rss) / self.s2


def _thinned(setup: Setup) -> Setup:
    """``setup`` with each test thinned to at most ``_SAMPLE`` rows spread over its range (first and last kept)."""
    tests = []
    for test in setup.tests:
        n = test.control.size
        keep = np.unique(np.round(np.linspace(0, n - 1, min(n, _SAMPLE))).astype(int))
        tests.append(dataclasses.replace(test, control=test.control[keep],
                                         responses={k: v[keep] for k, v in test.responses.items()}))
    return dataclasses.replace(setup, tests=tuple(tests))


def run(problem: Problem, x, budget: int, tol: float = _TOL) -> tuple[np.ndarray, int, int]:
    """least_squares from ``x`` for at most ``budget`` evaluations, to ``tol`` (its ftol, xtol and gtol): (x, its
    status, evaluations)."""
    from scipy.optimize import least_squares

    bounded = np.any(np.isfinite(problem.lower)) or np.any(np.isfinite(problem.upper))
    gtol = tol if problem.gradient_test or not bounded else None  # Levenberg-Marquardt's is a cosine: scale-free
    out = least_squares(problem, np.clip(x, problem.lower, problem.upper), jac=problem.jacobian,
                        bounds=(problem.lower, problem.upper), method="trf" if bounded else "lm", ftol=tol,
                        xtol=tol, gtol=gtol, max_nfev=budget)
    return out.x, out.status, out.nfev


def scaled(setup: Setup, material: Material, free: list[Key], count: dict) -> Problem:
    """The ``Problem`` of ``material``'s keys ``free``, each scaled (module docstring)."""
    mu0 = abs(material.mu0)
    scales = np.array([mu0 if k.unit == "stress" else max(abs(k.coordinate(material)), 1.0) for k in free])
    if not np.all(np.isfinite(scales)) or not np.all(scales > 0.0) or not math.isfinite(mu0):
        raise ConvergenceError("the fit's start has no finite positive mu_0")
    return Problem(setup, material, free, scales, count)
