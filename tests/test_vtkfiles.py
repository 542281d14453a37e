"""VTK output: profile and revolved surface of synthetic states, resampling, field data, series, atomic writes.

The states are built analytically (a spherical cap; a flat-topped pocket whose
free part is a circular arc), not solved, so these tests do not depend on the
solvers and every expected number is exact.
"""

from __future__ import annotations

import dataclasses
import math
import xml.etree.ElementTree as ET

import meshio
import numpy as np
import pytest

from pocket import shooting
from pocket.apps import folders
from pocket.apps.contactpatch import KEYS as CONTACT
from pocket.apps.vtk import files, resampling
from pocket.core.errors import InputError
from pocket.core.materials import mooney_rivlin
from pocket.core.states import CHECKS, CompressedState, InflatedState, Profile

NAMES = {"lambda_1", "lambda_2", "lambda_3", "T_1", "T_2", "contact", "displacement", "r"}


def _profile(r, rho, eta, contact, pressure):
    """Stretches from the geometry (lambda_1 = ds/dr, lambda_2 = rho/r); made-up tensions."""
    stretch_1 = np.hypot(np.gradient(rho, r), np.gradient(eta, r))
    stretch_2 = np.where(r > 0, rho / np.where(r > 0, r, 1.0), stretch_1)
    return Profile(r, rho, eta, stretch_1, stretch_2, pressure * stretch_1, pressure * stretch_2, contact)


def cap(height, n=201, pressure=0.1):
    """Spherical cap through the clamp (1, 0) with pole height ``height``, uniform meridional stretch.

    Sphere radius a = (1 + h^2)/(2 h); exact volume pi h^2 (3 a - h) / 3.
    """
    a = (1 + height**2) / (2 * height)
    r = np.linspace(0.0, 1.0, n)
    phi = r * math.asin(1 / a)
    rho, eta = a * np.sin(phi), height - a * (1 - np.cos(phi))
    rho[0], rho[-1], eta[-1] = 0.0, 1.0, 0.0
    volume = math.pi * height**2 * (3 * a - height) / 3
    profile = _profile(r, rho, eta, np.zeros(n, bool), pressure)
    stretches = profile.stretch_1[0], height, volume, profile.stretch_1[-1]
    return InflatedState(mooney_rivlin(0.3), pressure, *stretches, profile, "test")


def pressed_shape(r, contact_radius=0.3, stretch=1.2, height=0.3):
    """(rho, eta) at Lagrangian radii ``r`` of the flat-topped pocket: rho = stretch r, eta = height for
    r <= a_c, then a circular arc with horizontal tangent at the contact edge down to the clamp (1, 0),
    its angle linear in r. Arc radius b = ((1 - c)^2 + H^2) / (2 H) about (c, H - b), c = stretch a_c."""
    c, H = stretch * contact_radius, height
    b = ((1 - c) ** 2 + H**2) / (2 * H)
    free = r > contact_radius
    psi = (r - contact_radius) / (1 - contact_radius) * math.acos((b - H) / b)
    return np.where(free, c + b * np.sin(psi), stretch * r), np.where(free, H - b + b * np.cos(psi), H)


def pressed(n=201, contact_radius=0.3, stretch=1.2, height=0.3, r=None):
    """The flat-topped pocket (``pressed_shape``) sampled at ``r`` (default n equally spaced radii).

    Volume pi int_0^H (c + s)^2 dz, s = sqrt(b^2 - (z - H + b)^2): closed form below.
    """
    c, H = stretch * contact_radius, height
    b = ((1 - c) ** 2 + H**2) / (2 * H)
    r = np.linspace(0.0, 1.0, n) if r is None else r
    free = r > contact_radius
    rho, eta = pressed_shape(r, contact_radius, stretch, height)
    rho[-1], eta[-1] = 1.0, 0.0
    u0, u1 = b - H, b  # u = z - (H - b) over the free part

    def segment(u):  # an antiderivative of sqrt(b^2 - u^2)
        return u * math.sqrt(max(b * b - u * u, 0.0)) / 2 + b * b * math.asin(u / b) / 2

    volume = math.pi * (c * c * H + 2 * c * (segment(u1) - segment(u0)) + b * b * H - (u1**3 - u0**3) / 3)
    pressure = 0.2
    profile = _profile(r, rho, eta, ~free, pressure)
    inflated = cap(0.4)
    area = c * c  # A_c / (pi R^2)
    return CompressedState(
        mooney_rivlin(0.3), inflated.pressure, pressure * area / inflated.pressure, pressure,
        pressure / inflated.pressure, area, contact_radius, stretch, H, H / inflated.height, volume, profile,
        inflated, "test",
    )


