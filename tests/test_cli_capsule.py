"""``pocket inflate`` and ``pocket compress`` with ``--geometry capsule``: the surface reaches the solver, the
capsule's keys reach the JSON and the table, and a solver or an indenter that does not pose the capsule is
refused in one line (exit 2).

The plumbing is checked with a stand-in for a solver's entry points (``capsulestates``: states built by hand,
an exact inflated sphere and a pressed shape), so that it does not depend on any solver posing the capsule:
what the command prints must be, to the last bit, what the entry point returned, and the entry point must have
been given the capsule. Where the shooting and finite-element solvers pose the capsule, the command's JSON is
checked against their Python API.
"""

from __future__ import annotations

import json

import capsulestates
import meshio
import numpy as np
import pytest
from capsulestates import sphere, stood_in

from pocket import fem, shooting
from pocket.cli import main
from pocket.core.errors import InputError
from pocket.core.geometries import CAPSULE, GEOMETRIES
from pocket.core.reported import reported

#: the capsule's keys of a compressed state's ``extra`` and their units (``pocket.core.reported``, group capsule)
CAPSULE_KEYS = {"geometry": "text", "stretch_pole": "1", "radius_equator": "R", "force_ETR": "1"}
#: what the hidden check reads of each state
READ = ("pressure_ratio", "height", "volume", "contact_area", "contact_radius", "contact_radius_deformed",
        "stretch_pole", "radius_equator")


def run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


@pytest.fixture
def stand_in(monkeypatch):
    """The analytical solver's entry points replaced by ones returning hand-built capsule states
    (``capsulestates.stand_in``); the keywords they were given are recorded."""
    return capsulestates.stand_in(monkeypatch)


def test_the_capsule_keys_are_documented_with_their_units():
    """Exact answers: the keys a capsule's states add are in ``pocket.core.reported`` with the units the contract
    gives them (the radius in R, the rest pure numbers and a name)."""
    assert {key: reported(key).unit for key in CAPSULE_KEYS} == CAPSULE_KEYS


