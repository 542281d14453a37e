"""The contact patch as a user measures it, and columns that say their unit.

A camera or an ink print sees the contact patch out to the contact edge of the deformed sheet, at rho_c
from the axis; the Lagrangian a_c (where that edge was in the flat sheet) is smaller by the hoop stretch
there. Every output reports rho_c for every indenter and names a_c as Lagrangian; the rubber's stresses,
in units of mu_0, say so, so that a ``mu = 1.0`` is not read as 1 Pa beside ``pressure_Pa``.
"""

import csv
import json
import math
from concurrent.futures import ThreadPoolExecutor

import meshio
import numpy as np
import pytest

from pocket import fem, shooting
from pocket.apps.cases import sample
from pocket.apps.sweep.grid import run_sweep
from pocket.apps.vtk import files
from pocket.cli import main
from pocket.core.indenters import Sphere
from pocket.core.materials import check

CASE = """
name = "button"
[sheet]
thickness = "0.25 mm"
{rubber}
[clamp]
radius = "20 mm"
[initial]
pressure = "4.8 kPa"
[loads]
forces = ["0 N", "0.1 N", "0.3 N"]
{extra}"""
MOONEY_RIVLIN = 'modulus = "1 MPa"\nalpha = 0.3'
YEOH = 'material = "yeoh"\nc10 = "85 kPa"\nc20 = "2 kPa"\nc30 = "0.1 kPa"'  # mu_0 = 2 C10 = 170 kPa
SPHERE = '[indenter]\nshape = "sphere"\nradius = "8 mm"\n'
SUFFIXES = ("_Pa", "_N", "_m", "_m2", "_m3")


def _run(tmp_path, name, rubber=MOONEY_RIVLIN, extra=""):
    """``pocket run`` of the case; its JSON and its CSV rows."""
    path = tmp_path / f"{name}.toml"
    path.write_text(CASE.format(rubber=rubber, extra=extra))
    assert main(["run", str(path), "--out", str(tmp_path)]) == 0
    result = json.loads((tmp_path / f"{name}.json").read_text())
    with (tmp_path / f"{name}.csv").open(newline="") as file:
        return result, list(csv.DictReader(file))


def _edge(state) -> int:
    """The index of the contact edge on the state's profile: its last point in contact."""
    return int(np.flatnonzero(state.profile.contact)[-1])


def test_plate_deformed_radius_is_area_radius(tmp_path, capsys):
    """Sample 1 under the plate (``pocket run --sample 1``): the zone in contact is a flat disc, so
    ``contact_radius_deformed_m`` = sqrt(``contact_area_m2`` / pi) (to 1e-6, as asked of it) in the JSON and
    the CSV alike; it is R rho at the contact edge of the shooting solver's own profile, solved again
    from the rows' inputs (to 1e-9: the solver's tolerance is 1e-10), and larger than the Lagrangian
    ``contact_radius_lagrangian_m`` a_c R by the uniform stretch of the contact zone, lambda_c."""
    assert main(["run", "--sample", "1", "--out", str(tmp_path)]) == 0
    capsys.readouterr()
    rows = json.loads((tmp_path / "sample1.json").read_text())["states"]
    with (tmp_path / "sample1.csv").open(newline="") as file:
        table = list(csv.DictReader(file))
    radius = sample(1).radius
    states = shooting.compression_curve(rows[0]["alpha"], rows[0]["pressure_initial"], [r["force"] for r in rows])
    pressed = 0
    for row, line, state in zip(rows, table, states, strict=True):
        for got in (row, {k: float(line[k]) for k in ("contact_radius_deformed_m", "contact_area_m2")}):
            assert got["contact_radius_deformed_m"] == pytest.approx(math.sqrt(got["contact_area_m2"] / math.pi),
                                                                     rel=1e-6, abs=1e-15)
        if row["force"] == 0.0:
            continue
        pressed += 1
        assert row["contact_radius_deformed_m"] == pytest.approx(state.profile.rho[_edge(state)] * radius, rel=1e-9)
        assert row["contact_radius_deformed_m"] == pytest.approx(
            row["contact_radius_lagrangian_m"] * row["stretch_contact"], rel=1e-9)
        assert row["contact_radius_deformed_m"] > 1.1 * row["contact_radius_lagrangian_m"]  # lambda_c ~ 1.15
        assert row["contact_radius_deformed"] == pytest.approx(row["contact_radius_deformed_m"] / radius, rel=1e-15)
    assert pressed == 6
    assert "contact_radius_m" not in rows[0]