def enclosed_volume(mesh):
    """Volume between the surface and the plane z = 0, by the divergence theorem with F = (0, 0, z).

    The base disk (z = 0) adds nothing; each planar cell, split into triangles
    (a, b, c), adds ((b - a) x (c - a))_z / 2 * (z_a + z_b + z_c) / 3.
    """
    p = mesh.points
    total = 0.0
    for block in mesh.cells:
        cells = block.data
        for k in range(1, cells.shape[1] - 1):
            a, b, c = p[cells[:, 0]], p[cells[:, k]], p[cells[:, k + 1]]
            normal_z = np.cross(b - a, c - a)[:, 2] / 2
            total += np.sum(normal_z * (a[:, 2] + b[:, 2] + c[:, 2]) / 3)
    return total


def polyline_volume(state):
    """2 pi int eta rho d rho over the straight segments of the profile, exactly (eta linear in rho)."""
    rho, eta = state.profile.rho, state.profile.eta
    r0, r1, z0, z1 = rho[:-1], rho[1:], eta[:-1], eta[1:]
    # int_{r0}^{r1} (z0 + (z1 - z0) (x - r0)/(r1 - r0)) x dx = (r1 - r0) (z0 (2 r0 + r1) + z1 (r0 + 2 r1)) / 6
    return 2 * math.pi * np.sum((r1 - r0) * (z0 * (2 * r0 + r1) + z1 * (r0 + 2 * r1)) / 6)


STATES = {"cap": cap(0.5), "pressed": pressed()}


@pytest.mark.parametrize("kind", STATES)
def test_profile_mesh(kind):
    """Points (rho, 0, eta) in order, a chain of lines, the named point data."""
    state = STATES[kind]
    mesh = files.profile_mesh(state)
    np.testing.assert_array_equal(mesh.points[:, 0], state.profile.rho)
    np.testing.assert_array_equal(mesh.points[:, 2], state.profile.eta)
    assert mesh.cells[0].type == "line"
    assert len(mesh.cells[0].data) == len(state.profile.r) - 1
    assert set(mesh.point_data) == NAMES
    np.testing.assert_array_equal(mesh.point_data["contact"], state.profile.contact)
    np.testing.assert_array_equal(mesh.point_data["lambda_3"], state.profile.stretch_3)


@pytest.mark.parametrize("kind", STATES)
@pytest.mark.parametrize("segments", [3, 16])
def test_surface_topology(kind, segments):
    """The pole is one point with a fan of triangles; no duplicate points; quads elsewhere."""
    state = STATES[kind]
    n = len(state.profile.r)
    mesh = files.surface_mesh(state, segments=segments)
    assert len(mesh.points) == 1 + (n - 1) * segments
    assert len(np.unique(mesh.points.round(14), axis=0)) == len(mesh.points)
    blocks = {block.type: block.data for block in mesh.cells}
    assert len(blocks["triangle"]) == segments
    assert len(blocks["quad"]) == (n - 2) * segments
    used = np.unique(np.concatenate([b.ravel() for b in blocks.values()]))
    np.testing.assert_array_equal(used, np.arange(len(mesh.points)))


def test_surface_off_axis():
    """A profile starting off the axis keeps its first ring: quads only."""
    state = cap(0.5)
    profile = Profile(*(getattr(state.profile, f)[1:] for f in ("r", "rho", "eta", "stretch_1", "stretch_2",
                                                                "tension_1", "tension_2", "contact")))
    mesh = files.surface_mesh(dataclasses.replace(state, profile=profile), segments=8)
    assert [b.type for b in mesh.cells] == ["quad"]
    assert len(mesh.points) == 8 * len(profile.r)


