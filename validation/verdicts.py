"""Every comparison of a validation run as a row with a tolerance and a verdict.

Verdicts: ``pass`` / ``fail`` against a tolerance, ``info`` where no tolerance
should hold (a model's own error against a more complete model, the
analytical model's among them): reported, never failed.
Errors are relative (|x / x_ref - 1|) unless the row says otherwise. The
tolerances and their reasons:
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from pocket import fem
from pocket.core.states import CHECKS, CompressedState

from .plan import APPROXIMATE, REFERENCE
from .suite import on_plate

__all__ = [
    "ANALYTICAL_RANGE",
    "MEMBRANE",
    "TOLERANCES",
    "Check",
    "analytical_checks",
    "fem_checks",
    "fluid_row",
    "membrane_checks",
    "reference_checks",
    "relative",
    "row",
    "summary",
]

#: the largest element of the P2 FE model's default mesh (graded towards the axis), in R
P2_ELEMENT = float(np.diff(fem.default_mesh(order=2)).max())

#: name -> (tolerance, reason)
TOLERANCES = {
    "fem_p2": (1e-9, "every reported scalar of the P2 FE model at its default mesh (256 elements graded towards "
                     "the axis, the contact edge fitted) within 1e-9 of the shooting solver, the design's quality "
                     "bar: two independent discretisations of one model agree to their discretisation error "
                     "(measured <= 6e-10 over every law and fluid of the suite, the largest for Gent near its lock "
                     "at 0.95 of its range)"),
    "fem_p1": (1e-6, "every reported scalar of the P1 FE model at its default mesh (1024 elements; error O(h^2)) "
                     "within 1e-6 of the shooting solver (measured <= 7e-7 over every law and fluid)"),
    "fem_tension": (3e-3, "the smallest tensions T_1, T_2 are minima over each solver's own points (shooting: its "
                          "adaptive ODE steps; FE: nodes and quadrature points, P1's tensions constant per "
                          "element, O(h) = 1e-3), so the two agree to that sampling, not to the discretisation "
                          "(measured <= 1.4e-3 for P1 and 2.3e-4 for P2, the largest near the end of Gent's range)"),
    "fem_sphere": (5e-8, "under a sphere, every reported scalar of the P2 FE model at its default mesh (the contact "
                         "pressure at the pole and at the edge and the deformed contact radius among them) within "
                         "5e-8 of the shooting solver: the P2 elements' O(h^4) on a curved contact is above 1e-8 at "
                         "256 elements (measured <= 3.4e-8, the pole's stretch and contact pressure under the "
                         "smallest sphere, and 16-fold less at 512 elements)"),
    "fem_sphere_tension": (P2_ELEMENT**2, "under a sphere, the smallest tensions: the FE samples an interior minimum "
                                          "at its nodes and quadrature points, to O(h^2) (a smooth function's "
                                          "minimum missed by a point spaced h from it is off by f'' h^2 / 2), "
                                          "where shooting refines it: h^2, h the largest element of the default "
                                          f"P2 mesh ({P2_ELEMENT:.2g} R)"),
    "fem_sphere_profile": (5e-5, "under a sphere, the meridians' largest distance in R, measured by interpolating the "
                                 "FE nodes linearly as under the plate (fem_profile): measured <= 2.3e-5 on the "
                                 "suite's spheres, where every scalar of the same states agrees to 3.4e-8. The "
                                 "interpolation dominates it: at Fhat = 1 under spheres of 1 R and 3 R it falls "
                                 "3.8 to 4.2-fold per halving of the elements (128, 256, 512), O(h^2), while the "
                                 "scalars fall 16-fold; the curvature it scales with jumps at the contact edge, "
                                 "from the sphere's to the free dome's"),
    "fem_profile": (1e-5, "largest distance between the FE and shooting meridians at the shooting's "
                          "radii, in R; interpolating the FE nodes linearly (h <= 4e-3) adds ~ h^2 kappa / 8"),
    "fem_force": (1e-8, "the indenter's reaction equals the applied force to the Newton tolerance (relative to "
                        "the force)"),
    "fluid": (1e-9, "the fluid's own law at every force, |V / V_law - 1|: a liquid keeps V_law = V_I, a gas "
                    "V_law = V_I ((P_I + P_atm) / (P + P_atm))^(1/gamma); shooting root residual 1e-12, ODE rtol "
                    "1e-10; FE Lagrange multiplier to Newton tolerance 1e-10"),
    "membrane": (0.0, "membrane theory holds only while both tensions are positive: a state with T_1 or T_2 <= 0 "
                      "anywhere (a sheet that would wrinkle) fails, whichever solver gives it; the verdict covers "
                      "every state of the curve (each state's smallest tensions and flag: states.csv)"),
    "fit": (1e-6, "a law fitted by the shooting model to noise-free pole heights of the P2 FE model (within ~1e-10 "
                  "of the shooting solver: fem_p2) recovers each parameter to that difference times the fit's "
                  "conditioning (up to ~1e3: Yeoh's C30 the least determined), far inside 1e-6; for Ogden, whose "
                  "parameters are not unique, mu_0 and the curve (every datum) are checked and the parameters "
                  "reported"),
    "capsule_sphere": (1e-12, "the shooting solver's inflated capsule against the sphere's closed form Phat = "
                              "w'(lambda) / (E lambda^2), written per law from the strain energy "
                              "(validation/capsules.py), not from the solver's tension kernel: the solver finds "
                              "lambda by Brent's method to 1e-15 of it, so the two agree to the rounding of w' "
                              "(its factor lambda - lambda^-5 loses eps / (lambda - 1) ~ 1e-14 at the suite's "
                              "smallest strain, 0.03) times d ln Phat / d ln lambda (about 1 on the first branch "
                              "far from the balloon's maximum)"),
    "capsule_force": (1e-10, "a capsule's plate force against the fluid's pressure on the contact patch, F = P A_c "
                             "(in units E T R: force_ETR = pi Phat rho_c^2): shooting closes its residual "
                             "q rho_c^2 / Fhat - 1 to Newton's floor, 10 residual_tol ~ 1e-11 at the suite's Phat_I "
                             ">= 0.1 (its free part shot in segments, each amplifying the pole's errors at most "
                             "100-fold); the FE model's rho_c^2 is its contact_area = Fhat / q by construction"),
    "capsule_equator": (1e-9, "a capsule's vertical balance at the equator, 2 pi rho T_1 = P pi rho^2 - F (units E T "
                              "R), relative to P pi rho^2: an identity of the ODEs (the theory's first integral), "
                              "not a condition the shooting solver closes, so it holds to the integration's error, "
                              "DOP853 at rtol 1e-10 accumulated over the meridian's steps (a few rtol); the FE model "
                              "is held to the same (its T_1 at the equator's node: measured <= 6e-13)"),
    "capsule_fem": (1e-9, "every key of a capsule's contract, the P2 FE model on 512 elements against shooting: the "
                          "default 256 elements on a meridian pi/2 long, a quarter of them on the contact patch, leave "
                          "the free part's largest element 0.02 to 0.04 R (the pocket's 0.006 R) and its O(h^4) error "
                          "at up to 1.7e-9; 512 elements divide it by 16, below the pocket's 1e-9 bar, which is the "
                          "shooting's own accuracy (the mesh convergence on a capsule, in the report, measures it)"),
    "capsule_profile": (3e-4, "a capsule's meridians' largest distance in R, the FE nodes interpolated linearly at the "
                              "shooting's arc lengths: linear interpolation between nodes d apart misses a curve by up "
                              "to d^2 |x''| / 8, with d <= 0.02 R (half the free part's largest P2 element at the "
                              "suite's largest compression) and |x''| = |d^2 (rho, eta) / dS^2| <= 5 at the rim of the "
                              "most compressed capsules: 2.5e-4 (measured <= 3e-6: the shooting's points rarely fall "
                              "where both are largest)"),
}
#: Fhat below which the paper calls its analytical model good (its section 5): its errors are reported up to it
#: and beyond it
ANALYTICAL_RANGE = 0.1
#: the comparison name of the wrinkling verdicts
MEMBRANE = "membrane theory (T_1, T_2 > 0)"
_INFLATION_KEYS = ("stretch_pole", "height", "volume", "stretch_clamp")
_COMPRESSION_KEYS = ("pressure", "contact_area", "contact_radius", "stretch_contact", "height", "volume")


@dataclasses.dataclass(frozen=True)
class Check:
    """One compared quantity: ``value`` against ``reference``, ``error`` against ``tolerance``."""

    case: str
    comparison: str  # e.g. "FEM P2 vs shooting"
    step: str  # "inflation" | "compression" | "consistency" | "membrane" | "order" | ...
    quantity: str
    where: str
    value: float
    reference: float
    error: float
    tolerance: float | None
    verdict: str  # "pass" | "fail" | "info"


def relative(value, reference) -> float:
    """|value / reference - 1|, or |value| against a reference of 0."""
    return abs(value - reference) if reference == 0.0 else abs(value / reference - 1.0)


def _verdict(error, tolerance) -> str:
    if tolerance is None:
        return "info"
    return "pass" if error <= tolerance else "fail"


def row(case, comparison, step, quantity, where, value, reference, error, tolerance) -> Check:
    """A check with its verdict: ``info`` without a tolerance, else ``pass`` iff error <= tolerance."""
    return Check(case, comparison, step, quantity, where, float(value), float(reference), float(error),
                 tolerance, _verdict(error, tolerance))


def profile_distance(state, reference) -> float:
    """Largest distance between two meridians at the reference's Lagrangian radii, in R."""
    p, q = state.profile, reference.profile
    rho = np.interp(q.r, p.r, p.rho)
    eta = np.interp(q.r, p.r, p.eta)
    return float(np.max(np.hypot(rho - q.rho, eta - q.eta)))


