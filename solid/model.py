r"""The discretised sheet: Taylor-Hood bases on the cross-section, its constraints, the assembled system.

Displacement u on biquadratic quadrilaterals (Q2, scikit-fem's ``ElementQuad2``), the pressure p
of the incompressibility constraint on bilinear ones (Q1): the Taylor-Hood pair, stable (inf-sup)
for incompressible elasticity, with errors O(h^2) in u and p in the energy norm (O(h^3) in u in L2).
Constraints: the clamp r = 1 fixed through the thickness (u = 0), the axis r = 0 (u_r = 0).

``solid`` returns the residual and the tangent of the rubber alone, ``fluid`` the cavity's volume
and its first and second derivatives (the weak forms, assembled by the contractions of
``assembly`` on the tables each model keeps); ``equations`` borders them with the fluid and the plate.
"""

from __future__ import annotations

import dataclasses

import numpy as np
from skfem import Basis, ElementQuad1, ElementQuad2, ElementVector, FacetBasis, MeshQuad

from pocket.core.geometries import DISC, Geometry

from . import assembly

__all__ = ["Model", "discretize", "fluid", "solid", "split"]


@dataclasses.dataclass(frozen=True)
class Model:
    """The discretised sheet of thickness ``thickness`` (T/R) and rubber ``law`` (``laws.derivatives``, units
    mu_0). ``top_z`` and ``top_radial`` are the vertical and radial displacement dofs of the upper surface's
    nodes, ordered by their Lagrangian radius ``top_r``; ``mid_r`` and ``mid_dofs`` ((2, n): u_r and u_z) the
    same for the mid-surface z = 0; ``free`` the dofs not fixed by the clamp or the axis (of the vector [u, p]);
    ``tables`` the bases at the quadrature points (``assembly``); ``geometry`` the reference surface
    (``pocket.core.geometries``: the flat clamped disc); ``base`` the radial nodes of the mesh asked for and
    ``cluster`` (r_e, w) the radius its elements are clustered about and the half-width of the cluster's core
    of short elements, when the mesh follows a contact edge (``edgemesh``; None: the mesh as asked)."""

    mesh: MeshQuad
    thickness: float
    law: object
    basis_u: Basis
    basis_p: Basis
    bottom: FacetBasis
    free: np.ndarray
    top_r: np.ndarray
    top_z: np.ndarray
    top_radial: np.ndarray
    mid_r: np.ndarray
    mid_dofs: np.ndarray
    tables: assembly.Tables
    geometry: Geometry = DISC
    base: np.ndarray | None = None
    cluster: tuple[float, float] | None = None

    @property
    def size(self) -> int:
        """Unknowns of [u, p]."""
        return self.basis_u.N + self.basis_p.N


def _line(basis: Basis, z: float) -> tuple[np.ndarray, np.ndarray]:
    """The nodes of the displacement basis at height z: their radii (sorted) and their (u_r, u_z) dofs
    ((2, n))."""
    loc = basis.doflocs
    on = [k[np.isclose(loc[1, k], z, rtol=0.0, atol=1e-12)] for k in basis.split_indices()]
    on = [k[np.argsort(loc[0, k])] for k in on]
    return loc[0, on[1]], np.array(on)


def discretize(thickness: float, mesh: MeshQuad, law, geometry: Geometry = DISC) -> Model:
    """The model of ``mesh`` (``mesh.section`` of the reference surface ``geometry``) for the sheet of
    T/R = ``thickness`` and the rubber ``law``."""
    basis_u = Basis(mesh, ElementVector(ElementQuad2()))
    basis_p = basis_u.with_element(ElementQuad1())
    bottom = FacetBasis(mesh, basis_u.elem, facets="bottom")
    fixed = np.concatenate([basis_u.get_dofs("right").all(), basis_u.get_dofs("left").all("u^1")])
    free = np.setdiff1d(np.arange(basis_u.N + basis_p.N), fixed)
    top_r, top = _line(basis_u, 0.5 * thickness)
    mid_r, mid = _line(basis_u, 0.0)
    return Model(mesh, thickness, law, basis_u, basis_p, bottom, free, top_r, top[1], top[0], mid_r, mid,
                 assembly.tables(basis_u, basis_p, bottom), geometry)


def split(model: Model, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The displacement and pressure parts of y = [u, p, ...]."""
    n = model.basis_u.N
    return y[:n], y[n:model.size]


def solid(model: Model, u: np.ndarray, p: np.ndarray):
    """The rubber's residual (R_u, R_p) and tangent blocks (K_uu, K_pu) at (u, p) (the weak forms, assembled by
    ``assembly``)."""
    return assembly.solid(model.tables, model.law, u, p)


def fluid(model: Model, u: np.ndarray):
    """The cavity's volume V (R^3) under the lower surface, V' (N_u,) and V'' (N_u x N_u) at u."""
    return assembly.fluid(model.tables, u)
