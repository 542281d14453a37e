r"""Edge-fitted contact with a curved indenter: the sheet wrapped on z(rho), contact exact, Newton on (U, P, h, a).

Unknowns as FITTED's (``model``), y = [U, P, h, a], in mode ``WRAPPED``: the first k elements
(``geometry.contact_elements``) map onto the contact zone [0, a], r = a xi / xi_k, so vertex k
(node E = p k) is the contact edge and moves with it. There the sheet lies on the indenter,

    eta(r) = h + z(rho(r))        (frictionless: rho slides freely along the surface),

exactly at every point, so the zone's only field is s = rho (its eta dofs are tied: eta_j = h + z(rho_j),
and leave the system). With g = z'(s), c = sqrt(1 + g^2), the stretches are l1 = s' c, l2 = s / r, and
the energy density (units E T R) and the fluid's share, -P times -pi rho^2 eta', are

    E(s, s', r) = 2 pi r w(l1, l2) + P q(s) s',     q = pi s^2 g.

With c_s = g z'' / c, the residual's flux and source are (v a variation of s)

    R(v) = int (E_s' v' + E_s v) dr,   E_s' = 2 pi r w_1 c + P q,
    E_s = 2 pi (r w_1 s' c_s + w_2) + P q_s s',

and the tangent int (A v' du' + B (v' du + v du') + C v du) dr with
A = 2 pi r w_11 c^2, B = 2 pi (r c s' c_s w_11 + c w_12 + r w_1 c_s) + P q_s,
C = 2 pi (r w_11 (s' c_s)^2 + 2 w_12 s' c_s + r w_1 s' c_ss + w_22 / r) + P q_ss s'. The pressure
term is a total derivative, d(P Z(s))/dr with Z' = q: the fluid does no work along the contact zone
(tangential equilibrium there does not involve P). dR/dP has flux q and source q_s s'. The zone
scales with a (r and the element lengths L are proportional to it), so at fixed nodal values
ds'/da = -s'/a, dr/da = r/a, dL/da = L/a and

    dR/da(v) = int [(-A s' + E_s'r r) v' + (E_s + (-B s' + E_sr r)) v] dr / a,
    E_s'r = 2 pi c (w_1 - l2 w_12),   E_sr = 2 pi (s' c_s (w_1 - l2 w_12) - w_22 l2 / r).

The free part [a, 1] is ``kernel``'s (its elements from the edge on), its a-derivative that of
``kernel``'s docstring with V = (1 - r)/(1 - a), V' = -1/(1 - a). It meets the zone at node E,
whose height is eta_E = h + z(rho_E): with R^f the free part's residual, the edge's rho row is the
contact one plus R^f_rho + g R^f_eta (tangential equilibrium of the edge node), its tangent the
free element's J^T K J + z'' R^f_eta (J: d(rho_E, eta_E)/d rho_E = (1, g)), and h enters only
through eta_E: dR/dh = J^T K e_eta_E, and the indenter's reaction is F = -R^f_eta_E.

Tangent contact closes a: the line force at the edge, normal to the surface (n = (-g, 1)/c), is the
normal component of the fluxes meeting there; the zone's flux is along the surface but for the
fluid's pi P rho^2 in eta, so the line force vanishes iff

    T(y) = R^f_eta_E - g R^f_rho_E + pi P rho_E^2 = 0,

which is the flat plate's closure (``model``) at g = 0 and has a simple root. Rows: the fluid's
V / V_I - q(P), T / F_s, and one control: h - h*, a - a* or (F - F*) / F_s (F_s as ``model.Control``).
The volume is that of the whole meridian (zone and free part); it does not depend on a at fixed
nodal values. Each iteration assembles element by element and solves the bordered band (``condensed``):
O(N).

``solve`` runs Newton, projects the zone's eta dofs onto the surface, and refuses a state outside
the model (``OutOfRangeError``): the zone wrapping past the surface's reach (a sphere's equator),
the free sheet above the surface (touching it outside the contact zone), a contact pressure
p_c = P + kappa_1 T_1 + kappa_2 T_2 below zero at a point of the zone, the indenter's lowest point
below the clamp plane, or the free part at it (``steps.check_clamp``).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from pocket.core.errors import OutOfRangeError

from . import banded, condensed, kernel
from .geometry import Placement, contact_elements
from .model import WRAPPED, Control, Model, placement
from .newton import Tolerances, newton
from .steps import check_clamp, scales
from .surfaces import Surface, surface

__all__ = [
    "PENETRATION",
    "Forms",
    "Zone",
    "check_range",
    "conform",
    "contact_pressure",
    "forms",
    "linearize",
    "reaction",
    "residual",
    "solve",
    "zone",
]

TWO_PI = 2.0 * np.pi
#: height (units R) by which the free sheet may sit above the surface before it counts as touching
#: it: the nodal values carry round-off of ~1e-16 R, and the gap closes quadratically at the edge
PENETRATION = 1e-12


@dataclasses.dataclass(frozen=True, eq=False)
class Zone:
    """The contact zone's forms at one state: at the zone's nodes (p k + 1,) the residual, dR/dP, dR/da of
    s = rho; the element matrices (k, p + 1, p + 1); its volume; and at its quadrature points (k, Q) r,
    rho, drho/dr, the tensions T_1, T_2 and the weights times the lengths (for integrals over r)."""

    residual: np.ndarray
    pressure: np.ndarray
    radius: np.ndarray
    matrices: np.ndarray
    volume: float
    r: np.ndarray
    rho: np.ndarray
    drho: np.ndarray
    tension_1: np.ndarray
    tension_2: np.ndarray
    measure: np.ndarray


def _gather(values: np.ndarray, p: int, k: int) -> np.ndarray:
    """(k, p + 1, ...) element values -> the sum at the p k + 1 nodes."""
    out = np.zeros((p * k + 1, *values.shape[2:]))
    for a in range(p + 1):
        out[a: a + p * (k - 1) + 1: p] += values[:, a]
    return out


def zone(model: Model, place: Placement, s_nodes: np.ndarray, pressure: float, surf: Surface,
         tangent: bool = True) -> Zone:
    """The contact zone's forms (module docstring) at the nodal radii ``s_nodes`` (p k + 1,)."""
    ref, p, k = model.ref, model.order, contact_elements(model.elements)
    S = s_nodes[p * np.arange(k)[:, None] + np.arange(p + 1)]
    L, r, a = place.lengths[:k, None], place.r[:k], place.a
    s, sp = S @ ref.phi.T, (S @ ref.dphi.T) / L
    g, g1, g2 = surf.slope(s), surf.second(s), surf.third(s)
    c = np.sqrt(1.0 + g * g)
    cs = g * g1 / c
    css = (g1 * g1 + g * g2) / c - (g * g1) ** 2 / c**3
    q, qs, qss = np.pi * s * s * g, np.pi * (2 * s * g + s * s * g1), np.pi * (2 * g + 4 * s * g1 + s * s * g2)
    l1, l2 = sp * c, s / r
    w1, w2, w11, w12, w22 = model.law.derivatives(l1, l2)
    P = pressure
    flux = TWO_PI * r * w1 * c + P * q
    source = TWO_PI * (r * w1 * sp * cs + w2) + P * qs * sp
    A = TWO_PI * r * w11 * c * c
    B = TWO_PI * (r * c * sp * cs * w11 + c * w12 + r * w1 * cs) + P * qs
    C = TWO_PI * (r * w11 * (sp * cs) ** 2 + 2 * w12 * sp * cs + r * w1 * sp * css + w22 / r) + P * qss * sp
    flux_r = TWO_PI * c * (w1 - l2 * w12)
    source_r = TWO_PI * (sp * cs * (w1 - l2 * w12) - w22 * l2 / r)
    wq, phi, dphi = ref.weights, ref.phi, ref.dphi

    def integrate(f, g_):
        return np.einsum("q,eq,qa->ea", wq, f, dphi) + np.einsum("q,eq,qa->ea", wq, L * g_, phi)

    res = _gather(integrate(flux, source), p, k)
    res_p = _gather(integrate(q, qs * sp), p, k)
    res_a = _gather(integrate((-A * sp + flux_r * r) / a, (source - B * sp + source_r * r) / a), p, k)
    matrices = np.zeros((k, p + 1, p + 1))
    if tangent:
        matrices = (np.einsum("q,eq,qa,qb->eab", wq, A / L, dphi, dphi)
                    + np.einsum("q,eq,qa,qb->eab", wq, B, dphi, phi)
                    + np.einsum("q,eq,qa,qb->eab", wq, B, phi, dphi)
                    + np.einsum("q,eq,qa,qb->eab", wq, C * L, phi, phi))
    volume = -float(np.einsum("q,eq->", wq, q * sp * L))
    return Zone(res, res_p, res_a, matrices, volume, r, s, sp, w1 / l2, w2 / l1, wq[None, :] * L)


