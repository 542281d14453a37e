"""The states the solver returns, built from converged unknowns and checked before they leave.

Reported quantities (``pocket.core.states``): the inputs (alpha or the
material, pressure or pressure_initial, force, the fluid) are echoed exactly as
given (``material.law_of``, ``pocket.core.fluids.as_fluid``), the indenter as ``Control`` holds it.

Smallest tensions: T_1 = w_1 / lambda_2 and T_2 = w_2 / lambda_1 at the
quadrature points and at the profile's nodes; the state reports the least of
each, so that a compressive tension anywhere the solver evaluates it flags
the state as wrinkled.

Inflated: ``height`` = eta(0), ``stretch_pole`` and ``stretch_clamp`` from
``post``, ``volume`` V(x).

Compressed, edge-fitted contact (``fitted``): ``contact_radius`` = a (an
unknown), ``stretch_contact`` = rho(a)/a, ``contact_area`` = rho(a)^2 (the
deformed disc pi rho(a)^2 over pi R^2), ``height`` = h, ``pressure`` = P.
Diagnostics in ``extra``: ``force_reaction`` (the plate reaction -sum_C R_j),
``force_pressure_area`` (P times the deformed contact area), both as Fhat,
``force_difference`` (their difference), ``contact_pressure_error`` (the
plate's nodal reactions at the contact zone's nodes off the edge against the
consistent nodal loads of the fluid pressure P, max |difference| / max |load|:
a frictionless flat plate carries exactly the fluid pressure) and
``penetration`` (max(eta - h - z(rho)) over the free part's nodes, z the
indenter's height profile: the free part must stay below the indenter).

Compressed, penalty contact (``penalty``): ``contact_area`` = Fhat P_I/P from
the plate force and the pressure, ``contact_radius`` = sqrt(A_c)/lambda_c (under a curved
indenter the active set's curved area and its outermost point, ``penalty.contact_zone_active``),
``height`` = eta(0) (the sheet, about p_N/kappa above the plate with a pure
penalty), ``force_pressure_area`` from the active quadrature points (O(h)),
``penetration`` (max(eta - h) at the quadrature points) and
``penetration_pole``.

Checks (``check``): every number finite, every stretch positive (at the
quadrature points too), rho(1) = 1 (lambda_2(1) = 1), the volume at its
target (V_I, or V_I q(P) for a gas: ``gas``) and for a gas the polytropic law
itself, and for the fitted contact the plate reaction equal to the force and,
where the indenter makes it an identity (``Indenter.pressure_area``: the flat
plate), F = P A_c (within ``force_allowance``, below; the others within CONSISTENCY).
A state that fails one is a solver failure (``ConvergenceError``
naming the check), never returned.

How far a force identity may be off (``force_allowance``, the one bound the clamped sheet's, the capsule's
and the curved indenter's states use). Newton does not solve for the reported forces: they follow from
the border rows (``model``), which it solves relative to the plate force F_s they are measured against
(``Control.scale``: the force asked, or under travel control pi P rho(a)^2 of the last solve's guess, within
a step of the state's own). With t = (sum_C R_j + pi P rho(a)^2) / F_s the tangency row and
c = (pi P rho(a)^2 - F*) / F_s the force-control row at the returned unknowns, and the forces reported
divided by pi P_I (Fhat),

    force_reaction - Fhat = (c - t) F_s / (pi P_I),    force_pressure_area - Fhat = c F_s / (pi P_I),

and F_s / (pi P_I) is Fhat itself. Newton's two ways of accepting a residual bound t and c at the state it
returns (its last iterate plus the last step, whose linear model zeroes the rows):

- a residual that has stopped falling within ``newton.FLOOR`` times its tolerance: a row within FLOOR tol
  (a fine mesh can stall there: the neo-Hookean capsule at Phat_I = 0.01 on 2048 elements, at Fhat = 0.14
  seeded from 0.1, accepted 5.3e-8 and kept 2.3e-8 in the tangency row, its reaction 3.2e-9 off in Fhat);
- a residual within ``newton.NOISE`` of the unknowns' round-off, the rows' change when every unknown moves
  by ``newton.ULPS`` units in its last place: the round-off the last step cannot remove. For one row, with
  the worst signs, that is nu = ULPS eps (|C_k| |U| + |D_k| |s|) (``newton.border_noise``, C_k and D_k the
  row's gradient in the bordered tangent, read at the state under force control: ``identity_noise``; a
  linearisation, so read only for a state the first term alone does not admit).

Hence, with ``tol`` Newton's residual tolerance,

    |force - Fhat| <= Fhat (2 FLOOR tol + NOISE (nu_t + nu_c)).

The first term is relative to the force: the 1 / P_I of the reaction cancels against the P_I in F_s. The
second is where the reaction's own round-off sits: the tangency row's gradient is k_C / F_s, k_C = K 1_C the
sum of the n_C tied rows of the stiffness, so Fhat nu_t = ULPS eps |k_C| |U| / (pi P_I) + ...: absolute in
Fhat, accumulated over the contact zone's nodes (half the mesh's on the capsule) and stiff where the
elements are small (the disc's graded pole), growing as 1 / Phat_I at a given stiffness, and, however small the
force, not shrinking with it. It is what admits a tiny force on a fine mesh (the disc on 2048 elements at
Fhat = 1e-7, Phat_I = 0.01: the reaction 8e-13 off, 40 times the first term, 1 % of the second). The
penalty plate's force, a quadrature of the contact pressure rather than a reaction, rests on its
force-control row alone (the first term); a curved indenter's reaction rows are ``obstacle``'s, read alike.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

import numpy as np

from pocket.core.errors import ConvergenceError
from pocket.core.fluids import LIQUID
from pocket.core.states import CompressedState, InflatedState

from . import post
from .model import FITTED, FREE, PENALTY, Control, Model, fields, forms, linearize, plate_force
from .newton import FLOOR, NOISE, Tolerances, border_noise
from .penalty import contact_area_active, contact_zone_active, penetration

__all__ = ["CONSISTENCY", "fitted_state", "force_allowance", "force_control", "identity_noise", "inflated",
           "penalty_state", "uncompressed"]

#: relative tolerance of the state's own volume, gas law and pressure: Newton leaves ~1e-12
CONSISTENCY = 1e-9
#: the border rows the force identities are made of (``model``): the tangency row and the control row
_FORCE_ROWS = (1, 2)


def force_allowance(force: float, tol: Tolerances, noise: float = 0.0) -> float:
    """How far a reported force (Fhat) of a state Newton accepted under ``tol`` may be from the force asked:
    |force| (2 FLOOR tol.residual + NOISE noise) (module docstring).

    Parameters
    ----------
    force : float
        The force Fhat = F / (P_I pi R^2) the state was solved for.
    tol : Tolerances
        Newton's tolerances of the solve.
    noise : float, optional
        The round-off of the identities' rows at the state, relative to the plate force like the rows
        (``identity_noise``).

    Returns
    -------
    float
        The allowance, in Fhat.

    Examples
    --------
    >>> from pocket.fem.newton import Tolerances
    >>> print(f"{force_allowance(0.14, Tolerances()):.3g}", f"{force_allowance(0.14, Tolerances(), 1e-8):.3g}")
    2.8e-08 4.2e-08
    """
    return abs(force) * (len(_FORCE_ROWS) * FLOOR * tol.residual + NOISE * noise)


def identity_noise(system, y: np.ndarray) -> float:
    """The round-off of the force identities' rows (the tangency and the force-control row) of the bordered
    ``system`` linearised at y under force control: ``newton.border_noise`` of the two, summed."""
    return float(border_noise(system, y)[list(_FORCE_ROWS)].sum())


def force_control(fill: Control, force: float, unit: float) -> Control:
    """``fill`` under the control of the plate force ``force`` (in units of ``unit`` E T R: pi Phat_I for Fhat),
    the rows measured against it: the linearisation the identities' round-off is read from."""
    plate = force * unit
    return dataclasses.replace(fill, force=plate, scale=plate)


