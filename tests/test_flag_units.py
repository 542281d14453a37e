"""One way to say a quantity on the command line: commands that know R and E (design, sense) take a unit on
every dimensional option and warn on a plain number (read as SI); commands in the model's units (inflate,
compress, sweep) refuse a value with a unit, naming the unit they want; each option's help names its unit."""

import json
import math

import numpy as np
import pytest

from pocket import shooting
from pocket.apps import design as design_module
from pocket.apps.design import design
from pocket.cli import main
from pocket.cli.common import MODEL_UNITS, PHYSICAL_UNITS
from pocket.core.fluids import gas
from pocket.core.units import plain_warnings

# the paper's section 6 button (as tests/test_design.py), SI
R, H0, E, ALPHA, F, RATIO = 0.02, 0.010, 1e6, 0.3, 0.67, 0.8
BUTTON = ["design", "--radius", "20 mm", "--height", "10 mm", "--force", "0.67 N", "--json"]


def _no_solving(*args, **kwargs):
    raise AssertionError("a solve started before the bad input was refused")


def _one_line(capsys) -> str:
    out, err = capsys.readouterr()
    assert out == "", err
    assert err.count("\n") == 1, err
    assert "Traceback" not in err, err
    return err


def test_compress_indenter_radius_with_unit_refused_naming_ratio(capsys):
    """``pocket compress --indenter-radius '8 mm'``: compress knows no R to divide 8 mm by, so the value is
    refused (exit 2, one line) saying it wants R_s/R, a number, and which command takes physical values."""
    argv = ["compress", "--alpha", "0.3", "--pressure", "0.3", "--force", "0.2", "--indenter", "sphere"]
    assert main([*argv, "--indenter-radius", "8 mm"]) == 2
    err = _one_line(capsys)
    assert "--indenter-radius: '8 mm' has a unit, but pocket compress works in the model's units: give R_s/R " \
           "(a number); pocket run takes physical values in a case file" in err


@pytest.mark.parametrize(("argv", "option", "value", "unit"), [
    (["inflate", "--alpha", "0.3"], "--pressure", "3 kPa", "Phat = P R / (E T)"),
    (["inflate", "--alpha", "0.3"], "--volume", "2 mL", "V/R^3"),
    (["compress", "--alpha", "0.3", "--force", "0.2"], "--pressure", "3 kPa", "Phat_I = P_I R / (E T)"),
    (["compress", "--alpha", "0.3", "--pressure", "0.3"], "--force", "0.5 N", "Fhat = F / (P_I pi R^2)"),
    (["compress", "--alpha", "0.3", "--pressure", "0.3"], "--height", "5 mm", "H/R"),
    (["compress", "--alpha", "0.3", "--pressure", "0.3", "--force", "0.2", "--fluid", "gas"], "--ambient",
     "101.325 kPa", "Phat_atm = P_atm R / (E T)"),
    (["compress", "--law", "neo-hookean", "--pressure", "0.3", "--force", "0.2"], "--mu", "20 kPa",
     "a stress in any one unit shared by the law's stresses"),
    (["sweep", "--alpha", "0.3", "--force", "0.2", "--out", "s.csv"], "--pressure", "3 kPa",
     "Phat_I = P_I R / (E T)"),
    (["sweep", "--alpha", "0.3", "--pressure", "0.3", "--force", "0.2", "--out", "s.csv", "--indenter", "sphere"],
     "--indenter-radius", "8 mm", "R_s/R"),
])
def test_model_unit_commands_refuse_every_value_with_a_unit(argv, option, value, unit, capsys, tmp_path,
                                                            monkeypatch):
    """Each dimensional option of inflate, compress and sweep refuses a value with a unit the same way: exit 2,
    one line naming the option, the command and the unit it wants; nothing written."""
    monkeypatch.chdir(tmp_path)
    assert main([*argv, option, value]) == 2
    err = _one_line(capsys)
    assert f"argument {option}: '{value}' has a unit, but pocket {argv[0]} works in the model's units: give " \
           f"{unit}" in err, err
    assert list(tmp_path.iterdir()) == []


