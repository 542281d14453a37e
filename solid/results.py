"""The solid's states in the membrane solvers' containers (``pocket.core.states``), key by key comparable.

Units as the membrane's: lengths / R, Phat = P R / (E T) = p_f / (3 t) (p_f in units mu_0, E = 3
mu_0), Fhat = F / (P_I pi R^2). ``height`` is the upper surface's pole height (the plate's height
in contact) above the clamp plane (the flat sheet's mid-plane), ``volume`` the cavity's under the
lower surface (the fluid's). The profile is the mid-surface's, its tensions the through-thickness
stress resultants (``post``). Extra keys: ``height_mid`` (the mid-surface's pole height),
``volume_mid`` (the volume under the mid-surface, from its own flat plane: equal to ``volume`` up
to the discrete incompressibility, for the sheet between them keeps its volume), the mesh
(``mesh_elements`` along the radius, as built: the clamp's corner elements replace a few of the
elements asked for; ``mesh_layers`` through the thickness) and the iterations, and two measures of
det F - 1 (``post``), named for what they are, not a volume error: ``det_f_constraint_residual`` (the
residual of Taylor-Hood's constraint int q (J - 1) dV = 0, max over the bilinear pressures q of
|int q (J - 1) dV| / int q dV: at the Newton tolerance) and ``mesh_det_f_error_peak`` (the largest
|det F - 1| at one quadrature point: ~0.4 at the clamp's singular corners, a local discretisation
error of the mesh; the sheet's volume is kept to the constraint's residual).

The states are the solid's, not a membrane's (``membrane`` false): a compressive stress resultant is
carried by the solid, and its warning says what that means for it (``pocket.core.states``).

Contact on the plate: the contact edge lies between the outermost node of the active set and the next
node, which is free. Beyond the edge the sheet leaves the plate tangentially, its gap to the plate
growing as g ~ (r - r_c)^2 where its tension bends it (the membrane's edge, whose curvature jumps there)
and as (r - r_c)^(3/2) very close to the edge, within a fraction of the thickness, where the solid is
locally a half-space (the Hertz asymptotics). With the exponent a (g^(1/a) linear in r beyond the edge),
the two free nodes beyond the active set, with gaps g_1 and g_2 at r_1 and r_2, place the edge at

    r_c = r_1 - g_1^(1/a) (r_2 - r_1) / (g_2^(1/a) - g_1^(1/a)),

kept within a node of the active set's edge: between the last active node but one and the first free
node (the contact acts on the nodes only, so between them the discrete surface may sit a little above or
below the plate, and the last active node often carries a small force: the continuum's edge can lie
before it). The exponent is the one of the nodes' distance from the edge (``edge_radius``):
``EDGE_EXPONENT`` = 3/2 where they lie in the core of the cluster of short elements the mesh keeps about
the edge (``edgemesh``), ``GAP_EXPONENT`` = 2 on the mesh as asked, whose elements there are longer than
the thickness' fraction. The states are solved on the clustered mesh, so that a state's edge is
extrapolated from nodes ~1e-3 R apart (``edgemesh``: its derivation and its measured convergence); the
spread of the two exponents' estimates from the same state is its own error estimate
(``extra["contact_radius_error"]``, R). The deformed radius rho_c is the upper surface's at r_c, the
contact area pi rho_c^2 / (pi R^2). The plate's reaction is the sum of the contact forces
(``extra["reaction"]``, Fhat).

Under a sphere of radius K or a profile (``contact``) the same, with the gaps to the indenter and the
meanings of the membrane solvers: ``height`` the indenter's lowest point h, ``contact_area`` the curved
area in contact over pi R^2 (``contact.Surface.area``: 2 K z(rho_c) on a sphere), ``contact_radius_deformed``
rho_c, ``stretch_contact`` the pole's stretch (the zone is not uniform), and the reaction the vertical part
of the contact forces, sum_k lambda_k dg_k/dh. A state whose contact reaches the sphere's equator or the
profile's last radius, or whose mid-surface reaches the clamp plane, is past the end of the range and is
refused on the load path (``rangeend``); one read here against a surface its contact passes (the sphere's
equator, the profile's last radius) is an OutOfRangeError all the same, for it has no contact area.
"""

from __future__ import annotations

import numpy as np

from pocket.core.errors import OutOfRangeError
from pocket.core.fluids import Fluid
from pocket.core.materials import Material
from pocket.core.states import CompressedState, InflatedState, Profile

from .contact import PLATE_SURFACE, Surface, gaps
from .contact import force as force_of
from .model import Model, split
from .post import fields

__all__ = ["EDGE_EXPONENT", "GAP_EXPONENT", "compressed", "contact_radius", "edge_radius", "inflated"]


def _profile(f, contact: np.ndarray) -> Profile:
    return Profile(f.r, f.rho, f.eta, f.stretch_1, f.stretch_2, f.tension_1, f.tension_2, contact)


def _extra(model: Model, f, iterations: int) -> dict:
    return {"height_mid": float(f.eta[0]), "volume_mid": f.volume_mid,
            "det_f_constraint_residual": f.det_f_constraint_residual, "mesh_det_f_error_peak": f.mesh_det_f_error_peak,
            "thickness_ratio": model.thickness, "mesh_elements": model.mesh.t.shape[1] // _layers(model),
            "mesh_layers": _layers(model), "iterations": iterations}


