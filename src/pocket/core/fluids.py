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
    """The fluid in the pocket: a liquid (fixed volume) or an ideal gas sealed at the initial pressure.

    A gas follows (P + P_atm) V^gamma = (P_I + P_atm) V_I^gamma, pressures gauge. Make a gas with ``gas``
    (checked); ``LIQUID`` is the liquid.

    Parameters
    ----------
    kind : {"liquid", "gas"}
        The fluid.
    ambient : float
        A gas's ambient (absolute) pressure P_atm, in the unit of the pressures it meets: Pa in physical units,
        Phat_atm = P_atm R / (E T) for a solver.
    gamma : float
        A gas's polytropic exponent, in ``GAMMA_RANGE`` (1 isothermal, 1.4 air compressed adiabatically).

    Examples
    --------
    Air at 1 atm, compressed isothermally (Boyle's law) from a gauge pressure of 5 kPa to 6 kPa:

    >>> from pocket.core.fluids import LIQUID, gas
    >>> air = gas(101325.0)
    >>> print(round(air.volume_ratio(6e3, 5e3), 6), round((5e3 + 101325) / (6e3 + 101325), 6))
    0.990683 0.990683
    >>> print(LIQUID.volume_ratio(6e3, 5e3))
    1.0
    >>> print(air.scaled(1e4).describe())
    {'fluid': 'gas', 'ambient': 10.1325, 'gamma': 1.0}
    """

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
    """An ideal gas at the ambient pressure ``ambient`` with the polytropic exponent ``gamma``, checked.

    Parameters
    ----------
    ambient : float
        P_atm > 0, absolute: in Pa for a case, as Phat_atm = P_atm R / (E T) for a solver.
    gamma : float, optional
        In ``GAMMA_RANGE``, [1, 5/3]: 1 isothermal, 1.4 air compressed adiabatically, 5/3 a monatomic gas.
    where : str, optional
        The prefix of the names in error messages.

    Returns
    -------
    Fluid

    Raises
    ------
    InputError
        For an ambient pressure that is not > 0, or a gamma outside ``GAMMA_RANGE``.

    Examples
    --------
    A gas stiffens towards the liquid as its ambient pressure grows:

    >>> from pocket import shooting
    >>> from pocket.core.fluids import gas
    >>> soft = shooting.compress(47 / 160, 0.31, 0.19, fluid=gas(1.0))
    >>> stiff = shooting.compress(47 / 160, 0.31, 0.19, fluid=gas(1e6))
    >>> liquid = shooting.compress(47 / 160, 0.31, 0.19)
    >>> print(soft.pressure_ratio < stiff.pressure_ratio, abs(stiff.pressure_ratio - liquid.pressure_ratio) < 1e-5)
    True True
    >>> gas(1.0, gamma=2.0)
    Traceback (most recent call last):
        ...
    pocket.core.errors.InputError: fluid.gamma = 2.0, but it must lie in [1, 5/3] ...
    """
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
    """The fluid of ``value``, as every compression entry point takes its ``fluid`` argument.

    Parameters
    ----------
    value : Fluid or str or None
        None or ``"liquid"`` is ``LIQUID``; a ``Fluid`` is re-checked and returned as given.

    Returns
    -------
    Fluid

    Raises
    ------
    InputError
        For anything else, or a fluid that is not a liquid or a valid gas.

    Examples
    --------
    >>> from pocket.core.fluids import LIQUID, as_fluid
    >>> print(as_fluid(None) is LIQUID, as_fluid("liquid") is LIQUID)
    True True
    >>> as_fluid("air")
    Traceback (most recent call last):
        ...
    pocket.core.errors.InputError: fluid = 'air', but it must be 'liquid' or a gas (pocket.core.fluids.gas)
    """
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
