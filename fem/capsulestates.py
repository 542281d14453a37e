"""The closed capsule's states, built from converged unknowns and checked before they leave.

The unknowns are the upper half's (``capsule``): the mesh coordinate r in [0, 1] is S / c, S the arc length
from the pole on the undeformed sphere and c = pi / 2, and the volume the kernel integrates is the upper
half's with the equatorial plane. A state reports (``pocket.core.reported``, the capsule's group):

Inflated: ``height`` = eta(0), the pole above the equatorial plane; ``volume`` twice the half's;
``stretch_pole`` from rho / sin S near the pole (``post.pole_stretch``); ``stretch_clamp`` the meridional
stretch at the equator, from its flux: the equator's eta row is a reaction (eta = 0 is prescribed) and,
equilibrium holding inside, equals f_1 there, 2 pi w_1 t_eta + pi P rho^2 with r0 = 1; the rho row is free
(zero), so the meridian is vertical in the flux's sense, T_1 = w_1 / lambda_2 = (pi P rho_eq^2 - R_eta) /
(2 pi rho_eq), and lambda_1 carries it at lambda_2 = rho_eq (``material.Law.planar_stretch``); ``extra``
adds ``geometry`` and ``radius_equator`` = rho(pi / 2).

Compressed (edge-fitted contact, ``model``'s FITTED unknowns with the contact zone on ``model.flat``
elements): ``contact_radius`` a_c = c a, ``contact_radius_deformed`` rho_c = rho(a_c),
``stretch_contact`` = rho_c / sin a_c, ``contact_area`` = rho_c^2, ``height`` = h, ``volume`` twice the
half's; ``extra`` adds ``stretch_pole`` (the pole's, in contact), ``radius_equator``, ``force_ETR`` =
pi Fhat Phat_I, and the force diagnostics of the disc's states (``results``): the plate's reaction and P
A_c, as Fhat.

Checks: every number finite, every stretch positive, eta(pi / 2) = 0, the volume at its target (or the gas
law), the plate reaction and P A_c equal to the force (within ``results.force_allowance``, the disc's bound),
0 < a_c < pi / 2. A state that fails one is a solver failure (``ConvergenceError``), never returned. A state past
the end of the range (its contact edge slack) never reaches them: the solve that finds it says so
(``steps.check_edge``, ``OutOfRangeError``).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from pocket.core.states import CompressedState, InflatedState, Profile

from . import post, results
from .geometry import node_radii
from .model import FITTED, FREE, Control, Model, edge, fields, forms, placement
from .newton import Tolerances

__all__ = ["fitted_state", "inflated", "uncompressed"]


def _arc(model: Model) -> float:
    """c: the arc length S per unit of the mesh coordinate (pi / 2)."""
    return float(model.geometry.length)


def _capsule(model: Model, y: np.ndarray) -> dict:
    """The capsule's own keys of every state: the geometry and the equator's radius."""
    return dict(geometry=model.geometry.name, radius_equator=float(y[model.dofs - 2]))


def _slopes(model: Model, y: np.ndarray, mode: str) -> np.ndarray:
    """|dx/dS| at every node (the meridian's stretch where the node is in the rubber's reference), (nodes,)."""
    return post.node_slope(model, y, mode) / _arc(model)


def _equator_stretch(model: Model, y: np.ndarray, rows: np.ndarray, slopes: np.ndarray) -> float:
    """lambda_1 at the equator from its eta reaction (module docstring); ``slopes``: ``_slopes`` at y."""
    n, pressure = model.dofs, float(y[model.dofs])
    radius = float(y[n - 2])
    tension = (np.pi * pressure * radius**2 - rows[n - 1]) / (2.0 * np.pi * radius)
    return model.law.planar_stretch(float(tension), float(slopes[-1]), hoop=radius)


def _profile(model: Model, y: np.ndarray, mode: str, slopes: np.ndarray, pole: float, equator: float,
             contact: float = 0.0) -> Profile:
    """Every node's S, rho, eta, stretches, tensions and contact flag (S <= a_c); ``slopes``: ``_slopes`` at y."""
    u = y[: model.dofs]
    r = node_radii(placement(model, y, mode), model.ref)
    arc = _arc(model) * r
    rho, eta = u[0::2].copy(), u[1::2].copy()
    l1 = slopes.copy()
    l2 = np.empty_like(r)
    l2[1:] = rho[1:] / post.reference_radius(model, r[1:])
    l1[0] = l2[0] = pole
    l1[-1] = equator
    t1, t2 = model.law.tensions(l1, l2)
    return Profile(arc, rho, eta, l1, l2, t1, t2, arc <= contact if contact > 0.0 else arc < 0.0)


def _common(model: Model, y: np.ndarray, mode: str, state, where: str, half: float, target: float) -> None:
    """The checks of every state (module docstring); ``half``: the upper half's volume, ``target`` its target."""
    numbers = [v for v in state.scalars().values() if isinstance(v, float)]
    profile = state.profile
    arrays = [profile.rho, profile.eta, profile.stretch_1, profile.stretch_2, profile.tension_1, profile.tension_2]
    if not (np.all(np.isfinite(numbers)) and all(np.all(np.isfinite(a)) for a in arrays)):
        results._fail(where, "a number that is not finite")
    w = fields(model, y, mode)
    smallest = min(float(w.l1.min()), float(w.l2.min()), float(profile.stretch_1.min()),
                   float(profile.stretch_2.min()))
    if smallest <= 0.0:
        results._fail(where, f"a stretch {smallest:.3g} <= 0 (the meridian degenerate or through the axis)")
    if profile.eta[-1] != model.ends()[model.dofs - 1]:
        results._fail(where, f"eta at the equator = {profile.eta[-1]!r}, not on the equatorial plane")
    if abs(half / target - 1.0) > results.CONSISTENCY:
        results._fail(where, f"volume {2 * half!r} against its target {2 * target!r}")