@pytest.mark.parametrize("kind", STATES)
def test_surface_point_data(kind):
    """Point data copied around each ring; deformed minus displacement is the flat sheet at radius r."""
    state = STATES[kind]
    mesh = files.surface_mesh(state, segments=12)
    assert set(mesh.point_data) == NAMES
    reference = mesh.points - mesh.point_data["displacement"]
    np.testing.assert_allclose(np.hypot(reference[:, 0], reference[:, 1]), mesh.point_data["r"], atol=1e-15)
    np.testing.assert_allclose(reference[:, 2], 0.0, atol=0)
    radius = np.hypot(mesh.points[:, 0], mesh.points[:, 1])
    ring = np.searchsorted(state.profile.r, mesh.point_data["r"])  # r is copied exactly
    np.testing.assert_array_equal(state.profile.r[ring], mesh.point_data["r"])
    np.testing.assert_allclose(state.profile.rho[ring], radius, atol=1e-14)
    np.testing.assert_array_equal(mesh.point_data["T_1"], state.profile.tension_1[ring])
    np.testing.assert_array_equal(mesh.point_data["contact"], state.profile.contact[ring])


@pytest.mark.parametrize("kind", STATES)
@pytest.mark.parametrize("segments", [3, 7, 64])
def test_volume_is_polygon_factor_times_polyline_volume(kind, segments):
    """Exact identity: the polyhedron's volume is N sin(2 pi/N)/(2 pi) times the volume of
    revolution of the profile's polyline (each sector is the circular one scaled by cos(pi/N)
    radially and cut to a triangle). Round-off only: rel 1e-12."""
    state = STATES[kind]
    volume = enclosed_volume(files.surface_mesh(state, segments=segments))
    factor = segments * math.sin(2 * math.pi / segments) / (2 * math.pi)
    assert volume == pytest.approx(factor * polyline_volume(state), rel=1e-12)


@pytest.mark.parametrize("kind", STATES)
def test_volume_converges_at_second_order(kind):
    """The enclosed volume tends to the analytical one as segments^-2 (polygon area).

    The profile has 4001 points, so the meridian error (about 1e-8 relative) stays
    far below the angular error of 128 segments (about 4e-4 relative)."""
    state = cap(0.5, n=4001) if kind == "cap" else pressed(n=4001)
    segments = np.array([8, 16, 32, 64, 128])
    volumes = [enclosed_volume(files.surface_mesh(state, segments=s)) for s in segments]
    errors = np.abs(np.array(volumes) - state.volume)
    order = -np.polyfit(np.log(segments), np.log(errors), 1)[0]
    assert abs(order - 2) < 0.05, f"observed order {order!r}, errors {errors!r}"
    assert errors[-1] < 5e-4 * state.volume, errors
    # the limit itself: the polyline volume is the analytical volume to 1e-7 (meridian sampling)
    assert polyline_volume(state) == pytest.approx(state.volume, rel=1e-7)


@pytest.mark.parametrize("kind", STATES)
def test_write_state_round_trip(tmp_path, kind):
    """meshio reads back the same points, cells and point data; the state is not changed."""
    state = STATES[kind]
    before = {f: np.copy(getattr(state.profile, f)) for f in ("r", "rho", "eta", "contact")}
    paths = files.write_state(tmp_path / "out", state, stem="s", segments=10)
    assert [p.name for p in paths] == ["s_profile.vtu", "s_surface.vtu"]
    expected = [files.profile_mesh(state), files.surface_mesh(state, segments=10)]
    for path, mesh in zip(paths, expected, strict=True):
        back = meshio.read(path)
        np.testing.assert_array_equal(back.points, mesh.points)
        assert [b.type for b in back.cells] == [b.type for b in mesh.cells]
        for got, want in zip(back.cells, mesh.cells, strict=True):
            np.testing.assert_array_equal(got.data, want.data)
        assert set(back.point_data) == NAMES
        for name, values in mesh.point_data.items():
            np.testing.assert_array_equal(back.point_data[name], values)
    for f, values in before.items():
        np.testing.assert_array_equal(getattr(state.profile, f), values)


