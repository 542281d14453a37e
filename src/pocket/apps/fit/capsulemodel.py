r"""The model's gaps at a capsule's measured forces, the residuals that compare them, and the keys a fit varies.

A trial is a rubber and an initial pressure (``Trial``): the capsule is inflated at P_I, its liquid sealed, then
squeezed between two plates. With E T = 3 mu_0 T (the material's stresses times T, or already products with T
without a thickness: ``pocket.apps.fit.model.Setup.scale``) the solver's loads are

    Phat_I = P_I R / (E T),   Fhat = F / (P_I pi R^2),

and a state's ``height`` H is the plate's distance from the equatorial plane in units of R
(``pocket.core.states``): the model's gap is 2 H R and its displacement from first touch 2 R (lambda_I - H),
lambda_I = H at zero force (the inflated state's height). Each test's forces are solved as one compression
curve by continuation (``pocket.apps.fit.model.compressed``, force control: one solve per evaluation, where
gap control would root-find a force for every datum); a force past the range's end, a Phat_I above the law's
pressure maximum, a failed solve or a trial outside the law's admissible set gives NaN, as for the clamped sheet.

Residuals. The force is the control, taken as exact; the plates' position carries the error, an absolute one (a
stage's or an image's resolution, not a fraction of the gap). So the residual of a datum d (a gap or a
displacement, m) with model value m is (m - d) / (2 R), the error in units of the undeformed capsule's diameter,
or (m - d) / sigma with the column's stated uncertainty sigma (``--sigma gap=0.1um``). A gap says more than a
displacement: it includes the untouched capsule's size 2 lambda_I R, which the displacement, counted from first
touch, leaves out (at a trial, the displacement's residual is the gap's with its sign turned, plus the trial's
lambda_I less the capsule's). A datum with no state gives ``pocket.apps.fit.model.PENALTY``.

Keys. The law's keys (``pocket.apps.fit.keys``; the prestretch aside: a capsule's reference sphere is unstressed)
read and move a trial's rubber; ``INITIAL_PRESSURE`` reads and moves its P_I, a pressure in Pa whatever the
thickness, bounded below by 0 (the solver needs P_I > 0).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from pocket.core.errors import ConvergenceError, OutOfRangeError
from pocket.core.materials import Material

from ..solvers import entry, record
from . import model
from .keys import PRESTRETCH, Key, keys
from .model import Setup, admissible, compressed, missing

__all__ = ["INITIAL_PRESSURE", "Trial", "capsule_keys", "predict", "residuals", "uninflated"]

#: the key of the capsule's initial pressure (Pa)
INITIAL_PRESSURE = "initial_pressure"


@dataclasses.dataclass(frozen=True)
class Trial:
    """A capsule's rubber ``material`` (stresses in the setup's unit) and its initial pressure
    ``pressure_initial`` P_I (Pa); ``mu0`` is the rubber's."""

    material: Material
    pressure_initial: float

    @property
    def mu0(self) -> float:
        """The rubber's small-strain shear modulus, in its stresses' unit."""
        return self.material.mu0


def _on_trial(pair):
    get, put = pair
    return (lambda t: get(t.material)), (lambda t, v: dataclasses.replace(t, material=put(t.material, v)))


def capsule_keys(law: str, terms: int = 1) -> tuple[Key, ...]:
    """The keys of a capsule's fit: those of ``law`` (``terms`` terms for Ogden) but the prestretch, each on a
    ``Trial``'s rubber, then ``INITIAL_PRESSURE``.

    Examples
    --------
    >>> from pocket.apps.fit.capsulemodel import Trial, capsule_keys
    >>> from pocket.core.materials import Material
    >>> keys = capsule_keys("neo-hookean")
    >>> trial = keys[1].put(Trial(Material("neo-hookean", {"mu": 1e5}), 1200.0), 900.0)
    >>> print([k.name for k in keys], keys[0].get(trial), trial.pressure_initial)
    ['mu', 'initial_pressure'] 100000.0 900.0
    """
    out = []
    for key in keys(law, terms):
        if key.name != PRESTRETCH:
            get, put = _on_trial((key.get, key.put))
            out.append(dataclasses.replace(key, get=get, put=put,
                                           unknown=None if key.unknown is None else _on_trial(key.unknown)))
    out.append(Key(INITIAL_PRESSURE, "pressure", 0.0, math.inf, lambda t: t.pressure_initial,
                   lambda t, v: dataclasses.replace(t, pressure_initial=float(v))))
    return tuple(out)


def predict(setup: Setup, trial: Trial | None) -> tuple[list[dict], int]:
    """The model's value at each datum of ``setup``'s capsule tests (per test, column name -> SI array of the test's
    shape, NaN where the model has no state) for ``trial`` (None: outside the admissible set), and the number of
    solver calls (module docstring)."""
    if trial is None or not admissible(trial.material) or not trial.pressure_initial >= 0.0:
        return missing(setup), 0
    calls = [0]
    radius, pressure = setup.radius, trial.pressure_initial
    unit = trial.material.scaled()
    tension = setup.tension(trial.material)
    phat = pressure * radius / tension
    out = []
    for test in setup.tests:
        order = np.argsort(test.control)
        if pressure == 0.0:  # an uninflated capsule: each force F / (E T R) on its own (``uninflated``)
            states = uninflated(setup, unit, [float(f) for f in test.control[order] / (tension * radius)], calls)
        else:
            forces = [float(f) for f in test.control[order] / (pressure * math.pi * radius**2)]
            try:
                states = compressed(setup, unit, phat, forces, calls, geometry="capsule")
            except (OutOfRangeError, ConvergenceError):
                states = [None] * len(forces)
        values = {name: np.full(test.control.shape, math.nan) for name in test.responses}
        for i, state in zip(order, states, strict=True):
            if state is not None:
                for name in values:
                    values[name][i] = 2.0 * radius * (state.height if name == "gap" else
                                                      state.inflated.height - state.height)
        out.append(values)
    return out, calls[0]


def uninflated(setup: Setup, material: Material, forces: list[float], calls: list) -> list:
    """The uninflated capsule's states (P_I = 0) at ``forces`` F / (E T R), each solved alone by the setup's solver
    (``force_unit="ETR"``); None where it has none (a force short of its range's start, a failed solve)."""
    curve = entry(record(setup.solver), "compression_curve", "an uninflated capsule's compression test")
    states = []
    for force in forces:
        calls[0] += 1
        try:
            (state,) = curve(material, 0.0, [force], geometry="capsule", force_unit="ETR", **setup.options)
        except (OutOfRangeError, ConvergenceError):
            state = None
        states.append(state)
    return states


def residuals(setup: Setup, values: list[dict]) -> np.ndarray:
    """The residual of each datum (module docstring), tests in order; shape (n,)."""
    return model.residuals(setup, values, lambda m, d: (m - d) / (2.0 * setup.radius))
