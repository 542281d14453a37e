"""Case files of a capsule (``geometry = "capsule"`` and ``[capsule] radius``), the built-in example capsule, and
``pocket run`` on them: the results in SI units, the gap between the plates 2 H R and the force on each plate.

The run's plumbing is checked with a stand-in for the analytical solver's entry points (``capsulestates``:
hand-built states), so that every SI value is computed here from the state the entry point returned and the
case's scales (P = Phat E T / R, F = Fhat P_I pi R^2, lengths x R); where the shooting solver poses the capsule,
the run is checked against its Python API.
"""

from __future__ import annotations

import csv
import json
import math

import capsulestates
import pytest
from capsulestates import stood_in

from pocket import shooting
from pocket.apps.casefile import solved
from pocket.apps.cases import capsule_example, example, parse
from pocket.apps.columns import column
from pocket.apps.physical import resolve
from pocket.cli import main
from pocket.core.errors import CAPSULE_EDGE, InputError
from pocket.core.geometries import CAPSULE, DISC

#: a 50 um capsule with a 0.5 um wall (neo-Hookean, mu = 1 MPa: E = 3 MPa) at P_I = 3 kPa
CAPSULE_CASE = {"geometry": "capsule", "sheet": {"thickness": "0.5 um", "material": "neo-hookean", "mu": "1 MPa"},
                "capsule": {"radius": "50 um"}, "initial": {"pressure": "3 kPa"},
                "loads": {"forces": ["2 uN", "5 uN"]}}


@pytest.fixture
def stand_in(monkeypatch):
    """The analytical solver's entry points replaced by hand-built capsule states (``capsulestates.stand_in``)."""
    return capsulestates.stand_in(monkeypatch)


def test_a_capsule_case_has_its_geometry_and_radius():
    """Exact answers: ``geometry = "capsule"`` with ``[capsule] radius = "50 um"`` is the capsule of R = 50 um, its
    radius's key capsule.radius; a case without ``geometry`` is the flat pocket of its clamp's radius; both name
    their geometry in the results' case."""
    case = parse(CAPSULE_CASE)
    assert (case.geometry, case.radius, case.thickness) == (CAPSULE, pytest.approx(50e-6, rel=1e-15), 0.5e-6)
    assert case.radius_key == "capsule.radius"
    assert case.as_given("capsule.radius") == "50 um"
    assert case.fields()["geometry"] == "capsule"
    pocket = parse({**{k: v for k, v in CAPSULE_CASE.items() if k not in ("geometry", "capsule")},
                    "clamp": {"radius": "20 mm"}})
    assert (pocket.geometry, pocket.radius_key, pocket.fields()["geometry"]) == (DISC, "clamp.radius", "pocket")


@pytest.mark.parametrize(("change", "message"), [
    ({"geometry": "torus"}, "case: geometry = 'torus', but it must be one of pocket, capsule"),
    ({"geometry": 1}, "case: geometry = 1, but it must be one of pocket, capsule"),
    ({"clamp": {"radius": "20 mm"}}, "case: [clamp] holds a pocket's radius, but the case is a capsule "
                                     "(geometry = 'capsule'), whose radius is [capsule] radius"),
    ({"geometry": "pocket"}, "case: [capsule] holds a capsule's radius, but the case is a pocket "
                             "(geometry = 'pocket'), whose radius is [clamp] radius"),
    ({"capsule": {"radius": "50 um", "height": "1 mm"}}, "case: unknown key 'capsule.height' (known: radius)"),
    ({"capsule": {"radius": "5 kPa"}}, "capsule.radius = '5 kPa' has dimension"),
    ({"sheet": {"thickness": "30 um", "material": "neo-hookean", "mu": "1 MPa"}},
     "sheet.thickness = '30 um' on capsule.radius = '50 um': the sheet's thickness is 0.6 times"),
], ids=["unknown", "not-text", "clamp", "capsule-of-a-pocket", "unknown-key", "dimension", "thick"])
def test_a_bad_capsule_case_is_one_line(change, message):
    """Exact answers: an unknown geometry, the radius table of the other geometry, an unknown key of
    ``[capsule]``, a radius that is no length, and a wall too thick for a membrane are each one InputError
    naming the key, before any solver runs."""
    with pytest.raises(InputError) as caught:
        parse({**CAPSULE_CASE, **change})
    assert str(caught.value).startswith(message)
    assert "\n" not in str(caught.value)