def _layers(model: Model) -> int:
    return np.unique(np.round(model.mesh.p[1], 12)).size - 1


#: the gap's growth beyond a contact edge, g ~ (r - r_c)^GAP_EXPONENT (module docstring)
GAP_EXPONENT = 2.0
#: the gap's growth within a fraction of the thickness of the edge, where a mesh clustered there has its
#: nodes (``edgemesh``): the half-space's (Hertz)
EDGE_EXPONENT = 1.5


def contact_radius(model: Model, y: np.ndarray, active: np.ndarray, surface: Surface = PLATE_SURFACE,
                   exponent: float = GAP_EXPONENT) -> float:
    """The Lagrangian contact radius r_c / R of the state y in contact on the upper-surface nodes ``active``
    with the indenter ``surface`` (default the flat plate), extrapolated from the gaps of the two nodes beyond
    them as g ~ (r - r_c)^``exponent`` (module docstring)."""
    edge = int(np.max(active))
    r = model.top_r
    if edge + 2 >= r.size:
        return float(r[edge])
    gap = gaps(model, surface, y, np.arange(edge + 1, edge + 3))
    q = np.maximum(gap, 0.0) ** (1.0 / exponent)
    if q[1] <= q[0]:  # the gap does not grow: no edge to extrapolate to
        return float(r[edge])
    low = r[edge - 1] if edge > 0 else r[edge]
    return float(np.clip(r[edge + 1] - q[0] * (r[edge + 2] - r[edge + 1]) / (q[1] - q[0]), low, r[edge + 1]))


def edge_radius(model: Model, y: np.ndarray, active: np.ndarray, surface: Surface = PLATE_SURFACE) -> float:
    """The contact radius r_c / R of the state y (``contact_radius``) with the gap's exponent of the nodes it is
    extrapolated from: ``EDGE_EXPONENT`` where they lie in the core of a cluster of short elements about the
    edge (``edgemesh``, ``Model.cluster``), ``GAP_EXPONENT`` elsewhere."""
    return contact_radius(model, y, active, surface, EDGE_EXPONENT if in_cluster(model, active) else GAP_EXPONENT)


def in_cluster(model: Model, active: np.ndarray) -> bool:
    """Whether the two nodes beyond the active set lie in the core of the mesh's cluster (``Model.cluster``)."""
    if model.cluster is None:
        return False
    edge, width = model.cluster
    beyond = model.top_r[min(int(np.max(active)) + 2, model.top_r.size - 1)]
    return bool(abs(model.top_r[int(np.max(active))] - edge) <= width and abs(beyond - edge) <= width)


def volume(model: Model, y: np.ndarray) -> float:
    """The cavity's volume (R^3) of the state y."""
    from .model import fluid

    return fluid(model, split(model, y)[0])[0]


def inflated(model: Model, material: Material, y: np.ndarray, iterations: int, pressure=None, volume_given=None):
    """The InflatedState of y; ``pressure`` or ``volume_given`` echoes what was asked."""
    f = fields(model, y)
    phat = float(y[model.size]) / (3.0 * model.thickness)
    return InflatedState(
        material=material, pressure=phat if pressure is None else pressure,
        stretch_pole=float(f.stretch_1[0]), height=float(f.top_eta[0]),
        volume=volume(model, y) if volume_given is None else volume_given,
        stretch_clamp=float(f.stretch_1[-1]), profile=_profile(f, np.zeros(f.r.size, bool)), solver="solid",
        extra=_extra(model, f, iterations), membrane=False, geometry=model.geometry)


def compressed(model: Model, material: Material, y: np.ndarray, active: np.ndarray, iterations: int,
               start: InflatedState, fluid: Fluid, force: float | None = None,
               surface: Surface = PLATE_SURFACE) -> CompressedState:
    """The CompressedState of y in contact on the upper-surface nodes ``active`` with the indenter ``surface``
    (default the flat plate); ``force`` echoes the Fhat asked (None under height control: the reaction)."""
    f = fields(model, y)
    scale = 3.0 * model.thickness
    phat = float(y[model.size]) / scale
    reaction = force_of(model, surface, y, active) / (np.pi * start.pressure * scale)
    r_c = edge_radius(model, y, active, surface)
    rho_c = float(np.interp(r_c, f.r, f.top_rho))
    if rho_c >= surface.reach:
        raise OutOfRangeError(f"the sheet would wrap past {surface.end} (its contact reaches rho = {rho_c:.6g} R, "
                              f"the indenter's surface ends at {surface.reach:.6g} R)")
    area = surface.area(rho_c)
    stretch = float(np.interp(r_c, f.r, f.stretch_2) if surface.flat else f.stretch_1[0])
    height = float(y[model.size + 1])
    extra = {**_extra(model, f, iterations), "reaction": reaction}
    if in_cluster(model, active):
        extra["contact_radius_error"] = abs(contact_radius(model, y, active, surface) - r_c)
    return CompressedState(
        material=material, pressure_initial=start.pressure, force=reaction if force is None else force,
        pressure=phat, pressure_ratio=phat / start.pressure, contact_area=area, contact_radius=r_c,
        stretch_contact=stretch, height=height, height_ratio=height / start.height,
        volume=volume(model, y), profile=_profile(f, f.r <= r_c), inflated=start, solver="solid", extra=extra,
        fluid=fluid, contact_radius_deformed=rho_c, membrane=False)