def test_dimensionless_option_with_a_unit_says_it_is_a_number(capsys):
    """``--height-ratio '8 mm'`` in design: H/H0 has no unit in any command, so the line says the option is a
    plain number (not that '8 mm' is no number)."""
    assert main([*BUTTON, "--alpha", "0.3", "--modulus", "1 MPa", "--height-ratio", "8 mm"]) == 2
    assert "argument --height-ratio: '8 mm' has a unit, but this option is a plain number" in _one_line(capsys)


@pytest.fixture(scope="module")
def button():
    """The section 6 button, designed from H0 (the forward design)."""
    return design("20 mm", "10 mm", "1 MPa", ALPHA, "0.67 N", RATIO)


def test_design_plain_ambient_warns(capsys):
    """``--ambient 101325`` is read as 101325 Pa, and a warning naming --ambient says so (the line of
    ``plain_warnings``); the design is the one of '101.325 kPa' exactly (the same SI value), which draws no
    warning."""
    argv = [*BUTTON, "--alpha", "0.3", "--modulus", "1 MPa", "--fluid", "gas", "--ambient"]
    assert main([*argv, "101325"]) == 0
    plain, err = capsys.readouterr()
    assert err.splitlines() == [f"pocket: warning: {plain_warnings('--ambient', '101325', 'pressure')[0]}"]
    assert "--ambient = '101325' has no unit and is read as 101325 Pa" in err
    assert main([*argv, "101.325 kPa"]) == 0
    written, err = capsys.readouterr()
    assert err == ""
    plain, written = json.loads(plain), json.loads(written)
    assert plain["ambient_Pa"] == written["ambient_Pa"] == 101325.0
    assert plain["pressure_initial_Pa"] == written["pressure_initial_Pa"]
    assert plain["warnings"] == plain_warnings("--ambient", "101325", "pressure")


def test_sense_plain_pressure_warns(capsys):
    """``pocket sense --pressure 5000``: 5000 Pa, with the warning naming --pressure; the reading is that of
    '5 kPa' (sample 2, P_I = 4812.75 Pa)."""
    argv = ["sense", "--sample", "2", "--json", "--pressure"]
    assert main([*argv, "5000"]) == 0
    plain, err = capsys.readouterr()
    assert err.splitlines() == [f"pocket: warning: {plain_warnings('--pressure', '5000', 'pressure')[0]}"]
    assert main([*argv, "5 kPa"]) == 0
    written, err = capsys.readouterr()
    assert err == ""
    assert json.loads(plain) == json.loads(written)


@pytest.mark.slow
def test_design_mu_with_unit_taken(button, capsys):
    """``--law neo-hookean --mu '200 kPa'``: the stress is taken with its unit and sets E = 3 mu = 600 kPa. A
    neo-Hookean rubber is Mooney-Rivlin with alpha = 0, so the design is the library's for alpha = 0 and
    E = 600 kPa (the solver resolves ~1e-10; 1e-9). A plain ``--mu 200000`` is the same 200 kPa, with a
    warning."""
    reference = design("20 mm", "10 mm", "600 kPa", 0.0, "0.67 N", RATIO)
    for value in ("200 kPa", "200000"):
        assert main([*BUTTON, "--law", "neo-hookean", "--mu", value]) == 0
        out, err = capsys.readouterr()
        assert err.splitlines() == [f"pocket: warning: {w}" for w in plain_warnings("--mu", value, "pressure")]
        out = json.loads(out)
        assert out["material"] == "neo-hookean"
        assert out["mu"] == 1.0
        assert out["pressure_initial_Pa"] == pytest.approx(reference.pressure_initial_Pa, rel=1e-9)
        assert out["thickness_m"] == pytest.approx(reference.thickness_m, rel=1e-9)


def test_design_stress_beside_modulus_not_ignored(capsys, monkeypatch):
    """``--law neo-hookean --mu '20 kPa' --modulus '1 MPa'``: the stress sets E = 60 kPa, which --modulus
    contradicts; before, the stress's magnitude was silently dropped. Now refused (exit 2, one line naming
    both flags and the E of the stresses), before any solve."""
    monkeypatch.setattr(design_module, "pressure_for_height", _no_solving)
    assert main([*BUTTON, "--law", "neo-hookean", "--mu", "20 kPa", "--modulus", "1 MPa"]) == 2
    err = _one_line(capsys)
    assert "--modulus = '1 MPa' is given beside the neo-hookean law's stresses (--mu), which set E = 3 mu_0 " \
           "(here 60000 Pa) themselves" in err, err


