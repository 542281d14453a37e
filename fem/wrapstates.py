r"""The compressed state under a curved indenter (``obstacle``), built from converged unknowns and checked.

Reported as for the flat plate (``results``), with on a curved indenter: ``contact_area`` the
CURVED area in contact over pi R^2 (``surfaces``: 2 R_s z(rho_c) / R^2 on a sphere),
``contact_radius`` = a (Lagrangian), ``stretch_contact`` the pole stretch (the zone is not
uniform), ``height`` = h, the indenter's lowest point; as the shooting solver's states (units Phat,
R): ``contact_pressure_pole`` = P + 2 kappa(0) T_0 (T_0 = w_1(l0, l0) / l0 at the pole),
``contact_pressure_edge`` p_c at the edge (T_1 there from the zone's flux, ``_edge_pressure``),
``contact_radius_deformed`` rho_c = rho(a), and ``contact_pressure`` p_c = P + kappa_1 T_1 + kappa_2 T_2
at each profile node in contact (the edge node's value the edge's, NaN off the contact zone). In
``extra`` (forces as Fhat, pressures in Phat units):

- ``force_reaction``: the indenter's reaction -R^f_eta at the edge (the force it carries);
- ``force_cap``: the contact cap as a free body, P pi rho_c^2 + 2 pi rho_c T_1 sin(theta_c),
  with 2 pi rho_c T_1 c the zone's own flux at the edge (its residual there:
  2 pi rho_c T_1 c + pi P rho_c^2 z'), sin(theta_c) = z'/c;
- ``force_contact_pressure``: the integral of p_c over the contact area,
  int_0^{rho_c} p_c 2 pi rho d rho, p_c = P + kappa_1 T_1 + kappa_2 T_2 at the zone's quadrature points;
- ``force_difference``: force_cap - force_contact_pressure (the discretisation error of the balance);
- ``contact_pressure_min``: the least p_c at the zone's quadrature points;
- ``penetration``: max(eta - h - z(rho)) over the free part's nodes under the surface (0 or round-off);
- ``energy``: the stored elastic energy U = 2 pi int w(l1, l2) r dr (units E T R^2, the rubber's W / E
  by the same quadrature as the solver's), whose slope along the indenter's travel is the force:
  F = (-dU + P dV) / dh.

Checks as ``results``' (finite numbers, positive stretches, rho(1) = 1, the fluid's volume or gas law)
and the reaction equal to the force asked (within ``results.force_allowance``).
"""

from __future__ import annotations

import numpy as np

from pocket.core.materials import energy
from pocket.core.states import CompressedState

from . import post
from .geometry import contact_elements
from .model import WRAPPED, Control, Model, fields, placement
from .newton import Tolerances
from .obstacle import contact_pressure, forms, linearize, zone
from .results import (
    _check_common,
    _check_forces,
    _check_gas,
    _echo,
    _extra,
    _fail,
    _least_tensions,
    _volume_target,
    force_control,
    identity_noise,
)
from .surfaces import surface

__all__ = ["state"]

#: the most Newton steps solving T_1(lambda_1, lambda_2) for lambda_1 at the edge (quadratic from a close start)
EDGE_NEWTON = 8


def _edge_pressure(model: Model, y: np.ndarray, surf, pressure: float, flux: float) -> float:
    """p_c at the edge (units Phat) from the zone's flux there, ``flux`` = 2 pi rho_c T_1 (converging as the
    reaction does, faster than a slope): T_1 = flux / (2 pi rho_c) and lambda_2 = rho_c / a fix lambda_1
    (Newton from the zone's last element's one-sided slope), hence T_2."""
    p, k = model.order, contact_elements(model.elements)
    nodes = y[0: 2 * p * k + 1: 2][-(p + 1):]
    place = placement(model, y, WRAPPED)
    slope = (nodes[1] - nodes[0]) if p == 1 else (nodes[0] - 4 * nodes[1] + 3 * nodes[2])
    s, g = nodes[-1], surf.slope(nodes[-1])
    l1, l2 = slope / place.lengths[k - 1] * np.sqrt(1 + g * g), s / place.vertices[k]
    target = flux / (2.0 * np.pi * s)
    for _ in range(EDGE_NEWTON):
        d = 1e-7 * l1
        low, high = (model.law.tensions(np.array([l1 + e]), np.array([l2]))[0][0] for e in (-d, d))
        step = (model.law.tensions(np.array([l1]), np.array([l2]))[0][0] - target) * 2 * d / (high - low)
        l1 -= step
        if abs(step) <= 1e-15 * l1:
            break
    t1, t2 = model.law.tensions(np.array([l1]), np.array([l2]))
    k1, k2 = surf.curvatures(s)
    return float(pressure + k1 * t1[0] + k2 * t2[0])


