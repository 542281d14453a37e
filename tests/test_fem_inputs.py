"""Bad input to the finite-element solver: a one-line InputError quoting the value,
raised before any work (the rubber, its law's parameters, the fluid, the loads, the options);
and a mesh the solver cannot use, rejected saying why."""

import numpy as np
import pytest

from pocket import fem
from pocket.core.errors import InputError
from pocket.core.fluids import Fluid
from pocket.core.materials import Material

CASES = [
    (lambda: fem.inflate(-1.0, 0.1), "alpha = -1.0"),
    (lambda: fem.inflate(-1.5, 0.1), "alpha = -1.5"),
    (lambda: fem.inflate(0.3, 0.0), "pressure = 0.0"),
    (lambda: fem.inflate(0.3, -0.2), "pressure = -0.2"),
    (lambda: fem.inflate_volume(0.3, -1.0), "volume = -1.0"),
    (lambda: fem.compress(0.3, 0.31, -0.1), "force = -0.1"),
    (lambda: fem.compress(0.3, 0.31, float("nan")), "force = nan is not finite"),
    (lambda: fem.compress(0.3, -0.31, 0.1), "pressure_initial = -0.31"),
    (lambda: fem.compress(0.3, 0.31, 0.1, contact="penalty", penalty=0.0), "penalty = 0.0"),
    (lambda: fem.compress(0.3, 0.31, 0.1, contact="penalty", penalty=-5.0), "penalty = -5.0"),
    (lambda: fem.compress(0.3, 0.31, 0.1, penalty=1e4), "penalty = 10000.0 applies only to contact = 'penalty'"),
    (lambda: fem.compress(0.3, 0.31, 0.1, augmented=False), "augmented = False applies only to contact"),
    (lambda: fem.compress(0.3, 0.31, 0.1, contact="exact"), "contact = 'exact', but it must be one of"),
    (lambda: fem.compress_height(0.3, 0.31, -0.1), "height = -0.1"),
    (lambda: fem.compress_height(0.3, 0.31, 0.0), "height = 0.0"),
    (lambda: fem.inflate(0.3, 0.1, order=3), "order = 3"),
    (lambda: fem.inflate(0.3, 0.1, elements=3), f"elements = 3, but it must lie in [4, {fem.MAX_ELEMENTS}]"),
    (lambda: fem.inflate(0.3, 0.1, mesh=np.linspace(0, 1, 3)),
     f"mesh elements = 2, but it must lie in [4, {fem.MAX_ELEMENTS}]"),
    (lambda: fem.inflate(0.3, 0.1, mesh=np.linspace(0, 2, 11)), "spans"),
    (lambda: fem.inflate(0.3, 0.1, mesh=np.linspace(0, 1, 11)[::-1]), "increasing"),
    (lambda: fem.inflate(0.3, 0.1, mesh=np.zeros((3, 4))), "1-D"),
    (lambda: fem.compress(0.3, 0.31, 0.1, mesh=np.linspace(0, 1, 11), elements=10), "either mesh or elements"),
    (lambda: fem.inflate("rubber", 0.1), "alpha = 'rubber'"),
    (lambda: fem.inflate(Material("gent", (("mu", 1.0), ("jm", -2.0))), 0.1), "sheet.jm = -2.0"),
    (lambda: fem.inflate(Material("ogden", (("mu", (1.0,)), ("exponents", (-2.0,)))), 0.1), "mu_p alpha_p > 0"),
    (lambda: fem.inflate(Material("rubber", ()), 0.1), "material = 'rubber', but it must be one of"),
    (lambda: fem.compress(0.3, 0.31, 0.1, fluid="water"), "fluid = 'water', but it must be 'liquid' or a gas"),
    (lambda: fem.compress(0.3, 0.31, 0.1, fluid=Fluid("gas", -1.0, 1.0)), "fluid.ambient = -1.0"),
    (lambda: fem.compress(0.3, 0.31, 0.1, fluid=Fluid("gas", 1.0, 2.0)), "fluid.gamma = 2.0"),
    (lambda: fem.compress(0.3, 0.31, 0.1, fluid=Fluid("liquid", 1.0, 1.0)), "a liquid has no ambient pressure"),
    (lambda: fem.compress(0.3, 0.31, 0.1, fluid=Fluid("plasma")), "fluid.kind = 'plasma'"),
    (lambda: fem.compress_height(0.3, 0.31, 0.2, fluid="water"), "fluid = 'water'"),
]


@pytest.mark.parametrize(("call", "quoted"), CASES)
def test_bad_input_is_a_one_line_input_error(call, quoted):
    """InputError, one line, quoting the offending value."""
    with pytest.raises(InputError) as info:
        call()
    message = str(info.value)
    assert quoted in message, message
    assert "\n" not in message, message


def test_abrupt_tiny_element_is_rejected_saying_why():
    """Nodes 0, 1e-14, then 20 uniform to 1: the first element is 1e-14 long, 5e12 times shorter
    than its neighbour, which no double-precision stiffness can use: InputError naming the element,
    its length and the limit (before, a stretch of -170.6 came back with exit 0)."""
    nodes = np.concatenate([[0.0, 1e-14], np.linspace(0.05, 1.0, 20)])
    with pytest.raises(InputError, match=r"element 1 \(r from 0.0 to 1e-14\) is 1e-14 R long") as info:
        fem.inflate(0.3, 0.3, mesh=nodes)
    assert "\n" not in str(info.value)


def test_abrupt_size_jump_is_rejected():
    """A mesh whose neighbouring elements differ 5000-fold in length (above MAX_RATIO = 1e3)."""
    nodes = np.concatenate([np.linspace(0.0, 1e-5, 3), np.linspace(0.05, 1.0, 20)])
    with pytest.raises(InputError, match="differ in length by a factor"):
        fem.inflate(0.3, 0.3, mesh=nodes)
