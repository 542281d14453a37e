r"""The fluid in the pocket: a liquid (fixed volume) or an ideal gas sealed at the initial pressure.

Pressures are gauge pressures (above the ambient pressure P_atm), as P_I is. A
liquid keeps its volume: V = V_I. An ideal gas sealed at P_I follows the
polytropic law

    (P + P_atm) V^gamma = (P_I + P_atm) V_I^gamma,

gamma = 1 for slow (isothermal) compression, 1.4 for fast (adiabatic) compression
of air; gamma lies in [1, 5/3] (5/3 is a monatomic gas). So the volume at the
pressure P is

    V(P) = V_I ((P_I + P_atm) / (P + P_atm))^(1/gamma),

and as P_atm grows the gas stiffens towards the liquid: V(P) -> V_I. In the
model's units the ambient pressure is dimensionless like every pressure,
Phat_atm = P_atm R / (E T).
"""

from __future__ import annotations

import dataclasses
import math

from .errors import InputError
from .inputs import check_finite, quote

__all__ = ["AMBIENT", "GAMMA_RANGE", "LIQUID", "Fluid", "as_fluid", "gas"]

#: polytropic exponents accepted: isothermal to monatomic adiabatic
GAMMA_RANGE = (1.0, 5.0 / 3.0)
#: the standard atmosphere, Pa
AMBIENT = 101325.0


@dataclasses.dataclass(frozen=True)
class Fluid:
    """``kind`` "liquid" or "gas"; a gas has ``ambient`` (P_atm, in the unit of the pressures) and ``gamma``."""

    kind: str = "liquid"
    ambient: float = math.inf
    gamma: float = 1.0

    @property
    def is_gas(self) -> bool:
        return self.kind == "gas"

    def volume_ratio(self, pressure: float, pressure_initial: float) -> float:
        """V / V_I at the gauge ``pressure`` for a fluid sealed at ``pressure_initial`` (1 for a liquid)."""
        if not self.is_gas:
            return 1.0
        return ((pressure_initial + self.ambient) / (pressure + self.ambient)) ** (1.0 / self.gamma)

    def scaled(self, pressure_scale: float) -> Fluid:
        """The same fluid with its ambient pressure divided by ``pressure_scale`` (E T / R: Phat_atm)."""
        return self if not self.is_gas else dataclasses.replace(self, ambient=self.ambient / pressure_scale)

    def describe(self) -> dict:
        """The fluid as a flat JSON-ready dict."""
        return {"fluid": self.kind} if not self.is_gas else {"fluid": "gas", "ambient": self.ambient,
                                                              "gamma": self.gamma}


LIQUID = Fluid()


def gas(ambient, gamma=1.0, where: str = "fluid") -> Fluid:
    """An ideal gas at ambient pressure ``ambient`` (> 0) with exponent ``gamma`` in GAMMA_RANGE, checked."""
    ambient_value = check_finite(f"{where}.ambient", ambient)
    if ambient_value <= 0.0:
        raise InputError(f"{where}.ambient = {quote(ambient)}, but the ambient (absolute) pressure must be > 0")
    gamma_value = check_finite(f"{where}.gamma", gamma)
    low, high = GAMMA_RANGE
    if not low <= gamma_value <= high:
        raise InputError(f"{where}.gamma = {quote(gamma)}, but it must lie in [1, 5/3] (1 isothermal, 1.4 air "
                         "compressed adiabatically, 5/3 a monatomic gas)")
    return Fluid("gas", ambient_value, gamma_value)


def as_fluid(value) -> Fluid:
    """The fluid of ``value``: None or "liquid" is ``LIQUID``; a ``Fluid`` is re-checked and returned as given."""
    if value is None or (isinstance(value, str) and value == "liquid"):
        return LIQUID
    if not isinstance(value, Fluid):
        raise InputError(f"fluid = {quote(value)}, but it must be 'liquid' or a gas (pocket.core.fluids.gas)")
    if value.kind == "liquid":
        if value != LIQUID:
            raise InputError(f"fluid = {quote(value)}: a liquid has no ambient pressure or gamma")
        return value
    if value.kind != "gas":
        raise InputError(f"fluid.kind = {quote(value.kind)}, but it must be 'liquid' or 'gas'")
    gas(value.ambient, value.gamma)
    return value
