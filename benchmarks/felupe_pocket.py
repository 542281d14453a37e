r"""The headline pocket as an axisymmetric solid in FElupe: an independent peer of the membrane solvers.

A benchmark helper, never a dependency of ``pocket`` (FElupe is installed by hand:
``pip install felupe tensortrax``). Nothing runs at import; ``bench_felupe.py`` calls it.

The model
---------
Units: lengths / R, stresses / mu_0 (E = 3 mu_0), so T/R = ``thickness`` = t and the fluid pressure
P = Phat E T / R = 3 t Phat. The sheet's cross-section r in [0, 1] by z in [-t/2, t/2]: the flat
sheet's mid-plane is z = 0, the membrane's clamp plane, so heights are comparable with the membrane's.
FElupe's axisymmetric fields take the first coordinate as the axis and the second as the radius, so
the mesh points are (z, r).

- Elements: biquadratic quads (``BiQuadraticQuad``, 9 nodes) for the displacement; FElupe's mixed
  u-p-J formulation (``FieldsMixed`` + ``NearlyIncompressible``: a linear pressure p and volume ratio
  Jbar per element, discontinuous) with the bulk modulus ``bulk`` mu_0 on U = K (Jbar - 1)^2 / 2;
  the rubber's deviatoric energy is Mooney-Rivlin W = C1 (I1h - 3) + C2 (I2h - 3) on the isochoric
  invariants (FElupe's ``mooney_rivlin`` through tensortrax), with mu_0 = 2 (C1 + C2) = 1, C2 = alpha C1.
  The bulk modulus only sets how near J is to 1: p / K ~ 1e-2 / 1e4 here, far below the mesh error.
- Mesh: ``layers`` equal layers through the thickness; ``elements`` along the radius with the nodes
  r_i = 1 - (1 - i/n)^q, q = ``grading``, finer towards the clamp, where the sheet bends over a
  boundary layer a few thicknesses wide.
- Boundaries: u_r = 0 on the axis r = 0; u = 0 on the clamp r = 1 through the thickness; the fluid
  pressure on the lower face z = -t/2 as a follower load (``SolidBodyPressure``: P per deformed area).
- Inflation: pressure control, Newton (FElupe's ``newtonraphson``) along a geometric ramp of pressures
  from 1e-4 P (the flat sheet's first response is bending, stiff and nearly linear; the membrane's
  deflection grows like P^(1/3)).

What a state reports (heights from the flat mid-plane z = 0, the clamp plane):
``height`` the upper surface's pole height, ``height_mid`` the mid-surface's; ``volume`` the cavity's
under the deformed lower surface, measured from the flat sheet's lower face z = -t/2 (the plane the
fluid filled before inflation):

    V = int_0^1 2 pi rho w (d rho / d r) dr,

rho(r) the lower surface's deformed radius, w(r) its axial displacement, along the surface's
quadratic edges by 3-point Gauss (exact: the integrand is a polynomial of degree 5 on an edge).
``volume_mid`` is the same integral along the mid-surface (w its height above z = 0): the membrane's
volume, under its mid-surface; the two are equal up to the discrete incompressibility (the sheet
between them keeps its volume).

Compression at fixed fluid volume by a rigid flat plate
-------------------------------------------------------
FElupe has no cavity (a pressure that is the multiplier of a volume), so the pressure is found by an
outer secant iteration: at a plate height h, the pressure P is the root of V(P; h) = V_I (the liquid
keeps its volume), each V(P; h) a FElupe Newton solve from the last converged state. The plate is
FElupe's ``ContactRigidPlane`` (frictionless, node to plane, a penalty lambda_n = ``penalty`` per node;
its nodal force over lambda_n is the penetration, ~ 1e-4 / 1e3 = 1e-7 R here, below the solver's
tolerances) on the upper surface's nodes, pressed down under displacement control of its centre
point; the plate's force is the sum of the nodal contact forces (FElupe's axisymmetric nodal forces are
the ring's total, 2 pi r times the force per radian). A force F is reached by a secant iteration on
h. Reported: Fhat = F / (P_I pi R^2), P/P_I, H/H0 (the plate's height over the inflated upper
pole's) and the contact area (``contact_area``: from the contact edge, on the mesh as built; FElupe's mesh does
not follow the edge as ``pocket.solid``'s does).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

#: the headline pocket: the paper's sample 1 (Mooney-Rivlin alpha = C2/C1 = 47/160, Phat_I = 0.31), T/R
ALPHA, PHAT, THICKNESS = 47 / 160, 0.31, 0.0125
#: 3-point Gauss-Legendre on [-1, 1]
_GAUSS_S = np.array([-np.sqrt(0.6), 0.0, np.sqrt(0.6)])
_GAUSS_W = np.array([5.0, 8.0, 5.0]) / 9.0


@dataclass
class Pocket:
    """A FElupe model of the sheet and its state (the field's values change as it is solved)."""

    thickness: float
    elements: int
    layers: int
    points: np.ndarray  # (n, 2) reference (z, r)
    field: object  # felupe FieldContainer (u, p, Jbar)
    solid: object
    pressure: object  # SolidBodyPressure on the lower face
    boundaries: dict
    lower: np.ndarray  # lower-face node indices, by r
    mid: np.ndarray  # mid-plane node indices, by r
    upper: np.ndarray  # upper-face node indices
    centre: int  # the plate's centre point (not in any cell)
    iterations: int = 0
    log: dict = field(default_factory=dict)


def radial_nodes(elements: int, grading: float) -> np.ndarray:
    """Radial element boundaries (elements + 1,), 0 to 1, finer towards the clamp r = 1."""
    return 1.0 - (1.0 - np.linspace(0.0, 1.0, elements + 1)) ** grading


def build(alpha=ALPHA, thickness=THICKNESS, elements=64, layers=4, grading=2.0, bulk=1e4, corner=None):
    """The flat, unloaded sheet as a FElupe model: Mooney-Rivlin alpha = C2/C1 (mu_0 = 1), T/R = thickness.

    ``corner`` None: the mesh of the module docstring; a length in thicknesses: ``pocket.solid``'s section
    instead (its radial nodes, graded by its own exponent with the clamp's corner elements ``corner`` T long, and
    its layers graded towards both surfaces; ``grading`` unused), the same mesh as the solid's before its
    cluster follows the contact edge."""
    import felupe as fem
    import felupe.constitution.tensortrax as tt

    t = thickness
    if corner is None:
        z, r = 0.5 * t * np.linspace(-1.0, 1.0, layers + 1), radial_nodes(elements, grading)
    else:
        from pocket.solid import mesh as solid_mesh

        z = solid_mesh.heights(t, layers)
        r = solid_mesh.corner_nodes(solid_mesh.radial_nodes(elements), corner * t)
    mesh = fem.mesh.convert(fem.Grid(z, r), order=2, calc_midfaces=True)
    mesh.update(points=np.vstack([mesh.points, [[t, 0.0]]]))  # the plate's centre point, above the pole
    centre = mesh.npoints - 1
    x = mesh.points
    c1 = 1.0 / (2.0 * (1.0 + alpha))
    region = fem.RegionBiQuadraticQuad(mesh)
    fields = fem.FieldsMixed(region, n=3, axisymmetric=True)
    rubber = tt.Hyperelastic(tt.models.hyperelastic.mooney_rivlin, C10=c1, C01=alpha * c1)
    solid = fem.SolidBody(fem.NearlyIncompressible(rubber, bulk=bulk), fields)
    in_cells = np.zeros(mesh.npoints, bool)
    in_cells[mesh.cells.ravel()] = True
    wet = fem.RegionBiQuadraticQuadBoundary(mesh, mask=np.isclose(x[:, 0], -0.5 * t), ensure_3d=True)
    pressure = fem.SolidBodyPressure(fem.FieldContainer([fem.FieldAxisymmetric(wet, dim=2)]))
    u = fields[0]
    boundaries = {"axis": fem.Boundary(u, fy=0.0, skip=(1, 0)), "clamp": fem.Boundary(u, fy=1.0),
                  "plate": fem.Boundary(u, mask=np.arange(mesh.npoints) == centre)}

    def line(z):
        idx = np.flatnonzero(np.isclose(x[:, 0], z) & in_cells)
        return idx[np.argsort(x[idx, 1])]

    return Pocket(t, elements, layers, x, fields, solid, pressure, boundaries, line(-0.5 * t), line(0.0),
                  line(0.5 * t), centre)


def _line_volume(rho: np.ndarray, w: np.ndarray) -> float:
    """int 2 pi rho w d rho along a line of quadratic edges (nodes (2k+1,), by r; 3-point Gauss, exact)."""
    s = _GAUSS_S[:, None]
    n = np.stack([0.5 * s * (s - 1.0), 1.0 - s * s, 0.5 * s * (s + 1.0)])  # (3 nodes, 3 points, 1)
    dn = np.stack([s - 0.5, -2.0 * s, s + 0.5])
    edges = np.stack([rho[0:-1:2], rho[1::2], rho[2::2]])[:, None, :]  # (3 nodes, 1, edges)
    wedges = np.stack([w[0:-1:2], w[1::2], w[2::2]])[:, None, :]
    rq, wq, drq = (n * edges).sum(0), (n * wedges).sum(0), (dn * edges).sum(0)
    return float(2.0 * np.pi * np.sum(_GAUSS_W[:, None] * rq * wq * drq))


def measure(m: Pocket) -> dict:
    """The state's heights (from the flat mid-plane) and volumes (see the module docstring)."""
    u = m.field[0].values
    x = m.points + u
    low, mid = m.lower, m.mid
    return {"height": float(x[m.upper[0], 0]), "height_mid": float(x[mid[0], 0]),
            "volume": _line_volume(x[low, 1], u[low, 0]), "volume_mid": _line_volume(x[mid, 1], x[mid, 0])}


def contact_area(m: Pocket, plate: float) -> float:
    """The contact area under the plate, from the contact edge on the mesh as built.

    The edge's deformed radius rho_c is placed as ``pocket.solid``'s on its mesh as asked: g^(1/2) linear in rho
    beyond the edge, g the upper surface nodes' gaps to the plate, extrapolated from the two nodes beyond the last
    one that touches (g <= 0: the penalty's penetration), kept between the touching node before it and the first
    free node.

    Parameters
    ----------
    m : Pocket
        The model, in its state under the plate.
    plate : float
        The plate's height / R.

    Returns
    -------
    float
        rho_c^2: the contact area over pi R^2.
    """
    x = m.points[m.upper] + m.field[0].values[m.upper]
    rho, gap = x[:, 1], plate - x[:, 0]
    last = int(np.flatnonzero(gap <= 0.0)[-1])
    (r1, r2), (g1, g2) = rho[last + 1:last + 3], np.sqrt(gap[last + 1:last + 3])
    rho_c = np.clip(r1 - g1 * (r2 - r1) / (g2 - g1), rho[max(last - 1, 0)], r1)
    return float(rho_c**2)


def _solve(m: Pocket, items, tol):
    import felupe as fem

    dof0, dof1 = fem.dof.partition(m.field, m.boundaries)
    ext0 = fem.dof.apply(m.field, m.boundaries, dof0)
    res = fem.newtonraphson(items=items, x0=m.field, dof1=dof1, dof0=dof0, ext0=ext0, tol=tol, verbose=0,
                            maxiter=40)
    m.iterations += res.iterations
    return res


def inflate(m: Pocket, phat=PHAT, steps=21, tol=1e-9) -> dict:
    """Inflate the flat sheet ``m`` to Phat = ``phat`` (pressure control, ``steps`` geometric steps from
    1e-4 of it); the state's measures, with its pressure, Newton iterations and wall time (s)."""
    tic = time.perf_counter()
    p = 3.0 * m.thickness * phat
    for pk in p * np.geomspace(1e-4, 1.0, steps):
        m.pressure.update(pk)
        _solve(m, [m.solid, m.pressure], tol)
    return {"pressure": phat, **measure(m), "iterations": m.iterations, "seconds": time.perf_counter() - tic}


def _secant(fun, x0, x1, tol, maxiter=30):
    """A root of fun by the secant method from x0, x1 (fun(x0) first); the last fun value with it."""
    f0 = fun(x0)
    for _ in range(maxiter):
        f1 = fun(x1)
        if abs(f1) < tol:
            return x1, f1
        x0, x1, f0 = x1, x1 - f1 * (x1 - x0) / (f1 - f0), f1
    raise RuntimeError(f"secant iteration did not converge: residual {f1:.3g}")


def compress(m: Pocket, inflated: dict, forces, penalty=1e3, tol=1e-9) -> list[dict]:
    """Press the inflated ``m`` (its state ``inflated`` from ``inflate``) by a rigid flat plate at fixed
    liquid volume to each Fhat in ``forces`` (increasing); per force P/P_I, H/H0, the contact force and the
    state's measures. The fluid pressure is the root of V(P; h) = V_I and the plate's height h the root
    of F(h) = F, both by secant iterations (see the module docstring)."""
    import felupe as fem

    p_i = 3.0 * m.thickness * inflated["pressure"]
    h0, v_i = inflated["height"], inflated["volume"]
    u = m.field[0]
    mask = np.arange(m.points.shape[0]) == m.centre
    u.values[m.centre] = [h0 - m.thickness, 0.0]  # the plate, free of the sheet so far, put on its top
    m.boundaries["plate"] = fem.Boundary(u, mask=mask, skip=(0, 1), value=h0 - m.thickness)
    m.boundaries["plate_r"] = fem.Boundary(u, mask=mask, skip=(1, 0))
    contact = fem.ContactRigidPlane(m.field, points=m.upper, centerpoint=m.centre, normal=np.array([-1.0, 0.0]),
                                    multiplier=penalty)
    items = [m.solid, m.pressure, contact]
    state = {"p": p_i, "dvdp": None}

    def volume_error(p):
        m.pressure.update(p)
        _solve(m, items, tol)
        return measure(m)["volume"] - v_i

    def force_at(h):
        """Fhat with the plate at h and the pressure that keeps the volume."""
        m.boundaries["plate"].value = h - m.thickness
        m.boundaries["plate"].update(h - m.thickness)
        p0 = state["p"]
        p1 = p0 * (1.0 + 1e-3)
        state["p"], _ = _secant(volume_error, p0, p1, 1e-10 * v_i)
        reaction = contact.assemble.vector(m.field).toarray().ravel()[2 * m.centre]
        return abs(reaction) / (np.pi * p_i)

    tic = time.perf_counter()
    out, h, h_prev = [], h0, h0
    for target in forces:
        # march down until the force passes the target, then the secant on h
        while True:
            step = min(0.01, 2.0 * (h_prev - h)) if h_prev > h else 1e-5
            h_try = h - step
            h_prev, h = h, h_try
            if force_at(h_try) >= target:
                break
        h, _ = _secant(lambda hh, f=target: force_at(hh) - f, h_prev, h, 1e-8)
        s = measure(m)
        out.append({"force": target, "pressure_ratio": state["p"] / p_i, "height_ratio": h / h0, "plate": h,
                    "contact_area": contact_area(m, h), **s, "seconds": time.perf_counter() - tic,
                    "iterations": m.iterations})
        h_prev = h
    return out
