"""``pocket sweep --geometry capsule``: the geometry reaches the solver, is part of each point, and the capsule's
keys fill their columns.

As in ``test_cli_capsule``, the plumbing is checked with a stand-in for the analytical solver's entry points
(``capsulestates``: hand-built states) on a thread pool (the stand-in lives in this process); where the shooting
solver poses the capsule, a sweep's rows are checked against its Python API.
"""

from __future__ import annotations

import csv
from concurrent.futures import ThreadPoolExecutor

import capsulestates
import pytest
from capsulestates import stood_in

from pocket import shooting
from pocket.apps.columns import column
from pocket.apps.sweep.grid import run_sweep
from pocket.apps.sweep.journal import CAPSULE, COLUMNS
from pocket.cli import main
from pocket.core.errors import InputError
from pocket.core.geometries import CAPSULE as CAPSULE_GEOMETRY
from pocket.core.materials import mooney_rivlin


@pytest.fixture
def stand_in(monkeypatch):
    """The analytical solver's entry points replaced by hand-built capsule states (``capsulestates.stand_in``)."""
    return capsulestates.stand_in(monkeypatch)


def _rows(path) -> list[dict]:
    with open(path, newline="") as file:
        return list(csv.DictReader(file))


def test_the_sweep_files_columns_hold_the_geometry_and_the_capsules_keys():
    """Exact answers: the sweep file has a ``geometry`` column and the capsule's keys, every column documented
    (``pocket.apps.columns``)."""
    assert {"geometry", *CAPSULE} <= set(COLUMNS)
    assert CAPSULE == ("stretch_pole", "radius_equator", "force_ETR")
    assert all(column(name) for name in COLUMNS)


def test_a_capsule_sweep_passes_the_geometry_and_writes_the_capsules_keys(tmp_path, stand_in):
    """Exact answers: the compression curve is given the capsule; each row's ``geometry`` is capsule and its
    keys are the states the stand-in returned, written exactly (repr); a rerun reuses both points; the same grid
    on the flat pocket is other points of the same file (the geometry is part of a point)."""
    path = tmp_path / "grid.csv"
    with ThreadPoolExecutor(1) as executor:
        assert run_sweep(path, [0.1], [0.3], [0.2, 0.4], executor, solver="analytical",
                         geometry="capsule") == (2, 0)
        assert [options["geometry"] for name, options in stand_in] == [CAPSULE_GEOMETRY]
        rows = _rows(path)
        for row, state in zip(rows, stood_in([0.2, 0.4]), strict=True):
            assert (row["geometry"], row["status"], row["solver_options"]) == ("capsule", "ok", "")
            for key in CAPSULE:
                assert row[key] == repr(float(state.extra[key])), key
            for key in ("height", "volume", "contact_area", "contact_radius", "pressure_ratio"):
                assert row[key] == repr(float(getattr(state, key))), key
        assert run_sweep(path, [0.1], [0.3], [0.2, 0.4], executor, solver="analytical",
                         geometry="capsule") == (0, 2)
        assert run_sweep(path, [0.1], [0.3], [0.2, 0.4], executor, solver="analytical") == (2, 0)
    assert sorted(row["geometry"] for row in _rows(path)) == ["capsule", "capsule", "pocket", "pocket"]


def test_a_sweep_file_of_pockets_only_is_of_an_earlier_pocket(tmp_path):
    """Exact answer: a file whose header lacks the geometry and the capsule's keys (as pocket wrote them before
    the capsule) is refused in one line saying what its rows do not record, untouched."""
    path = tmp_path / "old.csv"
    before = [c for c in COLUMNS if c not in ("geometry", *CAPSULE)]
    path.write_text(",".join(before) + "\n")
    with ThreadPoolExecutor(1) as executor, pytest.raises(InputError, match="the membrane's geometry"):
        run_sweep(path, [0.1], [0.3], [0.2], executor)
    assert path.read_text() == ",".join(before) + "\n"


def test_a_solver_that_does_not_pose_the_capsule_stops_the_sweep_leaving_no_file(tmp_path):
    """Exact answers: the analytical solver refuses the capsule with its one line; the sweep stops with it and
    removes the file it created (no point finished)."""
    path = tmp_path / "grid.csv"
    with ThreadPoolExecutor(1) as executor, pytest.raises(InputError, match="solver analytical does not implement "
                                                                            "the capsule geometry"):
        run_sweep(path, [0.1], [0.3], [0.2], executor, solver="analytical", geometry="capsule")
    assert not path.exists()


def test_the_sweeps_help_offers_the_geometry(capsys):
    """Exact answers: ``pocket sweep --help`` offers ``--geometry {pocket,capsule}`` and says a capsule's Fhat has
    the force on each plate."""
    assert main(["sweep", "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    assert "--geometry {pocket,capsule}" in text
    assert "Fhat = F / (P_I pi R^2) with F the force on each plate" in text


def test_a_capsule_sweep_by_the_shooting_solver_is_its_curve(tmp_path):
    """Exact answer: a capsule sweep's rows (shooting) are the Python API's compression curve of the capsule, to
    the last bit (both continue through the same forces from one inflation)."""
    try:
        shooting.inflate(0.1, 0.3, geometry="capsule")
    except InputError:
        pytest.skip("the shooting solver does not pose the capsule yet")
    path = tmp_path / "grid.csv"
    forces = [0.2, 0.5]
    with ThreadPoolExecutor(1) as executor:
        run_sweep(path, [0.1], [0.3], forces, executor, geometry="capsule")
    states = shooting.compression_curve(mooney_rivlin(0.1), 0.3, forces, geometry="capsule")
    for row, state in zip(_rows(path), states, strict=True):
        assert row["status"] == "ok", row["message"]
        for key in ("pressure_ratio", "height", "volume", "contact_area"):
            assert float(row[key]) == getattr(state, key), key
        for key in CAPSULE:
            assert float(row[key]) == state.extra[key], key
