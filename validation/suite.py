"""Validation cases as data: ``cases.toml`` in physical units, dimensionless form derived.

Physical values are strings with units (``thickness = "0.25 mm"``, ``c1 =
"160 kPa"``), or plain numbers in SI, converted by ``pocket.core.units`` (the one
place units are handled); ``_KINDS`` names each key's kind. From the SI
values, with the paper's definitions (eqs (1), (10)):

    alpha = C2 / C1,   E = 6 (1 + alpha) C1 = 6 (C1 + C2),   Phat_I = P_I R / (E T).

Unknown or missing keys, non-positive sizes and alpha <= -1 raise ``InputError``
quoting the key, before any solver runs.
"""

from __future__ import annotations

import dataclasses
import math
import pathlib
import tomllib

from pocket.core.errors import InputError
from pocket.core.units import quantity

__all__ = ["Case", "Design", "load", "CASES_FILE"]

CASES_FILE = pathlib.Path(__file__).with_name("cases.toml")

#: physical key -> its kind in pocket.core.units
_KINDS = {
    "thickness": "length",
    "radius": "length",
    "height": "length",
    "c1": "pressure",
    "c2": "pressure",
    "modulus": "pressure",
    "pressure": "pressure",
    "force": "force",
}


@dataclasses.dataclass(frozen=True)
class Case:
    """One pocket: sheet, material and initial pressure, in SI units."""

    name: str
    label: str
    thickness: float
    c1: float
    c2: float
    radius: float
    pressure: float
    sample: int | None = None
    tags: tuple[str, ...] = ()

    @property
    def alpha(self) -> float:
        """C2 / C1."""
        return self.c2 / self.c1

    @property
    def modulus(self) -> float:
        """Young's modulus E = 6 (1 + alpha) C1, in Pa."""
        return 6.0 * (1.0 + self.alpha) * self.c1

    @property
    def pressure_hat(self) -> float:
        """Phat_I = P_I R / (E T)."""
        return self.pressure * self.radius / (self.modulus * self.thickness)


@dataclasses.dataclass(frozen=True)
class Design:
    """The soft button of the paper's section 6 (Table 2), in SI units."""

    radius: float
    height: float
    modulus: float
    alpha: float
    force: float
    height_ratio: float
    pressure_coefficient: float
    thickness_coefficient: float

    @property
    def pressure(self) -> float:
        """P_I = c F / (pi R^2), the paper's tactile rule."""
        return self.pressure_coefficient * self.force / (math.pi * self.radius**2)

    @property
    def thickness(self) -> float:
        """T = 0.216 P_I R^4 / (E H0^3), the paper's thickness rule."""
        return self.thickness_coefficient * self.pressure * self.radius**4 / (self.modulus * self.height**3)


def _fields(table: dict, where: str, plain: dict, required: set) -> dict:
    out = {}
    for key, value in table.items():
        if key in _KINDS:
            out[key] = quantity(f"{where}: {key}", value, _KINDS[key])
        elif key in plain:
            out[key] = plain[key](value, f"{where}: {key}")
        else:
            known = sorted(set(_KINDS) | set(plain))
            raise InputError(f"{where}: unknown key {key!r} (known: {', '.join(known)})")
    missing = required - set(out)
    if missing:
        raise InputError(f"{where}: missing {', '.join(sorted(missing))}")
    return out


def _number(value, where) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise InputError(f"{where} = {value!r}, but it must be a finite number")
    return float(value)


def _text(value, where) -> str:
    if not isinstance(value, str) or not value:
        raise InputError(f"{where} = {value!r}, but it must be a non-empty string")
    return value


def _tags(value, where) -> tuple[str, ...]:
    if not isinstance(value, list) or not all(isinstance(t, str) for t in value):
        raise InputError(f"{where} = {value!r}, but it must be a list of strings")
    return tuple(value)


def _sample(value, where) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise InputError(f"{where} = {value!r}, but it must be an integer")
    return value


def _positive(values: dict, where: str, names) -> None:
    for name in names:
        if values[name] <= 0.0:
            raise InputError(f"{where}: {name} = {values[name]!r} (SI), but it must be > 0")


def _case(table: dict, index: int) -> Case:
    where = f"case {index + 1}"
    plain = {"name": _text, "label": _text, "sample": _sample, "tags": _tags}
    values = _fields(table, where, plain, {"name", "label", "thickness", "c1", "c2", "radius", "pressure"})
    where = f"case {values['name']!r}"
    _positive(values, where, ("thickness", "c1", "radius", "pressure"))
    if values["c2"] / values["c1"] <= -1.0:
        raise InputError(f"{where}: alpha = C2/C1 = {values['c2'] / values['c1']!r}, but it must be > -1")
    return Case(**values)


def _design(table: dict) -> Design:
    plain = {k: _number for k in ("alpha", "height_ratio", "pressure_coefficient", "thickness_coefficient")}
    values = _fields(table, "design", plain, {f.name for f in dataclasses.fields(Design)})
    _positive(values, "design", ("radius", "height", "modulus", "force", "height_ratio",
                                 "pressure_coefficient", "thickness_coefficient"))
    return Design(**values)


def load(path=CASES_FILE) -> tuple[list[Case], Design]:
    """The cases and the design of a cases file (default: ``validation/cases.toml``)."""
    path = pathlib.Path(path)
    try:
        data = tomllib.loads(path.read_text())
    except (OSError, tomllib.TOMLDecodeError) as err:
        raise InputError(f"cannot read the cases file {path}: {err}") from None
    unknown = set(data) - {"case", "design"}
    if unknown:
        raise InputError(f"{path.name}: unknown table(s) {sorted(unknown)} (known: case, design)")
    if not data.get("case") or "design" not in data:
        raise InputError(f"{path.name}: needs [[case]] tables and a [design] table")
    cases = [_case(table, k) for k, table in enumerate(data["case"])]
    names = [c.name for c in cases]
    if len(set(names)) != len(names):
        raise InputError(f"{path.name}: case names repeat: {names}")
    return cases, _design(data["design"])
