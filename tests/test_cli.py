"""The ``pocket`` command line, called through ``main(argv)``."""

import json
import re
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
    assert status == 0
    assert err == ""
    data = json.loads(out)
    assert set(InflatedState.KEYS) <= set(data)
    ref = shooting.inflate(47 / 160, 0.31).scalars()
    assert all(data[k] == ref[k] for k in InflatedState.KEYS)


def test_compress_curve_is_a_json_list(capsys):
    status, out, _ = run(capsys, "compress", "--alpha", "0.3", "--pressure", "0.31",
                         "--force", "0.05", "0.1", "0.2", "--json")
    rows = json.loads(out)
    assert status == 0
    assert [r["force"] for r in rows] == [0.05, 0.1, 0.2]
    assert all(set(CompressedState.KEYS) <= set(r) for r in rows)


@pytest.mark.parametrize("solver", ["shooting", "analytical", "fem"])
def test_table(capsys, solver):
    """Exact answer: the table has a column for every key any state reports in JSON (the FE model's state at
    F = 0 lacks one its compressed states have: the column once went missing), each line a cell per column."""
    argv = ("compress", "--alpha", "47/160", "--pressure", "0.31", "--force", "0", "0.19", "--solver", solver)
    status, out, _ = run(capsys, *argv)
    lines = out.splitlines()
    assert status == 0
    assert lines[0] == f"# solver: {solver}"
    assert lines[1].split()[:3] == ["alpha", "pressure_initial", "force"]
    assert len(lines) == 4
    keys = {k for row in json.loads(run(capsys, *argv, "--json")[1]) for k in row} - {"solver", "warnings"}
    assert set(lines[1].split()) == keys
    assert all(len(line.split()) == len(keys) for line in lines[2:])


