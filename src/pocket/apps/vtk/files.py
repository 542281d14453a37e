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

A closed capsule (``pocket.core.geometries.CAPSULE``, the state's ``geometry``) is solved as its upper half,
from the pole to the equatorial plane z = 0; it is written whole: the profile runs on through that plane to
the lower pole, the upper half mirrored (eta -> -eta, ``pocket.apps.vtk.mirror``), and the surface, revolved
from pole to pole, is closed (triangles at both poles), so that ParaView (or pyvista) finds the volume it
encloses. Its ``r`` is the arc length S from the upper pole on the undeformed sphere (the same at a point and
its mirror image), and its displacement is from the undeformed sphere, (sin S, 0, cos S) on the upper half and
(sin S, 0, -cos S) on the lower. Both plates are drawn, at +H and -H (``pocket.apps.vtk.indentermesh``). Its
field data add the capsule's keys (``stretch_pole``, ``radius_equator``, ``force_ETR``) and ``geometry_code``,
the position of its geometry's name in ``pocket.core.geometries.GEOMETRIES`` (``NAMED``).

Point data, on the profile and the surface alike (copied around each ring),
all dimensionless:

=================  ==========================================================
``lambda_1``       meridional stretch (deformed / flat length along a meridian)
``lambda_2``       hoop stretch rho / r
``lambda_3``       thickness stretch 1 / (lambda_1 lambda_2) (incompressible); like lambda_1 and
                   lambda_2, relative to the clamped flat sheet: a sheet clamped with a
                   prestretch lambda_p is T lambda_3 / lambda_p^2 thick (T unstretched)
``T_1``, ``T_2``   meridional and hoop tensions (stress resultants), units of E T
``contact``        1 where the sheet touches the plate, else 0 (uint8)
``r``              Lagrangian radius: the point's radius in the flat sheet, units of R
``displacement``   deformed minus flat position, units of R (below)
=================  ==========================================================

The displacement is the deformed minus the reference position of each material
point, the reference being the flat sheet at height 0: point (r, t) of the
sheet moves from (r cos t, r sin t, 0) to (rho cos t, rho sin t, eta), so the
displacement is ((rho - r) cos t, (rho - r) sin t, eta). In ParaView,
"Warp By Vector" with scale -1 brings the surface back to the flat sheet.

Field data (one value per file, the state's scalars, named as everywhere in
pocket: ``pocket.core.states``): for a compressed state ``alpha``,
``pressure_initial`` (Phat_I), ``force`` (Fhat = F / (P_I pi R^2)), ``pressure``
(Phat = P R / (E T)), ``pressure_ratio`` (P / P_I), ``contact_area``
(A_c / (pi R^2)), ``contact_radius`` (Lagrangian a_c / R), ``stretch_contact``,
``height`` (H / R), ``height_ratio`` (H / H0), ``volume`` (V / R^3), then the contact patch
(``pocket.apps.contactpatch``): ``contact_radius_deformed`` (rho_c / R, the contact edge's distance from the
axis in the deformed sheet: the patch a camera sees), ``contact_pressure_pole`` and
``contact_pressure_edge`` (the contact pressure at the pole and at the contact edge, Phat; P on the
flat plate, larger under a sphere or a profile); for an
inflated state ``alpha``, ``pressure``, ``stretch_pole``, ``height``, ``volume``,
``stretch_clamp`` (``alpha`` only for a Mooney-Rivlin rubber given by it); then
for both the smallest tensions ``tension_1_min`` and ``tension_2_min`` (units E T)
and ``wrinkled`` (1 where one is not positive, else 0), the numeric parameters of
the rubber's law (units of mu_0; Ogden's ``mu`` and ``exponents`` one value per
term) and, for a gas-filled pocket, ``ambient`` (Phat_atm) and ``gamma``. Then what
tells two series apart: the names, as codes (``CODES``: ``solver_code``,
``material_code``, ``fluid_code``, the position of the name in its list, and for a
solver option given by name, such as the finite elements' ``contact``, ``contact_code``,
its position among the option's choices; -1 for a name not in the list), and the solver's numeric diagnostics
(the finite elements' mesh: ``elements``, ``order``; ``newton_iterations``, ...).
meshio writes no field data, so it is added to each file as a ``<FieldData>`` block
of ASCII values written with 17 significant digits (they read back exactly; a
string array would be lost to meshio, which reads numbers only).

One point set along a series. A solver samples each state's profile at its own
Lagrangian radii (the shooting solver's adaptive steps: a different count at
every force), and ParaView's temporal interpolation and point tracking need
the same points at every step. So ``write_series`` resamples every profile on
one fixed set of Lagrangian radii, ``points`` equally spaced radii plus the
contact edge of every state of the series, each profile piecewise on either
side of its own edge (``pocket.apps.vtk.resampling``): every step has a point
exactly at its contact edge, the kink of the meridian there is kept, and a
point index is one material point throughout the series.

Load paths. ``write_series`` writes ``step_0000_profile.vtu``,
``step_0000_surface.vtu``, ... and the collections ``profile.pvd`` and
``surface.pvd`` (file names relative to them), so ParaView plays the path as a
time series. A compression path also gets the indenter's surface at each step,
``step_0000_indenter.vtu``, ... and ``indenter.pvd`` (``pocket.apps.vtk.indentermesh``:
the flat plate a disc wider than the pocket, its lowest point at the state's height).
The "time" of a step defaults to its index; a compression path should pass
the force Fhat (an inflation path the pressure or the volume), strictly increasing.
The directory appears complete or not at all: the files go into a temporary
sibling directory that is renamed into place at the end and removed on any failure.
"""

from __future__ import annotations

import operator
import pathlib
from xml.sax.saxutils import quoteattr

import meshio
import numpy as np

from pocket.core.errors import InputError
from pocket.core.fluids import Fluid
from pocket.core.geometries import DISC, GEOMETRIES, Symmetry
from pocket.core.inputs import check_count
from pocket.core.materials import LAWS
from pocket.core.states import CHECKS, UNINFLATED_UNDEFINED

from ..contactpatch import contact_patch
from ..folders import check_replaceable, staged
from ..solvers import SOLVERS
from .indentermesh import indenter_mesh, reach_of
from .mirror import mirrored
from .resampling import resample, series_radii
from .revolve import revolve

__all__ = [
    "CODES",
    "KIND",
    "NAMED",
    "SERIES_POINTS",
    "field_data",
    "profile_mesh",
    "surface_mesh",
    "write_series",
    "write_state",
]

#: the kind of folder ``write_series`` writes (``pocket.apps.folders.check_replaceable``)
KIND = "VTK series"

#: field -> the names its code counts (the code is a name's position): the solver, the rubber's law, the fluid
CODES = {"solver_code": tuple(SOLVERS), "material_code": tuple(LAWS), "fluid_code": ("liquid", "gas")}

#: a state's ``extra`` key whose value is a name -> the names its code counts (``geometry_code``: a capsule's
#: states say their reference surface, ``pocket.core.geometries.GEOMETRIES``)
NAMED = {"geometry": tuple(GEOMETRIES)}

#: equally spaced Lagrangian radii of a series (the contact edges are added)
SERIES_POINTS = 201


def _profile(state):
    profile = getattr(state, "profile", None)
    if profile is None:
        raise InputError(f"{type(state).__name__} has no profile to write (the solver returned none)")
    n = len(profile.r)
    if n < 2 or any(len(getattr(profile, f)) != n for f in ("rho", "eta", "stretch_1", "stretch_2")):
        raise InputError(f"the profile needs >= 2 points and arrays of equal length, got r of length {n}")
    return profile


def field_data(state) -> dict[str, np.ndarray]:
    """A state's numeric scalars as VTK field data (``pocket.apps.vtk.files``).

    Its ``KEYS`` (an uninflated capsule's but its undefined Fhat and P / P_I), for a compressed state its contact
    patch, its smallest tensions and ``wrinkled`` (1.0 or 0.0),
    the rubber's parameters and the fluid's, the codes of its solver, law and fluid (``CODES``) and its numeric
    diagnostics.

    Parameters
    ----------
    state : InflatedState or CompressedState
        A solved state.

    Returns
    -------
    dict
        Name -> float64 array of one value (an Ogden parameter: one per term); dimensionless, as the state.

    Examples
    --------
    >>> from pocket import shooting
    >>> from pocket.apps.vtk.files import field_data
    >>> state = shooting.compress(47 / 160, 0.31, 0.19)
    >>> data = field_data(state)
    >>> print(data["pressure_ratio"][0] == state.pressure_ratio, data["force"], data["wrinkled"])
    True [0.19] [0.]
    """
    uninflated = getattr(state, "pressure_initial", None) == 0.0  # an uninflated capsule: no Fhat, no P / P_I
    out = {key: np.array([float(getattr(state, key))]) for key in state.KEYS
           if getattr(state, key) is not None and not (uninflated and key in UNINFLATED_UNDEFINED)}
    if hasattr(state, "indenter"):  # a compressed state: its contact patch
        out.update({key: np.array([value]) for key, value in contact_patch(state).items()})
    out.update({key: np.array([float(getattr(state, key))]) for key in CHECKS})  # wrinkled: 1.0 or 0.0
    described = {**state.material.describe(), **(state.fluid.describe() if hasattr(state, "fluid") else {})}
    for key, value in described.items():
        if not isinstance(value, str):
            out[key] = np.array(value, dtype=float).reshape(-1)
    fluid = getattr(state, "fluid", Fluid())
    for field, name in zip(CODES, (state.solver, state.material.law, fluid.kind), strict=True):
        out[field] = _code(name, CODES[field])
    solver = SOLVERS.get(state.solver)
    for key, value in state.extra.items():
        option = None if solver is None else solver.option(key)
        if isinstance(value, str) and option is not None and option.choices:
            out[f"{key}_code"] = _code(value, option.choices)
        elif isinstance(value, str) and key in NAMED:
            out[f"{key}_code"] = _code(value, NAMED[key])
        elif isinstance(value, int | float):  # a bool too: 1.0 or 0.0
            out[key] = np.array([float(value)])
    return out


def _code(name: str, names: tuple) -> np.ndarray:
    """The position of ``name`` in ``names`` (-1 if absent: a state made outside pocket's solvers)."""
    return np.array([float(names.index(name) if name in names else -1)])


def _point_data(profile, geometry=DISC) -> dict[str, np.ndarray]:
    """Per-point fields of the profile (displacement in the plane y = 0, from the reference surface
    ``geometry``'s point (r0(r), 0, z0(r)): the flat sheet's (r, 0, 0) by default)."""
    r, rho, eta = (np.asarray(a, dtype=float) for a in (profile.r, profile.rho, profile.eta))
    return {
        "lambda_1": np.asarray(profile.stretch_1, dtype=float),
        "lambda_2": np.asarray(profile.stretch_2, dtype=float),
        "lambda_3": np.asarray(profile.stretch_3, dtype=float),
        "T_1": np.asarray(profile.tension_1, dtype=float),
        "T_2": np.asarray(profile.tension_2, dtype=float),
        "contact": np.asarray(profile.contact, dtype=bool).astype(np.uint8),
        "r": r,
        "displacement": np.column_stack((rho - geometry.radius(r), np.zeros_like(r), eta - geometry.height(r))),
    }


def _meridian(state, radii) -> tuple[np.ndarray, np.ndarray, dict[str, np.ndarray]]:
    """(rho, eta, point data) of the state's whole meridian: its profile (resampled at ``radii``), continued
    through the mirror plane where its reference surface ends on one (a capsule: ``pocket.apps.vtk.mirror``)."""
    profile = _sampled(state, radii)
    geometry = getattr(state, "geometry", DISC)
    rho, eta = np.asarray(profile.rho, dtype=float), np.asarray(profile.eta, dtype=float)
    data = _point_data(profile, geometry)
    if isinstance(geometry.end, Symmetry):
        return mirrored(rho, eta, data, geometry.end.height)
    return rho, eta, data


def _sampled(state, radii):
    profile = _profile(state)
    return profile if radii is None else resample(profile, radii)


def profile_mesh(state, *, radii=None) -> meshio.Mesh:
    """The deformed meridian as a polyline of points (rho, 0, eta), with point data and the state's field data.

    Parameters
    ----------
    state : InflatedState or CompressedState
        A state with a profile.
    radii : array_like, optional
        Lagrangian radii r / R to resample the profile at (default: the solver's).

    Returns
    -------
    meshio.Mesh
        Points in units of R, ``line`` cells from the pole; point data ``lambda_1``, ``lambda_2``, ``lambda_3``,
        ``T_1``, ``T_2`` (units E T), ``contact``, ``r``, ``displacement``.

    Raises
    ------
    InputError
        For a state without a profile.

    Examples
    --------
    >>> import numpy as np
    >>> from pocket import shooting
    >>> from pocket.apps.vtk.files import profile_mesh
    >>> state = shooting.inflate(47 / 160, 0.31)
    >>> mesh = profile_mesh(state, radii=np.linspace(0.0, 1.0, 11))
    >>> print(mesh.points.shape, mesh.cells[0].type, round(float(mesh.points[0, 2]), 6) == round(state.height, 6))
    (11, 3) line True
    """
    rho, eta, data = _meridian(state, radii)
    points = np.column_stack((rho, np.zeros_like(rho), eta))
    lines = np.column_stack((np.arange(len(rho) - 1), np.arange(1, len(rho))))
    return meshio.Mesh(points, [("line", lines)], point_data=data, field_data=field_data(state))


def _segments(segments) -> int:
    try:
        value = operator.index(segments)
    except TypeError:
        value = 0
    if isinstance(segments, bool) or value < 3:
        raise InputError(f"segments = {segments!r}, but a surface of revolution needs an integer >= 3")
    return value


def surface_mesh(state, *, segments=64, radii=None) -> meshio.Mesh:
    """The deformed sheet as a surface: its profile revolved about the z axis (quads, triangles at the pole).

    Parameters
    ----------
    state : InflatedState or CompressedState
        A state with a profile.
    segments : int, optional
        Points per ring, at least 3.
    radii : array_like, optional
        Lagrangian radii r / R to resample the profile at (default: the solver's).

    Returns
    -------
    meshio.Mesh
        Points in units of R, the point data of ``profile_mesh`` copied around each ring, the state's field data.

    Raises
    ------
    InputError
        For a state without a profile, or fewer than 3 segments.

    Examples
    --------
    A profile that starts on the axis keeps one point at the pole and ``segments`` on every other ring:

    >>> import numpy as np
    >>> from pocket import shooting
    >>> from pocket.apps.vtk.files import surface_mesh
    >>> mesh = surface_mesh(shooting.inflate(47 / 160, 0.31), segments=16, radii=np.linspace(0.0, 1.0, 11))
    >>> print(len(mesh.points) == 1 + 10 * 16, [block.type for block in mesh.cells])
    True ['triangle', 'quad']
    """
    segments = _segments(segments)
    rho, eta, meridian = _meridian(state, radii)
    surface = revolve(rho, eta, segments)
    source, hoop, cos, sin = surface.source, surface.hoop, surface.cos, surface.sin
    data = {name: values[source] for name, values in meridian.items()}
    radial, up = data["displacement"][:, 0], data["displacement"][:, 2]
    data["displacement"] = np.column_stack((radial * cos[hoop], radial * sin[hoop], up))
    return meshio.Mesh(surface.points, surface.cells, point_data=data, field_data=field_data(state))


def _write_vtu(path: pathlib.Path, mesh: meshio.Mesh) -> None:
    """meshio's .vtu with the mesh's field data added (meshio reads field data but does not write it)."""
    meshio.write(path, meshio.Mesh(mesh.points, mesh.cells, point_data=mesh.point_data), file_format="vtu")
    arrays = "".join(f'<DataArray type="Float64" Name={quoteattr(name)} NumberOfTuples="{len(values)}" '
                     f'format="ascii">{" ".join(repr(float(v)) for v in values)}</DataArray>\n'
                     for name, values in mesh.field_data.items())
    text = path.read_text()
    if arrays:
        text = text.replace("<UnstructuredGrid>", f"<UnstructuredGrid>\n<FieldData>\n{arrays}</FieldData>", 1)
    path.write_text(text)


def _fields(fields) -> dict[str, np.ndarray]:
    """Field data of one value each from ``fields`` ({name: number}, or None)."""
    return {name: np.array([float(value)]) for name, value in (fields or {}).items()}


def write_state(directory, state, *, stem="state", segments=64, radii=None, fields=None) -> list[pathlib.Path]:
    """Write a state's profile and surface for ParaView: ``{stem}_profile.vtu`` and ``{stem}_surface.vtu``.

    Parameters
    ----------
    directory : str or path
        The folder (made if missing).
    state : InflatedState or CompressedState
        A state with a profile.
    stem : str, optional
        The files' name before ``_profile``, ``_surface``.
    segments : int, optional
        Points per ring of the surface.
    radii : array_like, optional
        Lagrangian radii to resample the profile at.
    fields : dict, optional
        ``{name: value}`` added to the field data of both (a case's scales).

    Returns
    -------
    list of pathlib.Path
        The two files.

    Raises
    ------
    InputError
        For a state without a profile, or fewer than 3 segments.

    Examples
    --------
    >>> import tempfile
    >>> import meshio
    >>> from pocket import shooting
    >>> from pocket.apps.vtk.files import write_state
    >>> state = shooting.compress(47 / 160, 0.31, 0.19)
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     paths = write_state(folder, state, stem="pressed", fields={"radius_m": 0.02})
    ...     back = meshio.read(paths[1])
    >>> print([path.name for path in paths], bool(back.point_data["contact"].any()))
    ['pressed_profile.vtu', 'pressed_surface.vtu'] True
    """
    meshes = {"profile": profile_mesh(state, radii=radii), "surface": surface_mesh(state, segments=segments,
                                                                                   radii=radii)}
    for mesh in meshes.values():
        mesh.field_data.update(_fields(fields))
    directory = pathlib.Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    paths = []
    for part, mesh in meshes.items():
        paths.append(directory / f"{stem}_{part}.vtu")
        _write_vtu(paths[-1], mesh)
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


def write_series(directory, states, *, times=None, segments=64, points=SERIES_POINTS,
                 overwrite=False, fields=None, of=None) -> pathlib.Path:
    """Write a load path for ParaView: a profile and a surface per state, and ``profile.pvd``, ``surface.pvd``.

    For compressed states (with an ``indenter``) also the indenter's surface per state and ``indenter.pvd``.
    Every step has the same points: the profiles are resampled on ``series_radii(states, points)``.

    Parameters
    ----------
    directory : str or path
        The folder. An existing non-empty folder is replaced as a whole only if it is a series pocket wrote for
        ``of`` and ``overwrite`` (``pocket.apps.folders.check_replaceable``); anything else is refused.
    states : sequence of states
        The steps, each with a profile.
    times : array_like, optional
        The steps' labels, finite and strictly increasing (default: the step index).
    segments : int, optional
        Points per ring of the surfaces.
    points : int, optional
        Points of each resampled profile.
    overwrite : bool, optional
        Replace a series pocket wrote before.
    fields : dict, optional
        ``{name: value}`` added to the field data of every file (the scales of a case).
    of : str, optional
        What the series is of (a case), recorded with it.

    Returns
    -------
    pathlib.Path
        The folder, absolute.

    Raises
    ------
    InputError
        For no states, bad times, or a folder pocket may not replace.
    OutputError
        If the files cannot be written (nothing half-written is left).

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from pocket import shooting
    >>> from pocket.apps.vtk.files import write_series
    >>> forces = [0.0, 0.1, 0.19]
    >>> states = shooting.compression_curve(47 / 160, 0.31, forces)
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     out = write_series(pathlib.Path(folder) / "press", states, times=forces, segments=8, points=21)
    ...     names = sorted(path.name for path in out.glob("*.pvd"))
    ...     steps = len(list(out.glob("step_*_surface.vtu")))
    >>> print(names, steps)
    ['indenter.pvd', 'profile.pvd', 'surface.pvd'] 3
    """
    states = list(states)
    if not states:
        raise InputError("no states to write")
    times = _times(times, len(states))
    segments = _segments(segments)
    points = check_count("points", points, 2, 100_000)
    radii = series_radii([_profile(s) for s in states], points)
    target = check_replaceable(directory, KIND, "VTK folder", overwrite=overwrite, of=of)
    with staged(target, KIND, of) as partial:
        width = max(4, len(str(len(states) - 1)))
        pressed = all(hasattr(s, "indenter") for s in states)
        files: dict[str, list] = {"profile": [], "surface": [], **({"indenter": []} if pressed else {})}
        reach = reach_of([_profile(s) for s in states])
        for k, state in enumerate(states):
            stem = f"step_{k:0{width}d}"
            paths = write_state(partial, state, stem=stem, segments=segments, radii=radii, fields=fields)
            if pressed:
                paths.append(partial / f"{stem}_indenter.vtu")
                end = state.geometry.end
                mesh = indenter_mesh(state.indenter, state.height, reach, segments=segments,
                                     mirror=end.height if isinstance(end, Symmetry) else None)
                mesh.field_data.update(_fields(fields))
                _write_vtu(paths[-1], mesh)
            for part, path in zip(files, paths, strict=True):
                files[part].append(path.name)
        for part, names in files.items():
            _pvd(partial / f"{part}.pvd", names, times)
    return target
