r"""A curved indenter's lower surface as the finite elements need it: z(rho) and three derivatives.

The contact zone's energy (``obstacle``) is written in the radius rho alone, the height being
eta = h + z(rho); its tangent needs z', z'' and z''' (the sheet's meridional stretch there is
rho' sqrt(1 + z'^2)). ``SURFACES`` maps an indenter kind to the closed forms of its surface; the
indenter's parameters are in units of R. For a sphere of radius K, with q = sqrt(K^2 - rho^2):

    z = K - q,   z' = rho / q,   z'' = K^2 / q^3,   z''' = 3 K^2 rho / q^5,

the curved area of the cap rho < rho_c is 2 pi K z(rho_c), and the surface ends at its equator,
``reach`` = K. The principal curvatures of any profile are kappa_1 = z'' / (1 + z'^2)^(3/2)
(meridional) and kappa_2 = z' / (rho sqrt(1 + z'^2)) (hoop; z''(0) on the axis): 1/K both on a sphere.

A user's profile (``pocket.core.profiles.Shape``) gives z, z' and z'' up to its ``extent``, its
``reach``. Its third derivative enters only the tangent (through c_ss, ``obstacle``), never the
residual, so it is the central difference of z'' with step d = THIRD_STEP * extent (z'' is even,
z''(-rho) = z''(rho); one-sided at the extent): its error, O(d^2 z^(5)) + O(eps z'' / d), about
1e-10 relative, leaves the solution exact and Newton quadratic down to that level. The curved area
of the cap rho < rho_c is the integral of 2 pi rho sqrt(1 + z'^2), by adaptive quadrature to
``AREA_RTOL``.
"""

from __future__ import annotations

import dataclasses
import itertools
from collections.abc import Callable

import numpy as np

from pocket.core.indenters import Indenter

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


def _sphere(params: dict) -> Surface:
    k = params["radius"]

    def root(rho):  # NaN past the equator, which the solver rejects
        with np.errstate(invalid="ignore"):
            return np.sqrt(k * k - np.square(rho))

    return Surface(height=lambda rho: k - root(rho), slope=lambda rho: rho / root(rho),
                   second=lambda rho: k * k / root(rho) ** 3, third=lambda rho: 3.0 * k * k * rho / root(rho) ** 5,
                   area=lambda rho_c: 2.0 * np.pi * k * float(k - root(rho_c)), reach=k)


def _profile(params: dict) -> Surface:
    shape = params["shape"]
    extent, step = shape.extent, THIRD_STEP * shape.extent

    def third(rho):
        rho = np.asarray(rho, dtype=float)
        hi = np.minimum(rho + step, extent)
        return (shape.second(hi) - shape.second(np.abs(rho - step))) / (hi - (rho - step))

    def area(rho_c: float) -> float:
        """The curved area inside rho_c, summed between the table's rows (``shape.knots``), where the integrand
        is smooth: across a row its second derivative jumps, and one adaptive quadrature over many rows stalls
        short of its tolerance (and warns)."""
        from scipy.integrate import quad

        def band(rho):
            return 2.0 * np.pi * rho * np.sqrt(1.0 + float(shape.slope(np.asarray(rho))) ** 2)

        bounds = [0.0, *(k for k in shape.knots if 0.0 < k < rho_c), rho_c]
        return float(sum(quad(band, lo, hi, epsabs=0.0, epsrel=AREA_RTOL, limit=200)[0]
                         for lo, hi in itertools.pairwise(bounds)))

    return Surface(height=shape.height, slope=shape.slope, second=shape.second, third=third, area=area,
                   reach=extent, end="the end of the indenter's profile")


#: indenter kind -> its surface from its parameters (units R)
SURFACES: dict[str, Callable[[dict], Surface]] = {"sphere": _sphere, "profile": _profile}


def surface(indenter: Indenter) -> Surface:
    """The surface of ``indenter`` (its kind must be in ``SURFACES``)."""
    return SURFACES[indenter.kind](dict(indenter.params))
