"""The report's headline in two verdicts: the numerics (pass/fail) and the models' limits (measured).

The numerics: the solvers of one model agree with each other (the FE model, P1 and P2, against the
shooting solver; each solver's own consistency), converge (the mesh-convergence study) and identify a
known rubber (the fits); every such check has a tolerance, and one failure fails the run.

The models' limits are facts about the models, not about the software: where each model is within
``LIMIT`` (1 %) of the more complete one, computed from the run's own data: the membrane against the solid
for the paper's samples (``membrane_vs_solid``), the analytical model against the membrane
(``analytical_vs_membrane``). Their checks are informational. The membrane theory's own condition, both
tensions positive at every state (``MEMBRANE``), is a verdict: a state that would wrinkle is not a state of
the membrane model, whichever solver gives it (``wrinkling``).
"""

from __future__ import annotations

from . import thickness
from .plan import APPROXIMATE, REFERENCE
from .verdicts import ANALYTICAL_RANGE, MEMBRANE

__all__ = [
    "LIMIT",
    "MODEL_COMPARISONS",
    "analytical_vs_membrane",
    "blocks",
    "is_numerics",
    "membrane_vs_solid",
    "sentence",
    "sentences",
    "tally",
    "wrinkling",
]

#: within this relative error a model counts as the more complete one's equal
LIMIT = thickness.LIMIT
#: the comparisons of a model with a more complete one, and the membrane theory's own condition
MODEL_COMPARISONS = (f"{APPROXIMATE.label} vs {REFERENCE.label}", thickness.COMPARISON, MEMBRANE)
#: the solid's quantities quoted in the headline (mid-surface heights: like with like), and their short names
_SOLID = {"V": "V", "H0 (mid-surface)": "H0", "P/P_I": "P/P_I", "H/H0 (mid-surface)": "H/H0", "A_c": "A_c"}
#: the analytical model's compressed quantities, inflated ones, and their names
_PRESSED = {"pressure_ratio": "P/P_I", "contact_area": "A_c", "height_ratio": "H/H0"}
_INFLATED = {"height": "H0", "volume": "V"}


def is_numerics(check) -> bool:
    """Whether ``check`` (a ``verdicts.Check``) is about the numerics, not a model's limits."""
    return check.comparison not in MODEL_COMPARISONS


def tally(checks) -> dict:
    """Verdict -> number of ``checks``."""
    out = {"pass": 0, "fail": 0, "info": 0}
    for c in checks:
        out[c.verdict] += 1
    return out


_WITHIN = f"within {100 * LIMIT:g} %"


def _pct(x: float) -> str:
    """A fraction as a percentage to two significant digits, never an exponent: 0.54, 3.9, 26, 118."""
    return f"{100 * x:.0f}" if x >= 0.1 else f"{100 * x:.2g}"


def _span(errors) -> str:
    """The spread of relative errors as percentages: "26 %", "13-26 %", or "up to 3.4 %" if some are within
    LIMIT."""
    low, high = min(errors), max(errors)
    if low <= LIMIT:
        return f"up to {_pct(high)} %"
    return f"{_pct(high)} %" if _pct(low) == _pct(high) else f"{_pct(low)}-{_pct(high)} %"


def _and(items) -> str:
    items = list(items)
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def _numbers(numbers) -> str:
    """Sample numbers as "1", "1 and 3", "1-3"."""
    numbers = sorted(numbers)
    if len(numbers) > 2 and numbers == list(range(numbers[0], numbers[-1] + 1)):
        return f"{numbers[0]}-{numbers[-1]}"
    return _and(map(str, numbers))


def sentence(lead: str, clauses) -> str:
    """A limit (``membrane_vs_solid``, ``analytical_vs_membrane``) as one sentence."""
    return f"{lead}: {'; '.join(clauses)}."


def membrane_vs_solid(comparisons) -> tuple[str, list[str]]:
    """(lead, clauses): per sample, the quantities in which the membrane is within LIMIT of the solid at every
    pressure and force of the run, and by how much it differs in the others."""
    from pocket.solid import DEFAULT_ELEMENTS, DEFAULT_LAYERS

    errors: dict = {}
    for c in comparisons:
        for quantity in _SOLID:
            forces = [None] if quantity in thickness.INFLATION else c.forces
            errors.setdefault(c.sample, {}).setdefault(quantity, []).extend(abs(c.error(quantity, f)) for f in forces)
    ratio = {c.sample: c.thickness_ratio for c in comparisons}
    within = {n: [q for q, e in errors[n].items() if max(e) <= LIMIT] for n in errors}
    parts = []
    for n in sorted(errors):
        text = f"sample {n} (T/R = {ratio[n]:g}) "
        text += f"{_WITHIN} in {_and(_SOLID[q] for q in within[n])}" if within[n] else f"{_WITHIN} in no quantity"
        beyond = [f"{_span(e)} in {_SOLID[q]}" for q, e in errors[n].items() if q not in within[n]]
        parts.append(text + (f", off by {_and(beyond)}" if beyond else ""))
    everywhere = [n for n in sorted(errors) if len(within[n]) == len(_SOLID)]
    pressures = _and(f"{p:g}" for p in sorted({c.pressure_kpa for c in comparisons}))
    forces = _and(f"{f:g}" for f in comparisons[0].forces)
    if everywhere:
        parts.insert(0, f"sample{'s' if len(everywhere) > 1 else ''} {_numbers(everywhere)} {_WITHIN} in every "
                        "quantity")
        parts = [p for p in parts if not any(p.startswith(f"sample {n} ") for n in everywhere)]
    return (f"The membrane against the solid (the paper's samples at P_I = {pressures} kPa, pressed to Fhat = "
            f"{forces}; the solid at its default mesh, {DEFAULT_ELEMENTS} elements along the radius and "
            f"{DEFAULT_LAYERS} through the thickness)", parts)