def _fem_tolerance(column) -> float:
    """The scalar tolerance of an FE column: by its element order (P2 unless it says P1)."""
    return TOLERANCES["fem_p1" if dict(column.options).get("order", 2) == 1 else "fem_p2"][0]


def fluid_row(name, label, where, state) -> Check:
    """The fluid's law at ``state``: V against V_I (a liquid) or the polytropic gas law at its pressure."""
    expected = state.inflated.volume * state.fluid.volume_ratio(state.pressure, state.pressure_initial)
    quantity = "gas law: V = V_I ((P_I + P_atm)/(P + P_atm))^(1/gamma)" if state.fluid.is_gas else "volume = V_I"
    return row(name, label, "consistency", quantity, where, state.volume, expected, relative(state.volume, expected),
                TOLERANCES["fluid"][0])


def fem_checks(curves, fem) -> list[Check]:
    """A solver column (``compute.ColumnCurve``) against the reference at each of its forces, and its
    own consistency (indenter reaction = F, the fluid's law). Under a curved indenter the compressed
    states are compared on the contact's own scalars too (``CompressedState.CONTACT_KEYS``), with the
    sphere's tolerances."""
    name, own = curves.pocket.case.name, fem.column.label
    label = f"{own} vs {REFERENCE.label}"
    by_force = dict(zip(curves.forces.tolist(), curves.reference, strict=True))
    tol, tol_profile, tol_tension = _fem_tolerance(fem.column), TOLERANCES["fem_profile"][0], \
        TOLERANCES["fem_tension"][0]
    compression_keys: tuple[str, ...] = _COMPRESSION_KEYS
    if not on_plate(curves.pocket):
        compression_keys += CompressedState.CONTACT_KEYS
        tol, tol_tension = TOLERANCES["fem_sphere"][0], TOLERANCES["fem_sphere_tension"][0]
        tol_profile = TOLERANCES["fem_sphere_profile"][0]
    rows = []
    keys: tuple[str, ...]
    for state in fem.states:
        ref = by_force[state.force]
        if state.force == 0.0:
            step, where, a, b, keys = "inflation", "Fhat = 0", state.inflated, ref.inflated, _INFLATION_KEYS
        else:
            step, where, a, b, keys = "compression", f"Fhat = {state.force:.4g}", state, ref, compression_keys
        for key in keys:
            value, reference = getattr(a, key), getattr(b, key)
            rows.append(row(name, label, step, key, where, value, reference, relative(value, reference), tol))
        for key in CHECKS[:2]:
            value, reference = getattr(a, key), getattr(b, key)
            rows.append(row(name, label, step, key, where, value, reference, relative(value, reference), tol_tension))
        distance = profile_distance(a, b)
        rows.append(row(name, label, step, "profile (distance / R)", where, distance, 0.0, distance, tol_profile))
        if state.force > 0.0:
            reaction = state.extra["force_reaction"]
            rows.append(row(name, own, "consistency", "indenter reaction = F", where,
                             reaction, state.force, relative(reaction, state.force), TOLERANCES["fem_force"][0]))
            rows.append(fluid_row(name, own, where, state))
    return rows


