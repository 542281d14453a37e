"""Solver records are obeyed: every command gets a solver's entry points from its record
(``pocket.core.solver.Solver.entry``), and a request the record does not serve is a one-line error
naming the solver and the entry point it lacks (exit 2), never an internal error.

The walk covers every (solver, command, case-file form) pair, for the three solvers and for a toy
solver registered here whose record lists inflation alone while its module (the analytical model's)
has every entry point: a command that called the module by duck typing would serve it anyway.
"""

import dataclasses
import importlib

import pytest

from pocket.apps.solvers import SOLVERS
from pocket.cli import main
from pocket.core.errors import InputError
from pocket.core.solver import ENTRY_POINTS, Solver

#: a solver whose record serves less than its module has (registered by the ``toy`` fixture)
TOY = Solver(name="toy", summary="inflation only", module="pocket.analytical", entry_points=("inflate",))

#: the case-file forms: initial state and loads (thickness 0.25 mm, E = 1 MPa, R = 20 mm, alpha 0.3)
INITIAL = {"pressure": 'pressure = "3.75 kPa"', "height": 'height = "8 mm"', "volume": 'volume = "5 mL"'}
LOADS = {"forces": 'forces = ["0.2 N"]', "heights": 'heights = ["7 mm"]'}


def _case(tmp_path, solver, initial, loads):
    path = tmp_path / f"{solver}-{initial}-{loads}.toml"
    path.write_text(f'name = "walk"\n[sheet]\nthickness = "0.25 mm"\nmodulus = "1 MPa"\nalpha = 0.3\n'
                    f'[clamp]\nradius = "20 mm"\n[initial]\n{INITIAL[initial]}\n[loads]\n{LOADS[loads]}\n'
                    f'[solver]\nname = "{solver}"\n')
    return str(path)


def _commands(tmp_path, solver):
    """(label, argv, the entry points it needs) of every command and case-file form, for ``solver``.

    The needs are read off the applications: a case starts by inflating (by pressure, or for an initial
    height by pressure through an inverse problem, or by volume then by pressure), then compresses its
    loads as one curve, solving each plate height for its force (``compress``); a force is checked
    against the end of the range (the shooting's when the solver has none); sensing inverts ``compress``
    and takes slopes on a curve; a design inflates and compresses both ways; a sweep solves curves and,
    where one fails, points.
    """
    initial_needs = {"pressure": {"inflate"}, "height": {"inflate"}, "volume": {"inflate_volume", "inflate"}}
    load_needs = {"forces": set(), "heights": {"compress"}}
    rubber = ["--alpha", "0.3", "--solver", solver]
    out = [("inflate --pressure", ["inflate", "--pressure", "0.3", *rubber], {"inflate"}),
           ("inflate --volume", ["inflate", "--volume", "0.5", *rubber], {"inflate_volume"}),
           ("compress", ["compress", "--pressure", "0.3", "--force", "0.1", *rubber],
            {"compression_curve"}),
           ("design", ["design", "--radius", "20 mm", "--height", "8 mm", "--modulus", "1 MPa", "--alpha", "0.3",
                       "--force", "0.2 N", "--solver", solver], {"inflate", "compress", "compression_curve"}),
           ("sweep", ["sweep", "--alpha", "0.3", "--pressure", "0.3", "--force", "0.1", "--workers", "1",
                      "--solver", solver, "--out", str(tmp_path / f"{solver}.csv")], {"compress", "compression_curve"})]
    for initial in INITIAL:
        for loads in LOADS:
            case = _case(tmp_path, solver, initial, loads)
            needs = initial_needs[initial] | load_needs[loads]
            out.append((f"run ({initial}, {loads})", ["run", case, "--out", str(tmp_path)],
                        needs | {"compression_curve"}))
            out.append((f"sense ({initial}, {loads})", ["sense", case, "--ratio", "1.01"],
                        needs | {"compress", "compression_curve"}))
    return out


@pytest.fixture
def toy(monkeypatch):
    monkeypatch.setitem(SOLVERS, TOY.name, TOY)
    return TOY


def _offered(argv) -> bool:
    """Whether the command offers the solver of ``argv`` (``pocket design`` offers shooting and fem)."""
    return argv[0] != "design" or argv[-1] in ("shooting", "fem")


WALKED = (*SOLVERS, TOY.name)
#: the solid's sensing takes 7 to 10 s per case form (a search of repeated solves, each inflating afresh): it walks
#: one form; the others differ from it only in the case's initial and load forms, which its ``run`` rows walk
SOLID_SENSE = "sense (pressure, forces)"


