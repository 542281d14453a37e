"""The runnable examples of ``examples/``, each run as a user runs it: a script in a subprocess."""

import pathlib
import re
import subprocess
import sys

import pytest

from pocket import shooting
from pocket.core.indenters import sphere

pytestmark = pytest.mark.slow  # the slow lane (pytest -m slow)

EXAMPLES = pathlib.Path(__file__).resolve().parent.parent / "examples"


def test_fingertip_button_designs_for_the_sphere_and_writes_its_series(tmp_path):
    """Exact answer: the example's printed design (Phat_I, Fhat) gives H/H0 = 0.8 under the 8 mm sphere
    (K = 0.4) when shooting solves it afresh, P_I = F / (pi R^2 Fhat); its VTK series has the fingertip's
    surface in every step beside the sheet's."""
    run = subprocess.run([sys.executable, str(EXAMPLES / "fingertip_button.py"), str(tmp_path)],
                         capture_output=True, text=True, timeout=300, check=False)
    assert run.returncode == 0, run.stderr
    assert not run.stderr, run.stderr
    phat_i = float(re.search(r"Phat_I = (\S+),", run.stdout).group(1))
    fhat = float(re.search(r"Fhat = (\S+),", run.stdout).group(1))
    state = shooting.compress(47 / 160, phat_i, fhat, indenter=sphere(0.4))
    assert state.height_ratio == pytest.approx(0.8, abs=1e-8)
    p_i = float(re.search(r"P_I = (\S+) kPa", run.stdout).group(1)) * 1e3
    assert p_i == pytest.approx(0.67 / (3.141592653589793 * 0.02**2 * fhat), rel=1e-3)  # printed to 4 digits
    vtk = tmp_path / "vtk"
    steps = [len(re.findall(r'file="', (vtk / f"{part}.pvd").read_text())) for part in ("surface", "indenter")]
    assert steps[0] == steps[1] == len(list(vtk.glob("step_*_indenter.vtu"))) == 11


def test_bulge_fit_recovers_the_rubber_and_presses_the_fitted_sheet(tmp_path):
    """Exact answer: the rubber behind the example's made-up bulge test. Each fitted parameter lies within four
    of its standard errors of the truth (the heights carry 0.2 % seeded noise: the fit's own error bars say how
    far it may land; beyond four of them the chance is 6e-5 per parameter for honest errors), the figure and the
    fitted sheet's case file are written, and the pressed sheet's rows are those of that case file solved afresh
    by the shooting solver (printed to 6 digits)."""
    from pocket.apps.cases import load

    run = subprocess.run([sys.executable, str(EXAMPLES / "bulge_fit.py"), str(tmp_path)],
                         capture_output=True, text=True, timeout=300, check=False)
    assert run.returncode == 0, run.stderr
    assert not run.stderr, run.stderr
    truth = {"c10": 85e3, "c20": -2e3, "c30": 0.2e3}
    for name, value in truth.items():
        fitted, error = (float(x) for x in re.search(rf"{name} = (\S+) Pa \+- (\S+)", run.stdout).groups())
        assert abs(fitted - value) < 4.0 * error, (name, fitted, error)
    assert (tmp_path / "fit" / "fit.png").stat().st_size > 0
    case = load(tmp_path / "fit" / "fitted.toml")
    states = shooting.compression_curve(case.material.scaled(), case.initial[1] * case.radius / (case.modulus *
                                        case.thickness), [f / (case.initial[1] * 3.141592653589793 * case.radius**2)
                                                          for f in case.loads])
    rows = re.findall(r"^\s+(\S+)\s+(\S+)\s+(\S+)$", run.stdout.split("pressed by the plate")[1], re.M)[1:]
    assert len(rows) == len(states) > 0
    for (_, pressure, _), state in zip(rows, states, strict=True):
        assert float(pressure) * 1e3 == pytest.approx(state.pressure_ratio * case.initial[1], rel=1e-5)


def test_membrane_error_prints_both_models_and_draws_them(tmp_path):
    """Exact answers: each printed error is membrane / solid - 1 of its printed values, and the membrane's
    column is the shooting solver's state solved afresh (the pressure at the largest force); the figure is
    written. Physics that could fail: at T/R = 0.08 the membrane's fluid volume is off by more than 1 %
    (about 3 T/R here, as the validation report's table shows), its pressure rise by less."""
    from pocket.apps.cases import sample

    run = subprocess.run([sys.executable, str(EXAMPLES / "membrane_error.py"), str(tmp_path)],
                         capture_output=True, text=True, timeout=600, check=False)
    assert run.returncode == 0, run.stderr
    assert not run.stderr, run.stderr
    rows = re.findall(r"^  (\S.*?)\s+(\S+)\s+(\S+) (?:\S+)?\s+([+-]\S+)%$", run.stdout, re.M)
    assert len(rows) == 3 + 3 * 3, run.stdout
    for _, membrane, solid, error in rows:
        assert float(error) / 100.0 == pytest.approx(float(membrane) / float(solid) - 1.0, abs=2e-4)  # printed
    errors = {name.strip(): float(error) / 100.0 for name, _, _, error in rows}
    assert abs(errors["fluid volume"]) > 0.01
    case = sample(4)
    phat = 5e3 * case.radius / (case.modulus * case.thickness)
    state = shooting.compress(case.material.scaled(), phat, 2.0 / (5e3 * 3.141592653589793 * case.radius**2))
    printed = float([m for name, m, _, _ in rows if name.strip() == "pressure"][-1])
    assert printed == pytest.approx(state.pressure * 5.0 / phat, rel=1e-4)  # kPa, printed to 5 digits
    assert (tmp_path / "membrane_error.png").stat().st_size > 0
