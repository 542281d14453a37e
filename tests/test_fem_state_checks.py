"""The finite-element states' own force check: as tight as what Newton accepts, and no tighter.

Exact answers: the identities' errors are the border rows' algebra, reaction - Fhat = (c - t) F_s / (pi P_I) and
P A_c / P_I - Fhat = c F_s / (pi P_I) with t, c the tangency and force-control rows (``model.residual``) and F_s
the force itself, to the round-off of the sums. The allowance (``results``' docstring derives it) is
Fhat (2 FLOOR tol + NOISE nu): the two rows Newton accepts within FLOOR tol, or within NOISE of their round-off nu,
the worst change of the rows when the unknowns move by ULPS units in their last place (``newton.border_noise``,
checked here on a small system whose gradients are given). A state built from solved unknowns but echoing a force
10 allowances off, or with its pressure moved so that P A_c is 10 allowances off, is refused (``ConvergenceError``
naming the identity), on the clamped sheet, the capsule and under a curved indenter; a fine capsule whose Newton
solve stalls at its residual floor (Phat_I = 0.01, neo-Hookean, 2048 elements, Fhat = 0.14 after 0.1) is returned,
and so is a tiny force on a fine disc, whose reaction is off by more than the first term (its round-off does not
shrink with the force) but within the allowance.
"""

import functools
from dataclasses import replace
from types import SimpleNamespace

import numpy as np
import pytest
from pocket.fem import api, fitted, model, obstacle, results, wrapping, wrapstates
from pocket.fem.newton import FLOOR, NOISE, ULPS, Tolerances, border_noise
from pocket.fem.surfaces import surface

from pocket import fem
from pocket.core import geometries
from pocket.core.errors import ConvergenceError
from pocket.core.indenters import Sphere

ALPHA, PHAT, FORCE, ELEMENTS = 0.3, 0.31, 0.19, 16


@functools.lru_cache
def _solved(geometry: str):
    """(model, FITTED unknowns at FORCE, iterations, inflated state, fill, tolerances, builder) on ELEMENTS."""
    posed, _ = geometries.posed(api.GEOMETRIES, "fem", geometry)
    m, _, _, tol, y_i, inflated, fill, _ = api._setup(ALPHA, PHAT, None, None, posed, None, ELEMENTS, 2, "fitted",
                                                      None, None, 1e-10)
    unit = np.pi * inflated.pressure
    y, iterations = fitted.first_contact(m, y_i, fill, fitted.A_FIRST / 4, tol)
    y, more = fitted.force_path(m, y, fill, FORCE * unit, tol, unit)
    y.flags.writeable = False  # shared by the tests (cached)
    return m, y, iterations + more, inflated, fill, tol, api._builder(posed)


@pytest.mark.parametrize("geometry", ["pocket", "capsule"])
def test_the_force_identities_are_the_border_rows(geometry):
    """reaction - Fhat = (c - t) Fhat and P A_c / P_I - Fhat = c Fhat, t and c the tangency and control rows
    measured against F_s = pi P_I Fhat: at the solved state (the state's own reports) and with its pressure and
    edge radius moved by 1e-6 (rows ~1e-6, the reaction -sum_C R_j by ``model.plate_force``); to 1e-12 Fhat,
    the sums' round-off."""
    m, y, iterations, inflated, fill, tol, builder = _solved(geometry)
    unit = np.pi * inflated.pressure
    force = FORCE * unit
    state = builder.fitted_state(m, y, iterations, inflated, fill, FORCE, tol)
    moved = np.array(y)
    moved[m.dofs] *= 1.0 + 1e-6
    moved[model.edge(m)] *= 1.0 - 1e-6
    reports = [(y, state.extra["force_reaction"], state.extra["force_pressure_area"]),
               (moved, model.plate_force(m, moved, model.FITTED) / unit,
                moved[m.dofs] * moved[model.edge(m)] ** 2 / inflated.pressure)]
    for z, reaction, area in reports:
        t, c = model.residual(m, np.array(z), model.FITTED, replace(fill, force=force, scale=force))[-2:]
        assert reaction - FORCE == pytest.approx((c - t) * FORCE, abs=1e-12 * FORCE)
        assert area - FORCE == pytest.approx(c * FORCE, abs=1e-12 * FORCE)


