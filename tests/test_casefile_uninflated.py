"""Case files of an uninflated capsule (``initial.pressure = "0 Pa"``, or its radius as ``initial.height``) and
``pocket run`` on them.

Its forces have no Fhat = F / (P_I pi R^2): the case's loads go to the solvers as F / (E T R). Every SI value is
checked here against the scale the test computes from the case's own inputs (E = 3 mu, so E T R = 3 x 1 MPa x
0.5 um x 50 um = 75 uN), and against identities that hold whatever the solver: F = P A_c on the flat plate, the
gap 2 H R, the unstressed sphere's height R and volume 4 pi R^3 / 3 at F = 0. Heights by the shooting solver and
forces by the finite elements cross-check each other.
"""

from __future__ import annotations

import csv
import functools
import json
import math

import meshio
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pocket.shooting.descent import branch_start

from pocket.apps import casefile
from pocket.apps.casefile import solved
from pocket.apps.cases import parse
from pocket.apps.physical import resolve
from pocket.apps.sense import sensitivity_at_rest
from pocket.cli import main
from pocket.core.errors import InputError, OutOfRangeError
from pocket.core.materials import check

R, T, MU = 50e-6, 0.5e-6, 1e6
NEO = check("neo-hookean", {"mu": 1.0})  # the case's rubber, in units of mu
ETR = 3.0 * MU * T * R  # E T R, N: the unit of an uninflated capsule's force
START = "is outside the capsule's range, whose states start deeper"

#: a 50 um capsule with a 0.5 um neo-Hookean wall (mu = 1 MPa), full of liquid at no pressure
UNINFLATED = {"geometry": "capsule", "sheet": {"thickness": "0.5 um", "material": "neo-hookean", "mu": "1 MPa"},
              "capsule": {"radius": "50 um"}, "initial": {"pressure": "0 Pa"},
              "loads": {"forces": ["0 uN", "0.5 uN", "5 uN", "20 uN"]}, "solver": {"name": "fem"}}


def _case(**change):
    return parse({**UNINFLATED, **change})


def test_a_case_presses_an_uninflated_capsule_by_forces_in_newtons():
    """Each force load is F / (E T R) to the solver: the rows report it as asked (``force_ETR``, and ``force_N``
    as given), with no Fhat or P / P_I. F = 0 is the unstressed sphere the plates touch (gap 2 R, volume
    4 pi R^3 / 3); 0.5 uN (0.0067 E T R) is short of where the states start (0.064 E T R for this rubber and a
    liquid, the capsule guide's table), so it is listed as not reached with the solver's reason; the others hold
    F = P A_c in SI to the finite elements' force check (relative 1e-8, far above its allowance)."""
    result, pocket, _ = solved(_case())
    assert pocket.pressure_initial == 0.0
    assert pocket.uninflated
    assert pocket.force_unit == "ETR"
    assert pocket.force_unit_N == pytest.approx(ETR, rel=1e-15)
    rows = result["states"]
    assert [row["load"] for row in rows] == ["0 uN", "5 uN", "20 uN"]
    for row, newtons in zip(rows, (0.0, 5e-6, 20e-6), strict=True):
        assert row["force_N"] == pytest.approx(newtons, rel=1e-15, abs=0.0)
        assert row["force_ETR"] == pytest.approx(newtons / ETR, rel=1e-14, abs=0.0)
        assert "force" not in row
        assert "pressure_ratio" not in row
        assert row["gap_m"] == pytest.approx(2.0 * row["height"] * R, rel=1e-14)
    sphere = rows[0]
    assert (sphere["gap_m"], sphere["contact_area_m2"], sphere["pressure_Pa"]) == (pytest.approx(2 * R, rel=1e-15),
                                                                                    0.0, 0.0)
    assert sphere["volume_m3"] == pytest.approx(4.0 * math.pi * R**3 / 3.0, rel=1e-9)
    for row in rows[1:]:
        assert row["pressure_Pa"] * row["contact_area_m2"] == pytest.approx(row["force_N"], rel=1e-8)
    (missed,) = result["unreachable"]
    assert (missed["load"], missed["force_N"]) == ("0.5 uN", 0.5e-6)
    assert missed["warnings"][0].startswith(f"loads.forces[1] = '0.5 uN' (F / (E T R) = {0.5e-6 / ETR:.10g}): "
                                            f"force_ETR = ")
    assert START in missed["warnings"][0]


def test_an_uninflated_capsule_by_its_radius_as_initial_height_is_the_same_case():
    """Exact answer: an initial height of R is the unstressed capsule, P_I = 0, pressed in the same unit E T R as
    "0 Pa"."""
    by_pressure, by_height = resolve(_case()), resolve(_case(initial={"height": "50 um"}))
    assert by_height.pressure_initial == by_pressure.pressure_initial == 0.0
    assert (by_height.force_unit, by_height.force_unit_N) == (by_pressure.force_unit, by_pressure.force_unit_N)