def test_pyvista_reads_state(tmp_path):
    """pyvista (VTK's own reader) opens the surface with every point array."""
    pv = pytest.importorskip("pyvista")
    state = STATES["pressed"]
    _, surface = files.write_state(tmp_path, state, segments=10)
    grid = pv.read(surface)
    assert grid.n_points == 1 + (len(state.profile.r) - 1) * 10
    assert set(grid.point_data.keys()) >= NAMES
    expected = files.surface_mesh(state, segments=10)
    np.testing.assert_array_equal(grid.point_data["contact"], expected.point_data["contact"])
    np.testing.assert_array_equal(grid.points, expected.points)


def edged(n, contact_radius):
    """n equally spaced Lagrangian radii and the contact edge: a solver's profile has a point there."""
    return np.union1d(np.linspace(0.0, 1.0, n), [contact_radius])


def series():
    """A synthetic compression path: pocket flattening, plate force as time; each profile has its own
    point count, as the shooting solver's have."""
    states = [pressed(contact_radius=a, height=h, r=edged(n, a))
              for n, a, h in [(41, 0.1, 0.4), (57, 0.2, 0.35), (33, 0.3, 0.3)]]
    return states, [s.force for s in states]


def test_write_series(tmp_path):
    """One profile, one surface and (compressed states) one indenter per step; each .pvd lists every step with its
    time, relative names."""
    states, forces = series()
    out = files.write_series(tmp_path / "path", states, times=forces, segments=8)
    names = sorted(p.name for p in out.iterdir())
    parts = ("profile", "surface", "indenter")
    steps = [f"step_{k:04d}_{part}.vtu" for k in range(3) for part in parts]
    assert names == sorted(steps + [f"{part}.pvd" for part in parts] + [folders.MARKER])
    for part in parts:
        root = ET.parse(out / f"{part}.pvd").getroot()
        assert root.get("type") == "Collection"
        sets = root.find("Collection").findall("DataSet")
        assert [d.get("file") for d in sets] == [f"step_{k:04d}_{part}.vtu" for k in range(3)]
        assert [float(d.get("timestep")) for d in sets] == forces  # repr(): exact
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]  # no temporary left


def test_pyvista_reads_series(tmp_path):
    """pyvista's PVD reader lists the times and reads each step's surface."""
    pv = pytest.importorskip("pyvista")
    states, forces = series()
    out = files.write_series(tmp_path / "path", states, times=forces, segments=8)
    reader = pv.get_reader(out / "surface.pvd")
    assert reader.time_values == pytest.approx(forces, rel=1e-15)
    for state, force in zip(states, forces, strict=True):
        reader.set_active_time_value(force)
        block = reader.read()[0]
        assert block.points[:, 2].max() == pytest.approx(state.height, rel=1e-15)
        assert set(block.point_data.keys()) >= NAMES
    assert [d.path for d in reader.datasets] == [f"step_{k:04d}_surface.vtu" for k in range(3)]
    first = pv.read(out / "profile.pvd")  # pyvista.read gives the first step as a MultiBlock
    radii = resampling.series_radii([s.profile for s in states], files.SERIES_POINTS)
    assert first[0].n_points == len(radii)


def test_series_default_times(tmp_path):
    """Times default to the step index."""
    states, _ = series()
    out = files.write_series(tmp_path / "path", states, segments=4)
    sets = ET.parse(out / "surface.pvd").getroot().iter("DataSet")
    assert [float(d.get("timestep")) for d in sets] == [0.0, 1.0, 2.0]


