r"""The indenter's contact rows: the gap of the upper surface's nodes to a flat plate, a sphere or a profile.

An upper-surface node k sits at x_k = (rho_k, z_k), rho_k = r_k + u_r, z_k = t/2 + u_z (units R). The
indenter's lowest point is at the height h; its gap g_k(x_k, h) >= 0 is

    flat plate:  g = h - z                      grad_x g = (0, -1),  d2g/dx2 = 0;
    sphere K:    g = |x - c| - K, c = (0, h + K)  grad_x g = n = (x - c) / d,  d2g/dx2 = (I - n n^T) / d,
    profile f:   g = h + f(rho) - z             grad_x g = (f', -1),  d2g/dx2 = [[f'', 0], [0, 0]],

d = |x - c|, n the sphere's outward normal at the node. The profile's gap is vertical, not the
distance to the surface: its zero set is the surface all the same, and its gradient is normal to it,
so the contact force lambda grad_x g is normal (frictionless) and the active set's test (g < 0 inside
the indenter) is the same; only lambda's scale differs from a distance gap's (by |grad_x g|), which
no reported number depends on. All three depend on h only through z - h (a
vertical translation of the pair), so dg/dh = -dg/dz and d/dh (grad_x g) = -(d2g/dx2) e_z. The contact
row of an active node is c_k = -g_k = 0 (the plate's z_k - h), its multiplier lambda_k >= 0 the force
pushing the node along -grad_x g (into the sheet), entering the Lagrangian as + lambda_k c_k; hence in
the equations (``equations``):

    r_u      += E lambda,                 E = -dg/du        (n x m: the node's (u_r, u_z) columns)
    K_uu     += -sum_k lambda_k d2g_k/du2                  (the curvature: the normal turns with the node)
    dr_u/dh   = sum_k lambda_k (d2g_k/dx2) e_z              (on the node's dofs)
    row c_k:    d/du = E^T,  d/dh = -dg_k/dh.

The force on the indenter is the vertical part of the contact forces, F = sum_k lambda_k (-n_z,k) =
sum_k lambda_k dg_k/dh (the plate's sum lambda_k); under force control its row F - F_given has
dF/dlambda_k = dg_k/dh, dF/du = -sum_k lambda_k e_z^T d2g_k/dx2 and dF/dh = sum_k lambda_k (d2g_k/dx2)_zz.
The flat plate has no curvature terms: its rows are those of a linear constraint, assembled exactly
as before there was a sphere (the same entries, the same sparsity).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import scipy.sparse as sp

from pocket.core.errors import OutOfRangeError
from pocket.core.indenters import PLATE, Indenter, Plate, Sphere

__all__ = ["PLATE_SURFACE", "Rows", "Surface", "cap_area", "force", "gaps", "node_terms", "positions", "rows"]


@dataclasses.dataclass(frozen=True)
class Surface:
    """The surface of ``indenter`` (``pocket.core.indenters``, units R) as the contact rows need it: the flat
    plate, a sphere of radius K = R_s / R (its gap the distance to the sphere) or any other curved indenter (its
    gap vertical, from its own z, z' and z'': a profile)."""

    indenter: Indenter = PLATE

    @property
    def flat(self) -> bool:
        return isinstance(self.indenter, Plate)

    @property
    def word(self) -> str:
        """What messages call the indenter: plate, sphere or indenter."""
        return "plate" if self.flat else "sphere" if isinstance(self.indenter, Sphere) else "indenter"

    @property
    def reach(self) -> float:
        """The largest radius the surface has (a sphere's equator, a profile's last radius; inf: the plate)."""
        return self.indenter.reach

    @property
    def end(self) -> str:
        """Where the surface ends, in words (a sphere's equator, a profile's last radius; "" on the plate)."""
        if self.flat:
            return ""
        return "the sphere's equator" if isinstance(self.indenter, Sphere) else "the end of the indenter's profile"

    @property
    def rim(self) -> float:
        """The surface's height above its lowest point at its reach (a sphere's K; a profile's last height)."""
        return float(self.indenter.height(np.array([float(self.reach)]))[0])

    def area(self, rho_c: float) -> float:
        """The area in contact within the deformed radius rho_c, over pi R^2: rho_c^2 on the plate, the curved
        area int_0^rho_c 2 rho (1 + z'^2)^(1/2) drho on a sphere (``cap_area``) or another curved indenter."""
        if self.flat:
            return rho_c**2
        if isinstance(self.indenter, Sphere):
            return cap_area(self.indenter.radius, rho_c)
        from scipy.integrate import quad

        def band(rho):
            return 2.0 * rho * np.sqrt(1.0 + float(self.indenter.slope(np.asarray(rho))) ** 2)

        return float(quad(band, 0.0, rho_c, epsabs=0.0, epsrel=1e-12, limit=200)[0])

    def local(self, rho: np.ndarray | None, z: np.ndarray, h: float):
        """At nodes (rho, z) (m,) with the lowest point at h: the gap g (m,), grad_x g (m, 2) and d2g/dx2
        (m, 2, 2) (None on the flat plate)."""
        if self.flat:
            grad = np.zeros((z.size, 2))
            grad[:, 1] = -1.0
            return h - z, grad, None
        assert rho is not None  # a curved indenter's gap needs the radii (``_nodes``)
        if not isinstance(self.indenter, Sphere):
            grad = np.stack([self.indenter.slope(rho), -np.ones_like(z)], axis=1)
            hess = np.zeros((z.size, 2, 2))
            hess[:, 0, 0] = self.indenter.second(rho)
            return h + self.indenter.height(rho) - z, grad, hess
        k = self.indenter.radius
        d_rho, d_z = rho, z - (h + k)
        d = np.hypot(d_rho, d_z)
        n = np.stack([d_rho / d, d_z / d], axis=1)
        hess = (np.eye(2)[None] - n[:, :, None] * n[:, None, :]) / d[:, None, None]
        return d - k, n, hess


#: the flat plate
PLATE_SURFACE = Surface()


def cap_area(radius: float, rho_c: float) -> float:
    """The curved area (over pi R^2) of a sphere of radius K = ``radius`` below the circle of radius rho_c:
    2 K z(rho_c), z = K - sqrt(K^2 - rho_c^2) the cap's height (Archimedes), as the membrane solvers report
    it; written 2 K rho_c^2 / (K + sqrt(K^2 - rho_c^2)) to keep its digits when rho_c << K."""
    return 2.0 * radius * rho_c**2 / (radius + np.sqrt(radius**2 - rho_c**2))


def positions(model, y: np.ndarray, nodes) -> tuple[np.ndarray, np.ndarray]:
    """(rho, z) (R) of the upper-surface nodes ``nodes`` (indices of ``model.top_z``) of the state y."""
    return model.top_r[nodes] + y[model.top_radial[nodes]], 0.5 * model.thickness + y[model.top_z[nodes]]


def _nodes(model, surface: Surface, y: np.ndarray, nodes):
    """(rho, z) of the upper-surface nodes ``nodes`` of the state y (rho None on the flat plate, which needs
    none)."""
    z = 0.5 * model.thickness + y[model.top_z[nodes]]
    return (None if surface.flat else model.top_r[nodes] + y[model.top_radial[nodes]]), z


def _lambda(model, y: np.ndarray, active) -> np.ndarray:
    """The indenter's contact forces lambda (m,) of the state y (after its height; the clamp's jaw's, if any,
    follow them: ``jaw``)."""
    return y[model.size + 2:model.size + 2 + len(active)]


def gaps(model, surface: Surface, y: np.ndarray, nodes=slice(None)) -> np.ndarray:
    """The gaps g (R) of the upper-surface nodes ``nodes`` (default all) to the indenter of the state y, its
    lowest point at y[size + 1]. Past the surface's reach (a sphere's equator, a profile's last radius) the
    gap is to the plane of its rim, z = h + z(reach): a node there that rises above it joins the active set,
    whose rows then say the contact left the indenter's surface (``rows``)."""
    rho, z = _nodes(model, surface, y, nodes)
    h = float(y[model.size + 1])
    g = surface.local(rho, z, h)[0]
    if not surface.flat:
        past = rho >= surface.reach
        g[past] = h + surface.rim - z[past]
    return g


def force(model, surface: Surface, y: np.ndarray, active: np.ndarray) -> float:
    """The indenter's force sum_k lambda_k dg_k/dh (mu_0 R^2) of the state y in contact on ``active``."""
    rho, z = _nodes(model, surface, y, active)
    return float(np.sum(_lambda(model, y, active) * -surface.local(rho, z, float(y[model.size + 1]))[1][:, 1]))


@dataclasses.dataclass(frozen=True)
class Rows:
    """The contact's terms at a state (module docstring): ``residual`` c = -g (m,), ``E`` = -dg/du (n x m,
    CSC), ``dgdh`` (m,); ``force`` F; and the curvature terms (None on the flat plate): ``k_uu`` (n x n),
    ``k_uh`` = dr_u/dh (n x 1), ``f_u`` = dF/du (1 x n), ``f_h`` = dF/dh."""

    residual: np.ndarray
    E: sp.csc_matrix
    dgdh: np.ndarray
    force: float
    k_uu: sp.csc_matrix | None
    k_uh: sp.csc_matrix | None
    f_u: sp.csr_matrix | None
    f_h: float


def rows(model, surface: Surface, y: np.ndarray, active: np.ndarray) -> Rows:
    """The contact's ``Rows`` of the state y on the upper-surface nodes ``active``."""
    n, m = model.basis_u.N, len(active)
    lam = _lambda(model, y, active)
    rho, z = _nodes(model, surface, y, active)
    if not surface.flat and np.any(rho >= surface.reach):
        raise OutOfRangeError(f"the sheet would wrap past {surface.end} (a node in contact at rho = {rho.max():.6g} "
                              f"R, the indenter's surface ends at {surface.reach:.6g} R)")
    g, grad, hess = surface.local(rho, z, float(y[model.size + 1]))
    dgdh = -grad[:, 1]
    if hess is None:
        E = sp.csc_matrix((-grad[:, 1], (model.top_z[active], np.arange(m))), shape=(n, m))
        return Rows(-g, E, dgdh, float(np.sum(lam * dgdh)), None, None, None, 0.0)
    E, k_uu = node_terms(model, active, lam, grad, hess)
    dofs = np.stack([model.top_radial[active], model.top_z[active]], axis=1)  # (m, 2)
    weighted = lam[:, None, None] * hess
    k_uh = sp.csc_matrix((weighted[:, :, 1].ravel(), (dofs.ravel(), np.zeros(2 * m, int))), shape=(n, 1))
    f_u = sp.csr_matrix((-weighted[:, 1, :].ravel(), (np.zeros(2 * m, int), dofs.ravel())), shape=(1, n))
    return Rows(-g, E, dgdh, float(np.sum(lam * dgdh)), k_uu, k_uh, f_u, float(weighted[:, 1, 1].sum()))


def node_terms(model, nodes, lam: np.ndarray, grad: np.ndarray, hess: np.ndarray):
    """The terms of the gaps of the upper-surface nodes ``nodes`` (m,) in the displacement, with their forces
    ``lam`` (m,), gradients ``grad`` (m, 2) and Hessians ``hess`` (m, 2, 2) in x = (rho, z): E = -dg/du
    (n x m, CSC) and the curvature -sum_k lam_k d2g_k/du2 (n x n, CSC) (module docstring; the indenter's and
    the clamp's jaw's, ``jaw``)."""
    n, m = model.basis_u.N, len(nodes)
    dofs = np.stack([model.top_radial[nodes], model.top_z[nodes]], axis=1)  # (m, 2)
    E = sp.csc_matrix((-grad.ravel(), (dofs.ravel(), np.repeat(np.arange(m), 2))), shape=(n, m))
    weighted = lam[:, None, None] * hess
    k_uu = sp.csc_matrix((-weighted.ravel(), (np.repeat(dofs, 2, axis=1).ravel(), np.tile(dofs, 2).ravel())),
                         shape=(n, n))
    return E, k_uu
