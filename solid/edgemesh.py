r"""A mesh that follows the contact edge: the radial nodes clustered about it, the state carried over.

Why. The contact acts on the upper surface's nodes, so the discrete contact edge lies between the last
node of the active set and the next; ``results.contact_radius`` places it between them by extrapolating
the gaps of the free nodes beyond. Near the edge the solution is singular (within a distance ~T of it the
sheet is locally a half-space pressed by a flat punch's rounded edge: the contact pressure vanishes as
(r_c - r)^(1/2), the gap grows as (r - r_c)^(3/2), Hertz), so a Q2 element of length h that holds the edge
carries a local error of the gap comparable to the gap itself one node beyond: the extrapolated edge is
off by C h, a fraction of the element (first order in h), whatever the extrapolation's exponent. On the
default mesh that element is ~0.02 R long: sample 4's pocket (T/R = 0.08) at Fhat = 0.08 had its
contact area 7 % off.

What. Between solves the radial nodes move (the layers' heights stay) so that a cluster of elements
``size`` long sits about the edge estimate r_e: the element length wanted at r is

    h(r) = min(h_0(r), h_e(|r - r_e|)),   h_e(d) = size + (GROWTH - 1) max(d - CORE size, 0),

h_0 the base mesh's (``mesh.section``: graded towards the clamp, its corner elements), h_e flat over
CORE elements either side of r_e, then growing by about GROWTH per element until it meets h_0 (an
element of length h at distance d is followed by one of h + (GROWTH - 1) h). The nodes between the base
nodes a < r_e < b where h_e first exceeds 1.5 h_0 are placed at equal steps of phi(r) = int dr / h(r)
on [a, r_e] and on [r_e, b], each with a whole number of elements (so r_e is a vertex node; each side's
elements are scaled by round(phi) / phi, within a few percent of h); the base nodes outside [a, b]
stay, the clamp's three corner elements always. The mesh gains the cluster's elements (~2 CORE + 2
log(h_0 / size) / log(GROWTH): about 10 on the default mesh); its topology is a tensor product as
before, so every line of nodes at a fixed height is carried over by itself. size = ``SIZE`` T, at least
``MIN_SIZE`` (the edge is wanted to ~1e-3 R, which a thin sheet's T/32 overshoots at a cost) and at most
T/4 (the two nodes beyond the edge then lie within the half-space's zone, where the gap grows as
(r - r_c)^(3/2): ``results.edge_radius`` extrapolates them with that exponent).

The transfer. Each element is a rectangle, its map affine, so a Q2 field restricted to a line of its
nodes at one height (the vertex lines and the mid-layer lines alike) is the quadratic through the line's
three nodes of the element (two vertices, the midpoint) in r, and a Q1 field on a vertex line is linear in
r. The state is carried to the new nodes by evaluating these: Lagrange's quadratic through each old
element's three nodes for u (exact on every field the old elements hold: any piecewise quadratic in r on
the old elements, so any global quadratic; of order 3 in the old element's length on a smooth field),
linear interpolation for p (exact on Q1's fields, order 2). The contact forces are nodal forces: each is
divided by its node's share of the contact area (the consistent weights of a Q2 line, h/6, 4h/6, h/6
of an element, times 2 pi r), the density interpolated linearly to the new upper surface's nodes inside
the edge estimate (the new active set), and multiplied back by their shares (exact on a uniform
density). The fluid's pressure and the plate's height carry over as they are. The new nodes up to the old
active set's last one are marked as known to touch (``Control.known``: at the same load to the old mesh's
error, at a larger load the contact only spreads), which bounds the active set's search from below. Newton then
solves the load from there (``newton.contact``, the active set updated as ever): on the plate the Jacobian
does not depend on the multipliers, so the first Newton step sets them; the transfer's error in u is the
old mesh's interpolation error, so Newton starts within the old discretisation error of the new state.

When the mesh moves (``follow``, after each load is solved; ``ahead``, before the next load of a
curve). The first state in contact is solved on the base mesh; its edge, extrapolated there with
exponent 2, is off by a fraction of a base element (~0.02 R), which the cluster's core (CORE elements
of ``size`` either side) holds; the state is carried to the cluster about it and solved again. The mesh
moves again only while the edge estimate lies farther than ``STOP`` CORE elements (one) from the core's
centre. Within the core the estimate's error depends on where the edge lies only at the cluster's own
scale (``size`` times C(theta), theta the edge's offset from the core's centre in elements: the local
problem is self-similar below the scale T, the same discrete half-space edge, scaled), so moving again
would only trade one C(theta) size for another. Hence the estimate converges as the cluster's size:
first order in ``size``, with a small constant (the discrete edge's local error, a fraction of an
element, whatever the base mesh), as long as the rest of the mesh resolves the sheet (its own error in
the edge is the global solution's, of higher order). Along a curve (``ahead``) the cluster is moved
before each next load to where the edge is predicted to be, the state carried there unsolved (the march
to the load solves it): A_c ~ Fhat / (P/P_I) (the flat plate's F = P A_c of the membrane), so rho_c^2
scales by (F' / F)(P / P'), P' extrapolated from the last two states (the first contact's, no force at
P_I, the first of them), and r_c is read off the state's upper surface at that rho_c. The state arrives with
the nodes inside that predicted edge active: on the headline curve the prediction is within a node or two of
the solved edge, so the search takes one or two sets where, from the old edge's set, it took five to seven (the
10-force curve: 81 Newton iterations instead of 127). A prediction within the core spares the move after the
solve: on the headline curve none is moved after its solve but the first.

Measured (``tests/test_solid_edgemesh.py``). Sample 4's pocket (alpha = 47/160, Phat_I = 0.0503, T/R =
0.08, a liquid, the plate) at Fhat = 0.08, 0.16 and 0.32: the default mesh's contact area within +0.15 %,
-0.08 % and +0.12 % of the mesh of 256 elements by 8 layers, its contact radius within 2.3e-4 R (on the
mesh as asked: -6.5 %, -4.4 % and -0.7 %); on clusters of T/8, T/16 and T/32 at Fhat = 0.16 the contact
radius moves by 6.0e-4 R, then 2.6e-4 R (order 1.2); at T/R = 0.1, Fhat = 0.2, the default mesh's
contact radius within 4.5e-4 R of 128 x 8 under the plate and 2.1e-4 R under a sphere of K = 0.5 R. The
headline pocket's P/P_I (T/R = 0.0125, 10 forces) moves by 2.5e-7 from 64 to 256 elements (3.4e-5 on
the mesh as asked: its error along the radius was the edge's), for 137 Newton iterations instead of 110
and 71 elements instead of 61.

The estimate's own error: the spread of two estimates of the same edge from the same state, the gaps
beyond the active set extrapolated with the membrane's exponent 2 and with the half-space's 3/2, which
bracket the gap's local growth (``results``), reported as ``extra["contact_radius_error"]`` (R).
"""