@pytest.mark.slow
@pytest.mark.parametrize("solver", WALKED)
def test_every_command_either_works_or_names_what_the_solver_lacks(solver, tmp_path, capsys, request):
    """Each (solver, command, case-file form): exit 0 where the record serves every entry point the
    command needs; else exit 2 with one line naming the solver and an entry point it lacks."""
    if solver == TOY.name:
        request.getfixturevalue("toy")
    record = SOLVERS[solver]
    for label, argv, needs in _commands(tmp_path, solver):
        if solver == "solid" and label.startswith("sense") and label != SOLID_SENSE:
            continue
        status = main(argv)
        err = capsys.readouterr().err
        assert "internal error" not in err, (label, err)
        assert "Traceback" not in err, (label, err)
        if not _offered(argv):
            assert status == 2, (label, err)
            assert err.count("\n") == 1, (label, err)
            assert "invalid choice" in err, (label, err)
            continue
        missing = sorted(needs - set(record.entry_points))
        if not missing:
            assert status == 0, (label, err)
            continue
        assert status == 2, (label, err)
        assert err.count("\n") == 1, (label, err)
        assert f"solver {solver} has no " in err, (label, err)
        assert any(f"(entry point {name}" in err for name in missing), (label, err)


def test_an_analytical_case_with_an_initial_volume_is_one_line(tmp_path, capsys):
    """The analytical model has no volume-controlled inflation: a case asking for one is refused in one
    line naming the case's key, the solver, what it lacks and the solvers that have it."""
    path = tmp_path / "volume.toml"
    path.write_text('[sheet]\nthickness = "0.25 mm"\nmodulus = "1 MPa"\nalpha = 0.3\n[clamp]\nradius = "20 mm"\n'
                    '[initial]\nvolume = "2 mL"\n[loads]\nforces = ["0.2 N"]\n[solver]\nname = "analytical"\n')
    assert main(["run", str(path), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert err == ("pocket: error: initial.volume = '2 mL': solver analytical has no volume-controlled inflation "
                   "(entry point inflate_volume; solvers that have it: shooting, fem, solid)\n")
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("solver", SOLVERS.values(), ids=SOLVERS)
def test_a_record_lists_what_its_module_has(solver):
    """A record does not promise what its module lacks: each listed entry point is a function there."""
    module = importlib.import_module(solver.module)
    for name in solver.entry_points:
        assert callable(getattr(module, name)), (solver.name, name)
        assert solver.entry(name, "a test") is getattr(module, name)


def test_entry_refuses_in_one_line_and_knows_every_entry_point():
    """``Solver.entry`` names the purpose, the solver, what it lacks and the alternatives given; a name
    that is no entry point at all, in a call or in a record, is a bug (ValueError), not a user's error."""
    with pytest.raises(InputError) as info:
        TOY.entry("compress", "--force", ["shooting", "fem"])
    assert str(info.value) == ("--force: solver toy has no compression (entry point compress; solvers that have "
                               "it: shooting, fem)")
    with pytest.raises(InputError, match=r"^--force: solver toy has no compression \(entry point compress\)$"):
        TOY.entry("compress", "--force")
    with pytest.raises(ValueError, match="not an entry point"):
        TOY.serves("inflate_pressure")
    with pytest.raises(ValueError, match="inflate_pressure"):
        dataclasses.replace(TOY, entry_points=("inflate_pressure",))
    assert set(ENTRY_POINTS) >= {name for s in SOLVERS.values() for name in s.entry_points}


def test_check_option_checks_by_the_record_and_refuses_an_undeclared_option():
    """``Solver.check_option`` is the record's own ``Option.checked`` (same value, same one-line error);
    an option the record does not declare is a bug of the solver (ValueError), not a user's error."""
    fem = SOLVERS["fem"]
    option = fem.option("order")
    assert option is not None
    for value in (1, 2):
        assert fem.check_option("order", value) == option.checked(value)
    with pytest.raises(InputError) as expected:
        option.checked(0, lambda _: "mesh order")
    with pytest.raises(InputError) as got:
        fem.check_option("order", 0, lambda _: "mesh order")
    assert str(got.value) == str(expected.value)
    with pytest.raises(ValueError, match="solver toy declares no option 'tol'"):
        TOY.check_option("tol", 1e-8)


@pytest.mark.parametrize(("command", "flag", "entry_point"), [("inflate", "--volume", "inflate_volume"),
                                                               ("compress", "--height", "compress_height")])
def test_a_flags_help_names_the_solvers_whose_records_serve_it(command, flag, entry_point, capsys):
    """The help of a flag only some solvers serve names exactly the solvers whose records list its entry point
    (it once named shooting and fem where the solid serves both too)."""
    from pocket.apps.solvers import SOLVERS
    from pocket.cli import main

    assert main([command, "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    help_of = text.split(f"{flag} ")[-1]  # the flag's own help, after its mentions in the usage line
    named = help_of.split("solvers ", 1)[1].split(")")[0].split(" --")[0]
    serving = {n for n, s in SOLVERS.items() if s.serves(entry_point)}
    assert set(named.replace(" and ", ", ").split(", ")) == serving, named
