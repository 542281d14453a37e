"""Sweeps of a capsule by forces F / (E T R) (``force_unit="ETR"``, ``pocket sweep --force-etr``), the only forces
of an uninflated capsule (Phat_I = 0), on worker processes.

Each row is checked against the finite elements' own answer from a fresh solve (``fem.compress``), with the force
the row says it was asked: at Phat_I = 0 F / (E T R) itself, at Phat_I > 0 the Fhat F / (E T R) / (pi Phat_I).
The sweep runs on processes, as the command line's do, so the capsule reaches the solver pickled.
"""

from __future__ import annotations

import csv
import math
import pickle
import re

import pytest

from pocket import fem
from pocket.apps.sweep.grid import run_sweep
from pocket.apps.sweep.workers import local_executor
from pocket.cli import main
from pocket.core.errors import UNINFLATED_CAPSULE
from pocket.core.geometries import CAPSULE, DISC
from pocket.core.materials import check

NEO = check("neo-hookean", {"mu": 1.0})
ELEMENTS = 64  # both sides solve on one mesh: they agree to the solver's tolerance, whatever its error


def _rows(path) -> list[dict]:
    with open(path, newline="") as file:
        return list(csv.DictReader(file))


def test_a_surface_sent_to_another_process_is_the_solvers_own():
    """The solvers tell surfaces apart by identity: a pickled capsule reads back as ``CAPSULE`` itself (before, it
    was another object, and the finite elements took it for a clamped sheet: "the capsule geometry's meridian is
    not clamped at its end", and a sweep's points on worker processes all failed), and a capsule solved from it is
    the capsule's state."""
    for surface in (CAPSULE, DISC):
        assert pickle.loads(pickle.dumps(surface)) is surface
    sent = pickle.loads(pickle.dumps(CAPSULE))
    (state,) = fem.compression_curve(0.0, 0.1, [0.5], geometry=sent, elements=ELEMENTS)
    assert state.scalars() == fem.compression_curve(0.0, 0.1, [0.5], geometry=CAPSULE, elements=ELEMENTS)[0].scalars()


def test_a_sweep_presses_an_uninflated_capsule_by_forces_in_etr(tmp_path):
    """At Phat_I = 0 each point's force is its F / (E T R) as asked (its Fhat and P / P_I cells empty); 0.01 is
    short of where the states start (0.064 for a neo-Hookean rubber and a liquid): out of range, saying so. At
    Phat_I = 0.1 the same forces are the Fhats F / (E T R) / (pi Phat_I). Every ok row is the solver's state at
    its force; a rerun reuses every point."""
    path = tmp_path / "grid.csv"
    pressures, forces = [0.0, 0.1], [0.01, 0.1, 0.5]
    options = {"elements": ELEMENTS}
    with local_executor(2) as executor:
        assert run_sweep(path, None, pressures, forces, executor, solver="fem", options=options, material=NEO,
                         geometry="capsule", force_unit="ETR") == (6, 0)
    rows = _rows(path)
    assert [(float(r["pressure_initial"]), float(r["force_ETR"])) for r in rows] == [(p, f) for p in pressures
                                                                                     for f in forces]
    low = rows[0]
    assert low["status"] == "out_of_range"
    assert re.match(r"force_ETR = 0\.01 is outside the capsule's range, whose states start deeper", low["message"])
    for row in rows[1:3]:
        assert (row["status"], row["force"], row["pressure_ratio"]) == ("ok", "", "")
        state = fem.compress(NEO, 0.0, float(row["force_ETR"]), geometry="capsule", force_unit="ETR", **options)
        assert float(row["height"]) == state.height
    for row, f in zip(rows[3:], forces, strict=True):
        assert row["status"] == "ok"
        assert float(row["force"]) == f / (math.pi * 0.1)
        state = fem.compress(NEO, 0.1, float(row["force"]), geometry="capsule", **options)
        assert float(row["height"]) == pytest.approx(state.height, rel=1e-9)  # a curve's continuation: its tolerance
    with local_executor(1) as executor:
        assert run_sweep(path, None, pressures, forces, executor, solver="fem", options=options, material=NEO,
                         geometry="capsule", force_unit="ETR") == (0, 6)


@pytest.mark.parametrize(("flags", "message"), [
    (["--geometry", "capsule", "--pressure", "0", "--force", "0.1"], f"pressure = 0: {UNINFLATED_CAPSULE}"),
    (["--pressure", "0.1", "--force-etr", "0.1"], "forces F / (E T R) (--force-etr) are a capsule's (--geometry "
                                                  "capsule); a pocket's are Fhat"),
    (["--geometry", "capsule", "--pressure", "-0.1", "--force-etr", "0.1"], "pressure = -0.1, but it must be >= 0"),
])
def test_a_sweep_refuses_forces_in_the_wrong_unit_before_touching_its_file(tmp_path, capsys, flags, message):
    """One line, exit 2, and no file: an uninflated capsule has no Fhat; a pocket's forces are Fhat."""
    path = tmp_path / "grid.csv"
    assert main(["sweep", "--law", "neo-hookean", "--mu", "1", "--out", str(path), "--workers", "1", *flags]) == 2
    err = capsys.readouterr().err
    assert err == f"pocket: error: {message}\n"
    assert not path.exists()