@pytest.mark.parametrize("command", ["inflate", "compress"])
def test_the_help_offers_the_geometries_and_says_the_capsules_units(capsys, command):
    """Exact answers: ``--geometry`` offers the names of ``GEOMETRIES`` (default pocket), and the help says that a
    capsule's lengths are in units of its radius R and, for a compression, that Fhat's F is the force on each
    plate and the gap between the plates is 2 H R."""
    assert main([command, "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    assert "--geometry {" + ",".join(GEOMETRIES) + "}" in text
    assert "R is the capsule's radius (lengths in units of R), Phat = P R / (E T)" in text
    if command == "compress":
        assert "Fhat = F / (P_I pi R^2) with F the force on each plate" in text
        assert "the gap between the plates is 2 H R" in text


def test_compress_json_is_what_the_solver_returned_for_the_capsule(capsys, stand_in):
    """Exact answers: the compression curve is given ``geometry`` = the capsule (and the inflation nothing else);
    the JSON is a list with each state's scalars to the last bit, the capsule's keys among them; the table has a
    column for each of them, ``geometry`` reading capsule."""
    argv = ("compress", "--geometry", "capsule", "--solver", "analytical", "--alpha", "0.1", "--pressure", "0.3",
            "--force", "0.2", "0.4")
    status, out, err = run(capsys, *argv, "--json")
    assert (status, err) == (0, "")
    assert [(name, options["geometry"]) for name, options in stand_in] == [("compression_curve", CAPSULE)]
    rows = json.loads(out)
    expected = [state.scalars() for state in stood_in((0.2, 0.4))]
    for row, scalars in zip(rows, expected, strict=True):
        assert set(row) - {"warnings"} == set(scalars)
        assert set(READ) | set(CAPSULE_KEYS) <= set(row)
        for key, value in scalars.items():
            assert row[key] == value if not isinstance(value, float) else float(row[key]).hex() == value.hex(), key
    status, out, _ = run(capsys, *argv)
    header, *lines = out.splitlines()[1:]
    columns = header.split()
    assert status == 0
    assert set(CAPSULE_KEYS) <= set(columns)
    assert [line.split()[columns.index("geometry")] for line in lines] == ["capsule", "capsule"]


def test_inflate_passes_the_capsule_and_prints_its_keys(capsys, stand_in):
    """Exact answers: ``pocket inflate --geometry capsule`` gives the solver the capsule and prints the sphere's
    scalars, its ``radius_equator`` and ``geometry`` among them, in the table as in JSON."""
    argv = ("inflate", "--geometry", "capsule", "--solver", "analytical", "--alpha", "0.1", "--pressure", "0.3")
    status, out, _ = run(capsys, *argv, "--json")
    assert status == 0
    assert stand_in[-1] == ("inflate", {"geometry": CAPSULE})
    data = json.loads(out)
    assert data["geometry"] == "capsule"
    assert data["radius_equator"] == sphere(stretch=1.2).stretch_pole
    status, out, _ = run(capsys, *argv)
    table = dict(line.split() for line in out.splitlines()[1:])
    assert (table["geometry"], float(table["radius_equator"])) == ("capsule", 1.2)


def test_compress_vtk_writes_the_closed_capsule_and_both_plates(capsys, stand_in, tmp_path):
    """Exact answers: ``--vtk`` writes each step's whole capsule, from pole (+H) to pole (-H), and the two plates at
    +H and -H (the writer's own tests check the surface and the volume)."""
    folder = tmp_path / "press"
    argv = ("compress", "--geometry", "capsule", "--solver", "analytical", "--alpha", "0.1", "--pressure", "0.3",
            "--force", "0.2", "--vtk", str(folder))
    assert run(capsys, *argv)[0] == 0
    surface = meshio.read(folder / "step_0000_surface.vtu")
    plates = meshio.read(folder / "step_0000_indenter.vtu")
    assert [surface.points[:, 2].max(), surface.points[:, 2].min()] == [0.9, -0.9]
    assert np.unique(plates.points[:, 2]).tolist() == [-0.9, 0.9]


@pytest.mark.parametrize("solver", ["analytical", "solid"])
def test_a_solver_that_does_not_pose_the_capsule_is_refused_in_one_line(capsys, solver):
    """Exact answer: a solver whose table has no capsule (the small-strain model of the flat pocket; the solid's
    clamped rectangle) refuses ``--geometry capsule`` with its own one line, exit 2, nothing on stdout."""
    status, out, err = run(capsys, "compress", "--geometry", "capsule", "--solver", solver, "--alpha", "0.1",
                           "--pressure", "0.3", "--force", "0.2", "--json")
    if status == 0:
        pytest.skip(f"solver {solver} poses the capsule")
    assert (status, out) == (2, "")
    assert err.startswith(f"pocket: error: solver {solver} does not implement the capsule geometry")
    assert err.count("\n") == 1


@pytest.mark.parametrize("flags", [("--indenter", "sphere", "--indenter-radius", "0.5"),
                                   ("--solver", "analytical", "--height", "0.8")], ids=["sphere", "height"])
def test_what_a_capsule_cannot_be_given_is_one_line(capsys, flags):
    """Exact answers: a sphere pressing a capsule (it sits between two plates), and travel control by a solver that
    has none, are refused in one line naming the capsule or the missing entry point, exit 2, before any output."""
    status, out, err = run(capsys, "compress", "--geometry", "capsule", "--alpha", "0.1", "--pressure", "0.3",
                           "--force" if "--height" not in flags else "--json", *(() if "--height" in flags else
                                                                                 ("0.2",)), *flags)
    assert (status, out) == (2, "")
    assert err.count("\n") == 1
    assert ("capsule" in err) if "--indenter" in flags else ("height-controlled compression" in err)


def _poses(solve, *args, **options) -> bool:
    """Whether the solver's entry point ``solve`` poses the capsule (else it refuses it before any work)."""
    try:
        solve(*args, geometry="capsule", **options)
    except InputError as err:
        if "capsule geometry" in str(err):
            return False
        raise
    return True


#: flags of the command line -> the keywords of the Python call (rubber, fluid, solver options)
CASES = {
    "mooney-rivlin": (("--alpha", "0.1"), {"material": 0.1}),
    "neo-hookean": (("--law", "neo-hookean", "--mu", "1"), {"material": "neo-hookean"}),
    "yeoh": (("--law", "yeoh", "--c10", "0.5", "--c20", "-0.01", "--c30", "0.001"), {"material": "yeoh"}),
    "gas": (("--alpha", "0.1", "--fluid", "gas", "--ambient", "2", "--gamma", "1.4"), {"material": 0.1,
                                                                                         "fluid": (2.0, 1.4)}),
}


@pytest.mark.parametrize("case", CASES)
def test_compress_json_is_the_shooting_capsules(capsys, case):
    """Exact answer: ``pocket compress --geometry capsule ... --json`` (shooting) prints the scalars of the Python
    API's compression curve of the capsule with the same rubber and fluid, to the last bit, the keys the
    capsule's states carry among them."""
    from pocket.apps.rubbers import rubber
    from pocket.core.fluids import gas
    from pocket.core.materials import mooney_rivlin

    if not _poses(shooting.inflate, 0.1, 0.3):
        pytest.skip("the shooting solver does not pose the capsule yet")
    flags, call = CASES[case]
    material = call["material"]
    if material == "neo-hookean":
        material = rubber("neo-hookean", {"mu": 1.0})
    elif material == "yeoh":
        material = rubber("yeoh", {"c10": 0.5, "c20": -0.01, "c30": 0.001})
    else:
        material = mooney_rivlin(material)
    options = {"fluid": gas(*call["fluid"])} if "fluid" in call else {}
    forces = [0.2, 0.5]
    status, out, err = run(capsys, "compress", "--geometry", "capsule", *flags, "--pressure", "0.3", "--force",
                           *map(str, forces), "--json")
    assert status == 0, err
    states = shooting.compression_curve(material, 0.3, forces, geometry="capsule", **options)
    for row, state in zip(json.loads(out), states, strict=True):
        scalars = state.scalars()
        assert set(READ) | set(CAPSULE_KEYS) <= set(row)
        for key in READ:
            assert float(row[key]).hex() == float(scalars[key]).hex(), key
        assert row["geometry"] == "capsule"


@pytest.mark.slow
def test_compress_json_is_the_finite_element_capsules(capsys):
    """Exact answer: with ``--solver fem`` the JSON is the FE API's capsule states at the same mesh, to the last
    bit."""
    if not _poses(fem.inflate, 0.1, 0.3, elements=16):
        pytest.skip("the finite-element solver does not pose the capsule yet")
    status, out, err = run(capsys, "compress", "--geometry", "capsule", "--solver", "fem", "--alpha", "0.1",
                           "--pressure", "0.3", "--force", "0.3", "--elements", "64", "--json")
    assert status == 0, err
    state = fem.compress(0.1, 0.3, 0.3, geometry="capsule", elements=64)
    row = json.loads(out)
    for key in READ:
        assert float(row[key]).hex() == float(state.scalars()[key]).hex(), key


def test_plate_gap_control_of_a_capsule_is_served_or_refused_in_one_line(capsys):
    """Exact answers: ``--height`` with a capsule (each plate's distance from the equatorial plane) is either
    served, the state's plate at that height to the solver's tolerance, or refused in one line (exit 2) by a
    solver that does not pose it."""
    status, out, err = run(capsys, "compress", "--geometry", "capsule", "--alpha", "0.1", "--pressure", "0.3",
                           "--height", "1.05", "--json")
    if status == 2:
        assert out == ""
        assert err.count("\n") == 1
        return
    assert status == 0, err
    row = json.loads(out)
    assert row["geometry"] == "capsule"
    assert row["height"] == pytest.approx(1.05, rel=1e-8)  # the solver's tolerance on the height it is held at
