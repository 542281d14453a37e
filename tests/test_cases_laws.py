"""Case files with any rubber law and a liquid or a gas: ``pocket run`` end to end, and one-line errors."""

import csv
import dataclasses
import json
import math

import pytest

from pocket import shooting
from pocket.apps.cases import load
from pocket.apps.physical import resolve
from pocket.cli import main
from pocket.core.fluids import gas
from pocket.core.materials import Material, mooney_rivlin

R, T, P_I = 0.02, 0.5e-3, 4000.0  # m, m, Pa
FORCES = (0.0, 0.5, 1.0, 2.0)  # N

#: law -> (its [sheet] lines, E = 3 mu_0 in Pa by hand, its parameters in Pa / numbers)
LAWS = {
    "mooney-rivlin": ('material = "mooney-rivlin"\nc1 = "160 kPa"\nc2 = "47 kPa"', 6 * 207e3,
                      {"c1": 160e3, "c2": 47e3}),
    "neo-hookean": ('material = "neo-hookean"\nmu = "400 kPa"', 3 * 400e3, {"mu": 400e3}),
    "yeoh": ('material = "yeoh"\nc10 = "85 kPa"\nc20 = "2 kPa"\nc30 = "0.1 kPa"', 6 * 85e3,
             {"c10": 85e3, "c20": 2e3, "c30": 100.0}),
    "gent": ('material = "gent"\nmu = "400 kPa"\njm = 10', 3 * 400e3, {"mu": 400e3, "jm": 10.0}),
    "ogden": ('material = "ogden"\nmu = ["630 kPa", "1.2 kPa", "-10 kPa"]\nexponents = [1.3, 5.0, -2.0]',
              1.5 * (630e3 * 1.3 + 1.2e3 * 5.0 + 10e3 * 2.0),
              {"mu": (630e3, 1.2e3, -10e3), "exponents": (1.3, 5.0, -2.0)}),
}
#: fluid -> ([fluid] table, P_atm in Pa, gamma)
FLUIDS = {"liquid": ("", None, None),
          "air, isothermal": ('[fluid]\nkind = "gas"\n', 101325.0, 1.0),
          "air, adiabatic": ('[fluid]\nkind = "gas"\nambient = "100 kPa"\ngamma = 1.4\n', 100e3, 1.4)}


def case_text(law: str, fluid: str = "liquid", forces=FORCES) -> str:
    loads = ", ".join(f'"{f} N"' for f in forces)
    return (f'[sheet]\nthickness = "{T * 1e3} mm"\n{LAWS[law][0]}\n{FLUIDS[fluid][0]}[clamp]\nradius = "{R * 1e3} mm"\n'
            f'[initial]\npressure = "{P_I / 1e3} kPa"\n[loads]\nforces = [{loads}]\n')


def run_case(tmp_path, text, name="case"):
    path = tmp_path / f"{name}.toml"
    path.write_text(text)
    assert main(["run", str(path), "--out", str(tmp_path)]) == 0
    result = json.loads((tmp_path / f"{name}.json").read_text())
    rows = list(csv.DictReader((tmp_path / f"{name}.csv").open()))
    return result, rows


def by_hand(law: str) -> Material:
    """The rubber in units of mu_0 = E / 3, from the parameters and E written above (not Material.scaled)."""
    _, modulus, params = LAWS[law]
    mu0 = modulus / 3.0
    scaled = {k: (tuple(v / mu0 for v in value) if k == "mu" else value) if isinstance(value, tuple)
              else (value if k == "jm" else value / mu0) for k, value in params.items()}
    return Material(law, tuple(scaled.items()))


@pytest.mark.parametrize(("law", "fluid"), [(law, "liquid") for law in LAWS]
                         + [("neo-hookean", "air, isothermal"), ("yeoh", "air, isothermal"),
                            ("gent", "air, adiabatic"), ("ogden", "air, adiabatic"),
                            ("mooney-rivlin", "air, adiabatic")])
