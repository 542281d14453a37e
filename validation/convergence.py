"""Mesh convergence of the FE model against the shooting reference (``pocket converge``).

Two mesh families, both element orders, inflation and compression (at Fhat = ``FORCE``):

- ``fitted``: the FE model's default meshes (``meshes.polar``: graded towards the
  axis) and, in compression, its edge-fitted contact (a vertex follows the contact
  edge, the contact radius is a Newton unknown);
- ``uniform``: uniform meshes and, in compression, the fixed-mesh penalty plate
  (with augmented-Lagrangian updates): the edge falls inside an element.

Theory (Lagrange elements of order p). Where the solution is smooth inside every
element, the energy-norm error is O(h^p) and the error of smooth functionals is
O(h^2p), 2 for P1 and 4 for P2: the volume, the pressure, the heights, and the
contact radius (fixed by a variationally consistent flux). Two things break the
smoothness:

- the axis: the pole stretch is a derivative at r = 0, where the axisymmetric
  forms are singular; its influence function grows like 1/r and on uniform
  meshes it converges at O(h^2) whatever p. Meshes graded towards the axis
  restore O(h^2p) (measured).
- the contact edge, where the meridian's curvature jumps from 0 to P/T1. On a
  fixed mesh it sits inside an element, eta is only H^(5/2 - eps) there, and the
  energy-norm error is O(h^(3/2)): functionals converge at O(h^3) at best, and
  the errors scatter as the edge moves inside its element from mesh to mesh (the
  penalty's contact set is resolved to a quadrature point, its Uzawa loop stops
  at a floor): orders fitted to a few meshes range from 1 to 3.5 and are
  reported, not checked. The edge-fitted mesh keeps the full order.

``h`` is the largest element size (in compression on the fitted mesh, the largest
of the free part: the contact element holds the exact flat solution).
``observed_order`` fits log(error) against log(h) with np.polyfit. ``richardson``
extrapolates the three finest meshes: with q = (f_2h - f_4h) / (f_h - f_2h) and
mesh ratio k = h_2h / h_h, the observed order is p = log(q) / log(k) and the limit
f_h + (f_h - f_2h) / (k^p - 1), its error estimated by |f_h - f_2h| / (k^p - 1);
it needs q > 1 (errors of one sign, shrinking).
"""

from __future__ import annotations

import dataclasses
import math
import time

import numpy as np

from pocket.apps.physical import Pocket
from pocket.core.states import CompressedState, InflatedState

from .failures import located

__all__ = [
    "EXPECTED",
    "FITTED_P2_FINEST",
    "FORCE",
    "MESHES",
    "QUANTITIES",
    "RICHARDSON_FACTOR",
    "Sequence",
    "checks",
    "observed_order",
    "richardson",
    "sequence",
    "tasks",
]

#: the compressed state of the study: the paper's fig. 2b force
FORCE = 0.19
QUANTITIES = {"inflation": ("height", "volume", "stretch_pole"),
              "compression": ("height", "pressure", "contact_area", "contact_radius")}
#: mesh family -> what it means in each study
MESHES = {"fitted": "default meshes graded towards the axis; in compression the edge-fitted contact",
          "uniform": "uniform meshes; in compression the fixed-mesh penalty plate"}


@dataclasses.dataclass(frozen=True)
class Sequence:
    """FEM values of one study on a sequence of meshes, with the shooting values."""

    study: str  # "inflation" | "compression"
    order: int
    mesh: str  # a key of MESHES
    elements: tuple[int, ...]
    sizes: np.ndarray  # largest element size of each mesh
    values: dict  # quantity -> FEM values, shape (n,)
    reference: dict  # quantity -> shooting value
    seconds: float

    def errors(self, quantity: str) -> np.ndarray:
        """|FEM / shooting - 1| on each mesh."""
        return np.abs(self.values[quantity] / self.reference[quantity] - 1.0)


def tasks(case: Pocket, plan) -> list[tuple]:
    """Arguments of ``sequence`` for the study of ``plan`` (both studies, orders and mesh families)."""
    return [(case, study, order, mesh, plan.convergence_sizes[order])
            for study in QUANTITIES for order in (1, 2) for mesh in MESHES]


def _largest_element(state, study: str, mesh: str) -> float:
    lengths = np.diff(state.profile.r[:: state.extra["order"]])  # the profile holds every node: the vertices
    return float(lengths[1:].max() if (study, mesh) == ("compression", "fitted") else lengths.max())


