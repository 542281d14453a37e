"""Every table and key of a case file, from the declaration the case reader checks files against.

The keys are ``pocket.apps.cases``'s (its ``_SECTIONS``: an unknown key in a file is refused against it); a law's
parameters are ``pocket.core.materials.LAWS``'s, a solver's options its record's (``pocket.apps.solvers``), the
indenter's keys ``pocket.apps.indentertable``'s. The keys that no such record describes are described in
``WRITTEN`` below, and checked against the reader's declaration both ways: a key the reader takes without a
description here, or a description of a key it does not take, stops the build.
"""

from __future__ import annotations

from guide_markdown import HEADER, cell, code, table
from sphinx.errors import ExtensionError

from pocket.apps import cases, rubbers
from pocket.apps.solvers import SOLVERS
from pocket.core.fluids import AMBIENT, GAMMA_RANGE
from pocket.core.indenters import INDENTERS, SPHERE_RADII
from pocket.core.materials import LAWS, PRESTRETCH_LIMIT

#: key -> (what is written, default, meaning) for the keys no record describes; a law's parameters, the indenter's
#: shape-specific keys and the solvers' options come from their records
WRITTEN = {
    "name": ("text", "the case file's path", "the case's name, in the results' messages and headers"),
    "label": ("text", "", "a longer description (the validation report's legends)"),
    "tags": ("a list of text", "[]", "labels; the validation suite's `headline` picks its main pocket"),
    "sheet.thickness": ("a length", "required", "T, the unstretched sheet's thickness"),
    "sheet.material": ("text", rubbers.DEFAULT_LAW, f"the rubber's law: {', '.join(LAWS)}"),
    "sheet.modulus": ("a pressure", "",
                      "Mooney-Rivlin only, with `alpha` instead of `c1` and `c2`: E = 6 (C1 + C2)"),
    "sheet.alpha": ("a number", "", "Mooney-Rivlin only, with `modulus`: alpha = C2 / C1"),
    "sheet.prestretch": ("a number", "1", f"lambda_p, the equibiaxial stretch the sheet is clamped with, 1 to "
                                        f"{PRESTRETCH_LIMIT:g}; thickness and parameters stay the unstretched "
                                        "rubber's"),
    "geometry": ("text", "pocket", "the membrane: pocket (a flat sheet clamped at its rim, `[clamp]`) or capsule (a "
                                   "closed sphere squeezed between two parallel plates, `[capsule]`)"),
    "clamp.radius": ("a length", "required for a pocket", "R, the clamp's radius"),
    "capsule.radius": ("a length", "required for a capsule", "R, the capsule's radius (its wall: `sheet.thickness`)"),
    "fluid.kind": ("text", "liquid", f"{' or '.join(rubbers.FLUIDS)}: a liquid keeps its volume, an ideal gas "
                                     "sealed at P_I is compressed"),
    "fluid.ambient": ("a pressure", f"{AMBIENT / 1000:g} kPa", "a gas's ambient (absolute) pressure"),
    "fluid.gamma": ("a number", "1", f"a gas's polytropic exponent, {GAMMA_RANGE[0]:g} (isothermal) to 5/3 "
                                   "(1.4: air compressed adiabatically)"),
    "initial.pressure": ("a pressure", "one of three", "P_I, the gauge pressure the pocket is inflated "
                                                                 "to and sealed at (> 0; a capsule's may be 0)"),
    "initial.height": ("a length", "one of three", "H0, the inflated pole height (pocket solves for P_I)"),
    "initial.volume": ("a volume", "one of three", "the inflated volume under the sheet (pocket solves "
                                                             "for P_I; not with the analytical solver)"),
    "loads.forces": ("a list of forces", "one of two", f"the forces F, at most {cases.MAX_LOADS}"),
    "loads.heights": ("a list of lengths", "one of two",
                      "the indenter's lowest point H above the clamp plane, one state each (travel control)"),
    "indenter.shape": ("text", "plate", f"what presses: {', '.join(INDENTERS)}"),
    "indenter.radius": ("a length", "required for a sphere",
                        f"a sphere's radius R_s, with R_s / R from {SPHERE_RADII[0]:g} to {SPHERE_RADII[1]:g}"),
    "indenter.file": ("a file name", "required for a profile", "a profile's CSV table (`radius [mm],height [mm]`, "
                                                             "from the axis out), relative to the case file"),
    "solver.name": ("text", "shooting", f"the solver: {', '.join(SOLVERS)}"),
}


