"""The dimensionless commands with any rubber law and a gas: --law and its parameters, --fluid gas."""

import csv
import json

import pytest

from pocket import shooting
from pocket.apps.sweep.journal import COLUMNS
from pocket.cli import main
from pocket.core.fluids import gas
from pocket.core.materials import check
from pocket.core.states import CompressedState

OGDEN = ["--law", "ogden", "--mu", "630", "1.2", "-10", "--exponents", "1.3", "5", "-2"]


def run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def test_compress_json_is_the_library_state(capsys):
    """Exact answer: the JSON is the shooting solver's state for the Ogden rubber rescaled to mu_0 = 1
    (Material.scaled) in a gas of Phat_atm 6.5 and gamma 1.4, key for key; it reports the law, its
    parameters in units of mu_0, the fluid and the smallest tensions."""
    status, out, err = run(capsys, "compress", *OGDEN, "--pressure", "0.3", "--force", "0.2", "0.5",
                           "--fluid", "gas", "--ambient", "6.5", "--gamma", "1.4", "--json")
    assert status == 0
    assert err == ""
    rows = json.loads(out)
    rubber = check("ogden", {"mu": [630.0, 1.2, -10.0], "exponents": [1.3, 5.0, -2.0]}).scaled()
    states = shooting.compression_curve(rubber, 0.3, [0.2, 0.5], fluid=gas(6.5, 1.4))
    for row, state in zip(rows, states, strict=True):
        assert row == {**state.scalars(), "warnings": []}
        assert "alpha" not in row
        assert row["material"] == "ogden"
        assert row["exponents"] == [1.3, 5.0, -2.0]
        assert (row["fluid"], row["ambient"], row["gamma"]) == ("gas", 6.5, 1.4)
        assert row["wrinkled"] is False
    mu0 = 0.5 * sum(m * a for m, a in zip(rows[0]["mu"], rows[0]["exponents"], strict=True))
    assert mu0 == pytest.approx(1.0, rel=1e-15)  # the unit of the parameters is mu_0


def test_parameters_in_any_unit_are_rescaled(capsys):
    """Exact: Yeoh's (85, 2, 0.1) in kPa and the same rubber in units of mu_0 = 2 C10 (0.5, 2/170,
    1/1700) are one rubber: the same states, to rounding, and the same reported parameters."""
    outs = []
    for params in (("85", "2", "0.1"), ("0.5", "2/170", "1/1700")):
        argv = ["compress", "--law", "yeoh", "--c10", params[0], "--c20", params[1], "--c30", params[2],
                "--pressure", "0.3", "--force", "0.4", "--json"]
        status, out, _ = run(capsys, *argv)
        assert status == 0
        outs.append(json.loads(out))
    for key, value in outs[1].items():
        assert outs[0][key] == (pytest.approx(value, rel=1e-13) if isinstance(value, float) else value), key
    assert outs[0]["c10"] == 0.5
    assert outs[0]["c20"] == 2 / 170


def test_neo_hookean_is_mooney_rivlin_with_alpha_0(capsys):
    """Exact: --law neo-hookean --mu 1 (a Material) and --alpha 0 (the float path) are one energy, so one
    state (the solver resolves ~1e-10)."""
    rows = []
    for rubber in (["--law", "neo-hookean", "--mu", "1"], ["--alpha", "0"]):
        status, out, _ = run(capsys, "compress", *rubber, "--pressure", "0.3", "--force", "1", "--json")
        assert status == 0
        rows.append(json.loads(out))
    for key in ("pressure", "contact_area", "contact_radius", "height", "volume", "tension_1_min"):
        assert rows[0][key] == pytest.approx(rows[1][key], rel=1e-9), key


def test_inflate_with_a_law(capsys):
    """Exact answer: the table's rows are the library's inflated state for Gent (mu 1, Jm 3)."""
    status, out, _ = run(capsys, "inflate", "--law", "gent", "--mu", "1", "--jm", "3", "--pressure", "0.3", "--json")
    assert status == 0
    assert json.loads(out) == {**shooting.inflate(check("gent", {"mu": 1.0, "jm": 3.0}), 0.3).scalars(),
                               "warnings": []}