def _fitted_noise(model: Model, y: np.ndarray, fill: Control, force: float, unit: float) -> float:
    """``identity_noise`` of the FITTED state y at the force ``force`` (units of ``unit`` E T R, as for
    ``force_control``; the disc's and the capsule's)."""
    return identity_noise(linearize(model, y, FITTED, force_control(fill, force, unit))[1], y)


def _check_forces(reported: dict[str, float], force: float, tol: Tolerances, where: str,
                  noise: Callable[[], float] | None = None) -> None:
    """ConvergenceError if a reported force (name: Fhat) is off the force asked by more than ``force_allowance``;
    ``noise()`` its noise term, evaluated only if the first term alone does not hold them all (it costs a
    linearisation)."""
    off = {name: abs(value - force) for name, value in reported.items()}
    if all(v <= force_allowance(force, tol) for v in off.values()):
        return
    allowed = force_allowance(force, tol, 0.0 if noise is None else noise())
    for name, value in reported.items():
        if not off[name] <= allowed:
            _fail(where, f"{name} = {value!r} against the force {force!r} (F = P A_c; allowed {allowed:.3g})")


def _extra(model: Model, iterations: int, contact: str | None = None) -> dict:
    out: dict[str, int | str] = dict(elements=model.elements, order=model.order, newton_iterations=int(iterations))
    if contact is not None:
        out["contact"] = contact
    return out