def _free_rate(model: Model, place: Placement, u_free: np.ndarray, pressure: float) -> np.ndarray:
    """dR/da of the free part (its dofs), from ``kernel``'s formula with V = (1 - r)/(1 - a), V' = -1/(1 - a)."""
    ref, a = model.ref, place.a
    assert a is not None, "a WRAPPED placement has its contact edge"
    w = kernel.fields(ref, place, u_free, pressure)
    w1, w2, w11, w12, w22 = model.law.derivatives(w.l1, w.l2)
    velocity, rate = (1.0 - w.r) / (1.0 - a), -1.0 / (1.0 - a)
    common = TWO_PI * ((w1 - w.l2 * w12) * velocity - w11 * w.r * w.l1 * rate)
    fa0, fa1 = common * w.drho / w.l1, common * w.deta / w.l1
    ga0 = TWO_PI * ((w2 - w.l1 * w12) * rate - w22 * w.l2 / w.r * velocity)
    L = w.lengths[:, None]
    local = np.zeros((L.size, ref.order + 1, 2))
    local[:, :, 0] = np.einsum("q,eq,qa->ea", ref.weights, fa0, ref.dphi) + \
        np.einsum("q,eq,qa->ea", ref.weights, L * ga0, ref.phi)
    local[:, :, 1] = np.einsum("q,eq,qa->ea", ref.weights, fa1, ref.dphi)
    return _gather(local, ref.order, L.size).ravel()