from __future__ import annotations

import dataclasses

import numpy as np
from skfem import MeshQuad

from pocket.core.errors import ConvergenceError

from .equations import Control
from .jaw import Jaw, candidates
from .model import Model, discretize
from .newton import contact
from .rangeend import margins
from .results import edge_radius

__all__ = ["CORE", "GROWTH", "MIN_SIZE", "SIZE", "STOP", "ahead", "clustered", "follow", "quadratic", "transfer"]

#: the cluster's element length at the edge, in thicknesses
SIZE = 1.0 / 32.0
#: the cluster's shortest element length (R): the edge is wanted to ~1e-3 R however thin the sheet
MIN_SIZE = 2e-3
#: the cluster's flat core: elements of ``SIZE`` either side of the edge estimate
CORE = 4
#: the cluster's growth of the elements' lengths away from its core
GROWTH = 2.0
#: the mesh moves again while the edge estimate lies farther from the cluster's centre than this fraction of
#: the core's half-width (CORE elements): one element
STOP = 0.25
#: the clamp's corner elements (``mesh.corner_nodes``), whose nodes the cluster leaves where they are
CLAMP_NODES = 3
#: most moves of the mesh at one load
MAX_MOVES = 6


def _radial(model: Model) -> np.ndarray:
    """The radial nodes (vertices) of the model's tensor-product mesh, sorted."""
    return np.unique(model.mesh.p[0])


def _heights(model: Model) -> np.ndarray:
    return np.unique(model.mesh.p[1])