def test_design_mooney_rivlin_without_modulus_refused(capsys, monkeypatch):
    """--alpha gives only C2/C1: without --modulus the sheet's E is unknown, refused in one line."""
    monkeypatch.setattr(design_module, "pressure_for_height", _no_solving)
    assert main([*BUTTON, "--alpha", "0.3"]) == 2
    assert "--modulus is missing: a Mooney-Rivlin rubber given by alpha = C2/C1 needs the modulus E" in \
        _one_line(capsys)


def _option_help(text: str, option: str) -> str:
    """The help of ``option`` in a command's formatted ``--help`` ``text``, its lines joined."""
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.lstrip().startswith(f"{option} ")
                 or line.strip() == option)
    block = [lines[start]]
    for line in lines[start + 1:]:
        if not line.strip() or line.lstrip().startswith("-"):
            break
        block.append(line)
    return " ".join(" ".join(block).split())


MODEL = {
    "inflate": {"--pressure": "Phat = P R / (E T)", "--volume": "V/R^3"},
    "compress": {"--pressure": "Phat_I = P_I R / (E T)", "--force": "Fhat = F / (P_I pi R^2)", "--height": "H/R",
                 "--ambient": "Phat_atm = P_atm R / (E T)", "--indenter-radius": "K = R_s/R (a number)",
                 "--mu": "a stress in any one unit", "--c10": "a stress in any one unit"},
    "sweep": {"--pressure": "Phat_I = P_I R / (E T)", "--force": "Fhat = F / (P_I pi R^2)",
              "--ambient": "Phat_atm = P_atm R / (E T)", "--indenter-radius": "K = R_s/R (a number)",
              "--mu": "a stress in any one unit"},
}
PHYSICAL = {
    "design": {"--radius": "a length, e.g. '20 mm' (plain: m, with a warning)",
               "--height": "a length, e.g. '10 mm' (plain: m, with a warning)",
               "--thickness": "a length, e.g. '0.5 mm' (plain: m, with a warning)",
               "--pressed-height": "a length, e.g. '8 mm' (plain: m, with a warning)",
               "--modulus": "a pressure, e.g. '1 MPa' (plain: Pa, with a warning)",
               "--force": "a force, e.g. '0.67 N' (plain: N, with a warning)",
               "--ambient": "a pressure, e.g. '101.325 kPa' (plain: Pa, with a warning)",
               "--indenter-radius": "a length, e.g. '8 mm' (plain: m, with a warning)",
               "--mu": "a stress, e.g. '20 kPa' (plain: Pa, with a warning)",
               "--c10": "a stress, e.g. '20 kPa' (plain: Pa, with a warning)",
               "--height-ratio": "H/H0 at F, a number", "--jm": "a number"},
    "sense": {"--pressure": "a pressure, e.g. '5.2 kPa' (plain: Pa, with a warning)",
              "--max-force": "a force, e.g. '2 N' (plain: N, with a warning)",
              "--range": "a force, e.g. '2 N' (plain: N, with a warning)", "--ratio": "P/P_I, a number"},
}


@pytest.mark.parametrize("command", [*MODEL, *PHYSICAL])
def test_help_names_each_options_unit(command, capsys):
    """Each dimensional option's help names its unit: the model's ratio where the command works in the model's
    units, a kind with an example and what a plain number means where it knows R and E; the command's
    description states its rule (the same sentence in every command of a kind)."""
    assert main([command, "--help"]) == 0
    text = capsys.readouterr().out
    units = {**MODEL, **PHYSICAL}[command]
    for option, unit in units.items():
        assert unit in _option_help(text, option), (option, _option_help(text, option))
    rule = MODEL_UNITS if command in MODEL else PHYSICAL_UNITS
    assert rule in " ".join(text.split())