def inflated(model: Model, y: np.ndarray, iterations: int, *, pressure: float | None = None,
             volume: float | None = None) -> InflatedState:
    """The inflated capsule of FREE unknowns y; ``pressure`` or ``volume`` (the whole capsule's): the given input,
    echoed."""
    linear = forms(model, y, FREE)
    slopes = _slopes(model, y, FREE)
    pole, equator = post.pole_stretch(model, y, FREE), _equator_stretch(model, y, linear.residual, slopes)
    profile = _profile(model, y, FREE, slopes, pole, equator)
    state = InflatedState(
        material=model.law.material, geometry=model.geometry,
        pressure=pressure if pressure is not None else float(y[model.dofs]),
        stretch_pole=pole, height=float(y[1]), volume=volume if volume is not None else 2.0 * linear.volume,
        stretch_clamp=equator, profile=profile, solver="fem",
        extra={**results._extra(model, iterations), **_capsule(model, y)},
        **results._least_tensions(linear, profile),
    )
    where = f"of the capsule at Phat = {state.pressure:.6g}"
    _common(model, y, FREE, state, where, linear.volume, linear.volume if volume is None else 0.5 * volume)
    return state


def uncompressed(state: InflatedState, fill: Control, contact: str) -> CompressedState:
    """The state at Fhat = 0: the inflated capsule (with the fluid ``fill`` holds), its contact edge at the pole (at
    P_I = 0 the unstressed sphere the plates touch: its ``force`` and ``pressure_ratio`` NaN, its ``force_ETR``
    0)."""
    out = results.uncompressed(state, fill, contact)
    out = dataclasses.replace(out, extra={**out.extra, "stretch_pole": state.stretch_pole, "force_ETR": 0.0},
                              contact_radius_deformed=0.0)
    return out if state.pressure > 0.0 else dataclasses.replace(out, force=np.nan, pressure_ratio=np.nan)


def fitted_state(model: Model, y: np.ndarray, iterations: int, state: InflatedState, fill: Control,
                 force, tol: Tolerances) -> CompressedState:
    """The compressed capsule of FITTED unknowns y at the given ``force`` (Fhat, echoed; at P_I = 0, where Fhat is
    undefined, F / (E T R), and the state's ``force`` and ``pressure_ratio`` are NaN) with the fluid ``fill``;
    ``tol``: Newton's tolerances of the solve (``results.force_allowance``)."""
    n, p_i = model.dofs, state.pressure
    unit = np.pi * p_i if p_i > 0.0 else 1.0  # the force's unit, E T R
    pressure, h, a = (float(v) for v in y[n:])
    rho_c, a_c = float(y[edge(model)]), _arc(model) * a
    linear = forms(model, y, FITTED)
    rows = linear.residual
    reaction = -float(rows[model.tied()].sum()) / unit
    area = np.pi * pressure * rho_c**2 / unit
    slopes = _slopes(model, y, FITTED)
    pole, equator = post.pole_stretch(model, y, FITTED), _equator_stretch(model, y, rows, slopes)
    extra = results._extra(model, iterations, FITTED)
    extra.update(force_reaction=reaction, force_pressure_area=area, force_difference=reaction - area,
                 penetration=max(0.0, float((y[edge(model) + 1: n: 2] - h).max())), **_capsule(model, y),
                 stretch_pole=pole, force_ETR=force * unit)
    profile = _profile(model, y, FITTED, slopes, pole, equator, a_c)
    out = CompressedState(
        material=model.law.material, fluid=results._fluid(fill), indenter=fill.indenter, pressure_initial=p_i,
        force=force if p_i > 0.0 else np.nan, pressure=pressure, pressure_ratio=pressure / p_i if p_i > 0.0 else np.nan,
        contact_area=rho_c**2, contact_radius=a_c, stretch_contact=rho_c / float(np.sin(a_c)), height=h,
        height_ratio=h / state.height, volume=2.0 * linear.volume, profile=profile, inflated=state, solver="fem",
        extra=extra, contact_radius_deformed=rho_c, **results._least_tensions(linear, profile),
    )
    where = f"of the capsule at Fhat = {force!r}" if p_i > 0.0 else \
        f"of the uninflated capsule at F/(E T R) = {force!r}"
    assert fill.volume is not None, "a fill holds the upper half's V_I"
    _common(model, y, FITTED, out, where, linear.volume,
            fill.volume * (1.0 if fill.gas is None else fill.gas.ratio(pressure)[0]))
    if fill.gas is not None:
        error = fill.gas.residual(pressure, linear.volume, fill.volume)
        if abs(error) > results.CONSISTENCY:
            results._fail(where, f"the gas law (P + P_atm) V^gamma = (P_I + P_atm) V_I^gamma off by {error:.3g}")
    results._check_forces({name: extra[name] for name in ("force_reaction", "force_pressure_area")}, force, tol, where,
                          lambda: results._fitted_noise(model, y, fill, force, unit))
    if not 0.0 < a < 1.0:
        results._fail(where, f"contact radius a_c = {a_c!r} outside (0, pi/2)")
    return out
