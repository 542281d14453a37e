r"""The discrete model: unknowns, equations and their bordered tangent, for the three kinds of state.

Unknowns y = [U, s]: U all 2 (p n + 1) nodal values of x = (rho, eta) (node j
holds U[2j] = rho, U[2j + 1] = eta), s the scalar unknowns. Prescribed dofs
keep their values (rho(0) = 0, and rho(1), eta(1) those of the reference surface's clamp,
``Model.clamp``: 1 and 0; or eta(1) alone where the meridian ends on a plane of symmetry, ``Model.ends``);
their rows are the identity in the tangent and zero in the residual.
The reference surface is the flat clamped disc (``pocket.core.geometries``, ``api.GEOMETRIES``), whose
arc length is the reference radius: the mesh's coordinate r is both; or the closed capsule's upper half, meshed
in r = 2 S / pi (``kernel``, ``capsule``): everything below holds for both, with the volume the upper half's and
the plate's force the one on each plate.

``FREE`` (no plate, inflation), s = [P]: the membrane rows R(U; P) = 0 and one
control row, P / P* - 1 (pressure control) or V(U) / V* - 1 (volume control).

The modes with a plate, ``PENALTY`` and ``FITTED``, pose the flat plate
(``pocket.core.indenters.PLATE``); ``api.CONTACTS`` maps each indenter class to the
modes that pose it. With a plate the volume row is the fluid's: V / V_I - 1 for a liquid, and
V / V_I - q(P) for a gas sealed at P_I (``gas``: the polytropic law solved for
the volume; its tangent has the corner entry -q'(P) in the column of P).

``WRAPPED``: the edge-fitted contact with a curved indenter, its unknowns as FITTED's; its
equations are ``obstacle``'s.

``PENALTY`` (fixed mesh, penalty plate at height h), s = [P, h]: R includes
the plate pressure (``kernel``); control rows V / V_I - 1 and h - h* (plate
height) or (F(U, h) - F*) / F* (plate force F = 2 pi int p_N r dr).

``FITTED`` (edge-fitted mesh, exact contact), s = [P, h, a]. The first element
(the first ``Model.flat`` elements: a quarter of the mesh on the capsule, whose flat zone is not uniform)
is the contact zone [0, a] (``geometry``): its eta dofs (the set C) are tied to
the plate, U_j = h, and its rows leave the system. The plate is a rigid body:
with the force potential F h, stationarity in h is sum_C R_j + F = 0, so the
plate force is the reaction F_plate = -sum_C R_j (R without the plate; it is
the variationally consistent flux through the first free element and
converges like the energy). The contact radius is closed by tangent contact,
no line force at the edge: vertical equilibrium of the flat disc of deformed
radius rho(a) gives F_plate = P pi rho(a)^2 + 2 pi a T_1 lambda_2 sin(psi)(a+),
so the line force vanishes iff

    T(y) = sum_C R_j + pi P U_E^2 = 0,      U_E = rho(a) (the dof of vertex ``flat``, ``edge``).

Unlike the energy's derivative in a, which vanishes quadratically there (a
configurational force ~ (line force)^2), T has a simple root. Rows:
V / V_I - 1, T / F_s, and one control: h - h* (plate height), a - a* (contact
radius) or (pi P U_E^2 - F*) / F_s (plate force: with T = 0 it is
F_plate = F*); F_s is the plate force the rows are measured against
(``Control.scale``), so that the Newton tolerance is relative to it.

Tangent (``kernel`` for K, dR/dP, dR/da; k_C = K 1_C the column of h, before
the tied rows and columns are removed):

    [ K       dR/dP             k_C               dR/da   ] [dU]
    [ dV      -q'(P) V_I        dV . 1_C          0       ] [dP]
    [ k_C^T + 2 pi P U_E e_E    1_C.dR/dP + pi U_E^2   1_C.k_C   1_C.dR/da ] [dh]
    [ control row                                         ] [da]

(dV does not depend on a: the volume is a property of the curve; the rows
carry the scalings above; q' = 0 for a liquid.) The increment of the tied dofs is dh. The prescribed
and tied dofs' rows and columns are cleared in the element matrices, which
``condensed.system`` condenses (P2) and factors.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from pocket.core.geometries import DISC, Clamp, Geometry, Symmetry, clamp_of
from pocket.core.indenters import PLATE, Indenter

from . import banded, condensed, kernel, spherepenalty
from .gas import Gas
from .geometry import Placement, contact_elements, place
from .material import Law, law_of
from .reference import Reference, reference
from .surfaces import Surface

__all__ = [
    "FITTED",
    "FREE",
    "PENALTY",
    "WRAPPED",
    "Control",
    "Model",
    "conform",
    "discretize",
    "edge",
    "fields",
    "forms",
    "linearize",
    "placement",
    "plate_force",
    "residual",
    "split",
]

FREE, PENALTY, FITTED, WRAPPED = "free", "penalty", "fitted", "wrapped"
_SCALARS = {FREE: 1, PENALTY: 2, FITTED: 3, WRAPPED: 3}


@dataclasses.dataclass(frozen=True)
class Control:
    """What is prescribed: ``pressure`` or ``volume``; and with a plate one of ``height``,
    ``radius`` (the Lagrangian contact radius a, fitted only) or ``force`` (units E T R), and the
    ``indenter`` (the flat plate; states echo it).

    ``scale`` (units E T R) divides the rows that balance forces on the plate (the tangency
    row and the force-control row), so that the absolute Newton tolerance on them is
    relative to the plate force, however small it is (``steps.solve`` sets it). The
    pressure and volume rows are relative too: P / P* - 1, V / V* - 1 (V / V* - q(P) with a ``gas``
    sealed at V* = V_I).
    """

    pressure: float | None = None
    volume: float | None = None
    height: float | None = None
    radius: float | None = None
    force: float | None = None
    scale: float = 1.0
    gas: Gas | None = None
    indenter: Indenter = PLATE


@dataclasses.dataclass(frozen=True, eq=False)
class Model:
    """A reference mesh ``xi`` (vertices, (n + 1,)), element tables, the rubber's law and the penalty;
    ``obstacle``, the surface (``surfaces.Surface``) of a curved indenter posed by penalty (None: the plate);
    ``geometry``, the reference surface (``pocket.core.geometries``; the flat clamped disc); ``flat``, the
    elements of the flat contact zone of FITTED (1 on the disc, whose zone is uniform; more on the capsule's sphere).

    ``workspace`` holds the large arrays of ``linearize`` from one call to the next (a system it
    returns is valid until the next call, which is how Newton uses it).
    """

    law: Law
    xi: np.ndarray
    ref: Reference
    penalty: float
    obstacle: Surface | None = None
    geometry: Geometry = DISC
    flat: int = 1
    workspace: dict = dataclasses.field(default_factory=dict, repr=False)

    @property
    def order(self) -> int:
        return self.ref.order

    @property
    def clamp(self) -> Clamp:
        """Where the reference surface's meridian ends, held fixed: the prescribed rho(1) and eta(1)."""
        return clamp_of(self.geometry)

    @property
    def elements(self) -> int:
        return self.xi.size - 1

    @property
    def dofs(self) -> int:
        """Nodal dofs N = 2 (p n + 1)."""
        return 2 * (self.order * self.elements + 1)

    @property
    def kl(self) -> int:
        """Half-bandwidth of the tangent: 2 p + 1."""
        return 2 * self.order + 1

    def ends(self) -> dict[int, float]:
        """The prescribed dofs and their values: rho(0) = 0, and at the meridian's end rho(1), eta(1) of a clamp
        or eta(1) alone on a plane of symmetry (the capsule's equator, its radius free)."""
        n, end = self.dofs, self.geometry.end
        if isinstance(end, Symmetry):
            return {0: 0.0, n - 1: end.height}
        clamp = self.clamp
        return {0: 0.0, n - 2: clamp.radius, n - 1: clamp.height}

    def fixed(self, mode: str) -> np.ndarray:
        """Dofs held fixed in ``mode``: rho(0), the end's (``ends``), and with FITTED (WRAPPED) the tied set C
        (the eta dofs of the contact zone, ``obstacle``)."""
        bc = np.array(list(self.ends()))
        if mode == WRAPPED:
            return np.concatenate([bc, 2 * np.arange(self.order * contact_elements(self.elements) + 1) + 1])
        return np.concatenate([bc, self.tied()]) if mode == FITTED else bc

    def tied(self) -> np.ndarray:
        """C: the eta dofs of the contact elements' nodes (FITTED)."""
        return 2 * np.arange(self.order * self.flat + 1) + 1


def discretize(material, nodes: np.ndarray, order: int, penalty: float, geometry: Geometry = DISC) -> Model:
    """The model of the rubber ``material`` (a Material, or a Mooney-Rivlin alpha: ``material.law_of``) on
    the reference vertices ``nodes`` (arc lengths from the pole over the meridian's length, checked by the caller)
    of the reference surface ``geometry`` (one ``api.GEOMETRIES`` poses): on the capsule's sphere the flat
    contact zone of FITTED is not uniform, and a quarter of the elements (``geometry.contact_elements``) map onto
    it."""
    nodes = np.asarray(nodes, dtype=float)
    flat = 1 if geometry is DISC else contact_elements(nodes.size - 1)
    return Model(law_of(material), nodes, reference(order), penalty, geometry=geometry, flat=flat)


def edge(model: Model) -> int:
    """Index of rho(a), the rho dof of vertex ``model.flat`` (FITTED)."""
    return 2 * model.order * model.flat


def conform(model: Model, y: np.ndarray, mode: str) -> np.ndarray:
    """A copy of y with the prescribed dofs at their values and (FITTED) the tied dofs at h."""
    out = np.array(y, dtype=float)
    n, ends = model.dofs, model.ends()
    out[list(ends)] = list(ends.values())
    if mode == FITTED:
        out[model.tied()] = out[n + 1]
    return out


def split(model: Model, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(U, scalars) of the unknown vector y."""
    return y[: model.dofs], y[model.dofs:]


def placement(model: Model, y: np.ndarray, mode: str) -> Placement:
    """The physical elements of the state y."""
    if mode == WRAPPED:
        return place(model.xi, model.ref, y[model.dofs + 2], contact_elements(model.elements))
    return place(model.xi, model.ref, y[model.dofs + 2] if mode == FITTED else None, model.flat)


def _contact(model: Model, y: np.ndarray, mode: str, multiplier):
    return kernel.Contact(y[model.dofs + 1], model.penalty, multiplier) if mode == PENALTY else None


def fields(model: Model, y: np.ndarray, mode: str) -> kernel.Fields:
    """The state y at the quadrature points."""
    u, s = split(model, y)
    return kernel.fields(model.ref, placement(model, y, mode), u, s[0], model.geometry)


def forms(model: Model, y: np.ndarray, mode: str, multiplier=0.0, tangent: bool = False, out=None) -> kernel.Linear:
    """The forms at the state y (``kernel.evaluate``): R and its derivatives, the volume, the plate force."""
    u, s = split(model, y)
    contact, place = _contact(model, y, mode, multiplier), placement(model, y, mode)
    if contact is not None and model.obstacle is not None:
        linear = kernel.evaluate(model.law, model.ref, place, u, s[0], None, tangent, out)
        return spherepenalty.add(model.ref, place, u, s[0], contact, model.obstacle, linear, tangent)
    return kernel.evaluate(model.law, model.ref, place, u, s[0], contact, tangent, out, model.geometry)


def plate_force(model: Model, y: np.ndarray, mode: str, multiplier=0.0) -> float:
    """Plate force F (units E T R): the penalty integral, or the reaction -sum_C R_j (FITTED)."""
    linear = forms(model, y, mode, multiplier)
    return linear.plate_force if mode == PENALTY else -float(linear.residual[model.tied()].sum())


def residual(model: Model, y: np.ndarray, mode: str, control: Control, multiplier=0.0) -> np.ndarray:
    """The residual [R with fixed rows zeroed, control rows], length ``len(y)``."""
    linear = forms(model, y, mode, multiplier)
    full = linear.residual.copy()
    border = _border_residual(model, y, mode, control, linear)
    full[model.fixed(mode)] = 0.0
    return np.concatenate([full, border])


def _border_residual(model, y, mode, control, linear) -> np.ndarray:
    u, s = split(model, y)
    rows = [s[0] / control.pressure - 1.0 if control.pressure is not None
            else linear.volume / control.volume - _ratio(control, s[0])[0]]
    if mode == PENALTY:
        rows.append(s[1] - control.height if control.height is not None
                    else (linear.plate_force - control.force) / control.scale)
    elif mode == FITTED:
        pa = np.pi * s[0] * u[edge(model)] ** 2
        rows.append((linear.residual[model.tied()].sum() + pa) / control.scale)
        if control.height is not None:
            rows.append(s[1] - control.height)
        elif control.radius is not None:
            rows.append(s[2] - control.radius)
        else:
            rows.append((pa - control.force) / control.scale)
    return np.array(rows)


def linearize(model: Model, y: np.ndarray, mode: str, control: Control, multiplier=0.0):
    """(residual, the bordered tangent: ``condensed.system``) at y."""
    u, s = split(model, y)
    n, m = model.dofs, _SCALARS[mode]
    buffer = banded.Buffers(model.workspace)
    out = buffer("vectors", (4, n)), buffer("matrices", (model.elements, model.ref.local, model.ref.local))
    linear = forms(model, y, mode, multiplier, tangent=True, out=out)
    border = _border_residual(model, y, mode, control, linear)
    fixed = model.fixed(mode)
    full = linear.residual.copy()
    full[fixed] = 0.0
    matrices, rp = linear.matrices, linear.pressure  # dR/dP = -dV
    b, c = buffer("columns", (n, m)), buffer("rows", (m, n))  # B and C of the bordered system
    b[:, 0] = rp
    if control.pressure is None:
        assert control.volume is not None, "a control prescribes the pressure or the volume"
        np.divide(rp, -control.volume, out=c[0])
    else:
        c[0] = 0.0
    corner = np.zeros((m, m))
    corner[0, 0] = 1.0 / control.pressure if control.pressure is not None else -_ratio(control, s[0])[1]
    if mode == PENALTY:
        b[:, 1] = -linear.force
        if control.height is not None:
            c[1] = 0.0
            corner[1, 1] = 1.0
        else:
            np.divide(linear.force, control.scale, out=c[1])
            corner[1, 1] = linear.force_stiffness / control.scale
    elif mode == FITTED:
        tied, e = model.tied(), edge(model)
        k_c, r_a = _tied_column(model, matrices, buffer("tied", (n,))), linear.radius
        b[:, 1], b[:, 2] = k_c, r_a
        np.divide(k_c, control.scale, out=c[1])
        c[1, e] += 2.0 * np.pi * s[0] * u[e] / control.scale
        c[2] = 0.0
        corner[0, 1] = -rp[tied].sum() / control.volume if control.pressure is None else 0.0
        corner[1] = np.array([rp[tied].sum() + np.pi * u[e] ** 2, k_c[tied].sum(), r_a[tied].sum()]) / control.scale
        if control.height is not None:
            corner[2, 1] = 1.0
        elif control.radius is not None:
            corner[2, 2] = 1.0
        else:
            c[2, e] = 2.0 * np.pi * s[0] * u[e] / control.scale
            corner[2, 0] = np.pi * u[e] ** 2 / control.scale
    b[fixed] = 0.0
    c[:, fixed] = 0.0
    banded.constrain(matrices, 2 * model.order, fixed)
    return np.concatenate([full, border]), condensed.system(matrices, model.order, b, c, corner, model.workspace)


def _ratio(control: Control, pressure: float) -> tuple[float, float]:
    """(q, dq/dP): the volume ratio V / V_I of the fluid at P and its slope (1, 0 for a liquid)."""
    return (1.0, 0.0) if control.gas is None else control.gas.ratio(pressure)


def _tied_column(model: Model, matrices: np.ndarray, out: np.ndarray) -> np.ndarray:
    """k_C = K 1_C, written into ``out``, from the elements that hold the tied dofs (the contact
    elements and the next)."""
    local = np.zeros((model.flat + 1, model.ref.local))
    local[:-1, 1::2] = 1.0  # every eta dof of the contact elements
    local[-1, 1] = 1.0  # the edge vertex's eta dof, first in the next element
    out[:] = 0.0
    products = np.matmul(matrices[: model.flat + 1], local[:, :, None])[:, :, 0]
    rows = 2 * model.order * np.arange(model.flat + 1)[:, None] + np.arange(model.ref.local)
    np.add.at(out, rows, products)  # element by element, in order: the sums of the loop this replaced
    return out
