"""The ``pocket`` command line, called through ``main(argv)``."""

import json
import subprocess
import sys

import pytest

from pocket import shooting
from pocket.cli import main
from pocket.core.states import CompressedState, InflatedState


def run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def test_inflate_json_has_the_design_keys(capsys):
    """Exact answer: the JSON equals the library's state (same solver, same call)."""
    status, out, err = run(capsys, "inflate", "--alpha", "47/160", "--pressure", "0.31", "--json")
    assert status == 0 and err == ""
    data = json.loads(out)
    assert set(InflatedState.KEYS) <= set(data)
    ref = shooting.inflate(47 / 160, 0.31).scalars()
    assert all(data[k] == ref[k] for k in InflatedState.KEYS)


def test_compress_curve_is_a_json_list(capsys):
    status, out, _ = run(capsys, "compress", "--alpha", "0.3", "--pressure", "0.31",
                         "--force", "0.05", "0.1", "0.2", "--json")
    rows = json.loads(out)
    assert status == 0 and [r["force"] for r in rows] == [0.05, 0.1, 0.2]
    assert all(set(CompressedState.KEYS) <= set(r) for r in rows)


@pytest.mark.parametrize("solver", ["shooting", "analytical"])
def test_table(capsys, solver):
    status, out, _ = run(capsys, "compress", "--alpha", "47/160", "--pressure", "0.31",
                         "--force", "0", "0.19", "--solver", solver)
    lines = out.splitlines()
    assert status == 0 and lines[0] == f"# solver: {solver}"
    assert lines[1].split()[:3] == ["alpha", "pressure_initial", "force"] and len(lines) == 4