def clustered(base: np.ndarray, edge: float, size: float) -> np.ndarray:
    """The radial nodes ``base`` (sorted, from 0 to 1) with a cluster of elements ``size`` long about r =
    ``edge`` (module docstring): ``edge`` a node, the base nodes outside the cluster kept."""
    last = base.size - 1 - CLAMP_NODES
    if not 0.0 < edge < base[last]:  # an edge at the axis or among the clamp's corner elements: no cluster
        return base
    h_base = np.diff(base)
    mids = 0.5 * (base[1:] + base[:-1])

    def wanted(r):
        d = np.abs(r - edge)
        near = size + (GROWTH - 1.0) * np.maximum(d - CORE * size, 0.0)
        return np.minimum(np.interp(r, mids, h_base), near)

    def reach(side):  # the base node where the cluster's length first exceeds the base's, on that side
        order = np.flatnonzero(base < edge)[::-1] if side < 0 else np.flatnonzero(base > edge)
        for k in order:
            if size + (GROWTH - 1.0) * max(abs(base[k] - edge) - CORE * size, 0.0) >= 1.5 * wanted(base[k]):
                return k
        return order[-1] if order.size else None

    a, b = reach(-1), reach(1)
    a = 0 if a is None else a
    b = last if b is None else min(b, last)
    pieces = [base[:a]]
    for lo, hi in ((base[a], edge), (edge, base[b])):
        grid = np.linspace(lo, hi, 2001)
        dens = 1.0 / wanted(grid)
        phi = np.concatenate([[0.0], np.cumsum(0.5 * (dens[1:] + dens[:-1]) * np.diff(grid))])
        count = max(1, round(phi[-1]))
        pieces.append(np.interp(np.linspace(0.0, phi[-1], count + 1)[:-1], phi, grid))
    pieces.append(base[b:])
    return np.concatenate(pieces)


def _lines(model: Model, component: int):
    """The displacement dofs of one component by lines of constant height: a list of (radii sorted, dofs)."""
    dofs = model.basis_u.split_indices()[component]
    loc = model.basis_u.doflocs[:, dofs]
    out = []
    for z in np.unique(np.round(loc[1], 12)):
        on = dofs[np.isclose(loc[1], z, rtol=0.0, atol=1e-12)]
        r = model.basis_u.doflocs[0, on]
        order = np.argsort(r)
        out.append((z, r[order], on[order]))
    return out


