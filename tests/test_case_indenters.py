"""The ``[indenter]`` table of a case file: the flat plate by default and end to end with ``pocket run`` (its
contact pressure the pressure P at pole and edge, every other key as without the table), a sphere's radius
and a profile's file made dimensionless by the clamp radius, and every bad table one line, exit 2, before any
solving. A sphere runs end to end in both numerical solvers (its contact pressure above P, its curved contact
area); the analytical model, which does not pose it, refuses it in one line."""

import json
import math

import numpy as np
import pytest

from pocket import fem, shooting
from pocket.apps import casefile
from pocket.apps.cases import load
from pocket.cli import main
from pocket.core.indenters import PLATE, Profile, Sphere
from pocket.core.profiles import read_csv

CASE = """
name = "button"
[sheet]
thickness = "0.25 mm"
modulus = "1 MPa"
alpha = 0.3
[clamp]
radius = "20 mm"
[initial]
pressure = "4.8 kPa"
[loads]
forces = ["0 N", "0.3 N"]
"""

TIP = "radius [mm],height [mm]\n" + "".join(f"{r:g},{r * r / 16:.17g}\n" for r in np.linspace(0, 6, 13))


def _no_solving(*args, **kwargs):
    raise AssertionError("a solve started before the bad indenter was refused")


def _case(tmp_path, table: str = "", name: str = "case.toml"):
    path = tmp_path / name
    path.write_text(CASE + table)
    return path


def test_no_table_and_a_plate_table_are_the_flat_plate(tmp_path):
    assert load(_case(tmp_path)).indenter == PLATE
    assert load(_case(tmp_path, '[indenter]\nshape = "plate"\n')).indenter == PLATE


def test_a_sphere_radius_is_made_dimensionless_by_the_clamp_radius(tmp_path):
    case = load(_case(tmp_path, '[indenter]\nshape = "sphere"\nradius = "8 mm"\n'))
    assert case.indenter == Sphere(8.0 / 20.0)  # K = R_s / R
    assert case.fields()["indenter"] == "sphere"
    assert case.fields()["indenter_radius_m"] == pytest.approx(0.008, rel=1e-15)


def test_a_profile_file_is_relative_to_the_case_file(tmp_path, monkeypatch):
    folder = tmp_path / "cases"
    folder.mkdir()
    (folder / "tip.csv").write_text(TIP)  # z = rho^2 / 16 mm: a paraboloid of tip radius 8 mm
    monkeypatch.chdir(tmp_path)  # not the case file's folder
    case = load(_case(folder, '[indenter]\nshape = "profile"\nfile = "tip.csv"\n'))
    assert isinstance(case.indenter, Profile)
    assert case.indenter.shape.source == str(folder / "tip.csv")
    # z(5 mm) = 25/16 mm, in units of R = 20 mm; the spline in rho^2 is exact for a parabola
    assert case.indenter.height(5.0 / 20.0) == pytest.approx(25.0 / 16.0 / 20.0, rel=1e-12)
    assert case.indenter.curvature(0.0) == pytest.approx(20.0 / 8.0, rel=1e-12)  # 1/(8 mm) in units of 1/R