def _keys() -> list[str]:
    """Every key the case reader takes, ``section.key`` or a top-level ``key``, in its order."""
    out = []
    for section, keys in cases._SECTIONS.items():
        out += [section] if keys is None else [f"{section}.{key}" for key in keys]
    return out


def _law_rows() -> dict[str, tuple[str, str, str]]:
    """sheet.<parameter> -> row, for every law's parameters; a name two laws share (``mu``) says each law's."""
    kinds: dict[str, dict[str, list[str]]] = {}
    meanings: dict[str, list[str]] = {}
    for law in LAWS.values():
        for p in law.parameters:
            kind = ("a list of stresses" if p.listed else "a stress") if p.unit == "stress" else (
                "a list of numbers" if p.listed else "a number")
            kinds.setdefault(p.name, {}).setdefault(kind, []).append(law.name)
            meanings.setdefault(p.name, []).append(f"{law.name}: {p.help}")
    out = {}
    for name, by in kinds.items():
        kind = next(iter(by)) if len(by) == 1 else "; ".join(f"{k} ({', '.join(laws)})" for k, laws in by.items())
        needed = "c1 and c2, or modulus and alpha" if name in ("c1", "c2") else "required by its law"
        out[f"sheet.{name}"] = (kind, needed, "; ".join(meanings[name]))
    return out


def _shown(value) -> str:
    """A solver option's default as a case file writes it (``1e-10``, ``256``, ``true``; none: a dash)."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return str(value).lower()
    return f"{value:g}" if isinstance(value, float) else str(value)


def _solver_rows() -> dict[str, tuple[str, str, str]]:
    """solver.<option> -> row, for every solver's options; an option two solvers share says each one's."""
    kinds = {"path": "a file name", "bool": "true or false", "float": "a number", "int": "an integer"}
    parts: dict[str, list[tuple[str, str, str, str]]] = {}
    for solver in SOLVERS.values():
        for option in solver.options:
            kind = " or ".join(option.choices) if option.kind == "choice" else kinds[option.kind]
            default, text = _shown(option.default), option.help
            if option.name == cases.THICKNESS_RATIO:  # a case's sheet says it: the reader refuses the key
                default, text = "sheet.thickness / clamp.radius", "T/R, never written in a case file (refused)"
            parts.setdefault(f"solver.{option.name}", []).append((solver.name, kind, default, text))
    out = {}
    for key, each in parts.items():
        many = len(each) > 1
        out[key] = (each[0][1], "; ".join(f"{n} {d}" if many else d for n, _, d, _ in each if d),
                    "; ".join(f"{n}: {text}" for n, _, _, text in each))
    return out


def rows() -> dict[str, tuple[str, str, str]]:
    """key -> (what is written, default, meaning) of every key the reader takes; an ExtensionError for a key
    without a description, or a description of no key."""
    described = {**WRITTEN, **_law_rows(), **_solver_rows()}
    keys = _keys()
    missing = [k for k in keys if k not in described]
    stale = [k for k in described if k not in keys]
    if missing or stale:
        raise ExtensionError(f"the case-file page is out of step with pocket.apps.cases: keys without a description "
                             f"{missing}, descriptions of no key {stale} (docs/_ext/guide_cases.py)")
    return {k: described[k] for k in keys}


def page() -> str:
    """The case file's keys: the top-level ones, then a table per section."""
    by = rows()
    out = [HEADER]
    top = [k for k in by if "." not in k]
    out.append(table(("key", "written as", "default", "meaning"),
                     [(code(k), cell(by[k][0]), cell(by[k][1] or "—"), cell(by[k][2])) for k in top]))
    for section, keys in cases._SECTIONS.items():
        if keys is None:
            continue
        out.append(f"\n### `[{section}]`\n")
        out.append(table(("key", "written as", "default", "meaning"),
                         [(code(k), cell(by[f"{section}.{k}"][0]), cell(by[f"{section}.{k}"][1] or "—"),
                           cell(by[f"{section}.{k}"][2])) for k in keys]))
    return "\n".join(out)