def _nodal_pressure(profile, surf, pressure: float, edge: float) -> np.ndarray:
    """p_c = P + kappa_1 T_1 + kappa_2 T_2 (units Phat) at each node of ``profile`` in contact, shape (n,),
    NaN off the contact zone; at the edge node the one-sided ``edge`` value (the node's averaged slope
    straddles the kink of the meridian there)."""
    on = profile.contact
    k1, k2 = surf.curvatures(profile.rho[on])
    out = np.full(profile.r.shape, np.nan)
    out[on] = pressure + k1 * profile.tension_1[on] + k2 * profile.tension_2[on]
    out[np.flatnonzero(on)[-1]] = edge
    return out


def _stored_energy(model: Model, y: np.ndarray, zn, surf) -> float:
    """U = 2 pi int w r dr (units E T R^2): the zone's points (``zn``) and the free part's (``model.fields``)."""
    material = model.law.material.scaled()  # stresses in mu_0 = E / 3
    k = contact_elements(model.elements)
    stretch = zn.drho * np.sqrt(1.0 + surf.slope(zn.rho) ** 2)
    inside = np.sum(zn.measure * zn.r * energy(material, stretch, zn.rho / zn.r))
    w = fields(model, y, WRAPPED)
    free = np.sum(model.ref.weights * w.lengths[k:, None] * w.r[k:] * energy(material, w.l1[k:], w.l2[k:]))
    return float(2.0 * np.pi * (inside + free) / 3.0)


def state(model: Model, y: np.ndarray, iterations: int, inflated, fill: Control, force,
          tol: Tolerances) -> CompressedState:
    """The compressed state of WRAPPED unknowns y at the given ``force`` (Fhat, echoed) with ``fill``; ``tol``:
    Newton's tolerances of the solve (``results.force_allowance``)."""
    surf = surface(fill.indenter)
    n, p_i = model.dofs, inflated.pressure
    e = 2 * model.order * contact_elements(model.elements)
    pressure, h, a = (float(v) for v in y[n:])
    rho_c = float(y[e])
    f = forms(model, y, surf)
    unit = np.pi * p_i
    g = float(surf.slope(np.array(rho_c)))
    c = np.sqrt(1.0 + g * g)
    ring = (f.zone.residual[-1] - np.pi * pressure * rho_c**2 * g) / c  # 2 pi rho_c T_1
    zn = zone(model, placement(model, y, WRAPPED), y[0: e + 1: 2], pressure, surf, tangent=False)
    pc = contact_pressure(zn, pressure, surf)
    integral = float(np.sum(zn.measure * pc * 2 * np.pi * zn.rho * zn.drho))
    pole = post.pole_stretch(model, y, WRAPPED)
    t0 = float(model.law.tensions(np.array([pole]), np.array([pole]))[0][0])
    cap = np.pi * pressure * rho_c**2 + ring * g / c
    free_rho, free_eta = y[e: n: 2], y[e + 1: n: 2]
    under = free_rho < surf.reach
    extra = _extra(model, iterations, "fitted")
    extra.update(force_reaction=-float(f.free.residual[1]) / unit, force_cap=cap / unit,
                 force_contact_pressure=integral / unit, force_difference=(cap - integral) / unit,
                 contact_pressure_min=float(pc.min()),
                 penetration=max(0.0, float((free_eta[under] - h - surf.height(free_rho[under])).max())),
                 energy=_stored_energy(model, y, zn, surf))
    rows = post.reaction(model, y, WRAPPED)
    clamp = post.clamp_stretch(model, y, WRAPPED, rows)
    profile = post.profile(model, y, WRAPPED, pole=pole, clamp=clamp, contact_radius=a)
    edge = _edge_pressure(model, y, surf, pressure, float(ring))
    tensions = _least_tensions(f.free, profile)
    tensions = dict(tension_1_min=min(tensions["tension_1_min"], float(zn.tension_1.min())),
                    tension_2_min=min(tensions["tension_2_min"], float(zn.tension_2.min())))
    out = CompressedState(
        **_echo(model, fill), pressure_initial=p_i, force=force, pressure=pressure, pressure_ratio=pressure / p_i,
        contact_area=surf.area(rho_c) / np.pi, contact_radius=a, stretch_contact=pole, height=h,
        height_ratio=h / inflated.height, volume=f.volume, profile=profile, inflated=inflated, solver="fem",
        extra=extra, **tensions, contact_radius_deformed=rho_c,
        contact_pressure_pole=pressure + 2.0 * float(surf.curvatures(np.array([0.0]))[0][0]) * t0,
        contact_pressure_edge=edge, contact_pressure=_nodal_pressure(profile, surf, pressure, edge),
    )
    where = f"at Fhat = {force!r} under the {fill.indenter.name}"
    _check_common(model, y, WRAPPED, out, where, _volume_target(fill, pressure))
    _check_gas(fill, out, where)
    _check_forces({"force_reaction": extra["force_reaction"]}, force, tol, where,
                  lambda: identity_noise(linearize(model, y, force_control(fill, force, np.pi * p_i), surf)[1], y))
    if not 0.0 < a < 1.0:
        _fail(where, f"contact radius a/R = {a!r} outside (0, 1)")
    return out
