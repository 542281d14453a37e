"""The gallery's examples (``examples/``, run by sphinx-gallery when the documentation builds): each read as
a page and its use of pocket's names checked in the default lane, without running it; each example's numbers
(returned unrounded by its ``main``, as it printed them) checked in the slow lane against a physical law or
the solvers solving them afresh; one of them also run as a user runs it, a script in a subprocess."""

import ast
import importlib
import importlib.util
import math
import os
import pathlib
import re
import subprocess
import sys

import numpy as np
import pytest

from pocket import shooting
from pocket.core.indenters import Sphere

EXAMPLES = pathlib.Path(__file__).resolve().parent.parent / "examples"
NAMES = sorted(path.stem for path in EXAMPLES.glob("*.py"))


def example(name: str):
    """The example ``examples/<name>.py`` imported as a module (its run cell, guarded by ``__name__ ==
    "__main__"``, not run)."""
    spec = importlib.util.spec_from_file_location(f"example_{name}", EXAMPLES / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_gallery_orders_its_examples_by_number():
    """Exact answer: every example is ``plot_NN_<topic>.py`` with NN = 01, 02, ... in sequence (sphinx-gallery
    sorts the pages by file name, the order a user needs them), at least twelve of them."""
    numbers = [re.fullmatch(r"plot_(\d\d)_[a-z0-9_]+", name) for name in NAMES]
    assert all(numbers), NAMES
    assert [int(m.group(1)) for m in numbers] == list(range(1, len(NAMES) + 1))
    assert len(NAMES) >= 12


@pytest.mark.parametrize("name", NAMES)
def test_every_example_is_a_page_whose_pocket_names_exist(name):
    """Exact answers, read from the source without running it (the default lane): the docstring opens with an
    rST title underlined by '=' of its length, then a paragraph, and shows how to run the script; ``main`` takes
    nothing or ``out`` (the folder it writes into) and ``draw`` the numbers; the only code run at import is
    definitions, the solving guarded by ``if __name__ == "__main__":`` (so the tests import it to call
    ``main``); and every name it imports from pocket exists (a name pocket no longer has fails here)."""
    tree = ast.parse((EXAMPLES / f"{name}.py").read_text(encoding="utf-8"))
    lines = ast.get_docstring(tree, clean=True).splitlines()
    assert lines[0].strip(), lines[:4]
    assert lines[1] == "=" * len(lines[0]), lines[:4]
    assert not lines[2], lines[:4]
    assert lines[3], lines[:4]
    assert f"python examples/{name}.py" in " ".join(lines)
    functions = {node.name: node for node in tree.body if isinstance(node, ast.FunctionDef)}
    assert [a.arg for a in functions["main"].args.args] in ([], ["out"])
    assert len(functions["draw"].args.args) == 1
    guarded = [node for node in tree.body if isinstance(node, ast.If) and "__name__" in ast.unparse(node.test)]
    assert [ast.unparse(node.test) for node in guarded] == ["__name__ == '__main__'"]
    assert tree.body[-1] is guarded[0]
    allowed = (ast.Import, ast.ImportFrom, ast.FunctionDef, ast.Assign, ast.Expr, ast.If)
    assert all(isinstance(node, allowed) for node in tree.body)
    for node in tree.body:
        if isinstance(node, ast.ImportFrom) and node.module.split(".")[0] == "pocket":
            module = importlib.import_module(node.module)
            for alias in node.names:
                assert hasattr(module, alias.name) or importlib.util.find_spec(f"{node.module}.{alias.name}"), \
                    (node.module, alias.name)


@pytest.mark.slow  # the slow lane (pytest -m slow): the example solves for seconds
def test_paper_pocket_fe_matches_shooting_and_the_plate_reaction_is_p_times_area(capsys):
    """Exact answers: the finite elements' H/H0 and P/P_I at each force are the shooting solver's to within
    1e-6 (P2 on 64 elements of the default mesh family is within 1.5e-7 of shooting on every validation case,
    the bound measured in pocket.fem.api's docstring), and the plate's reaction summed from the FE's nodal
    contact forces equals P A_c (F = P A_c on a flat contact zone) to 1e-9 (Newton's tolerance is 1e-10)."""
    states = example("plot_01_paper_pocket").main()
    reference = {s.force: s for s in states["shooting"]}
    assert len(states["fem"]) >= 3
    for f in states["fem"]:
        s = reference[f.force]
        for key in ("height_ratio", "pressure_ratio"):
            assert abs(getattr(f, key) / getattr(s, key) - 1) < 1e-6, (f.force, key)
        pressure_area = f.pressure * f.contact_area / f.pressure_initial
        assert abs(f.extra["force_reaction"] / pressure_area - 1) < 1e-9, f.force
    assert "reaction / (P A_c) - 1" in capsys.readouterr().out


@pytest.mark.slow  # the slow lane (pytest -m slow): the example designs for seconds
def test_soft_button_reaches_its_target_under_the_plate_and_the_fingertip(capsys):
    """Exact answers: each design's dimensionless answer (Phat_I, Fhat, as printed: their repr), solved afresh
    by shooting, gives the inflated height H0/R = 10/20 and H/H0 = 0.8 under its finger (the plate; the 8 mm
    sphere, K = 0.4) to 1e-8 (the design's root finding is to 1e-13 on solver values good to 1e-10); its
    P_I is F / (pi R^2 Fhat) and its T = P_I R / (E Phat_I) (the definitions of Fhat and Phat)."""
    button = example("plot_02_soft_button")
    designs = button.main()
    out = capsys.readouterr().out
    assert list(designs) == list(button.FINGERS)
    for finger, design in designs.items():
        assert f"Phat_I = {design.pressure_initial!r}, Fhat = {design.force!r}" in out
        indenter = None if button.FINGERS[finger] is None else Sphere(button.FINGERTIP / button.RADIUS)
        state = shooting.compress(button.ALPHA, design.pressure_initial, design.force, indenter=indenter)
        assert state.inflated.height == pytest.approx(button.HEIGHT / button.RADIUS, abs=1e-8)
        assert state.height_ratio == pytest.approx(button.HEIGHT_RATIO, abs=1e-8)
        # the definitions: only the rounding of the products differs
        assert design.pressure_initial_Pa == pytest.approx(
            button.FORCE / (math.pi * button.RADIUS**2 * design.force), rel=1e-12)
        assert design.thickness_m == pytest.approx(
            design.pressure_initial_Pa * button.RADIUS / (button.MODULUS * design.pressure_initial), rel=1e-12)


@pytest.mark.slow  # the slow lane (pytest -m slow): the example solves for seconds
def test_air_sensor_reciprocity_meets_the_curve_and_a_reading_reads_back():
    """Exact answers: the sensitivity at rest by reciprocity (from inflations alone) equals the calibration's
    dP/dF at F = 0 (a one-sided difference of the compression curve, step 1e-6 Fhat: round-off ~1e-11 / 1e-6
    relative) to 1e-4; the force read at 6 kPa, pressed afresh by shooting with the same air and fingertip,
    gives 6 kPa back to 1e-8; and the same pocket filled with a liquid is more sensitive at rest (the air adds
    its compliance V / (gamma (P + P_atm)) to the denominator of the reciprocity)."""
    from pocket.apps.cases import parse
    from pocket.apps.physical import resolve
    from pocket.apps.sense import sensitivity_at_rest

    sensor = example("plot_03_fingertip_sensor")
    got = sensor.main()
    assert got["at_rest"] == pytest.approx(got["calibration"][0].sensitivity_kPa_per_N, rel=1e-4)
    pocket = resolve(parse(sensor.CASE))
    state = shooting.compress(pocket.material, pocket.pressure_initial, got["reading"].force, **pocket.options())
    assert state.pressure_ratio * pocket.pressure_initial_Pa == pytest.approx(6e3, rel=1e-8)
    liquid = resolve(parse({k: v for k, v in sensor.CASE.items() if k != "fluid"}))
    assert sensitivity_at_rest(liquid) > got["at_rest"]


@pytest.mark.slow  # the slow lane (pytest -m slow): the example solves for a second or more
def test_profile_indenter_force_balances_the_contact_cap(tmp_path):
    """Exact answers: on every state, under the table's paraboloid and under the sphere, the force equals the
    contact cap's equilibrium, P pi rho_c^2 + 2 pi rho_c T_1 sin(theta_c), computed from the state's profile
    and the indenter's slope at the contact edge, to 1e-8 (the solver's tolerance is 1e-10); the table read
    back is the paraboloid written, exactly at its rows up to the 6 digits written."""
    profile = example("plot_04_profile_indenter")
    states = profile.main(tmp_path)
    for curve in states.values():
        assert len(curve) == len(profile.FORCES)
        for state in curve:
            assert profile.free_body_force(state) == pytest.approx(state.force, rel=1e-8)
    tip = states["profile"][0].indenter
    rho = np.linspace(0.0, profile.REACH, profile.ROWS) / profile.RADIUS
    paraboloid = rho**2 * profile.RADIUS / (2 * profile.TIP)
    assert np.allclose(tip.height(rho), paraboloid, rtol=1e-5, atol=1e-9)


@pytest.mark.slow  # the slow lane (pytest -m slow): the example solves for seconds
def test_five_rubbers_agree_at_small_strain_and_part_at_large():
    """Exact answers: scaled to one mu_0 the five laws are one material at small strain, so at Phat = 1e-4
    their inflated heights differ by less than the pole strain lambda_0 - 1 (their energies differ at higher
    order in the strain); at V = 3 R^3 their pressures spread by more than 10 %; the neo-Hookean sheet's
    pressure has a maximum inside the volumes inflated (Phat(V) rises, then falls)."""
    got = example("plot_05_rubbers").main()
    assert len(got) == 5
    heights = [states["small"].height for states in got.values()]
    strain = got["neo-hookean"]["small"].stretch_pole - 1
    assert np.ptp(heights) / np.mean(heights) < strain
    large = [states["inflation"][-1].pressure for states in got.values()]
    assert np.ptp(large) / np.mean(large) > 0.1
    neo = [s.pressure for s in got["neo-hookean"]["inflation"]]
    peak = int(np.argmax(neo))
    assert 0 < peak < len(neo) - 1


@pytest.mark.slow  # the slow lane (pytest -m slow): the example solves for a second or more
def test_gas_keeps_its_law_the_liquid_its_volume_and_air_is_softer():
    """Exact answers: along each gas curve (P + P_atm) V^gamma stays at its value at rest, and along the
    liquid's V stays V_I, to 1e-9 (the solver closes the volume at 1e-10); at every force the air-filled
    pocket is pressed lower than the liquid one, the isothermal air (gamma = 1, more compressible) lower
    than the adiabatic."""
    got = example("plot_06_gas_and_liquid").main()
    for name, states in got.items():
        fluid = states[0].fluid
        gamma, ambient = (fluid.gamma, fluid.ambient) if fluid.is_gas else (1.0, 0.0)
        held = [(s.pressure + ambient) * s.volume**gamma if fluid.is_gas else s.volume for s in states]
        assert max(abs(h / held[0] - 1) for h in held) < 1e-9, name
    liquid, isothermal, adiabatic = got.values()
    for a, b, c in zip(liquid[1:], isothermal[1:], adiabatic[1:], strict=True):
        assert b.height_ratio < c.height_ratio < a.height_ratio, a.force


@pytest.mark.slow  # the slow lane (pytest -m slow): the example fits for seconds
def test_bulge_fit_recovers_the_rubber_and_presses_the_fitted_sheet(tmp_path):
    """Exact answer: the rubber behind the example's made-up bulge test. Each fitted parameter lies within four
    of its standard errors of the truth (the heights carry 0.2 % seeded noise: the fit's own error bars say how
    far it may land; beyond four of them the chance is 6e-5 per parameter for honest errors), the figure and the
    fitted sheet's case file are written, and the pressed sheet's pressures are those of that case file solved
    afresh by the shooting solver."""
    from pocket.apps.cases import load

    bulge = example("plot_07_bulge_fit")
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


@pytest.mark.slow  # the slow lane (pytest -m slow): the example fits for seconds
def test_pressed_fit_recovers_mu0_and_says_c1_c2_are_not_separable(tmp_path):
    """Exact answers: the rubber behind the made-up compression test. C1, C2 and mu_0 = 2 (C1 + C2) each lie
    within four of their standard errors of the truth (0.2 % seeded noise; as for the bulge fit), and the
    fit reports what a compression test cannot tell: |correlation(C1, C2)| > 0.99, its own warning's
    threshold, with mu_0 known far better than either (its relative error below a tenth of C1's)."""
    pressed = example("plot_08_pressed_fit")
    s = pressed.main(tmp_path)["fit"].statistics
    for name, fitted, error in zip(s.names, s.values, s.standard_errors, strict=True):
        assert abs(fitted - pressed.TRUTH[name]) < 4.0 * error, (name, fitted, error)
    assert abs(s.mu0 - 2 * sum(pressed.TRUTH.values())) < 4.0 * s.mu0_error
    assert abs(s.correlation[0, 1]) > 0.99
    assert any("correlated" in w for w in s.warnings)
    assert s.mu0_error / s.mu0 < 0.1 * s.standard_errors[0] / s.values[0]


@pytest.mark.slow  # the slow lane (pytest -m slow): the example solves the solid for seconds
@pytest.mark.slow  # the slow lane: the fit solves the capsule some fifteen times
def test_capsule_fit_recovers_the_wall_and_its_curve_is_the_solvers(tmp_path):
    """Exact answers: the wall behind the made-up squeeze test. E T = 3 mu T lies within four standard errors of
    the truth (0.05 um seeded noise on gaps of about 100 um), and inside the fit's 95 % interval; the figure's
    curve is the solver's: F / (E T R) = pi Fhat Phat_I at each state, and every state balances F = P A_c."""
    capsule = example("plot_13_capsule_fit")
    numbers = capsule.main(tmp_path)
    s = numbers["fit"].statistics
    assert abs(3 * s.values[0] - capsule.ET) < 4.0 * 3 * s.standard_errors[0]
    assert s.intervals[0][0] < capsule.ET / 3 < s.intervals[0][1]
    states, lam = capsule.curve(capsule.ET, capsule.FORCES)
    phat = capsule.PRESSURE * capsule.RADIUS / capsule.ET
    for force, state in zip(capsule.FORCES, states, strict=True):
        assert state.extra["force_ETR"] == pytest.approx(force / (capsule.ET * capsule.RADIUS), rel=1e-12, abs=0)
        assert state.pressure_ratio * state.contact_area == pytest.approx(state.force, rel=1e-10, abs=1e-300)
    assert lam == pytest.approx(shooting.inflate(capsule.NEO, phat, geometry="capsule").stretch_pole, rel=1e-15)


@pytest.mark.slow  # the slow lane: some forty capsule states
def test_uninflated_capsule_curves_start_and_end_where_the_solvers_say(capsys):
    """Exact answers: the uninflated curve starts at the start the shooting solver quoted (its first state solved
    there, to the shots' tolerance); each finite-element marker at a height is the shooting solver's state there
    (within 1e-6 in F / (E T R): the default mesh's error away from the start, ``tests/test_capsule_uninflated_
    solvers.py``), the one under a force reports it; and the slightly inflated capsule's first branch lies wholly
    above its deep branch, both refusals printed."""
    capsule = example("plot_14_uninflated_capsule")
    numbers = capsule.main()
    assert numbers["uninflated"][0].height == pytest.approx(numbers["start"], abs=1e-9)
    for marker in numbers["markers"][:3]:
        shot = shooting.compress_height(capsule.NEO, 0.0, marker.height, geometry="capsule")
        assert marker.extra["force_ETR"] == pytest.approx(shot.extra["force_ETR"], rel=1e-6)
    assert numbers["markers"][3].extra["force_ETR"] == 1.0
    assert min(s.height for s in numbers["first"]) > max(s.height for s in numbers["second"])
    printed = capsys.readouterr().out
    assert "outside the capsule's range" in printed
    assert "lies between the capsule's two branches" in printed


def test_membrane_against_solid_prints_both_models_and_the_error_falls_at_first_order():
    """Exact answers: the membrane's column is the shooting solver's states solved afresh (the pressure at each
    force, in kPa). Physics that could fail: at T/R = 0.08 the membrane's fluid volume is off by more than 1 %
    (about 3 T/R here, as the validation report's table shows), its pressure rise by less at every force; and
    over T/R = 0.01 to 0.08 the inflated volume's error falls at first order in T/R, the solid tending to the
    membrane (observed order within 0.1 of 1: second-order terms shift a fitted slope by O(T/R) <= 0.08)."""
    from pocket.apps.cases import sample

    membrane_error = example("plot_09_membrane_vs_solid")
    got = membrane_error.main()
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
    ratios = list(got["sweep"])
    errors = [m / s - 1 for m, s in got["sweep"].values()]
    assert abs(np.polyfit(np.log(ratios), np.log(errors), 1)[0] - 1.0) < 0.1, errors


@pytest.mark.slow  # the slow lane (pytest -m slow): the example starts processes and a dask cluster
def test_sweep_on_processes_and_on_dask_agree_with_a_fresh_solve(tmp_path):
    """Exact answers: the local processes and the dask cluster write the same rows, every point of the grid
    once with status ok; each row's P/P_I and H/H0 are those of shooting.compress solved afresh at that point
    to 1e-8 (the sweep's continuation and a fresh inflation each resolve the state to 1e-10)."""
    sweep = example("plot_10_sweep")
    rows = sweep.main(tmp_path)
    assert rows["local"] == rows["dask"]
    grid = {(a, p, f) for a in sweep.ALPHAS for p in sweep.PRESSURES for f in sweep.FORCES}
    assert {(r["alpha"], r["pressure_initial"], r["force"]) for r in rows["dask"]} == grid
    assert len(rows["dask"]) == len(grid)
    for row in rows["dask"]:
        assert row["status"] == "ok"
        state = shooting.compress(row["alpha"], row["pressure_initial"], row["force"])
        for key in ("pressure_ratio", "height_ratio"):
            assert row[key] == pytest.approx(getattr(state, key), rel=1e-8), (row, key)


@pytest.mark.slow  # the slow lane (pytest -m slow): the example writes and reads a VTK series
def test_paraview_series_has_every_step_and_reads_back_each_state(tmp_path):
    """Exact answers: the series has the fingertip's surface in every step beside the sheet's (STEPS files
    listed in each .pvd), and the force and pressure read back by pyvista from each surface file's field data
    are the solved state's, exactly (written with 17 significant digits)."""
    series = example("plot_11_paraview_series")
    got = series.main(tmp_path)
    vtk = got["vtk"]
    assert vtk == tmp_path / "vtk"
    steps = [len(re.findall(r'file="', (vtk / f"{part}.pvd").read_text())) for part in ("surface", "indenter")]
    assert steps[0] == steps[1] == len(list(vtk.glob("step_*_indenter.vtu"))) == series.STEPS
    assert got["read"]["force"] == [s.force for s in got["states"]]
    assert got["read"]["pressure"] == [s.pressure for s in got["states"]]


@pytest.mark.slow  # the slow lane (pytest -m slow): the example solves on many meshes
def test_mesh_convergence_orders_are_the_elements():
    """Exact answers: the observed orders of the FE's pressure and height errors against shooting are 2 p
    for P1 and P2 (smooth functionals of Lagrange elements on edge-fitted meshes) to within 0.5 (the coarsest
    meshes lie before the asymptotic range), and the finest P2 error is below 1e-7 (the default family's
    64-element bound, 1.5e-7, measured over every validation case)."""
    got = example("plot_12_mesh_convergence").main()
    for order, result in got.items():
        for key, observed in result["orders"].items():
            assert abs(observed - 2 * order) < 0.5, (order, key, observed)
    assert max(got[2]["pressure"][-1], got[2]["height"][-1]) < 1e-7


@pytest.mark.slow  # the slow lane (pytest -m slow): the example runs in a new process for seconds
def test_an_example_runs_as_a_script(tmp_path):
    """Exact answer: ``python examples/plot_11_paraview_series.py FOLDER``, as a user runs it (no display),
    ends with status 0, prints nothing on stderr, and writes its VTK series into FOLDER/vtk, the files its
    last line names (the numbers are the in-process test's)."""
    script = EXAMPLES / "plot_11_paraview_series.py"
    env = {k: v for k, v in os.environ.items() if k != "DISPLAY"} | {"MPLBACKEND": "Agg"}
    run = subprocess.run([sys.executable, str(script), str(tmp_path / "out")], capture_output=True, text=True,
                         timeout=600, check=False, env=env)
    assert run.returncode == 0, run.stderr
    assert not run.stderr, run.stderr
    assert run.stdout.splitlines()[-1].endswith("vtk/surface.pvd, vtk/indenter.pvd"), run.stdout
    series = [tmp_path / "out" / "vtk" / f"{part}.pvd" for part in ("surface", "indenter")]
    assert all(path.stat().st_size > 0 for path in series)