def test_a_capsule_case_without_its_radius_is_refused():
    """Exact answer: a capsule case without ``[capsule]`` misses that table, as a pocket's misses ``[clamp]``."""
    with pytest.raises(InputError, match=r"^case: missing key 'capsule'$"):
        parse({k: v for k, v in CAPSULE_CASE.items() if k != "capsule"})


def test_the_built_in_capsule_is_a_microcapsule_at_phat_a_tenth():
    """Exact answers: the example capsule is R = 50 um with a 0.5 um wall, E = 3 mu = 3 MPa, so that its P_I = 3 kPa
    is Phat_I = P_I R / (E T) = 0.1 (computed here from its SI values); ``example("capsule")`` is it, another name
    is one line."""
    case = capsule_example()
    assert case.geometry is CAPSULE
    assert case.initial[1] * case.radius / (case.modulus * case.thickness) == pytest.approx(0.1, rel=1e-14)
    assert example("capsule") == case
    with pytest.raises(InputError, match=r"^example = 'torus', but the built-in examples are capsule, "
                                         r"uninflated-capsule$"):
        example("torus")


def test_the_case_gives_the_solver_the_capsule_at_each_step(stand_in):
    """Exact answers: the inflation, the range's end and the compression curve are each given ``geometry`` = the
    capsule, the forces as Fhat = F / (P_I pi R^2) with F on each plate."""
    case = parse({**CAPSULE_CASE, "solver": {"name": "analytical"}})
    _, pocket, states = solved(case)
    assert {name for name, _ in stand_in} == {"inflate", "range_end", "compression_curve"}
    assert all(options["geometry"] is CAPSULE for _, options in stand_in)
    scale = 3e3 * math.pi * case.radius**2
    assert pocket.force_scale_N == pytest.approx(scale, rel=1e-15)
    assert [s.force for s in states] == [f / pocket.force_scale_N for f in case.loads]
    assert case.loads == pytest.approx((2e-6, 5e-6), rel=1e-15)


