r"""A curved indenter's lower surface as the finite elements need it: z(rho) and three derivatives.

The contact zone's energy (``obstacle``) is written in the radius rho alone, the height being
eta = h + z(rho); its tangent needs z', z'' and z''' (the sheet's meridional stretch there is
rho' sqrt(1 + z'^2)). ``SURFACES`` maps an indenter kind to the closed forms of its surface; the
indenter's parameters are in units of R. For a sphere of radius K, with q = sqrt(K^2 - rho^2):

    z = K - q,   z' = rho / q,   z'' = K^2 / q^3,   z''' = 3 K^2 rho / q^5,

the curved area of the cap rho < rho_c is 2 pi K z(rho_c), and the surface ends at its equator,
``reach`` = K. The principal curvatures of any profile are kappa_1 = z'' / (1 + z'^2)^(3/2)
(meridional) and kappa_2 = z' / (rho sqrt(1 + z'^2)) (hoop; z''(0) on the axis): 1/K both on a sphere.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

import numpy as np

from pocket.core.indenters import Indenter

__all__ = ["Surface", "SURFACES", "surface"]


@dataclasses.dataclass(frozen=True)
class Surface:
    """z and its derivatives (each: rho array -> array of its shape, units R), the curved area of the
    cap rho < rho_c (units R^2) and ``reach``, the largest radius the surface covers (units R)."""

    height: Callable[[np.ndarray], np.ndarray]
    slope: Callable[[np.ndarray], np.ndarray]
    second: Callable[[np.ndarray], np.ndarray]
    third: Callable[[np.ndarray], np.ndarray]
    area: Callable[[float], float]
    reach: float

    def curvatures(self, rho) -> tuple[np.ndarray, np.ndarray]:
        """(kappa_1, kappa_2) at ``rho`` (units 1/R; module docstring)."""
        rho = np.asarray(rho, dtype=float)
        g, second = self.slope(rho), self.second(rho)
        c = np.sqrt(1.0 + g * g)
        with np.errstate(invalid="ignore", divide="ignore"):
            hoop = np.where(rho > 0.0, g / (rho * c), second)  # z'/rho -> z''(0) on the axis
        return second / c**3, hoop


def _sphere(params: dict) -> Surface:
    k = params["radius"]

    def root(rho):  # NaN past the equator, which the solver rejects
        with np.errstate(invalid="ignore"):
            return np.sqrt(k * k - np.square(rho))

    return Surface(height=lambda rho: k - root(rho), slope=lambda rho: rho / root(rho),
                   second=lambda rho: k * k / root(rho) ** 3, third=lambda rho: 3.0 * k * k * rho / root(rho) ** 5,
                   area=lambda rho_c: 2.0 * np.pi * k * float(k - root(rho_c)), reach=k)


#: indenter kind -> its surface from its parameters (units R)
SURFACES: dict[str, Callable[[dict], Surface]] = {"sphere": _sphere}


def surface(indenter: Indenter) -> Surface:
    """The surface of ``indenter`` (its kind must be in ``SURFACES``)."""
    return SURFACES[indenter.kind](dict(indenter.params))
