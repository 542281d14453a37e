"""Read and write 1-D meshes of [0, 1] in any format meshio knows.

A 1-D mesh on file is a set of points on the x axis (y = z = 0, or only an x
column) joined by ``line`` cells; ``vertex`` cells (boundary points that
Gmsh writes) are allowed and ignored. ``read`` returns the sorted node
coordinates and rejects, with one line naming the file and the problem:

- a file meshio cannot read (missing, unknown extension, corrupt);
- a mesh that is not 1-D: a nonzero y or z coordinate, or cells other than
  ``line`` / ``vertex`` (triangles, quadratic ``line3``, ...);
- nodes that are not distinct (two points at the same r);
- line cells that do not join each node to the next one in sorted order
  (a gap, an overlap, or a missing element); the points themselves may come
  in any order;
- a mesh that does not span [0, 1] (ends within 1e-12 are snapped to 0 and 1).

``write`` stores nodes as points (r, 0, 0) and the chain of line cells. The
format follows the extension as in meshio, except that ``.msh`` means Gmsh 2.2
(meshio would pick ANSYS first) and XDMF is written with its data inline
(``data_format="XML"``) so that the file is self-contained. meshio needs
h5py for any XDMF file, even inline.
"""

from __future__ import annotations

import contextlib
import io
import pathlib

import meshio
import numpy as np

from pocket.core.errors import InputError

__all__ = ["check", "read", "write"]

_SNAP = 1e-12  # ends this close to 0 and 1 are round-off, not a wrong span


def check(nodes, where: str = "nodes") -> np.ndarray:
    """Validate a node array; return it as a new float array (ends exact)."""
    x = np.array(nodes, dtype=float)
    if x.ndim != 1 or x.size < 2:
        raise InputError(f"{where}: a 1-D mesh needs at least 2 nodes in a flat array, got shape {x.shape}")
    if not np.all(np.isfinite(x)):
        raise InputError(f"{where}: node coordinates must be finite")
    steps = np.diff(x)
    if np.any(steps <= 0.0):
        k = int(np.argmax(steps <= 0.0))
        raise InputError(
            f"{where}: nodes must be distinct and increasing, "
            f"but node {k + 1} (r = {float(x[k + 1])!r}) follows r = {float(x[k])!r}"
        )
    if abs(x[0]) > _SNAP or abs(x[-1] - 1.0) > _SNAP:
        raise InputError(f"{where}: the mesh spans [{float(x[0])!r}, {float(x[-1])!r}], not [0, 1]")
    x[0], x[-1] = 0.0, 1.0
    return x


def _readers(path: pathlib.Path, file_format) -> list[str]:
    """meshio formats to try for ``path``, as meshio deduces them but Gmsh first."""
    if file_format:
        return [file_format]
    ext, found = "", []
    for suffix in reversed(path.suffixes):
        ext = (suffix + ext).lower()
        found += meshio.extension_to_filetypes.get(ext, [])
    return sorted(found, key=lambda name: name != "gmsh")


def write(path, nodes, *, file_format=None) -> None:
    """Write ``nodes`` (checked as by ``read``) to ``path`` with meshio."""
    path = pathlib.Path(path)
    x = check(nodes, str(path))
    points = np.zeros((x.size, 3))
    points[:, 0] = x
    lines = np.column_stack((np.arange(x.size - 1), np.arange(1, x.size)))
    if file_format is None and path.suffix.lower() == ".msh":
        file_format = "gmsh22"
    kind = file_format or {".xdmf": "xdmf", ".xmf": "xdmf"}.get(path.suffix.lower())
    cell_data, options = {}, {}
    if kind in ("gmsh", "gmsh22"):
        tags = np.ones(len(lines), dtype=int)  # one physical and geometrical entity
        cell_data = {"gmsh:physical": [tags], "gmsh:geometrical": [tags]}
    if kind == "xdmf":
        options["data_format"] = "XML"
    mesh = meshio.Mesh(points, [("line", lines)], cell_data=cell_data)
    try:
        meshio.write(path, mesh, file_format=file_format, **options)
    except (meshio.ReadError, meshio.WriteError) as exc:  # unknown format
        raise InputError(f"{path}: cannot write a mesh ({' '.join(str(exc).split())})") from None


def read(path, *, file_format=None) -> np.ndarray:
    """Node coordinates of the 1-D mesh in ``path``, sorted, from 0.0 to 1.0.

    ``file_format`` (a meshio format name) overrides the extension.
    """
    path = pathlib.Path(path)
    formats = _readers(path, file_format)
    if not path.is_file():
        raise InputError(f"{path}: no such file")
    if not formats:
        raise InputError(f"{path}: cannot tell the mesh format from the extension {path.suffix!r}")
    reasons = []
    for name in formats:
        try:  # meshio prints its ReadError and calls sys.exit: keep both in here
            with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
                mesh = meshio.read(path, file_format=name)
            break
        except SystemExit:
            reasons.append(f"not a valid {name} file")
        except Exception as exc:  # meshio's readers raise many types for a bad file
            reasons.append(f"as {name}: " + (" ".join(str(exc).split()) or type(exc).__name__))
    else:
        raise InputError(f"{path}: cannot read a mesh ({'; '.join(reasons)})")
    points = np.asarray(mesh.points, dtype=float)
    if points.ndim != 2 or points.shape[0] < 2:
        raise InputError(f"{path}: a 1-D mesh needs at least 2 points, found {len(points)}")
    if points.shape[1] > 1 and np.any(points[:, 1:] != 0.0):
        raise InputError(f"{path}: not a 1-D mesh (points have nonzero y or z coordinates)")
    others = sorted({c.type for c in mesh.cells} - {"line", "vertex"})
    if others:
        raise InputError(f"{path}: not a 1-D mesh of line cells (has {', '.join(others)} cells)")
    lines = [c.data for c in mesh.cells if c.type == "line"]
    if not lines:
        raise InputError(f"{path}: no line cells")
    x = points[:, 0]
    order = np.argsort(x, kind="stable")
    nodes = check(x[order], str(path))
    rank = np.empty_like(order)
    rank[order] = np.arange(order.size)
    edges = np.sort(rank[np.concatenate(lines)], axis=1)
    starts = np.sort(edges[:, 0])
    if np.any(edges[:, 1] - edges[:, 0] != 1) or not np.array_equal(starts, np.arange(nodes.size - 1)):
        raise InputError(
            f"{path}: the line cells do not join each node to the next one "
            "(a gap, an overlap or a missing element)"
        )
    return nodes
