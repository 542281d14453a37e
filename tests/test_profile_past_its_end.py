"""A profile whose range ends at its table's edge: a force past that end is refused by every solver.

Under a short table (its last radius small beside the contact the force wants) the range ends where the sheet's
contact edge reaches the table's last row (``pocket.shooting.surface``). Past its extent the shooting solver
reads the profile's curvature at the extent, so a state there solves with no failed step; it must be refused
all the same, as the finite elements refuse it: one line naming the end, exit 2, and no warning of a library
(the contact area's quadrature once ran past the table and warned). Below the end both solve and agree.
"""

from __future__ import annotations

import itertools
import re
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pocket.shooting.problem import CONTACTS

from pocket import fem, shooting
from pocket.cli import main
from pocket.core import profiles
from pocket.core.errors import OutOfRangeError
from pocket.core.indenters import Profile

ALPHA, PRESSURE = 47 / 160, 0.31
PAST = (1.007, 2.0)  # just past the end (beyond any solver's error on it) and well past
PROFILE_END = CONTACTS[Profile].END  # what the shooting solver calls the end at the table's edge
FE_END = "the sheet wraps past the end of the indenter's profile"


def _paraboloid_rows(extent: float = 0.3, rows: int = 20) -> np.ndarray:
    """z = rho^2 / 2 tabled up to ``extent`` (units R): a shallow tip whose range ends at its last row."""
    rho = np.linspace(0.0, extent, rows)
    return np.column_stack([rho, rho**2 / 2.0])


def _write(path, table: np.ndarray):
    path.write_text("radius [R],height [R]\n" + "".join(f"{r!r},{z!r}\n" for r, z in table.tolist()))
    return path


