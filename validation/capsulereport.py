"""The capsule section of the report: its text, its tables, its figure and the CSV of every capsule state.

The figure draws the force-deformation curves as the literature plots them (Feng & Yang 1973; Liu, Williams &
Briscoe 1996): the force on each plate in units of E T R, F / (E T R) = pi Fhat Phat_I (a state's ``force_ETR``),
against the compression 1 - H / lambda_I = 1 - gap / (2 lambda_I R), the gap's closure relative to the inflated
capsule's diameter; (a) every law at Phat_I = ``capsules.PRESSURE`` filled with a liquid, the FE model as markers,
(b) the paper's rubber at three Phat_I, with a gas, and uninflated (``uninflated``: P_I = 0, where the plates'
height presses it and lambda_I = 1).
"""

from __future__ import annotations

import numpy as np

from . import capsulechecks, uninflated
from .capsules import FEM_ELEMENTS, FORCE, GAS, PRESSURE, STUDY, capsule_value
from .convergence import FITTED_P2_FINEST, RICHARDSON_FACTOR, observed_order, richardson
from .plotdata import Figure, Panel, Series
from .pockets import cell

__all__ = ["CSV", "NAME", "blocks", "compression", "figure", "state_rows"]

#: the figure's name (its PNG and CSV), and the file of every capsule state
NAME = "capsules"
CSV = "capsule_states.csv"
_X, _Y = "1 - H / lambda_I", "F / (E T R)"
#: the keys of capsule_states.csv after the case, solver, law, fluid and the compression
_KEYS = ("pressure_initial", "force", *capsulechecks.COMPRESSED_KEYS, "tension_1_min", "tension_2_min", "wrinkled")


def compression(state) -> float:
    """1 - H / lambda_I: the plates' travel relative to the inflated capsule's radius."""
    return 1.0 - state.height / state.inflated.stretch_pole


def _series(curve, solver: str, label: str, color: int) -> Series:
    states = curve.shooting if solver == "shooting" else curve.fem
    return Series(label, solver, np.array([compression(s) for s in states]),
                  np.array([s.extra["force_ETR"] for s in states]), color)


def figure(curves, unpressurised=None) -> Figure:
    """Force against compression (module docstring); ``unpressurised``: the uninflated capsule
    (``uninflated.Uninflated``), drawn in panel (b), or None."""
    liquids = [c for c in curves if c.capsule.pressure == PRESSURE and not c.capsule.fluid.is_gas]
    laws = []
    for k, curve in enumerate(liquids):
        law = curve.capsule.material.law
        laws.append(_series(curve, "shooting", f"{law}: shooting", k))
        if curve.fem:
            laws.append(_series(curve, "FEM P2", f"{law}: FEM P2", k))
    paper = [c for c in curves if c.capsule.material.law == STUDY.material.law]
    paper.sort(key=lambda c: (c.capsule.fluid.is_gas, c.capsule.pressure))
    pressures = tuple(_series(c, "shooting", f"Phat_I = {c.capsule.pressure:g}, {c.capsule.fluid.kind}", k)
                      for k, c in enumerate(paper))
    if unpressurised is not None:
        for solver, states in (("shooting", unpressurised.shooting), ("FEM P2", unpressurised.fem)):
            pressures += (Series(f"Phat_I = 0, liquid: {solver}", solver, np.array([compression(s) for s in states]),
                                 np.array([s.extra["force_ETR"] for s in states]), len(paper)),)
    return Figure(NAME, "A capsule between two plates: the force on each plate F / (E T R) against the compression "
                  "1 - H / lambda_I (the gap between the plates is 2 H R, lambda_I R the inflated capsule's radius), "
                  f"(a) every law's example rubber at Phat_I = {PRESSURE:g} filled with a liquid, the FE model (P2, "
                  f"its default mesh) as markers, (b) the paper's rubber ({STUDY.material.law}, alpha = "
                  f"{STUDY.material.alpha:.3g}) at "
                  f"several Phat_I, and filled with a gas (Phat_atm = {GAS.ambient:g}, gamma = {GAS.gamma:g})"
                  + (", and uninflated (P_I = 0, a liquid, pressed by the plates' height; the FE model as markers)"
                     if unpressurised is not None else "") + ". Lines: the shooting solver.",
                  (Panel(f"(a) every law, Phat_I = {PRESSURE:g}, a liquid", _X, _Y, tuple(laws)),
                   Panel(f"(b) {STUDY.material.law}: Phat_I and the fluid", _X, _Y, pressures)))