def _fail(where: str, what: str):
    raise ConvergenceError(f"the finite-element state {where} fails its own check: {what}")


def _echo(model: Model, fill: Control | None = None) -> dict:
    """The inputs a state echoes as given: the material, and the reference surface (inflated) or the fluid and
    the indenter (compressed: its surface is its inflated state's)."""
    out: dict[str, object] = dict(material=model.law.material)
    if fill is None:
        out.update(geometry=model.geometry)
    else:
        out.update(fluid=_fluid(fill), indenter=fill.indenter)
    return out


def _fluid(fill: Control):
    """The fluid as given: LIQUID, or the gas sealed in ``fill``."""
    return LIQUID if fill.gas is None else fill.gas.fluid


def _least_tensions(linear, profile) -> dict:
    """The least T_1 and T_2 over the quadrature points (``linear``: the state's forms) and the profile's
    nodes (units E T)."""
    t1, t2 = linear.tension_min
    return dict(tension_1_min=min(t1, float(profile.tension_1.min())),
                tension_2_min=min(t2, float(profile.tension_2.min())))


def _volume_target(fill: Control, pressure: float) -> float:
    """V_I, or V_I q(P) for a gas."""
    assert fill.volume is not None, "a fill holds V_I"
    return fill.volume * (1.0 if fill.gas is None else fill.gas.ratio(pressure)[0])


def _check_gas(fill: Control, state, where: str) -> None:
    if fill.gas is not None:
        assert fill.volume is not None, "a fill holds V_I"
        error = fill.gas.residual(state.pressure, state.volume, fill.volume)
        if abs(error) > CONSISTENCY:
            _fail(where, f"the gas law (P + P_atm) V^gamma = (P_I + P_atm) V_I^gamma off by {error:.3g} (relative)")


def _check_common(model: Model, y: np.ndarray, mode: str, state, where: str, volume_target: float) -> None:
    numbers = [v for v in state.scalars().values() if isinstance(v, float)]
    arrays = [getattr(state.profile, f.name) for f in dataclasses.fields(state.profile) if f.name != "contact"]
    if not (np.all(np.isfinite(numbers)) and all(np.all(np.isfinite(a)) for a in arrays)):
        _fail(where, "a number that is not finite")
    w = fields(model, y, mode)
    smallest = min(float(w.l1.min()), float(w.l2.min()), float(state.profile.stretch_1.min()),
                   float(state.profile.stretch_2.min()))
    if smallest <= 0.0:
        _fail(where, f"a stretch {smallest:.3g} <= 0 (the meridian degenerate or through the axis)")
    if abs(state.profile.rho[-1] - model.clamp.radius) > 1e-14:
        _fail(where, f"rho(1) = {state.profile.rho[-1]!r}, not the clamp's {model.clamp.radius!r}")
    if abs(state.volume / volume_target - 1.0) > CONSISTENCY:
        _fail(where, f"volume {state.volume!r} against its target {volume_target!r}")