def _upto(pairs, key) -> float | None:
    """The largest Fhat up to which every state of ``pairs`` (analytical, shooting) is within LIMIT in ``key``;
    None if the smallest force is not."""
    last = None
    for a, s in pairs:
        if abs(getattr(a, key) / getattr(s, key) - 1.0) > LIMIT:
            break
        last = s.force
    return last


def _worst(pairs, key, limit=None) -> float | None:
    chosen = [abs(getattr(a, key) / getattr(s, key) - 1.0) for a, s in pairs if limit is None or s.force <= limit]
    return max(chosen) if chosen else None


def analytical_vs_membrane(curves) -> tuple[str, list[str]]:
    """(lead, clauses): over the pockets the analytical model poses (a flat plate), its inflated H0 and V against
    the membrane's (shooting), and per compressed quantity the Fhat up to which it is within LIMIT, its error at
    the smallest force, below the paper's ANALYTICAL_RANGE and over the whole curve."""
    posed = [c for c in curves if c.approximate and c.approximate[0] is not None]
    if not posed:
        return "The analytical model", ["it poses none of the pockets (a curved indenter presses each)"]
    inflated = []  # its H0 and V
    for key, name in _INFLATED.items():
        errors = [abs(getattr(c.approximate[0].inflated, key) / getattr(c.reference[0].inflated, key) - 1.0)
                  for c in posed]
        inflated.append(f"{_span(errors)} in {name}")
    parts = []  # a clause per compressed quantity
    for key, name in _PRESSED.items():
        pairs = [[(a, s) for a, s in zip(c.approximate[1:], c.reference[1:], strict=True) if a is not None]
                 for c in posed]
        pairs = [p for p in pairs if p]
        reach = sorted(u for u in (_upto(p, key) for p in pairs) if u is not None)
        if reach:
            span = f"{reach[0]:g}" + (f"-{reach[-1]:g}" if reach[-1] > reach[0] else "")
            text = f"{name} {_WITHIN} up to Fhat = {span} for {len(reach)} of {len(pairs)} pockets"
        else:
            text = f"{name} {_WITHIN} for no pocket from its smallest force on"
        first = {p[0][1].force for p in pairs}
        start = _span([abs(getattr(p[0][0], key) / getattr(p[0][1], key) - 1.0) for p in pairs])
        text += f" ({start} at Fhat = {min(first):g}" if len(first) == 1 else f" ({start} at the smallest force"
        paper = [w for w in (_worst(p, key, ANALYTICAL_RANGE) for p in pairs) if w is not None]
        if paper:
            text += f", up to {_pct(max(paper))} % for Fhat <= {ANALYTICAL_RANGE:g}"
        whole = [w for w in (_worst(p, key) for p in pairs) if w is not None]
        parts.append(text + f", up to {_pct(max(whole))} % over the curves)")
    plural = "s" if len(posed) > 1 else ""
    return (f"The analytical model against the membrane (shooting) on the {len(posed)} pocket{plural} pressed by "
            "the plate", [f"inflated, off by {_and(inflated)}", *parts])


def wrinkling(checks) -> tuple[str, str]:
    """(verdict, sentence): the membrane theory's own condition over the ``checks`` of ``MEMBRANE``."""
    rows = [c for c in checks if c.comparison == MEMBRANE]
    failed = [c for c in rows if c.verdict == "fail"]
    if not rows:
        return "info", ""
    if not failed:
        return "pass", (f"Both tensions T_1, T_2 stay positive at every state of the {len(rows)} curves checked, "
                        "every solver's: a state that would wrinkle is not a state of the membrane model.")
    where = "; ".join(f"{c.case}: {c.where}" for c in failed)
    return "fail", (f"A tension falls to zero or below (the sheet would wrinkle: not a state of the membrane model) "
                    f"on {len(failed)} of the {len(rows)} curves checked: {where}.")


def _limits(results) -> list[tuple[str, list[str]]]:
    out = []
    if results.thicknesses:
        out.append(membrane_vs_solid(results.thicknesses))
    if results.curves:
        out.append(analytical_vs_membrane(results.curves))
    return out


def sentences(results) -> list[str]:
    """The models' limits in sentences, from the run's own data (``results``: a ``runner.Results``)."""
    return [sentence(*limit) for limit in _limits(results)]


def blocks(results) -> list:
    """The report's headline as ``document`` blocks: the verdict on the numerics, the one on the membrane
    theory's own condition (if any curve was checked), and the models' limits."""
    numerics = tally(c for c in results.checks if is_numerics(c))
    out: list[tuple] = []
    out.append(("p", f"Numerics: {'FAIL' if numerics['fail'] else 'PASS'}. The solvers agree with each other and "
                 f"converge: {numerics['pass']} checks pass, {numerics['fail']} fail ({numerics['info']} more are "
                 "reported without a tolerance): the finite-element model (P1, P2) against the shooting solver, "
                 "each solver's own consistency (the fluid's law, the indenter's reaction), the observed orders of "
                 "the mesh-convergence study and its Richardson extrapolations, each law fitted to known data "
                 "against the truth" + (", and the capsules against the sphere's closed form and their own balances"
                                        if results.capsules else "") + "."))
    verdict, sentence = wrinkling(results.checks)
    if sentence:
        out.append(("p", f"Membrane theory's condition: {verdict.upper()}. {sentence}"))
    measured = _limits(results)
    out.append(("p", "The models' limits, measured in this run (facts about the models, not pass/fail; each model "
                     f"against the more complete one, {_WITHIN} or not)" + (":" if measured else ": none.")))
    for lead, clauses in measured:
        out += [("p", f"{lead}:"), ("list", clauses)]
    return out