@dataclasses.dataclass(frozen=True, eq=False)
class Forms:
    """The forms at one state: the zone's (``Zone``), the free part's (``kernel.Linear``, its dofs from
    the edge node on, and its dR/da), the assembled R, dR/dP, dR/da (N,), the volume, and z', z'' at the
    edge."""

    zone: Zone
    free: kernel.Linear
    free_rate: np.ndarray
    residual: np.ndarray
    pressure: np.ndarray
    radius: np.ndarray
    volume: float
    slope: float
    second: float


def conform(model: Model, y: np.ndarray, surf: Surface) -> np.ndarray:
    """A copy of y with the prescribed dofs at their values and the zone's eta dofs on the surface."""
    out = np.array(y, dtype=float)
    n, e, clamp = model.dofs, model.order * contact_elements(model.elements), model.clamp
    out[[0, n - 2, n - 1]] = 0.0, clamp.radius, clamp.height
    out[1: 2 * e + 2: 2] = out[n + 1] + surf.height(out[0: 2 * e + 1: 2])
    return out


def forms(model: Model, y: np.ndarray, surf: Surface, tangent: bool = False) -> Forms:
    """The forms of the module docstring at the (conforming) state y."""
    n, p = model.dofs, model.order
    k = contact_elements(model.elements)
    E = p * k
    place = placement(model, y, WRAPPED)
    pressure = float(y[n])
    zn = zone(model, place, y[0: 2 * E + 1: 2], pressure, surf, tangent)
    free_place = Placement(place.vertices[k:], place.lengths[k:], place.r[k:], place.a)
    u_free = np.ascontiguousarray(y[2 * E: n])
    free = kernel.evaluate(model.law, model.ref, dataclasses.replace(free_place, a=None), u_free, pressure,
                           None, tangent)
    rate = _free_rate(model, free_place, u_free, pressure)
    g = float(surf.slope(y[2 * E]))
    assembled = []
    for zone_part, free_part in ((zn.residual, free.residual), (zn.pressure, free.pressure), (zn.radius, rate)):
        out = np.zeros(n)
        out[0: 2 * E + 1: 2] = zone_part
        out[2 * E:] += free_part
        out[2 * E] += g * free_part[1]
        assembled.append(out)
    residual, pressure_rate, radius_rate = assembled
    return Forms(zn, free, rate, residual, pressure_rate, radius_rate, zn.volume + free.volume, g,
                 float(surf.second(y[2 * E])))