def inflated(model: Model, y: np.ndarray, iterations: int, *, pressure: float | None = None,
             volume: float | None = None) -> InflatedState:
    """The inflated state of FREE unknowns y; ``pressure`` or ``volume``: the given input, echoed."""
    linear = forms(model, y, FREE)
    pole, clamp = post.pole_stretch(model, y, FREE), post.clamp_stretch(model, y, FREE, linear.residual)
    v = linear.volume
    profile = post.profile(model, y, FREE, pole=pole, clamp=clamp)
    state = InflatedState(
        **_echo(model),
        pressure=pressure if pressure is not None else float(y[model.dofs]),
        stretch_pole=pole,
        height=float(y[1]),
        volume=volume if volume is not None else v,
        stretch_clamp=clamp,
        profile=profile,
        solver="fem",
        extra=_extra(model, iterations),
        **_least_tensions(linear, profile),
    )
    where = f"at Phat = {state.pressure:.6g}"
    _check_common(model, y, FREE, state, where, v if volume is None else volume)
    if pressure is not None and abs(y[model.dofs] / pressure - 1.0) > CONSISTENCY:
        _fail(where, f"pressure {y[model.dofs]!r} against the given {pressure!r}")
    return state


def uncompressed(state: InflatedState, fill: Control, contact: str) -> CompressedState:
    """The state at Fhat = 0: the inflated one (with the fluid ``fill`` holds)."""
    return CompressedState(
        material=state.material, fluid=_fluid(fill), pressure_initial=state.pressure, force=0.0,
        pressure=state.pressure, pressure_ratio=1.0,
        contact_area=0.0, contact_radius=0.0, stretch_contact=state.stretch_pole, height=state.height,
        height_ratio=1.0, volume=state.volume, profile=state.profile, inflated=state, solver="fem",
        extra={**state.extra, "contact": contact, "newton_iterations": 0, "penetration": 0.0,
               "force_reaction": 0.0, "force_pressure_area": 0.0, "force_difference": 0.0},
        tension_1_min=state.tension_1_min, tension_2_min=state.tension_2_min, indenter=fill.indenter,
    )


def _contact_pressure_error(model: Model, y: np.ndarray, rows: np.ndarray) -> float:
    """Plate reactions against the consistent loads of P at the contact element's nodes off the edge."""
    n, p = model.dofs, model.order
    pressure, a = y[n], y[n + 2]
    stretch = y[2 * p] / a
    ref = model.ref
    r = a * ref.t  # the contact element's quadrature points
    load = pressure * stretch**2 * 2.0 * np.pi * (a * ref.weights * r) @ ref.phi  # consistent nodal loads
    plate = -rows[model.tied()]
    return float(np.max(np.abs(plate[:p] - load[:p])) / np.max(np.abs(load[:p])))