@pytest.mark.parametrize(("table", "message"), [
    ('shape = "sphere"\nradius = "-8 mm"\n', "indenter.radius = '-8 mm', but it must be > 0"),
    ('shape = "sphere"\nradius = "0 mm"\n', "indenter.radius = '0 mm', but it must be > 0"),
    ('shape = "sphere"\nradius = "8 kPa"\n', "indenter.radius = '8 kPa' has dimension"),
    ('shape = "sphere"\n', "missing key 'indenter.radius' (a sphere indenter needs it)"),
    ('shape = "plate"\nradius = "8 mm"\n', "indenter.radius = '8 mm', but a plate indenter takes no other key"),
    ('radius = "8 mm"\n', "indenter.radius = '8 mm', but a plate indenter takes no other key"),
    ('shape = "profile"\nradius = "8 mm"\nfile = "tip.csv"\n', "indenter.radius = '8 mm', but a profile indenter "
                                                              "takes file"),
    ('shape = "cone"\n', "indenter.shape = 'cone', but it must be one of plate, sphere, profile"),
    ('shape = "profile"\nfile = "missing.csv"\n', "missing.csv: cannot read the profile file"),
    ('shape = "profile"\nfile = "bad.csv"\n', "bad.csv: column 1 ('radius') has no unit"),
    ('colour = "red"\n', "unknown key 'indenter.colour'"),
])
def test_a_bad_indenter_table_is_one_line_exit_2_before_any_solving(tmp_path, capsys, monkeypatch, table,
                                                                   message):
    (tmp_path / "bad.csv").write_text("radius,height\n0,0\n1,1\n2,4\n3,9\n")
    monkeypatch.setattr(casefile, "resolve", _no_solving)
    assert main(["run", str(_case(tmp_path, "[indenter]\n" + table)), "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert message in err
    assert err.count("\n") == 1
    assert not list(tmp_path.glob("case.*json"))


def test_a_plate_table_runs_end_to_end_with_the_contact_pressure_p(tmp_path, capsys):
    """With ``shape = "plate"`` every key has the value it has without the table, and the contact pressure at
    the pole and at the edge is the pressure P (the flat plate carries P straight through the sheet)."""
    plain, plate = tmp_path / "plain", tmp_path / "plate"
    plain.mkdir(), plate.mkdir()
    assert main(["run", str(_case(plain)), "--out", str(plain)]) == 0
    assert main(["run", str(_case(plate, '[indenter]\nshape = "plate"\n')), "--out", str(plate)]) == 0
    before = json.loads((plain / "case.json").read_text())
    after = json.loads((plate / "case.json").read_text())
    for old, new in zip(before["states"], after["states"], strict=True):
        assert new["contact_pressure_pole_Pa"] == new["contact_pressure_edge_Pa"] == new["pressure_Pa"]
        assert new == old
        assert new["contact_area_m2"] == pytest.approx(new["contact_radius_lagrangian_m"] ** 2 * math.pi
                                                       * new["stretch_contact"] ** 2, rel=1e-12, abs=1e-18)
        # flat: A = pi (lambda_c a_c)^2
    assert after["case"]["indenter"] == before["case"]["indenter"] == "plate"
    assert after["case"]["given"]["indenter.shape"] == "plate"


@pytest.mark.slow
@pytest.mark.parametrize("solver", ["shooting", "fem"])
def test_a_sphere_runs_end_to_end_with_its_contact_pressure_and_curved_area(tmp_path, solver):
    """A sphere of 8 mm on the 20 mm pocket: each compressed row carries the solver's contact pressure at the
    pole and the edge times the pressure scale E T / R (above P), and the curved area of the spherical cap in
    contact, 2 pi R_s (R_s - sqrt(R_s^2 - rho_c^2)) with rho_c the solver's deformed contact radius."""
    path = _case(tmp_path, f'[indenter]\nshape = "sphere"\nradius = "8 mm"\n[solver]\nname = "{solver}"\n')
    assert main(["run", str(path), "--out", str(tmp_path)]) == 0
    rows = json.loads((tmp_path / "case.json").read_text())["states"]
    modulus, thickness, clamp, radius = 1e6, 0.25e-3, 0.020, 0.008  # the case's values, SI
    scale = modulus * thickness / clamp  # Pa per unit Phat
    solve = {"shooting": shooting.compress, "fem": fem.compress}[solver]
    pressed = [row for row in rows if row["force"] > 0.0]
    assert pressed
    for row in pressed:
        state = solve(row["alpha"], row["pressure_initial"], row["force"], indenter=Sphere(radius / clamp))
        assert row["contact_pressure_pole_Pa"] == pytest.approx(state.contact_pressure_pole * scale, rel=1e-12)
        assert row["contact_pressure_edge_Pa"] == pytest.approx(state.contact_pressure_edge * scale, rel=1e-12)
        assert row["contact_pressure_pole_Pa"] > row["contact_pressure_edge_Pa"] > row["pressure_Pa"]
        rho_c = state.contact_radius_deformed * clamp
        cap = 2 * math.pi * radius * (radius - math.sqrt(radius**2 - rho_c**2))
        assert row["contact_area_m2"] == pytest.approx(cap, rel=1e-12)
        assert row["contact_area_m2"] > math.pi * rho_c**2  # curved, not its flat projection
        assert row["contact_radius_lagrangian_m"] == pytest.approx(state.contact_radius * clamp, rel=1e-12)
        assert row["contact_radius_deformed_m"] == pytest.approx(rho_c, rel=1e-12)


def test_a_sphere_reaches_the_analytical_solver_which_refuses_it_in_one_line(tmp_path, capsys):
    path = _case(tmp_path, '[indenter]\nshape = "sphere"\nradius = "8 mm"\n[solver]\nname = "analytical"\n')
    assert main(["run", str(path), "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "solver analytical does not implement the sphere indenter" in err
    assert err.count("\n") == 1
    assert not list(tmp_path.glob("case.*json"))
    assert not list(tmp_path.glob("case.csv"))


def test_the_documented_profile_table_is_a_paraboloid_of_tip_radius_8_mm(tmp_path):
    """The documentation's example rows are z = rho^2 / 16 mm, whose tip curvature is 1/(8 mm) (2 z'' = 1/8 mm)."""
    import documents

    text = documents.text().split("```text\nradius [mm],height [mm]\n", 1)[1].split("```", 1)[0]
    (tmp_path / "tip.csv").write_text("radius [mm],height [mm]\n" + text)
    tip = Profile(read_csv(tmp_path / "tip.csv", clamp_radius=0.020))
    assert tip.curvature(0.0) == pytest.approx(20.0 / 8.0, rel=1e-12)  # units 1/R, R = 20 mm
