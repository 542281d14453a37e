r"""The uninflated capsule in the capsule section: P_I = 0, pressed by the plates' height, by both solvers.

The paper's rubber (``capsules.STUDY``'s) filled with a liquid at P_I = 0, the usual microcapsule test: its states
lie on the branch reached deep (the theory's section 12, "Two branches"), pressed by the plates' height H R (Fhat
is undefined at P_I = 0; the force is F / (E T R)). The shooting solver solves it at ``HEIGHTS``, where its
membrane is taut (below H ~ 0.47 the pole's patch no longer compresses), the FE model (P2, ``capsules.FEM_ELEMENTS``)
at ``FEM_HEIGHTS``; both solvers also locate where the range starts (the contact edge's tension vanishing), the
shooting solver to 2e-6, the FE model as a bracket.

Checks (``checks``, the capsule section's tolerances): each state's F = P A_c (``capsule_force``), the equator's
vertical balance 2 pi rho T_1 = P pi rho^2 - F (``capsule_equator``), the liquid's volume (``fluid``: the unstressed
sphere's, 4 pi / 3 by the shooting solver's closed form), every key of the contract between the solvers
(``capsule_fem``), the smallest tensions (``fem_tension``) and the meridian (``capsule_profile``), every state taut
(the wrinkling verdict), and the FE model's bracket of the start against the shooting solver's (informational).
"""

from __future__ import annotations

import dataclasses
import math
import re
import time

from pocket.core.errors import OutOfRangeError
from pocket.core.states import CompressedState

from .capsulechecks import BALANCES, FEM, equator_balance
from .capsules import FEM_ELEMENTS, STUDY, capsule_value
from .failures import located
from .verdicts import TOLERANCES, Check, fluid_row, membrane_checks, profile_distance, relative, row

__all__ = ["FEM_HEIGHTS", "HEIGHTS", "KEYS", "NAME", "Uninflated", "checks", "solve"]

#: the case's name in the checks
NAME = "capsule-mooney-rivlin-uninflated"
#: the plates' heights H / R the shooting solver presses it to (compressions 55 % to 75 %), and the FE model
HEIGHTS = (0.45, 0.4, 0.35, 0.3, 0.25)
FEM_HEIGHTS = (0.45, 0.35, 0.25)
#: the keys compared between the solvers (the capsule's contract without P / P_I, undefined at P_I = 0)
KEYS = ("pressure", "contact_area", "contact_radius", "contact_radius_deformed", "stretch_contact", "height",
        "height_ratio", "volume", "stretch_pole", "radius_equator", "force_ETR")
_START = 0.95  # a height above the range's start: its refusal quotes the start


@dataclasses.dataclass(frozen=True)
class Uninflated:
    """The uninflated capsule's states by each solver (in the order of ``HEIGHTS``, ``FEM_HEIGHTS``), the start of
    its range by each (the shooting solver's H*, the FE model's bracket), and the solves' ``seconds``."""

    shooting: tuple[CompressedState, ...]
    fem: tuple[CompressedState, ...]
    start: float
    fem_start: tuple[float, float]
    seconds: float


def _start(refused: OutOfRangeError, pattern: str) -> tuple[float, ...]:
    found = re.search(pattern, str(refused))
    if found is None:
        raise refused
    return tuple(float(v) for v in found.groups())


