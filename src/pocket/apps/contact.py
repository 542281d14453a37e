"""The contact pressure a compressed state reports at the pole and at the contact edge (units Phat).

On the flat plate the sheet in contact lies flat and carries the fluid pressure straight to the plate:
the contact pressure is P all over the contact zone, so its values at the pole and at the edge are the
state's pressure. On a curved indenter it exceeds P (P + (T_1 + T_2) / R_s on a sphere) and only the
solver knows it: both solvers give it as the state's ``contact_pressure_pole`` and
``contact_pressure_edge`` (units Phat), and a state of a curved indenter without them reports none.
"""

from __future__ import annotations

import math

__all__ = ["KEYS", "contact_pressures"]

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