@pytest.mark.slow
def test_design_given_thickness_gives_pressure_and_height(button, capsys):
    """Round trip: the forward design's T from (R, H0, E, F, H/H0 = 0.8), fed back with --thickness and the same
    H/H0, gives the same P_I and H0; so does the pressed height H = 0.8 H0 = 8 mm as the target, and so does
    the library. The roots are solved to 1e-13 on a solver that resolves ~1e-10, so 1e-6 (test_design's bar)
    is far above what they leave. The answer fed to the forward solver gives H0 and H/H0 = 0.8 at F."""
    thickness = f"{button.thickness_m * 1e3!r} mm"
    for target in (["--height-ratio", "0.8"], ["--pressed-height", "8 mm"]):
        argv = ["design", "--radius", "20 mm", "--thickness", thickness, "--modulus", "1 MPa", "--alpha", "0.3",
                "--force", "0.67 N", *target, "--json"]
        assert main(argv) == 0
        out, err = capsys.readouterr()
        assert err == ""
        out = json.loads(out)
        assert out["solved"] == ["pressure_initial", "height"]
        assert out["pressure_initial_Pa"] == pytest.approx(button.pressure_initial_Pa, rel=1e-6)
        assert out["height_m"] == pytest.approx(H0, rel=1e-6)
        assert out["height_ratio"] == pytest.approx(RATIO, rel=1e-6)
        assert out["thickness_m"] == pytest.approx(button.thickness_m, rel=1e-15)
    p_i = out["pressure_initial_Pa"]
    state = shooting.compress(ALPHA, p_i * R / (E * button.thickness_m), F / (p_i * math.pi * R**2))
    assert state.inflated.height * R == pytest.approx(H0, rel=1e-6)
    assert state.height_ratio == pytest.approx(RATIO, rel=1e-6)


def test_design_given_thickness_and_height_gives_pressure_and_feel(button):
    """Given both T and H0 of the forward design, the pressure is the forward P_I (step 1 alone) and H/H0 at F is
    the 0.8 it was designed for (1e-6, as above); the paper's column is then the forward design's."""
    d = design(R, H0, E, ALPHA, F, thickness=button.thickness_m)
    assert d.solved == ("pressure_initial", "height_ratio")
    assert d.pressure_initial_Pa == pytest.approx(button.pressure_initial_Pa, rel=1e-6)
    assert d.height_ratio == pytest.approx(RATIO, rel=1e-6)
    assert (d.paper_pressure_initial_Pa, d.paper_thickness_m) == (button.paper_pressure_initial_Pa,
                                                                  button.paper_thickness_m)


@pytest.mark.slow
def test_gas_button_given_thickness_round_trip():
    """The adiabatic air-filled button: the forward design's T fed back (T known, so Phat_atm = P_atm R / (E T)
    is known too) gives its P_I and H0 (1e-6, as above)."""
    air = gas(101325.0, 1.4)
    forward = design(R, H0, E, ALPHA, F, RATIO, fluid=air, points=2)
    back = design(R, None, E, ALPHA, F, RATIO, thickness=forward.thickness_m, fluid=air, points=2)
    assert back.pressure_initial_Pa == pytest.approx(forward.pressure_initial_Pa, rel=1e-6)
    assert back.height_m == pytest.approx(H0, rel=1e-6)
    assert back.ambient == pytest.approx(forward.ambient, rel=1e-6)


def test_given_sheet_path_rises_with_pressure(button):
    """The claim behind ``pressure_for_sheet``'s single root: with T and F fixed (Fhat = c / Phat_I), H/H0 and
    the pressed height H/R rise strictly with Phat_I, checked at 12 pressures from 0.6 to 4 times the design's."""
    c = F / (math.pi * R * E * button.thickness_m)
    states = [shooting.compress(ALPHA, p, c / p) for p in button.pressure_initial * (0.6 + 0.3 * np.arange(12))]
    for key in ("height_ratio", "height"):
        values = [getattr(s, key) for s in states]
        assert np.all(np.diff(values) > 0), (key, values)



@pytest.mark.slow
def test_design_given_thickness_target_below_the_sheets_reach_is_one_line(capsys):
    """A 0.15 mm sheet of the section 6 button asked for H/H0 = 0.05 at 0.67 N: along the path of a known sheet,
    H/H0 tends to a limit near 0.5 as the pressure falls (test above, and pressure_for_sheet's docstring),
    so no pressure gives 0.05: exit 2, one line naming the flag and the value, no solver failure."""
    argv = ["design", "--radius", "20 mm", "--thickness", "0.15 mm", "--modulus", "1 MPa", "--alpha", "0.3",
            "--force", "0.67 N", "--height-ratio", "0.05"]
    assert main(argv) == 2
    assert "pocket: error: --height-ratio = 0.05 is not reached on this sheet: it is still 0.5" in _one_line(capsys)