def test_sphere_deformed_radius_not_lagrangian(tmp_path):
    """A sphere of 8 mm on a 20 mm pocket: ``contact_radius_deformed_m`` is the same from the two independent
    solvers run through ``pocket run`` (shooting and finite elements: to 1e-8, the agreement asked of
    their SI rows; measured ~1e-10); it is R rho at the contact edge of the shooting state's profile (to
    1e-9), and it exceeds the Lagrangian radius by the hoop stretch lambda_2 = rho / r there, read from
    that profile. The contact pressures, above P, are in the row in Pa and in Phat."""
    shot, _ = _run(tmp_path, "shot", extra=SPHERE)
    fe, _ = _run(tmp_path, "fe", extra=SPHERE + '[solver]\nname = "fem"\n')
    clamp, scale = 0.020, 1e6 * 0.25e-3 / 0.020  # R, and E T / R in Pa
    pressed = [(a, b) for a, b in zip(shot["states"], fe["states"], strict=True) if a["force"] > 0.0]
    assert len(pressed) == 2
    for a, b in pressed:
        assert b["contact_radius_deformed_m"] == pytest.approx(a["contact_radius_deformed_m"], rel=1e-8)
        state = shooting.compress(a["alpha"], a["pressure_initial"], a["force"], indenter=Sphere(0.008 / clamp))
        edge = _edge(state)
        assert a["contact_radius_deformed_m"] == pytest.approx(state.profile.rho[edge] * clamp, rel=1e-9)
        assert a["contact_radius_deformed_m"] / a["contact_radius_lagrangian_m"] == pytest.approx(
            state.profile.stretch_2[edge], rel=1e-9)
        assert a["contact_radius_deformed_m"] > 1.05 * a["contact_radius_lagrangian_m"]
        assert a["contact_pressure_edge_Pa"] == pytest.approx(a["contact_pressure_edge"] * scale, rel=1e-14)
        assert a["contact_pressure_pole"] > a["contact_pressure_edge"] > a["pressure"]


def test_sweep_carries_deformed_radius(tmp_path):
    """A sweep's rows under the plate and a sphere K = 0.5, in one file: under the plate
    ``contact_radius_deformed`` = sqrt(``contact_area``) (the flat disc, exactly: both cells are written with
    repr) and the contact pressure at pole and edge is ``pressure``; under the sphere they are the shooting
    solver's fresh solve of the point (to 1e-9: the sweep continues along the curve, each solve to the
    solver's tolerance 1e-10), the pressures above P; a point past the model's range leaves them empty."""
    path = tmp_path / "sweep.csv"
    forces = [0.2, 0.5, 50.0]  # 50: past the range under both
    with ThreadPoolExecutor(max_workers=1) as executor:
        run_sweep(path, [0.3], [0.3], forces, executor)
        run_sweep(path, [0.3], [0.3], forces, executor, indenter=Sphere(0.5))
    with path.open(newline="") as file:
        rows = list(csv.DictReader(file))
    assert sorted((r["indenter"], r["force"], r["status"]) for r in rows) == [
        (indenter, force, status) for indenter in ("plate", "sphere K=0.5")
        for force, status in (("0.2", "ok"), ("0.5", "ok"), ("50.0", "out_of_range"))]
    for row in rows:
        keys = ("contact_radius_deformed", "contact_pressure_pole", "contact_pressure_edge")
        if row["status"] != "ok":
            assert [row[k] for k in keys] == ["", "", ""]
            continue
        rho_c, pole, edge = (float(row[k]) for k in keys)
        if row["indenter"] == "plate":
            assert rho_c == math.sqrt(float(row["contact_area"]))
            assert pole == edge == float(row["pressure"])
        else:
            state = shooting.compress(0.3, 0.3, float(row["force"]), indenter=Sphere(0.5))
            assert rho_c == pytest.approx(state.contact_radius_deformed, rel=1e-9)
            assert (pole, edge) == pytest.approx((state.contact_pressure_pole, state.contact_pressure_edge), rel=1e-9)
            assert pole > edge > float(row["pressure"])
        assert rho_c > float(row["contact_radius"]) * 1.1  # the hoop stretch at the edge


