"""Travel control where a user meets it: ``pocket compress --height H`` (the indenter's lowest point at H/R
above the clamp plane) for the solvers whose record declares ``compress_height``, and ``[loads] heights`` in a
case file under a sphere. The state at a height H has a force F, and compressing by F gives back H (to the
solver's tolerance: Newton to 1e-10 on the same mesh, shooting's resolution ~1e-10); a solver without height
control, a height above the pocket or not positive, and --height with --force are one line, exit 2."""

import json

import pytest

from pocket import fem
from pocket.apps.solvers import SOLVERS
from pocket.cli import main

BASE = ["compress", "--alpha", "0.3", "--pressure", "0.3", "--json"]
FEM = ["--solver", "fem", "--elements", "40"]
SPHERE = ["--indenter", "sphere", "--indenter-radius", "0.5"]


def _run(capsys, args):
    assert main(args) == 0, capsys.readouterr().err
    return json.loads(capsys.readouterr().out)


@pytest.mark.parametrize("indenter", [[], SPHERE], ids=["plate", "sphere"])
def test_the_force_at_a_height_gives_back_that_height(capsys, indenter):
    """Heights between the clamp plane and the inflated pocket's top (its fifth and three fifths): each state
    sits at its height with a positive force, and the force-controlled state at that force sits there too."""
    top = fem.inflate(0.3, 0.3, elements=40).height
    heights = [0.8 * top, 0.6 * top]
    by_height = _run(capsys, [*BASE, *FEM, *indenter, "--height", *map(repr, heights)])
    assert [s["height"] for s in by_height] == pytest.approx(heights, rel=1e-12)
    assert all(s["force"] > 0.0 for s in by_height)
    for state in by_height:
        by_force = _run(capsys, [*BASE, *FEM, *indenter, "--force", repr(state["force"])])
        assert by_force["height"] == pytest.approx(state["height"], rel=1e-8)
        assert by_force["pressure"] == pytest.approx(state["pressure"], rel=1e-8)


def test_every_solver_that_declares_height_control_is_reached():
    """The CLI serves exactly the solvers whose record lists ``compress_height`` (today: fem)."""
    assert [n for n, s in SOLVERS.items() if s.serves("compress_height")] == ["fem"]


@pytest.mark.parametrize("args, message", [
    (["--height", "0.3"], "--height: solver shooting has no height-controlled compression (entry point "
                          "compress_height; solvers that have it: fem)"),
    (["--height", "0.3", "--solver", "analytical"], "--height: solver analytical has no height-controlled "
                                                    "compression"),
    (["--height", "5", *FEM], "--height 5 is above the inflated pocket (H0/R = "),
    (["--height", "0", *FEM], "--height = 0.0, but it must be > 0"),
    (["--height", "0.3", "--force", "0.1", *FEM], "argument --force: not allowed with argument --height"),
])
def test_refusals_are_one_line_exit_2(capsys, args, message):
    assert main([*BASE, *args]) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1, err


def test_a_vtk_series_refuses_a_height_given_twice(capsys, tmp_path):
    assert main([*BASE, *FEM, "--height", "0.3", "0.3", "--vtk", str(tmp_path / "vtk")]) == 2
    assert "--height gives 0.3 more than once" in capsys.readouterr().err
    assert not (tmp_path / "vtk").exists()


CASE = """
name = "tip"
[sheet]
thickness = "0.25 mm"
modulus = "1 MPa"
alpha = 0.3
[clamp]
radius = "20 mm"
[initial]
height = "10 mm"
[loads]
heights = ["9 mm", "8 mm"]
[indenter]
shape = "sphere"
radius = "8 mm"
"""


@pytest.mark.parametrize("solver", ["shooting", "fem"])
def test_case_file_heights_under_a_sphere(tmp_path, capsys, solver):
    """``[loads] heights`` under an 8 mm sphere: each state sits at its height (the force found for it), the
    travel is H0 - H, and the solver compressing by that force gives back the height."""
    case = tmp_path / "tip.toml"
    case.write_text(CASE + f"[solver]\nname = \"{solver}\"\nelements = 40\n" if solver == "fem" else CASE)
    assert main(["run", str(case), "--out", str(tmp_path / "out")]) == 0, capsys.readouterr().err
    states = json.loads((tmp_path / "out" / "tip.json").read_text())["states"]
    assert [s["height_m"] for s in states] == pytest.approx([0.009, 0.008], rel=1e-9)
    assert [s["travel_m"] for s in states] == pytest.approx([0.001, 0.002], rel=1e-6)
    assert all(s["contact_pressure_pole_Pa"] > s["pressure_Pa"] for s in states)  # a sphere, not the plate


def test_case_file_height_above_the_pocket_names_the_indenter(tmp_path, capsys):
    case = tmp_path / "tip.toml"
    case.write_text(CASE.replace('"8 mm"]', '"11 mm"]'))
    assert main(["run", str(case), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert "loads.heights[1] = '11 mm' is above the inflated pocket (H0 = 10 mm): the indenter would not touch " \
           "it" in err and err.count("\n") == 1, err