def quadratic(r: np.ndarray, f: np.ndarray, x: np.ndarray) -> np.ndarray:
    """The piecewise quadratic through the nodes r (2 n + 1, sorted: vertices and midpoints of n elements) with
    values f at the points x: Lagrange's quadratic through each element's three nodes."""
    k = 2 * np.clip(np.searchsorted(r[::2], x, side="right") - 1, 0, (r.size - 1) // 2 - 1)
    r0, r1, r2 = r[k], r[k + 1], r[k + 2]
    return (f[k] * (x - r1) * (x - r2) / ((r0 - r1) * (r0 - r2)) + f[k + 1] * (x - r0) * (x - r2) / ((r1 - r0) *
            (r1 - r2)) + f[k + 2] * (x - r0) * (x - r1) / ((r2 - r0) * (r2 - r1)))


def _weights(r: np.ndarray) -> np.ndarray:
    """Each node's share int phi_k 2 pi r dr of a Q2 line through the nodes r (vertices and midpoints): h/6,
    4h/6, h/6 of each element times 2 pi r at the node (the contact forces' densities, ``transfer``)."""
    w = np.zeros(r.size)
    h = r[2::2] - r[:-2:2]
    w[:-2:2] += h / 6.0
    w[1::2] += 4.0 * h / 6.0
    w[2::2] += h / 6.0
    return w * 2.0 * np.pi * np.maximum(r, 0.25 * h.min())


def transfer(old: Model, new: Model, y: np.ndarray, control: Control, edge: float) -> tuple[np.ndarray, Control]:
    """The state y of ``control`` on ``old`` carried to ``new`` (the same heights, the radial nodes moved):
    u by each line's piecewise quadratic, p linearly, the contact forces by their densities (module
    docstring); the active set the new upper-surface nodes within r = ``edge`` (R, the contact edge's
    estimate; the pole's node at least), those up to the old set's last node known to touch (``Control.known``)."""
    out = np.zeros(new.size + y.size - old.size)
    for component in (0, 1):
        for (z, r, dofs), (_, r_new, dofs_new) in zip(_lines(old, component), _lines(new, component), strict=True):
            out[dofs_new] = quadratic(r, y[dofs], r_new)
    n, n_new = old.basis_u.N, new.basis_u.N
    loc, loc_new = old.basis_p.doflocs, new.basis_p.doflocs
    for z in np.unique(np.round(loc[1], 12)):
        on = np.flatnonzero(np.isclose(loc[1], z, rtol=0.0, atol=1e-12))
        on_new = np.flatnonzero(np.isclose(loc_new[1], z, rtol=0.0, atol=1e-12))
        order = np.argsort(loc[0, on])
        out[n_new + on_new] = np.interp(loc_new[0, on_new], loc[0, on[order]], y[n + on[order]])
    out = out[:new.size]
    active = np.asarray(control.active)
    new_active = np.flatnonzero(new.top_r <= edge + 1e-12)
    known = int(np.count_nonzero(new.top_r <= old.top_r[active.max()] + 1e-12))
    density = y[old.size + 2:old.size + 2 + active.size] / _weights(old.top_r)[active]
    lam = np.interp(new.top_r[new_active], old.top_r[active], density) * _weights(new.top_r)[new_active]
    out = np.concatenate([out, y[old.size:old.size + 2], lam])
    if control.jaw is None:
        return out, dataclasses.replace(control, active=new_active, known=known)
    mu, clamp = _jaw_carried(old, new, y[old.size + 2 + active.size:], control.jaw)
    return np.concatenate([out, mu]), dataclasses.replace(control, active=new_active, jaw=clamp, known=known)


def _jaw_carried(old: Model, new: Model, mu: np.ndarray, clamp: Jaw) -> tuple[np.ndarray, Jaw]:
    """The clamp's upper jaw's multipliers ``mu`` (one per candidate of ``old``, ``jaw.candidates``) and its
    active set carried to the candidates of ``new``: a node at the same radius keeps its own (the jaw touches
    the sheet at its corner, whose nodes the cluster leaves where they are), any other is inactive, mu = 0."""
    before, after = old.top_r[candidates(old)], new.top_r[candidates(new)]
    k = np.clip(np.searchsorted(before, after), 0, before.size - 1)
    same = np.abs(before[k] - after) <= 1e-12
    active = np.zeros(after.size, bool)
    active[same] = clamp.mask(old)[k[same]]
    return np.where(active, mu[k], 0.0), dataclasses.replace(clamp, active=active)


def remeshed(model: Model, edge: float, size: float) -> Model:
    """The model of ``model``'s sheet and rubber on its base mesh clustered about r = ``edge`` (``clustered``)."""
    base = _radial(model) if model.base is None else model.base
    mesh = MeshQuad.init_tensor(clustered(base, edge, size), _heights(model)).with_defaults()
    return dataclasses.replace(discretize(model.thickness, mesh, model.law, model.geometry), base=base,
                               cluster=(edge, CORE * size))


def _size(model: Model) -> float:
    """The cluster's element length (R): ``SIZE`` thicknesses, at least ``MIN_SIZE`` and at most a quarter of the
    thickness."""
    return min(max(SIZE * model.thickness, MIN_SIZE), 0.25 * model.thickness)


def ahead(model: Model, y: np.ndarray, control: Control, force: float, before: tuple[float, float] | None):
    """The state y of ``control`` (in contact under a force) carried to the mesh clustered about the edge it is
    predicted to have at the force ``force`` (mu_0 R^2), the nodes inside that edge active, unsolved (the march to
    that force solves it); ``before`` the force and the fluid's pressure of the state before it, if any (module
    docstring). (model, y, control)."""
    active = np.asarray(control.active)
    r_c = edge_radius(model, y, active, control.surface)
    top_rho = model.top_r + y[model.top_radial]
    rho = float(np.interp(r_c, model.top_r, top_rho))
    pf, now = float(y[model.size]), float(control.force or 0.0)
    slope = 0.0 if before is None or before[0] == now else (pf - before[1]) / (now - before[0])
    ratio = (force / now) * pf / max(pf + slope * (force - now), 1e-3 * pf)
    edge = float(np.interp(rho * np.sqrt(ratio), top_rho, model.top_r))
    if model.cluster is not None and abs(edge - model.cluster[0]) <= STOP * model.cluster[1]:
        return model, y, control
    new = remeshed(model, edge, _size(model))
    return (new, *transfer(model, new, y, control, edge))


def follow(model: Model, y: np.ndarray, control: Control, tol: float):
    """The state y of ``control`` on ``model`` solved again on meshes clustered about its contact edge until the
    edge lies in the middle of a cluster (module docstring). (model, y, control, Newton iterations)."""
    size = _size(model)
    total = 0
    for _ in range(MAX_MOVES):
        edge = edge_radius(model, y, np.asarray(control.active), control.surface)
        if model.cluster is not None and abs(edge - model.cluster[0]) <= STOP * model.cluster[1]:
            break
        new = remeshed(model, edge, size)
        try:
            y_new, control_new, iterations = contact(new, *transfer(model, new, y, control, edge), tol)
        except ConvergenceError:  # the state stays on the mesh it solved on, its edge error reported as it is
            break
        if min(margins(new, y_new, control_new).values()) <= 0.0:  # a state at the range's end, found inside it
            break  # on the mesh it was solved on, stays there (``rangeend``: every state returned is inside)
        model, y, control, total = new, y_new, control_new, total + iterations
    return model, y, control, total
