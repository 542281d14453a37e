"""The end of the compression range (``pocket.shooting.range_end``): one number per pocket."""

import math
import re
import sys
import types

import numpy as np
import pytest
from pocket.shooting import end as ends
from pocket.shooting import plateend
from pocket.shooting.laws import law_of
from pocket.shooting.plate import PlateProblem

from pocket import shooting
from pocket.apps import inverse
from pocket.cli.main import main
from pocket.core.errors import ConvergenceError, OutOfRangeError
from pocket.core.solver import Solver

SAMPLE = 47 / 160
POCKETS = [(SAMPLE, 0.31), (0.0, 0.1), (1.0, 1.0), (5.0, 2.0), (0.3, 1e-4)]


def _quoted_end(err) -> str:
    return re.search(r"ends at force = (\S+) ", str(err)).group(1)


@pytest.mark.parametrize(("alpha", "pressure"), POCKETS)
def test_at_the_end_the_plate_carries_the_whole_pressure(alpha, pressure):
    """Exact answer: vertical equilibrium of the sheet. The pressure pushes up P pi R^2 (whatever
    the shape spanning the clamp circle); the plate takes F, the clamp 2 pi R T_1 sin(psi(1)),
    which vanishes at psi(1) = pi. So at the end Fhat = P/P_I, and by F = P A_c the deformed
    contact area is pi R^2 (contact_area = 1). Found without using this, by psi(1) = pi."""
    end = shooting.range_end(alpha, pressure)
    state = shooting.compress(alpha, pressure, end)
    # the end and the state are resolved to ~1e-10 (rtol); 1e-8 leaves room
    assert state.pressure_ratio == pytest.approx(end, rel=1e-8)
    assert state.contact_area == pytest.approx(1.0, rel=1e-8)
    below = shooting.compress(alpha, pressure, end * (1 - 1e-3))
    assert below.contact_area < 1.0


def test_a_force_past_the_end_quotes_the_same_end_whatever_was_asked():
    """Exact answer: one number, range_end, in every message, for forces just past it and far past it."""
    end = shooting.range_end(SAMPLE, 0.31)
    quoted = set()
    for force in (end * (1 + 1e-12), 9.95, 10.0, 3000.0, 1e6):
        with pytest.raises(OutOfRangeError, match="beyond the model's range") as err:
            shooting.compress(SAMPLE, 0.31, force)
        quoted.add(_quoted_end(err.value))
    assert quoted == {f"{end:.10g}"}
    with pytest.raises(OutOfRangeError):  # in a curve, too, after states that solve
        shooting.compression_curve(SAMPLE, 0.31, [0.5, 9.0, 12.0])


def test_a_force_up_to_the_end_solves():
    """Exact answer: every force <= range_end has a state, alone (continuation from the inflated
    state) or in a curve, and its clamp angle is below pi (to the tolerance at the end itself)."""
    end = shooting.range_end(SAMPLE, 0.31)
    fractions = [0.3, 0.9, 0.999, 1 - 1e-6, 1 - 1e-12, 1.0]
    curve = shooting.compression_curve(SAMPLE, 0.31, [end * f for f in fractions])
    for fraction, state in zip(fractions, curve, strict=True):
        alone = shooting.compress(SAMPLE, 0.31, end * fraction)
        assert alone.pressure_ratio == pytest.approx(state.pressure_ratio, rel=1e-9)
        assert state.contact_area <= 1.0 + 1e-8