def test_series_is_atomic(tmp_path, monkeypatch):
    """A failure mid-way (third file) leaves neither the directory nor a temporary behind."""
    states, _ = series()
    calls, write = [], meshio.write

    def failing(*args, **kwargs):
        calls.append(args[0])
        if len(calls) == 3:
            raise OSError("disk full")
        write(*args, **kwargs)

    monkeypatch.setattr(meshio, "write", failing)
    with pytest.raises(OSError, match="disk full"):
        files.write_series(tmp_path / "path", states)
    assert list(tmp_path.iterdir()) == []
    # the same with overwrite: the old series survives untouched
    monkeypatch.setattr(meshio, "write", write)
    files.write_series(tmp_path / "path", states[:1])
    old = sorted(p.name for p in (tmp_path / "path").iterdir())
    calls.clear()
    monkeypatch.setattr(meshio, "write", failing)
    with pytest.raises(OSError, match="disk full"):
        files.write_series(tmp_path / "path", states, overwrite=True)
    assert sorted(p.name for p in (tmp_path / "path").iterdir()) == old
    assert [p.name for p in tmp_path.iterdir()] == ["path"]


def test_series_refuses_non_empty(tmp_path):
    """A directory pocket did not write is refused even with overwrite=True; a series it wrote is
    refused without overwrite, then replaced as a whole with it."""
    states, _ = series()
    target = tmp_path / "path"
    target.mkdir()
    (target / "stale.txt").write_text("old")
    for overwrite in (False, True):
        with pytest.raises(InputError, match=r"holds stale\.txt, which pocket did not write"):
            files.write_series(target, states, overwrite=overwrite)
    (target / "stale.txt").unlink()
    files.write_series(target, states[:1])
    with pytest.raises(InputError, match="previous VTK series"):
        files.write_series(target, states)
    files.write_series(target, states, overwrite=True)
    assert (target / "step_0002_surface.vtu").exists()
    assert [p.name for p in tmp_path.iterdir()] == ["path"]
    empty = tmp_path / "empty"
    empty.mkdir()
    assert (files.write_series(empty, states[:1]) / "profile.pvd").exists()


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"times": [0.0, 1.0]}, "there are 3 states"),
        ({"times": [0.0, 2.0, 1.0]}, "strictly increasing"),
        ({"times": [0.0, 1.0, math.nan]}, "strictly increasing"),
        ({"segments": 2}, "segments = 2"),
        ({"segments": 4.0}, "segments = 4.0"),
    ],
)
def test_series_bad_input(tmp_path, kwargs, message):
    """Bad times or segments: InputError before any file is written."""
    states, _ = series()
    with pytest.raises(InputError, match=message):
        files.write_series(tmp_path / "path", states, **kwargs)
    assert list(tmp_path.iterdir()) == []


def test_no_profile(tmp_path):
    """A state without a profile (and an empty series) is refused with one line."""
    state = dataclasses.replace(cap(0.5), profile=None)
    with pytest.raises(InputError, match="no profile"):
        files.write_state(tmp_path, state)
    with pytest.raises(InputError, match="no states"):
        files.write_series(tmp_path / "path", [])


def test_resample_keeps_the_flat_zone_and_the_kink():
    """Exact answer: ``pressed_shape`` itself. The flat zone (rho = stretch r, eta = H) is reproduced to
    round-off (cubic splines reproduce lines and constants); on the arc, splines through 201 points
    (h = 0.005) are fourth-order accurate: below 1e-9 at 1001 other radii (measured 3.6e-11). ``contact``
    is exactly r <= a_c. A single spline across the edge, as a resampler blind to the kink would use, is
    off by about the curvature jump times h^2 (measured 8e-7): over 1e3 times further (measured 2e4)."""
    from scipy.interpolate import CubicSpline

    a = 0.3
    state = pressed(contact_radius=a, r=edged(201, a))
    at = np.linspace(0.0, 1.0, 1001)
    out = resampling.resample(state.profile, at)
    rho, eta = pressed_shape(at, contact_radius=a)
    flat = at <= a
    np.testing.assert_array_equal(out.contact, flat)
    np.testing.assert_allclose(out.eta[flat], 0.3, rtol=0, atol=1e-15)
    np.testing.assert_allclose(out.rho[flat], 1.2 * at[flat], rtol=0, atol=1e-15)
    piecewise = max(np.abs(out.rho - rho).max(), np.abs(out.eta - eta).max())
    assert piecewise < 1e-9, piecewise
    blind = np.abs(CubicSpline(state.profile.r, state.profile.eta)(at) - eta).max()
    assert blind > 1e3 * piecewise, (blind, piecewise)