@pytest.mark.parametrize(
    ("argv", "message"),
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
    status = main(argv)  # argparse's own errors too: main returns their status
    out, err = capsys.readouterr()
    assert status == 2
    assert out == ""
    assert len(err.strip().splitlines()) == 1, err
    assert message in err, err


@pytest.mark.slow
def test_console_script_whole_process():
    """The installed entry point: exit status and stderr of a real process, no traceback."""
    proc = subprocess.run([sys.executable, "-m", "pocket.cli", "compress", "--alpha", "0.3",
                           "--pressure", "0.3", "--force", "50"], capture_output=True, text=True)
    assert proc.returncode == 2
    assert "Traceback" not in proc.stderr


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
    assert status == 2
    assert "--overwrite" in err


def test_vtk_times_are_the_forces_in_any_order(capsys, tmp_path):
    """Exact answer: forces given decreasing are written in increasing order, each step's time its own
    force (the .pvd) and equal to the force in its field data; a force given twice is refused (exit 2,
    one line, no folder), as the time would repeat."""
    import xml.etree.ElementTree as ET

    import meshio

    out = tmp_path / "series"
    argv = ["compress", "--alpha", "0.3", "--pressure", "0.31", "--vtk", str(out), "--force"]
    assert run(capsys, *argv, "0.2", "0.05", "0.1")[0] == 0
    sets = list(ET.parse(out / "surface.pvd").getroot().iter("DataSet"))
    assert [float(d.get("timestep")) for d in sets] == [0.05, 0.1, 0.2]
    assert [meshio.read(out / d.get("file")).field_data["force"].tolist() for d in sets] == [[0.05], [0.1], [0.2]]
    status, _, err = run(capsys, *argv, "0.1", "0.2", "0.1", "--overwrite")
    assert status == 2, err
    assert err.count("\n") == 1, err
    assert "--force gives 0.1 more than once" in err, err


@pytest.mark.parametrize(("flags", "solver", "extra"), [
    ([], "shooting", {}),
    (["--solver", "analytical"], "analytical", {}),
    (["--solver", "fem", "--elements", "40", "--order", "1"], "fem", {"elements": [40.0], "order": [1.0]}),
])
def test_vtk_field_data_name_the_solver_and_mesh(flags, solver, extra, capsys, tmp_path):
    """Exact answer: the solver, the law and the fluid read back (meshio) as the codes of the README's
    table (solver: shooting 0, fem 1, analytical 2; mooney-rivlin 0; liquid 0); the FE mesh as its
    element count and order."""
    import meshio

    out = tmp_path / "series"
    assert run(capsys, "compress", "--alpha", "0.3", "--pressure", "0.31", "--force", "0.1", "--vtk", str(out),
               *flags)[0] == 0
    data = {k: v.tolist() for k, v in meshio.read(out / "step_0000_surface.vtu").field_data.items()}
    assert data["solver_code"] == [float(("shooting", "fem", "analytical").index(solver))]
    assert data["material_code"] == [0.0]
    assert data["fluid_code"] == [0.0]
    assert {k: data[k] for k in extra} == extra


def test_fem_solver_same_keys_as_shooting_plus_its_own(capsys, tmp_path):
    """The FE answer through the CLI: the shooting keys, agreeing with shooting's to 1e-5
    (a loose bar: 200 P2 elements give about 1e-9, tests/test_solvers_agree.py checks 1e-8), plus
    the mesh, Newton and contact diagnostics, and a VTK series of the FE states."""
    argv = ["compress", "--alpha", "47/160", "--pressure", "0.31", "--force", "0.05", "0.19", "--json"]
    status, out, _ = run(capsys, *argv, "--solver", "fem", "--elements", "200", "--vtk", str(tmp_path / "fe"))
    fe = json.loads(out)
    _, out, _ = run(capsys, *argv)
    ref = json.loads(out)
    assert status == 0
    assert [r["solver"] for r in fe] == ["fem", "fem"]
    for a, b in zip(fe, ref, strict=True):
        assert {"elements", "order", "newton_iterations", "penetration", "force_difference"} <= set(a)
        assert a["elements"] == 200
        assert a["order"] == 2
        for key in CompressedState.KEYS:
            assert a[key] == pytest.approx(b[key], rel=1e-5, abs=1e-12), key
    assert sorted(p.name for p in (tmp_path / "fe").glob("*.pvd")) == ["indenter.pvd", "profile.pvd", "surface.pvd"]


@pytest.mark.slow
def test_closed_pipe_ends_quietly():
    """`pocket ... | head`: the reader is gone before the output is written (its end of the
    pipe is closed here first, so the write must fail); no traceback, status 0 (the run passed)."""
    proc = subprocess.Popen([sys.executable, "-m", "pocket.cli", "inflate", "--alpha", "0.3",
                             "--pressure", "0.3"], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    proc.stdout.close()
    err = proc.stderr.read().decode()
    assert proc.wait() == 0
    assert err == ""


@pytest.mark.slow
def test_python_dash_m_pocket_runs_the_command():
    """Exact answer: `python -m pocket --version` prints what `pocket --version` does, from the installed
    metadata, and `python -m pocket inflate` solves (status 0, JSON with the asked pressure)."""
    from pocket.apps.provenance import described

    done = subprocess.run([sys.executable, "-m", "pocket", "--version"], capture_output=True, text=True)
    assert (done.returncode, done.stdout.strip(), done.stderr) == (0, f"pocket {described()}", "")
    done = subprocess.run([sys.executable, "-m", "pocket", "inflate", "--alpha", "0.3", "--pressure", "0.3",
                           "--json"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["pressure"] == 0.3, done.stderr


@pytest.mark.parametrize("solver", ["shooting", "fem"])
def test_inflate_by_volume_is_the_inverse_of_inflate_by_pressure(capsys, solver):
    """Exact answer: `inflate --volume V` gives a state of volume V; inflating by pressure to its
    pressure gives the same volume back (one first-branch state per pressure below the maximum)."""
    status, out, err = run(capsys, "inflate", "--alpha", "0.3", "--volume", "1", "--solver", solver, "--json")
    by_volume = json.loads(out)
    assert status == 0
    assert err == ""
    assert by_volume["volume"] == pytest.approx(1.0, rel=1e-9)
    status, out, _ = run(capsys, "inflate", "--alpha", "0.3", "--pressure", repr(by_volume["pressure"]),
                         "--solver", solver, "--json")
    assert status == 0
    assert json.loads(out)["volume"] == pytest.approx(1.0, rel=1e-6)


def test_inflate_by_volume_where_a_solver_has_none_or_with_a_pressure_is_one_line_exit_2(capsys):
    """The analytical model inflates by pressure only: one line naming --volume and the solvers that
    have it; --volume with --pressure is a usage error."""
    status, out, err = run(capsys, "inflate", "--alpha", "0.3", "--volume", "1", "--solver", "analytical")
    assert (status, out) == (2, "")
    assert err == ("pocket: error: --volume: solver analytical has no volume-controlled "
                                                "inflation (entry point inflate_volume; solvers that have it: "
                                                "shooting, fem, solid)\n")
    status, out, err = run(capsys, "inflate", "--alpha", "0.3", "--volume", "1", "--pressure", "0.3")
    assert (status, out) == (2, "")
    assert "--pressure: not allowed with argument --volume" in err


@pytest.mark.parametrize("solver", ["shooting", "fem"])
def test_a_pressure_above_the_maximum_quotes_it_and_volume_control_passes_it(capsys, solver):
    """Exact answer: alpha = 0 (neo-Hookean) has a first-branch pressure maximum below Phat = 0.8; the
    refusal (status 2) quotes the maximum and its volume and points to --volume. Inflating to the quoted
    volume gives the quoted pressure (the maximum: P(V) is flat there, so 6 digits of V give 6 of P), and
    one 20 % further, past the maximum, a lower pressure."""
    status, out, err = run(capsys, "inflate", "--alpha", "0", "--pressure", "0.8", "--solver", solver)
    found = re.search(r"maximum Phat = (\S+), reached at V/R\^3 = (\S+) .*pocket inflate --volume V\)$", err)
    assert status == 2, err
    assert out == "", err
    assert err.count("\n") == 1, err
    assert found, err
    maximum, volume = float(found[1]), float(found[2])
    assert maximum < 0.8
    pressures = []
    for v in (volume, 1.2 * volume):
        status, out, _ = run(capsys, "inflate", "--alpha", "0", "--volume", repr(v), "--solver", solver, "--json")
        pressures.append(json.loads(out)["pressure"])
    assert pressures[0] == pytest.approx(maximum, rel=1e-5)
    assert pressures[1] < pressures[0]


@pytest.mark.parametrize(("stage", "where"), [("inflation", "small-strain dome"),
                                          ("compression", "first contact: Newton failed at every contact radius")])
def test_fem_newton_failure_is_one_line_exit_1_and_no_files(capsys, tmp_path, monkeypatch, stage, where):
    """Exact answer: a Newton that never converges (patched in: always, or once the plate is
    down) makes the FE solver give up and say where; the CLI prints that one line, exits 1,
    and the --vtk folder does not appear (nothing half-written is left looking complete)."""
    import pocket.fem.steps as steps
    from pocket.fem.inflation import forget

    from pocket.core.errors import ConvergenceError

    real = steps.newton
    forget()  # an inflation remembered from an earlier test would not meet the patched Newton

    def failing(linearize, guess, *args, **kwargs):
        plate = linearize(guess)[1].B.shape[1] > 1  # the pressure, and the plate's unknowns
        if stage == "inflation" or plate:
            raise ConvergenceError("Newton: patched to fail", iterations=1, residual=1.0)
        return real(linearize, guess, *args, **kwargs)

    monkeypatch.setattr(steps, "newton", failing)
    status, out, err = run(capsys, "compress", "--alpha", "0.3", "--pressure", "0.31", "--force", "0.1",
                           "--solver", "fem", "--elements", "50", "--vtk", str(tmp_path / "fe"))
    assert status == 1, err
    assert out == "", err
    assert len(err.strip().splitlines()) == 1, err
    assert where in err, err
    assert "patched to fail" in err, err
    assert list(tmp_path.iterdir()) == []


def _commands():
    """Every subcommand's parser, by name (the parser ``pocket --help`` lists)."""
    from pocket.cli.main import _parser

    parser = _parser()
    sub = next(a for a in parser._actions if isinstance(a, __import__("argparse")._SubParsersAction))
    return sub.choices


def test_inflate_help_names_no_force_and_no_fluid(capsys):
    """Exact answer: inflate's help says nothing of forces or fluids, which it does not take (compress's does,
    and its parser has --force and --fluid: the words are the ones to look for)."""
    texts = {}
    for name in ("inflate", "compress"):
        assert main([name, "--help"]) == 0
        texts[name] = " ".join(capsys.readouterr().out.split()).lower()
    for word in ("--force", "--fluid", "fhat", "forces", "fluid"):
        assert word in texts["compress"], word
        assert word not in texts["inflate"], word


def test_documented_commands_are_harmless_to_paste():
    """Exact answer: every line of the sh blocks of the README and the documentation's pages, its comment
    cut off and its quoted words blanked, holds no shell operator a synopsis would bring ([a|b] runs as a
    pipeline, <x> redirects), and each `pocket` line without a placeholder parses as a command (argparse: a
    bad one is exit 2)."""
    import shlex

    import documents

    from pocket.cli.main import _parser

    blocks = re.findall(r"```sh\n(.*?)```", documents.text(), flags=re.S)
    lines = [line for block in blocks for line in block.splitlines() if line.strip()]
    assert any(line.startswith("pocket inflate") for line in lines)
    for line in lines:
        code = re.sub(r"'[^']*'|\"[^\"]*\"", "''", line).split(" #")[0]
        assert not set(code) & set("[]|<>"), line
        if code.startswith("pocket ") and not {"COMMAND", "..."} & set(code.split()):  # placeholders: prose
            args = _parser().parse_args(shlex.split(code)[1:])
            assert args.handler, line


@pytest.mark.parametrize("name", sorted(_commands()))
def test_every_subcommand_help(name, capsys):
    """`pocket COMMAND --help`: exit 0, a description, help for every option, each option's default
    (for solver flags the default of the solver's record), and the exit codes."""
    import argparse

    from pocket.apps.solvers import all_options

    parser = _commands()[name]
    assert main([name, "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    assert parser.description
    assert "exit status: 0 " in text
    records = all_options()
    for action in parser._actions:
        if isinstance(action, argparse._HelpAction):
            continue
        assert action.help, action.option_strings
        line = " ".join(parser._get_formatter()._expand_help(action).split())
        assert line in text
        name_ = action.dest
        default = records[name_][0][1].default if name_ in records else action.default
        if isinstance(default, bool | str) and default:
            assert str(default).lower() in line.lower(), (action.option_strings, line)
        elif isinstance(default, int | float) and not isinstance(default, bool):  # 1e5 or 100000: the number
            numbers = {float(x) for x in re.findall(r"\d+(?:\.\d+)?(?:e[-+]?\d+)?", line)}
            assert float(default) in numbers, (action.option_strings, line)


def test_a_default_the_help_text_omits_comes_from_the_record(capsys, monkeypatch):
    """Exact answer: --rtol's help text names no default, so the help adds the shooting record's
    (1e-10); change the record's default and the help follows."""
    import dataclasses

    from pocket.apps import solvers

    assert main(["inflate", "--help"]) == 0
    assert "(default: 1e-10)" in " ".join(capsys.readouterr().out.split())
    rtol = dataclasses.replace(solvers.SOLVERS["shooting"].options[0], default=3e-9)
    monkeypatch.setitem(solvers.SOLVERS, "shooting", dataclasses.replace(solvers.SOLVERS["shooting"], options=(rtol,)))
    assert main(["inflate", "--help"]) == 0
    assert "(default: 3e-09)" in " ".join(capsys.readouterr().out.split())


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["inflate", "--alpha", "0.3", "--pressure", "0.3", "--rtol", "2"], "--rtol = 2.0, but it must lie in [1e-14"),
        (["compress", "--alpha", "0.3", "--pressure", "0.3", "--force", "0.1", "--rtol", "1e-20"],
         "--rtol = 1e-20, but it must lie in [1e-14, 0.0001]"),
        (["inflate", "--alpha", "0.3", "--pressure", "0.3", "--solver", "fem", "--tol", "0"], "--tol = 0.0"),
        (["inflate", "--alpha", "0.3", "--pressure", "0.3", "--solver", "fem", "--elements", "1000000"],
         "--elements = 1000000, but it must lie in [4, 100000]"),
        (["inflate", "--alpha", "0.3", "--pressure", "0.3", "--solver", "fem", "--mesh", "/dev/zero"],
         "--mesh = '/dev/zero' is not a regular file"),
        (["inflate", "--alpha", "0.3", "--pressure", "1e300"], "pressure = 1e+300 is outside the magnitudes"),
        (["inflate", "--alpha", "0.3", "--pressure", "1e-300"], "pressure = 1e-300 is outside the magnitudes"),
        (["inflate", "--alpha", "0.3", "--pressure", "1" + "0" * 400 + "/1"], "is not a number"),
        (["inflate", "--alpha", "0.3", "--pressure", "0/0"], "'0/0' is not a number"),
        (["compress", "--alpha", "0.3", "--pressure", "0.3", "--force", "nan"], "force = nan is not finite"),
    ],
)
def test_solver_options_and_magnitudes_through_the_cli(capsys, argv, message):
    """Option values the records refuse, and numbers outside the model's magnitudes: exit 2, one line."""
    status = main(argv)  # argparse's own errors too: main returns their status
    out, err = capsys.readouterr()
    assert status == 2, err
    assert out == "", err
    assert err.count("\n") == 1, err
    assert message in err, err


def _with_warnings(monkeypatch):
    """The shooting solver, patched so that every state carries two warnings (one of its inflated state): its
    entry points as the package hands them out, from its ``api``."""
    import dataclasses

    import pocket.shooting.api as api

    real_inflate, real_curve = api.inflate, api.compression_curve

    def inflate(*args, **kwargs):
        return dataclasses.replace(real_inflate(*args, **kwargs), warnings=("inflated: note",))

    def compression_curve(*args, **kwargs):
        return [dataclasses.replace(s, warnings=(f"at force {s.force}",),
                                    inflated=dataclasses.replace(s.inflated, warnings=("inflated: note",)))
                for s in real_curve(*args, **kwargs)]

    monkeypatch.setattr(api, "inflate", inflate)
    monkeypatch.setattr(api, "compression_curve", compression_curve)


def test_warnings_on_stderr_and_in_json(capsys, monkeypatch, tmp_path):
    """Each state's warnings: `pocket: warning: ...` lines on stderr (each once), and a `warnings`
    list per state in JSON, for inflate, compress and run."""
    _with_warnings(monkeypatch)
    status, out, err = run(capsys, "inflate", "--alpha", "0.3", "--pressure", "0.3", "--json")
    assert status == 0
    assert json.loads(out)["warnings"] == ["inflated: note"]
    assert err == "pocket: warning: inflated: note\n"
    status, out, err = run(capsys, "compress", "--alpha", "0.3", "--pressure", "0.3", "--force", "0.1", "0.2",
                           "--json")
    assert [r["warnings"] for r in json.loads(out)] == [["at force 0.1"], ["at force 0.2"]]
    assert err.splitlines() == ["pocket: warning: inflated: note", "pocket: warning: at force 0.1",
                                "pocket: warning: at force 0.2"]
    status, out, err = run(capsys, "compress", "--alpha", "0.3", "--pressure", "0.3", "--force", "0.1")
    assert status == 0
    assert "warnings" not in out
    assert "at force 0.1" in err
    status, out, err = run(capsys, "run", "--sample", "1", "--out", str(tmp_path))
    result = json.loads((tmp_path / "sample1.json").read_text())
    assert status == 0
    assert result["inflated"]["warnings"] == ["inflated: note"]
    assert [s["warnings"] for s in result["states"]] == [[f"at force {s['force']}"] for s in result["states"]]
    assert err.splitlines()[0] == "pocket: warning: inflated: note"
    assert len(err.splitlines()) == 8


class _Terminal(__import__("io").StringIO):
    """A stderr that says it is a terminal."""

    def isatty(self):
        return True


def _curve_with_progress(monkeypatch, calls):
    """The shooting curve, patched to take ``progress`` as the entry-point protocol says, recording it."""
    import pocket.shooting.api as api

    real = api.compression_curve

    def compression_curve(alpha, pressure_initial, forces, *, progress=None, **options):
        calls.append(progress)
        states = []
        for done, force in enumerate(forces, start=1):
            states += real(alpha, pressure_initial, [force], **options)
            if progress is not None:
                progress(done, len(forces))
        return states

    monkeypatch.setattr(api, "compression_curve", compression_curve)


@pytest.mark.parametrize("terminal", [True, False])
def test_progress_bar_only_on_a_terminal(terminal, capsys, monkeypatch, tmp_path):
    """A curve on a terminal: the solver gets a progress callback and a tqdm bar reaches 3/3 on
    stderr; off a terminal (a file, a pipe) it gets none and stderr stays empty."""
    calls = []
    _curve_with_progress(monkeypatch, calls)
    stderr = _Terminal() if terminal else __import__("io").StringIO()
    monkeypatch.setattr(sys, "stderr", stderr)
    assert main(["compress", "--alpha", "0.3", "--pressure", "0.3", "--force", "0.1", "0.2", "0.3"]) == 0
    assert main(["run", "--sample", "1", "--out", str(tmp_path)]) == 0
    assert len(calls) == 2
    assert all((c is not None) == terminal for c in calls)
    text = stderr.getvalue()
    assert ("3/3" in text and "7/7" in text) if terminal else text == ""


def test_sweep_bar_on_a_terminal(monkeypatch, tmp_path, capsys):
    """The sweep's tqdm bar counts its points on a terminal."""
    stderr = _Terminal()
    monkeypatch.setattr(sys, "stderr", stderr)
    assert main(["sweep", "--alpha", "0.3", "--pressure", "0.3", "--force", "0.1", "0.2", "--out",
                 str(tmp_path / "s.csv"), "--workers", "1"]) == 0
    assert "2/2" in stderr.getvalue()
    assert "points" in stderr.getvalue()


@pytest.mark.slow
@pytest.mark.parametrize(
    "argv",
    [
        ["compress", "--alpha", "0.3", "--pressure", "0.3", "--force", "0.1", "0.2", "--json"],
        ["design", "--radius", "20 mm", "--height", "10 mm", "--modulus", "1 MPa", "--alpha", "0.3",
         "--force", "0.67 N"],
        ["sense", "--sample", "1", "--ratio", "1.2"],
        ["run", "--sample", "1", "--out", "{tmp}"],
        ["sweep", "--alpha", "0.3", "--pressure", "0.3", "--force", "0.1", "--out", "{tmp}/s.csv", "--workers", "1"],
        ["--help"],
        ["inflate", "--help"],
        ["--version"],
    ],
)
@pytest.mark.parametrize("buffered", [True, False])
def test_every_command_on_a_closed_pipe(argv, buffered, tmp_path):
    """`pocket ... | head` with the reader gone before any output: status 0, nothing on stderr, with
    Python's stdout buffered (as for users) or not (PYTHONUNBUFFERED, as in some CI)."""
    import os

    argv = [a.replace("{tmp}", str(tmp_path)) for a in argv]
    env = {k: v for k, v in os.environ.items() if k != "PYTHONUNBUFFERED"} | ({} if buffered else
                                                                              {"PYTHONUNBUFFERED": "1"})
    proc = subprocess.Popen([sys.executable, "-m", "pocket.cli", *argv], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, env=env)
    proc.stdout.close()
    err = proc.stderr.read().decode()
    assert proc.wait() == 0, err
    assert err == "", err


def test_interrupt_is_one_line_and_130(capsys, monkeypatch):
    """Ctrl-C during a solve (KeyboardInterrupt in the solver): status 130, `pocket: interrupted`."""
    import pocket.shooting.api as api

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(api, "inflate", interrupted)
    status, out, err = run(capsys, "inflate", "--alpha", "0.3", "--pressure", "0.3")
    assert status == 130
    assert out == ""
    assert err == "pocket: interrupted\n"


def _interrupted(hold, args, release=True, **popen) -> None:
    """Run the held command ``args`` (``holds.Hold.popen``, ``popen`` its further keywords), send it SIGINT where
    it waits (then release the hold, unless ``release`` is False: the compiler's hold is never let go), and check
    how it ended: status 130, stderr exactly `pocket: interrupted`, nothing on stdout."""
    import signal

    proc = hold.popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, **popen)
    try:
        assert hold.arrived(), proc.communicate()
        proc.send_signal(signal.SIGINT)
        if release:
            hold.release()
        out, err = proc.communicate(timeout=600)
    finally:
        proc.kill()
    assert proc.returncode == 130, err
    assert err == b"pocket: interrupted\n", err
    assert out == b"", err


@pytest.mark.slow
def test_sigint_reaches_a_held_command_from_a_test_run_that_ignores_it(tmp_path):
    """A test run started in the background (`pytest &`, nohup, a runner without a terminal) has SIGINT
    ignored, and every process it starts inherits that; a held command is the foreground command of a
    terminal all the same: SIGINT while it waits in its solve gives status 130, stderr exactly `pocket:
    interrupted`, nothing on stdout (a command that ignored it would end with the solve's AssertionError)."""
    import signal

    from holds import SHOOTING_INFLATE, Hold

    with Hold(tmp_path, SHOOTING_INFLATE) as hold:
        _interrupted(hold, ["inflate", "--alpha", "0.3", "--pressure", "0.3"],
                     preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_IGN))


@pytest.mark.slow
def test_sigint_to_a_long_fe_solve(tmp_path):
    """A real SIGINT to an FE curve while it solves its second force inside compiled code (the solve
    waits there for the test): status 130, stderr exactly `pocket: interrupted`, nothing on stdout, no
    --vtk folder."""
    from holds import FE_NEXT_POINT, Hold

    with Hold(tmp_path, FE_NEXT_POINT) as hold:
        _interrupted(hold, ["compress", "--alpha", "0.3", "--pressure", "0.3", "--force", "0.5", "1", "--solver",
                            "fem", "--elements", "400", "--vtk", str(tmp_path / "v")])
    assert [p.name for p in tmp_path.iterdir()] == [hold.script.name]  # no --vtk folder


@pytest.mark.slow
def test_sigint_during_compilation_is_not_lost(tmp_path):
    """A real SIGINT while numba compiles (an empty compiled-code cache), delivered while llvmlite's
    object-cache callback runs, where the KeyboardInterrupt is ignored (the compiler waits there for the
    test): the run still ends, status 130, stderr exactly `pocket: interrupted`, nothing on stdout."""
    import os

    from holds import IN_COMPILER, Hold

    from pocket.core.compiled import CACHE_ENV

    with Hold(tmp_path, IN_COMPILER) as hold:
        _interrupted(hold, ["inflate", "--alpha", "0.3", "--pressure", "0.3"], release=False,
                     env=os.environ | {CACHE_ENV: str(tmp_path / "cache")})