def solve() -> Uninflated:
    """Both solvers on the uninflated capsule (module docstring)."""
    from pocket import fem, shooting

    start = time.perf_counter()
    material = STUDY.material
    with located(NAME, "uninflated capsule between two plates (shooting)", "no mesh (shooting)",
                 f"{len(HEIGHTS)} heights H/R = {min(HEIGHTS):g} to {max(HEIGHTS):g}"):
        shot = tuple(shooting.compress_height(material, 0.0, h, geometry="capsule") for h in HEIGHTS)
        try:
            shooting.compress_height(material, 0.0, _START, geometry="capsule")
        except OutOfRangeError as refused:
            (first,) = _start(refused, r"start deeper, at height = (\S+):")
    with located(NAME, "uninflated capsule between two plates (fem)", f"FE P2 {FEM_ELEMENTS} mesh",
                 f"{len(FEM_HEIGHTS)} heights H/R = {min(FEM_HEIGHTS):g} to {max(FEM_HEIGHTS):g}"):
        fe = tuple(fem.compress_height(material, 0.0, h, geometry="capsule", elements=FEM_ELEMENTS)
                   for h in FEM_HEIGHTS)
        try:
            fem.compress_height(material, 0.0, _START, geometry="capsule", elements=FEM_ELEMENTS)
        except OutOfRangeError as refused:
            reached, beyond = _start(refused, r"start deeper, at plate height h/R = (\S+) to (\S+) \(")
    return Uninflated(shot, fe, first, (reached, beyond), time.perf_counter() - start)


def _balances(label: str, states) -> list[Check]:
    comparison, out = f"{BALANCES} ({label})", []
    for s in states:
        where = f"H/R = {s.height:.4g}"
        area = math.pi * s.pressure * s.contact_radius_deformed**2
        out.append(row(NAME, comparison, "consistency", "F = P A_c: force_ETR = pi Phat rho_c^2", where,
                       s.extra["force_ETR"], area, relative(s.extra["force_ETR"], area),
                       TOLERANCES["capsule_force"][0]))
        pull, balance = equator_balance(s)
        scale = math.pi * s.pressure * float(s.extra["radius_equator"]) ** 2
        out.append(row(NAME, comparison, "consistency", "equator: 2 pi rho T_1 = P pi rho^2 - F", where, pull,
                       balance, abs(pull - balance) / scale, TOLERANCES["capsule_equator"][0]))
        out.append(fluid_row(NAME, comparison, where, s))
    return out


def checks(found: Uninflated) -> list[Check]:
    """Every check of the uninflated capsule (module docstring)."""
    out = _balances("shooting", found.shooting) + _balances("FEM P2", found.fem)
    sphere = 4.0 * math.pi / 3.0
    out.append(row(NAME, f"{BALANCES} (shooting)", "consistency", "V_I = 4 pi / 3 (the unstressed sphere)",
                   "P_I = 0", found.shooting[0].inflated.volume, sphere,
                   relative(found.shooting[0].inflated.volume, sphere), TOLERANCES["fluid"][0]))
    out += membrane_checks(NAME, "shooting", found.shooting, False) + membrane_checks(NAME, "FEM P2", found.fem, False)
    by_height = dict(zip(HEIGHTS, found.shooting, strict=True))
    for height, state in zip(FEM_HEIGHTS, found.fem, strict=True):
        ref, where = by_height[height], f"P_I = 0, H/R = {height:g}"
        for key in KEYS:
            value, reference = capsule_value(state, key), capsule_value(ref, key)
            out.append(row(NAME, FEM, "compression", key, where, value, reference, relative(value, reference),
                           TOLERANCES["capsule_fem"][0]))
        for key in ("tension_1_min", "tension_2_min"):
            value, reference = getattr(state, key), getattr(ref, key)
            out.append(row(NAME, FEM, "compression", key, where, value, reference, relative(value, reference),
                           TOLERANCES["fem_tension"][0]))
        distance = profile_distance(state, ref)
        out.append(row(NAME, FEM, "compression", "profile (distance / R)", where, distance, 0.0, distance,
                       TOLERANCES["capsule_profile"][0]))
    low, high = found.fem_start
    middle = 0.5 * (low + high)
    out.append(row(NAME, FEM, "range", "start of the range H* (FE bracket's middle; shooting)",
                   f"P_I = 0, FE bracket [{low:.10g}, {high:.10g}]", middle, found.start,
                   relative(middle, found.start), None))
    return out
