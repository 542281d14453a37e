r"""The weak forms of ``forms`` assembled by contractions over whole arrays instead of per-pair form calls.

Everything that does not change between Newton iterations is tabulated once per model (``tables``):
at each quadrature point x_q of each element e and for each displacement basis function phi_i, the five
components c_ia = dF[phi_i]_a (``forms.components``), the bilinear pressures psi_k, the weights
w_eq = |e|_q 2 pi r_q of the axisymmetric measure, and, on the lower surface's facets f, the three values
d_i = (phi_i,r, phi_i,z, d phi_i,r / dr) the fluid's forms need, with w_fq = |f|_q 2 pi. A state's fields
at the points are then the contractions of its element dofs U_ei = u[dofs_ie] with these tables:

    dF_a = sum_i U_ei c_ia,   F = I + sum_a dF_a E_a,   p = sum_k P_ek psi_k,
    (u_r, u_z, du_r/dr) on the lower surface = sum_i U_fi d_i.

With the stress s = dW + p dJ and the tangent T = d^2 W + p d^2 J at the points (``kinematics``,
one ``energy_derivatives`` call per Newton iteration gives both), the element vectors and matrices are

    R_u:  sum_q w s_a c_ia,       R_p:  sum_q w psi_k (J - 1),
    K_uu: sum_q w c_ia T_ab c_jb,  K_pu: sum_q w psi_k dJ_a c_ja,

each one einsum over (basis functions, components, elements, points), added into the global arrays
through the element dofs (``np.bincount``, and COO triplets whose duplicates sum). The fluid's forms
(``forms.volume_first``, ``forms.volume_second``) are, with rho = r + u_r, zeta = u_z, rho' = 1 + du_r/dr,

    V' :  sum_q w g . d_i,          g = (zeta rho', rho rho', rho zeta),
    V'':  sum_q w d_i . M d_j,      M = [[0, rho', zeta], [rho', 0, rho], [zeta, rho, 0]],

the six terms of V''[v, w] being the symmetric bilinear form of M in (v_r, v_z, v_r') and (w_r, w_z, w_r').
Tests compare each with scikit-fem's assembly of the form it replaces.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import scipy.sparse as sp
from skfem import Basis, FacetBasis

from . import forms
from . import kinematics as kin

__all__ = ["Tables", "tables", "fields", "solid", "fluid"]


@dataclasses.dataclass(frozen=True)
class Tables:
    """A model's basis functions at its quadrature points (shapes in ``tables``)."""

    comps: np.ndarray         # (18, 5, e, q): dF[phi_i] components
    weight: np.ndarray        # (e, q): |e|_q 2 pi r
    dofs_u: np.ndarray        # (18, e)
    psi: np.ndarray           # (4, e, q): the bilinear pressures
    dofs_p: np.ndarray        # (4, e)
    facet: np.ndarray         # (18, 3, f, q): (phi_r, phi_z, d phi_r / dr) on the lower surface
    facet_r: np.ndarray       # (f, q): the facets' radii
    facet_weight: np.ndarray  # (f, q): |f|_q 2 pi
    facet_dofs: np.ndarray    # (18, f)
    n_u: int
    n_p: int


def tables(basis_u: Basis, basis_p: Basis, bottom: FacetBasis) -> Tables:
    """The tables of the displacement and pressure bases and of the lower surface's facet basis."""
    r = basis_u.global_coordinates()[0]
    comps = np.array([forms.components(phi[0], r) for phi in basis_u.basis])
    psi = np.array([np.asarray(phi[0]) for phi in basis_p.basis])
    facet = np.array([[phi[0].value[0], phi[0].value[1], phi[0].grad[0, 0]] for phi in bottom.basis])
    return Tables(comps, basis_u.dx * 2.0 * np.pi * r, basis_u.element_dofs, psi, basis_p.element_dofs, facet,
                  bottom.global_coordinates()[0], bottom.dx * 2.0 * np.pi, bottom.element_dofs, basis_u.N,
                  basis_p.N)


def fields(tab: Tables, u: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """F (3, 3, e, q) and the pressure p (e, q) at the quadrature points of the state (u, p)."""
    dF = np.einsum("ie,iaeq->aeq", u[tab.dofs_u], tab.comps)
    return kin.tensor(dF, 1.0), np.einsum("ke,keq->eq", p[tab.dofs_p], tab.psi)


def _vector(local: np.ndarray, dofs: np.ndarray, size: int) -> np.ndarray:
    """The global vector of element vectors ``local`` (e, i) on the element dofs ``dofs`` (i, e)."""
    return np.bincount(dofs.T.ravel(), weights=local.ravel(), minlength=size)


def _matrix(local: np.ndarray, rows: np.ndarray, cols: np.ndarray, shape: tuple[int, int]) -> sp.csr_matrix:
    """The global matrix of element matrices ``local`` (e, i, j), rows on the dofs ``rows`` (i, e) and columns
    on ``cols`` (j, e)."""
    r = np.broadcast_to(rows.T[:, :, None], local.shape).ravel()
    c = np.broadcast_to(cols.T[:, None, :], local.shape).ravel()
    return sp.coo_matrix((local.ravel(), (r, c)), shape=shape).tocsr()


def solid(tab: Tables, law, u: np.ndarray, p: np.ndarray):
    """The rubber's residual (R_u, R_p) and tangent blocks (K_uu, K_pu) at (u, p), the ``forms`` assembled."""
    F, pq = fields(tab, u, p)
    first, second = kin.energy_derivatives(F, law)
    d_j, d2_j = kin.jacobian_derivatives(F)
    stress, table = first + pq * d_j, second + pq * d2_j
    w, c = tab.weight, tab.comps
    r_u = _vector(np.einsum("aeq,iaeq,eq->ei", stress, c, w, optimize=True), tab.dofs_u, tab.n_u)
    r_p = _vector(np.einsum("keq,eq,eq->ek", tab.psi, kin.jacobian(F) - 1.0, w), tab.dofs_p, tab.n_p)
    k_uu = _matrix(np.einsum("iaeq,abeq,jbeq,eq->eij", c, table, c, w, optimize=True), tab.dofs_u, tab.dofs_u,
                   (tab.n_u, tab.n_u))
    k_pu = _matrix(np.einsum("keq,aeq,jaeq,eq->ekj", tab.psi, d_j, c, w, optimize=True), tab.dofs_p, tab.dofs_u,
                   (tab.n_p, tab.n_u))
    return r_u, r_p, k_uu, k_pu


def fluid(tab: Tables, u: np.ndarray):
    """The cavity's volume V (R^3) under the lower surface, V' (N_u,) and V'' (N_u x N_u, CSR) at u."""
    ur, uz, dur = np.einsum("if,iafq->afq", u[tab.facet_dofs], tab.facet)
    rho, drho, w = tab.facet_r + ur, 1.0 + dur, tab.facet_weight
    g = np.array([uz * drho, rho * drho, rho * uz])
    zero = np.zeros_like(rho)
    M = np.array([[zero, drho, uz], [drho, zero, rho], [uz, rho, zero]])
    d = tab.facet
    first = _vector(np.einsum("afq,iafq,fq->fi", g, d, w, optimize=True), tab.facet_dofs, tab.n_u)
    second = _matrix(np.einsum("iafq,abfq,jbfq,fq->fij", d, M, d, w, optimize=True), tab.facet_dofs,
                     tab.facet_dofs, (tab.n_u, tab.n_u))
    return float(np.sum(w * rho * uz * drho)), first, second