def fitted_state(model: Model, y: np.ndarray, iterations: int, state: InflatedState, fill: Control,
                 force, tol: Tolerances) -> CompressedState:
    """The compressed state of FITTED unknowns y at the given ``force`` (Fhat, echoed) with the fluid ``fill``;
    ``tol``: Newton's tolerances of the solve (``force_allowance``)."""
    n, p_i = model.dofs, state.pressure
    pressure, h, a = (float(v) for v in y[n:])
    rho_a = float(y[2 * model.order])
    linear = forms(model, y, FITTED)
    rows = linear.residual
    reaction = -float(rows[model.tied()].sum()) / (np.pi * p_i)
    area = pressure * rho_a**2 / p_i
    free_rho, free_eta = y[2 * model.order: n: 2], y[2 * model.order + 1: n: 2]
    extra = _extra(model, iterations, FITTED)
    extra.update(force_reaction=reaction, force_pressure_area=area, force_difference=reaction - area,
                 contact_pressure_error=_contact_pressure_error(model, y, rows),
                 penetration=max(0.0, float((free_eta - h - fill.indenter.height(free_rho)).max())))
    stretch = rho_a / a
    clamp = post.clamp_stretch(model, y, FITTED, rows)
    profile = post.profile(model, y, FITTED, pole=stretch, clamp=clamp, contact_radius=a)
    out = CompressedState(
        **_echo(model, fill), pressure_initial=p_i, force=force, pressure=pressure, pressure_ratio=pressure / p_i,
        contact_area=rho_a**2, contact_radius=a, stretch_contact=stretch, height=h, height_ratio=h / state.height,
        volume=linear.volume,
        profile=profile, inflated=state, solver="fem", extra=extra, **_least_tensions(linear, profile),
    )
    where = f"at Fhat = {force!r}"
    _check_common(model, y, FITTED, out, where, _volume_target(fill, pressure))
    _check_gas(fill, out, where)
    identities = ("force_reaction", "force_pressure_area") if fill.indenter.pressure_area else ("force_reaction",)
    _check_forces({name: extra[name] for name in identities}, force, tol, where,
                  lambda: _fitted_noise(model, y, fill, force, np.pi * p_i))
    if not 0.0 < a < 1.0:
        _fail(where, f"contact radius a/R = {a!r} outside (0, 1)")
    return out


def penalty_state(model: Model, y: np.ndarray, lam, iterations: int, state: InflatedState, fill: Control,
                  force: float | None, tol: Tolerances) -> CompressedState:
    """The compressed state of PENALTY unknowns y (multiplier ``lam``) with the fluid ``fill``; ``force``: the
    given Fhat (None under plate-height control: the reaction is reported); ``tol`` as for ``fitted_state``."""
    n, p_i = model.dofs, state.pressure
    pressure, h = float(y[n]), float(y[n + 1])
    reaction = plate_force(model, y, PENALTY, lam) / (np.pi * p_i)
    fhat = reaction if force is None else force
    area = fhat * p_i / pressure
    stretch = post.pole_stretch(model, y, PENALTY)
    radius = float(np.sqrt(area) / stretch)
    if model.obstacle is not None:  # a curved indenter: the active set's curved area and edge (O(h))
        area, radius = contact_zone_active(model, y, lam)
        area /= np.pi
    active = pressure * contact_area_active(model, y, lam) / (np.pi * p_i)
    extra = _extra(model, iterations, PENALTY)
    extra.update(penetration=penetration(model, y), penetration_pole=max(0.0, float(y[1] - h)),
                 force_reaction=reaction, force_pressure_area=active, force_difference=reaction - active)
    linear = forms(model, y, PENALTY, lam)
    clamp = post.clamp_stretch(model, y, PENALTY, linear.residual)
    profile = post.profile(model, y, PENALTY, pole=stretch, clamp=clamp, contact_radius=radius)
    out = CompressedState(
        **_echo(model, fill), pressure_initial=p_i, force=fhat, pressure=pressure, pressure_ratio=pressure / p_i,
        contact_area=float(area), contact_radius=radius, stretch_contact=stretch, height=float(y[1]),
        height_ratio=float(y[1]) / state.height, volume=linear.volume,
        profile=profile, inflated=state, solver="fem", extra=extra, **_least_tensions(linear, profile),
    )
    where = f"at Fhat = {fhat!r}"
    _check_common(model, y, PENALTY, out, where, _volume_target(fill, pressure))
    _check_gas(fill, out, where)
    if force is not None:
        _check_forces({"force_reaction": reaction}, force, tol, where)
    return out