def sequence(case: Pocket, study: str, order: int, mesh: str, counts) -> Sequence:
    """Solve ``study`` of ``case`` (a ``pocket.apps.physical.Pocket``) with FEM order ``order`` on ``mesh``
    meshes of ``counts`` elements."""
    from pocket import fem, meshes, shooting

    start = time.perf_counter()
    rubber, pressure, sealed = case.material, case.pressure_initial, case.fluid_options()
    case_name, what = case.case.name, f"convergence study ({study}, FEM P{order} on {mesh} meshes)"
    force = "inflated state (Fhat = 0)" if study == "inflation" else f"Fhat = {FORCE}"
    with located(case_name, what + ": its shooting reference", "no mesh (shooting)", force):
        ref = shooting.inflate(rubber, pressure) if study == "inflation" else \
            shooting.compress(rubber, pressure, FORCE, **sealed)
    names = QUANTITIES[study]
    values: dict[str, list[float]] = {name: [] for name in names}
    sizes = []
    for n in counts:
        grid = fem.default_mesh(n) if mesh == "fitted" else meshes.uniform(n)
        contact = "fitted" if mesh == "fitted" else "penalty"
        where = f"{mesh} mesh of {n} elements" + ("" if study == "inflation" else f", {contact} contact")
        state: InflatedState | CompressedState
        with located(case_name, what, where, force):
            if study == "inflation":
                state = fem.inflate(rubber, pressure, mesh=grid, order=order)
            else:
                state = fem.compress(rubber, pressure, FORCE, mesh=grid, order=order, contact=contact, **sealed)
        sizes.append(_largest_element(state, study, mesh))
        for name in names:
            values[name].append(float(getattr(state, name)))
    return Sequence(study=study, order=order, mesh=mesh, elements=tuple(counts), sizes=np.array(sizes),
                    values={k: np.array(v) for k, v in values.items()},
                    reference={name: float(getattr(ref, name)) for name in names},
                    seconds=time.perf_counter() - start)


def observed_order(sizes, errors) -> float:
    """Slope of log(error) against log(h), least squares (np.polyfit)."""
    return float(np.polyfit(np.log(sizes), np.log(errors), 1)[0])


def richardson(sizes, values) -> tuple[float, float, float] | None:
    """(extrapolated value, error estimate, observed order) from the three finest meshes, or None."""
    (h2, h1), (f4, f2, f1) = sizes[-2:], values[-3:]
    d1, d2 = f1 - f2, f2 - f4
    if d1 == 0.0 or d2 / d1 <= 1.0:
        return None
    ratio = h2 / h1
    p = math.log(d2 / d1) / math.log(ratio)
    correction = d1 / (ratio**p - 1.0)
    return f1 + correction, abs(correction), p


def _expected():
    smooth = "smooth in every element: O(h^2p)"
    out = {}
    for order in (1, 2):
        full = (2.0 * order, 0.2 if order == 1 else 0.3, smooth)
        out[("inflation", order, "fitted")] = {q: full for q in QUANTITIES["inflation"]}
        near_axis = (2.0 * order, 0.3, smooth + "; the axis pollutes the coarse uniform meshes")
        out[("inflation", order, "uniform")] = {"height": near_axis, "volume": full,
                                                "stretch_pole": (2.0, 0.3, "a derivative at the axis: O(h^2)")}
        out[("compression", order, "fitted")] = {q: full for q in QUANTITIES["compression"]}
    scatter = "the edge inside an element: errors scattered, not a function of h; reported, not checked"
    out[("compression", 1, "uniform")] = {q: (2.0, None, f"P1's own order, at best; {scatter}")
                                          for q in QUANTITIES["compression"]}
    out[("compression", 2, "uniform")] = {q: (3.0, None, f"H^(5/2) at the edge: O(h^3) at best; {scatter}")
                                          for q in QUANTITIES["compression"]}
    return out


#: (study, order, mesh) -> {quantity: (theory's order, tolerance on the observed one or None: reported
#: only, reason)}
EXPECTED = _expected()
#: P2 on fitted meshes in compression: the finest error below this
FITTED_P2_FINEST = 1e-8
#: Richardson: the shooting value must lie within this many error estimates of the extrapolation
RICHARDSON_FACTOR = 3.0


def checks(sequences) -> list:
    """Observed orders against theory, the finest fitted error, and Richardson against shooting, as checks."""
    from .verdicts import Check

    rows = []
    for seq in sequences:
        label = f"FEM P{seq.order} {seq.mesh} meshes"
        where = f"{seq.study}, {len(seq.elements)} meshes"
        expected = EXPECTED[(seq.study, seq.order, seq.mesh)]
        for quantity in seq.values:
            errors = seq.errors(quantity)
            order = observed_order(seq.sizes, errors)
            p, tol, _ = expected[quantity]
            verdict = "info" if tol is None else "pass" if abs(order - p) <= tol else "fail"
            rows.append(Check("convergence", label, "order", quantity, where, order, p, abs(order - p), tol, verdict))
            if (seq.study, seq.order, seq.mesh) == ("compression", 2, "fitted"):
                ok = errors[-1] < FITTED_P2_FINEST
                rows.append(Check("convergence", label, "finest error", quantity, where, errors[-1], 0.0,
                                  errors[-1], FITTED_P2_FINEST, "pass" if ok else "fail"))
            rows.append(_richardson_row(seq, quantity, label, where))
    return rows


def _richardson_row(seq, quantity, label, where):
    from .verdicts import Check

    ref = seq.reference[quantity]
    result = richardson(seq.sizes, seq.values[quantity])
    checked = seq.mesh == "fitted" or seq.study == "inflation"  # uniform meshes in contact: scattered errors
    if result is None:
        return Check("convergence", label, "Richardson", quantity, where + ": not monotone, no extrapolation",
                     float("nan"), ref, float("nan"), None, "info")
    value, estimate, _ = result
    error, tol = abs(value / ref - 1.0), RICHARDSON_FACTOR * estimate / abs(ref)
    verdict = ("pass" if error <= tol else "fail") if checked else "info"
    return Check("convergence", label, "Richardson", quantity, where, value, ref, error, tol if checked else None,
                 verdict)