def test_run_each_law_and_fluid(law, fluid, tmp_path, capsys):
    """Exact answers: the rows are the shooting solver's states for the rubber in units of mu_0 and the
    gas's Phat_atm = P_atm R / (E T), with E = 3 mu_0 worked out by hand per law (6 C10 for Yeoh,
    (3/2) sum mu_p alpha_p for Ogden); and, from the SI columns alone, the fluid's own law holds from
    row to row: a liquid keeps its volume, a gas keeps (P + P_atm) V^gamma."""
    result, rows = run_case(tmp_path, case_text(law, fluid))
    _, modulus, _params = LAWS[law]
    _, ambient, gamma = FLUIDS[fluid]
    scale = modulus * T / R  # E T / R
    sealed = {} if ambient is None else {"fluid": gas(ambient / scale, gamma)}
    rubber = 0.047 / 0.16 if law == "mooney-rivlin" else by_hand(law)
    expected = shooting.compression_curve(rubber, P_I / scale, [f / (P_I * math.pi * R**2) for f in FORCES], **sealed)
    assert result["case"]["modulus_Pa"] == pytest.approx(modulus, rel=1e-15)
    assert result["case"]["material"] == law
    assert result["case"]["fluid"] == ("liquid" if ambient is None else "gas")
    for row, state in zip(result["states"], expected, strict=True):
        for key in ("pressure_ratio", "contact_area", "height", "volume", "tension_1_min", "tension_2_min"):
            assert row[key] == pytest.approx(getattr(state, key), rel=1e-9, abs=1e-15), key  # solver resolution
        assert row["material"] == law
        assert row["wrinkled"] is False
        for name, value in state.material.params:  # the parameters in units of mu_0, the stresses saying so
            column = name if name in ("jm", "exponents") else f"{name}_per_mu0"  # Gent's Jm, Ogden's alpha_p: numbers
            assert row[column] == pytest.approx(list(value) if isinstance(value, tuple) else value, rel=1e-14)
        if ambient is not None:
            assert (row["fluid"], row["ambient"], row["gamma"]) == ("gas", pytest.approx(ambient / scale), gamma)
    first = [float(x) for x in (rows[0]["pressure_Pa"], rows[0]["volume_m3"])]
    for row in rows[1:]:
        p, v = float(row["pressure_Pa"]), float(row["volume_m3"])
        if ambient is None:
            assert v == pytest.approx(first[1], rel=1e-9)  # fixed volume, to the root finder's residual
        else:
            assert (p + ambient) * v**gamma == pytest.approx((first[0] + ambient) * first[1] ** gamma, rel=1e-9)
            assert v < first[1]  # the gas is compressed
    assert "warning" not in capsys.readouterr().err


def test_mooney_rivlin_takes_its_old_path(tmp_path):
    """Exact: a c1/c2 case (with or without material = "mooney-rivlin") hands the solvers the rubber of
    alpha = C2/C1, as before other laws existed, and its rows are that solve to the last bit; Phat_I
    is P_I R / (E T) with E = 6 (C1 + C2)."""
    plain = case_text("mooney-rivlin").replace('material = "mooney-rivlin"\n', "")
    for text in (plain, case_text("mooney-rivlin")):
        pocket = resolve(load_text(tmp_path, text))
        assert pocket.material == mooney_rivlin(47e3 / 160e3)
        assert pocket.material.alpha == 47e3 / 160e3
        assert pocket.fluid.kind == "liquid"
        assert pocket.pressure_initial == pytest.approx(P_I * R / (6 * 207e3 * T), rel=1e-15)
        result, _ = run_case(tmp_path, text)
        states = shooting.compression_curve(pocket.material, pocket.pressure_initial,
                                            [s["force"] for s in result["states"]])
        for row, state in zip(result["states"], states, strict=True):
            assert all(row[k] == getattr(state, k) for k in state.KEYS if k != "alpha")
            assert row["alpha"] == 47e3 / 160e3
            assert (row["c1_per_mu0"], row["c2_per_mu0"]) == (state.material["c1"], state.material["c2"])


def load_text(tmp_path, text, name="loaded"):
    path = tmp_path / f"{name}.toml"
    path.write_text(text)
    return load(path)