def state_rows(curves, unpressurised=None) -> tuple[list, list]:
    """(header, rows): every capsule state of every solver (and of the uninflated capsule ``unpressurised``, if
    given: its Fhat and P / P_I NaN)."""
    header = ["case", "solver", "material", "fluid", "compression", *_KEYS]
    rows = []
    groups = [(curve.capsule.name, solver, states) for curve in curves
              for solver, states in (("shooting", curve.shooting), ("FEM P2", curve.fem))]
    if unpressurised is not None:
        groups += [(uninflated.NAME, solver, states)
                   for solver, states in (("shooting", unpressurised.shooting), ("FEM P2", unpressurised.fem))]
    for name, solver, states in groups:
        for s in states:
            values = [capsule_value(s, k) if k != "wrinkled" else s.wrinkled for k in _KEYS]
            rows.append([name, solver, s.material.law, s.fluid.kind, repr(compression(s))]
                        + [v if isinstance(v, bool) else repr(float(v)) for v in values])
    return header, rows


def _case_rows(curves, checks) -> tuple[list, list]:
    header = ["capsule", "rubber (units of mu_0)", "fluid", "Phat_I", "lambda_I", "forces (shooting, FE)",
              "largest compression", "largest F / (E T R)", "worst error / tolerance", "verdict"]
    rows = []
    for curve in curves:
        own = [c for c in checks if c.case == curve.capsule.name and c.tolerance]
        worst = max(own, key=lambda c: c.error / c.tolerance)
        last = curve.shooting[-1]
        rows.append([curve.capsule.label, _rubber(curve.capsule.material),
                     curve.capsule.fluid.kind, f"{curve.capsule.pressure:g}", cell(last.inflated.stretch_pole, 6),
                     f"{len(curve.shooting)}, {len(curve.fem)}", cell(compression(last), 3),
                     cell(last.extra["force_ETR"], 4), f"{cell(worst.error / worst.tolerance, 2)} "
                     f"({worst.quantity}, {worst.comparison})",
                     "fail" if any(c.verdict == "fail" for c in own) else "pass"])
    return header, rows


def _convergence_blocks(sequence) -> list:
    rows = []
    for quantity, values in sequence.values.items():
        extrapolated = richardson(sequence.sizes, values)
        rows.append([quantity, " ".join(map(str, sequence.elements)),
                     cell(observed_order(sequence.sizes, sequence.errors(quantity)), 3),
                     cell(float(sequence.errors(quantity)[-1]), 2), cell(extrapolated[0] if extrapolated else None, 12),
                     cell(sequence.reference[quantity], 12)])
    return [("h", 3, "Mesh convergence on the capsule"),
            ("p", f"The FE model (P2, its default meshes, a vertex on the contact edge) on {STUDY.label} at Phat_I = "
                  f"{STUDY.pressure:g}, pressed to Fhat = {FORCE:g}, against shooting: the theory's order is 4 (the "
                  "solution smooth in every element), checked as the pocket's edge-fitted meshes are, h the largest "
                  f"element; the finest error must be below {FITTED_P2_FINEST:g} and Richardson's extrapolation "
                  f"from the three finest meshes must hold shooting within {RICHARDSON_FACTOR:g} of its error "
                  f"estimates. {sequence.seconds:.1f} s."),
            ("table", ["quantity", "elements", "observed order", "finest error", "Richardson", "shooting"], rows)]


def _rubber(material) -> str:
    """A scaled rubber in a table cell: its law and parameters ("yeoh: c10 0.5, c20 -0.0118, c30 0.00118")."""
    values = ", ".join(f"{name} {' '.join(f'{v:.3g}' for v in value) if isinstance(value, tuple) else f'{value:.3g}'}"
                       for name, value in material.params)
    return f"{material.law}: {values}"


