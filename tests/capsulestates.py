"""Capsule states built by hand, for the tests of what pocket writes of a capsule (VTK files, tables): no solver.

``sphere(alpha, stretch)`` is an exact inflated capsule: a sphere of uniform stretch lambda, rho = lambda sin S,
eta = lambda cos S (section 12 of the theory: it solves the capsule's equations for any law), at the Mooney-Rivlin
pressure Phat = 2 (1 - lambda^-6)(1 + alpha lambda^2) / (3 (1 + alpha) lambda), with the whole volume
4/3 pi lambda^3.

``pressed(...)`` is a pressed capsule's shape, not an equilibrium: a flat disc of radius rho_c at the plate's height
H for S <= a_c, then a quarter circle of radius H about (rho_c, 0) down to the equator, where it stands vertical at
rho_c + H; its angle linear in S. Its whole volume is exact: twice the integral of pi (rho_c + sqrt(H^2 - z^2))^2
over z in [0, H], 2 pi (rho_c^2 H + pi rho_c H^2 / 2 + 2 H^3 / 3). Its stretches come from its geometry, its
tensions are made up (positive).
"""

from __future__ import annotations

import math

import numpy as np

from pocket.core.geometries import CAPSULE
from pocket.core.materials import mooney_rivlin
from pocket.core.states import CompressedState, InflatedState, Profile

__all__ = ["STAND_IN_STRETCH", "pressed", "pressed_volume", "sphere", "sphere_pressure", "stand_in", "stood_in"]

#: the stand-in's inflated stretch
STAND_IN_STRETCH = 1.2


def sphere_pressure(alpha: float, stretch: float) -> float:
    """Phat of the Mooney-Rivlin sphere of uniform stretch ``stretch`` (theory, eq. capsule-mooney-rivlin)."""
    return 2.0 * (1.0 - stretch**-6) * (1.0 + alpha * stretch**2) / (3.0 * (1.0 + alpha) * stretch)


def _profile(arc, rho, eta, contact, tension):
    """Stretches from the geometry: lambda_1 = |d(rho, eta)/dS|, lambda_2 = rho / sin S (its limit at the pole)."""
    stretch_1 = np.hypot(np.gradient(rho, arc), np.gradient(eta, arc))
    r0 = CAPSULE.radius(arc)
    stretch_2 = np.where(r0 > 0, rho / np.where(r0 > 0, r0, 1.0), stretch_1)
    return Profile(arc, rho, eta, stretch_1, stretch_2, tension * stretch_1, tension * stretch_2, contact)


def sphere(alpha: float = 0.1, stretch: float = 1.2, n: int = 201, solver: str = "test") -> InflatedState:
    """The inflated capsule of uniform stretch ``stretch`` (module docstring), its profile at ``n`` arc lengths."""
    arc = np.linspace(0.0, CAPSULE.length, n)
    rho, eta = stretch * np.sin(arc), stretch * np.cos(arc)
    rho[0], eta[-1] = 0.0, 0.0
    pressure = sphere_pressure(alpha, stretch)
    profile = Profile(arc, rho, eta, np.full(n, stretch), np.full(n, stretch), np.full(n, pressure * stretch / 2),
                      np.full(n, pressure * stretch / 2), np.zeros(n, bool))
    return InflatedState(mooney_rivlin(alpha), pressure, stretch, stretch, 4.0 / 3.0 * math.pi * stretch**3,
                         stretch, profile, solver, extra={"geometry": "capsule", "radius_equator": stretch},
                         geometry=CAPSULE)


def pressed_volume(rho_c: float, height: float) -> float:
    """The whole volume of ``pressed``'s shape (module docstring)."""
    return 2.0 * math.pi * (rho_c**2 * height + math.pi * rho_c * height**2 / 2.0 + 2.0 * height**3 / 3.0)


def pressed(inflated: InflatedState, force: float, contact_radius: float = 0.4, rho_c: float = 0.5,
            height: float = 0.8, n: int = 401) -> CompressedState:
    """A pressed capsule's shape (module docstring) from ``inflated``, reported at ``force`` (Fhat), its contact edge
    at the arc length ``contact_radius`` and the radius ``rho_c``, its plate at ``height``."""
    arc = np.linspace(0.0, CAPSULE.length, n)
    arc = np.unique(np.concatenate((arc, [contact_radius])))
    free = arc > contact_radius
    theta = (arc - contact_radius) / (CAPSULE.length - contact_radius) * math.pi / 2.0
    rho = np.where(free, rho_c + height * np.sin(theta), rho_c * arc / contact_radius)
    eta = np.where(free, height * np.cos(theta), height)
    eta[-1] = 0.0
    profile = _profile(arc, rho, eta, ~free, 0.1)
    ratio = force / rho_c**2
    pressure_initial = inflated.pressure
    extra = {"geometry": "capsule", "stretch_pole": rho_c / contact_radius, "radius_equator": rho_c + height,
             "force_ETR": math.pi * force * pressure_initial}
    return CompressedState(inflated.material, pressure_initial, force, ratio * pressure_initial, ratio, rho_c**2,
                           contact_radius, rho_c / math.sin(contact_radius), height, height / inflated.height,
                           pressed_volume(rho_c, height), profile, inflated, inflated.solver, extra=extra,
                           contact_radius_deformed=rho_c)


def stood_in(forces) -> list[CompressedState]:
    """The stand-in's states at ``forces`` (``stand_in``): pressed shapes of the sphere of stretch
    ``STAND_IN_STRETCH``, the k-th with rho_c = 0.3 + 0.1 k and H = 0.9 - 0.1 k."""
    inflated = sphere(stretch=STAND_IN_STRETCH, solver="analytical")
    return [pressed(inflated, f, rho_c=0.3 + 0.1 * k, height=0.9 - 0.1 * k) for k, f in enumerate(forces)]


def stand_in(monkeypatch) -> list:
    """The analytical solver's ``inflate``, ``compression_curve`` and ``range_end`` replaced by ones returning
    hand-built capsule states (``sphere``, ``stood_in``) and no end of the range; returns the list of
    (entry point, keywords) of their calls, filled as they are called."""
    from pocket import analytical

    calls = []

    def inflate(material, pressure, **options):
        calls.append(("inflate", options))
        return sphere(stretch=STAND_IN_STRETCH, solver="analytical")

    def compression_curve(material, pressure_initial, forces, **options):
        calls.append(("compression_curve", {k: v for k, v in options.items() if k != "progress"}))
        return stood_in(forces)

    def range_end(material, pressure_initial, **options):
        calls.append(("range_end", options))
        return math.inf

    for name, fn in (("inflate", inflate), ("compression_curve", compression_curve), ("range_end", range_end)):
        monkeypatch.setattr(analytical, name, fn)
    return calls