def test_vtk_field_data_has_deformed_radius_and_contact_pressures(tmp_path):
    """A series under a sphere K = 0.5 (finite elements): each step's field data holds the state's
    ``contact_radius_deformed``, ``contact_pressure_pole`` and ``contact_pressure_edge`` exactly (written with
    17 digits); the deformed radius is where the file's own meridian leaves the sphere, the largest x of its
    points in contact (every step has a point at its contact edge: to 1e-9, the interpolation's rounding)."""
    forces = [0.1, 0.3, 0.6]
    states = fem.compression_curve(0.3, 0.3, forces, indenter=Sphere(0.5))
    out = files.write_series(tmp_path / "vtk", states, times=forces, segments=6)
    for k, state in enumerate(states):
        mesh = meshio.read(out / f"step_{k:04d}_profile.vtu")
        fields = {key: values.tolist() for key, values in mesh.field_data.items()}
        for key in ("contact_radius_deformed", "contact_pressure_pole", "contact_pressure_edge"):
            assert fields[key] == [getattr(state, key)], key
        touching = mesh.point_data["contact"] == 1
        assert fields["contact_radius_deformed"][0] == pytest.approx(mesh.points[touching, 0].max(), rel=1e-9)
        assert fields["contact_pressure_pole"][0] > fields["contact_pressure_edge"][0] > fields["pressure"][0]


def test_law_parameters_not_read_as_pascals(tmp_path):
    """A Yeoh rubber of C10 = 85 kPa, C20 = 2 kPa, C30 = 0.1 kPa (mu_0 = 2 C10 = 170 kPa): ``pocket run``'s CSV
    and JSON (the states and the inflated state) name its stresses ``c10_per_mu0``, ... and hold no bare
    ``c10``; times mu_0 = E / 3 (the JSON case's ``modulus_Pa``) they give back the case's pascals; the CSV's
    header is the JSON rows' keys. A sweep given the rubber in Pa from Python writes the same numbers in
    units of mu_0 (0.5, 2/170, 1/1700), not 85000; every column name with a unit is one of the SI suffixes."""
    result, rows = _run(tmp_path, "yeoh", rubber=YEOH)
    mu0 = result["case"]["modulus_Pa"] / 3.0
    assert mu0 == pytest.approx(170e3, rel=1e-15)
    assert list(rows[0]) == list(result["states"][0])
    for row in (*result["states"], result["inflated"], *rows):
        assert not {"c10", "c20", "c30"} & set(row)
        got = [float(row[f"c{k}0_per_mu0"]) * mu0 for k in (1, 2, 3)]
        assert got == pytest.approx([85e3, 2e3, 0.1e3], rel=1e-14)
    assert {k for k in rows[0] if k.endswith(SUFFIXES)} == {
        "force_N", "pressure_Pa", "pressure_rise_Pa", "contact_pressure_pole_Pa", "contact_pressure_edge_Pa",
        "contact_area_m2", "contact_radius_deformed_m", "contact_radius_lagrangian_m", "height_m", "travel_m",
        "volume_m3", "volume_lower_m3"}
    path = tmp_path / "sweep.csv"
    with ThreadPoolExecutor(max_workers=1) as executor:
        run_sweep(path, None, [0.3], [0.2], executor,
                  material=check("yeoh", {"c10": 85e3, "c20": 2e3, "c30": 0.1e3}))
    with path.open(newline="") as file:
        (row,) = csv.DictReader(file)
    assert not {"c10", "c20", "c30", "mu", "c1"} & set(row)
    assert [float(row[f"c{k}0_per_mu0"]) for k in (1, 2, 3)] == pytest.approx([0.5, 2 / 170, 1 / 1700], rel=1e-14)
    assert row["status"] == "ok"
