"""The validation cases file: read as case files, each pocket's dimensionless numbers right, bad files refused."""

import math
import tomllib

import pytest
from pocket.validation.plan import DEFAULT, QUICK, Column
from pocket.validation.suite import CASES_FILE, load

from pocket.apps.cases import sample
from pocket.core.errors import InputError


def test_cases_cover_the_paper():
    """Exact answer: the paper's Table 1 (the built-in samples 1-4 of ``pocket run --sample``: sheets and
    clamp), P_I spanning 2-5 kPa, and alpha = 0 and 1 bracketing the paper's 0.3-1.2."""
    pockets, button = load()
    cases = [p.case for p in pockets]
    for number in (1, 2, 3, 4):
        table1 = sample(number)
        same = [c for c in cases if (c.thickness, c.material, c.radius) ==
                (table1.thickness, table1.material, table1.radius)]
        assert same, f"no case with the sheet of sample {number}"
    silicone = [p for p in pockets if p.case.alpha == 47 / 160]
    assert min(p.pressure_initial_Pa for p in silicone) == pytest.approx(2e3, rel=1e-12)
    assert max(p.pressure_initial_Pa for p in silicone) == pytest.approx(5e3, rel=1e-12)
    assert {c.alpha for c in cases} >= {0.0, 1.0, 47 / 160}
    assert sum("headline" in c.tags for c in cases) == 1
    four = [p for p in pockets if "fig4" in p.case.tags]
    assert sorted(p.case.thickness for p in four) == [sample(n).thickness for n in (1, 2, 3, 4)]
    assert len({p.pressure_initial_Pa for p in four}) == 1  # the same P_I
    assert all(c.label for c in cases)
    assert len({c.label for c in cases}) == len(cases)
    assert button.radius == 20e-3
    assert button.force == 0.67
    assert button.height_ratio == 0.8


def _modulus(sheet, si) -> float:
    """E = 3 mu_0 of a [case.sheet] table, by hand per law from the TOML's text."""
    law = sheet.get("material", "mooney-rivlin")
    if law == "mooney-rivlin":
        return 6 * (si(sheet["c1"]) + si(sheet["c2"]))  # 6 (1 + alpha) C1
    if law == "yeoh":
        return 6 * si(sheet["c10"])
    if law == "ogden":
        return 1.5 * sum(si(m) * a for m, a in zip(sheet["mu"], sheet["exponents"], strict=True))
    return 3 * si(sheet["mu"])  # neo-Hookean and Gent


def test_dimensionless_numbers():
    """Exact answer: the paper's definitions recomputed from the TOML's own text, units read by hand:
    alpha = C2/C1, E = 3 mu_0 (6 (1 + alpha) C1 for Mooney-Rivlin, 6 C10 for Yeoh, (3/2) sum mu_p alpha_p
    for Ogden, 3 mu for Gent), Phat_I = P_I R / (E T), and a gas's Phat_atm = P_atm R / (E T)."""

    def si(text):  # the file's two units, by hand: an independent reading of pocket.core.units'
        number, unit = text.split()
        return float(number) * {"mm": 1e-3, "kPa": 1e3}[unit]

    raw = {t["name"]: t for t in tomllib.loads(CASES_FILE.read_text())["case"]}
    pockets = load()[0]
    for pocket in pockets:
        t = raw[pocket.case.name]
        thickness, modulus = si(t["sheet"]["thickness"]), _modulus(t["sheet"], si)
        radius, pressure = si(t["clamp"]["radius"]), si(t["initial"]["pressure"])
        if "c1" in t["sheet"]:
            assert pocket.alpha == pytest.approx(si(t["sheet"]["c2"]) / si(t["sheet"]["c1"]), rel=1e-15)
        else:
            assert pocket.alpha is None
            assert pocket.case.material.law == t["sheet"]["material"]
        assert pocket.case.modulus == pytest.approx(modulus, rel=1e-15)
        assert pocket.pressure_initial == pytest.approx(pressure * radius / (modulus * thickness), rel=1e-14)
        if "fluid" in t:
            ambient = si(t["fluid"]["ambient"])
            assert pocket.fluid.ambient == pytest.approx(ambient * radius / (modulus * thickness), rel=1e-14)
            assert pocket.fluid.gamma == t["fluid"]["gamma"]
    head = next(p for p in pockets if "headline" in p.case.tags)
    # the paper's fig. 2 case: sample 1 at Phat_I = 0.31, E = 1.242 MPa (Table 1)
    assert head.pressure_initial == pytest.approx(0.31, rel=1e-12)
    assert head.case.modulus == pytest.approx(1.242e6, rel=1e-12)


