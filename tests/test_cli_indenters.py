"""The indenter flags of ``pocket compress`` (units of the clamp radius R): the plate flag is today's compression,
a sphere reaches the solver (which refuses it in one line until it poses it), and a flag the shape does not take,
a missing one, a radius that is not positive or a bad profile file is one line, exit 2, before any solving."""

import json

import pytest
from pocket.shooting import compression

from pocket.apps import design
from pocket.cli import main

BASE = ["compress", "--pressure", "0.3", "--force", "0.5", "--alpha", "0.1"]


def _no_solving(*args, **kwargs):
    raise AssertionError("a solve started before the bad indenter was refused")


def test_the_plate_flag_is_the_default_compression(capsys):
    assert main([*BASE, "--json"]) == 0
    default = json.loads(capsys.readouterr().out)
    assert main([*BASE, "--json", "--indenter", "plate"]) == 0
    assert json.loads(capsys.readouterr().out) == default


@pytest.mark.parametrize("solver", ["shooting", "fem"])
def test_a_sphere_reaches_the_solver_which_refuses_it_in_one_line(capsys, solver):
    assert main([*BASE, "--solver", solver, "--indenter", "sphere", "--indenter-radius", "0.4"]) == 2
    err = capsys.readouterr().err
    assert f"solver {solver} does not implement the sphere indenter" in err and err.count("\n") == 1


@pytest.mark.parametrize("flags, message", [
    (["--indenter", "sphere", "--indenter-radius", "-0.4"], "--indenter-radius = -0.4, but a sphere's radius must "
                                                            "be > 0"),
    (["--indenter", "sphere", "--indenter-radius", "0"], "--indenter-radius = 0, but a sphere's radius must be > 0"),
    (["--indenter", "sphere"], "--indenter sphere needs --indenter-radius"),
    (["--indenter-radius", "0.4"], "--indenter-radius is given, but a plate indenter takes no size"),
    (["--indenter", "sphere", "--indenter-radius", "0.4", "--indenter-file", "tip.csv"],
     "--indenter-file is given, but a sphere indenter takes --indenter-radius"),
    (["--indenter", "profile"], "--indenter profile needs --indenter-file"),
    (["--indenter", "profile", "--indenter-file", "{mm}"], "is in mm, but a dimensionless command takes the profile "
                                                           "in units of the clamp radius"),
    (["--indenter", "profile", "--indenter-file", "{cone}"], "does not start flat on the axis"),
])
def test_bad_indenter_flags_are_one_line_exit_2_before_any_solving(capsys, monkeypatch, tmp_path, flags, message):
    (tmp_path / "mm.csv").write_text("radius [mm],height [mm]\n0,0\n1,0.1\n2,0.4\n3,0.9\n")
    (tmp_path / "cone.csv").write_text("radius [R],height [R]\n0,0\n0.1,0.1\n0.2,0.2\n0.3,0.3\n")
    monkeypatch.setattr(compression, "inflate", _no_solving)
    flags = [f.format(mm=tmp_path / "mm.csv", cone=tmp_path / "cone.csv") for f in flags]
    assert main([*BASE, *flags]) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1


DESIGN = ["design", "--radius", "20 mm", "--height", "10 mm", "--modulus", "1 MPa", "--alpha", "0.3", "--force",
          "0.67 N"]


def test_design_with_the_plate_flag_is_todays_design(capsys):
    assert main([*DESIGN, "--json"]) == 0
    default = json.loads(capsys.readouterr().out)
    assert main([*DESIGN, "--json", "--indenter", "plate"]) == 0
    assert json.loads(capsys.readouterr().out) == default


def test_design_for_a_fingertip_reaches_the_solver_which_refuses_it_in_one_line(capsys):
    assert main([*DESIGN, "--indenter", "sphere", "--indenter-radius", "8 mm"]) == 2
    err = capsys.readouterr().err
    assert "solver shooting does not implement the sphere indenter" in err and err.count("\n") == 1


@pytest.mark.parametrize("flags, message", [
    (["--indenter", "sphere", "--indenter-radius", "-8 mm"], "indenter.radius = '-8 mm', but it must be > 0"),
    (["--indenter", "sphere", "--indenter-radius", "0"], "indenter.radius = '0', but it must be > 0"),
    (["--indenter-radius", "8 mm"], "--indenter-radius is given, but a plate indenter takes no size"),
    (["--indenter", "profile", "--indenter-file", "{bad}"], "column 1 ('radius') has no unit"),
])
def test_bad_design_indenter_flags_are_one_line_exit_2_before_any_solving(capsys, monkeypatch, tmp_path, flags,
                                                                         message):
    (tmp_path / "bad.csv").write_text("radius,height\n0,0\n1,1\n2,4\n3,9\n")
    monkeypatch.setattr(design, "pressure_for_height", _no_solving)
    assert main([*DESIGN, *[f.format(bad=tmp_path / "bad.csv") for f in flags]]) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1


def test_sense_with_a_sphere_in_the_case_reaches_the_solver_which_refuses_it(capsys, tmp_path):
    case = tmp_path / "case.toml"
    case.write_text('[sheet]\nthickness = "0.25 mm"\nc1 = "160 kPa"\nc2 = "47 kPa"\n[clamp]\nradius = "20 mm"\n'
                    '[initial]\npressure = "4.8 kPa"\n[loads]\nforces = ["1 N"]\n'
                    '[indenter]\nshape = "sphere"\nradius = "8 mm"\n')
    assert main(["sense", str(case), "--ratio", "1.1"]) == 2
    err = capsys.readouterr().err
    assert "solver shooting does not implement the sphere indenter" in err and err.count("\n") == 1