@pytest.mark.parametrize(("argv", "message"), [
    (["compress", "--law", "neo-hookean", "--mu", "1", "--c10", "1"], "--c10 is not a parameter of the neo-hookean "
                                                                      "law (its parameters: --mu)"),
    (["compress", "--mu", "1"], "--mu is not a parameter of the mooney-rivlin law (it takes --alpha"),
    (["compress", "--law", "yeoh", "--alpha", "0.3", "--c10", "1", "--c20", "0", "--c30", "0"],
     "--alpha is not a parameter of the yeoh law (its parameters: --c10, --c20, --c30)"),
    (["compress"], "--alpha is missing: the mooney-rivlin law (the default --law) needs it"),
    (["compress", "--law", "yeoh", "--c10", "1", "--c20", "0"], "--c30 is missing: the yeoh law needs --c10, --c20, "
                                                                 "--c30"),
    (["compress", "--law", "gent", "--mu", "1", "2", "--jm", "3"], "--mu takes one value for the gent law, got 2"),
    (["compress", "--law", "gent", "--mu", "1", "--jm", "0"], "--jm = 0.0, but the locking parameter Jm must be > 0"),
    (["compress", "--law", "ogden", "--mu", "1", "2", "--exponents", "2"], "--mu has 2 terms but --exponents has 1"),
    (["compress", "--law", "ogden", "--mu", "1", "--exponents", "-2"], "a stable Ogden term needs mu_p alpha_p > 0"),
    (["compress", "--law", "yeoh", "--c10", "1", "--c20", "-1", "--c30", "0.1"], "a stable Yeoh rubber needs"),
    (["compress", "--law", "yoeh"], "argument --law: invalid choice: 'yoeh'"),
    (["compress", "--alpha", "0.3", "--ambient", "6"], "--ambient applies to a gas: give --fluid gas"),
    (["compress", "--alpha", "0.3", "--gamma", "1.4"], "--gamma applies to a gas: give --fluid gas"),
    (["compress", "--alpha", "0.3", "--fluid", "gas"], "--fluid gas needs --ambient PHAT_ATM"),
    (["compress", "--alpha", "0.3", "--fluid", "gas", "--ambient", "0"], "--ambient = 0.0, but it must be > 0"),
    (["compress", "--alpha", "0.3", "--fluid", "gas", "--ambient", "-6"], "--ambient = -6.0, but it must be > 0"),
    (["compress", "--alpha", "0.3", "--fluid", "gas", "--ambient", "6", "--gamma", "0.9"],
     "--gamma = 0.9, but it must lie in [1, 5/3]"),
    (["compress", "--alpha", "0.3", "--fluid", "gas", "--ambient", "6", "--gamma", "1.7"],
     "--gamma = 1.7, but it must lie in [1, 5/3]"),
    (["compress", "--alpha", "0.3", "--fluid", "water"], "argument --fluid: invalid choice: 'water'"),
    (["inflate", "--alpha", "0.3", "--fluid", "gas"], "unrecognized arguments: --fluid gas"),
])
def test_bad_law_or_fluid_flags(argv, message, capsys, tmp_path):
    """Each: exit 2, one line naming the flag, nothing written (the --vtk folder never appears), before
    any solve."""
    status, out, err = run(capsys, *argv, "--pressure", "0.3", *(["--force", "0.2"] if argv[0] == "compress" else []),
                           "--vtk", str(tmp_path / "vtk"))
    assert status == 2, err
    assert out == "", err
    assert err.count("\n") == 1, err
    assert message in err, err
    assert "Traceback" not in err, err
    assert not (tmp_path / "vtk").exists()


