"""Inflation by the finite-element solver, against the shooting reference and known limits.

Exact answers: the shooting solver (an independent derivation, rtol 1e-12);
the small-pressure limit H0/R = K Phat^(1/3); inverse consistency of pressure
and volume control; the absence of a first-branch state above the neo-Hookean
pressure maximum; the pole stretch's convergence order on uniform meshes (2)
and on meshes graded towards the axis (4 with P2).
"""

import re

import numpy as np
import pytest

from pocket import fem, meshes, shooting
from pocket.core.errors import OutOfRangeError

KEYS = ("pressure", "stretch_pole", "height", "volume", "stretch_clamp")
CASES = [(47 / 160, 0.05), (47 / 160, 0.31), (0.0, 0.05), (0.0, 0.31), (1.0, 1.5), (-0.5, 0.1)]


def _worst(state, reference):
    diffs = {k: abs(getattr(state, k) / getattr(reference, k) - 1.0) for k in KEYS}
    return max(diffs.values()), diffs


@pytest.mark.parametrize(("alpha", "pressure"), CASES)
def test_default_mesh_matches_shooting(alpha, pressure):
    """Every scalar within 1e-9 relative of shooting at the default mesh."""
    worst, diffs = _worst(fem.inflate(alpha, pressure), shooting.inflate(alpha, pressure, rtol=1e-12))
    assert worst < 1e-9, f"relative differences {diffs}"


def test_pressure_is_echoed_exactly():
    """The state's pressure is the number given, not the multiplier Newton left (0.1 stays 0.1)."""
    assert fem.inflate(0.3, 0.1, elements=8).pressure == 0.1


def test_small_pressure_limit():
    """H0/R -> K Phat^(1/3) as Phat -> 0: K from FEM (default mesh) equals shooting's to 1e-9, is
    constant between Phat = 1e-4 and 1e-6 to 1e-2 (the next term is O(Phat^(2/3))),
    and is within 5 % of the small-strain model's sqrt(3/2)/(4 sqrt 6)^(1/3) = 0.572
    (eqs (16a), (18): an assumed stretch profile, so an approximation of the limit)."""
    k = [fem.inflate(47 / 160, p).height / p ** (1 / 3) for p in (1e-4, 1e-6)]
    k_ref = shooting.inflate(47 / 160, 1e-6, rtol=1e-12).height / 1e-6 ** (1 / 3)
    k_model = np.sqrt(1.5) / (4 * np.sqrt(6)) ** (1 / 3)
    assert k[1] == pytest.approx(k_ref, rel=1e-9)
    assert k[0] == pytest.approx(k[1], rel=1e-2)
    assert k[1] == pytest.approx(k_model, rel=0.05), f"K = {k[1]!r}, model {k_model!r}"


def test_volume_control_inverts_pressure_control():
    """inflate_volume(V(Phat)) returns Phat (both on the same mesh: to Newton tolerance)."""
    by_pressure = fem.inflate(47 / 160, 0.2, elements=64)
    by_volume = fem.inflate_volume(47 / 160, by_pressure.volume, elements=64)
    assert by_volume.pressure == pytest.approx(0.2, rel=1e-10)
    assert by_volume.height == pytest.approx(by_pressure.height, rel=1e-10)
    assert by_volume.volume == by_pressure.volume  # echoed


def test_above_neo_hookean_maximum_is_out_of_range():
    """alpha = 0: Phat(V) has a maximum (about 0.63 near V = 2.8); Phat = 0.7 is above it, so
    no first-branch state exists: OutOfRangeError naming the maximum."""
    with pytest.raises(OutOfRangeError, match="maximum"):
        fem.inflate(0.0, 0.7, elements=64)


def test_volume_control_passes_the_maximum():
    """Volume control goes past the neo-Hookean pressure maximum (near V = 2.8): the pressure
    at V = 4 is below the one at V = 3.5 (descending branch) and agrees with shooting (1e-8)."""
    states = [fem.inflate_volume(0.0, v) for v in (3.5, 4.0)]
    assert states[1].pressure < states[0].pressure
    assert states[1].pressure == pytest.approx(shooting.inflate_volume(0.0, 4.0, rtol=1e-12).pressure, rel=1e-8)


@pytest.mark.parametrize(("family", "expected"), [("uniform", 2.0), ("polar", 4.0)])
def test_pole_stretch_order(family, expected):
    """The pole stretch is a point derivative at the axis, where the axisymmetric forms are singular:
    P2 converges at order 2 on uniform meshes and at order 4 on meshes graded towards the axis
    (meshes.polar, power 2.5), within 0.2 (fit over 40..160 elements)."""
    ref = shooting.inflate(47 / 160, 0.31, rtol=1e-12).stretch_pole
    ns = (40, 80, 160)
    errors = [abs(fem.inflate(47 / 160, 0.31, mesh=getattr(meshes, family)(n)).stretch_pole / ref - 1) for n in ns]
    order = -np.polyfit(np.log(ns), np.log(errors), 1)[0]
    assert abs(order - expected) < 0.2, f"{family}: order {order:.3f}, errors {errors}"


def test_state_contents():
    """solver tag, extras and a nodal profile with T1 = T2 at the pole (equibiaxial)."""
    state = fem.inflate(47 / 160, 0.31, elements=50, order=1)
    assert state.solver == "fem"
    assert {"elements", "order", "newton_iterations"} <= set(state.extra)
    assert state.extra["elements"] == 50
    assert state.extra["order"] == 1
    prof = state.profile
    assert prof.r[0] == 0.0
    assert prof.r[-1] == 1.0
    assert not prof.contact.any()
    assert prof.tension_1[0] == pytest.approx(prof.tension_2[0], rel=1e-12)
    assert prof.eta[0] == state.height
    assert prof.stretch_2[-1] == 1.0


