"""VTK files of a capsule: the whole closed surface (the upper half's meridian mirrored through the equatorial
plane and revolved) and both plates, read back with pyvista and meshio.

The states are built by hand (``capsulestates``: an exact inflated sphere, a pressed shape of known volume), so
every expected number is exact or bounded by a stated discretisation error. A surface of revolution with N points
per ring is inscribed in the true one: its cross-sections are regular N-gons of area N sin(2 pi / N) / (2 pi)
times the circles', so its volume is exactly that factor times the volume of the meridian's polyline revolved,
which differs from the true volume by at most the surface's area times the chords' largest sagitta.
"""

from __future__ import annotations

import math
import pathlib

import meshio
import numpy as np
import pytest
from capsulestates import pressed, sphere

from pocket.apps.vtk import files
from pocket.apps.vtk.revolve import revolve
from pocket.core.errors import InputError
from pocket.core.geometries import GEOMETRIES

pv = pytest.importorskip("pyvista")

SEGMENTS = 64


def _inscribed(segments: int) -> float:
    """The area of a regular polygon of ``segments`` corners over its circumscribed circle's."""
    return segments * math.sin(2.0 * math.pi / segments) / (2.0 * math.pi)


def _closed_volume(path) -> tuple[int, float]:
    """(open edges, enclosed volume) of the surface in the .vtu file ``path``, by pyvista (VTK's mass properties)."""
    surface = pv.read(path).extract_surface(algorithm="dataset_surface").triangulate()
    return surface.n_open_edges, surface.volume


def test_revolving_a_meridian_from_pole_to_pole_closes_the_surface():
    """Exact answers: a meridian that starts and ends on the axis has one point at each pole and ``segments``
    on each ring between, triangles at both ends and quads between; it has no open edge, and each triangle
    fan shares its edges with the neighbouring band of quads."""
    angle = np.linspace(0.0, math.pi, 9)
    rho, eta = np.sin(angle), np.cos(angle)
    rho[[0, -1]] = 0.0
    surface = revolve(rho, eta, 8)
    assert len(surface.points) == 2 + 7 * 8
    assert [kind for kind, _ in surface.cells] == ["triangle", "quad", "triangle"]
    assert surface.points[-1].tolist() == [0.0, 0.0, -1.0]
    triangles = np.vstack([block for kind, block in surface.cells if kind == "triangle"])
    quads = next(block for kind, block in surface.cells if kind == "quad")
    mesh = pv.UnstructuredGrid({pv.CellType.QUAD: quads, pv.CellType.TRIANGLE: triangles}, surface.points)
    assert mesh.extract_surface(algorithm="dataset_surface").n_open_edges == 0


def test_an_inflated_capsule_is_written_as_the_whole_sphere(tmp_path):
    """Exact answers: the inflated sphere of stretch lambda is written (at its own points) as a closed surface
    whose every point lies at distance lambda from the centre (to round-off: lambda^2 (sin^2 + cos^2)), with
    both poles, at z = +-lambda; its volume is 4/3 pi lambda^3 times the inscribed polygons' factor, to within
    the area 4 pi lambda^2 times the sagitta lambda (dS)^2 / 8 of the meridian's chords; the profile runs from
    pole to pole through the equator, and its displacement from the unit sphere is (lambda - 1) times the
    position on it, mirrored below."""
    state = sphere(stretch=1.3, n=101)
    lam = state.stretch_pole
    profile, surface = files.write_state(tmp_path, state, segments=SEGMENTS)
    back = meshio.read(surface)
    np.testing.assert_allclose(np.linalg.norm(back.points, axis=1), lam, rtol=1e-14)
    assert sorted(back.points[:, 2])[0] == -lam
    assert sorted(back.points[:, 2])[-1] == lam
    open_edges, volume = _closed_volume(surface)
    sagitta = lam * (state.profile.r[1] - state.profile.r[0]) ** 2 / 8.0
    assert open_edges == 0
    assert abs(volume / _inscribed(SEGMENTS) - state.volume) <= 4.0 * math.pi * lam**2 * sagitta
    line = meshio.read(profile)
    assert len(line.points) == 2 * len(state.profile.r) - 1
    unit = line.points / lam
    np.testing.assert_allclose(line.point_data["displacement"], (lam - 1.0) * unit, atol=1e-14)
    assert back.field_data["geometry_code"].tolist() == [float(tuple(GEOMETRIES).index("capsule"))]
    assert back.field_data["radius_equator"].tolist() == [lam]