def _ratio(control: Control, pressure: float) -> tuple[float, float]:
    """(q, dq/dP): the fluid's volume ratio V / V_I at P and its slope (1, 0 for a liquid)."""
    return (1.0, 0.0) if control.gas is None else control.gas.ratio(pressure)


def _border(model: Model, y: np.ndarray, control: Control, f: Forms) -> np.ndarray:
    """The rows V / V_I - q(P), T / F_s and the control (module docstring)."""
    n, E = model.dofs, model.order * contact_elements(model.elements)
    pressure, rho_e = y[n], y[2 * E]
    fr, fe = f.free.residual[0], f.free.residual[1]
    assert control.volume is not None, "a compression holds its fluid's volume"
    rows = [f.volume / control.volume - _ratio(control, pressure)[0],
            (fe - f.slope * fr + np.pi * pressure * rho_e**2) / control.scale]
    if control.height is not None:
        rows.append(y[n + 1] - control.height)
    elif control.radius is not None:
        rows.append(y[n + 2] - control.radius)
    else:
        rows.append((-fe - control.force) / control.scale)
    return np.array(rows)


def residual(model: Model, y: np.ndarray, control: Control, surf: Surface) -> np.ndarray:
    """[R with fixed rows zeroed, the three rows] at the state y (made conforming first)."""
    y = conform(model, y, surf)
    f = forms(model, y, surf)
    full = f.residual.copy()
    full[model.fixed(WRAPPED)] = 0.0
    return np.concatenate([full, _border(model, y, control, f)])


def linearize(model: Model, y: np.ndarray, control: Control, surf: Surface):
    """(residual, the bordered tangent: ``condensed.system``) at the state y (made conforming first)."""
    y = conform(model, y, surf)
    n, p, k = model.dofs, model.order, contact_elements(model.elements)
    E, size = p * k, model.ref.local
    f = forms(model, y, surf, tangent=True)
    g, g1 = f.slope, f.second
    fr, fe = f.free.residual[0], f.free.residual[1]
    pressure, rho_e = y[n], y[2 * E]
    matrices = np.zeros((model.elements, size, size))
    matrices[:k, 0::2, 0::2] = f.zone.matrices
    matrices[k:] = f.free.matrices
    m0 = f.free.matrices[0].copy()  # the first free element, before the edge's transformation
    first = matrices[k]
    first[0] += g * first[1]
    first[:, 0] += g * first[:, 1]
    first[0, 0] += g1 * fe
    fixed = model.fixed(WRAPPED)
    rp, ra = f.free.pressure, f.free_rate
    b, c, corner = np.zeros((n, 3)), np.zeros((3, n)), np.zeros((3, 3))
    b[:, 0], b[:, 2] = f.pressure, f.radius
    b[2 * E: 2 * E + size, 1] = m0[:, 1]
    b[2 * E, 1] += g * m0[1, 1]
    c[0] = -f.pressure / control.volume
    corner[0, 0] = -_ratio(control, pressure)[1]
    corner[0, 1] = -rp[1] / control.volume
    tangency = m0[1] - g * m0[0]
    c[1, 2 * E: 2 * E + size] = tangency
    c[1, 2 * E] += g * tangency[1] - g1 * fr + TWO_PI * pressure * rho_e
    corner[1] = rp[1] - g * rp[0] + np.pi * rho_e**2, m0[1, 1] - g * m0[0, 1], ra[1] - g * ra[0]
    c[1] /= control.scale
    corner[1] /= control.scale
    if control.height is not None:
        corner[2, 1] = 1.0
    elif control.radius is not None:
        corner[2, 2] = 1.0
    else:
        c[2, 2 * E: 2 * E + size] = -m0[1]
        c[2, 2 * E] -= g * m0[1, 1]
        corner[2] = np.array([-rp[1], -m0[1, 1], -ra[1]]) / control.scale
        c[2] /= control.scale
    full = f.residual.copy()
    full[fixed] = 0.0
    b[fixed] = 0.0
    c[:, fixed] = 0.0
    banded.constrain(matrices, 2 * p, fixed)
    border = _border(model, y, control, f)
    return np.concatenate([full, border]), condensed.system(matrices, p, b, c, corner)


