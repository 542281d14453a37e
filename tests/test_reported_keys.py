"""Every key pocket reports and every column it writes is in its one table of units and meanings.

The model's keys are ``pocket.core.reported``'s, the columns the applications add ``pocket.apps.columns``'s;
the documentation's page of outputs is written from the same two tables. The states here are computed, by
every solver and contact method, under the plate, a sphere and a profile, with a liquid and a gas, for every
rubber law and a prestretched sheet, so that a key any of them adds without a meaning fails.
"""

import csv
import dataclasses
import io
import json

import numpy as np
import pytest

from pocket import analytical, fem, shooting, solid
from pocket.apps import casefile, columns
from pocket.apps.cases import parse
from pocket.apps.sweep.journal import COLUMNS as SWEEP_COLUMNS
from pocket.cli import main
from pocket.core import profiles
from pocket.core.fluids import gas
from pocket.core.indenters import Profile, Sphere
from pocket.core.materials import LAWS, check, mooney_rivlin
from pocket.core.reported import GROUPS, REPORTED, UNITS, reported
from pocket.core.states import CHECKS, CompressedState, InflatedState

ALPHA, PHAT, FHAT = 0.3, 0.3, 0.2


def _profile() -> Profile:
    """A sphere of radius 0.6 R given as a table of 12 rows up to 0.4 R from the axis."""
    rho = np.linspace(0.0, 0.4, 12)
    return Profile(profiles.table(rho, Sphere(0.6).height(rho)))


def _keys(states) -> set[str]:
    """The keys the ``states`` report (``scalars``, and the ``warnings`` every output adds), their inflated
    states' too."""
    out = set()
    for state in states:
        for each in (state, getattr(state, "inflated", None)):
            if each is not None:
                out |= {*each.scalars(), "warnings"}
    return out


def _states():
    """Compressed states of every solver and contact method (with their inflated states), each law, a gas, a
    prestretched sheet, the plate, a sphere and a profile, a pocket and a capsule."""
    yield shooting.compress(ALPHA, PHAT, FHAT)
    yield shooting.compress(ALPHA, PHAT, FHAT, indenter=Sphere(0.4), fluid=gas(6.5, 1.4))
    yield shooting.compress(ALPHA, PHAT, FHAT, indenter=_profile())
    for law in LAWS.values():
        yield shooting.compress(check(law.name, dict(law.example)), PHAT, FHAT)
    yield shooting.compress(dataclasses.replace(mooney_rivlin(ALPHA), prestretch=1.1), PHAT, FHAT)
    yield shooting.compress(ALPHA, PHAT, FHAT, geometry="capsule", fluid=gas(6.5, 1.4))
    yield shooting.compress(ALPHA, PHAT, 0.0, geometry="capsule")
    yield fem.compress(ALPHA, PHAT, FHAT, elements=32)
    yield fem.compress(ALPHA, PHAT, 0.0, elements=32)
    yield fem.compress(ALPHA, PHAT, FHAT, elements=32, contact="penalty")
    yield fem.compress(ALPHA, PHAT, FHAT, elements=32, indenter=Sphere(0.4))
    yield fem.compress(ALPHA, PHAT, FHAT, elements=32, indenter=Sphere(0.4), contact="penalty")
    yield analytical.compress(ALPHA, PHAT, FHAT)
    yield solid.compress(ALPHA, PHAT, FHAT, elements=16, layers=2)
    yield solid.compress(ALPHA, PHAT, FHAT, elements=16, layers=2, indenter=Sphere(0.4))


@pytest.fixture(scope="module")
def reported_keys() -> set[str]:
    return _keys(_states())


def test_every_key_any_state_reports_has_a_unit_and_meaning(reported_keys):
    """Exact answer: the keys reported by the states of every solver, contact method, indenter, fluid and law
    (``_states``) are all in ``pocket.core.reported.REPORTED``, with a unit of ``UNITS`` and a meaning."""
    missing = sorted(k for k in reported_keys if k not in REPORTED)
    assert not missing, f"reported but not in pocket.core.reported: {missing}"
    for key in reported_keys:
        assert reported(key).unit in UNITS, key
        assert reported(key).meaning, key


def test_every_key_a_state_declares_is_in_the_table():
    """Exact answer: the keys the state classes declare (KEYS, CONTACT_KEYS and the membrane's CHECKS) are all
    in the table, whether or not a solver reported them in ``_states``."""
    declared = {*InflatedState.KEYS, *CompressedState.KEYS, *CompressedState.CONTACT_KEYS, *CHECKS}
    assert declared <= set(REPORTED), sorted(declared - set(REPORTED))