@pytest.mark.parametrize(
    "argv, message",
    [
        (["inflate", "--alpha", "-1", "--pressure", "0.3"], "alpha = -1.0"),
        (["inflate", "--alpha", "0.3", "--pressure", "0"], "pressure = 0.0"),
        (["inflate", "--alpha", "0", "--pressure", "1"], "no inflated state on the first branch"),
        (["compress", "--alpha", "0.3", "--pressure", "0.3", "--force", "-0.1"], "force = -0.1"),
        (["compress", "--alpha", "0.3", "--pressure", "0.3", "--force", "50"], "beyond the model's range"),
        (["compress", "--alpha", "x", "--pressure", "0.3", "--force", "1"], "'x' is not a number"),
        (["inflate", "--alpha", "0.3", "--pressure", "0.3", "--order", "2"],
         "--order does not apply to solver shooting (its options: --rtol)"),
        (["inflate", "--alpha", "0.3", "--pressure", "0.3", "--solver", "analytical", "--rtol", "1e-8"],
         "--rtol does not apply to solver analytical"),
        (["compress", "--alpha", "0.3", "--pressure", "0.3", "--force", "1", "--solver", "fem", "--rtol", "1e-8"],
         "--rtol does not apply to solver fem"),
        (["inflate", "--alpha", "0.3", "--pressure", "0.3", "--solver", "fem", "--penalty", "1e4"],
         "unrecognized arguments: --penalty"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(capsys, argv, message):
    try:
        status = main(argv)
    except SystemExit as exc:  # argparse's own errors
        status = exc.code
    out, err = capsys.readouterr()
    assert status == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and message in err, err


def test_console_script_whole_process():
    """The installed entry point: exit status and stderr of a real process, no traceback."""
    proc = subprocess.run([sys.executable, "-m", "pocket.cli", "compress", "--alpha", "0.3",
                           "--pressure", "0.3", "--force", "50"], capture_output=True, text=True)
    assert proc.returncode == 2 and "Traceback" not in proc.stderr


def test_vtk_series(capsys, tmp_path):
    """Exact answer: one surface per force, the .pvd times are the forces, the data read back."""
    import xml.etree.ElementTree as ET

    import meshio

    out = tmp_path / "series"
    status, _, _ = run(capsys, "compress", "--alpha", "0.3", "--pressure", "0.31",
                       "--force", "0", "0.1", "0.2", "--vtk", str(out))
    assert status == 0
    sets = ET.parse(out / "surface.pvd").getroot().iter("DataSet")
    assert [float(d.get("timestep")) for d in sets] == [0.0, 0.1, 0.2]
    mesh = meshio.read(out / "step_0002_surface.vtu")
    assert {"lambda_1", "lambda_2", "lambda_3", "T_1", "T_2", "contact"} <= set(mesh.point_data)
    status, _, err = run(capsys, "compress", "--alpha", "0.3", "--pressure", "0.31",
                         "--force", "0.1", "--vtk", str(out))
    assert status == 2 and "--overwrite" in err


def test_fem_solver_same_keys_as_shooting_plus_its_own(capsys, tmp_path):
    """The FE answer through the CLI: the shooting keys, agreeing with shooting's to 1e-5
    (issue 3's bar at its default mesh; a coarser 200-element P2 mesh passes it too), plus
    the mesh, Newton and contact diagnostics, and a VTK series of the FE states."""
    argv = ["compress", "--alpha", "47/160", "--pressure", "0.31", "--force", "0.05", "0.19", "--json"]
    status, out, _ = run(capsys, *argv, "--solver", "fem", "--elements", "200", "--vtk", str(tmp_path / "fe"))
    fe = json.loads(out)
    _, out, _ = run(capsys, *argv)
    ref = json.loads(out)
    assert status == 0 and [r["solver"] for r in fe] == ["fem", "fem"]
    for a, b in zip(fe, ref, strict=True):
        assert {"elements", "order", "newton_iterations", "penetration", "force_difference"} <= set(a)
        assert a["elements"] == 200 and a["order"] == 2
        for key in CompressedState.KEYS:
            assert a[key] == pytest.approx(b[key], rel=1e-5, abs=1e-12), key
    assert sorted(p.name for p in (tmp_path / "fe").glob("*.pvd")) == ["profile.pvd", "surface.pvd"]


def test_closed_pipe_ends_quietly():
    """`pocket ... | head`: the reader is gone before the output is written (its end of the
    pipe is closed here first, so the write must fail); no traceback, status 1."""
    proc = subprocess.Popen([sys.executable, "-m", "pocket.cli", "inflate", "--alpha", "0.3",
                             "--pressure", "0.3"], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    proc.stdout.close()
    err = proc.stderr.read().decode()
    assert proc.wait() == 1 and err == ""


@pytest.mark.parametrize("stage, where", [("inflation", "small-strain dome"),
                                          ("compression", "first contact: Newton failed at every contact radius")])
def test_fem_newton_failure_is_one_line_exit_1_and_no_files(capsys, tmp_path, monkeypatch, stage, where):
    """Exact answer: a Newton that never converges (patched in: always, or once the plate is
    down) makes the FE solver give up and say where; the CLI prints that one line, exits 1,
    and the --vtk folder does not appear (nothing half-written is left looking complete)."""
    import pocket.fem.steps as steps

    from pocket.core.errors import ConvergenceError

    real = steps.newton

    def failing(linearize, guess, *args, **kwargs):
        plate = linearize(guess)[1].B.shape[1] > 1  # the pressure, and the plate's unknowns
        if stage == "inflation" or plate:
            raise ConvergenceError("Newton: patched to fail", iterations=1, residual=1.0)
        return real(linearize, guess, *args, **kwargs)

    monkeypatch.setattr(steps, "newton", failing)
    status, out, err = run(capsys, "compress", "--alpha", "0.3", "--pressure", "0.31", "--force", "0.1",
                           "--solver", "fem", "--elements", "50", "--vtk", str(tmp_path / "fe"))
    assert status == 1 and out == "" and len(err.strip().splitlines()) == 1, err
    assert where in err and "patched to fail" in err, err
    assert list(tmp_path.iterdir()) == []
