"""The rubber law as a registered object: the solvers' tables refuse a law they lack, the kernels refuse a code
they have no formula for, and the command line's flags and help come from the registry.

A toy law, registered here only (``toy``), stands for the next law: W = (mu / 2) (x + k x^2 / 2), x = I1 - 3, a
law of I1 alone with a stress mu and a dimensionless k.
"""

import numpy as np
import pytest
from pocket.fem import laws as fem_laws
from pocket.fem import material as fem_material
from pocket.shooting import laws as shooting_laws
from pocket.shooting.tensions import GENT, YEOH, tensions, tensions_compiled
from pocket.solid import laws as solid_laws
from test_fem_laws import check_derivatives
from test_shooting_laws import check_tensions

from pocket import fem, shooting, solid
from pocket.cli import main
from pocket.core.errors import InputError
from pocket.core.materials import LAWS, Parameter, RubberLaw, check, register


def _toy_energy(p, l1, l2, l3, i1, i2):
    x = i1 - 3.0
    return 0.5 * p["mu"] * (x + 0.5 * p["k"] * x * x)


def _toy_admissible(p, where):
    if not (p["mu"] > 0.0 and p["k"] >= 0.0):
        raise InputError(f"{where}.mu, k = {p['mu']:g}, {p['k']:g}, but the toy law needs mu > 0 and k >= 0")


TOY = RubberLaw("toy", (Parameter("mu", "stress", "the shear modulus mu"),
                        Parameter("k", "dimensionless", "the toy law's stiffening k")),
                mu0=lambda p: p["mu"], energy=_toy_energy, admissible=_toy_admissible,
                example={"mu": 0.4e6, "k": 0.5})


@pytest.fixture
def toy():
    """The toy law registered for one test (the checked example rubber, in Pa); removed after it."""
    register(TOY)
    try:
        yield check("toy", dict(TOY.example))
    finally:
        del LAWS["toy"]


def test_a_law_the_solvers_lack_is_refused_in_one_line_naming_the_law_and_the_solver(toy):
    """The solvers' tables lack the toy law: their kernels and entry points answer an InputError naming it
    and the solver, never another law's numbers."""
    for law_of, solver in ((shooting_laws.law_of, "shooting"), (fem_material.law_of, "finite-element"),
                           (solid_laws.derivatives, "solid")):
        with pytest.raises(InputError, match=f"the {solver} solver has no kernel for the toy law") as err:
            law_of(toy)
        assert "\n" not in str(err.value)
    for call in (lambda: shooting.inflate(toy, 0.1), lambda: fem.inflate(toy, 0.1), lambda: solid.inflate(toy, 0.1)):
        with pytest.raises(InputError, match="no kernel for the toy law"):
            call()


def test_the_command_line_answers_a_law_a_solver_lacks_in_one_line_exit_2(toy, capsys):
    """``--law toy`` is offered (the choices come from the registry) and refused by each solver, exit 2."""
    for solver, name in (("shooting", "shooting"), ("fem", "finite-element"), ("solid", "solid")):
        status = main(["inflate", "--law", "toy", "--mu", "1", "--k", "0.5", "--pressure", "0.1",
                       "--solver", solver])
        out, err = capsys.readouterr()
        assert status == 2, (status, out, err)
        assert out == "", (status, out, err)
        assert err.count("\n") == 1, (status, out, err)
        assert f"the {name} solver has no kernel for the toy law" in err


