r"""Identify a capsule's wall from its micromanipulation test: least squares on the capsule between two plates.

The unknowns are the law's keys (``pocket.apps.fit.capsulemodel.capsule_keys``) and, if asked, the initial
pressure P_I; the residuals are the gaps' (or displacements') in units of the diameter 2 R or of a stated
uncertainty (``pocket.apps.fit.capsulemodel``). The search, the Jacobian, the statistics and the intervals are the
clamped sheet's (``pocket.apps.fit.leastsquares.search``, ``pocket.apps.fit.stats``, ``pocket.apps.fit.intervals``),
with each trial set a rubber and a P_I (``pocket.apps.fit.capsulemodel.Trial``).

Scales. A stress is scaled by the start's mu_0, P_I by its given value (the start), a number by max(|value|, 1).

Starts. A force-gap test gives no small-strain estimate of E T: at small force the plates press on the inflated
membrane's tension N_0 = P_I lambda_I R / 2 and the displacement is F / (2 pi N_0) times a logarithm in which
alone E T appears (docs/theory.md, section 12, the small-force law). So each of the law's start shapes is tried at
E T = P_I R / Phat_I for the Phat_I of ``PRESSURES`` (the inflated capsule from near the neo-Hookean pressure
maximum, 0.413, to slack), P_I the given value, in that order, until the cost rises past the least so far (the
cost is one valley in E T; a trial with a datum without state costs infinitely much, so it stops the scan only
after one with every state: a soft wall may have none, past its pressure maximum or its range's end); the fit runs
from the best of each shape (``search``). A scan stops early because a failed solve costs much more
than one that succeeds: the shooting solver gives up on a capsule inflated at a small Phat_I only after cutting
its continuation's steps many times. An uninflated capsule (P_I = 0, held) has no Phat_I: its force F / (E T R) is
a function of the compression alone, so each shape is tried at the E T that puts the largest force at the F / (E T
R) of ``UNINFLATED_FORCES``, from deep (a soft wall) to shallow, the same way; its states are solved force by force
(``pocket.apps.fit.capsulemodel.uninflated``: a force short of the range's start has no state), the finite
elements' much faster than the shooting solver's there.

Separating P_I from E T. The same law says why they can be hard to tell apart: a test that stays at small
deformation sees mainly P_I (the force scales with it), and E T through a logarithm, which a change of P_I can
mimic. When P_I is fitted, the correlation of its estimate with mu_0's (the covariance of the keys mapped to
mu_0 by the delta method, ``pocket.apps.fit.stats``) beyond ``pocket.apps.fit.stats.CORRELATED`` is a warning
saying so.
"""

from __future__ import annotations

import dataclasses
import math
import time
from typing import cast

import numpy as np

from pocket.core.errors import InputError

from ..solvers import entry, record
from .capsulemodel import INITIAL_PRESSURE, Trial, capsule_keys, predict, residuals
from .keys import Key, key_named
from .leastsquares import PROBED, Fit, Problem, free_keys, search
from .model import PENALTY, Setup
from .start import at_tensions
from .stats import CORRELATED

__all__ = ["PRESSURES", "UNINFLATED_FORCES", "CapsuleFit", "CapsuleProblem", "fit", "separation", "summary"]

#: the Phat_I = P_I R / (E T) at which each start shape is tried (module docstring)
PRESSURES = (0.4, 0.2, 0.1, 0.05, 0.02, 0.01)
#: an uninflated capsule's: the F / (E T R) of its largest force at which each start shape is tried (module docstring)
UNINFLATED_FORCES = (10.0, 3.0, 1.0, 0.3, 0.1)


