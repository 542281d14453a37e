"""The integrated equations against the paper's eqs (4)-(7) and (9), independently.

The membrane equations of ``shooting.equations.rhs`` are checked at random states:
the derivatives they return must satisfy normal and tangential equilibrium,
eq (4), with the curvatures of eq (5) and the tensions of eq (6) typed here from
the paper and differentiated by sympy. Eq (7) must agree symbolically; eq (9) only
with the corrected pressure term.
"""

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from pocket.shooting.equations import pole_state, rhs
from pocket.shooting.integrator import OK, integrate
from pocket.shooting.laws import law_of

L1, L2, AL = sp.symbols("lambda_1 lambda_2 alpha", positive=True)
# Eq (6), in units of 2 C1 T, typed from the paper.
T1 = (L1 / L2 - 1 / (L1**3 * L2**3)) * (1 + AL * L2**2)
T2 = (L2 / L1 - 1 / (L1**3 * L2**3)) * (1 + AL * L1**2)
_T = sp.lambdify((L1, L2, AL), [T1, T2, sp.diff(T1, L1), sp.diff(T1, L2)])


def _derivatives(r, y, alpha, p):
    out = np.empty(5)
    law = law_of(alpha)
    rhs(r, y, law.code, law.params, p, out)
    return out


@settings(max_examples=200, deadline=None)
@given(
    r=st.floats(0.05, 0.95),
    l1=st.floats(1.01, 2.5),  # stretched: t1 > 0 needs lambda_1^4 lambda_2^2 > 1
    l2=st.floats(1.01, 2.5),
    psi=st.floats(0.05, 1.4),
    alpha=st.floats(0.0, 1.5),
    p=st.floats(0.01, 5.0),
)
def test_rhs_satisfies_equilibrium_eq4_with_eq5_curvatures(r, l1, l2, psi, alpha, p):
    """Exact answer: kappa_1 T1 + kappa_2 T2 = P and dT1/drho + (T1 - T2)/rho = 0."""
    y = np.array([l2 * r, 0.0, psi, l1, 0.0])
    d = _derivatives(r, y, alpha, p)
    rho = y[0]
    drho, deta, dpsi, dl1 = d[0], d[1], d[2], d[3]
    dl2 = (drho - l2) / r
    # Second derivatives of the meridian w.r.t. r, then w.r.t. rho (eq (5) is written in rho).
    d2rho = dl1 * np.cos(psi) - l1 * np.sin(psi) * dpsi
    d2eta = -dl1 * np.sin(psi) - l1 * np.cos(psi) * dpsi
    e1 = deta / drho
    e2 = (d2eta * drho - deta * d2rho) / drho**3
    kappa1 = -e2 / (1 + e1**2) ** 1.5
    kappa2 = -e1 / (rho * np.sqrt(1 + e1**2))
    t1, t2, a, b = _T(l1, l2, alpha)
    # rtol 1e-9: the residuals are differences of O(1) terms evaluated in double precision.
    assert kappa1 * t1 + kappa2 * t2 == pytest.approx(p, rel=1e-9)
    dt1_drho = (a * dl1 + b * dl2) / drho
    assert dt1_drho + (t1 - t2) / rho == pytest.approx(0.0, abs=1e-9 * (abs(t1) + abs(t2)) / rho)


def test_eq7_is_the_tangential_equilibrium_used():
    """Exact answer: the paper's eq (7) equals our lambda_1' with w = rho' (symbolic)."""
    r, w = sp.symbols("r w", positive=True)
    dl2 = (w - L2) / r
    ours = ((T2 - T1) * w / (L2 * r) - sp.diff(T1, L2) * dl2) / sp.diff(T1, L1)
    paper = (
        (w / L2) * (L2 / L1 - L1 / L2 - AL * (1 / (L1 * L2**3) - 1 / (L1**3 * L2)))
        - (w - L2) * ((-L1 / L2**2 + 3 / (L1**3 * L2**4)) * (1 + AL * L2**2)
                      + 2 * AL * L2 * (L1 / L2 - 1 / (L1**3 * L2**3)))
    ) / r / ((1 / L2 + 3 / (L1**4 * L2**3)) * (1 + AL * L2**2))
    assert sp.simplify(ours - paper) == 0


def test_eq9_holds_only_with_the_corrected_pressure_term():
    """Exact answer: w' = rho'' from our equations equals eq (9) with p r (not Phat (1+alpha)/2).

    p = P R / (2 C1 T) = 3 (1 + alpha) Phat, so the corrected term is 3 (1 + alpha) Phat r.
    """
    r, psi, phat = sp.symbols("r psi Phat", positive=True)
    p = 3 * (1 + AL) * phat
    rho = L2 * r
    w = L1 * sp.cos(psi)
    dpsi = L1 * (p - T2 * sp.sin(psi) / rho) / T1
    dl1 = sp.Symbol("dl1")  # eq (9) carries d lambda_1/dr through; leave it symbolic
    ours = dl1 * sp.cos(psi) - L1 * sp.sin(psi) * dpsi
    root = L1 * sp.sin(psi)  # (lambda_1^2 - w^2)^(1/2) with psi in (0, pi)
    def eq9(term):
        return (L1 * root / T1 * (root / (L1 * L2) * T2 - term)) / r + w / L1 * dl1
    assert sp.simplify(ours - eq9(p * r)) == 0
    assert sp.simplify(ours - eq9(phat * (1 + AL) / 2)) != 0


@pytest.mark.parametrize(("alpha", "phat", "l0"), [(47 / 160, 0.31, 1.16), (0.0, 0.05, 1.035)])
def test_pole_series_is_on_the_regular_solution(alpha, phat, l0):
    """Exact answer: the shot is independent of where the series starts.

    The series error is O(r0^3): starting at r0 and at 10 r0 must give the same
    clamp state to within the series error at 10 r0 plus the integration error.
    """
    p = 3 * (1 + alpha) * phat
    ends = []
    for r0 in (1e-5, 1e-4):
        law = law_of(alpha)
        status, _, y, _ = integrate(pole_state(l0, law, p, r0), r0, law, p, rtol=1e-12)
        assert status == OK
        ends.append(y)
    # (1e-4)^3 = 1e-12 series error, 1e-11 allows for the ODE error at rtol 1e-12
    np.testing.assert_allclose(ends[0], ends[1], rtol=1e-10, atol=1e-11)