def _uninflated_blocks(found, checks) -> list:
    own = [c for c in checks if c.case == uninflated.NAME]
    worst = max((c for c in own if c.tolerance), key=lambda c: c.error / c.tolerance)
    low, high = found.fem_start
    rows = [[f"{s.height:g}", solver, cell(compression(s), 3), cell(s.pressure, 8), cell(s.extra["force_ETR"], 8),
             cell(s.contact_radius_deformed, 8), cell(s.extra["radius_equator"], 8)]
            for solver, states in (("shooting", found.shooting), ("FEM P2", found.fem)) for s in states]
    return [("h", 3, "The uninflated capsule"),
            ("p", f"The paper's rubber ({STUDY.material.law}, alpha = {STUDY.material.alpha:.3g}) filled with a liquid "
                  "at P_I = 0, the usual microcapsule test: Fhat and P / P_I are undefined, the force is F / (E T R), "
                  "and the capsule is pressed by the plates' height H R. Its states start deep (the theory's "
                  "section 12, 'Two branches'): the contact edge's meridional tension first holds at H/R = "
                  f"{found.start:.7g} by the shooting solver, in [{low:.10g}, {high:.10g}] by the FE model "
                  f"(P2, {FEM_ELEMENTS} elements); at the smaller compressions the pole's patch is compressive "
                  f"(flagged wrinkled), and the states checked, from a compression of "
                  f"{1.0 - max(uninflated.HEIGHTS):.2g} on, are taut. Checked as the other capsules: F = P "
                  "A_c, the equator's balance, the liquid's volume (the unstressed sphere's), every key between the "
                  f"solvers, every state taut; worst error over tolerance {cell(worst.error / worst.tolerance, 2)} "
                  f"({worst.quantity}, {worst.comparison}), "
                  f"{'fail' if any(c.verdict == 'fail' for c in own) else 'pass'}. {found.seconds:.1f} s."),
            ("table", ["H/R", "solver", "compression", "Phat", "F / (E T R)", "contact radius rho_c / R",
                       "equator rho / R"], rows)]


def blocks(curves, sequence, checks, caption: str, unpressurised=None) -> list:
    """The section's blocks: what it solves and checks, one row per capsule, the figure (its ``caption``), the
    uninflated capsule (``unpressurised``, or None), the convergence study (``sequence``, or None)."""
    header, rows = _case_rows(curves, checks)
    fem = any(c.fem for c in curves)
    out = [("h", 2, "A capsule between two plates"),
           ("p", "A closed spherical membrane of radius R and thickness T (the theory's section 12), inflated to "
                 "Phat_I = P_I R / (E T), then squeezed between two parallel frictionless plates, each pushing with "
                 "the force F: Fhat = F / (P_I pi R^2), or F / (E T R) = pi Fhat Phat_I; H R is a plate's distance "
                 "from the equatorial plane, the compression 1 - H / lambda_I. Each law's example rubber at Phat_I "
                 f"= {PRESSURE:g}, filled with a liquid and with a gas, and the paper's rubber at other Phat_I. "
                 "Checked: the inflated capsule against the sphere's closed form, Phat = w'(lambda) / (E lambda^2) "
                 "(tolerance capsule_sphere); at every state, F = P A_c (capsule_force), the equator's vertical "
                 "balance 2 pi rho T_1 = P pi rho^2 - F (capsule_equator) and the fluid's law (fluid); "
                 + ("the FE model against shooting on every key of the capsule's contract, the smallest tensions and "
                    "the meridian (capsule_fem, fem_tension, capsule_profile), with its plate's reaction (fem_force)"
                    if fem else "no FE model in this run (the plan's capsule FE forces are empty)")
                 + "; every state's tensions positive (the wrinkling verdict). The tolerances' reasons are in the "
                   f"section 'Tolerances'; every capsule state is in {CSV}."),
           ("table", header, rows),
           ("image", f"{NAME}.png", f"{caption} Data: {NAME}.csv.")]
    if unpressurised is not None:
        out += _uninflated_blocks(unpressurised, checks)
    if sequence is not None:
        out += _convergence_blocks(sequence)
    return out