def test_the_command_line_says_out_of_range_with_status_2(capsys):
    """Exact answer: exit status 2 and the one end, for 10 and for 1e6 (it used to fail to start, status 1)."""
    for force in ("10", "1e6"):
        assert main(["compress", "--alpha", "0.29375", "--pressure", "0.31", "--force", force]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1
        assert f"{shooting.range_end(0.29375, 0.31):.10g}" in err


def test_tolerance_of_the_end():
    """Exact answer: rtol 1e-10 -> 1e-12 moves the end by less than 1e-9 relative (the stated tolerance)."""
    coarse = shooting.range_end(SAMPLE, 0.31, rtol=1e-10)
    fine = shooting.range_end(SAMPLE, 0.31, rtol=1e-12)
    assert abs(coarse / fine - 1) < 1e-9, (coarse, fine)


def test_computed_once_per_pocket(monkeypatch):
    """Exact answer: a second request (range_end, or forces past it) reads the cache."""
    shooting.range_end(0.4, 0.2)
    calls = []
    monkeypatch.setattr(plateend, "plate_end", lambda *a: calls.append(a))
    shooting.range_end(0.4, 0.2)
    with pytest.raises(OutOfRangeError):
        shooting.compress(0.4, 0.2, 1e3)
    assert calls == []


def test_a_fold_ends_the_range_of_a_softening_rubber():
    """Exact answer: for alpha = -0.5, Phat_I = 0.1 the force has a maximum along the branch before
    psi(1) = pi. The end is that maximum: the branch solved at clamp angles on both sides of it
    carries less force, forces up to it solve on its rising side, forces above it do not."""
    alpha, pressure = -0.5, 0.1
    end = shooting.range_end(alpha, pressure)
    problem = PlateProblem(shooting.inflate(alpha, pressure), 1e-10, law_of(alpha))
    info = ends.end_of(problem)
    assert info.fold
    assert info.angle < math.pi
    assert info.force == end
    for dtheta in (-1e-3, 1e-3):
        sol = plateend._at_angle(problem, info.angle + dtheta, list(info.path))
        assert sol.x[2] < end
    states = shooting.compression_curve(alpha, pressure, [0.5 * end, 0.999 * end, end])
    angles = [problem.clamp_angle([s.pressure_ratio, (s.stretch_contact - 1) / problem.strain], s.force)
              for s in states]
    assert angles == sorted(angles)
    assert angles[-1] <= info.angle + 1e-6
    with pytest.raises(OutOfRangeError, match="has a maximum"):
        shooting.compress(alpha, pressure, end * (1 + 1e-9))


def test_inverse_uses_the_solvers_own_end():
    """Exact answer: pocket.apps.inverse.range_end returns the solver's number (no bisection)."""
    assert inverse.range_end(shooting.SOLVER, SAMPLE, 0.31) == shooting.range_end(SAMPLE, 0.31)
    assert inverse.range_end(shooting.SOLVER, SAMPLE, 0.31, below=1.0) == 1.0


def test_inverse_bisection_treats_failures_as_failures(monkeypatch):
    """Exact answer: a solver without range_end is bisected on OutOfRangeError; its ConvergenceError
    is not a range edge and propagates."""
    def compress(alpha, pressure, force):
        if force > 3.0:
            raise OutOfRangeError("past the end")
        if force > 2.0:
            raise ConvergenceError("failed")
        return types.SimpleNamespace(height=1.0 - force)

    fake = _record(monkeypatch, "fake", compress)
    assert inverse.range_end(fake, 0.0, 0.1, below=1.5) == 1.5
    with pytest.raises(ConvergenceError):
        inverse.range_end(fake, 0.0, 0.1)
    ok = _record(monkeypatch, "ok", lambda a, p, f: compress(a, p, min(f, 2.0) if f <= 3.0 else f))
    assert inverse.range_end(ok, 0.0, 0.1) == pytest.approx(3.0, rel=1e-8)
    assert np.isfinite(inverse.range_end(ok, 0.0, 0.1))


def _record(monkeypatch, name, compress) -> Solver:
    """The record of a solver whose only entry point is ``compress``, its module registered for the test."""
    module = types.ModuleType(f"fake_solver_{name}")
    module.compress = compress
    monkeypatch.setitem(sys.modules, module.__name__, module)
    return Solver(name=name, summary="a test's", module=module.__name__, entry_points=("compress",))
