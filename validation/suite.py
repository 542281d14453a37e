"""The suite's pockets and button: ``cases.toml``, read with the case-file reader of ``pocket run``.

Each ``[[case]]`` table is a case in the schema of ``pocket.apps.cases`` (name,
label, tags, ``[case.sheet]``, ``[case.clamp]``, ``[case.initial]``), parsed by
``pocket.apps.cases.parse`` and resolved to the dimensionless model by
``pocket.apps.physical.resolve``: alpha = C2/C1, E = 6 (C1 + C2) and
Phat_I = P_I R / (E T) (or the Phat_I of a given initial height or volume).
The suite chooses the forces and the solvers itself, so a case with loads or a
solver is refused rather than silently ignored.

The ``[design]`` table holds the inputs of the paper's soft button (section 6):
R, H0, E, alpha, the finger force F and the target H/H0. The paper's rules for
P_I and T are ``pocket.apps.design.paper_rules``.

Every problem is a one-line ``InputError`` naming the case and the key, raised
before any solver runs.
"""

from __future__ import annotations

import dataclasses
import pathlib

from pocket.apps.cases import parse
from pocket.apps.design import paper_rules
from pocket.apps.physical import Pocket, resolve
from pocket.apps.tomlfiles import read_toml
from pocket.core.errors import InputError
from pocket.core.indenters import PLATE
from pocket.core.inputs import check_alpha, check_finite, quote
from pocket.core.units import positive

__all__ = ["CASES_FILE", "Button", "headline", "load", "on_plate"]

CASES_FILE = pathlib.Path(__file__).with_name("cases.toml")

_BUTTON_KINDS = {"radius": "length", "height": "length", "modulus": "pressure", "force": "force"}


@dataclasses.dataclass(frozen=True)
class Button:
    """The soft button of the paper's section 6 (Table 2): its inputs in SI units."""

    radius: float
    height: float  # H0
    modulus: float  # E
    alpha: float
    force: float  # F
    height_ratio: float  # the target H/H0 at F

    @property
    def paper(self) -> tuple[float, float]:
        """(P_I, T) by the paper's rules (``pocket.apps.design.paper_rules``), Pa and m."""
        return paper_rules(self.radius, self.height, self.modulus, self.force)


def _button(table) -> Button:
    if not isinstance(table, dict):
        raise InputError(f"design must be a table ([design]), got {quote(table)}")
    known = (*_BUTTON_KINDS, "alpha", "height_ratio")
    for key in table:
        if key not in known:
            raise InputError(f"design: unknown key {key!r} (known: {', '.join(known)})")
    missing = [key for key in known if key not in table]
    if missing:
        raise InputError(f"design: missing key(s) {', '.join(missing)}")
    values = {key: positive(f"design.{key}", table[key], kind) for key, kind in _BUTTON_KINDS.items()}
    ratio = check_finite("design.height_ratio", table["height_ratio"])
    if not 0.0 < ratio < 1.0:
        raise InputError(f"design.height_ratio = {quote(table['height_ratio'])}, but a pressed button has "
                         "0 < H/H0 < 1")
    try:
        alpha = check_alpha(table["alpha"])
    except InputError as err:
        raise InputError(f"design.{err}") from None
    return Button(alpha=alpha, height_ratio=ratio, **values)


def _pocket(table, index: int) -> Pocket:
    where = f"case {index + 1}" + (f" ({table['name']!r})" if isinstance(table, dict) and "name" in table else "")
    for section in ("loads", "solver"):
        if isinstance(table, dict) and section in table:
            raise InputError(f"{where}: a validation case takes no '{section}': the suite chooses its "
                             "forces and solvers")
    try:
        case = parse(table, where, require_loads=False)
    except InputError as err:
        message = str(err)
        raise InputError(message if message.startswith(where) else f"{where}: {message}") from None
    if not case.label:
        raise InputError(f"{where}: missing key 'label' (the figures' legends show it)")
    return resolve(case)


def load(path=CASES_FILE) -> tuple[tuple[Pocket, ...], Button]:
    """The pockets and the button of a cases file (default: the suite's own ``cases.toml``)."""
    path = pathlib.Path(path)
    data = read_toml(path)
    unknown = set(data) - {"case", "design"}
    if unknown:
        raise InputError(f"{path.name}: unknown table(s) {sorted(unknown)} (known: case, design)")
    if not isinstance(data.get("case"), list) or not data["case"] or "design" not in data:
        raise InputError(f"{path.name}: needs [[case]] tables and a [design] table")
    pockets = tuple(_pocket(table, k) for k, table in enumerate(data["case"]))
    names = [p.case.name for p in pockets]
    if len(set(names)) != len(names):
        raise InputError(f"{path.name}: case names repeat: {names}")
    return pockets, _button(data["design"])


def headline(pockets) -> Pocket:
    """The pocket tagged "headline" (the first one if none is)."""
    return next((p for p in pockets if "headline" in p.case.tags), pockets[0])


def on_plate(pocket) -> bool:
    """Whether ``pocket`` is pressed by the flat plate (the paper's indenter), not by a curved one."""
    return pocket.case.indenter == PLATE