def test_once_mapped_the_toy_law_passes_both_kernels_checks(toy, monkeypatch):
    """Exact answers: W = (mu/2) (x + k x^2/2) is Yeoh's with C10 = mu/2, C20 = mu k/4, C30 = 0; mapped
    so in both tables, both kernels pass the checks every registered law passes (finite differences of the
    energy); mapped wrongly (Gent's kernel: C20 read as Jm), they fail them."""
    monkeypatch.setitem(shooting_laws.KERNELS, "toy",  # stresses in units of mu_0 (= mu)
                        lambda unit: (YEOH, [unit["mu"] / 2, unit["mu"] * unit["k"] / 4, 0.0]))
    monkeypatch.setitem(fem_material.KERNELS, "toy",  # in units of E = 3 mu_0: a third of that
                        lambda p: (fem_laws.YEOH, [p["mu"] / 6, p["mu"] * p["k"] / 12, 0.0]))
    check_tensions(toy)
    check_derivatives(toy)
    assert shooting.inflate(toy, 0.1).height == pytest.approx(fem.inflate(toy, 0.1).height, rel=1e-3)
    monkeypatch.setitem(shooting_laws.KERNELS, "toy", lambda unit: (GENT, [unit["mu"], unit["k"]]))
    monkeypatch.setitem(fem_material.KERNELS, "toy", lambda p: (fem_laws.GENT, [p["mu"] / 3, p["k"]]))
    with pytest.raises(AssertionError):
        check_tensions(toy)
    with pytest.raises(AssertionError):
        check_derivatives(toy)


@pytest.mark.parametrize("code", [5, -1, 99])
def test_a_kernel_code_without_a_formula_is_an_error_not_gent(code):
    """Each kernel has an explicit branch per code; an unknown one raises (Python and compiled), where it
    used to compute Gent's numbers."""
    params = np.array([1.0, 10.0])
    for call in (lambda: tensions(1.2, 1.1, code, params), lambda: tensions_compiled(1.2, 1.1, code, params),
                 lambda: fem_laws.derivatives(code, params, 1.2, 1.1)):
        with pytest.raises(ValueError, match=r"no .* for this law code"):
            call()


def test_every_registered_law_is_mapped_by_both_solvers(rubber):
    """The shipped laws are each in both tables (a law added to the registry without a kernel fails here)."""
    assert rubber.law in shooting_laws.KERNELS
    assert rubber.law in fem_material.KERNELS


def test_the_help_is_built_from_the_registry(toy, capsys):
    """Every parameter of every registered law other than Mooney-Rivlin (which takes --alpha) is a flag
    whose help carries the parameter's help text; the toy law's new ``--k`` too."""
    assert main(["compress", "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    for law in LAWS.values():
        if law.name != "mooney-rivlin":
            for q in law.parameters:
                assert f"--{q.name} {q.name.upper()}" in text, q
                assert " ".join(q.help.split()) in text, q
    assert "the toy law's stiffening k (toy)" in text


@pytest.mark.parametrize(("bad", "message"), [
    (Parameter("k", "dimensionless", " "), "needs a unit"),
    (Parameter("k", "pascal", "a modulus"), "needs a unit"),
    (Parameter("mu", "stress", "again"), "names a parameter twice"),
])
def test_a_parameter_without_help_or_unit_is_refused_at_registration(bad, message, capsys):
    """A parameter with no help text, an unknown unit, or a name used twice is refused by ``register``
    (ValueError, the registry unchanged), so it cannot break the commands."""
    law = RubberLaw("toy", (TOY.parameters[0], bad), mu0=TOY.mu0, energy=TOY.energy, admissible=lambda p, w: None,
                    example={"mu": 1.0, "k": 1.0})
    with pytest.raises(ValueError, match=message):
        register(law)
    assert "toy" not in LAWS
    assert main(["inflate", "--alpha", "0.3", "--pressure", "0.1"]) == 0
    capsys.readouterr()


def test_a_law_whose_example_fails_its_own_check_is_refused_at_registration():
    """The example is checked by the law's admissible set when the law is registered (ValueError naming it)."""
    law = RubberLaw("toy", TOY.parameters, mu0=TOY.mu0, energy=TOY.energy, admissible=_toy_admissible,
                    example={"mu": 1.0, "k": -1.0})
    with pytest.raises(ValueError, match=r"the toy law's example is not a rubber of it: .*k >= 0"):
        register(law)
    assert "toy" not in LAWS


def test_every_registered_law_is_in_the_documentation():
    """The laws' table (``pocket.core.materials``) and the README's list of ``--law`` values name every law."""
    from pathlib import Path

    from pocket.core import materials

    readme = Path(__file__).resolve().parents[1].joinpath("README.md").read_text()
    start = readme.index("The rubber: `--law")
    for name in LAWS:
        assert f"\n{name} " in materials.__doc__, name
        assert name in readme[start:start + 400], name
