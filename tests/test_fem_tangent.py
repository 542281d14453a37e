"""The bordered tangent is the derivative of the residual (fem/kernel.py, fem/model.py, fem/gas.py).

Exact answer: for a smooth residual R and its jacobian J, the Taylor remainder
|R(y + t d) - R(y) - t J d| falls as t^2. Checked at converged states: inflated
(pressure and volume control), pressed on the edge-fitted mesh with the contact
active (every unknown: the nodal values, the pressure, the plate height h and
the contact radius a, whose derivative moves the mesh; under force, height and
contact-radius control), and pressed with the penalty plate (height and force
control); for a Mooney-Rivlin alpha with P1 and P2, for the other laws with P2,
and with a liquid and a gas (whose volume row V/V_I - q(P) adds the corner
-q'(P): the pressure's share of the direction tests it).
"""

from dataclasses import replace

import numpy as np
import pytest
from pocket.fem import fitted, inflation, model, penalty
from pocket.fem.api import default_mesh
from pocket.fem.gas import sealed
from pocket.fem.material import law_of
from pocket.fem.newton import Tolerances

from pocket.core.fluids import gas
from pocket.core.materials import check

ALPHA, PHAT = 47 / 160, 0.31
RUBBERS = {
    "alpha": ALPHA,
    "yeoh": check("yeoh", {"c10": 0.5, "c20": -0.02, "c30": 0.003}),
    "gent": check("gent", {"mu": 1.0, "jm": 6.0}),
    "ogden": check("ogden", {"mu": [1.1, 0.02, -0.05], "exponents": [1.4, 4.5, -2.2]}),
}
#: (order, rubber, gas ambient Phat_atm and gamma or None for a liquid)
CASES = [(1, "alpha", None), (2, "alpha", None), (2, "yeoh", None), (2, "gent", None), (2, "ogden", None),
         (1, "alpha", (0.5, 1.4)), (2, "gent", (0.3, 1.0))]


@pytest.fixture(scope="module", params=CASES, ids=lambda c: f"P{c[0]}-{c[1]}-{'gas' if c[2] else 'liquid'}")
def states(request):
    """An inflated and a pressed state (both contact methods) on 12 elements, and the fluid's volume row."""
    order, rubber, fluid = request.param
    m = model.discretize(RUBBERS[rubber], default_mesh(12), order, 1e3)
    tol = Tolerances()
    y_i, _ = inflation.to_pressure(m, PHAT, tol)
    fill = model.Control(volume=inflation.volume(m, y_i), gas=None if fluid is None else sealed(gas(*fluid), PHAT))
    y_f, _ = fitted.first_contact(m, y_i, fill, 0.05, tol)
    y_f, _ = fitted.force_path(m, y_f, fill, 0.4, tol)
    lam = np.zeros((m.elements, m.ref.t.size))
    y_p, _ = penalty.press_to_height(m, np.concatenate([y_i, [y_i[1]]]), fill, 0.42, lam, tol)
    return m, y_i, y_f, y_p, fill


def _taylor_slope(m, y, mode, control, direction):
    r0, system = model.linearize(m, y, mode, control)
    x, s = direction[: m.dofs].copy(), direction[m.dofs:]
    x[m.fixed(mode)] = 0.0  # J acts on the reduced unknowns; tied dofs follow h through its column
    jd = np.concatenate(system.apply(x, s))
    steps_ = np.logspace(-2, -5, 7)
    remainders = [np.abs(model.residual(m, y + t * direction, mode, control) - r0 - t * jd).max() for t in steps_]
    return np.polyfit(np.log(steps_), np.log(remainders), 1)[0], remainders


def _direction(m, y, mode, scalars):
    nodes = np.arange(m.dofs // 2) / (m.dofs // 2 - 1)  # any smooth field of the node index will do
    u = np.column_stack([np.sin(3 * nodes), np.cos(2 * nodes)]).ravel() * 1e-2
    u[[0, m.dofs - 2, m.dofs - 1]] = 0.0
    d = np.concatenate([u, scalars])
    if mode == model.FITTED:
        d[m.tied()] = scalars[1]
    return d


@pytest.mark.parametrize("control", ["pressure", "volume"])
def test_inflated(states, control):
    """FREE state, all unknowns (nodal values and P): remainder slope 2 (within 0.1)."""
    m, y_i, _, _, fill = states
    c = model.Control(pressure=PHAT) if control == "pressure" else model.Control(volume=fill.volume)
    slope, rem = _taylor_slope(m, y_i, model.FREE, c, _direction(m, y_i, model.FREE, [1e-2]))
    assert abs(slope - 2.0) < 0.1, f"Taylor order {slope:.3f}, remainders {rem}"


@pytest.mark.parametrize("control", ["force", "height", "radius"])
@pytest.mark.parametrize("unknown", ["all", "h", "a"])
def test_edge_fitted_contact(states, control, unknown):
    """FITTED state with contact: along all unknowns at once, and along h alone and a alone
    (the mesh moves with a): remainder slope 2 (within 0.1)."""
    m, _, y, _, fill = states
    n = m.dofs
    c = {"force": replace(fill, force=0.4, scale=0.4), "height": replace(fill, height=float(y[n + 1])),
         "radius": replace(fill, radius=float(y[n + 2]))}[control]
    scalars = {"all": [1e-2, 1e-3, 1e-3], "h": [0.0, 1e-2, 0.0], "a": [0.0, 0.0, 1e-2]}[unknown]
    d = _direction(m, y, model.FITTED, scalars)
    if unknown != "all":
        d[:n] = 0.0
        d[m.tied()] = scalars[1]
    slope, rem = _taylor_slope(m, y, model.FITTED, c, d)
    assert abs(slope - 2.0) < 0.1, f"Taylor order {slope:.3f}, remainders {rem}"


@pytest.mark.parametrize("control", ["height", "force"])
def test_penalty_contact(states, control):
    """PENALTY state with the plate pressing (contact active at several quadrature points):
    remainder slope 2 (within 0.1: a point may cross the active-set kink)."""
    m, _, _, y, fill = states
    n = m.dofs
    assert (model.fields(m, y, model.PENALTY).eta > y[n + 1]).sum() >= 3, "the plate must press"
    c = (replace(fill, height=float(y[n + 1])) if control == "height"
         else replace(fill, force=model.plate_force(m, y, model.PENALTY)))
    slope, rem = _taylor_slope(m, y, model.PENALTY, c, _direction(m, y, model.PENALTY, [1e-2, 1e-3]))
    assert abs(slope - 2.0) < 0.1, f"Taylor order {slope:.3f}, remainders {rem}"


def test_tensions_are_the_papers_eq6():
    """T1 = 2 C1 T (l1/l2 - 1/(l1 l2)^3)(1 + alpha l2^2) / (E T), E = 6 (1 + alpha) C1 (eq (6))."""
    alpha, a, b = 0.29375, 1.2, 1.05
    t1, t2 = law_of(alpha).tensions(a, b)
    scale = 2.0 / (6.0 * (1.0 + alpha))
    assert t1 == pytest.approx(scale * (a / b - 1 / (a * b) ** 3) * (1 + alpha * b**2), rel=1e-14)
    assert t2 == pytest.approx(scale * (b / a - 1 / (a * b) ** 3) * (1 + alpha * a**2), rel=1e-14)