def _cli(capsys, argv) -> tuple[int, str, list]:
    """(exit status, stderr, the warnings raised) of ``pocket`` with ``argv``."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        status = main(argv)
    return status, capsys.readouterr().err, caught


@pytest.mark.parametrize("solver", ["shooting", "fem"])
@pytest.mark.parametrize("factor", PAST)
def test_a_force_past_a_short_profiles_end_is_one_line_exit_2(tmp_path, capsys, solver, factor):
    """z = rho^2/2 tabled to rho = 0.3 R: the shooting solver's range end (``range_end``, computed here) is where
    the contact edge reaches the last row (the state at the end has rho_c = 0.3, to the shots' error). At 1.007
    and 2 times that force each solver exits 2 with one line on stderr that names the end and a force there, and
    no warning of any kind, and writes nothing. The shooting solver quotes ``range_end`` to its 10 digits; the FE
    the last state it reached, whose contact edge is within 1e-3 of the last row (its refusal's condition, the
    edge quoted too) and whose force is below the end (to 1e-6: the FE's states at its default mesh are within
    1e-8 of shooting's here, and the force rises with the contact edge)."""
    table = _paraboloid_rows()
    indenter = Profile(profiles.table(*table.T))
    end = shooting.range_end(ALPHA, PRESSURE, indenter=indenter)
    at_end = shooting.compress(ALPHA, PRESSURE, end, indenter=indenter)
    assert at_end.contact_radius_deformed == pytest.approx(table[-1, 0], rel=1e-6)
    path = _write(tmp_path / "t.csv", table)
    status, err, caught = _cli(capsys, ["compress", "--alpha", "47/160", "--pressure", repr(PRESSURE),
                                        "--indenter", "profile", "--indenter-file", str(path),
                                        "--solver", solver, "--force", repr(end * factor)])
    assert status == 2, err
    assert err.count("\n") == 1, err
    assert err.startswith("pocket: error: force = "), err
    assert not caught, [str(w.message) for w in caught]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["t.csv"]
    if solver == "shooting":
        assert f"ends at force = {end:.10g}" in err, err
        assert PROFILE_END in err, err
    else:
        quoted = re.search(r"ends near force = ([0-9.eE+-]+): .*rho_c/R = ([0-9.eE+-]+) of", err)
        assert FE_END in err, err
        assert float(quoted.group(1)) <= end * (1.0 + 1e-6), err
        assert float(quoted.group(2)) >= (1.0 - 1e-3) * table[-1, 0], err


def test_height_below_a_short_profiles_end_is_refused_naming_the_end():
    """Travel control under the same table: a height 1e-3 below the height at the end (the state at ``range_end``)
    is out of range, the message quoting that end force; a height just above it solves, its force below the end
    (the height falls strictly with the force along the branch)."""
    indenter = Profile(profiles.table(*_paraboloid_rows().T))
    end = shooting.range_end(ALPHA, PRESSURE, indenter=indenter)
    lowest = shooting.compress(ALPHA, PRESSURE, end, indenter=indenter).height
    with pytest.raises(OutOfRangeError, match=re.escape(f"force = {end:.10g}")):
        shooting.compress_height(ALPHA, PRESSURE, lowest * (1.0 - 1e-3), indenter=indenter)
    assert shooting.compress_height(ALPHA, PRESSURE, lowest * (1.0 + 1e-3), indenter=indenter).force < end


def test_a_curve_crossing_a_short_profiles_end_is_refused_whole():
    """``compression_curve`` with one force below the end and one past it: an OutOfRangeError naming the end (no
    list with a state past it), while the force below alone solves with its contact edge inside the table."""
    table = _paraboloid_rows()
    indenter = Profile(profiles.table(*table.T))
    end = shooting.range_end(ALPHA, PRESSURE, indenter=indenter)
    with pytest.raises(OutOfRangeError, match=re.escape(PROFILE_END)):
        shooting.compression_curve(ALPHA, PRESSURE, [0.5 * end, 1.5 * end], indenter=indenter)
    assert shooting.compress(ALPHA, PRESSURE, 0.5 * end, indenter=indenter).contact_radius_deformed < table[-1, 0]


@pytest.mark.slow
@pytest.mark.parametrize("solver", [shooting, fem], ids=["shooting", "fem"])
def test_the_contact_area_on_a_table_of_many_rows_warns_nothing(solver):
    """A rounded cone z = sqrt(b^2 + s^2 rho^2) - b tabled in 37 rows to its end (b = 0.04, s = 0.8, rows b / (6 s)
    apart): at 0.99 of the range end the state's curved contact area, 2 int_0^rho_c rho sqrt(1 + z'^2) drho of the
    table's spline, is returned with no warning (one adaptive quadrature across the rows once stalled and warned),
    and equals the same integral by 20-point Gauss-Legendre on each row interval, where the spline is smooth
    (exact there to round-off: the integrand is analytic on each interval, far from its singularities), for
    each solver at its own contact edge."""
    b, s, extent = 0.04, 0.8, 0.3
    rho = np.linspace(0.0, extent, 37)
    shape = profiles.table(rho, np.sqrt(b * b + (s * rho) ** 2) - b)
    indenter = Profile(shape)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        state = solver.compress(ALPHA, PRESSURE, 0.99 * shooting.range_end(ALPHA, PRESSURE, indenter=indenter),
                                indenter=indenter)
    assert not caught, [str(w.message) for w in caught]
    edge = state.contact_radius_deformed
    bounds = np.append(rho[rho < edge], edge)
    nodes, weights = np.polynomial.legendre.leggauss(20)
    area = 0.0
    for lo, hi in itertools.pairwise(bounds):
        r = 0.5 * (hi - lo) * nodes + 0.5 * (hi + lo)
        area += 0.5 * (hi - lo) * float(np.sum(weights * r * np.sqrt(1.0 + shape.slope(r) ** 2)))
    assert state.contact_area == pytest.approx(2.0 * area, rel=1e-12)


# -- over random short tables -------------------------------------------------------------------------------

SCALARS = ("height", "pressure", "volume", "contact_area", "contact_radius", "contact_radius_deformed",
           "contact_pressure_pole", "contact_pressure_edge")
ELEMENTS = 128  # and half as many: the FE's change between the two bounds its error (below)
SHOTS = 1e-9  # the shots' own error on these scalars at rtol 1e-10 (test_shooting_profile: a table solved
# at rtol 1e-10 stays within 1e-9 of the same table at 1e-12)


@st.composite
def short_tables(draw) -> np.ndarray:
    """Rows (rho, z) of a convex tip flat on the axis, tabled to a small extent: z = c1 rho^2 + c2 rho^4 + c3 rho^6
    (c1 > 0, c2, c3 >= 0), from a paraboloid (c2 = c3 = 0) to a tip steepening outwards. z = g(rho^2) with g a
    cubic, which the table's not-a-knot spline of g reproduces exactly (``pocket.core.profiles``): both solvers
    see one smooth surface, so the FE converges at its elements' full order (a general table's spline has its
    third derivative jump at rows the FE's elements straddle, and its error there does not fall steadily)."""
    extent, rows = draw(st.floats(0.12, 0.3)), draw(st.integers(5, 25))
    c1, c2, c3 = draw(st.floats(0.25, 1.5)), draw(st.floats(0.0, 10.0)), draw(st.floats(0.0, 50.0))
    rho = np.linspace(0.0, extent, rows)
    s = rho**2
    return np.column_stack([rho, s * (c1 + s * (c2 + s * c3))])


def _worst(states, reference) -> float:
    """The largest relative difference over SCALARS and the states of two curves."""
    return max(abs(getattr(s, k) / getattr(r, k) - 1.0) for s, r in zip(states, reference, strict=True)
               for k in SCALARS)


@pytest.mark.slow
@settings(max_examples=10, deadline=None)
@given(short_tables(), st.floats(0.2, 0.95))
def test_both_solvers_solve_below_a_short_profiles_end_and_refuse_past_it(table, fraction):
    """For a short table whose range ends at its last row (asserted: the state at ``range_end`` has its contact
    edge there, to the shots' error), forces at ``fraction`` and 0.99 of the end solve in both solvers and
    agree: the FE at ELEMENTS elements within its own change from ELEMENTS / 2 (for a discretisation converging
    at order p >= 1, error(N) = change / (2^p - 1) <= change; P2 elements on a smooth surface converge at order 4,
    the change falling 16-fold per doubling) plus the shots' error SHOTS. Both read the same spline of the table,
    so nothing else separates them. At 1.007 and 2 times the end both raise OutOfRangeError; no warning at all."""
    indenter = Profile(profiles.table(*table.T))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        end = shooting.range_end(ALPHA, PRESSURE, indenter=indenter)
        forces = sorted({fraction * end, 0.99 * end})
        edge = shooting.compress(ALPHA, PRESSURE, end, indenter=indenter).contact_radius_deformed
        assert edge == pytest.approx(table[-1, 0], rel=1e-6)
        ref = shooting.compression_curve(ALPHA, PRESSURE, forces, indenter=indenter)
        fine, coarse = (fem.compression_curve(ALPHA, PRESSURE, forces, indenter=indenter, elements=n)
                        for n in (ELEMENTS, ELEMENTS // 2))
        change, error = _worst(coarse, fine), _worst(fine, ref)
        print(f"end {end!r}: FE against shooting {error:.2e}, FE's change from {ELEMENTS // 2} elements {change:.2e}")
        assert error <= change + SHOTS
        for factor in PAST:
            for solve in (shooting.compress, fem.compress):
                with pytest.raises(OutOfRangeError):
                    solve(ALPHA, PRESSURE, factor * end, indenter=indenter)
    assert not caught, [str(w.message) for w in caught]