class CapsuleProblem(Problem):
    """The residual function of a capsule's fit (``pocket.apps.fit.leastsquares.Problem``): its model and residuals
    are ``pocket.apps.fit.capsulemodel``'s, its trial sets ``Trial``. Its residuals are lengths in units of 2 R
    (or of a stated uncertainty), whose gradient is as small as the deformation is: the least squares stop on their
    steps and their cost, not on the gradient's size (``gradient_test``)."""

    gradient_test = False

    def values(self, material) -> tuple[list, int]:
        return predict(self.setup, material)

    def compare(self, values: list) -> np.ndarray:
        return residuals(self.setup, values)


def _scaled(setup: Setup, trial: Trial, free: list[Key], count: dict) -> CapsuleProblem:
    scales = np.array([abs(trial.mu0) if k.unit == "stress" else abs(k.coordinate(trial)) if k.unit == "pressure"
                       else max(abs(k.coordinate(trial)), 1.0) for k in free])
    return CapsuleProblem(setup, trial, free, scales, count)


@dataclasses.dataclass(frozen=True)
class CapsuleFit(Fit):
    r"""A capsule's fit (``fit``): a ``pocket.apps.fit.leastsquares.Fit`` whose keys are a capsule's
    (``pocket.apps.fit.capsulemodel.capsule_keys``), with the ``initial_pressure`` P_I in Pa (held or fitted);
    its ``material`` is the fitted rubber (``fit`` shows one made).

    Examples
    --------
    >>> import dataclasses
    >>> from pocket.apps.fit.capsuletest import CapsuleFit
    >>> from pocket.apps.fit.leastsquares import Fit
    >>> print([f.name for f in dataclasses.fields(CapsuleFit)][len(dataclasses.fields(Fit)):])
    ['initial_pressure']
    """

    initial_pressure: float

    def predicted(self, setup: Setup) -> list:
        """The fitted capsule's values at ``setup``'s data (``pocket.apps.fit.capsulemodel.predict``)."""
        return predict(setup, Trial(self.material, self.initial_pressure))[0]

    def law_keys(self) -> tuple[Key, ...]:
        """All keys of a capsule's fit of this law (``pocket.apps.fit.capsulemodel.capsule_keys``)."""
        return capsule_keys(self.material.law, len(self.material["mu"]) if self.material.law == "ogden" else 1)


