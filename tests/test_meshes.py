"""Meshes of [0, 1]: properties of the generators, file round trips, bad files."""

from __future__ import annotations

import math

import meshio
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pocket.meshes.named import RECIPES

from pocket import meshes
from pocket.core.errors import InputError

counts = st.integers(min_value=1, max_value=400)
ratios = st.floats(min_value=1.0, max_value=1e3)


def assert_valid(x):
    """The contract of every mesh: float, strictly increasing, ends exactly 0 and 1."""
    assert x.dtype == float
    assert x.ndim == 1
    assert x[0] == 0.0
    assert x[-1] == 1.0
    assert np.all(np.diff(x) > 0.0), x


@given(counts)
def test_uniform(n):
    """n equal elements of size 1/n."""
    x = meshes.uniform(n)
    assert_valid(x)
    assert len(x) == n + 1
    np.testing.assert_allclose(np.diff(x), 1.0 / n, rtol=1e-12)


@given(st.integers(min_value=2, max_value=400), ratios, st.sampled_from([0.0, 1.0]))
def test_graded_towards_an_end(n, ratio, towards):
    """n elements, finest at ``towards``, largest/smallest exactly ``ratio``, monotone sizes."""
    x = meshes.graded(n, towards=towards, ratio=ratio)
    assert_valid(x)
    assert len(x) == n + 1
    h = np.diff(x)
    assert h.max() / h.min() == pytest.approx(ratio, rel=1e-9)  # rel: round-off of cumsum
    finest = 0 if towards == 0.0 else -1
    assert h[finest] == pytest.approx(h.min(), rel=1e-12)
    assert np.all(np.diff(h) * (1 if towards == 0.0 else -1) >= -1e-15)


@given(st.integers(min_value=4, max_value=400), ratios, st.floats(min_value=0.01, max_value=0.99))
def test_graded_towards_interior(n, ratio, towards):
    """``towards`` is a node; each side graded with ``ratio``, finest next to it."""
    x = meshes.graded(n, towards=towards, ratio=ratio)
    assert_valid(x)
    assert len(x) == n + 1
    k = int(np.flatnonzero(x == towards)[0])
    h = np.diff(x)
    for side in (h[:k][::-1], h[k:]):  # each ordered away from ``towards``
        if len(side) > 1:
            assert side.max() / side.min() == pytest.approx(ratio, rel=1e-9)
        assert side[0] == pytest.approx(side.min(), rel=1e-12)


@given(
    st.integers(min_value=1, max_value=200),
    st.floats(min_value=0.001, max_value=0.999),
    st.floats(min_value=0.001, max_value=0.5),
    st.floats(min_value=1.0, max_value=20.0),
)
@settings(deadline=None)
def test_refined(n, at, width, factor):
    """``at`` is a node; elements within ``width`` of it at most 1/(n factor), others at most 1/n."""
    x = meshes.refined(n, at=at, width=width, factor=factor)
    assert_valid(x)
    assert at in x
    h = np.diff(x)
    mid = 0.5 * (x[1:] + x[:-1])
    inside = np.abs(mid - at) < width
    slack = 1 + 1e-9  # ceil() keeps sizes below the target up to round-off
    assert np.all(h[inside] <= slack / (n * factor))
    assert np.all(h <= slack / n)
    # about n (1 + 2 width (factor - 1)) elements: the band plus rounding up of <= 4 pieces
    assert len(h) <= n * (1 + 2 * width * (factor - 1)) + 4


@given(st.integers(min_value=1, max_value=400), st.floats(min_value=1.0, max_value=4.0))
def test_polar(n, power):
    """Nodes (k/n)^p (1 + (p - 1)(1 - k/n)): element sizes grow from the axis up to s = p/(p + 1),
    where dr/ds = s^(p-1) (p^2 - (p^2 - 1) s) peaks; the last is 1/n to first order (dr/ds = 1 at
    s = 1), and the largest is max_s dr/ds / n within 2 p^2 / n^2."""
    x = meshes.polar(n, power=power)
    assert_valid(x)
    assert len(x) == n + 1
    h = np.diff(x)
    rising = h[: max(int(n * power / (power + 1)) - 1, 0)]
    assert np.all(np.diff(rising) >= -1e-15)
    s = np.linspace(0.0, 1.0, 100001)
    slope = s ** (power - 1) * (power**2 - (power**2 - 1) * s)  # dr/ds
    assert h.max() == pytest.approx(slope.max() / n, abs=2.0 * power**2 / n**2)
    assert h[-1] == pytest.approx(1.0 / n, abs=2.0 * power**2 / n**2)


@pytest.mark.parametrize(
    ("call", "quoted"),
    [
        (lambda: meshes.uniform(0), "n = 0"),
        (lambda: meshes.uniform(2.0), "n = 2.0"),
        (lambda: meshes.uniform(True), "n = True"),
        (lambda: meshes.graded(8, ratio=0.5), "ratio = 0.5"),
        (lambda: meshes.graded(8, ratio=math.inf), "ratio = inf"),
        (lambda: meshes.graded(8, towards=1.5), "towards = 1.5"),
        (lambda: meshes.graded(1, towards=0.5), "n = 1"),
        (lambda: meshes.refined(8, at=0.0), "at = 0.0"),
        (lambda: meshes.refined(8, at=1.0), "at = 1.0"),
        (lambda: meshes.refined(8, at=0.5, width=0.0), "width = 0.0"),
        (lambda: meshes.refined(8, at=0.5, factor=0.5), "factor = 0.5"),
        (lambda: meshes.refined(8, at="x"), "at = 'x'"),
        (lambda: meshes.polar(8, power=0.5), "power = 0.5"),
        (lambda: meshes.polar(0), "n = 0"),
    ],
)
def test_bad_arguments(call, quoted):
    """Each bad argument: InputError, one line, quoting the value."""
    with pytest.raises(InputError) as info:
        call()
    assert quoted in str(info.value)
    assert "\n" not in str(info.value)


