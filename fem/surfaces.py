r"""A curved indenter's lower surface as the finite elements need it: z(rho) and three derivatives.

The contact zone's energy (``obstacle``) is written in the radius rho alone, the height being
eta = h + z(rho); its tangent needs z', z'' and z''' (the sheet's meridional stretch there is
rho' sqrt(1 + z'^2)). ``SURFACES`` maps an indenter class to the closed forms of its surface; the
indenter's parameters are in units of R. For a sphere of radius K, with q = sqrt(K^2 - rho^2):

    z = K - q,   z' = rho / q,   z'' = K^2 / q^3,   z''' = 3 K^2 rho / q^5,

the curved area of the cap rho < rho_c is 2 pi K z(rho_c), and the surface ends at its equator,
``reach`` = K. The principal curvatures of any profile are kappa_1 = z'' / (1 + z'^2)^(3/2)
(meridional) and kappa_2 = z' / (rho sqrt(1 + z'^2)) (hoop; z''(0) on the axis): 1/K both on a sphere.

Any other curved indenter (a user's profile, ``pocket.core.profiles.Shape``) gives z, z' and z'' itself
(``pocket.core.indenters.Indenter``) up to its ``reach``. Its third derivative enters only the tangent
(through c_ss, ``obstacle``), never the residual, so it is the central difference of z'' with step
d = THIRD_STEP * reach (z'' is even, z''(-rho) = z''(rho); one-sided at the reach): its error,
O(d^2 z^(5)) + O(eps z'' / d), about 1e-10 relative, leaves the solution exact and Newton quadratic down
to that level. The curved area of the cap rho < rho_c is the integral of 2 pi rho sqrt(1 + z'^2), by
adaptive quadrature to ``AREA_RTOL`` between the indenter's ``knots``.
"""

from __future__ import annotations

import dataclasses
import itertools
from collections.abc import Callable
from typing import Any

import numpy as np

from pocket.core.indenters import Indenter, Sphere

__all__ = ["AREA_RTOL", "SURFACES", "THIRD_STEP", "Surface", "surface"]

#: step of the central difference giving a profile's third derivative (a fraction of its extent; ~eps^(1/3))
THIRD_STEP = 6e-6
#: relative tolerance of the quadrature giving a profile's curved contact area
AREA_RTOL = 1e-13


@dataclasses.dataclass(frozen=True)
class Surface:
    """z and its derivatives (each: rho array -> array of its shape, units R), the curved area of the
    cap rho < rho_c (units R^2) and ``reach``, the largest radius the surface covers (units R), which
    ``end`` names in messages (a sphere's equator)."""

    height: Callable[[np.ndarray], np.ndarray]
    slope: Callable[[np.ndarray], np.ndarray]
    second: Callable[[np.ndarray], np.ndarray]
    third: Callable[[np.ndarray], np.ndarray]
    area: Callable[[float], float]
    reach: float
    end: str = "the indenter's equator"

    def curvatures(self, rho) -> tuple[np.ndarray, np.ndarray]:
        """(kappa_1, kappa_2) at ``rho`` (units 1/R; module docstring)."""
        rho = np.asarray(rho, dtype=float)
        g, second = self.slope(rho), self.second(rho)
        c = np.sqrt(1.0 + g * g)
        with np.errstate(invalid="ignore", divide="ignore"):
            hoop = np.where(rho > 0.0, g / (rho * c), second)  # z'/rho -> z''(0) on the axis
        return second / c**3, hoop


def _sphere(indenter: Sphere) -> Surface:
    k = indenter.radius

    def root(rho):  # NaN past the equator, which the solver rejects
        with np.errstate(invalid="ignore"):
            return np.sqrt(k * k - np.square(rho))

    return Surface(height=lambda rho: k - root(rho), slope=lambda rho: rho / root(rho),
                   second=lambda rho: k * k / root(rho) ** 3, third=lambda rho: 3.0 * k * k * rho / root(rho) ** 5,
                   area=lambda rho_c: 2.0 * np.pi * k * float(k - root(rho_c)), reach=indenter.reach)


def _curved(indenter: Indenter) -> Surface:
    extent, step = indenter.reach, THIRD_STEP * indenter.reach

    def third(rho):
        rho = np.asarray(rho, dtype=float)
        hi = np.minimum(rho + step, extent)
        return (indenter.second(hi) - indenter.second(np.abs(rho - step))) / (hi - (rho - step))

    def area(rho_c: float) -> float:
        """The curved area inside rho_c, summed between the indenter's ``knots`` (a table's rows), where the
        integrand is smooth: across a knot its second derivative jumps, and one adaptive quadrature over many rows
        stalls short of its tolerance (and warns)."""
        from scipy.integrate import quad

        def band(rho):
            return 2.0 * np.pi * rho * np.sqrt(1.0 + float(indenter.slope(np.asarray(rho))) ** 2)

        bounds = [0.0, *(k for k in indenter.knots if 0.0 < k < rho_c), rho_c]
        return float(sum(quad(band, lo, hi, epsabs=0.0, epsrel=AREA_RTOL, limit=200)[0]
                         for lo, hi in itertools.pairwise(bounds)))

    return Surface(height=indenter.height, slope=indenter.slope, second=indenter.second, third=third, area=area,
                   reach=extent, end="the end of the indenter's profile")


#: indenter class -> its surface in closed form (units R); any other curved indenter's is built from its own
#: z, z' and z'' (module docstring)
SURFACES: dict[type[Indenter], Callable[[Any], Surface]] = {Sphere: _sphere}


def surface(indenter: Indenter) -> Surface:
    """The surface of the curved ``indenter``: its closed form in ``SURFACES``, else built from its own z, z'
    and z''."""
    return SURFACES.get(type(indenter), _curved)(indenter)