def fit(setup: Setup, law: str, pressure_initial: float, *, terms: int = 1, fixed: dict | None = None,
        fit_pressure: bool = False) -> CapsuleFit:
    r"""Fit a rubber law (and, if asked, the initial pressure) to a capsule's micromanipulation tests.

    Parameters
    ----------
    setup : Setup
        The capsule's tests (``pocket.apps.fit.capsuledata.read``), its radius R (m) and thickness T (m, or None:
        stresses are fitted times T, in N/m), the solver.
    law : str
        The law (``pocket.core.materials.LAWS``).
    pressure_initial : float
        P_I in Pa, > 0: held, or the start of its fit; 0, held: an uninflated capsule, its forces F / (E T R) at
        each trial's E T (``pocket.apps.fit.capsulemodel.uninflated``).
    terms : int, optional
        Ogden's terms.
    fixed : dict, optional
        Law key -> value held (stresses in the setup's unit).
    fit_pressure : bool, optional
        Fit P_I too (key ``initial_pressure``).

    Returns
    -------
    CapsuleFit

    Raises
    ------
    InputError
        For P_I < 0 (or 0 with ``fit_pressure``), fewer data than unknowns + 1, an unknown key (before any solve).
    ConvergenceError
        If no start, or no result, has a state for every datum.

    Examples
    --------
    A capsule's test made by the model (neo-Hookean, mu = 0.1 MPa, R = 50 um, T = 1 um, P_I = 1.2 kPa) is fitted
    back (``tests/test_fit_capsule_solver.py`` checks it on the command line):

    >>> import numpy as np
    >>> from pocket import shooting
    >>> from pocket.apps.fit.capsuletest import fit
    >>> from pocket.apps.fit.data import Dataset
    >>> from pocket.apps.fit.model import Setup
    >>> from pocket.core.materials import Material
    >>> radius, thickness, pressure, mu = 50e-6, 1e-6, 1200.0, 1e5
    >>> phat = pressure * radius / (3 * mu * thickness)
    >>> forces = [0.5, 1.0, 2.0, 4.0]
    >>> states = shooting.compression_curve(Material("neo-hookean", {"mu": 1.0}), phat, forces, geometry="capsule")
    >>> gaps = np.array([2 * s.height * radius for s in states])
    >>> test = Dataset("capsule", np.array(forces) * pressure * np.pi * radius**2, {"gap": gaps}, None, "model")
    >>> result = fit(Setup((test,), radius, thickness), "neo-hookean", pressure)
    >>> print(f"mu = {result.material['mu'] / 1e6:.5f} MPa")
    mu = 0.10000 MPa
    """
    clock = time.perf_counter()
    if not pressure_initial >= 0.0 or not math.isfinite(pressure_initial):
        raise InputError(f"initial pressure = {pressure_initial!r} Pa, but a capsule's fit needs P_I >= 0")
    if pressure_initial == 0.0 and fit_pressure:
        raise InputError("initial pressure = 0 Pa: an uninflated capsule's P_I is held (its fit starts from a "
                         "positive P_I)")
    all_keys = capsule_keys(law, terms)
    fixed = dict(fixed or {})
    if INITIAL_PRESSURE in fixed:
        raise InputError(f"--fix {INITIAL_PRESSURE}: the initial pressure is given by --initial-pressure (and "
                         "fitted with --fit-initial-pressure)")
    start = {INITIAL_PRESSURE: pressure_initial} if fit_pressure else {}
    if not fit_pressure:
        fixed[INITIAL_PRESSURE] = pressure_initial
    free = free_keys(setup, all_keys, fixed, start)
    count = {"calls": 0, "penalised": 0}
    shapes = _scan(setup, law, terms, pressure_initial, all_keys, fixed, free, count)
    result = search(setup, law, shapes, all_keys, free, fixed, start, law in PROBED, _scaled, clock)
    result = dataclasses.replace(result, calls=result.calls + count["calls"])
    trial = cast(Trial, result.material)  # the search's trial set: a rubber and its P_I
    stats = result.statistics
    warning = separation(trial, free, stats.covariance)
    if warning:
        stats = dataclasses.replace(stats, warnings=(*stats.warnings, warning))
    fields = {f.name: getattr(result, f.name) for f in dataclasses.fields(result)}
    return CapsuleFit(**{**fields, "material": trial.material, "statistics": stats},
                      initial_pressure=trial.pressure_initial)


def _scan(setup: Setup, law: str, terms: int, pressure: float, all_keys, fixed: dict, free: list[Key],
          count: dict) -> list[list[Trial]]:
    """Per start shape of ``law``, the trial at P_I = ``pressure`` with the least cost over the scan of ``PRESSURES``
    (module docstring), the values of ``fixed`` put in; a shape without a trial that has every state is left out."""
    if pressure > 0.0:
        tensions = [pressure * setup.radius / p for p in PRESSURES]
    else:  # an uninflated capsule: its largest force at F / (E T R) from deep (soft) to shallow (stiff)
        largest = max(float(np.max(test.control)) for test in setup.tests)
        tensions = [largest / (setup.radius * f) for f in UNINFLATED_FORCES]
    materials = at_tensions(setup, law, terms, tensions)
    out = []
    for first in range(0, len(materials), len(tensions)):
        least, best = math.inf, None
        for material in materials[first:first + len(tensions)]:
            trial = Trial(material, pressure)
            for name, value in fixed.items():
                trial = key_named(all_keys, name, "--fix").put(trial, value)
            problem = _scaled(setup, trial, free, count)
            r = problem(problem.x(trial))
            cost = math.inf if np.any(r == PENALTY) else float(r @ r)
            if best is not None and cost > least:
                break
            if cost < least:
                least, best = cost, trial
        if best is not None:
            out.append([best])
    return out