def test_the_table_holds_only_keys_some_state_reports(reported_keys):
    """Exact answer: no key of the table is a stale one that no state reports: each of ``REPORTED`` is among the
    keys of ``_states``, which cover every solver's diagnostics."""
    stale = sorted(set(REPORTED) - reported_keys)
    assert not stale, f"in pocket.core.reported but reported by no state: {stale}"


def test_groups_do_not_share_a_key():
    """Exact answer: the flat table has as many keys as the groups together: a key is described once."""
    assert len(REPORTED) == sum(len(group) for group in GROUPS.values())


def _case(**sections) -> dict:
    base = {"sheet": {"thickness": "0.25 mm", "c1": "160 kPa", "c2": "47 kPa"}, "clamp": {"radius": "20 mm"},
            "initial": {"pressure": "4.8 kPa"}, "loads": {"forces": ["0.2 N", "0.5 N", "100 N"]}}
    return {**base, **sections}


CASES = {
    "plate": _case(),
    "sphere and gas": _case(indenter={"shape": "sphere", "radius": "8 mm"},
                            fluid={"kind": "gas", "gamma": 1.4}),
    "ogden, prestretched": _case(sheet={"thickness": "0.25 mm", "material": "ogden", "prestretch": 1.1,
                                        "mu": ["630 kPa", "1.2 kPa", "-10 kPa"], "exponents": [1.3, 5.0, -2.0]}),
    "fem": _case(solver={"name": "fem", "elements": 32}),
    "solid": _case(solver={"name": "solid", "elements": 16, "layers": 2}),
    "analytical": _case(solver={"name": "analytical"}),
}


@pytest.mark.parametrize("name", CASES)
def test_every_column_pocket_run_writes_is_documented(name, tmp_path):
    """Exact answer: every column of ``pocket run``'s CSV (a reached load's row and an unreached one's) and every
    key of its JSON's state rows is in ``pocket.apps.columns.column``'s tables: COLUMNS, a stress in units of
    mu_0, or the model's keys."""
    result = casefile.solve(parse(CASES[name], "case"))
    paths = casefile.results_paths(tmp_path, "case")
    casefile.write(result, paths)
    data = json.loads(paths[0].read_text())
    header = next(csv.reader(io.StringIO(paths[1].read_text())))
    assert data["unreachable"], "the 100 N load is past the range: its row is written too"
    for key in {*header, *data["inflated"], *(k for row in data["states"] for k in row)}:
        assert columns.column(key).unit in columns.UNITS, key


def test_every_column_of_a_sweep_file_is_documented():
    """Exact answer: each of the sweep file's COLUMNS is in ``pocket.apps.columns.column``'s tables."""
    for key in SWEEP_COLUMNS:
        assert columns.column(key).unit in columns.UNITS, key


def test_an_undocumented_column_fails_before_anything_is_written(tmp_path):
    """The user's need: no column leaves pocket unexplained. A result row with a key in neither table (here
    ``mystery``) makes ``casefile.write`` raise KeyError naming it, and neither file is written."""
    result = casefile.solve(parse(_case(loads={"forces": ["0.2 N"]}), "case"))
    result["states"][0]["mystery"] = 1.0
    paths = casefile.results_paths(tmp_path, "case")
    with pytest.raises(KeyError, match="mystery"):
        casefile.write(result, paths)
    assert not any(path.exists() for path in paths)


def test_a_bare_stress_column_is_refused():
    """Exact answer: a law's stress as a column must say its unit: ``c1`` is refused naming ``c1_per_mu0``,
    which is documented with the unit mu_0 and Mooney-Rivlin's C1 as its meaning."""
    with pytest.raises(KeyError, match="c1_per_mu0"):
        columns.column("c1")
    assert columns.column("c1_per_mu0").unit == "mu_0"
    assert "C1" in columns.column("c1_per_mu0").meaning


def test_compress_json_keys_are_documented(capsys):
    """Exact answer: every key of ``pocket compress --json``'s objects (a fem state, with its diagnostics) is in
    ``pocket.core.reported``."""
    assert main(["compress", "--alpha", "0.3", "--pressure", "0.3", "--force", "0.2", "--solver", "fem",
                 "--elements", "32", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    rows = out if isinstance(out, list) else [out]
    for row in rows:
        for key in row:
            assert reported(key).meaning, key
