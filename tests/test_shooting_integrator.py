"""The compiled DOP853 against scipy's ``solve_ivp(method="DOP853")`` on the same equations."""

import numpy as np
import pytest
from pocket.shooting.equations import pole_state, rhs
from pocket.shooting.integrator import AXIS, FOLD, OK, integrate
from pocket.shooting.laws import law_of
from scipy.integrate import solve_ivp


def _scipy(y0, r0, alpha, p, rtol):
    law = law_of(alpha)

    def f(r, y):
        out = np.empty(5)
        rhs(r, y, law.code, law.params, p, out)
        return out

    # the same first step as ours, so that both take the same steps
    return solve_ivp(f, (r0, 1.0), y0, method="DOP853", rtol=rtol, atol=rtol * 1e-2, first_step=1e-6)


@pytest.mark.parametrize(("alpha", "p", "l0"), [(47 / 160, 1.2, 1.16), (0.0, 0.2, 1.04), (1.0, 3.0, 1.3)])
def test_matches_solve_ivp(alpha, p, l0):
    """Exact answer: scipy's DOP853 at rtol 1e-13; ours at 1e-10 within the error scipy makes at 1e-10.

    Same tableau and step control, so the step counts agree too (to a step or two:
    rounding can flip one accept/reject decision).
    """
    y0 = pole_state(l0, law_of(alpha), p, 1e-5)
    status, r, y, steps = integrate(y0, 1e-5, law_of(alpha), p, rtol=1e-10, store=5000)
    peer = _scipy(y0, 1e-5, alpha, p, 1e-10)
    exact = _scipy(y0, 1e-5, alpha, p, 1e-13).y[:, -1]
    assert status == OK
    assert r == 1.0
    err_ours = np.max(np.abs(y - exact))
    err_peer = np.max(np.abs(peer.y[:, -1] - exact))
    assert err_ours <= max(2 * err_peer, 1e-11), (err_ours, err_peer)
    assert abs(steps.shape[0] - peer.t.size) <= 2


def test_stops_when_the_meridian_curls_back():
    """Exact answer: far too much pressure for the pole stretch curls the meridian (status, not NaN)."""
    law, l0 = law_of(0.3), 1.01
    status, r, y, _ = integrate(pole_state(l0, law, 50.0, 1e-5), 1e-5, law, 50.0, rtol=1e-10)
    assert status in (AXIS, FOLD)
    assert r < 1.0
    assert np.all(np.isfinite(y))


def test_tableau_is_scipys_bit_for_bit():
    """Exact answer: the stored DOP853 coefficients (pocket.shooting.tableau) equal scipy's exactly,
    so the compiled integrator takes scipy's steps without importing scipy.integrate."""
    from pocket.shooting import tableau
    from scipy.integrate import DOP853

    for name in ("A", "B", "C", "E3", "E5", "A_EXTRA", "C_EXTRA", "D"):
        assert np.array_equal(getattr(tableau, name), getattr(DOP853, name)), name
    assert DOP853.n_stages == tableau.N_STAGES


def test_per_component_absolute_tolerance():
    """Exact answer: an absolute tolerance per component equal to the scalar one changes nothing
    (the same steps, bit for bit); a tighter one on the volume alone reaches the clamp with the
    same volume to the relative tolerance."""
    law = law_of(47 / 160)
    y0 = pole_state(1.16, law, 1.2, 1e-5)
    scalar = integrate(y0, 1e-5, law, 1.2, rtol=1e-10, atol=1e-12, store=5000)
    vector = integrate(y0, 1e-5, law, 1.2, rtol=1e-10, atol=np.full(5, 1e-12), store=5000)
    assert np.array_equal(scalar[3], vector[3])
    tight = integrate(y0, 1e-5, law, 1.2, rtol=1e-10, atol=[1e-12] * 4 + [1e-15], store=5000)
    assert tight[0] == OK
    assert tight[2][4] == pytest.approx(scalar[2][4], rel=1e-9)


@pytest.mark.parametrize(("alpha", "p", "l0"), [(47 / 160, 1.2, 1.16), (1.0, 3.0, 1.3)])
def test_dense_output_matches_solve_ivp(alpha, p, l0):
    """Exact answer: scipy's DOP853 at rtol 1e-13 between the steps too; ours at 1e-10 with a ``grid`` within the
    error scipy's own dense output makes at 1e-10 (the same interpolant of the same steps, to a step or two as in
    ``test_matches_solve_ivp``), or 1e-11. The grid changes no step: the end state is the shot's without it, bit for
    bit; a point at or before the start is the start."""
    law = law_of(alpha)
    y0 = pole_state(l0, law, p, 1e-5)
    grid = np.linspace(0.0, 1.0, 41)
    status, _, y, dense = integrate(y0, 1e-5, law, p, rtol=1e-10, grid=grid)
    assert status == OK
    assert np.array_equal(y, integrate(y0, 1e-5, law, p, rtol=1e-10)[2])
    assert np.array_equal(dense[:, 0], grid)
    assert np.array_equal(dense[0, 1:], y0)
    peer = solve_ivp(*_scipy_args(y0, alpha, p), rtol=1e-10, atol=1e-12, first_step=1e-6, dense_output=True)
    exact = solve_ivp(*_scipy_args(y0, alpha, p), rtol=1e-13, atol=1e-15, first_step=1e-6, dense_output=True)
    err_ours = np.max(np.abs(dense[1:, 1:] - exact.sol(grid[1:]).T))
    err_peer = np.max(np.abs(peer.sol(grid[1:]).T - exact.sol(grid[1:]).T))
    assert err_ours <= max(2 * err_peer, 1e-11), (err_ours, err_peer)


def _scipy_args(y0, alpha, p):
    """(fun, span, y0, method) of ``solve_ivp`` for our equations from r = 1e-5 to the clamp."""
    law = law_of(alpha)

    def f(r, y):
        out = np.empty(5)
        rhs(r, y, law.code, law.params, p, out)
        return out

    return f, (1e-5, 1.0), y0, "DOP853"
