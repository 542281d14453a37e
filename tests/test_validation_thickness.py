"""The membrane-vs-solid table's uncertainty column (``pocket.validation.thickness``), on comparisons built here.

Exact answers: a comparison whose solid moves from s to s' on the refined mesh has, for a membrane value m, the
uncertainty |m / s' - m / s| (computed here from the numbers built in); without the refined solve the table says
'-' and the verdict states no uncertainty; the verdict's largest error carries the uncertainty of that same entry.
"""

import math

import pytest
from pocket.validation import thickness
from pocket.validation.thickness import Comparison

FORCES = (0.2, 0.5)


def _comparison(refined: bool) -> Comparison:
    """Sample 4 with V 26 % off (the solid 1.0, on the refined mesh 1.001) and A_c 40 % and 30 % off (the solid
    0.5 and 0.6, refined 0.499 and 0.6006); every other quantity exact."""
    values = {(q, None): (1.0, 1.0) for q in thickness.INFLATION}
    values["V", None] = (1.26, 1.0)
    for f in FORCES:
        values.update({(q, f): (1.0, 1.0) for q in thickness.COMPRESSION})
    values["A_c", 0.2] = (0.7, 0.5)
    values["A_c", 0.5] = (0.78, 0.6)
    fine = {key: solid for key, (_, solid) in values.items()}
    fine.update({("V", None): 1.001, ("A_c", 0.2): 0.499, ("A_c", 0.5): 0.6006})
    return Comparison(4, 0.08, 5.0, 0.05, FORCES, values, 0.0, fine if refined else {})


def test_the_uncertainty_is_the_error_s_change_on_the_refined_mesh():
    c = _comparison(refined=True)
    assert c.uncertainty("V") == pytest.approx(abs(1.26 / 1.001 - 1.26 / 1.0), rel=1e-12)
    assert c.uncertainty("A_c", 0.2) == pytest.approx(abs(0.7 / 0.499 - 0.7 / 0.5), rel=1e-12)
    assert c.uncertainty("P/P_I", 0.5) == 0.0
    header, rows = thickness.rows([c])
    column = header.index("+/- (solid's mesh)")
    row = next(r for r in rows if r[4] == "A_c" and r[3] == "0.2")
    assert float(row[column]) == pytest.approx(abs(0.7 / 0.499 - 0.7 / 0.5), rel=1e-1)  # printed to 2 digits
    # the largest A_c error is the 40 % at Fhat = 0.2: its own uncertainty, 0.28 %, stands beside it
    sentence = next(s for s in thickness.verdict([c]) if s.startswith("A_c: "))
    assert sentence.endswith(f"(largest error 40.00% +/- {100 * abs(0.7 / 0.499 - 0.7 / 0.5):.1g}% (the solid's "
                             "mesh)).")


def test_without_the_refined_solve_no_uncertainty_is_stated():
    c = _comparison(refined=False)
    assert math.isnan(c.uncertainty("V"))
    header, rows = thickness.rows([c])
    assert {r[header.index("+/- (solid's mesh)")] for r in rows} == {"-"}
    sentence = next(s for s in thickness.verdict([c]) if s.startswith("V: "))
    assert sentence.endswith("(largest error 26.00%).")
