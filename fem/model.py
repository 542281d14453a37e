"""The discrete model: basis, boundary conditions and the bordered Newton system.

Unknowns y = [x_free, P, h]: the free nodal values of x = (rho, eta), the
pressure Phat (volume multiplier) and the plate height h. Boundary conditions
rho(0) = 0, rho(1) = 1, eta(1) = 0 are eliminated (eta(0) stays free).

Equations (forms in ``forms``):

    R(x; P, h)            = 0     (membrane + pressure + plate, free rows)
    P - P*   or  V(x) - V* = 0     (pressure or volume control)
    h - h*   or  F(x, h) - F* = 0  (plate-height or plate-force control)

and the jacobian is bordered by two columns and rows:

    [ K       -dV      dR/dh ] [dx]
    [ C_P              .     ] [dP]   C_P = [0, 1, 0] or [dV, 0, 0]
    [ C_h              .     ] [dh]   C_h = [0, 0, 1] or [dF/dx, 0, dF/dh]

Without a plate, h sits at ``NO_PLATE`` (far above the sheet) under height
control, so that every term of the contact form vanishes.
"""

from __future__ import annotations

import dataclasses
import types

import numpy as np
import scipy.sparse as sp
from skfem import Basis, ElementLineP1, ElementLineP2, ElementVector, MeshLine

from . import forms
from .material import MooneyRivlin

__all__ = [
    "Model",
    "Control",
    "NO_PLATE",
    "discretize",
    "full",
    "parameters",
    "residual",
    "jacobian",
    "penetration",
    "plate_pressure",
    "multiplier_update",
]

NO_PLATE = 1.0e3
_ELEMENTS = {1: ElementLineP1, 2: ElementLineP2}


@dataclasses.dataclass(frozen=True)
class Control:
    """What is prescribed: ``pressure`` or ``volume``; ``height`` or ``force``.

    ``force`` is the plate force in units of E T R (= Fhat pi Phat_I).
    """

    pressure: float | None = None
    volume: float | None = None
    height: float | None = NO_PLATE
    force: float | None = None


@dataclasses.dataclass(frozen=True, eq=False)
class Model:
    """A mesh, element order, material and penalty, with the dof bookkeeping."""

    material: MooneyRivlin
    basis: Basis
    order: int
    penalty: float
    free: np.ndarray
    fixed: np.ndarray
    fixed_values: np.ndarray

    @property
    def size(self) -> int:
        """Length of y: free dofs plus P and h."""
        return self.free.size + 2

    @property
    def elements(self) -> int:
        return self.basis.mesh.nelements

    def zero_multiplier(self) -> np.ndarray:
        """Contact multiplier field at the quadrature points, all zero."""
        return np.zeros((self.elements, self.basis.X.shape[1]))


def discretize(alpha: float, nodes: np.ndarray, order: int, penalty: float) -> Model:
    """Build the model on the sorted ``nodes`` of [0, 1] (inputs already checked)."""
    mesh = MeshLine(np.asarray(nodes, dtype=float))
    basis = Basis(mesh, ElementVector(_ELEMENTS[order](), 2), intorder=2 * order + 2)
    pole = basis.get_dofs(lambda x: x[0] == 0.0).nodal
    clamp = basis.get_dofs(lambda x: x[0] == 1.0).nodal
    fixed = np.concatenate([pole["u^1"], clamp["u^1"], clamp["u^2"]])
    free = np.setdiff1d(np.arange(basis.N), fixed)
    return Model(MooneyRivlin(alpha), basis, order, penalty, free, fixed, np.array([0.0, 1.0, 0.0]))


def full(model: Model, y: np.ndarray) -> np.ndarray:
    """All nodal values of x = (rho, eta) from the unknown vector y."""
    u = np.empty(model.basis.N)
    u[model.free] = y[:-2]
    u[model.fixed] = model.fixed_values
    return u


def _fields(w: dict):
    """The keyword arguments as the forms see them (attribute access)."""
    return types.SimpleNamespace(**w)


def parameters(model: Model, y: np.ndarray, lam: np.ndarray) -> dict:
    """Keyword arguments of the forms at the state y."""
    u = model.basis.interpolate(full(model, y))
    r = model.basis.global_coordinates()[0]
    return dict(u=u, r=r, P=y[-2], h=y[-1], kappa=model.penalty, lam=lam)


def residual(model: Model, y: np.ndarray, control: Control, lam: np.ndarray) -> np.ndarray:
    """The residual vector of the module docstring, length ``model.size``."""
    w = parameters(model, y, lam)
    r_x = forms.residual.assemble(model.basis, **forms.residual_coefficients(model.material, _fields(w)))
    r_x = r_x[model.free]
    if control.pressure is not None:
        r_p = y[-2] - control.pressure
    else:
        r_p = forms.volume.assemble(model.basis, **w) - control.volume
    if control.height is not None:
        r_h = y[-1] - control.height
    else:
        r_h = forms.contact_force.assemble(model.basis, **w) - control.force
    return np.concatenate([r_x, [r_p, r_h]])


def jacobian(model: Model, y: np.ndarray, control: Control, lam: np.ndarray) -> sp.csc_matrix:
    """The bordered tangent of the module docstring, sparse, square."""
    w = parameters(model, y, lam)
    free = model.free
    coefficients = forms.tangent_coefficients(model.material, _fields(w))
    k = forms.tangent.assemble(model.basis, **coefficients).tocsr()[free][:, free]
    dv = sp.csc_matrix(forms.volume_gradient.assemble(model.basis, **w)[free][:, None])
    df = sp.csc_matrix(forms.contact_force_gradient.assemble(model.basis, **w)[free][:, None])
    if control.pressure is not None:
        row_p = [None, sp.csc_matrix([[1.0]]), None]
    else:
        row_p = [dv.T, None, None]
    if control.height is not None:
        row_h = [None, None, sp.csc_matrix([[1.0]])]
    else:
        dfdh = forms.contact_force_stiffness.assemble(model.basis, **w)
        row_h = [df.T, None, sp.csc_matrix([[dfdh]])]
    return sp.bmat([[k, -dv, -df], row_p, row_h], format="csc")


def penetration(model: Model, y: np.ndarray) -> float:
    """Largest eta - h at the quadrature points, where contact is imposed (0 if none)."""
    eta = model.basis.interpolate(full(model, y))[1]
    return max(0.0, float(eta.max() - y[-1]))


def plate_pressure(model: Model, y: np.ndarray, lam) -> tuple[np.ndarray, np.ndarray]:
    """(p_N, chi) at the quadrature points: plate pressure per reference area, active set."""
    return forms.contact_pressure(_fields(parameters(model, y, lam)))


def multiplier_update(model: Model, y: np.ndarray, lam: np.ndarray) -> np.ndarray:
    """Augmented-Lagrangian (Uzawa) update: lam <- <lam + kappa (eta - h)>_+."""
    return np.asarray(plate_pressure(model, y, lam)[0])
