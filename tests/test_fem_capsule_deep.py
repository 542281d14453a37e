"""The finite-element capsule deep in its compression: the second branch of a low P_I, and the uninflated capsule.

Pressed from the touch, a neo-Hookean capsule at Phat_I = 0.01 ends its first branch at Fhat ~ 0.15 (the contact
edge's meridional tension vanishing, ``tests/test_fem_capsule_end.py``); deeper its states resume, and an uninflated
capsule (P_I = 0) has only those. ``pocket.fem.descent`` reaches them from Phat_I = 0.1 at a fixed plate height,
lowering the sealed fluid. What is checked: the uninflated state's own balances (its volume the unstressed sphere's,
F = P A_c, Fhat and P / P_I not reported), that it is the limit of inflated capsules as P_I -> 0, the start of its
range where the edge's tension vanishes, the gap between a low P_I's two branches refused with both ends, force
and height control inverse to each other on the deep branch, and the command line.
"""

from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest
from pocket.fem import descent

from pocket import fem
from pocket.cli import main
from pocket.core.errors import CAPSULE_EDGE, UNINFLATED_CAPSULE, InputError, OutOfRangeError, exit_status
from pocket.core.fluids import gas
from pocket.core.states import UNINFLATED_UNDEFINED

RUBBER = 0.0  # neo-Hookean (Mooney-Rivlin alpha = 0)
ELEMENTS = 32  # a coarse mesh: what is checked here holds on any mesh
DEEP = 0.6  # a plate height on the uninflated capsule's branch (its start is near 0.79)
KEYS = ("pressure", "height", "volume", "contact_area", "contact_radius", "contact_radius_deformed", "stretch_pole",
        "radius_equator")


def _key(state, key: str) -> float:
    return float(state.extra[key]) if key in state.extra else float(getattr(state, key))


def _uninflated(height: float = DEEP, **options):
    return fem.compress_height(RUBBER, 0.0, height, geometry="capsule", elements=ELEMENTS, **options)


def test_the_uninflated_capsule_keeps_its_volume_and_its_plates_carry_p_times_a():
    """At P_I = 0 the liquid keeps the unstressed sphere's volume (the finite elements' own, that of the inflated
    state at Phat = 0), each plate carries F = P A_c (``force_ETR`` = pi P rho_c^2 and the plate's reaction), and
    the keys undefined without P_I (Fhat, P / P_I) are NaN and not reported."""
    state = _uninflated()
    assert state.pressure_initial == 0.0
    assert abs(state.volume / state.inflated.volume - 1.0) < 1e-9
    assert abs(state.inflated.volume / (4.0 / 3.0 * math.pi) - 1.0) < 1e-6  # the discrete sphere, P2 elements
    assert state.height == DEEP
    force = state.extra["force_ETR"]
    assert abs(force / (math.pi * state.pressure * state.contact_area) - 1.0) < 1e-12
    assert abs(state.extra["force_reaction"] / force - 1.0) < 1e-8
    assert all(math.isnan(getattr(state, key)) for key in UNINFLATED_UNDEFINED)
    assert not set(UNINFLATED_UNDEFINED) & set(state.scalars())


def test_the_uninflated_capsule_is_the_limit_of_inflated_ones():
    """At a fixed plate height the state is a smooth function of Phat_I (the deep branch is regular there), so
    s(p) = s(0) + s1 p + s2 p^2 + O(p^3): the linear extrapolation from p and 2p, 2 s(p) - s(2p), misses s(0) by
    -2 s2 p^2, which the second difference s(3p) - 2 s(2p) + s(p) = 2 s2 p^2 measures. So the state solved at
    P_I = 0 must lie within that (twice: the cubic terms) of the extrapolation, plus Newton's noise. The steps are
    not small: an inflated capsule's discrete sphere is stiffened only by its tension, ~ p, against the mesh's
    misfit of the sphere, so its volume is off the closed form by a relative 3e-6 at p = 2e-3 on this mesh (2e-7 at
    1e-2), which would swamp the second difference of smaller steps."""
    p = 1e-2
    at = {k: fem.compress_height(RUBBER, k * p, DEEP, geometry="capsule", elements=ELEMENTS) for k in (1, 2, 3)}
    zero = _uninflated()
    for key in KEYS:
        (s1, s2, s3), s0 = (_key(at[k], key) for k in (1, 2, 3)), _key(zero, key)
        extrapolated = 2.0 * s1 - s2
        second = abs(s3 - 2.0 * s2 + s1)
        print(f"{key}: P_I = 0 {s0!r}, extrapolated {extrapolated!r}, second difference {second:.2e}")
        assert abs(extrapolated - s0) <= 2.0 * second + 1e-9 * max(1.0, abs(s0)), key