def test_cases_cover_every_law_and_fluid():
    """The suite holds a pocket of each other law (Yeoh, Ogden, Gent) and gas-filled pockets, isothermal and
    adiabatic, each with FE columns to near the end of its range in both plans; the Gent pocket gets near its
    lock (I1 - 3 above 0.8 Jm at 0.95 of its range end, from its shooting profile); the "fluids" pockets are one
    sheet at one P_I with a liquid and both gases (the liquid-vs-gas figure)."""
    import numpy as np

    from pocket import shooting

    pockets = load()[0]
    laws = {p.case.material.law for p in pockets if "fem-range" in p.case.tags}
    assert laws >= {"yeoh", "ogden", "gent"}
    gases = {p.case.fluid.gamma for p in pockets if p.case.fluid.is_gas and "fem-range" in p.case.tags}
    assert gases == {1.0, 1.4}
    for plan in (DEFAULT, QUICK):
        assert None in plan.fem["fem-range"]
        assert 0.0 in plan.fem["fem-range"]
    fluids = [p for p in pockets if "fluids" in p.case.tags]
    assert len({(p.case.thickness, p.case.material, p.case.radius, p.pressure_initial_Pa) for p in fluids}) == 1
    assert sorted((p.case.fluid.kind, p.case.fluid.gamma) for p in fluids) == [("gas", 1.0), ("gas", 1.4),
                                                                               ("liquid", 1.0)]
    gent = next(p for p in pockets if p.case.material.law == "gent")
    state = shooting.compress(gent.material, gent.pressure_initial,
                              0.95 * shooting.range_end(gent.material, gent.pressure_initial))
    l1, l2 = state.profile.stretch_1, state.profile.stretch_2
    assert np.max(l1**2 + l2**2 + (l1 * l2) ** -2 - 3) > 0.8 * gent.case.material["jm"]


def test_button_rules():
    """Exact answer: Table 2 by hand from the file's inputs, P_I = 5.7 F / (pi R^2), T = 0.216 P_I R^4 / (E H0^3)."""
    pressure, thickness = load()[1].paper
    expected = 5.7 * 0.67 / (math.pi * 0.02**2)
    assert pressure == pytest.approx(expected, rel=1e-14)
    assert thickness == pytest.approx(0.216 * expected * 0.02**4 / (1e6 * 0.01**3), rel=1e-14)


def test_initial_height_is_resolved(tmp_path):
    """Exact answer: a pocket given by its inflated height H0 gets the Phat_I whose inflated height is
    H0 / R (the case-file resolution, checked by inflating again)."""
    from pocket import shooting

    text = CASES_FILE.read_text().replace('pressure = "4.81275 kPa"', 'height = "9 mm"', 1)
    path = tmp_path / "cases.toml"
    path.write_text(text)
    head = next(p for p in load(path)[0] if "headline" in p.case.tags)
    assert shooting.inflate(head.alpha, head.pressure_initial).height == pytest.approx(9 / 20, rel=1e-10)


@pytest.mark.parametrize(("edit", "bad", "named"), [
    ('thickness = "0.25 mm"', 'thickness = "-0.25 mm"', "thickness"),
    ('radius = "20 mm"', 'radius_cm = 2.0', "radius_cm"),
    ('c2 = "47 kPa"', 'c2 = "-200 kPa"', "C2/C1"),
    ('c1 = "160 kPa"', 'c1 = "160 mm"', "c1"),
    ('name = "sample1-2kPa"', 'name = "sample1-headline"', "names repeat"),
    ('label = "sample 1 at 2 kPa"', 'tags = []', "label"),
    ('[case.clamp]', '[case.loads]\nforces = ["1 N"]\n[case.clamp]', "loads"),
    ('[case.clamp]', '[case.solver]\nname = "fem"\n[case.clamp]', "solver"),
    ('height_ratio = 0.8', 'height_ratio = 1.2', "height_ratio"),
    ('force = "0.67 N"', 'force = "0.67 m"', "design.force"),
    ('alpha = 0.29375', 'alpha = -1.5', "alpha"),
    ('alpha = 0.29375', 'colour = "red"', "colour"),
])
def test_bad_case_files_are_refused(tmp_path, edit, bad, named):
    """Exact answer: a one-line InputError naming the key, before any solve."""
    text = CASES_FILE.read_text()
    assert edit in text
    path = tmp_path / "cases.toml"
    path.write_text(text.replace(edit, bad, 1))
    with pytest.raises(InputError) as err:
        load(path)
    assert "\n" not in str(err.value), err.value
    assert named in str(err.value), err.value


@pytest.mark.parametrize(("solver", "options", "named"), [
    ("fem", (("order", 3),), "order"),
    ("shooting", (("order", 1),), "does not apply"),
    ("fem", (("penalty", -1.0),), "penalty"),
    ("spectral", (), "spectral"),
])
def test_columns_are_checked_by_the_solver_records(solver, options, named):
    """Exact answer: a solver column is checked by its solver's record, as a command-line flag is."""
    with pytest.raises(InputError, match=named):
        Column(solver, "column", options)


def test_plans_columns_take_their_options():
    """Exact answer: the FE columns of both plans are the fem solver at orders 1 and 2, the options its
    record checked (an int order, not a string)."""
    for plan in (DEFAULT, QUICK):
        assert [(c.solver, dict(c.options)) for c in plan.fem_columns] == [("fem", {"order": 1}), ("fem", {"order": 2})]
        assert [c.kwargs("inflate") for c in plan.fem_columns] == [{"order": 1}, {"order": 2}]


@pytest.mark.parametrize("command", ["validate", "converge"])
def test_help_and_docs_say_what_a_cases_file_needs(command, capsys):
    """Exact answer: the suite's own cases file, which ``load`` accepts: the help of ``--cases`` and the
    documentation's validation page name every key of its [design] table and the case tables it needs."""
    from documents import ROOT

    from pocket.cli import main

    design = tomllib.loads(CASES_FILE.read_text())["design"]
    assert main([command, "--help"]) == 0
    help_text = " ".join(capsys.readouterr().out.split())
    page = " ".join((ROOT / "docs" / "validation.md").read_text().split())
    for text in (help_text, page.replace("`", "")):
        assert "[design]" in text
        assert "[[case]]" in text
        assert "label" in text
        missing = [key for key in design if key not in text]
        assert not missing, missing