def test_resample_at_the_solver_radii_is_the_identity():
    """Exact answer: resampled at its own radii a profile is unchanged (a spline passes through its data)."""
    state = pressed(contact_radius=0.25, r=edged(81, 0.25))
    out = resampling.resample(state.profile, state.profile.r)
    for name in ("r", "rho", "eta", "stretch_1", "stretch_2", "tension_1", "tension_2", "contact"):
        np.testing.assert_allclose(getattr(out, name), getattr(state.profile, name), rtol=1e-14, atol=1e-15,
                                   err_msg=name)


@pytest.mark.parametrize(("radii", "message"), [([0.0], "at least 2"), ([0.5, 0.2], "increasing"),
                                            ([0.0, 1.5], "increasing"), ([], "empty")])
def test_resample_refuses_bad_radii(radii, message):
    """Exact answer: radii outside the profile's span, decreasing or too few are an InputError."""
    with pytest.raises(InputError, match=message):
        resampling.resample(cap(0.5).profile, radii)


def test_series_radii_hold_every_contact_edge():
    """Exact answer: the equally spaced radii plus each state's contact edge, each edge once; an edge within
    1e-9 of an equally spaced radius replaces it (no two points nearly coincide)."""
    states, _ = series()
    radii = resampling.series_radii([s.profile for s in states], 11)
    assert set(np.round(np.linspace(0, 1, 11), 12)) | {0.1, 0.2, 0.3} == set(np.round(radii, 12))
    assert len(radii) == 11
    assert {0.1, 0.2, 0.3} <= set(radii.tolist())
    assert np.diff(radii).min() > 0.05


def test_series_has_one_point_set(tmp_path):
    """Exact answer: every step of a series (profiles of 41, 57 and 33 points) has the same points count
    and the same Lagrangian radii r, so an index is one material point; each step has a point exactly at
    its own contact edge, in contact, and the next point is free (read back with meshio)."""
    states, forces = series()
    out = files.write_series(tmp_path / "path", states, times=forces, segments=6)
    radii = None
    for k, state in enumerate(states):
        profile = meshio.read(out / f"step_{k:04d}_profile.vtu")
        surface = meshio.read(out / f"step_{k:04d}_surface.vtu")
        radii = profile.point_data["r"] if radii is None else radii
        np.testing.assert_array_equal(profile.point_data["r"], radii)
        assert len(surface.points) == 1 + (len(radii) - 1) * 6
        edge = int(np.flatnonzero(radii == state.contact_radius)[0])
        assert profile.point_data["contact"][edge] == 1
        assert profile.point_data["contact"][edge + 1] == 0
        assert profile.points[edge, 0] == pytest.approx(1.2 * state.contact_radius, abs=1e-15)


#: the codes of the file format as the README's VTK table lists them: field -> the names, in code order
CODES = {"solver_code": ("shooting", "fem", "analytical"),
         "material_code": ("mooney-rivlin", "neo-hookean", "yeoh", "gent", "ogden"),
         "fluid_code": ("liquid", "gas"), "contact_code": ("fitted", "penalty")}


