"""The checks of the capsule section: each capsule against its closed form, its own balances, and the FE model.

Per capsule (``capsules.Curve``), as ``verdicts.Check`` rows, the tolerances ``verdicts.TOLERANCES``'s:

- ``SPHERE``: the inflated capsule's Phat_I against the sphere's closed form at the solver's stretch,
  ``capsules.sphere_pressure`` (``capsule_sphere``);
- ``BALANCES`` (per solver): F = P A_c, the force on the plate against the fluid's pressure on the patch
  (``capsule_force``); the vertical balance at the equator, 2 pi rho T_1 = P pi rho^2 - F (``capsule_equator``);
  the fluid's law (``fluid``); the plate's reaction against the force asked (the FE model's, ``fem_force``): each
  the worst over the curve's states;
- ``FEM``: the FE model against shooting at each of its forces, on every key of the capsule's contract (the
  inflated state's at Fhat = 0) and the smallest tensions, and the distance between the meridians
  (``capsule_fem``, ``fem_tension``, ``capsule_profile``);
- the wrinkling verdict (``verdicts.membrane_checks``) of each solver's curve;
- the FE model's mesh convergence (``capsules.sequence``): the observed order of each quantity against the theory's
  4 (P2, a vertex on the contact edge: the pocket's ``convergence.EXPECTED`` for its edge-fitted meshes), the
  finest mesh's error below the pocket's ``convergence.FITTED_P2_FINEST``, and Richardson's extrapolation against
  shooting (``convergence.RICHARDSON_FACTOR``).
"""

from __future__ import annotations

import math

from .capsules import capsule_value, sphere_pressure
from .convergence import EXPECTED, FITTED_P2_FINEST, RICHARDSON_FACTOR, observed_order, richardson
from .verdicts import TOLERANCES, Check, fluid_row, membrane_checks, profile_distance, relative, row

__all__ = [
    "BALANCES",
    "COMPRESSED_KEYS",
    "FEM",
    "INFLATED_KEYS",
    "ORDER",
    "SPHERE",
    "checks",
    "equator_balance",
    "order_checks",
]

SPHERE = "capsule: shooting vs closed form (sphere)"
BALANCES = "capsule: balances"
FEM = "capsule: FEM P2 vs shooting"
ORDER = "capsule: FEM P2 convergence"
#: the keys of the capsule's contract compared between the solvers: the inflated state's, the compressed one's
INFLATED_KEYS = ("stretch_pole", "height", "volume", "stretch_clamp", "radius_equator")
COMPRESSED_KEYS = ("pressure", "pressure_ratio", "contact_area", "contact_radius", "contact_radius_deformed",
                   "stretch_contact", "height", "height_ratio", "volume", "stretch_pole", "radius_equator",
                   "force_ETR")


def equator_balance(state) -> tuple[float, float]:
    """(2 pi rho T_1, P pi rho^2 - F) at the equator of a compressed capsule, units E T R (F = ``force_ETR``, pi
    Fhat Phat_I where P_I > 0; T_1 the profile's at its last point, the equator)."""
    rho = float(state.extra["radius_equator"])
    pull = 2.0 * math.pi * rho * float(state.profile.tension_1[-1])
    return pull, math.pi * state.pressure * rho**2 - float(state.extra["force_ETR"])


def _worst(rows: list[Check], count: int) -> Check:
    worst = max(rows, key=lambda c: c.error)
    return Check(worst.case, worst.comparison, worst.step, worst.quantity, f"worst of {count} forces "
                 f"({worst.where})", worst.value, worst.reference, worst.error, worst.tolerance, worst.verdict)


