"""The contact patch a compressed state reports: its deformed radius, and the contact pressure at the pole and
at the contact edge (units Phat).

The patch a camera or an ink print shows is bounded by the contact edge of the deformed sheet, at radius
rho_c from the axis: ``deformed_radius``. The state's ``contact_radius`` is the Lagrangian a_c, where that
edge was in the flat sheet, smaller by the hoop stretch there (rho_c = lambda_2 a_c). On the flat plate the
zone in contact is a flat disc, A_c = pi rho_c^2; every solver gives rho_c under a curved indenter
(``contact_radius_deformed``), where the curved area in contact is larger than pi rho_c^2.

On the flat plate the sheet in contact lies flat and carries the fluid pressure straight to the plate:
the contact pressure is P all over the contact zone, so its values at the pole and at the edge are the
state's pressure. On a curved indenter it exceeds P (P + (T_1 + T_2) / R_s on a sphere) and only the
solver knows it: both solvers give it as the state's ``contact_pressure_pole`` and
``contact_pressure_edge`` (units Phat), and a state of a curved indenter without them reports none.
"""

from __future__ import annotations

import math

__all__ = ["KEYS", "contact_patch", "contact_pressures", "deformed_radius"]

#: the ``CompressedState`` fields that carry the contact pressure at the pole and at the edge (units Phat)
KEYS = ("contact_pressure_pole", "contact_pressure_edge")


def contact_pressures(state) -> dict[str, float]:
    """{key: value} of ``KEYS`` for the ``CompressedState`` ``state`` (units Phat): the state's own values, or
    its pressure at both on a flat plate (``Indenter.pressure_area``); empty if it carries none."""
    if all(math.isfinite(getattr(state, key)) for key in KEYS):
        return {key: float(getattr(state, key)) for key in KEYS}
    if state.indenter.pressure_area:
        return dict.fromkeys(KEYS, float(state.pressure))
    return {}


def deformed_radius(state) -> float | None:
    """rho_c / R, the radial position of the contact edge in the deformed sheet, for the ``CompressedState``
    ``state``: its ``contact_radius_deformed`` where its solver gives it, else on a flat contact zone
    (``Indenter.pressure_area``: the plate) sqrt(A_c / (pi R^2)), the radius of the disc in contact; None for
    a curved indenter's state without it."""
    if math.isfinite(state.contact_radius_deformed):
        return float(state.contact_radius_deformed)
    if state.indenter.pressure_area:
        return math.sqrt(state.contact_area)
    return None


def contact_patch(state) -> dict[str, float]:
    """{"contact_radius_deformed": rho_c / R (``deformed_radius``), then ``contact_pressures``} for the
    ``CompressedState`` ``state``, each where it has one (the keys of pocket's outputs, dimensionless)."""
    rho_c = deformed_radius(state)
    return {**({} if rho_c is None else {"contact_radius_deformed": rho_c}), **contact_pressures(state)}
