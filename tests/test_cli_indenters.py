"""The indenter flags of ``pocket compress`` (units of the clamp radius R): the plate flag is today's compression,
a sphere solves in both numerical solvers (the analytical model refuses it in one line), and a flag the shape
does not take, a missing one, a radius that is not positive or a bad profile file is one line, exit 2, before any
solving."""

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
def test_a_sphere_solves_with_its_contact_pressure_above_p(capsys, solver):
    assert main([*BASE, "--json", "--solver", solver, "--indenter", "sphere", "--indenter-radius", "0.4"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["solver"] == solver
    assert out["force"] == 0.5
    assert out["contact_pressure_pole"] > out["contact_pressure_edge"] > out["pressure"]
    assert out["contact_radius_deformed"] < 0.4  # on the sphere's lower half


def test_a_sphere_reaches_the_analytical_solver_which_refuses_it_in_one_line(capsys):
    assert main([*BASE, "--solver", "analytical", "--indenter", "sphere", "--indenter-radius", "0.4"]) == 2
    err = capsys.readouterr().err
    assert "solver analytical does not implement the sphere indenter" in err
    assert err.count("\n") == 1


@pytest.mark.parametrize(("flags", "message"), [
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
    assert message in err
    assert err.count("\n") == 1


DESIGN = ["design", "--radius", "20 mm", "--height", "10 mm", "--modulus", "1 MPa", "--alpha", "0.3", "--force",
          "0.67 N"]


def test_design_with_the_plate_flag_is_todays_design(capsys):
    assert main([*DESIGN, "--json"]) == 0
    default = json.loads(capsys.readouterr().out)
    assert main([*DESIGN, "--json", "--indenter", "plate"]) == 0
    assert json.loads(capsys.readouterr().out) == default


def test_design_for_a_fingertip_meets_its_target_under_the_fingertip(capsys):
    """The button designed for an 8 mm fingertip travels 20 % of its 10 mm height (H/H0 = 0.8) under 0.67 N
    pressed by that sphere, and needs another P_I (in Pa) than the one designed for the plate."""
    assert main([*DESIGN, "--json", "--indenter", "sphere", "--indenter-radius", "8 mm"]) == 0
    finger = json.loads(capsys.readouterr().out)
    assert main([*DESIGN, "--json"]) == 0
    plate = json.loads(capsys.readouterr().out)
    # the curve's forces are fractions of twice the target, each F_k = (2 Fhat k / 20) P_I pi R^2: the tenth is the
    # target to rounding (its last bits move with the design's P_I), so it is found by nearness, not by its key
    row = min(finger["curve"], key=lambda r: abs(r["force_N"] - 0.67))
    assert row["force_N"] == pytest.approx(0.67, rel=1e-12)
    assert row["travel_m"] == pytest.approx((1.0 - 0.8) * 0.010, rel=1e-9)
    assert abs(finger["pressure_initial_Pa"] / plate["pressure_initial_Pa"] - 1) > 1e-3


@pytest.mark.parametrize(("flags", "message"), [
    (["--indenter", "sphere", "--indenter-radius", "-8 mm"], "--indenter-radius = '-8 mm', but it must be > 0"),
    (["--indenter", "sphere", "--indenter-radius", "0"], "--indenter-radius = '0', but it must be > 0"),
    (["--indenter", "sphere", "--indenter-radius", "8 km"], "--indenter-radius = '8 km' is 8000 m, outside the sizes "
                                                            "of a pocket"),
    (["--indenter-radius", "8 mm"], "--indenter-radius is given, but a plate indenter takes no size"),
    (["--indenter", "profile", "--indenter-file", "{bad}"], "column 1 ('radius') has no unit"),
])
def test_bad_design_indenter_flags_are_one_line_exit_2_before_any_solving(capsys, monkeypatch, tmp_path, flags,
                                                                         message):
    (tmp_path / "bad.csv").write_text("radius,height\n0,0\n1,1\n2,4\n3,9\n")
    monkeypatch.setattr(design, "pressure_for_height", _no_solving)
    assert main([*DESIGN, *[f.format(bad=tmp_path / "bad.csv") for f in flags]]) == 2
    err = capsys.readouterr().err
    assert message in err
    assert err.count("\n") == 1


def test_sense_with_a_sphere_in_the_case_solves(capsys, tmp_path):
    """``pocket sense`` under an 8 mm sphere: exit 0, the pressure ratio asked, reached at another force than
    under the plate."""
    case = tmp_path / "case.toml"
    text = ('[sheet]\nthickness = "0.25 mm"\nc1 = "160 kPa"\nc2 = "47 kPa"\n[clamp]\nradius = "20 mm"\n'
            '[initial]\npressure = "4.8 kPa"\n[loads]\nforces = ["1 N"]\n')
    case.write_text(text + '[indenter]\nshape = "sphere"\nradius = "8 mm"\n')
    assert main(["sense", str(case), "--ratio", "1.1", "--json"]) == 0
    finger = json.loads(capsys.readouterr().out)
    case.write_text(text)
    assert main(["sense", str(case), "--ratio", "1.1", "--json"]) == 0
    plate = json.loads(capsys.readouterr().out)
    assert finger["pressure_ratio"] == pytest.approx(1.1, rel=1e-9)
    assert abs(finger["force_N"] / plate["force_N"] - 1) > 1e-3
