"""The solid speaks as the solid: a case it solves draws neither membrane theory's thickness warning nor the
membrane's wrinkling sentence, and its discretisation measures are named for what they are."""

import json

import numpy as np
import pytest

from pocket.cli import main
from pocket.core.materials import mooney_rivlin
from pocket.core.states import InflatedState, Profile

#: a 2 mm sheet on a 15 mm clamp: T/R = 0.133, past the membrane's thin-sheet warning (T/R > 0.1)
THICK = """
name = "thick"
[sheet]
thickness = "2 mm"
c1 = "160 kPa"
c2 = "47 kPa"
[clamp]
radius = "15 mm"
[initial]
pressure = "5 kPa"
[loads]
forces = ["0.5 N"]
"""


def _run(tmp_path, capsys, solver):
    path = tmp_path / f"{solver}.toml"
    path.write_text(THICK + f'[solver]\nname = "{solver}"\n')
    assert main(["run", str(path), "--out", str(tmp_path / solver)]) == 0
    return capsys.readouterr().err, json.loads((tmp_path / solver / f"{solver}.json").read_text())


@pytest.mark.slow
def test_thick_sheet_solved_by_the_solid_has_no_membrane_theory_warning(tmp_path, capsys):
    """The same thick case: the membrane (shooting) warns that its O(T/R) error is no longer small; the solid,
    which models the thickness, does not, and its rows carry no such warning."""
    err, _ = _run(tmp_path, capsys, "shooting")
    assert "membrane theory" in err
    err, result = _run(tmp_path, capsys, "solid")
    assert "membrane theory" not in err, err
    assert not any("membrane theory" in w for row in (result["inflated"], *result["states"]) for w in row["warnings"])


@pytest.mark.slow
def test_solid_discretisation_measures_not_read_as_a_volume_error(tmp_path, capsys):
    """The solid's rows name the peak |det F - 1| as the mesh's local error and the constraint's residual as
    such (no bare 'incompressibility' an engineer reads as a volume error), and count the mesh as built: the
    constraint holds to Newton's tolerance, so the volume under the sheet is the fluid's."""
    _, result = _run(tmp_path, capsys, "solid")
    state = result["states"][0]
    assert "incompressibility" not in state
    assert "elements" not in state
    assert state["det_f_constraint_residual"] < 1e-8  # Newton's tolerance 1e-10 on the increment, with margin
    assert 0.0 < state["mesh_det_f_error_peak"] < 1.0
    assert state["mesh_layers"] == 4
    assert state["mesh_elements"] >= 8


def test_solid_compressive_resultant_speaks_of_the_solid_not_membrane_theory():
    """A state whose hoop resultant is negative: a membrane's warning says membrane theory needs positive
    tensions; a solid's (membrane false) says the solid carries it and a real sheet may wrinkle there."""
    r = np.linspace(0.0, 1.0, 5)
    tension_2 = np.array([1.0, 0.5, -0.25, 0.5, 1.0])
    profile = Profile(r, r, 1 - r**2, np.ones(5), np.ones(5), np.ones(5), tension_2, np.zeros(5, bool))
    common = dict(material=mooney_rivlin(0.3), pressure=0.3, stretch_pole=1.1, height=0.5, volume=0.8,
                  stretch_clamp=1.05, profile=profile, solver="test")
    membrane, solid = InflatedState(**common), InflatedState(**common, membrane=False)
    assert membrane.wrinkled
    assert solid.wrinkled
    assert "membrane theory needs T_1, T_2 > 0" in membrane.warnings[0]
    assert len(solid.warnings) == 1
    assert "membrane theory" not in solid.warnings[0]
    assert "T_2 = -0.25 E T at r = 0.5 R; the axisymmetric solid carries it" in solid.warnings[0]


def test_help_says_what_each_solver_is_for(capsys):
    """Every command that takes a solver lists each of its solvers on a line of its own in --help, with the
    record's summary of what it is for (the solid among them where it serves)."""
    from pocket.apps.solvers import SOLVERS

    for command, names in (("compress", tuple(SOLVERS)), ("run", tuple(SOLVERS)), ("sweep", tuple(SOLVERS)),
                           ("fit", ("shooting", "fem")), ("design", ("shooting", "fem"))):
        assert main([command, "--help"]) == 0
        lines = capsys.readouterr().out.splitlines()
        for name in names:
            start = " ".join(SOLVERS[name].summary.split()[:4])
            assert any(line.startswith(f"  {name}: {start}") for line in lines), (command, name)