def test_the_uninflated_range_starts_where_the_edge_tension_vanishes():
    """A height above the uninflated capsule's range is refused, its start quoted as a bracket of heights [beyond,
    reached] below the height asked; at the reached height the state solves with a small positive tension at the
    contact edge, and the height beyond it is refused in turn."""
    with pytest.raises(OutOfRangeError) as refused:
        _uninflated(0.9)
    message = str(refused.value)
    found = re.fullmatch(r"height = 0\.9 is outside the capsule's range, whose states start deeper, at plate height "
                         r"h/R = (\S+) to (\S+) \(.*\): before it " + re.escape(CAPSULE_EDGE), message)
    assert found, message
    reached, beyond = (float(v) for v in found.groups())
    assert reached < beyond < 0.9
    start = _uninflated(reached)
    edge = start.profile.tension_1[np.flatnonzero(start.profile.contact)[-1]]
    deep = _uninflated().profile
    assert 0.0 < edge < 0.01 * deep.tension_1[np.flatnonzero(deep.contact)[-1]]
    with pytest.raises(OutOfRangeError, match=re.escape(CAPSULE_EDGE)):
        _uninflated(beyond)


def test_force_control_at_p_i_zero_is_refused_saying_why():
    """Fhat = F / (P_I pi R^2) has no meaning at P_I = 0: force control is an InputError naming the plates'
    height instead."""
    with pytest.raises(InputError, match=f"^pressure = 0: {re.escape(UNINFLATED_CAPSULE)}$"):
        fem.compress(RUBBER, 0.0, 1.0, geometry="capsule", elements=ELEMENTS)


def test_a_low_pressures_deep_branch_inverts_force_and_height_control():
    """At Phat_I = 0.01 a force past the first branch's end and past the gap (Fhat = 3) is solved deep; the plates'
    height it finds, given back, finds its force again (to Newton's tolerance, relative 1e-8), and the state
    echoes its P_I and carries F = P A_c."""
    state = fem.compress(RUBBER, 0.01, 3.0, geometry="capsule", elements=ELEMENTS)
    assert state.height < 0.9  # deeper than the first branch's end (0.947)
    back = fem.compress_height(RUBBER, 0.01, state.height, geometry="capsule", elements=ELEMENTS)
    assert abs(back.force / 3.0 - 1.0) < 1e-8
    assert abs(state.pressure_ratio * state.contact_area / 3.0 - 1.0) < 1e-12


def test_a_height_between_the_branches_is_refused_with_both_ends():
    """At Phat_I = 0.01 a height between the branches is refused in one line quoting the first branch's end above
    it and the deep branch's start below it, each a bracket, and a curve crossing the gap from both sides solves
    each force on its own branch (the curve's forces in any order)."""
    with pytest.raises(OutOfRangeError) as refused:
        fem.compress_height(RUBBER, 0.01, 0.9, geometry="capsule", elements=ELEMENTS)
    message = str(refused.value)
    found = re.fullmatch(r"height = 0\.9 lies between the capsule's two branches of states: the one pressed from the "
                         r"touch ends at plate height h/R = (\S+) to (\S+) \(.*\), the one reached deeper starts at "
                         r"plate height h/R = (\S+) to (\S+) \(.*\); between them " + re.escape(CAPSULE_EDGE), message)
    assert found, message
    end_reached, end_beyond, start_reached, start_beyond = (float(v) for v in found.groups())
    assert start_reached < start_beyond < 0.9 < end_beyond < end_reached
    deep, near = fem.compression_curve(RUBBER, 0.01, [3.0, 0.1], geometry="capsule", elements=ELEMENTS)
    assert deep.height < start_reached
    assert near.height > end_reached
    assert deep.force == 3.0
    assert near.force == 0.1


def test_the_descent_starts_from_a_capsule_whose_branch_has_no_end():
    """The anchor of the descent is pressed from the touch to its deep height without meeting an end."""
    anchor = fem.compress_height(RUBBER, descent.ANCHOR, descent.DEEP, geometry="capsule", elements=ELEMENTS)
    assert anchor.height == descent.DEEP