def reference_checks(curves) -> list[Check]:
    """The reference curve's own consistency: the fluid's law at every force (the worst)."""
    rows = [fluid_row(curves.pocket.case.name, REFERENCE.label, "", state) for state in curves.reference]
    worst = max(rows, key=lambda c: c.error)
    return [dataclasses.replace(worst, where=f"worst of {len(curves.forces)} forces")]


def membrane_checks(name: str, label: str, states, inflated: bool = True) -> list[Check]:
    """One verdict over a curve's ``states`` (and the inflated state they start from, if ``inflated``: not an
    uninflated capsule's unstressed sphere, tension-free by definition): fail if any has a tension <= 0
    (``wrinkled``); the value is the smallest tension of all, in units of E T."""
    states = [states[0].inflated, *states] if inflated else list(states)
    worst = min(states, key=lambda s: min(s.tension_1_min, s.tension_2_min))
    low = min(worst.tension_1_min, worst.tension_2_min)
    which = "T_1" if worst.tension_1_min <= worst.tension_2_min else "T_2"
    wrinkled = sum(s.wrinkled for s in states)
    count = f"{wrinkled} of {len(states)} states wrinkled" if wrinkled else f"{len(states)} states"
    force = getattr(worst, "force", 0.0)
    at = f"Fhat = {force:.4g}" if math.isfinite(force) else f"H/R = {worst.height:.4g}"
    where = f"{label}, {count}; smallest: {which} at {at}"
    return [Check(name, MEMBRANE, "membrane", f"smallest tension ({label})", where, float(low), 0.0,
                  max(0.0, -float(low)), TOLERANCES["membrane"][0], "fail" if wrinkled else "pass")]


