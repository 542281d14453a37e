"""VTK files of solved states for ParaView: the profile, the surface, a load path.

Any state with a ``profile`` (``pocket.core.states.InflatedState`` or
``CompressedState``) can be written; the files hold dimensionless lengths (R).

Axes. z is the height eta, up; the sheet is clamped on the circle of radius 1
in the plane z = 0 and the fluid lies beneath it, between the sheet and that
plane. The profile is the meridian in the plane y = 0: point i at
(rho_i, 0, eta_i), ``line`` cells joining consecutive points from the pole.

Surface of revolution. The profile revolved about the z axis with
``segments`` points per ring: point (i, j) at
(rho_i cos t_j, rho_i sin t_j, eta_i), t_j = 2 pi j / segments, and ``quad``
cells (i, j), (i+1, j), (i+1, j+1), (i, j+1), wrapping around in j. Their
normal, (meridian tangent) x (hoop tangent), points away from the fluid (up
at the top of a dome). If the profile starts on the axis (rho_0 = 0, the pole
r = 0) its ring would be ``segments`` copies of one point and its quads
degenerate: that ring is collapsed to a single point and the first band is
made of ``triangle`` cells (pole, (1, j), (1, j+1)) instead. A profile that
starts off the axis (rho_0 > 0) keeps its first ring, leaving a small hole at
the top.

Each quad is an isosceles trapezoid, hence planar: together with the base
disk the cells bound a polyhedron inscribed in the true surface. Its volume
tends to the true volume as segments^-2 (a regular N-gon inscribed in a
circle has N sin(2 pi/N) / (2 pi) = 1 - (2 pi/N)^2 / 6 + ... of its area),
plus the error of sampling the meridian at the profile's points.

Point data, on the profile and the surface alike (copied around each ring):
``lambda_1``, ``lambda_2``, ``lambda_3`` (meridional, hoop, thickness
stretches), ``T_1``, ``T_2`` (tensions, units of E T), ``contact`` (1 where
the sheet touches the plate, else 0, uint8), ``r`` (Lagrangian radius) and
``displacement``, the deformed minus the reference position of each material
point, the reference being the flat sheet at height 0: point (r, t) of the
sheet moves from (r cos t, r sin t, 0) to (rho cos t, rho sin t, eta), so the
displacement is ((rho - r) cos t, (rho - r) sin t, eta). In ParaView,
"Warp By Vector" with scale -1 brings the surface back to the flat sheet.

Load paths. ``write_series`` writes ``step_0000_profile.vtu``,
``step_0000_surface.vtu``, ... and the collections ``profile.pvd`` and
``surface.pvd`` (file names relative to them), so ParaView plays the path as a
time series. The "time" of a step defaults to its index; a compression path
should pass the force Fhat (an inflation path the pressure or the volume),
strictly increasing. The directory appears complete or not at all: the files
go into a temporary sibling directory that is renamed into place at the end
and removed on any failure.
"""

from __future__ import annotations

import operator
import pathlib
from xml.sax.saxutils import quoteattr

import meshio
import numpy as np

from pocket.core.errors import InputError

from .folders import staged

__all__ = ["profile_mesh", "surface_mesh", "write_state", "write_series"]


def _profile(state):
    profile = getattr(state, "profile", None)
    if profile is None:
        raise InputError(f"{type(state).__name__} has no profile to write (the solver returned none)")
    n = len(profile.r)
    if n < 2 or any(len(getattr(profile, f)) != n for f in ("rho", "eta", "stretch_1", "stretch_2")):
        raise InputError(f"the profile needs >= 2 points and arrays of equal length, got r of length {n}")
    return profile


def _point_data(profile) -> dict[str, np.ndarray]:
    """Per-point fields of the profile (displacement in the plane y = 0)."""
    r, rho, eta = (np.asarray(a, dtype=float) for a in (profile.r, profile.rho, profile.eta))
    return {
        "lambda_1": np.asarray(profile.stretch_1, dtype=float),
        "lambda_2": np.asarray(profile.stretch_2, dtype=float),
        "lambda_3": np.asarray(profile.stretch_3, dtype=float),
        "T_1": np.asarray(profile.tension_1, dtype=float),
        "T_2": np.asarray(profile.tension_2, dtype=float),
        "contact": np.asarray(profile.contact, dtype=bool).astype(np.uint8),
        "r": r,
        "displacement": np.column_stack((rho - r, np.zeros_like(r), eta)),
    }


def profile_mesh(state) -> meshio.Mesh:
    """The meridian as a polyline of points (rho, 0, eta) with point data."""
    profile = _profile(state)
    rho, eta = np.asarray(profile.rho, dtype=float), np.asarray(profile.eta, dtype=float)
    points = np.column_stack((rho, np.zeros_like(rho), eta))
    lines = np.column_stack((np.arange(len(rho) - 1), np.arange(1, len(rho))))
    return meshio.Mesh(points, [("line", lines)], point_data=_point_data(profile))


