"""The runnable examples of ``examples/``: each imported (in the default lane) and its ``main`` called (in the
slow lane), its numbers (returned unrounded, as it printed them) checked against the solvers solving them
afresh; one of them also run as a user runs it, a script in a subprocess."""

import importlib.util
import inspect
import math
import pathlib
import re
import subprocess
import sys

import pytest

from pocket import shooting
from pocket.core.indenters import Sphere

EXAMPLES = pathlib.Path(__file__).resolve().parent.parent / "examples"


def example(name: str):
    """The example ``examples/<name>.py`` imported as a module (its ``main`` not yet run)."""
    spec = importlib.util.spec_from_file_location(f"example_{name}", EXAMPLES / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.mark.parametrize("name", sorted(path.stem for path in EXAMPLES.glob("*.py")))
def test_every_example_imports_and_says_what_it_does(name):
    """Exact answer: each example imports without running (a name it uses that pocket no longer has fails
    here, in the default lane), opens with a docstring that shows how to run it, and has ``main(out)``, the
    function its script runs and its tests call."""
    module = example(name)
    assert f"python examples/{name}.py" in module.__doc__
    assert list(inspect.signature(module.main).parameters) == ["out"]


@pytest.mark.slow  # the slow lane (pytest -m slow): the example solves for seconds or more
def test_fingertip_button_designs_for_the_sphere_and_writes_its_series(tmp_path, capsys):
    """Exact answer: the example's design (Phat_I, Fhat, as printed: their repr) gives H/H0 = 0.8 under the
    8 mm sphere (K = 0.4) when shooting solves it afresh, and its P_I is F / (pi R^2 Fhat); its VTK series has
    the fingertip's surface in every step beside the sheet's."""
    button = example("fingertip_button")
    got = button.main(tmp_path)
    design = got["design"]
    assert f"Phat_I = {design.pressure_initial!r}, Fhat = {design.force!r}," in capsys.readouterr().out
    state = shooting.compress(button.ALPHA, design.pressure_initial, design.force, indenter=Sphere(0.4))
    assert state.height_ratio == pytest.approx(button.HEIGHT_RATIO, abs=1e-8)
    # the definition of Fhat: only the rounding of the product differs
    assert design.pressure_initial_Pa == pytest.approx(button.FORCE / (math.pi * button.RADIUS**2 * design.force),
                                                       rel=1e-12)
    vtk = got["vtk"]
    assert vtk == tmp_path / "vtk"
    steps = [len(re.findall(r'file="', (vtk / f"{part}.pvd").read_text())) for part in ("surface", "indenter")]
    assert steps[0] == steps[1] == len(list(vtk.glob("step_*_indenter.vtu"))) == button.STEPS


@pytest.mark.slow  # the slow lane (pytest -m slow): the example solves for seconds or more
def test_bulge_fit_recovers_the_rubber_and_presses_the_fitted_sheet(tmp_path):
    """Exact answer: the rubber behind the example's made-up bulge test. Each fitted parameter lies within four
    of its standard errors of the truth (the heights carry 0.2 % seeded noise: the fit's own error bars say how
    far it may land; beyond four of them the chance is 6e-5 per parameter for honest errors), the figure and the
    fitted sheet's case file are written, and the pressed sheet's pressures are those of that case file solved
    afresh by the shooting solver."""
    from pocket.apps.cases import load

    bulge = example("bulge_fit")
    got = bulge.main(tmp_path)
    s = got["fit"].statistics
    assert list(s.names) == list(bulge.TRUTH)
    for name, fitted, error in zip(s.names, s.values, s.standard_errors, strict=True):
        assert abs(fitted - bulge.TRUTH[name]) < 4.0 * error, (name, fitted, error)
    assert (tmp_path / "fit" / "fit.png").stat().st_size > 0
    case = load(got["case"])
    states = shooting.compression_curve(case.material.scaled(), case.initial[1] * case.radius / (case.modulus *
                                        case.thickness), [f / (case.initial[1] * math.pi * case.radius**2)
                                                          for f in case.loads])
    rows = got["pressed"]["states"]
    assert len(rows) == len(states) > 0
    for row, state in zip(rows, states, strict=True):
        # the same solver on the same dimensionless loads: only the rounding of the unit conversions differs
        assert row["pressure_Pa"] == pytest.approx(state.pressure_ratio * case.initial[1], rel=1e-12)


@pytest.mark.slow  # the slow lane (pytest -m slow): the example solves for seconds or more
def test_membrane_error_prints_both_models_and_draws_them(tmp_path):
    """Exact answers: the membrane's column is the shooting solver's states solved afresh (the pressure at each
    force, in kPa); the figure is written. Physics that could fail: at T/R = 0.08 the membrane's fluid volume
    is off by more than 1 % (about 3 T/R here, as the validation report's table shows), its pressure rise by
    less at every force."""
    from pocket.apps.cases import sample

    membrane_error = example("membrane_error")
    got = membrane_error.main(tmp_path)
    table = got["table"]
    forces = membrane_error.FORCES
    assert len(table) == 3 + 3 * len(forces)

    def error(load, name):
        membrane, solid = table[load, name]
        return membrane / solid - 1.0

    volume = error(None, "fluid volume")
    assert abs(volume) > 0.01
    for force in forces:
        assert abs(error(force, "pressure")) < abs(volume), force
    case = sample(4)
    pressure = membrane_error.PRESSURE
    phat = pressure * case.radius / (case.modulus * case.thickness)
    states = shooting.compression_curve(case.material.scaled(), phat,
                                        [f / (pressure * math.pi * case.radius**2) for f in forces])
    for force, state in zip(forces, states, strict=True):
        # the same solver on the same loads: only the rounding of the conversion to kPa differs
        assert table[force, "pressure"][0] == pytest.approx(state.pressure * pressure / phat / 1e3, rel=1e-12)
    assert got["figure"] == tmp_path / "membrane_error.png"
    assert got["figure"].stat().st_size > 0


@pytest.mark.slow  # the slow lane (pytest -m slow): the example solves for seconds or more
def test_an_example_runs_as_a_script(tmp_path):
    """Exact answer: ``python examples/fingertip_button.py FOLDER``, as a user runs it, ends with status 0,
    prints nothing on stderr, and writes its VTK series into FOLDER/vtk, the files its last line names (the
    numbers are the in-process test's)."""
    run = subprocess.run([sys.executable, str(EXAMPLES / "fingertip_button.py"), str(tmp_path / "out")],
                         capture_output=True, text=True, timeout=600, check=False)
    assert run.returncode == 0, run.stderr
    assert not run.stderr, run.stderr
    series = [tmp_path / "out" / "vtk" / f"{part}.pvd" for part in ("surface", "indenter")]
    assert run.stdout.splitlines()[-1].endswith(f"{series[0]}, {series[1]}"), run.stdout
    assert all(path.stat().st_size > 0 for path in series)
