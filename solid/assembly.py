r"""The weak forms (the solid's residual and tangent, the fluid's volume with its derivatives), assembled by
contractions over whole arrays.

Solid (units: stresses of mu_0, lengths of R; the axisymmetric measure dV = 2 pi r dr dz). The
Lagrangian of the mixed displacement-pressure formulation is

    L(u, p) = int [W(Ib1, Ib2) + p (J - 1)] 2 pi r dr dz

(W at the isochoric invariants, ``kinematics``), so that, in the five components of dF,

    R_u[v] = int (dW + p dJ) . dF[v] 2 pi r,                 R_p[q] = int q (J - 1) 2 pi r,
    K_uu[du, v] = int dF[du] . (d^2 W + p d^2 J) . dF[v] 2 pi r,   K_pu[du, q] = int q dJ . dF[du] 2 pi r.

Below (Assembly), this module evaluates the stress dW + p dJ and the 5 x 5 tangent d^2 W + p d^2 J once per
Newton iteration at the quadrature points and assembles these sums by array contractions.

Fluid. The fluid fills the cavity between the deformed lower surface (rho, zeta)(r), rho = r + u_r,
zeta = -t/2 + u_z, and its flat reference plane zeta = -t/2; its volume is

    V(u) = int_0^1 2 pi rho u_z rho' dr       (rho' = d rho / dr = 1 + du_r/dr on the lower surface),

the volume swept by the surface above the plane (rho = 1, u_z = 0 at the clamp, rho = 0 on the axis).
Its variations (symmetric in dv, du, as a second derivative must be):

    V'[v]     = int 2 pi (v_r u_z rho' + rho v_z rho' + rho u_z v_r') dr,
    V''[v, w] = int 2 pi (v_r w_z rho' + v_r u_z w_r' + w_r v_z rho' + rho v_z w_r'
                          + w_r u_z v_r' + rho w_z v_r') dr.

The fluid at pressure p_f does the work p_f dV on the sheet (a follower load: exactly the
derivative of p_f V), so its terms in the equilibrium are -p_f V'[v] and -p_f V''[v, w].

Assembly. Everything that does not change between Newton iterations is tabulated once per model (``tables``):
at each quadrature point x_q of each element e and for each displacement basis function phi_i, the five
components c_ia = dF[phi_i]_a (``kinematics.field_components``), the bilinear pressures psi_k, the weights
w_eq = |e|_q 2 pi r_q of the axisymmetric measure, and, on the lower surface's facets f, the three values
d_i = (phi_i,r, phi_i,z, d phi_i,r / dr) the fluid's forms need, with w_fq = |f|_q 2 pi. A state's fields
at the points are then the contractions of its element dofs U_ei = u[dofs_ie] with these tables:

    dF_a = sum_i U_ei c_ia,   F = I + sum_a dF_a E_a,   p = sum_k P_ek psi_k,
    (u_r, u_z, du_r/dr) on the lower surface = sum_i U_fi d_i.

With the stress s = dW + p dJ and the tangent T = d^2 W + p d^2 J at the points (``kinematics``,
one ``energy_derivatives`` call per Newton iteration gives both), the element vectors and matrices are

    R_u:  sum_q w s_a c_ia,       R_p:  sum_q w psi_k (J - 1),
    K_uu: sum_q w c_ia T_ab c_jb,  K_pu: sum_q w psi_k dJ_a c_ja,

each a batch of small matrix products over the elements (the tables stored element-major, (e, q, 5, 18),
so that ``np.matmul`` runs them: K_e = B_e^T (w T B)_e with B_e the (5 q) x 18 matrix of the c_ia), added
into the global arrays through the element dofs (``np.bincount``, and COO triplets whose duplicates sum).
The fluid's V' and V'' are, with rho = r + u_r, zeta = u_z
and rho' = 1 + du_r/dr,

    V' :  sum_q w g . d_i,          g = (zeta rho', rho rho', rho zeta),
    V'':  sum_q w d_i . M d_j,      M = [[0, rho', zeta], [rho', 0, rho], [zeta, rho, 0]],

the six terms of V''[v, w] being the symmetric bilinear form of M in (v_r, v_z, v_r') and (w_r, w_z, w_r').
Tests compare each with scikit-fem's assembly of the weak form written as a scikit-fem form.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import scipy.sparse as sp
from skfem import Basis, FacetBasis

from . import kinematics as kin

__all__ = ["Tables", "fields", "fluid", "pressure_moments", "solid", "tables"]


@dataclasses.dataclass(frozen=True)
class Tables:
    """A model's basis functions at its quadrature points, element-major (e elements, q points each)."""

    comps: np.ndarray         # (e, q, 5, 18): the components c_ia of dF[phi_i]
    weight: np.ndarray        # (e, q): |e|_q 2 pi r
    dofs_u: np.ndarray        # (18, e)
    psi: np.ndarray           # (e, 4, q): the bilinear pressures
    dofs_p: np.ndarray        # (4, e)
    facet: np.ndarray         # (f, q, 3, 18): (phi_r, phi_z, d phi_r / dr) on the lower surface
    facet_r: np.ndarray       # (f, q): the facets' radii
    facet_weight: np.ndarray  # (f, q): |f|_q 2 pi
    facet_dofs: np.ndarray    # (18, f)
    n_u: int
    n_p: int


