r"""A gas sealed in the pocket: the volume row of the compression and its linearisation.

The pocket is inflated to Phat_I (volume V_I) and sealed. A liquid keeps its
volume, V = V_I: the pressure P is the free multiplier of that constraint. An
ideal gas follows the polytropic law (P gauge, Pa the ambient pressure, all in
units of E T / R)

    g(x, P) = (P + Pa) V(x)^gamma - (P_I + Pa) V_I^gamma = 0,

so P is no longer free: it is tied to the volume the sheet encloses. Solved for
the volume (V > 0, P + Pa > 0), g = 0 is

    h(x, P) = V(x) / V_I - q(P) = 0,    q(P) = ((P_I + Pa) / (P + Pa))^(1/gamma),

the form used here: it is the liquid's row V / V_I - 1 with 1 replaced by q, so
the same code serves both (a liquid is q = 1, q' = 0) and the gas row tends to
the liquid's as Pa grows. Its linearisation, with dV the volume's first
variation (``kernel``: dV = -dR/dP),

    dh = dV / V_I - q'(P) dP,     q'(P) = -q / (gamma (P + Pa)),

adds one entry to the bordered tangent: the corner d(row)/dP = -q' =
q / (gamma (P + Pa)) > 0 (``model``). It is the brief's linearisation of g
rescaled: at a root, dg = gamma (P + Pa) V_I V^(gamma - 1) dh, since
dg = gamma (P + Pa) V^(gamma - 1) dV + V^gamma dP and V_I q = V. Newton on
either row takes the same step, and stays quadratic.

q is evaluated as exp(-log1p((P - P_I) / (P_I + Pa)) / gamma), which keeps its
digits when Pa is large against P and P_I (as (P_I + Pa) / (P + Pa) would not).
As Pa -> infinity, q = 1 - (P - P_I) / (gamma Pa) + O(Pa^-2): the gas states
approach the liquid ones at rate 1/Pa.

What a caller gives (None, "liquid" or a ``pocket.core.fluids.Fluid``) is
checked by ``pocket.core.fluids.as_fluid``; ``sealed`` turns a gas into this
row's ``Gas``.
"""

from __future__ import annotations

import dataclasses
import math

from pocket.core.fluids import Fluid

__all__ = ["Gas", "sealed"]


@dataclasses.dataclass(frozen=True)
class Gas:
    """The gas ``fluid`` (ambient Phat_atm, exponent gamma) sealed at ``pressure_initial`` (Phat_I)."""

    fluid: Fluid
    pressure_initial: float

    @property
    def ambient(self) -> float:
        return self.fluid.ambient

    @property
    def gamma(self) -> float:
        return self.fluid.gamma

    def ratio(self, pressure: float) -> tuple[float, float]:
        """(q, dq/dP) at the gauge pressure P: V / V_I and its slope (module docstring)."""
        total = pressure + self.ambient
        if not total > 0.0:  # a Newton iterate past vacuum has no gas state: a non-finite residual, the step cut
            return math.inf, -math.inf
        q = math.exp(-math.log1p((pressure - self.pressure_initial) / (self.pressure_initial + self.ambient))
                     / self.gamma)
        return q, -q / (self.gamma * total)

    def residual(self, pressure: float, volume: float, volume_initial: float) -> float:
        """The polytropic law's relative residual (P + Pa) V^gamma / ((P_I + Pa) V_I^gamma) - 1."""
        return (pressure + self.ambient) / (self.pressure_initial + self.ambient) * (
            volume / volume_initial) ** self.gamma - 1.0


def sealed(fluid: Fluid, pressure_initial: float) -> Gas | None:
    """The Gas of ``fluid`` sealed at Phat_I, or None for a liquid."""
    return Gas(fluid, pressure_initial) if fluid.is_gas else None