def _balances(name: str, label: str, states) -> list[Check]:
    pressed = [s for s in states if s.force > 0.0]
    comparison = f"{BALANCES} ({label})"
    out = []
    force = [row(name, comparison, "consistency", "F = P A_c: force_ETR = pi Phat rho_c^2", f"Fhat = {s.force:.4g}",
                 s.extra["force_ETR"], math.pi * s.pressure * s.contact_radius_deformed**2,
                 relative(s.extra["force_ETR"], math.pi * s.pressure * s.contact_radius_deformed**2),
                 TOLERANCES["capsule_force"][0]) for s in pressed]
    out.append(_worst(force, len(pressed)))
    equator = []
    for s in pressed:
        pull, balance = equator_balance(s)
        scale = math.pi * s.pressure * float(s.extra["radius_equator"]) ** 2
        equator.append(row(name, comparison, "consistency", "equator: 2 pi rho T_1 = P pi rho^2 - F",
                           f"Fhat = {s.force:.4g}", pull, balance, abs(pull - balance) / scale,
                           TOLERANCES["capsule_equator"][0]))
    out.append(_worst(equator, len(pressed)))
    reaction = [row(name, comparison, "consistency", "plate's reaction = F", f"Fhat = {s.force:.4g}",
                    s.extra["force_reaction"], s.force, relative(s.extra["force_reaction"], s.force),
                    TOLERANCES["fem_force"][0]) for s in pressed if "force_reaction" in s.extra]
    if reaction:  # the FE model's: the nodal reaction of the contact zone
        out.append(_worst(reaction, len(reaction)))
    fluid = [fluid_row(name, comparison, f"Fhat = {s.force:.4g}", s) for s in pressed]
    out.append(_worst(fluid, len(pressed)))
    return out


def _fem_rows(curve) -> list[Check]:
    name, out = curve.capsule.name, []
    keys: tuple[str, ...]
    for state in curve.fem:
        ref = curve.shooting_at(state.force)
        if state.force == 0.0:
            step, where, a, b, keys = "inflation", "Fhat = 0", state.inflated, ref.inflated, INFLATED_KEYS
        else:
            step, where, a, b, keys = "compression", f"Fhat = {state.force:.4g}", state, ref, COMPRESSED_KEYS
        for key in keys:
            value, reference = capsule_value(a, key), capsule_value(b, key)
            out.append(row(name, FEM, step, key, where, value, reference, relative(value, reference),
                           TOLERANCES["capsule_fem"][0]))
        for key in ("tension_1_min", "tension_2_min"):
            value, reference = getattr(a, key), getattr(b, key)
            out.append(row(name, FEM, step, key, where, value, reference, relative(value, reference),
                           TOLERANCES["fem_tension"][0]))
        distance = profile_distance(a, b)
        out.append(row(name, FEM, step, "profile (distance / R)", where, distance, 0.0, distance,
                       TOLERANCES["capsule_profile"][0]))
    return out


def checks(curves) -> list[Check]:
    """Every check of the capsules' ``curves`` (module docstring)."""
    out = []
    for curve in curves:
        name, inflated = curve.capsule.name, curve.shooting[0].inflated
        closed = sphere_pressure(curve.capsule.material, inflated.stretch_pole)
        out.append(row(name, SPHERE, "inflation", "Phat_I = w'(lambda) / (E lambda^2)",
                       f"lambda = {inflated.stretch_pole:.6g}", inflated.pressure, closed,
                       relative(inflated.pressure, closed), TOLERANCES["capsule_sphere"][0]))
        out += _balances(name, "shooting", curve.shooting)
        out += membrane_checks(name, "shooting", curve.shooting)
        if curve.fem:
            out += _balances(name, "FEM P2", curve.fem)
            out += membrane_checks(name, "FEM P2", curve.fem)
            out += _fem_rows(curve)
    return out


def order_checks(sequence) -> list[Check]:
    """The FE model's observed orders on the capsule against the theory's, and Richardson against shooting."""
    out = []
    where = f"{sequence.study}, {len(sequence.elements)} meshes"
    expected = EXPECTED[("compression", 2, "fitted")]
    for quantity in sequence.values:
        errors = sequence.errors(quantity)
        p, tolerance, _ = expected.get(quantity, expected["height"])
        order = observed_order(sequence.sizes, errors)
        out.append(row("capsule", ORDER, "order", quantity, where, order, p, abs(order - p), tolerance))
        out.append(row("capsule", ORDER, "finest error", quantity, where, errors[-1], 0.0, errors[-1],
                       FITTED_P2_FINEST))
        extrapolated = richardson(sequence.sizes, sequence.values[quantity])
        reference = sequence.reference[quantity]
        if extrapolated is None:
            out.append(row("capsule", ORDER, "Richardson", quantity, where + ": not monotone, no extrapolation",
                           math.nan, reference, math.nan, None))
        else:
            value, estimate, _ = extrapolated
            out.append(row("capsule", ORDER, "Richardson", quantity, where, value, reference,
                           relative(value, reference), RICHARDSON_FACTOR * estimate / abs(reference)))
    return out