def tables(basis_u: Basis, basis_p: Basis, bottom: FacetBasis) -> Tables:
    """The tables of the displacement and pressure bases and of the lower surface's facet basis."""
    r = basis_u.global_coordinates()[0]
    comps = np.array([kin.field_components(phi[0], r) for phi in basis_u.basis])  # (18, 5, e, q)
    psi = np.array([np.asarray(phi[0]) for phi in basis_p.basis])  # (4, e, q)
    facet = np.array([[*np.asarray(phi[0])[:2], phi[0].grad[0, 0]] for phi in bottom.basis])
    return Tables(np.ascontiguousarray(comps.transpose(2, 3, 1, 0)), basis_u.dx * 2.0 * np.pi * r,
                  basis_u.element_dofs, np.ascontiguousarray(psi.transpose(1, 0, 2)), basis_p.element_dofs,
                  np.ascontiguousarray(facet.transpose(2, 3, 1, 0)), bottom.global_coordinates()[0],
                  bottom.dx * 2.0 * np.pi, bottom.element_dofs, basis_u.N, basis_p.N)


def _at_points(table: np.ndarray, dofs: np.ndarray, u: np.ndarray) -> np.ndarray:
    """sum_i U_ei table_e,q,a,i: a field's components (a, e, q) from its element dofs."""
    return np.moveaxis((table @ u[dofs].T[:, None, :, None])[..., 0], -1, 0)


def fields(tab: Tables, u: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """F (3, 3, e, q) and the pressure p (e, q) at the quadrature points of the state (u, p)."""
    return kin.tensor(_at_points(tab.comps, tab.dofs_u, u), 1.0), (p[tab.dofs_p].T[:, None, :] @ tab.psi)[:, 0]


def _vector(local: np.ndarray, dofs: np.ndarray, size: int) -> np.ndarray:
    """The global vector of element vectors ``local`` (e, i) on the element dofs ``dofs`` (i, e)."""
    return np.bincount(dofs.T.ravel(), weights=local.ravel(), minlength=size)


def _matrix(local: np.ndarray, rows: np.ndarray, cols: np.ndarray, shape: tuple[int, int]) -> sp.coo_matrix:
    """The global matrix of element matrices ``local`` (e, i, j), rows on the dofs ``rows`` (i, e) and columns
    on ``cols`` (j, e): COO, its duplicates summed where it is built into the Jacobian (``equations``)."""
    r = np.broadcast_to(rows.T[:, :, None], local.shape).ravel()
    c = np.broadcast_to(cols.T[:, None, :], local.shape).ravel()
    return sp.coo_matrix((local.ravel(), (r, c)), shape=shape)


def pressure_moments(tab: Tables, f: np.ndarray) -> np.ndarray:
    """int psi_k f 2 pi r dr dz for each bilinear pressure psi_k (N_p,) of the point values f (e, q): R_p for
    f = J - 1, the pressures' own volumes for f = 1."""
    return _vector((tab.psi @ (f * tab.weight)[..., None])[..., 0], tab.dofs_p, tab.n_p)


def _forms(B: np.ndarray, w: np.ndarray, vector: np.ndarray, matrix: np.ndarray):
    """The element vectors sum_q w v_a B_ai (e, i) and matrices sum_q w B_ai M_ab B_bj (e, i, j) of the point
    values v (a, e, q) and M (a, b, e, q), B the (e, q, a, i) table."""
    e, q, a, n = B.shape
    flat = B.reshape(e, q * a, n)
    wv = (np.moveaxis(vector, 0, -1) * w[..., None]).reshape(e, 1, q * a)
    wMB = (np.moveaxis(matrix, (0, 1), (-2, -1)) * w[..., None, None]) @ B
    return (wv @ flat)[:, 0], np.swapaxes(flat, 1, 2) @ wMB.reshape(e, q * a, n)


def solid(tab: Tables, law, u: np.ndarray, p: np.ndarray):
    """The rubber's residual (R_u, R_p) and tangent blocks (K_uu, K_pu) at (u, p): the weak forms assembled."""
    F, pq = fields(tab, u, p)
    first, second = kin.energy_derivatives(F, law)
    d_j, d2_j = kin.jacobian_derivatives(F)
    r_e, k_e = _forms(tab.comps, tab.weight, first + pq * d_j, second + pq * d2_j)
    r_u = _vector(r_e, tab.dofs_u, tab.n_u)
    r_p = pressure_moments(tab, kin.jacobian(F) - 1.0)
    k_uu = _matrix(k_e, tab.dofs_u, tab.dofs_u, (tab.n_u, tab.n_u))
    d_jb = (np.moveaxis(d_j, 0, -1)[..., None, :] @ tab.comps)[..., 0, :]  # dJ . dF[phi_j]: (e, q, 18)
    k_pu = _matrix((tab.psi * tab.weight[:, None, :]) @ d_jb, tab.dofs_p, tab.dofs_u, (tab.n_p, tab.n_u))
    return r_u, r_p, k_uu, k_pu


def fluid(tab: Tables, u: np.ndarray):
    """The cavity's volume V (R^3) under the lower surface, V' (N_u,) and V'' (N_u x N_u, COO) at u."""
    ur, uz, dur = _at_points(tab.facet, tab.facet_dofs, u)
    rho, drho, w = tab.facet_r + ur, 1.0 + dur, tab.facet_weight
    zero = np.zeros_like(rho)
    g = np.array([uz * drho, rho * drho, rho * uz])
    M = np.array([[zero, drho, uz], [drho, zero, rho], [uz, rho, zero]])
    first, second = _forms(tab.facet, w, g, M)
    return (float(np.sum(w * rho * uz * drho)), _vector(first, tab.facet_dofs, tab.n_u),
            _matrix(second, tab.facet_dofs, tab.facet_dofs, (tab.n_u, tab.n_u)))
