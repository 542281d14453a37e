"""Case files: one pocket and its loads, in physical units (TOML).

    name = "sample 1"                    # optional
    [sheet]
    thickness = "0.25 mm"
    c1 = "160 kPa"                       # either c1 and c2 ...
    c2 = "47 kPa"
    # modulus = "1.242 MPa"              # ... or modulus E = 6 (1 + alpha) C1 and alpha = C2/C1
    # alpha = 0.29375
    [clamp]
    radius = "20 mm"
    [initial]                            # exactly one of
    pressure = "4.8 kPa"                 # P_I, or height = "10 mm" (H0), or volume = "2 mL"
    [loads]                              # exactly one of
    forces = ["0 N", "0.5 N", "1 N"]     # plate forces F, or heights = ["9 mm", "8 mm"] (plate heights H)
    [solver]                             # optional, default shooting
    name = "shooting"                    # or "fem"; options: rtol (shooting);
                                         # elements, order, penalty, augmented, tol (fem)

Values carry units (``pocket.units``); plain numbers are SI. Unknown keys,
missing keys, wrong dimensions and impossible values are one-line
``InputError``s naming the key, raised before any solver runs.

The four silicone samples of the paper's Table 1 are built in (``sample(n)``):
T = 0.25, 0.5, 0.8, 1.6 mm, C1 = 160 kPa, C2 = 47 kPa, R = 20 mm, at
P_I = 4.81275 kPa, inside Table 1's 2-5 kPa and the pressure of the paper's
figure 2 for sample 1 (Phat_I = 0.31).
"""

from __future__ import annotations

import dataclasses
import math
import pathlib
import tomllib

from .checks import check_alpha
from .errors import InputError
from .units import positive, quantity

__all__ = ["Case", "SAMPLES", "load", "parse", "sample"]

_OPTIONS = {"shooting": {"rtol": float}, "fem": {"elements": int, "order": int, "penalty": float,
                                                 "augmented": bool, "tol": float}}
_TYPES = {bool: bool, int: int, float: (int, float)}  # TOML type accepted for each option type
_SECTIONS = {"name": None, "sheet": ("thickness", "c1", "c2", "modulus", "alpha"), "clamp": ("radius",),
             "initial": ("pressure", "height", "volume"), "loads": ("forces", "heights"),
             "solver": ("name", *sorted({k for opts in _OPTIONS.values() for k in opts}))}


@dataclasses.dataclass(frozen=True)
class Case:
    """A pocket in SI units: sheet, clamp, initial state and loads, with the solver to use.

    ``initial`` is ``("pressure", P_I)``, ``("height", H0)`` or ``("volume", V)``;
    ``load_kind`` is ``"forces"`` (F in N) or ``"heights"`` (plate height H in m).
    """

    name: str
    thickness: float
    c1: float
    c2: float
    radius: float
    initial: tuple[str, float]
    load_kind: str
    loads: tuple[float, ...]
    solver: str = "shooting"
    options: tuple[tuple[str, object], ...] = ()

    @property
    def alpha(self) -> float:
        """C2 / C1."""
        return self.c2 / self.c1

    @property
    def modulus(self) -> float:
        """E = 6 (1 + alpha) C1 = 6 (C1 + C2), Pa."""
        return 6.0 * (self.c1 + self.c2)

    def fields(self) -> dict:
        """The case as a flat JSON-ready dict in SI units."""
        return {"name": self.name, "thickness_m": self.thickness, "c1_Pa": self.c1, "c2_Pa": self.c2,
                "modulus_Pa": self.modulus, "alpha": self.alpha, "radius_m": self.radius,
                f"initial_{self.initial[0]}": self.initial[1], "load_kind": self.load_kind,
                "loads": list(self.loads), "solver": self.solver, **dict(self.options)}


def _table(data, section, where) -> dict:
    if section not in data:
        raise InputError(f"{where}: missing key '{section}'")
    table = data[section]
    if not isinstance(table, dict):
        raise InputError(f"{where}: '{section}' must be a table ([{section}]), got {table!r}")
    return table


def _one_of(table, keys, section, where) -> str:
    given = [k for k in keys if k in table]
    if len(given) != 1:
        names = " or ".join(f"'{section}.{k}'" for k in keys)
        raise InputError(f"{where}: missing key {names}" if not given else
                         f"{where}: give one of {names}, not {len(given)}")
    return given[0]


def _sheet(table, where) -> tuple[float, float, float]:
    thickness = positive("sheet.thickness", _need(table, "thickness", "sheet", where), "length")
    if "c1" in table or "c2" in table:
        if "modulus" in table or "alpha" in table:
            raise InputError(f"{where}: give either sheet.c1 and sheet.c2 or sheet.modulus and sheet.alpha")
        c1 = positive("sheet.c1", _need(table, "c1", "sheet", where), "pressure")
        c2 = quantity("sheet.c2", _need(table, "c2", "sheet", where), "pressure")
        try:
            check_alpha(c2 / c1)
        except InputError:
            raise InputError(f"sheet.c2 = {table['c2']!r}, but C2/C1 must be > -1") from None
        return thickness, c1, c2
    if "modulus" not in table and "alpha" not in table:
        raise InputError(f"{where}: missing key 'sheet.c1' (with 'sheet.c2') or 'sheet.modulus' (with 'sheet.alpha')")
    modulus = positive("sheet.modulus", _need(table, "modulus", "sheet", where), "pressure")
    alpha = _need(table, "alpha", "sheet", where)
    if isinstance(alpha, bool) or not isinstance(alpha, (int, float)):
        raise InputError(f"sheet.alpha = {alpha!r} is not a number")
    try:
        alpha = check_alpha(alpha)
    except InputError as err:
        raise InputError(f"sheet.{err}") from None
    c1 = modulus / (6.0 * (1.0 + alpha))
    return thickness, c1, alpha * c1