@pytest.mark.parametrize("solver", ["fem", "shooting"])
def test_heights_of_an_uninflated_capsule_cross_check_its_forces(solver):
    """Heights by a solver (each state solved at its height, to round-off), then the forces found as force loads by
    the finite elements: each comes back at its height within the finite elements' error, estimated as the shift
    from the mesh of half as many elements (the keys converge at least at first order; near the start of the states,
    where the contact edge's tension vanishes, only slowly: 1.5e-4 of the force at H/R = 0.78 on the default mesh).
    R is the unstressed sphere, force 0; 45 um lies above where the states start (H/R = 0.793 here), listed as not
    reached with the solver's reason."""
    heights = ["50 um", "45 um", "39 um", "30 um"]
    case = _case(loads={"heights": heights}, solver={"name": solver})
    result = solved(case)[0]
    rows = result["states"]
    assert [row["load"] for row in rows] == ["50 um", "39 um", "30 um"]
    assert rows[0]["force_N"] == 0.0
    for row, index in zip(rows, (0, 2, 3), strict=True):
        assert row["force_N"] == pytest.approx(row["force_ETR"] * ETR, rel=1e-14)
        assert row["height"] == pytest.approx(case.loads[index] / case.radius, rel=1e-13, abs=0.0)
    (missed,) = result["unreachable"]
    assert missed["warnings"][0].startswith("loads.heights[1] = '45 um' (H/R = 0.9): height = 0.9 ")
    assert START in missed["warnings"][0]
    forces = [f"{row['force_N']!r} N" for row in rows[1:]]
    back = solved(_case(loads={"forces": forces}))[0]["states"]
    elements = back[0]["elements"]
    coarse = solved(_case(loads={"forces": forces}, solver={"name": "fem", "elements": elements // 2}))[0]["states"]
    for row, half, height in zip(back, coarse, (39e-6, 30e-6), strict=True):
        assert abs(row["height_m"] - height) <= abs(row["height_m"] - half["height_m"])


def test_a_case_of_heights_solves_each_state_once(monkeypatch):
    """A height the solver holds itself is its state: no compression curve is asked for afterwards (at P_I = 0 the
    shooting solver's would find each height's force again as a root of its heights); forces are one curve."""
    asked = []
    real = casefile.entry
    monkeypatch.setattr(casefile, "entry", lambda solver, name, purpose: asked.append(name) or real(solver, name,
                                                                                                    purpose))
    solved(_case(loads={"heights": ["39 um", "30 um"]}))
    assert asked == []
    solved(_case(loads={"forces": ["5 uN", "20 uN"]}))
    assert asked == ["compression_curve"]


def test_a_flat_pocket_is_not_uninflated():
    """A pocket's sheet at no pressure is flat, with no state to press: its initial pressure must be > 0."""
    flat = {k: v for k, v in UNINFLATED.items() if k not in ("geometry", "capsule")}
    with pytest.raises(InputError, match=r"^initial.pressure = '0 Pa', but it must be > 0$"):
        parse({**flat, "clamp": {"radius": "20 mm"}})


def test_sensing_refuses_an_uninflated_capsule(tmp_path, capsys):
    """Sensing reads P / P_I and forces in units of P_I pi R^2: an uninflated capsule is one line, exit 2."""
    path = tmp_path / "squeeze.toml"
    path.write_text(_toml(UNINFLATED))
    assert main(["sense", str(path), "--pressure", "2 kPa"]) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert err.count("\n") == 1
    assert err.startswith("pocket: error: initial.pressure = '0 Pa' gives P_I = 0, an uninflated capsule")
    pocket = resolve(_case())
    with pytest.raises(InputError, match="an uninflated capsule: sensing reads"):
        sensitivity_at_rest(pocket)


def test_pocket_run_writes_an_uninflated_capsules_results_and_series(tmp_path, capsys):
    """The table shows F / (E T R) in place of Fhat and no P / P_I; the CSV's forces are as given; the ParaView
    series' times are the forces in N, and its field data hold no undefined Fhat or P / P_I (nor a force scale
    P_I pi R^2 = 0)."""
    path = tmp_path / "squeeze.toml"
    path.write_text(_toml({**UNINFLATED, "loads": {"forces": ["0 uN", "5 uN", "20 uN"]}}))
    assert main(["run", str(path), "--out", str(tmp_path / "out"), "--vtk", str(tmp_path / "vtk")]) == 0
    out = capsys.readouterr().out.splitlines()
    header = out[1].split()
    assert "force_ETR" in header
    assert "force" not in header
    assert "pressure_ratio" not in header
    rows = list(csv.DictReader((tmp_path / "out" / "squeeze.csv").open()))
    assert [float(row["force_N"]) for row in rows] == pytest.approx([0.0, 5e-6, 20e-6], rel=1e-15)
    series = (tmp_path / "vtk" / "surface.pvd").read_text()
    times = [float(line.split('timestep="')[1].split('"')[0]) for line in series.splitlines() if "timestep" in line]
    assert times == pytest.approx([0.0, 5e-6, 20e-6], rel=1e-15)
    mesh = meshio.read(tmp_path / "vtk" / "step_0002_surface.vtu")
    assert "force" not in mesh.field_data
    assert "pressure_ratio" not in mesh.field_data
    assert "force_scale_N" not in mesh.field_data
    assert mesh.field_data["force_ETR"][0] == pytest.approx(20e-6 / ETR, rel=1e-12)
    assert mesh.field_data["length_scale_m"][0] == pytest.approx(R, rel=1e-15)
    assert json.loads((tmp_path / "out" / "squeeze.json").read_text())["unreachable"] == []


def _toml(data: dict) -> str:
    """A case as TOML text: its top-level strings, then its tables of strings and lists of strings."""
    lines = [f"{key} = {json.dumps(value)}" for key, value in data.items() if not isinstance(value, dict)]
    for name, table in data.items():
        if isinstance(table, dict):
            lines += [f"[{name}]", *(f"{key} = {json.dumps(value)}" for key, value in table.items())]
    return "\n".join(lines) + "\n"


def test_the_built_in_uninflated_capsule_reaches_every_load(tmp_path, capsys):
    """``pocket run --example uninflated-capsule``: every force, 0 to 40 uN, lies past where the states start
    (0.064 E T R = 4.8 uN), so all five are solved; F = 0 is the unstressed sphere (gap 2 R), and the gap closes
    as the force grows."""
    assert main(["run", "--example", "uninflated-capsule", "--out", str(tmp_path)]) == 0
    capsys.readouterr()
    result = json.loads((tmp_path / "example_uninflated-capsule.json").read_text())
    rows = result["states"]
    assert [row["load"] for row in rows] == ["0 uN", "5 uN", "10 uN", "20 uN", "40 uN"]
    assert result["unreachable"] == []
    assert rows[0]["gap_m"] == pytest.approx(2 * R, rel=1e-15)
    gaps = [row["gap_m"] for row in rows]
    assert gaps == sorted(gaps, reverse=True)
    assert len(set(gaps)) == len(gaps)
    assert [row["force_ETR"] for row in rows] == pytest.approx([f * 1e-6 / ETR for f in (0, 5, 10, 20, 40)],
                                                               rel=1e-14)


@functools.cache
def _start_etr() -> float:
    """The least force of the uninflated capsule's states, F / (E T R), by the shooting solver (independent of the
    finite elements that solve the cases below)."""
    return branch_start(NEO, 0.0)[1]


@settings(max_examples=6, deadline=None)  # each example a case of up to four forces solved: about 0.4 s
@given(st.lists(st.one_of(st.just(0.0), st.floats(0.001, 0.063), st.floats(0.066, 1.0)), min_size=1, max_size=4))
def test_any_forces_on_an_uninflated_capsule_are_solved_or_listed_as_short_of_its_states(etrs):
    """Whatever the forces and their order (a force within 2 % of where the states start is not drawn: the two
    solvers place that start within 1e-4 of each other), each load is solved exactly when it is 0 or at least the
    least force of the states, else listed as not reached, short of them; every solved one holds F = P A_c, and a
    pressed one closes the gap below 2 R."""
    start = _start_etr()
    loads = [f"{etr * ETR * 1e6!r} uN" for etr in etrs]
    reached = [load for load, etr in zip(loads, etrs, strict=True) if etr == 0.0 or etr >= start]
    case = _case(loads={"forces": loads}, solver={"name": "fem", "elements": 64})
    if not reached:
        with pytest.raises(OutOfRangeError, match=START):
            solved(case)
        return
    result = solved(case)[0]
    assert [row["load"] for row in result["states"]] == reached
    assert [row["load"] for row in result["unreachable"]] == [load for load in loads if load not in reached]
    assert all(START in row["warnings"][0] for row in result["unreachable"])
    for row in result["states"]:
        if row["force_N"] > 0.0:
            assert row["pressure_Pa"] * row["contact_area_m2"] == pytest.approx(row["force_N"], rel=1e-8)
            assert row["gap_m"] < 2.0 * R