def test_a_pressed_capsules_series_has_the_closed_surface_and_both_plates(tmp_path):
    """Exact answers, for a series of two pressed shapes of known volume (``capsulestates.pressed``): each step's
    surface is closed, and its volume is the state's times the inscribed polygons' factor, to within the
    surface's area times the sagitta H (dtheta)^2 / 8 of the resampled meridian's chords on the rim's quarter
    circle (the resampling's spline error, fourth order in dS, is far below it); the surface reaches the plates
    at +-H; the indenter's file holds two discs, the upper one at +H and its mirror image at -H; the state's
    capsule keys are field data; the contact flag marks the plate's zone on both halves."""
    inflated = sphere(stretch=1.2)
    states = [pressed(inflated, 0.2, rho_c=0.4, height=0.9), pressed(inflated, 0.5, rho_c=0.6, height=0.7)]
    folder = files.write_series(tmp_path / "capsule", states, times=[0.2, 0.5], segments=SEGMENTS)
    names = sorted(p.name for p in folder.glob("*.pvd"))
    assert names == ["indenter.pvd", "profile.pvd", "surface.pvd"]
    step_arc = math.pi / 2 / (files.SERIES_POINTS - 1)
    for k, state in enumerate(states):
        surface = folder / f"step_{k:04d}_surface.vtu"
        open_edges, volume = _closed_volume(surface)
        rho_c, height = state.contact_radius_deformed, state.height
        dtheta = step_arc * (math.pi / 2) / (math.pi / 2 - state.contact_radius)
        area = 2.0 * (math.pi * rho_c**2 + 2.0 * math.pi * (rho_c + height) * math.pi * height / 2.0)
        assert open_edges == 0
        assert abs(volume / _inscribed(SEGMENTS) - state.volume) <= area * height * dtheta**2 / 8.0, (volume, k)
        back = meshio.read(surface)
        assert back.points[:, 2].max() == pytest.approx(height, abs=1e-15)
        assert back.points[:, 2].min() == pytest.approx(-height, abs=1e-15)
        on_plate = back.point_data["contact"].astype(bool)
        np.testing.assert_allclose(np.abs(back.points[on_plate, 2]), height, atol=1e-15)
        assert (back.points[on_plate, 2] < 0).any()
        assert (back.points[on_plate, 2] > 0).any()
        for key in ("stretch_pole", "radius_equator", "force_ETR", "volume", "height"):
            value = state.extra[key] if key in state.extra else getattr(state, key)
            assert back.field_data[key].tolist() == [value], key
        plates = pv.read(folder / f"step_{k:04d}_indenter.vtu")
        heights = np.unique(np.asarray(plates.points)[:, 2])
        assert heights.tolist() == [-height, height]
        assert plates.n_cells % 2 == 0
        assert np.linalg.norm(np.asarray(plates.points)[:, :2], axis=1).max() > state.extra["radius_equator"]


def test_a_pockets_files_are_unchanged_by_the_mirror(tmp_path):
    """Exact answer: a pocket's (the flat disc's) profile is written as it is, pole to clamp, with the
    displacement from the flat sheet (rho - r, 0, eta), and no ``geometry_code`` (its state names no
    geometry)."""
    from pocket import shooting

    state = shooting.inflate(0.1, 0.2)
    mesh = files.profile_mesh(state)
    assert len(mesh.points) == len(state.profile.r)
    expected = np.column_stack((state.profile.rho - state.profile.r, 0.0 * state.profile.r, state.profile.eta))
    np.testing.assert_array_equal(mesh.point_data["displacement"], expected)
    assert "geometry_code" not in mesh.field_data
    assert pathlib.Path(tmp_path).exists()


def test_a_solved_capsules_surface_encloses_its_volume(tmp_path):
    """Exact answer: the closed surface of a capsule pressed by the shooting solver encloses the state's volume,
    up to the polygons' factor (exact) and the meridian's chords, whose error is of second order in the arc length
    step: written with four times the points, the remaining error is at most an eighth of the first (order 2 gives
    a sixteenth), and below 1e-4 of the volume."""
    from pocket import shooting

    try:
        states = shooting.compression_curve(0.1, 0.3, [0.3], geometry="capsule")
    except InputError:
        pytest.skip("the shooting solver does not pose the capsule yet")
    errors = []
    for points in (101, 401):
        folder = files.write_series(tmp_path / f"p{points}", states, times=[0.3], segments=SEGMENTS, points=points)
        open_edges, volume = _closed_volume(folder / "step_0000_surface.vtu")
        assert open_edges == 0
        errors.append(abs(volume / _inscribed(SEGMENTS) - states[0].volume))
    assert errors[1] <= errors[0] / 8.0, errors
    assert errors[1] <= 1e-4 * states[0].volume, errors