@pytest.fixture
def counted(monkeypatch):
    """Calls of the inflation's pressure-controlled solve, from an empty memory of inflated states."""
    import collections

    from pocket.fem import inflation

    calls = []
    solve = inflation.to_pressure

    def to_pressure(model, target, tol):
        calls.append((model.elements, target))
        return solve(model, target, tol)

    monkeypatch.setattr(inflation, "to_pressure", to_pressure)
    monkeypatch.setattr(inflation, "_SOLVED", collections.OrderedDict(), raising=False)
    return calls


def _same(a, b):
    """Two states equal bit for bit: every field, arrays elementwise, the profile's arrays too."""
    import dataclasses

    for field in dataclasses.fields(a):
        x, y = getattr(a, field.name), getattr(b, field.name)
        if field.name == "profile":
            assert all(np.array_equal(getattr(x, f.name), getattr(y, f.name), equal_nan=True)
                       for f in dataclasses.fields(x)), field.name
        elif field.name == "inflated":
            _same(x, y)
        else:
            assert x == y or (x != x and y != y), field.name  # NaN where a key has no value


def test_one_inflation_per_pocket_and_mesh_bit_for_bit(counted):
    """Exact answer: the inflation of one (law, Phat_I, mesh) is solved once across entry-point calls
    (an inverse problem calls them once per bracket step), and the states are those of a fresh solve, bit
    for bit; another pressure, mesh or law is a solve of its own."""
    fresh = fem.compress(0.3, 0.3, 0.1)
    assert counted == [(fem.DEFAULT_ELEMENTS, 0.3)]
    again = [fem.compress(0.3, 0.3, 0.1), fem.inflate(0.3, 0.3), fem.compression_curve(0.3, 0.3, [0.1])[0]]
    assert len(counted) == 1
    _same(again[0], fresh)
    _same(again[1], fresh.inflated)
    _same(again[2], fresh)
    fem.inflate(0.3, 0.2)
    fem.inflate(0.3, 0.3, elements=64)
    fem.inflate(0.4, 0.3)
    assert len(counted) == 4


def test_a_capsule_inflation_is_remembered_apart_from_the_pocket(monkeypatch):
    """Exact answer: a capsule's inflation is solved once per (law, Phat_I, mesh) too, a capsule and a pocket of
    the same rubber, pressure and mesh are remembered apart (the reference surface is in the key), and the
    remembered capsule is a fresh solve's, bit for bit."""
    import collections

    from pocket.fem import capsule, inflation

    calls = []
    solve = capsule.inflate

    def counted_capsule(model, target, tol):
        calls.append(target)
        return solve(model, target, tol)

    monkeypatch.setattr(capsule, "inflate", counted_capsule)
    monkeypatch.setattr(inflation, "_SOLVED", collections.OrderedDict(), raising=False)
    fresh = fem.compress(0.3, 0.3, 0.5, geometry="capsule", elements=32)
    again = [fem.compress(0.3, 0.3, 0.5, geometry="capsule", elements=32),
             fem.inflate(0.3, 0.3, geometry="capsule", elements=32)]
    assert calls == [0.3]
    _same(again[0], fresh)
    _same(again[1], fresh.inflated)
    pocket = fem.inflate(0.3, 0.3, elements=32)
    assert calls == [0.3]
    assert pocket.extra.get("geometry") != fresh.inflated.extra["geometry"]


def test_the_memory_of_inflations_is_bounded(counted):
    """The last REMEMBERED inflations are remembered, the oldest forgotten first; a pressure with no
    state is never remembered (its error comes again)."""
    from pocket.fem.inflation import REMEMBERED

    pressures = [0.1 * (k + 1) for k in range(REMEMBERED + 1)]
    for p in pressures:
        fem.inflate(0.3, p, elements=16)
    fem.inflate(0.3, pressures[-1], elements=16)
    assert len(counted) == REMEMBERED + 1
    fem.inflate(0.3, pressures[0], elements=16)
    assert len(counted) == REMEMBERED + 2
    for _ in range(2):
        with pytest.raises(OutOfRangeError):
            fem.inflate(0.0, 2.0, elements=16)
    assert len(counted) == REMEMBERED + 4


def test_a_maximum_hidden_inside_one_step_is_found():
    """Exact answer: the shooting solver's first pressure maximum. At alpha = 0.0546875 the dip after the
    maximum is shallow and narrow (shooting: Phat 0.73277 at V/R^3 = 8.2, lower at 12, back above it by 16),
    so the states of one log V step can rise on both sides of it; the FE must still refuse Phat = 1 (the
    second rising branch reaches it near V/R^3 = 577) and quote the same maximum, to the golden-section
    search's tolerance in V (1e-7 in log V) and the default mesh's error (1e-8 in Phat)."""
    alpha = 0.0546875
    with pytest.raises(OutOfRangeError) as shooting_err:
        shooting.inflate(alpha, 1.0)
    with pytest.raises(OutOfRangeError) as fem_err:
        fem.inflate(alpha, 1.0)
    quoted = [float(re.search(r"maximum Phat = ([0-9.]+)", str(e.value)).group(1)) for e in (shooting_err, fem_err)]
    assert quoted[0] == pytest.approx(quoted[1], abs=2e-6), (str(shooting_err.value), str(fem_err.value))  # 6 digits