def _need(table, key, section, where):
    if key not in table:
        raise InputError(f"{where}: missing key '{section}.{key}'")
    return table[key]


def _loads(table, where) -> tuple[str, tuple[float, ...]]:
    kind = _one_of(table, ("forces", "heights"), "loads", where)
    values = table[kind]
    key = f"loads.{kind}"
    if not isinstance(values, list) or not values:
        raise InputError(f"{key} = {values!r}, but it must be a non-empty list")
    unit = "force" if kind == "forces" else "length"
    out = tuple(quantity(f"{key}[{i}]", v, unit) for i, v in enumerate(values))
    for i, (given, value) in enumerate(zip(values, out, strict=True)):
        if value < 0.0 or (kind == "heights" and value == 0.0):
            bound = ">= 0 (the plate pushes)" if kind == "forces" else "> 0 (above the clamp plane)"
            raise InputError(f"{key}[{i}] = {given!r}, but it must be {bound}")
    return kind, out


def _solver(table, where) -> tuple[str, tuple]:
    name = table.get("name", "shooting")
    if name not in _OPTIONS:
        raise InputError(f"solver.name = {name!r}, but it must be one of {', '.join(sorted(_OPTIONS))}")
    options = []
    for key, value in table.items():
        if key == "name":
            continue
        kind = _OPTIONS[name].get(key)
        if kind is None:
            raise InputError(f"{where}: solver.{key} does not apply to solver.name = {name!r}")
        if not isinstance(value, _TYPES[kind]) or (kind is not bool and isinstance(value, bool)):
            raise InputError(f"solver.{key} = {value!r} is not a {kind.__name__}")
        if kind is not bool and not (math.isfinite(value) and value > 0):
            raise InputError(f"solver.{key} = {value!r}, but it must be > 0")
        options.append((key, value))
    return name, tuple(options)


def parse(data: dict, where: str = "case") -> Case:
    """A ``Case`` from the TOML table ``data``; ``where`` names it in error messages."""
    for section, value in data.items():
        if section not in _SECTIONS:
            raise InputError(f"{where}: unknown key '{section}' (known: {', '.join(_SECTIONS)})")
        keys = _SECTIONS[section]
        if keys is not None and isinstance(value, dict):
            for key in value:
                if key not in keys:
                    raise InputError(f"{where}: unknown key '{section}.{key}' (known: {', '.join(keys)})")
    name = data.get("name", where)
    if not isinstance(name, str):
        raise InputError(f"name = {name!r} is not a string")
    thickness, c1, c2 = _sheet(_table(data, "sheet", where), where)
    clamp = _table(data, "clamp", where)
    radius = positive("clamp.radius", _need(clamp, "radius", "clamp", where), "length")
    initial = _table(data, "initial", where)
    kind = _one_of(initial, ("pressure", "height", "volume"), "initial", where)
    value = positive(f"initial.{kind}", initial[kind], {"height": "length"}.get(kind, kind))
    load_kind, loads = _loads(_table(data, "loads", where), where)
    solver, options = _solver(_table(data, "solver", where) if "solver" in data else {}, where)
    return Case(name=name, thickness=thickness, c1=c1, c2=c2, radius=radius, initial=(kind, value),
                load_kind=load_kind, loads=loads, solver=solver, options=options)


def load(path) -> Case:
    """Read and check the case file ``path``."""
    path = pathlib.Path(path)
    try:
        data = tomllib.loads(path.read_text())
    except OSError as err:
        raise InputError(f"{path}: cannot read the case file ({err.strerror})") from None
    except tomllib.TOMLDecodeError as err:
        raise InputError(f"{path}: not valid TOML ({err})") from None
    return parse(data, where=str(path))


#: Table 1 of the paper: sample number -> sheet thickness
SAMPLES = {1: "0.25 mm", 2: "0.5 mm", 3: "0.8 mm", 4: "1.6 mm"}


def sample(number: int) -> Case:
    """Sample ``number`` (1-4) of the paper's Table 1, at P_I = 4.81275 kPa, forces 0-6 N (Fhat up to 0.99)."""
    if number not in SAMPLES:
        raise InputError(f"sample = {number!r}, but Table 1 has samples {', '.join(map(str, SAMPLES))}")
    data = {"name": f"sample {number}",
            "sheet": {"thickness": SAMPLES[number], "c1": "160 kPa", "c2": "47 kPa"},
            "clamp": {"radius": "20 mm"}, "initial": {"pressure": "4.81275 kPa"},
            "loads": {"forces": [f"{f} N" for f in (0, 0.5, 1, 2, 3, 4.5, 6)]}}
    return parse(data, where=f"sample {number}")