def test_run_writes_the_capsules_results_in_si(tmp_path, capsys, stand_in):
    """Exact answers, from the states the stand-in returned and the case's scales (E T / R = 30 kPa,
    P_I pi R^2, R): each row's force_N is the force asked on each plate, pressure_Pa = Phat E T / R, gap_m = 2 H R,
    height_m = H R, radius_equator_m = rho_eq R, volume_m3 = V R^3, contact_radius_deformed_m = rho_c R; the
    dimensionless keys are the state's (its capsule's keys among them); every column is documented; the
    inflated row's gap is the sphere's height 2 lambda R; the printed table shows the gap."""
    path = tmp_path / "squeeze.toml"
    path.write_text('geometry = "capsule"\n[sheet]\nthickness = "0.5 um"\nmaterial = "neo-hookean"\nmu = "1 MPa"\n'
                    '[capsule]\nradius = "50 um"\n[initial]\npressure = "3 kPa"\n[loads]\nforces = ["2 uN", "5 uN"]\n'
                    '[solver]\nname = "analytical"\n')
    assert main(["run", str(path), "--out", str(tmp_path / "out")]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[0].startswith(f"# {path}: a capsule, solver analytical")  # the case's name
    assert "gap_m" in out.splitlines()[1].split()
    result = json.loads((tmp_path / "out" / "squeeze.json").read_text())
    case = parse({**CAPSULE_CASE, "solver": {"name": "analytical"}})
    r, stress = case.radius, case.modulus * case.thickness / case.radius
    force_scale = resolve(case).force_scale_N
    assert force_scale == pytest.approx(3e3 * math.pi * r**2, rel=1e-15)
    states = stood_in([f / force_scale for f in case.loads])
    for row, state, force in zip(result["states"], states, case.loads, strict=True):
        assert row["force_N"] == force
        assert row["pressure_Pa"] == pytest.approx(state.pressure * stress, rel=1e-14)
        assert row["gap_m"] == pytest.approx(2.0 * state.height * r, rel=1e-14)
        assert row["height_m"] == pytest.approx(state.height * r, rel=1e-14)
        assert row["radius_equator_m"] == pytest.approx(state.extra["radius_equator"] * r, rel=1e-14)
        assert row["volume_m3"] == pytest.approx(state.volume * r**3, rel=1e-14)
        assert row["contact_radius_deformed_m"] == pytest.approx(state.contact_radius_deformed * r, rel=1e-14)
        for key in ("geometry", "stretch_pole", "radius_equator", "force_ETR", "pressure_ratio", "contact_area"):
            assert row[key] == state.scalars()[key], key
        assert "volume_lower_m3" not in row
    assert result["inflated"]["gap_m"] == pytest.approx(2.0 * capsulestates.STAND_IN_STRETCH * r, rel=1e-14)
    assert result["case"]["geometry"] == "capsule"
    with (tmp_path / "out" / "squeeze.csv").open() as f:
        header = next(csv.reader(f))
    assert all(column(name) for name in header)
    assert {"gap_m", "radius_equator_m", "force_ETR"} <= set(header)


@pytest.mark.slow  # 2.5 s: the end of the capsule's range (checked for each force load) is a second of solves
def test_the_example_capsule_runs_by_the_shooting_solver(tmp_path, capsys):
    """Exact answer: ``pocket run --example capsule`` writes, for each load, the state of the shooting solver's
    Python API at the case's Phat_I and Fhat with the capsule, in SI (P = Phat E T / R, gap 2 H R)."""
    if not _poses_capsule():
        pytest.skip("the shooting solver does not pose the capsule yet")
    assert main(["run", "--example", "capsule", "--out", str(tmp_path)]) == 0
    result = json.loads((tmp_path / "example_capsule.json").read_text())
    pocket = resolve(capsule_example())
    forces = [row["force"] for row in result["states"]]
    states = shooting.compression_curve(pocket.material, pocket.pressure_initial, forces, geometry="capsule")
    for row, state in zip(result["states"], states, strict=True):
        assert row["pressure_Pa"] == pytest.approx(state.pressure * pocket.pressure_scale_Pa, rel=1e-9)
        assert row["gap_m"] == pytest.approx(2.0 * state.height * pocket.case.radius, rel=1e-9)
        assert row["stretch_pole"] == pytest.approx(state.extra["stretch_pole"], rel=1e-9)


def _poses_capsule() -> bool:
    """Whether the shooting solver poses the capsule (else it refuses it in one line)."""
    try:
        shooting.inflate(0.1, 0.1, geometry="capsule")
    except InputError:
        return False
    return True


def test_a_capsule_given_by_a_height_below_its_radius_is_out_of_range(stand_in):
    """Exact answer: a capsule's pole is at its radius R above the equator with no pressure (lambda = 1) and rises
    with it, so an initial height below R is reached by no inflation: one OutOfRangeError quoting the height as
    given, before any inflation; a height of exactly R is Phat_I = 0 (the uninflated capsule, whose loads
    tests/test_casefile_uninflated.py solves)."""
    from pocket.core.errors import OutOfRangeError

    case = parse({**CAPSULE_CASE, "initial": {"height": "40 um"}, "solver": {"name": "analytical"}})
    with pytest.raises(OutOfRangeError, match=r"^initial.height = '40 um': no inflated state of the model's first "
                                              r"branch is that low \(initial height H0/R = 0.8 is below the "
                                              r"undeformed capsule's \(1\)"):
        resolve(case)
    assert stand_in == []
    at_rest = parse({**CAPSULE_CASE, "initial": {"height": "50 um"}, "solver": {"name": "analytical"}})
    assert resolve(at_rest).pressure_initial == 0.0


def test_a_capsules_sensitivity_at_rest_is_the_limit_of_its_pressure_force_slopes():
    """Exact answer: by reciprocity a capsule's dP/dF at rest is twice (dH0/dP) / (dV0/dP) (two plates, each
    descending by dH, close the gap by 2 dH); it is the limit of the slopes at the start of its pressure-force curve
    from compressions, the one-sided second-order differences (-3 q(0) + 4 q(h) - q(2 h)) / (2 h). The capsule's
    small-force law is not analytic at F = 0 (the dent's corrections go like (c/l)^2 ln(l/c) with c^2 = Fhat,
    section 12, which puts a term of order F^2 ln F in P), so those differences converge at first order in h (up to
    ln h), not second: their errors keep one sign and shrink by more than 5 per decade of h (10 at first order,
    less only by the ratio of the logs), and the last is below 1e-3."""
    from pocket.apps.sense import sensitivity_at_rest

    if not _poses_capsule():
        pytest.skip("the shooting solver does not pose the capsule yet")
    pocket = resolve(capsule_example())
    at_rest = sensitivity_at_rest(pocket)
    kpa_per_n = pocket.pressure_initial_Pa / pocket.force_scale_N / 1e3  # d(P/P_I)/dFhat -> dP/dF in kPa/N
    errors = []
    for h in (1e-3, 1e-4, 1e-5):
        low, high = shooting.compression_curve(pocket.material, pocket.pressure_initial, [h, 2 * h],
                                               geometry="capsule")
        slope = (-3.0 + 4.0 * low.pressure_ratio - high.pressure_ratio) / (2.0 * h) * kpa_per_n
        errors.append(slope / at_rest - 1.0)
    assert all(e > 0 for e in errors), errors
    assert errors[0] > 5 * errors[1] > 25 * errors[2], errors
    assert errors[2] < 1e-3, errors


@pytest.mark.slow  # 30 s: the end of a capsule's range at a low P_I is marched to from a solved state
def test_a_force_past_a_capsules_range_is_listed_with_its_reason():
    """Exact answers: a liquid-filled capsule at a low P_I (Phat_I = 0.01: 300 Pa on a 30 kPa scale E T / R) has an
    end of its range, the shooting solver's ``range_end``, where the meridional tension at the contact edge vanishes;
    a force load below it is solved and one past it, short of the second branch deeper, is listed as unreachable, its
    reason saying so (the solver's refusal, quoting both branches' ends), after the load as the case gives it."""
    if not _poses_capsule():
        pytest.skip("the shooting solver does not pose the capsule yet")
    case = parse({**CAPSULE_CASE, "initial": {"pressure": "300 Pa"}, "loads": {"forces": ["0.2 uN", "0.5 uN"]}})
    pocket = resolve(case)
    end = shooting.range_end(pocket.material, pocket.pressure_initial, geometry="capsule")
    assert 0.2e-6 < end * pocket.force_scale_N < 0.5e-6
    result, _, states = solved(case)
    assert [row["load"] for row in result["states"]] == ["0.2 uN"]
    assert states[0].geometry is CAPSULE
    (missed,) = result["unreachable"]
    assert missed["load"] == "0.5 uN"
    fhat = case.loads[1] / pocket.force_scale_N
    assert missed["warnings"][0].startswith(f"loads.forces[1] = '0.5 uN' (Fhat = {fhat:.10g})")
    assert "lies between the capsule's two branches of states" in missed["warnings"][0]
    assert missed["warnings"][0].endswith(CAPSULE_EDGE)


@pytest.mark.slow  # 1.4 s: the search for the range's end, then the bracket's solves
def test_the_force_at_a_capsules_pressure_is_found_where_its_range_has_no_end():
    """Exact answer: a liquid-filled capsule's range has no end (``range_end`` is inf), and the force at which its
    pressure ratio reaches that of a state solved at Fhat = 0.5 is found again, 0.5, to the root finder's and the
    solver's resolution (1e-8), by bracketing the force as for a solver without an end."""
    from pocket.apps.inverse import force_where
    from pocket.apps.solvers import SOLVERS

    if not _poses_capsule():
        pytest.skip("the shooting solver does not pose the capsule yet")
    assert shooting.range_end(0.1, 0.3, geometry="capsule") == math.inf
    target = shooting.compress(0.1, 0.3, 0.5, geometry="capsule").pressure_ratio
    found = force_where(SOLVERS["shooting"], 0.1, 0.3, "pressure_ratio", target, increasing=True,
                        geometry="capsule")
    assert found == pytest.approx(0.5, rel=1e-8)
