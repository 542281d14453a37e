r"""Small-strain estimates of the inflated pocket (Hencky's regime, Phat -> 0).

Linearising the membrane law about the flat sheet gives the pole tension
T = 2 E T (lambda_0 - 1) for any Mooney-Rivlin alpha; with the paper's assumed
shape (its eqs (14)-(16)), normal equilibrium at the pole gives

    Phat = 4 sqrt(6) (lambda_0 - 1)^(3/2),   H0 / R = sqrt(3 (lambda_0 - 1) / 2),
    V / R^3 = (pi / 4) sqrt(6 (lambda_0 - 1)).

These are starting guesses for the solvers and brackets for root finders (a
shared guess cannot hide a bug: each solver converges to its own answer), and
the inflation of the analytical model.
"""

from __future__ import annotations

import math

__all__ = [
    "height",
    "height_constant",
    "height_of_strain",
    "pole_strain",
    "pressure_of_strain",
    "strain_of_volume",
    "volume",
    "volume_of_strain",
]


def pole_strain(pressure: float) -> float:
    """lambda_0 - 1 at Phat = ``pressure``: (Phat / (4 sqrt 6))^(2/3)."""
    return (pressure / (4.0 * math.sqrt(6.0))) ** (2.0 / 3.0)


def pressure_of_strain(strain: float) -> float:
    """Phat of the dome of pole strain s = lambda_0 - 1: 4 sqrt(6) s^(3/2) (``pole_strain`` inverted)."""
    return 4.0 * math.sqrt(6.0) * strain**1.5


def height_of_strain(strain: float) -> float:
    """H0 / R of the dome of pole strain s: sqrt(3 s / 2)."""
    return math.sqrt(1.5 * strain)


def volume_of_strain(strain: float) -> float:
    """V / R^3 of the dome of pole strain s: (pi / 4) sqrt(6 s)."""
    return 0.25 * math.pi * math.sqrt(6.0 * strain)


def height(pressure: float) -> float:
    """H0 / R at Phat = ``pressure``."""
    return height_of_strain(pole_strain(pressure))


def volume(pressure: float) -> float:
    """V / R^3 at Phat = ``pressure``."""
    return volume_of_strain(pole_strain(pressure))


def height_constant() -> float:
    """H0/R / Phat^(1/3) in this regime: sqrt(3/2) (4 sqrt 6)^(-1/3)."""
    return math.sqrt(1.5) * (4.0 * math.sqrt(6.0)) ** (-1.0 / 3.0)


def strain_of_volume(volume: float) -> float:
    """lambda_0 - 1 of the dome of volume V/R^3: (4 V / pi)^2 / 6 (``volume`` inverted)."""
    return (4.0 * volume / math.pi) ** 2 / 6.0