def separation(trial: Trial, free: list[Key], covariance) -> str | None:
    """The warning where the fitted P_I and mu_0 (of the fitted ``trial``, keys ``free`` with the keys'
    ``covariance``) are correlated beyond ``CORRELATED`` (module docstring); None otherwise, or if P_I is held."""
    names = [k.name for k in free]
    if INITIAL_PRESSURE not in names:
        return None
    k = names.index(INITIAL_PRESSURE)
    grad = np.zeros(len(free))
    for j, key in enumerate(free):
        if key.unit == "stress" or key.unknown is not None:
            value = key.get(trial)
            step = 1e-6 * max(abs(value), abs(trial.mu0) if key.unit == "stress" else 1.0)
            grad[j] = (key.put(trial, value + step).mu0 - trial.mu0) / step
    variance = float(grad @ covariance @ grad) * float(covariance[k, k])
    if not variance > 0.0:
        return None
    r = float(grad @ covariance[:, k]) / math.sqrt(variance)
    if abs(r) <= CORRELATED:
        return None
    return (f"the data do not separate the initial pressure from the wall's stiffness E T (their estimates are "
            f"correlated, r = {r:+.4f}): at small deformation the plates press on the inflated wall's tension "
            "P_I lambda_I R / 2, and E T shows only as the wall stretches further; compress further, or give a "
            "measured P_I and hold it (--initial-pressure without --fit-initial-pressure)")


def summary(result: CapsuleFit) -> dict:
    r"""The capsule's fit as one JSON-ready dict: ``pocket.apps.fit.report.summary``'s keys, and ``capsule``: the
    fitted capsule's geometry, P_I in Pa, Phat_I = P_I R / (E T), and its inflated stretch lambda_I with the gap
    2 lambda_I R between the plates at first touch (one inflation by the fit's solver).

    Parameters
    ----------
    result : CapsuleFit
        The fit (``fit``).

    Returns
    -------
    dict

    Examples
    --------
    >>> import numpy as np
    >>> from pocket import shooting
    >>> from pocket.apps.fit.capsuletest import fit, summary
    >>> from pocket.apps.fit.data import Dataset
    >>> from pocket.apps.fit.model import Setup
    >>> from pocket.core.materials import Material
    >>> radius, thickness, pressure, mu = 50e-6, 1e-6, 1200.0, 1e5
    >>> phat, forces = pressure * radius / (3 * mu * thickness), [0.5, 1.0, 2.0, 4.0]
    >>> states = shooting.compression_curve(Material("neo-hookean", {"mu": 1.0}), phat, forces, geometry="capsule")
    >>> gaps = np.array([2 * s.height * radius for s in states])
    >>> test = Dataset("capsule", np.array(forces) * pressure * np.pi * radius**2, {"gap": gaps}, None, "model")
    >>> out = summary(fit(Setup((test,), radius, thickness), "neo-hookean", pressure))
    >>> print(round(out["parameters"]["mu"]["value"] / 1e6, 5), out["fixed"]["initial_pressure"])
    0.1 {'value': 1200.0, 'unit': 'Pa'}
    >>> print(round(out["capsule"]["gap_initial_m"] / (2 * radius), 6) == round(states[0].inflated.height, 6))
    True
    """
    from .report import summary as report

    setup = result.setup
    out = report(result)
    phat = result.initial_pressure * setup.radius / setup.tension(result.material)
    inflate = entry(record(setup.solver), "inflate", "the fitted capsule's inflated state")
    stretch = inflate(result.material.scaled(), phat, geometry="capsule", **setup.options).stretch_pole
    out["capsule"] = {"geometry": "capsule", "initial_pressure_Pa": result.initial_pressure, "pressure_initial": phat,
                      "stretch_initial": stretch, "gap_initial_m": 2.0 * stretch * setup.radius}
    return out
