"""The indenter's surface in a VTK series: one dataset per step and ``indenter.pvd``, read back with meshio.
Exact answers: the flat plate is a disc at the state's height wider than the sheet; a sphere's points lie on
the sphere with its lowest point at the height; a profile table of that sphere lies on it to the table's
interpolation error; every step has the same points; an inflation path has no indenter."""

import xml.etree.ElementTree as ET

import meshio
import numpy as np
import pytest

from pocket import shooting
from pocket.apps.vtk import files, indentermesh
from pocket.cli import main
from pocket.core import profiles
from pocket.core.indenters import PLATE, Profile, Sphere

FORCES = [0.0, 0.5, 1.0]


def _read(path) -> meshio.Mesh:
    return meshio.read(path)


def test_a_compression_series_has_the_plate_pressing_at_each_step(tmp_path, capsys):
    """The plate of step k is the disc z = H_k / R (the state's height), its radius PLATE_MARGIN times the widest
    point of the sheet over the series (>= the clamp radius 1): it covers the pocket."""
    out = tmp_path / "vtk"
    argv = ["compress", "--pressure", "0.3", "--alpha", "0.1", "--force", *map(str, FORCES), "--vtk", str(out)]
    assert main(argv) == 0
    states = shooting.compression_curve(0.1, 0.3, FORCES)
    sets = ET.parse(out / "indenter.pvd").getroot().find("Collection").findall("DataSet")
    assert [float(d.get("timestep")) for d in sets] == FORCES
    widest = max(1.0, *(float(np.max(s.profile.rho)) for s in states))
    counts = set()
    for dataset, state in zip(sets, states, strict=True):
        mesh = _read(out / dataset.get("file"))
        counts.add(len(mesh.points))
        np.testing.assert_allclose(mesh.points[:, 2], state.height, rtol=1e-9)  # the solver's resolution
        radius = np.hypot(mesh.points[:, 0], mesh.points[:, 1]).max()
        assert radius == pytest.approx(indentermesh.PLATE_MARGIN * widest, rel=1e-12)
        assert radius > widest
        assert mesh.field_data["height"][0] == pytest.approx(state.height, rel=1e-9)
    assert len(counts) == 1  # the same points at every step


def test_an_inflation_path_has_no_indenter(tmp_path):
    states = [shooting.inflate(0.1, p) for p in (0.2, 0.3)]
    out = files.write_series(tmp_path / "vtk", states, segments=8)
    assert not list(out.glob("*indenter*"))


def _written(tmp_path, mesh) -> meshio.Mesh:
    path = tmp_path / "indenter.vtu"
    files._write_vtu(path, mesh)
    return _read(path)


def test_a_sphere_lies_on_the_sphere_with_its_lowest_point_at_the_height(tmp_path):
    radius, height = 0.4, 0.3
    mesh = _written(tmp_path, indentermesh.indenter_mesh(Sphere(radius), height, reach=1.5, segments=16))
    x, y, z = mesh.points.T
    np.testing.assert_allclose(np.hypot(np.hypot(x, y), z - height - radius), radius, rtol=1e-14)
    assert z.min() == height
    assert np.hypot(x, y).max() == pytest.approx(radius, rel=1e-15)
    assert mesh.field_data["radius"][0] == radius


def test_a_sphere_given_as_a_profile_draws_the_sphere(tmp_path):
    """To the table's interpolation error (``pocket.core.profiles``: 1e-7 R in height for 40 rows to 0.3 R)."""
    radius, height, top = 0.4, 0.3, 0.3
    rho = np.linspace(0.0, top, 40)
    tip = Profile(profiles.table(rho, Sphere(radius).height(rho)))
    mesh = _written(tmp_path, indentermesh.indenter_mesh(tip, height, reach=1.5, segments=16))
    x, y, z = mesh.points.T
    assert np.hypot(x, y).max() == pytest.approx(top, rel=1e-15)  # drawn to the table's last radius
    np.testing.assert_allclose(z, height + Sphere(radius).height(np.hypot(x, y)), atol=1e-7)


def test_the_flat_plate_mesh_is_a_disc(tmp_path):
    mesh = _written(tmp_path, indentermesh.indenter_mesh(PLATE, 0.25, reach=1.5, segments=16))
    assert np.all(mesh.points[:, 2] == 0.25)
    assert np.hypot(mesh.points[:, 0], mesh.points[:, 1]).max() == pytest.approx(1.5, rel=1e-15)
    assert {c.type for c in mesh.cells} == {"triangle", "quad"}