def test_sweep_with_a_law_and_a_gas(tmp_path, capsys):
    """Exact: an Ogden sweep in a gas writes the library's states at its grid points (repr floats), with
    the rubber's parameters (units of mu_0) and the gas in their columns and alpha empty; a
    Mooney-Rivlin sweep then shares the file, and rerunning either computes nothing."""
    path = tmp_path / "s.csv"
    gas_flags = ["--fluid", "gas", "--ambient", "6.5", "--gamma", "1.4"]
    ogden = ["sweep", *OGDEN, "--pressure", "0.1", "0.3", "--force", "0", "0.5", *gas_flags, "--out", str(path),
             "--workers", "1"]
    assert main(ogden) == 0
    rows = list(csv.DictReader(path.open()))
    assert tuple(rows[0]) == COLUMNS
    assert len(rows) == 4
    rubber = check("ogden", {"mu": [630.0, 1.2, -10.0], "exponents": [1.3, 5.0, -2.0]}).scaled()
    for row in rows:
        state = shooting.compress(rubber, float(row["pressure_initial"]), float(row["force"]), fluid=gas(6.5, 1.4))
        assert float(row["pressure_ratio"]) == state.pressure_ratio
        assert float(row["height"]) == state.height
        assert float(row["tension_2_min"]) == state.tension_2_min
        assert row["wrinkled"] == "False"
        assert (row["alpha"], row["material"], row["exponents"]) == ("", "ogden", "1.3 5.0 -2.0")
        assert [float(x) for x in row["mu_per_mu0"].split()] == list(rubber["mu"])
        assert (row["fluid"], row["ambient"], row["gamma"], row["c1_per_mu0"]) == ("gas", "6.5", "1.4", "")
    mooney = ["sweep", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.5", "--out", str(path), "--workers", "1"]
    assert main(mooney) == 0
    rows = list(csv.DictReader(path.open()))
    assert len(rows) == 5
    assert rows[0]["material"] == "mooney-rivlin"
    assert rows[0]["fluid"] == "liquid"
    capsys.readouterr()
    for argv in (ogden, mooney):
        assert main(argv) == 0
        assert "0 points computed" in capsys.readouterr().out


def test_sweep_refuses_an_earlier_file(tmp_path, capsys):
    """A sweep file written before the rubber and fluid columns: refused untouched, saying why."""
    path = tmp_path / "old.csv"
    old = ",".join((*CompressedState.KEYS, "solver", "status", "message")) + "\n"
    path.write_text(old)
    assert main(["sweep", "--alpha", "0.3", "--pressure", "0.1", "--force", "0.5", "--out", str(path)]) == 2
    assert "is a sweep file of an earlier pocket (0 points), whose rows do not record the solver's options, the " \
           "rubber and the fluid" in capsys.readouterr().err
    assert path.read_text() == old


def test_help_says_how_parameters_are_scaled(capsys):
    """The help of every command with a rubber says the parameters are rescaled to units of mu_0."""
    for name in ("inflate", "compress", "sweep", "design"):
        assert main([name, "--help"]) == 0
        text = " ".join(capsys.readouterr().out.split())
        assert "rescaled to units of mu_0" in text
        assert "--law" in text
        assert "mooney-rivlin" in text


def test_a_compressive_tension_reaches_the_user(capsys, monkeypatch):
    """A state with a compressive tension (patched in: no case tried gives one) is printed with exit 0, one
    'pocket: warning: compressive tension' line on stderr, and wrinkled: true in the JSON with its warning."""
    import dataclasses

    real = shooting.compression_curve

    def slack(*args, **kwargs):
        return [dataclasses.replace(s, tension_1_min=-0.02, warnings=()) for s in real(*args, **kwargs)]

    monkeypatch.setattr(shooting, "compression_curve", slack)
    status, out, err = run(capsys, "compress", "--law", "neo-hookean", "--mu", "1", "--pressure", "0.3",
                           "--force", "0.5", "--json")
    assert status == 0, err
    assert err.count("pocket: warning: compressive tension: T_1 = -0.02 E T") == 1, err
    row = json.loads(out)
    assert row["wrinkled"] is True
    assert row["tension_1_min"] == -0.02
    assert "compressive tension" in row["warnings"][0]
