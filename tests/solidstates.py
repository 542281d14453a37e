"""Solid states for the tests of the bordered system's Jacobian: a bent sheet with noise, and the check of the
Jacobian against central differences of the residual (``pocket.solid.equations.system``)."""

from __future__ import annotations

import numpy as np
from pocket.solid.equations import system

__all__ = ["bent", "check_jacobian"]


def bent(m, rng) -> np.ndarray:
    """A displacement u (basis_u.N,) of the model ``m``: the sheet lifted as 0.3 (1 - r^2) and stretched as
    0.05 r (1 - r), with noise of 1e-4 (noise over the node spacing << 1: J > 0 everywhere)."""
    x = m.basis_u.doflocs[0]
    u = np.zeros(m.basis_u.N)
    ur, uz = m.basis_u.split_indices()
    u[uz] = 0.3 * (1 - x[uz] ** 2) + 1e-4 * rng.standard_normal(uz.size)
    u[ur] = x[ur] * (0.05 * (1 - x[ur]) + 1e-4 * rng.standard_normal(ur.size))
    return u


def check_jacobian(m, y, control, rng) -> tuple[np.ndarray, float]:
    """Assert that the Jacobian of ``system`` at the state y, applied to a random direction over the free
    unknowns, is the central difference quotient of the residual along it (step 1e-6: O(step^2) truncation and
    ~1e-10 relative round-off, far below a wrong term's O(1)). (the direction (y.size,), the absolute
    tolerance used)."""
    _, jac, keep = system(m, y, control)
    direction = np.zeros_like(y)
    direction[keep] = rng.standard_normal(keep.size)
    step = 1e-6
    quotient = (system(m, y + step * direction, control)[0] - system(m, y - step * direction, control)[0]) / (2 * step)
    exact = jac @ direction[keep]
    atol = 1e-6 * np.abs(exact).max()
    np.testing.assert_allclose(exact, quotient, rtol=1e-5, atol=atol)
    return direction, atol