def analytical_checks(curves) -> list[Check]:
    """The analytical model against shooting, informational: its inflated H0, V and lambda_0 - 1, and per
    compressed quantity its largest error up to the paper's ANALYTICAL_RANGE and beyond it; none for a pocket
    it does not pose (a curved indenter).

    No tolerance: the model's error is a fact about the model, not about the software. Its assumed shape
    (lambda_1 uniform along the meridian) leaves an error that does not vanish with the strain (H0 and V
    several per cent off even as Phat -> 0), so no bound of order the strain holds; the report's headline says
    where it is within 1 % of the full model (``limits.analytical_vs_membrane``)."""
    name, label = curves.pocket.case.name, f"{APPROXIMATE.label} vs {REFERENCE.label}"
    if curves.approximate[0] is None:  # a curved indenter: the model is the flat plate's
        return []
    ref_i, ana_i = curves.reference[0].inflated, curves.approximate[0].inflated
    where = f"lambda_0 - 1 = {ref_i.stretch_pole - 1.0:.3g}"
    rows = []
    for key in ("height", "volume", "stretch_pole"):
        shift = 1.0 if key == "stretch_pole" else 0.0
        value, reference = getattr(ana_i, key) - shift, getattr(ref_i, key) - shift
        rows.append(row(name, label, "inflation", key if not shift else "lambda_0 - 1", where, value, reference,
                         relative(value, reference), None))
    pairs = [(a, s) for a, s in zip(curves.approximate[1:], curves.reference[1:], strict=True) if a is not None]
    for key in ("height_ratio", "pressure_ratio", "contact_area"):
        for inside in (True, False):
            chosen = [(a, s) for a, s in pairs if (s.force <= ANALYTICAL_RANGE) == inside]
            if not chosen:
                continue
            a, s = max(chosen, key=lambda p: relative(getattr(p[0], key), getattr(p[1], key)))
            span = (f"Fhat <= {ANALYTICAL_RANGE:g}" if inside
                    else f"{ANALYTICAL_RANGE:g} < Fhat <= {chosen[-1][1].force:.3g}")
            rows.append(row(name, label, "compression", key, f"worst at Fhat = {s.force:.3g} ({span})",
                             getattr(a, key), getattr(s, key), relative(getattr(a, key), getattr(s, key)), None))
    return rows


def summary(checks) -> list[dict]:
    """One row per (case, comparison, step): the worst verdict, the largest checked error, the count."""
    groups: dict = {}
    for c in checks:
        groups.setdefault((c.case, c.comparison, c.step), []).append(c)
    rows = []
    for (case, comparison, step), group in groups.items():
        verdicts = {c.verdict for c in group}
        verdict = "fail" if "fail" in verdicts else "pass" if "pass" in verdicts else "info"
        scored = [c for c in group if c.verdict != "info"] or group
        worst = max(scored, key=lambda c: c.error / (c.tolerance or 1.0))
        rows.append(dict(case=case, comparison=comparison, step=step, checks=len(group), verdict=verdict,
                         worst=f"{worst.quantity} ({worst.where})", error=worst.error, tolerance=worst.tolerance))
    return rows
