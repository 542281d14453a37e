"""The validation cases file: it loads, and each case's dimensionless numbers are right."""

import math

import pytest
from pocket.validation.suite import load

from pocket.core.errors import InputError


def test_cases_load_and_cover_the_paper():
    """Exact answer: Table 1 (T = 0.25, 0.5, 0.8, 1.6 mm, C1 = 160, C2 = 47 kPa, R = 20 mm),
    P_I spanning 2-5 kPa, and alpha = 0 and 1 bracketing the paper's 0.3-1.2."""
    cases, design = load()
    table1 = [c for c in cases if c.sample is not None]
    assert sorted({c.thickness for c in table1}) == pytest.approx([0.25e-3, 0.5e-3, 0.8e-3, 1.6e-3])
    assert {(c.c1, c.c2, c.radius) for c in table1} == {(160e3, 47e3, 20e-3)}
    assert min(c.pressure for c in table1) == 2e3 and max(c.pressure for c in table1) == 5e3
    assert {c.alpha for c in cases} >= {0.0, 1.0, 47 / 160}
    assert sum("headline" in c.tags for c in cases) == 1
    assert sorted(c.sample for c in cases if "fig4" in c.tags) == [1, 2, 3, 4]
    assert design.radius == 20e-3 and design.force == 0.67


def test_dimensionless_numbers():
    """Exact answer: the paper's definitions, recomputed from the TOML's own numbers:
    alpha = C2/C1, E = 6 (1 + alpha) C1, Phat_I = P_I R / (E T)."""
    import tomllib

    from pocket.validation.suite import CASES_FILE

    def si(text):  # the file's three units, by hand: an independent reading of pocket.core.units'
        number, unit = text.split()
        return float(number) * {"mm": 1e-3, "kPa": 1e3, "N": 1.0}[unit]

    raw = {t["name"]: t for t in tomllib.loads(CASES_FILE.read_text())["case"]}
    for case in load()[0]:
        t = {k: si(v) for k, v in raw[case.name].items() if k in ("c1", "c2", "pressure", "radius", "thickness")}
        alpha = t["c2"] / t["c1"]
        modulus = 6 * (1 + alpha) * t["c1"]
        phat = t["pressure"] * t["radius"] / (modulus * t["thickness"])
        assert case.alpha == pytest.approx(alpha, rel=1e-15)
        assert case.modulus == pytest.approx(modulus, rel=1e-15)
        assert case.pressure_hat == pytest.approx(phat, rel=1e-14)
    headline = next(c for c in load()[0] if "headline" in c.tags)
    # the paper's fig. 2 case: sample 1 at Phat_I = 0.31, E = 1.242 MPa (Table 1)
    assert headline.pressure_hat == pytest.approx(0.31, rel=1e-12)
    assert headline.modulus == pytest.approx(1.242e6, rel=1e-12)


def test_design_rules():
    """Exact answer: Table 2, P_I = 5.7 F / (pi R^2), T = 0.216 P_I R^4 / (E H0^3)."""
    design = load()[1]
    pressure = 5.7 * 0.67 / (math.pi * 0.02**2)
    assert design.pressure == pytest.approx(pressure, rel=1e-14)
    assert design.thickness == pytest.approx(0.216 * pressure * 0.02**4 / (1e6 * 0.01**3), rel=1e-14)


@pytest.mark.parametrize("edit, bad, named", [
    ('thickness = "0.25 mm"', 'thickness = "-0.25 mm"', "thickness"),
    ('radius = "20.0 mm"', 'radius_cm = 2.0', "radius_cm"),
    ('c2 = "47.0 kPa"', 'c2 = "-200.0 kPa"', "alpha = C2/C1"),
    ('c1 = "160.0 kPa"', 'c1 = "160.0 mm"', "c1"),
    ('name = "sample1-2kPa"', 'name = "sample1-headline"', "names repeat"),
])
def test_bad_case_files_are_refused(tmp_path, edit, bad, named):
    """Exact answer: a one-line InputError naming the key, before any solve."""
    from pocket.validation.suite import CASES_FILE

    text = CASES_FILE.read_text()
    assert edit in text
    path = tmp_path / "cases.toml"
    path.write_text(text.replace(edit, bad, 1))
    with pytest.raises(InputError) as err:
        load(path)
    assert "\n" not in str(err.value) and named in str(err.value), err.value