def test_the_allowance_is_the_rows_at_newtons_floor_and_noise():
    """Fhat (2 FLOOR tol + NOISE noise); the rows' noise of a bordered system C = [[1, -2], [0, 3]],
    D = [[-1], [2]] at y = [U, s] = [1, -1, 2] is ULPS eps (|C| |U| + |D| |s|) = ULPS eps [5, 7]."""
    tol = Tolerances(1e-8, 1e-8)
    assert results.force_allowance(0.5, tol) == pytest.approx(0.5 * 2 * FLOOR * 1e-8, rel=1e-15)
    assert results.force_allowance(0.5, tol, 3e-9) == pytest.approx(0.5 * (2 * FLOOR * 1e-8 + NOISE * 3e-9),
                                                                    rel=1e-15)
    system = SimpleNamespace(C=np.array([[1.0, -2.0], [0.0, 3.0]]), D=np.array([[-1.0], [2.0]]))
    expected = ULPS * np.finfo(float).eps * np.array([1 + 2 + 2, 3 + 4])
    assert np.allclose(border_noise(system, np.array([1.0, -1.0, 2.0])), expected, rtol=1e-15, atol=0)


def _allowance(m, y, inflated, fill, tol) -> float:
    """The allowance of the FITTED state y at FORCE, its noise read from the tangent as the state's check reads it."""
    control = results.force_control(fill, FORCE, np.pi * inflated.pressure)
    system = model.linearize(m, np.array(y), model.FITTED, control)[1]
    return results.force_allowance(FORCE, tol, results.identity_noise(system, np.array(y)))


@pytest.mark.parametrize("geometry", ["pocket", "capsule"])
def test_a_state_ten_allowances_off_is_refused(geometry):
    """The solved state passes (its identities within the allowance); echoing FORCE + 10 allowances fails on the
    reaction; moving P by 10 allowances (relative to the force) fails on P A_c (pocket and capsule alike)."""
    m, y, iterations, inflated, fill, tol, builder = _solved(geometry)
    state = builder.fitted_state(m, y, iterations, inflated, fill, FORCE, tol)
    allowance = _allowance(m, y, inflated, fill, tol)
    for name in ("force_reaction", "force_pressure_area"):
        assert abs(state.extra[name] - FORCE) <= allowance, (name, state.extra[name] - FORCE, allowance)
    with pytest.raises(ConvergenceError, match=r"force_reaction = .* against the force"):
        builder.fitted_state(m, y, iterations, inflated, fill, FORCE + 10 * allowance, tol)
    moved = y.copy()
    moved[m.dofs] *= 1.0 + 10 * allowance / FORCE  # P A_c / P_I moves by 10 allowances
    with pytest.raises(ConvergenceError, match=r"force_(reaction|pressure_area) = .* against the force"):
        builder.fitted_state(m, moved, iterations, inflated, fill, FORCE, tol)


def test_a_curved_indenters_state_ten_allowances_off_is_refused():
    """Under a sphere of radius 2 R (32 elements): the solved state passes; echoing FORCE + 10 allowances (its
    noise term read from ``obstacle``'s tangent, as the state's check reads it) fails on the reaction."""
    m, _, _, tol, y_i, inflated, fill, _ = api._setup(ALPHA, PHAT, None, Sphere(2.0), geometries.DISC, None, 32, 2,
                                                      "fitted", None, None, 1e-10)
    unit = np.pi * inflated.pressure
    y, iterations = wrapping.first_contact(m, y_i, fill, wrapping.first_radius(inflated, fill, fitted.A_FIRST), tol)
    y, more = wrapping.force_path(m, y, fill, FORCE * unit, tol, unit)
    wrapstates.state(m, y, iterations + more, inflated, fill, FORCE, tol)
    system = obstacle.linearize(m, y, results.force_control(fill, FORCE, unit), surface(fill.indenter))[1]
    allowance = results.force_allowance(FORCE, tol, results.identity_noise(system, y))
    with pytest.raises(ConvergenceError, match=r"force_reaction = .* against the force"):
        wrapstates.state(m, y, iterations + more, inflated, fill, FORCE + 10 * allowance, tol)


@pytest.mark.slow
def test_a_fine_capsule_stalled_at_its_floor_is_returned():
    """Neo-Hookean capsule at Phat_I = 0.01 on 2048 elements: Newton stalls at Fhat = 0.14 (seeded by 0.1) and
    accepts its floor; the state is returned, its identities within the allowance's relative term alone (the
    stall is in the relative rows)."""
    states = fem.compression_curve(0.0, 0.01, [0.1, 0.14], geometry="capsule", elements=2048)
    for state in states:
        allowance = results.force_allowance(state.force, Tolerances())
        for name in ("force_reaction", "force_pressure_area"):
            assert abs(state.extra[name] - state.force) <= allowance, (name, state.extra[name], state.force)


def test_a_tiny_force_on_a_fine_disc_is_returned():
    """Fhat = 1e-7 at Phat_I = 0.01 on 2048 elements (alpha 0.3): the reaction is off by more than the first
    term, 2 FLOOR tol Fhat (the round-off of the tied rows does not shrink with the force), and the state is
    returned: within the noise term its own check read."""
    force, tol = 1e-7, Tolerances()
    state = fem.compress(ALPHA, 0.01, force, elements=2048)
    error = abs(state.extra["force_reaction"] - force)
    assert error > results.force_allowance(force, tol), error