def test_the_command_line_presses_an_uninflated_capsule_by_its_height(capsys):
    """``pocket compress --pressure 0 --height`` prints the state, F / (E T R) its force and no Fhat; ``--force``
    at P_I = 0 is one line on stderr, exit 2."""
    args = ["compress", "--geometry", "capsule", "--solver", "fem", "--law", "neo-hookean", "--mu", "1",
            "--pressure", "0", "--elements", str(ELEMENTS)]
    assert main([*args, "--height", str(DEEP), "--json"]) == 0
    row = json.loads(capsys.readouterr().out)
    assert row["pressure_initial"] == 0.0
    assert row["force_ETR"] > 0.0
    assert "force" not in row
    assert "pressure_ratio" not in row
    status = main([*args, "--force", "1"])
    out, err = capsys.readouterr()
    assert status == exit_status(InputError("")) == 2
    assert out == ""
    assert err.count("\n") == 1
    assert UNINFLATED_CAPSULE in err


def test_a_soft_gas_starts_its_range_below_the_descents_height():
    """A gas with a low ambient pressure (Phat_atm = 0.5, isothermal) is squeezed to a pressure too low to hold the
    edge at ``descent.DEEP``: the descent lowers the fluid at half that height, and a height above the range's
    start is refused quoting it (below ``DEEP``); below the start the state solves, holding the gas law
    (P + P_atm) V = P_atm V_0 with V_0 the unstressed sphere's."""
    air = gas(0.5, 1.0)
    with pytest.raises(OutOfRangeError) as refused:
        fem.compress_height(RUBBER, 0.0, 0.6, geometry="capsule", fluid=air, elements=ELEMENTS)
    found = re.search(r"start deeper, at plate height h/R = (\S+) to ", str(refused.value))
    assert found, str(refused.value)
    start = float(found.group(1))
    assert descent.DEEPEST < start < descent.DEEP
    state = fem.compress_height(RUBBER, 0.0, start - 0.01, geometry="capsule", fluid=air, elements=ELEMENTS)
    assert abs((state.pressure + air.ambient) * state.volume / (air.ambient * state.inflated.volume) - 1.0) < 1e-9


def test_an_uninflated_capsule_under_a_force_in_units_of_etr():
    """``force_unit="ETR"``: at P_I = 0 the state carries the force asked, F / (E T R), its plate's reaction
    agreeing (Newton's tolerance, relative 1e-8), and the height it finds gives the force back by height control; a
    force below the range's start is refused quoting the start; at P_I > 0 the same forces are Fhat = F / (E T R) /
    (pi Phat_I)."""
    state = fem.compress(RUBBER, 0.0, 0.5, geometry="capsule", force_unit="ETR", elements=ELEMENTS)
    assert state.extra["force_ETR"] == 0.5
    assert abs(state.extra["force_reaction"] / 0.5 - 1.0) < 1e-8
    assert abs(_uninflated(state.height).extra["force_ETR"] / 0.5 - 1.0) < 1e-8
    with pytest.raises(OutOfRangeError, match=r"^force_ETR = 0\.01 is outside the capsule's range, whose states "
                                              r"start deeper, at plate force F/\(E T R\) = "):
        fem.compress(RUBBER, 0.0, 0.01, geometry="capsule", force_unit="ETR", elements=ELEMENTS)
    inflated = fem.compress(RUBBER, 0.2, 0.5, geometry="capsule", force_unit="ETR", elements=ELEMENTS)
    assert inflated.force == 0.5 / (math.pi * 0.2)
    assert abs(inflated.extra["force_ETR"] / 0.5 - 1.0) < 1e-15


def test_the_command_line_presses_an_uninflated_capsule_by_a_force_in_etr(capsys):
    """``--force-etr`` at ``--pressure 0``: a state per force, each reporting the force asked; with a solver that
    does not press an uninflated capsule, one line and exit 2."""
    args = ["compress", "--geometry", "capsule", "--law", "neo-hookean", "--mu", "1", "--pressure", "0"]
    assert main([*args, "--solver", "fem", "--elements", str(ELEMENTS), "--force-etr", "0.5", "1", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert [row["force_ETR"] for row in rows] == [0.5, 1.0]
    assert main([*args, "--solver", "analytical", "--force-etr", "0.5"]) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert err.count("\n") == 1
    assert "--force-etr" in err


def test_a_refused_force_etr_at_a_positive_pressure_is_said_as_given(capsys):
    """At P_I > 0 ``--force-etr`` forces go to the solver as Fhat = F / (E T R) / (pi Phat_I): a refusal names the
    values given and the Fhat each is (computed here), before the solver's reason; one line, exit 2."""
    assert main(["compress", "--alpha", "0.2", "--pressure", "0.31", "--force-etr", "100"]) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert err.count("\n") == 1
    fhat = 100 / (math.pi * 0.31)
    assert err.startswith(f"pocket: error: --force-etr 100 at --pressure 0.31 are Fhat = F / (E T R) / (pi Phat_I) "
                          f"= {fhat:.10g}: force = {fhat!r} is beyond the model's range")
