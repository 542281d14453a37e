"""The solid's convergence study (``pocket.validation.solidstudy``) on values whose limit and order are known.

A quantity made q(n) = q* + C n^-p on meshes of n = 16, 32, 64 elements must give back p and q* (Richardson's
extrapolation is exact on such a sequence), and the default mesh's error |q(64) / q* - 1|; one whose differences do
not shrink has no q*, and its error is the distance to the finest mesh plus the finest mesh's last change. The
solves themselves are tested on the quick report (``test_validation_report``, slow lane).
"""

from __future__ import annotations

import pytest
from pocket.validation import solidstudy
from pocket.validation.solidstudy import AXES, Study


def _study(values_of, counts=(16, 32, 64), axis=AXES[0], default=64):
    """A Study along the radius whose value of each key on the mesh of n elements is values_of(key, n), its
    default mesh that of ``default`` elements."""
    grid = tuple((n, 4, 0.5) for n in counts)
    default = (default, 4, 0.5)
    keys = [("V", None), ("H0", None)] + [(q, 0.1) for q in solidstudy.COMPRESSION]
    values = tuple({key: values_of(key, n) for key in keys} for n in counts)
    return Study(4, 0.08, 5.0, (0.1,), axis, grid, values, (0.0,) * len(counts), default)


@pytest.mark.parametrize("order", [1.0, 2.0, 3.5])
def test_richardson_recovers_a_known_limit_and_order(order):
    """Exact answer: on q = q* + C n^-p the observed order is p and q* is found to rounding."""
    limit, scale = 0.3, 0.7

    def values(key, n):
        return limit + scale * n ** -order

    study = _study(values)
    for key in study.quantities():
        found, _, p = study.estimate(key)
        assert p == pytest.approx(order, rel=1e-9)
        assert found == pytest.approx(limit, rel=1e-12)
        error, against = study.default_error(key)
        assert against
        expected = scale * 64**-order if key[0] in solidstudy.ABSOLUTE else scale * 64**-order / limit
        assert error == pytest.approx(expected, rel=1e-6)


def test_no_asymptotic_range_is_not_certified():
    """Exact answer: values that jump about have no q*; the default (the finest) is charged its last change, so
    a target can fail without one."""
    jumps = {16: 0.0438, 32: 0.0365, 64: 0.0371}

    def values(key, n):
        return jumps[n]

    study = _study(values)
    key = ("A_c", 0.1)
    assert study.estimate(key) is None
    error, against = study.default_error(key)
    assert not against
    assert error == pytest.approx(abs(0.0365 / 0.0371 - 1.0), rel=1e-12)
    verdicts = {c.quantity: c.verdict for c in solidstudy.checks([study]) if c.where.endswith("= 0.1")}
    assert verdicts["A_c"] == "fail"  # 1.6 % > 0.5 %
    assert verdicts["a_c"] == "pass"  # a length, measured absolutely: 6e-4 R < 1e-3 R
    assert verdicts["P/P_I"] == "info"


def test_default_not_the_finest():
    """Exact answer: with the default (32) inside the sequence, its error is |q(32) / q* - 1|."""
    def values(key, n):
        return 1.0 + n**-2.0

    study = _study(values, counts=(16, 32, 64), default=32)
    error, _ = study.default_error(("V", None))
    assert error == pytest.approx(32**-2.0, rel=1e-6)


def test_the_axes_refine_one_thing_each():
    """Exact answer: each axis's meshes vary its own entry and hold the others at the solid's defaults; the corner's
    refined count is 1 / its length (halving the length doubles it, as halving an element doubles a count)."""
    from pocket import solid

    default = (solid.DEFAULT_ELEMENTS, solid.DEFAULT_LAYERS, solid.DEFAULT_CORNER)
    for k, axis in enumerate(AXES):
        grid = solidstudy.meshes(axis, (1.0, 0.5, 0.25))
        assert all(m[:k] + m[k + 1:] == default[:k] + default[k + 1:] for m in grid)
        assert [m[k] for m in grid] == [1.0, 0.5, 0.25]
    study = Study(4, 0.08, 5.0, (0.1,), AXES[2], solidstudy.meshes(AXES[2], (1.0, 0.5, 0.25)), (), (), default)
    assert list(study.counts) == [1.0, 2.0, 4.0]


def test_rows_print_every_quantity_of_every_study():
    """Exact answer: one row per quantity and study, the values as given."""
    study = _study(lambda key, n: 2.0 + n**-2.0)
    header, rows = solidstudy.rows([study, study])
    assert len(rows) == 2 * len(list(study.quantities()))
    assert all(len(r) == len(header) for r in rows)
    assert rows[0][7] == ", ".join(f"{2.0 + n**-2.0:.8g}" for n in (16, 32, 64))
