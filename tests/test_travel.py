"""Travel control where a user meets it: ``pocket compress --height H`` (the indenter's lowest point at H/R
above the clamp plane) for the solvers whose record declares ``compress_height``, and ``[loads] heights`` in a
case file under a sphere. The state at a height H has a force F, and compressing by F gives back H (to the
solver's tolerance: Newton to 1e-10 on the same mesh, shooting's resolution ~1e-10); a solver without height
control, a height above the pocket or not positive, and --height with --force are one line, exit 2."""

import json

import pytest
from test_cases import BUTTON

from pocket import fem, shooting
from pocket.apps.solvers import SOLVERS
from pocket.cli import main
from pocket.core.errors import OutOfRangeError
from pocket.core.fluids import gas
from pocket.core.indenters import Sphere
from pocket.core.materials import Material

BASE = ["compress", "--alpha", "0.3", "--pressure", "0.3", "--json"]
FEM = ["--solver", "fem", "--elements", "40"]
SPHERE = ["--indenter", "sphere", "--indenter-radius", "0.5"]


def _run(capsys, args):
    assert main(args) == 0, capsys.readouterr().err
    return json.loads(capsys.readouterr().out)


@pytest.mark.slow
@pytest.mark.parametrize("solver", [FEM, []], ids=["fem", "shooting"])
@pytest.mark.parametrize("indenter", [[], SPHERE], ids=["plate", "sphere"])
def test_the_force_at_a_height_gives_back_that_height(capsys, indenter, solver):
    """Heights between the clamp plane and the inflated pocket's top (its fifth and three fifths): each state
    sits at its height with a positive force, and the force-controlled state at that force sits there too."""
    top = fem.inflate(0.3, 0.3, elements=40).height
    heights = [0.8 * top, 0.6 * top]
    by_height = _run(capsys, [*BASE, *solver, *indenter, "--height", *map(repr, heights)])
    assert [s["height"] for s in by_height] == pytest.approx(heights, rel=1e-9)  # shooting: the root's resolution
    assert all(s["force"] > 0.0 for s in by_height)
    for state in by_height:
        by_force = _run(capsys, [*BASE, *solver, *indenter, "--force", repr(state["force"])])
        assert by_force["height"] == pytest.approx(state["height"], rel=1e-8)
        assert by_force["pressure"] == pytest.approx(state["pressure"], rel=1e-8)


def test_every_solver_that_declares_height_control_is_reached():
    """The CLI serves exactly the solvers whose record lists ``compress_height`` (both membrane solvers and the
    solid)."""
    assert [n for n, s in SOLVERS.items() if s.serves("compress_height")] == ["shooting", "fem", "solid"]


GAS = gas(ambient=3.0)


@pytest.mark.slow
@pytest.mark.parametrize("indenter", [None, Sphere(0.8), Sphere(3.0)], ids=["plate", "sphere-0.8", "sphere-3"])
@pytest.mark.parametrize("fluid", [None, GAS], ids=["liquid", "gas"])
def test_shooting_and_fem_agree_at_a_height(indenter, fluid):
    """Two independent routes to the same state: shooting finds the force whose state sits at H by a root in
    the force; the FE holds the indenter at H and solves for the force. Every scalar agrees within the FE's
    discretisation floor at 256 P2 elements (measured up to 2.0e-9, in the small contact cap of the 0.8 R
    sphere at 0.9 H0; 2e-10 under the plate)."""
    rubber = Material("yeoh", {"c10": 0.5, "c20": 0.02, "c30": 0.001})
    top = shooting.inflate(rubber, 0.3).height
    for height in (0.9 * top, 0.6 * top):
        ref = shooting.compress_height(rubber, 0.3, height, fluid=fluid, indenter=indenter)
        fe = fem.compress_height(rubber, 0.3, height, fluid=fluid, indenter=indenter, elements=256)
        assert ref.height == pytest.approx(height, rel=1e-11)  # the root in the force (measured <= 5e-13)
        for key in ("force", "pressure", "pressure_ratio", "contact_area", "contact_radius", "volume"):
            assert getattr(ref, key) == pytest.approx(getattr(fe, key), rel=5e-9), key


def test_shooting_heights_end_where_the_range_ends():
    """At the inflated top the state is the uncompressed one (force 0); above it, and below the height at
    the end of the force range (``range_end``), there is no state: OutOfRangeErrors naming the bound."""
    top = shooting.inflate(0.3, 0.3).height
    assert shooting.compress_height(0.3, 0.3, top).force == 0.0
    end = shooting.range_end(0.3, 0.3)
    low = shooting.compress(0.3, 0.3, end).height
    assert shooting.compress_height(0.3, 0.3, low * (1 + 1e-6)).force == pytest.approx(end, rel=1e-3)
    with pytest.raises(OutOfRangeError, match=r"is below the lowest the model reaches \(H/R = "):
        shooting.compress_height(0.3, 0.3, 0.99 * low)
    for solver in (shooting, fem):
        with pytest.raises(OutOfRangeError, match=r"height = .* is above the inflated pocket \(H0/R = "):
            solver.compress_height(0.3, 0.3, 1.01 * top)


@pytest.mark.parametrize(("args", "message"), [
    (["--height", "0.3", "--solver", "analytical"], "--height: solver analytical has no height-controlled "
                                                    "compression (entry point compress_height; solvers that "
                                                    "have it: shooting, fem, solid)"),
    (["--height", "5", *FEM], "height = 5.0 is above the inflated pocket (H0/R = "),
    (["--height", "5"], "height = 5.0 is above the inflated pocket (H0/R = "),
    (["--height", "0", *FEM], "--height = 0.0, but it must be > 0"),
    (["--height", "0.3", "--force", "0.1", *FEM], "argument --force: not allowed with argument --height"),
])
def test_refusals_are_one_line_exit_2(capsys, args, message):
    assert main([*BASE, *args]) == 2
    err = capsys.readouterr().err
    assert message in err, err
    assert err.count("\n") == 1, err


def test_a_vtk_series_refuses_a_height_given_twice(capsys, tmp_path):
    assert main([*BASE, *FEM, "--height", "0.3", "0.3", "--vtk", str(tmp_path / "vtk")]) == 2
    assert "--height gives 0.3 more than once" in capsys.readouterr().err
    assert not (tmp_path / "vtk").exists()


#: the button of ``test_cases`` (heights 9 and 8 mm below its 10 mm dome) pressed by an 8 mm fingertip
CASE = BUTTON + '[indenter]\nshape = "sphere"\nradius = "8 mm"\n'


@pytest.mark.slow
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
    case.write_text(CASE.replace('"9 mm", "8 mm"]', '"11 mm"]'))
    assert main(["run", str(case), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert ("loads.heights[0] = '11 mm' is above the inflated pocket (H0 = 10 mm): the indenter would not touch "
            "it" in err), err
    assert err.count("\n") == 1, err