def test_one_rubber_four_ways(tmp_path):
    """Exact: neo-Hookean mu = Mooney-Rivlin (mu/2, 0) = Yeoh (mu/2, 0, 0) = Ogden ([mu], [2]) have one
    strain energy, so their cases give one set of rows (the Mooney-Rivlin one by the float-alpha path,
    the others as a Material), to the solver's resolution."""
    rubbers = {"neo-hookean": 'material = "neo-hookean"\nmu = "400 kPa"',
               "mooney-rivlin": 'c1 = "200 kPa"\nc2 = "0 kPa"',
               "yeoh": 'material = "yeoh"\nc10 = "200 kPa"\nc20 = 0\nc30 = "0 Pa"',
               "ogden": 'material = "ogden"\nmu = ["400 kPa"]\nexponents = [2]'}
    rows = {}
    for law, lines in rubbers.items():
        text = case_text("neo-hookean", "air, isothermal").replace(LAWS["neo-hookean"][0], lines)
        rows[law] = run_case(tmp_path, text, law)[0]["states"]
    for law in rubbers:
        for row, ref in zip(rows[law], rows["neo-hookean"], strict=True):
            for key in ("pressure_Pa", "contact_area_m2", "height_m", "volume_m3", "pressure_initial", "force"):
                assert row[key] == pytest.approx(ref[key], rel=1e-9, abs=1e-15), (law, key)


def test_a_compressive_tension_reaches_the_user(tmp_path, capsys, monkeypatch):
    """A state with a compressive tension (patched in: the solvers' states keep both tensions positive on
    every case tried) is run: exit 0, one 'pocket: warning: compressive tension' line on stderr, and the
    JSON row says wrinkled with the smallest tension and the warning."""
    real = shooting.compression_curve

    def slack(*args, **kwargs):
        states = real(*args, **kwargs)
        return [dataclasses.replace(states[0], tension_2_min=-0.01, warnings=()), *states[1:]]

    monkeypatch.setattr(shooting, "compression_curve", slack)
    path = tmp_path / "c.toml"
    path.write_text(case_text("yeoh"))
    assert main(["run", str(path), "--out", str(tmp_path)]) == 0
    err = capsys.readouterr().err
    assert err.count("pocket: warning: compressive tension: T_2 = -0.01 E T") == 1, err
    row = json.loads((tmp_path / "c.json").read_text())["states"][0]
    assert row["wrinkled"] is True
    assert row["tension_2_min"] == -0.01
    assert "compressive tension" in row["warnings"][0]


