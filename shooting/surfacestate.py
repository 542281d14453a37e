"""The solved state under a curved indenter (``pocket.shooting.surface``): its profile and contact pressure, how
far it stands from each end of the model, and the checks every returned state passes."""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from pocket.core.errors import CLAMP_PLANE, OutOfRangeError
from pocket.core.states import CompressedState

from .contact import final_shots
from .shots import profile_from_steps, tension_minima
from .tensions import tensions

__all__ = ["check", "gap", "gap_allowed", "margins", "scales", "solved", "state"]


def solved(problem, force, x):
    """The solved state's pieces at ``force``: (profile, contact pressure at its points (NaN off contact), free
    steps, y(1), y(a)); a ConvergenceError if its final shots do not reach the clamp."""
    q, lc, a, _p = problem.geometry(x, force)
    status, y, _, edge = problem.shoot(x, force)
    stored = problem.shoot(x, force, store=20000)
    final_shots(force, status, stored[0])
    inner, outer = stored[2]
    profile = profile_from_steps(np.concatenate([inner, outer[1:]]), problem.law, lc)
    on = profile.r <= a
    pc = np.where(on, problem.surface.pressure(profile.rho, profile.tension_1, profile.tension_2,
                                               problem.inflated.pressure * q), np.nan)
    return dataclasses.replace(profile, contact=on), pc, outer[1:], y, edge


def scales(problem) -> dict[str, float]:
    """What each margin of ``margins`` is divided by to compare them: the end's by the surface's ``end_scale``
    (the sphere's angle by pi/2), the clamp angle by pi, the lengths by the inflated dome's height."""
    height = problem.inflated.height
    return {problem.END: problem.surface.end_scale, CLAMP_PLANE: math.pi, problem.POLE: height, problem.TOUCH: height}


def margins(problem, force, x) -> dict[str, float]:
    """How far the solved state at ``force`` stands from each end of the model (positive inside it):
    {END: the surface's end margin (``Surface.end_margin``), CLAMP_PLANE: pi - psi(1) (rad), POLE: the height h
    (units R), TOUCH: the free sheet's smallest gap below the indenter where it is negative beyond
    ``gap_allowed``, else inf (units R; ``pocket.shooting.surfaceend``)}."""
    profile, _, _, y, edge = solved(problem, force, x)
    below = gap(problem, profile, -y[1])
    inside = float(np.min(below)) if below.size else math.inf  # zero at the edge by tangency: only < 0 counts
    return {problem.END: problem.surface.end_margin(edge), CLAMP_PLANE: math.pi - y[2], problem.POLE: -y[1],
            problem.TOUCH: inside if inside < -gap_allowed(problem, -y[1]) else math.inf}


def gap(problem, profile, height) -> np.ndarray:
    """The free sheet's distance below the indenter (units R; negative where it would be inside it), at each
    profile point off the contact zone with rho below the surface's reach (elsewhere the surface is not above
    it). ``height``: the indenter's lowest point above the clamp plane (the profile's eta = 0)."""
    free = ~profile.contact & (profile.rho < problem.surface.reach)
    surface = height + problem.indenter.height(profile.rho[free])
    return surface - profile.eta[free]


def gap_allowed(problem, height) -> float:
    """How far (units R) the free sheet may seem inside the indenter at ``height`` before it is: the shots'
    resolution of the gap, 1e3 rtol of the larger of h and H0."""
    return 1e3 * problem.rtol * max(height, problem.inflated.height)


def check(problem, profile, contact_pressure, height, force) -> None:
    """Refuse, by name, a state (its ``profile``, the ``contact_pressure`` at its points, ``height``) with a
    negative contact pressure or its free sheet inside the indenter (OutOfRangeError): neither is a state of
    this model."""
    pc = contact_pressure[profile.contact]
    if np.any(pc < 0.0):
        i = int(np.argmin(pc))
        raise OutOfRangeError(f"force = {force!r} ({problem.label}): the contact pressure would be negative "
                              f"({pc[i]:.6g}) at r = {profile.r[profile.contact][i]:.6g}: the sheet would pull "
                              f"on the {problem.NAME}")
    below = gap(problem, profile, height)
    if below.size and np.min(below) < -gap_allowed(problem, height):
        raise OutOfRangeError(f"force = {force!r} ({problem.label}): {problem.TOUCH} (the free sheet would lie "
                              f"{-np.min(below):.3g} R inside it)")


def state(problem, force, x, fluid) -> tuple[CompressedState, float]:
    """The compressed state at ``force`` (as given, ``fluid`` too) for the solved unknowns x, checked
    (``check``), and its clamp angle psi(1)."""
    q, lc, a, p = problem.geometry(x, force)
    profile, pc, outer, y, edge = solved(problem, force, x)
    height = -y[1]
    check(problem, profile, pc, height, force)
    low = tension_minima(profile, outer, problem.law, p, problem.tolerance)
    inflated = problem.inflated
    pressure = inflated.pressure * q
    t0 = tensions(lc, lc, problem.law.code, problem.law.params)[0] * problem.law.tension_scale
    compressed = CompressedState(
        pressure_initial=inflated.pressure, force=force, pressure=pressure,
        pressure_ratio=q, contact_area=problem.surface.area(edge),
        contact_radius=a, stretch_contact=lc, height=height, height_ratio=height / inflated.height,
        volume=y[4], profile=profile, inflated=inflated, solver="shooting", material=inflated.material,
        fluid=fluid, tension_1_min=low[0], tension_2_min=low[1], indenter=problem.indenter,
        contact_radius_deformed=float(edge[0]), contact_pressure_pole=pressure + 2.0 * t0 / problem.pole_radius,
        contact_pressure_edge=float(pc[profile.contact][-1]), contact_pressure=pc,
    )
    return compressed, float(y[2])
