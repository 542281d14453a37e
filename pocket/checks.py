"""Input checks shared by every solver: one-line ``InputError`` messages quoting the value."""

from __future__ import annotations

import math

from .errors import InputError

__all__ = ["check_finite", "check_alpha", "check_positive", "check_force"]


def check_finite(name, value) -> float:
    """``value`` as a finite float."""
    try:
        value = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{name} = {value!r} is not a number") from None
    if not math.isfinite(value):
        raise InputError(f"{name} = {value} is not finite")
    return value


def check_alpha(alpha) -> float:
    """alpha = C2/C1 must be > -1 (E = 6 (1 + alpha) C1 > 0)."""
    alpha = check_finite("alpha", alpha)
    if alpha <= -1.0:
        raise InputError(f"alpha = {alpha}, but the Mooney-Rivlin model needs alpha > -1")
    return alpha


def check_positive(name, value) -> float:
    """A quantity that must be finite and > 0 (a pressure, a volume)."""
    value = check_finite(name, value)
    if value <= 0.0:
        raise InputError(f"{name} = {value}, but it must be > 0")
    return value


def check_force(force) -> float:
    """The force Fhat = F / (P_I pi R^2) must be finite and >= 0 (the plate pushes)."""
    force = check_finite("force", force)
    if force < 0.0:
        raise InputError(f"force = {force}, but a plate can only push: it must be >= 0")
    return force