def _increment(model: Model, surf: Surface):
    """dy from the linear solve's parts: the zone's eta dofs follow h and the surface, d eta = dh + z' d rho."""
    e = model.order * contact_elements(model.elements)

    def join(y, x, s):
        x = x.copy()
        x[1: 2 * e + 2: 2] = s[1] + surf.slope(y[0: 2 * e + 1: 2]) * x[0: 2 * e + 1: 2]
        return np.concatenate([x, s])

    return join


def reaction(model: Model, y: np.ndarray, surf: Surface) -> float:
    """The indenter's reaction F = -R^f_eta at the contact edge (units E T R) of the state y."""
    return -float(forms(model, conform(model, y, surf), surf).free.residual[1])


def solve(model: Model, control: Control, guess: np.ndarray, tol: Tolerances) -> tuple[np.ndarray, int]:
    """Newton under ``control`` (its indenter curved: ``surfaces``) from ``guess``; (y, iterations), y
    conforming. OutOfRangeError for a state outside the model (module docstring)."""
    surf = surface(control.indenter)
    guess = conform(model, guess, surf)
    n, e = model.dofs, 2 * model.order * contact_elements(model.elements)
    scale = control.force if control.force is not None else float(np.pi * guess[n] * guess[e] ** 2)
    control = dataclasses.replace(control, scale=scale)
    result = newton(lambda z: linearize(model, z, control, surf), guess, tol, _increment(model, surf),
                    scales(model, guess, WRAPPED))
    y = conform(model, result.y, surf)
    check_range(model, y, surf)
    return y, result.iterations


def check_range(model: Model, y: np.ndarray, surf: Surface) -> None:
    """OutOfRangeError if the state y leaves the model: the clamp plane, past the surface's reach, the free
    sheet above the surface, or a negative contact pressure (module docstring)."""
    n, e = model.dofs, 2 * model.order * contact_elements(model.elements)
    where = f"at Phat = {y[n]:.6g}"
    rho_e = float(y[e])
    if not rho_e < surf.reach:
        raise OutOfRangeError(f"the sheet wraps past {surf.end} (contact radius "
                              f"rho_c/R = {rho_e:.6g} reaches {surf.reach:.6g} R, {where}), outside the model")
    free_rho, free_eta = y[e: n: 2], y[e + 1: n: 2]
    under = free_rho < surf.reach
    gap = free_eta[under] - y[n + 1] - surf.height(free_rho[under])
    if gap[1:].size and gap[1:].max() > PENETRATION:
        j = int(np.argmax(gap[1:])) + 1
        raise OutOfRangeError(f"the free sheet touches the indenter outside the contact zone (at rho/R = "
                              f"{free_rho[under][j]:.6g} it lies {gap[j]:.3g} R above its surface, {where}), "
                              "outside the model")
    zn = zone(model, placement(model, y, WRAPPED), y[0: e + 1: 2], float(y[n]), surf, tangent=False)
    pc = contact_pressure(zn, float(y[n]), surf)
    if pc.min() < 0.0:
        raise OutOfRangeError(f"the contact pressure turns negative in the contact zone (p_c R/(E T) = "
                              f"{pc.min():.3g}, {where}): the indenter would pull the sheet, outside the model")
    if y[n + 1] < 0.0:
        raise OutOfRangeError(f"the indenter presses the pole below the clamp plane (its lowest point at h/R = "
                              f"{y[n + 1]:.3g}, {where}), outside the model")
    check_clamp(model, y, WRAPPED)


def contact_pressure(zn: Zone, pressure: float, surf: Surface) -> np.ndarray:
    """p_c = P + kappa_1 T_1 + kappa_2 T_2 (units E T / R) at the zone's quadrature points (k, Q)."""
    k1, k2 = surf.curvatures(zn.rho)
    return pressure + k1 * zn.tension_1 + k2 * zn.tension_2
