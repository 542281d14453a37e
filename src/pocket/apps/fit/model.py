r"""The model's values at a fit's data, and the residuals that compare them.

Units. The membrane model sees the rubber only through its tension scale mu_0 T: with E = 3 mu_0,

    Phat = P R / (E T),   Fhat = F / (P_I pi R^2),   H = (H/R) R,   V = (V/R^3) R^3,

and the shape of the law (its stresses divided by mu_0). So a material here holds its stresses in
Pa when the thickness T is known, and the products stress * T in N/m when it is not (``Setup.scale``
is then 1 m): the same numbers enter the model either way.

Each datum is solved by the chosen solver (``pocket.apps.solvers``): an inflation test's pressures as one
march along the first branch where the solver serves ``inflation_curve`` (else, and where that march
fails or meets a pressure above the maximum, one by one), a compression test's forces as one curve
(continuation). A datum the model
has no state for at this trial set (``OutOfRangeError``: a pressure above the first branch's
maximum, a force past the end of the range, a rubber that locks first; or a ``ConvergenceError``)
gets NaN; so do all data of a trial set outside the law's admissible set. Pressures of an inflation
test increase, so once one is above the maximum the higher ones are too and are not solved.

Residuals. Column by column, a datum d with model value m gives (m - d) / |d| (relative: the
default) or (m - d) / sigma with the column's stated uncertainty sigma (same unit). A datum with no
state gives ``PENALTY``: finite, far above any residual of a trial set that has all its states
(relative residuals are O(1); residuals in units of a stated uncertainty reach it only at a start a
million uncertainties off), so the trust-region step that reached it is rejected and its radius
shrinks (scipy's ``least_squares`` compares costs: a larger one halves the step until it is back in
the model's range). The penalty is constant: the fit never differentiates across it
(``pocket.apps.fit.leastsquares`` takes a one-sided difference away from it).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from typing import TypeGuard

import numpy as np

from pocket.core.errors import ConvergenceError, InputError, OutOfRangeError
from pocket.core.materials import Material, check

from ..solvers import entry, record
from .data import Dataset

__all__ = ["PENALTY", "Setup", "admissible", "compressed", "missing", "predict", "residuals"]

#: the residual of a datum with no state (module docstring)
PENALTY = 1e6
_MISSED = (OutOfRangeError, ConvergenceError)


@dataclasses.dataclass(frozen=True)
class Setup:
    """What the fit compares: ``tests`` (``pocket.apps.fit.data.Dataset``), the clamp ``radius`` R (m), the
    ``thickness`` T (m, or None: stresses are then fitted as products with T, in N/m), the ``solver`` by
    name with its ``options``, and ``sigma`` (column name -> stated uncertainty, SI; a column not named
    has relative residuals)."""

    tests: tuple[Dataset, ...]
    radius: float
    thickness: float | None = None
    solver: str = "shooting"
    options: dict = dataclasses.field(default_factory=dict)
    sigma: dict = dataclasses.field(default_factory=dict)

    @property
    def scale(self) -> float:
        """The length the material's stresses are multiplied by to give tensions: T, or 1 m without T."""
        return 1.0 if self.thickness is None else self.thickness

    def tension(self, material: Material) -> float:
        """E T = 3 mu_0 T in N/m of ``material`` (its stresses in this setup's unit)."""
        return 3.0 * material.mu0 * self.scale

    @property
    def count(self) -> int:
        """The number of data."""
        return sum(t.count for t in self.tests)


def _inflation(setup: Setup, test: Dataset, material: Material, tension: float, calls: list) -> dict:
    solver = record(setup.solver)
    pressures = [float(p) * setup.radius / tension for p in test.control]
    out = {name: np.full(test.control.shape, math.nan) for name in test.responses}
    states: list = []
    if solver.serves("inflation_curve"):
        calls[0] += 1
        try:
            states = entry(solver, "inflation_curve", "an inflation test's data")(material, pressures, **setup.options)
        except _MISSED:  # a pressure above the maximum, or a failed march: each pressure on its own
            states = []
    if not states:
        inflate = entry(solver, "inflate", "an inflation test's data")
        for pressure in pressures:
            calls[0] += 1
            try:
                states.append(inflate(material, pressure, **setup.options))
            except OutOfRangeError:
                break  # the pressures increase: the higher ones are above the maximum too
            except ConvergenceError:
                states.append(None)
    for i, state in enumerate(states):
        for name in out:
            if state is not None:
                out[name][i] = state.height * setup.radius if name == "height" else state.volume * setup.radius**3
    return out