@pytest.mark.parametrize(("old", "new", "message"), [
    ('material = "yeoh"', 'material = "yoeh"', "sheet.material = 'yoeh', but it must be one of mooney-rivlin, "
                                                "neo-hookean, yeoh, gent, ogden"),
    ('material = "yeoh"', "material = 3", "sheet.material = 3, but it must be one of"),
    ('c30 = "0.1 kPa"', "", "sheet.c30 is missing: the yeoh law needs c10, c20, c30"),
    ('c30 = "0.1 kPa"', 'c30 = "0.1 kPa"\nmu = "1 kPa"', "sheet.mu is not a parameter of the yeoh law (its "
                                                         "parameters: c10, c20, c30)"),
    ('c30 = "0.1 kPa"', 'c30 = "0.1 kPa"\nc1 = "1 kPa"', "sheet.c1 is not a parameter of the yeoh law"),
    ('material = "yeoh"\n', "", "sheet.c10 is not a parameter of the mooney-rivlin law (its parameters: "
                                "c1 and c2, or modulus and alpha)"),
    ('c10 = "85 kPa"', 'c10 = "85 mm"', "sheet.c10 = '85 mm' has dimension [length], but a pressure (Pa) is needed"),
    ('c10 = "85 kPa"', 'c10 = "85 kPa m"', "sheet.c10 = '85 kPa m' has dimension"),
    ('c10 = "85 kPa"', 'c10 = "lots"', "sheet.c10 = 'lots' is not a quantity with a known unit"),
    ('c20 = "2 kPa"', 'c20 = "-50 kPa"', "a stable Yeoh rubber needs C10 > 0"),
    ('[fluid]\nkind = "gas"', '[fluid]\nkind = "gas"\ngamma = 0.9', "fluid.gamma = 0.9, but it must lie in [1, 5/3]"),
    ('[fluid]\nkind = "gas"', '[fluid]\nkind = "gas"\ngamma = 1.7', "fluid.gamma = 1.7, but it must lie in [1, 5/3]"),
    ('[fluid]\nkind = "gas"', '[fluid]\nkind = "gas"\ngamma = "1.4"', "fluid.gamma = '1.4' is not a number"),
    ('[fluid]\nkind = "gas"', '[fluid]\nkind = "gas"\nambient = "0 kPa"',
     "fluid.ambient = '0 kPa', but the ambient (absolute) pressure must be > 0"),
    ('[fluid]\nkind = "gas"', '[fluid]\nkind = "gas"\nambient = -101325',
     "fluid.ambient = -101325, but the ambient (absolute) pressure must be > 0"),
    ('[fluid]\nkind = "gas"', '[fluid]\nkind = "gas"\nambient = "1 bar m"', "fluid.ambient = '1 bar m' has dimension"),
    ('[fluid]\nkind = "gas"', '[fluid]\nkind = "oil"', "fluid.kind = 'oil', but it must be one of liquid, gas"),
    ('[fluid]\nkind = "gas"', '[fluid]\nkind = "liquid"\ngamma = 1.4',
     "fluid.gamma applies to a gas (fluid.kind = 'gas'), not to a liquid"),
    ('[fluid]\nkind = "gas"', '[fluid]\nambient = "1 bar"', "fluid.ambient applies to a gas"),
    ('[fluid]\nkind = "gas"', '[fluid]\nkind = "gas"\ntemperature = 300', "unknown key 'fluid.temperature'"),
])
def test_bad_law_or_fluid_is_one_line_naming_the_key(old, new, message, tmp_path, capsys):
    """Each bad rubber or fluid: exit 2, one line on stderr naming the key and quoting the value as written,
    nothing written, before any solve."""
    text = case_text("yeoh", "air, isothermal")
    assert old in text
    path = tmp_path / "bad.toml"
    path.write_text(text.replace(old, new))
    assert main(["run", str(path), "--out", str(tmp_path / "out")]) == 2
    out, err = capsys.readouterr()
    assert out == "", err
    assert err.count("\n") == 1, err
    assert message in err, err
    assert "Traceback" not in err, err
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize(("law", "old", "new", "message"), [
    ("ogden", '"-10 kPa"]', '"-10 m"]', "sheet.mu[2] = '-10 m' has dimension [length]"),
    ("ogden", "exponents = [1.3, 5.0, -2.0]", 'exponents = ["1.3", 5.0, -2.0]',
     "sheet.exponents[0] = '1.3' is not a number (it has no unit)"),
    ("ogden", "exponents = [1.3, 5.0, -2.0]", "exponents = [1.3, 5.0]", "sheet.mu has 3 terms but sheet.exponents "
                                                                        "has 2"),
    ("ogden", 'mu = ["630 kPa", "1.2 kPa", "-10 kPa"]', 'mu = "630 kPa"', "but the ogden law needs a non-empty list"),
    ("ogden", 'mu = ["630 kPa", "1.2 kPa", "-10 kPa"]', "mu = []", "but the ogden law needs a non-empty list"),
    ("gent", "jm = 10", 'jm = "10 kPa"', "sheet.jm = '10 kPa' is not a number (it has no unit)"),
    ("gent", "jm = 10", "jm = 0", "sheet.jm = 0.0, but the locking parameter Jm must be > 0"),
    ("gent", 'mu = "400 kPa"', 'mu = ["400 kPa"]', "sheet.mu = ['400 kPa'] is not a pressure"),
    ("neo-hookean", 'mu = "400 kPa"', "mu = true", "sheet.mu = True is not a pressure"),
])
def test_bad_parameters_of_other_laws(law, old, new, message, tmp_path, capsys):
    """Lists, numbers and units of the Ogden, Gent and neo-Hookean parameters: one line naming the key."""
    text = case_text(law)
    assert old in text
    path = tmp_path / "bad.toml"
    path.write_text(text.replace(old, new))
    assert main(["run", str(path), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    assert message in err, err


@pytest.mark.parametrize(("law", "fluid"), [("ogden", "air, adiabatic"), ("gent", "air, isothermal")])
def test_fe_and_shooting_runs_agree(law, fluid, tmp_path):
    """Two independent solvers through the same case file: the FE model (P2, its default mesh) gives the
    shooting rows to 1e-8 in every SI value (its measured agreement is ~1e-10; the validation suite holds
    it to 1e-9), the rubber and the gas reaching both the same way."""
    text = case_text(law, fluid)
    shot, _ = run_case(tmp_path, text, "shooting")
    fe, _ = run_case(tmp_path, text + '[solver]\nname = "fem"\n', "fem")
    for a, b in zip(fe["states"], shot["states"], strict=True):
        assert a["solver"] == "fem"
        assert b["solver"] == "shooting"
        for key in ("pressure_Pa", "contact_area_m2", "contact_radius_deformed_m", "contact_radius_lagrangian_m",
                    "height_m", "volume_m3", "ambient"):
            assert a[key] == pytest.approx(b[key], rel=1e-8, abs=1e-15), key