FORMATS = [".vtu", ".msh", ".xdmf", ".vtk"]


@pytest.mark.parametrize("suffix", FORMATS)
def test_round_trip(tmp_path, suffix):
    """write then read gives the same nodes bit for bit; the input is not changed."""
    if suffix == ".xdmf":
        pytest.importorskip("h5py", reason="meshio needs h5py for any XDMF file")
    x = meshes.refined(37, at=0.3, width=0.1, factor=3.0)
    before = x.copy()
    meshes.write(tmp_path / f"m{suffix}", x)
    np.testing.assert_array_equal(x, before)
    np.testing.assert_array_equal(meshes.read(tmp_path / f"m{suffix}"), x)


def test_msh_is_gmsh22(tmp_path):
    """``.msh`` means Gmsh 2.2 (meshio alone would choose ANSYS)."""
    meshes.write(tmp_path / "m.msh", meshes.uniform(3))
    assert (tmp_path / "m.msh").read_bytes().startswith(b"$MeshFormat\n2.2")


def test_read_unsorted_points(tmp_path):
    """Points in any order, joined in sorted order, read as the sorted mesh."""
    x = meshes.uniform(5)
    perm = np.array([3, 0, 5, 1, 4, 2])
    points = np.zeros((6, 3))
    points[:, 0] = x[perm]
    where = np.argsort(perm)  # where[k]: position in ``points`` of node k
    lines = np.column_stack((where[:-1], where[1:]))
    meshio.write(tmp_path / "m.vtu", meshio.Mesh(points, [("vertex", where[[0, -1], None]), ("line", lines)]))
    np.testing.assert_array_equal(meshes.read(tmp_path / "m.vtu"), x)


def _line_mesh(x, y=None, lines=None, extra=()):
    points = np.zeros((len(x), 3))
    points[:, 0] = x
    if y is not None:
        points[:, 1] = y
    if lines is None:
        lines = np.column_stack((np.arange(len(x) - 1), np.arange(1, len(x))))
    return meshio.Mesh(points, [("line", np.asarray(lines)), *list(extra)])


BAD = {
    "off the line": (_line_mesh([0.0, 0.5, 1.0], y=[0.0, 0.1, 0.0]), "nonzero y or z"),
    "triangles": (
        _line_mesh([0.0, 0.5, 1.0], extra=[("triangle", np.array([[0, 1, 2]]))]),
        "triangle",
    ),
    "short span": (_line_mesh([0.0, 0.5, 0.9]), "spans [0.0, 0.9]"),
    "offset span": (_line_mesh([0.1, 0.5, 1.0]), "not [0, 1]"),
    "duplicate node": (_line_mesh([0.0, 0.5, 0.5, 1.0]), "distinct"),
    "gap": (_line_mesh([0.0, 0.5, 0.7, 1.0], lines=[[0, 1], [2, 3]]), "do not join"),
    "overlap": (_line_mesh([0.0, 0.5, 1.0], lines=[[0, 2], [0, 1]]), "do not join"),
    "no lines": (meshio.Mesh(np.array([[0.0, 0, 0], [1.0, 0, 0]]), [("vertex", np.array([[0], [1]]))]), "no line"),
}


@pytest.mark.parametrize("kind", BAD)
def test_read_rejects(tmp_path, kind):
    """Each kind of bad mesh: InputError naming the file and the problem, one line."""
    mesh, problem = BAD[kind]
    path = tmp_path / "bad.vtu"
    meshio.write(path, mesh)
    with pytest.raises(InputError) as info:
        meshes.read(path)
    message = str(info.value)
    assert str(path) in message, message
    assert problem in message, message
    assert "\n" not in message, message


@pytest.mark.parametrize(
    ("name", "content"),
    [("missing.vtu", None), ("garbage.vtu", "not xml at all\n<"), ("m.unknownext", "0 1\n")],
)
def test_read_unreadable(tmp_path, name, content):
    """Missing, corrupt, or unknown-format files: InputError naming the file."""
    path = tmp_path / name
    if content is not None:
        path.write_text(content)
    with pytest.raises(InputError) as info:
        meshes.read(path)
    assert str(path) in str(info.value)
    assert "\n" not in str(info.value)


def test_write_rejects(tmp_path):
    """``write`` checks the nodes as ``read`` does, and the format."""
    with pytest.raises(InputError, match="not \\[0, 1\\]"):
        meshes.write(tmp_path / "m.vtu", [0.0, 0.5])
    with pytest.raises(InputError, match="distinct and increasing"):
        meshes.write(tmp_path / "m.vtu", [0.0, 0.6, 0.5, 1.0])
    with pytest.raises(InputError, match="cannot write"):
        meshes.write(tmp_path / "m.unknownext", [0.0, 1.0])


@pytest.mark.parametrize("name", meshes.NAMES)
def test_named(name):
    """Every named mesh loads, is valid, and equals its recipe (rerun make_named.py if not)."""
    x = meshes.named(name)
    assert_valid(x)
    np.testing.assert_array_equal(x, RECIPES[name]())


def test_named_unknown():
    """An unknown name lists the known ones."""
    with pytest.raises(InputError) as info:
        meshes.named("nope")
    assert all(name in str(info.value) for name in meshes.NAMES)