def compressed(setup: Setup, material: Material, pressure_initial: float, forces: list, calls: list,
               geometry: str | None = None) -> list:
    """The compressed states at ``forces`` (Fhat, increasing) of ``material`` (scaled) inflated at ``pressure_initial``
    (Phat_I) on the reference surface ``geometry`` (None: the clamped disc), by the setup's solver, or those below the
    range end, then None; ``calls[0]`` counts the solver's calls."""
    solver = record(setup.solver)
    curve = entry(solver, "compression_curve", "a compression test's data")
    options = {**setup.options, **({} if geometry is None else {"geometry": geometry})}
    calls[0] += 1
    try:
        return curve(material, pressure_initial, forces, **options)
    except OutOfRangeError:
        if not solver.serves("range_end"):
            return [None] * len(forces)
    calls[0] += 1
    try:
        end = entry(solver, "range_end", "a compression test's data")(material, pressure_initial, **options)
        inside = [f for f in forces if f <= end]
        calls[0] += bool(inside)
        states = curve(material, pressure_initial, inside, **options) if inside else []
    except _MISSED:
        return [None] * len(forces)
    return states + [None] * (len(forces) - len(inside))


def _compression(setup: Setup, test: Dataset, material: Material, tension: float, calls: list) -> dict:
    pressure_initial = test.initial_pressure
    assert pressure_initial is not None  # a compression test has its P_I (``pocket.apps.fit.data.read``)
    order = np.argsort(test.control)
    forces = [float(f) for f in test.control[order] / (pressure_initial * math.pi * setup.radius**2)]
    try:
        states = compressed(setup, material, pressure_initial * setup.radius / tension, forces, calls)
    except _MISSED:
        states = [None] * len(forces)
    out = {name: np.full(test.control.shape, math.nan) for name in test.responses}
    for i, state in zip(order, states, strict=True):
        if state is not None:
            for name in out:
                out[name][i] = state.height * setup.radius if name == "height" else \
                    state.pressure_ratio * pressure_initial
    return out


def admissible(material: Material | None) -> TypeGuard[Material]:
    """Whether ``material`` is inside its law's admissible set (None: a trial set outside it already)."""
    if material is None:
        return False
    try:
        check(material.law, {n: list(v) if isinstance(v, tuple) else v for n, v in material.params})
    except InputError:
        return False
    return True


def missing(setup: Setup) -> list[dict]:
    """The model's values of a trial set with no state for any datum: NaN everywhere (as ``predict``)."""
    return [{n: np.full(t.control.shape, math.nan) for n in t.responses} for t in setup.tests]


def predict(setup: Setup, material: Material | None) -> tuple[list[dict], int]:
    """The model's value at each datum (per test, column name -> SI array of the test's shape, NaN where the
    model has no state) for ``material`` (its stresses in the setup's unit; None: a trial set outside the
    law's admissible set), and the number of solver calls (entry points called: an inflation test marched as one
    curve is one call)."""
    calls = [0]
    if not admissible(material):  # no state anywhere
        return missing(setup), 0
    tension = setup.tension(material)
    unit = material.scaled()
    out = [(_inflation if t.kind == "inflation" else _compression)(setup, t, unit, tension, calls) for t in setup.tests]
    return out, calls[0]


def residuals(setup: Setup, values: list[dict], plain: Callable = lambda m, d: m / d - 1.0) -> np.ndarray:
    """The residual of each datum (module docstring), tests in order, columns in each test's order; shape (n,).
    ``plain(model, data)`` is the residual of a column without a stated uncertainty (relative; a capsule's gaps
    have their own, ``pocket.apps.fit.capsulemodel``)."""
    out = []
    for test, model in zip(setup.tests, values, strict=True):
        for name, data in test.responses.items():
            keep = np.isfinite(data)
            d, m = data[keep], model[name][keep]
            r = (m - d) / setup.sigma[name] if name in setup.sigma else plain(m, d)
            out.append(np.where(np.isfinite(m), r, PENALTY))
    return np.concatenate(out) if out else np.empty(0)