def _segments(segments) -> int:
    try:
        value = operator.index(segments)
    except TypeError:
        value = 0
    if isinstance(segments, bool) or value < 3:
        raise InputError(f"segments = {segments!r}, but a surface of revolution needs an integer >= 3")
    return value


def surface_mesh(state, *, segments=64) -> meshio.Mesh:
    """The profile revolved about the z axis: quads, triangles at the pole."""
    segments = _segments(segments)
    profile = _profile(state)
    rho, eta = np.asarray(profile.rho, dtype=float), np.asarray(profile.eta, dtype=float)
    pole = rho[0] == 0.0
    angle = 2.0 * np.pi * np.arange(segments) / segments
    cos, sin = np.cos(angle), np.sin(angle)
    rings = np.arange(1 if pole else 0, len(rho))  # profile index of each ring
    x, y = np.outer(rho[rings], cos).ravel(), np.outer(rho[rings], sin).ravel()
    points = np.column_stack((x, y, np.repeat(eta[rings], segments)))
    source = np.repeat(rings, segments)  # profile index of each point
    hoop = np.tile(np.arange(segments), len(rings))
    if pole:
        points = np.vstack(([[0.0, 0.0, eta[0]]], points))
        source, hoop = np.concatenate(([0], source)), np.concatenate(([0], hoop))
    first = 1 if pole else 0  # index of the first point of ring 0

    def at(ring, j):
        return first + ring * segments + j % segments

    j = np.arange(segments)
    band = np.arange(len(rings) - 1)[:, None]
    quads = np.stack((at(band, j), at(band + 1, j), at(band + 1, j + 1), at(band, j + 1)), axis=-1)
    cells = [("quad", quads.reshape(-1, 4))] if len(rings) > 1 else []
    if pole:
        cells.insert(0, ("triangle", np.column_stack((np.zeros(segments, int), at(0, j), at(0, j + 1)))))
    data = {name: values[source] for name, values in _point_data(profile).items()}
    radial, up = data["displacement"][:, 0], data["displacement"][:, 2]
    data["displacement"] = np.column_stack((radial * cos[hoop], radial * sin[hoop], up))
    return meshio.Mesh(points, cells, point_data=data)


def write_state(directory, state, *, stem="state", segments=64) -> list[pathlib.Path]:
    """Write ``{stem}_profile.vtu`` and ``{stem}_surface.vtu`` into ``directory``."""
    meshes = {"profile": profile_mesh(state), "surface": surface_mesh(state, segments=segments)}
    directory = pathlib.Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    paths = []
    for part, mesh in meshes.items():
        paths.append(directory / f"{stem}_{part}.vtu")
        meshio.write(paths[-1], mesh)
    return paths


def _times(times, count: int) -> np.ndarray:
    if times is None:
        return np.arange(count, dtype=float)
    values = np.asarray(times, dtype=float)
    if values.shape != (count,):
        raise InputError(f"times has shape {values.shape}, but there are {count} states")
    if not np.all(np.isfinite(values)) or np.any(np.diff(values) <= 0.0):
        raise InputError(f"times = {values.tolist()!r}, but ParaView needs finite, strictly increasing times")
    return values


def _pvd(path: pathlib.Path, files: list[str], times: np.ndarray) -> None:
    lines = ['<?xml version="1.0"?>', '<VTKFile type="Collection" version="0.1">', "  <Collection>"]
    for name, time in zip(files, times, strict=True):
        lines.append(f'    <DataSet timestep="{float(time)!r}" group="" part="0" file={quoteattr(name)}/>')
    lines += ["  </Collection>", "</VTKFile>", ""]
    path.write_text("\n".join(lines))


def write_series(directory, states, *, times=None, segments=64, overwrite=False) -> pathlib.Path:
    """Write one profile and one surface per state plus ``profile.pvd`` and ``surface.pvd``.

    ``times`` (default: the step index) label the steps. An existing
    non-empty ``directory`` is refused unless ``overwrite``; then it is
    replaced as a whole. Returns the directory (as an absolute path).
    """
    states = list(states)
    if not states:
        raise InputError("no states to write")
    times = _times(times, len(states))
    segments = _segments(segments)
    for state in states:
        _profile(state)
    target = pathlib.Path(directory).resolve()  # "." and "out/" need a name for the sibling
    if target.exists() and not target.is_dir():
        raise InputError(f"{target} exists and is not a directory")
    if target.is_dir() and any(target.iterdir()) and not overwrite:
        raise InputError(f"{target} exists and is not empty; replace it with overwrite=True (--overwrite)")
    with staged(target) as partial:
        width = max(4, len(str(len(states) - 1)))
        files = {"profile": [], "surface": []}
        for k, state in enumerate(states):
            stem = f"step_{k:0{width}d}"
            paths = write_state(partial, state, stem=stem, segments=segments)
            for part, path in zip(("profile", "surface"), paths, strict=True):
                files[part].append(path.name)
        for part, names in files.items():
            _pvd(partial / f"{part}.pvd", names, times)
    return target