def _numbers(state) -> dict:
    """What the field data must hold: the state's numeric attributes and those of its material and fluid,
    its solver, law and fluid by name (None for a solver outside pocket), the solver's numeric
    diagnostics and its contact method by name."""
    out = {k: [float(getattr(state, k))] for k in (*state.KEYS, *CHECKS) if getattr(state, k) is not None}
    if hasattr(state, "indenter"):  # the contact patch: on the plate a flat disc of area A_c, pressed at P
        flat = state.indenter.pressure_area
        out["contact_radius_deformed"] = [math.sqrt(state.contact_area) if flat else state.contact_radius_deformed]
        out.update({k: [state.pressure if flat else getattr(state, k)] for k in CONTACT})
    params = dict(state.material.params)
    if hasattr(state, "fluid") and state.fluid.is_gas:
        params.update(ambient=state.fluid.ambient, gamma=state.fluid.gamma)
    out.update({k: list(v) if isinstance(v, tuple) else [v] for k, v in params.items()})
    out.update(solver_code=state.solver if state.solver in CODES["solver_code"] else None,
               material_code=state.material.law, fluid_code=state.fluid.kind if hasattr(state, "fluid") else "liquid")
    for key, value in state.extra.items():
        out[f"{key}_code" if isinstance(value, str) else key] = value if isinstance(value, str) else [float(value)]
    return out


def _read(field_data) -> dict:
    """Field data read back (lists), each code replaced by the name it stands for (None for -1)."""
    out = {key: values.tolist() for key, values in field_data.items()}
    for key, names in CODES.items():
        if key in out:
            (code,) = out[key]
            assert code == int(code), (key, code)
            assert -1 <= code < len(names), (key, code)
            out[key] = None if code == -1 else names[int(code)]
    return out


def test_field_data_round_trip(tmp_path):
    """Exact answer: each step carries its state's scalars (force, pressure, P/P_I, height, volume,
    contact radius, ..., the contact patch: on the plate its deformed radius sqrt(A_c / (pi R^2)) and the
    contact pressure P at the pole and the edge; the smallest tensions, the wrinkling flag as 0 or 1, the rubber's
    parameters c1 and c2 in units of mu_0) as field data; meshio and pyvista's PVD reader give them
    back exactly."""
    states, forces = series()
    out = files.write_series(tmp_path / "path", states, times=forces, segments=6)
    for k, state in enumerate(states):
        for part in ("profile", "surface"):
            back = meshio.read(out / f"step_{k:04d}_{part}.vtu")
            expected = _numbers(state)
            assert set(expected) == {*CompressedState.KEYS, "contact_radius_deformed", *CONTACT, *CHECKS, "c1", "c2",
                                     *CODES} - {"contact_code"}
            assert _read(back.field_data) == expected
            assert back.field_data["wrinkled"].tolist() == [0.0]
    pv = pytest.importorskip("pyvista")
    reader = pv.get_reader(out / "surface.pvd")
    for state, force in zip(states, forces, strict=True):
        reader.set_active_time_value(force)
        block = reader.read()[0]
        for key in ("force", "pressure", "pressure_ratio", "height", "volume", "contact_radius"):
            assert block.field_data[key][0] == float(getattr(state, key)), key


def test_inflated_state_field_data():
    """Exact answer: an inflated state carries its own keys (pressure, stretch_pole, height, ...)."""
    state = cap(0.5)
    mesh = files.profile_mesh(state)
    assert _read(mesh.field_data) == _numbers(state)
    assert set(_numbers(state)) == {*InflatedState.KEYS, *CHECKS, "c1", "c2", *CODES} - {"contact_code"}


def test_other_law_and_gas_field_data(tmp_path):
    """Exact answer: an Ogden rubber in a gas-filled pocket carries no alpha, its mu and exponents one
    value per term (units of mu_0 and numbers), and the gas's Phat_atm and gamma; written and read
    back exactly."""
    from pocket.core.fluids import gas
    from pocket.core.materials import check

    ogden = check("ogden", {"mu": [630e3, 1.2e3, -10e3], "exponents": [1.3, 5.0, -2.0]}).scaled()
    state = shooting.compress(ogden, 0.3, 0.2, fluid=gas(6.5, 1.4))
    paths = files.write_state(tmp_path, state, segments=6)
    back = meshio.read(paths[0])
    expected = _numbers(state)
    assert "alpha" not in expected
    assert expected["exponents"] == [1.3, 5.0, -2.0]
    assert expected["ambient"] == [6.5]
    assert expected["material_code"] == "ogden"
    assert expected["fluid_code"] == "gas"
    assert _read(back.field_data) == expected
