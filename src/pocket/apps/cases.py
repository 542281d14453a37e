"""Case files: one pocket and its loads, in physical units (TOML).

    name = "sample 1"                    # optional
    label = "sample 1 at 4.8 kPa"        # optional, a longer description (reports)
    tags = ["headline"]                  # optional labels (the validation suite uses them)
    [sheet]
    thickness = "0.25 mm"
    material = "mooney-rivlin"           # optional: the default; or neo-hookean, yeoh, gent, ogden
    c1 = "160 kPa"                       # either c1 and c2 ...
    c2 = "47 kPa"
    # modulus = "1.242 MPa"              # ... or modulus E = 6 (1 + alpha) C1 and alpha = C2/C1
    # alpha = 0.29375
    # another law takes its own parameters, stresses with units (pocket.core.materials):
    # neo-hookean: mu;  yeoh: c10, c20, c30;  gent: mu and jm (a number);
    # ogden: mu = ["630 kPa", "1.2 kPa", "-10 kPa"] and exponents = [1.3, 5.0, -2.0]
    # prestretch = 1.1                   # optional: the sheet clamped stretched equibiaxially by 1.1
                                         # (default 1; thickness and parameters of the unstretched rubber)
    [fluid]                              # optional, default a liquid
    kind = "gas"                         # "liquid" or "gas"
    ambient = "101.325 kPa"              # gas only: ambient (absolute) pressure, default 101.325 kPa
    gamma = 1.0                          # gas only: polytropic exponent in [1, 5/3], default 1
    [clamp]
    radius = "20 mm"
    [initial]                            # exactly one of
    pressure = "4.8 kPa"                 # P_I, or height = "10 mm" (H0), or volume = "2 mL"
    [loads]                              # exactly one of
    forces = ["0 N", "0.5 N", "1 N"]     # forces F, or heights = ["9 mm", "8 mm"] (indenter heights H)
    [indenter]                           # optional, default the flat plate (pocket.apps.indentertable)
    shape = "sphere"                     # "plate", "sphere" with radius = "8 mm", or "profile" with
    radius = "8 mm"                      # file = "tip.csv" (relative to the case file's folder)
    [solver]                             # optional, default shooting
    name = "shooting"                    # or "fem", "analytical" or "solid", with that solver's options:
                                         # rtol (shooting); elements, mesh, order, penalty, augmented, tol (fem);
                                         # layers, elements, tol (solid: its thickness ratio T/R is
                                         # sheet.thickness / clamp.radius); a mesh file name is relative
                                         # to the case file's folder

A closed capsule squeezed between two parallel plates (``pocket.core.geometries.CAPSULE``) is the same case with
``geometry = "capsule"`` at the top and its radius in place of the clamp's::

    geometry = "capsule"                 # optional: "pocket" (default, the clamped sheet) or "capsule"
    [capsule]                            # a capsule's table, in place of [clamp]
    radius = "50 um"                     # R, the undeformed sphere's radius (the wall: sheet.thickness)

Its lengths are in units of R, its forces F on each plate; ``initial.height`` is the inflated capsule's pole
height above its equatorial plane (lambda R, half its height), ``initial.volume`` the whole capsule's, and
``loads.heights`` each plate's distance from the equatorial plane (half the gap between the plates). Only the
flat plates press a capsule; a solver or an indenter that does not pose it refuses the case in one line
before any work. A capsule may be uninflated, ``initial.pressure = "0 Pa"`` (or its radius as
``initial.height``): full of liquid at no pressure, or of a gas sealed at the ambient pressure. Its forces are
then given to the solvers as F / (E T R) (``pocket.apps.physical``), and a force short of the compression at
which its states start is listed as not reached.

The rubber and the fluid are read by ``pocket.apps.rubbers``. E = 3 mu_0 (mu_0 the
small-strain shear modulus; 6 (C1 + C2) for Mooney-Rivlin) makes pressures
dimensionless as Phat = P R / (E T), and a gas's ambient pressure as
Phat_atm = P_atm R / (E T).

The solver options and their checks come from the solver's record
(``pocket.core.solver``), the same that the command line's flags come from.

Values carry units (``pocket.core.units``); plain numbers are SI. Every problem
(unknown, missing or misplaced keys, wrong dimensions, impossible or absurd
values, a file that is not UTF-8 TOML, more than ``MAX_LOADS`` loads or a file
over ``tomlfiles.MAX_BYTES``) is a one-line ``InputError`` naming the key, raised before
any solver runs: the work a case can ask for is bounded. Lengths outside the sizes of a
pocket, or a sheet too thick for a membrane (T/R >= 0.5), are refused too; a plain length
above 1 m (probably meant in mm) or T/R above 0.1 is a warning the case carries
(``Case.warnings``, ``pocket.core.sizes``), and so does every row of its results.

A ``Case`` keeps the values as the user wrote them (``given``), so that results
quote ``"0.2 N"``, not 0.19999999999999998, and errors quote the user's value
and unit.

The four silicone samples of the paper's Table 1 are built in (``sample(n)``):
T = 0.25, 0.5, 0.8, 1.6 mm, C1 = 160 kPa, C2 = 47 kPa, R = 20 mm, at
P_I = 4.81275 kPa, inside Table 1's 2-5 kPa and the pressure of the paper's
figure 2 for sample 1 (Phat_I = 0.31).
"""

from __future__ import annotations

import dataclasses
import pathlib

from pocket.core.errors import InputError
from pocket.core.fluids import LIQUID, Fluid
from pocket.core.geometries import CAPSULE, DISC, GEOMETRIES, Geometry
from pocket.core.indenters import PLATE, Indenter
from pocket.core.inputs import check_volume, quote
from pocket.core.materials import LAWS, Material
from pocket.core.sizes import length_warnings, thin_sheet
from pocket.core.units import plain_warnings, positive, quantity

from . import indentertable
from .rubbers import PARAMETERS, fluid, sheet
from .solvers import SOLVERS, record
from .tomlfiles import read_toml

__all__ = ["EXAMPLES", "MAX_LOADS", "RADIUS_TABLES", "SAMPLES", "Case", "capsule_example", "example", "load", "parse",
           "sample", "uninflated_capsule_example"]

#: the option of a solver that models the sheet's thickness (``pocket.solid``): a case derives it from its sheet
THICKNESS_RATIO = "thickness_ratio"

#: most loads a case may list: a bound on the work a case can ask for (the file's size: ``tomlfiles``)
MAX_LOADS = 10_000

#: geometry -> the table that holds its radius R (``radius``): a pocket's clamp, a capsule's sphere
RADIUS_TABLES = {DISC.name: "clamp", CAPSULE.name: "capsule"}

_SECTIONS = {"name": None, "label": None, "tags": None, "geometry": None,
             "sheet": ("thickness", "material", *PARAMETERS, "modulus", "alpha", "prestretch"), "clamp": ("radius",),
             "capsule": ("radius",),
             "fluid": ("kind", "ambient", "gamma"),
             "initial": ("pressure", "height", "volume"), "loads": ("forces", "heights"),
             "indenter": indentertable.KEYS,
             "solver": ("name", *dict.fromkeys(o.name for s in SOLVERS.values() for o in s.options))}


@dataclasses.dataclass(frozen=True)
class Case:
    """A pocket in SI units: sheet, clamp, initial state and loads, with the solver to use.

    Read from a case file (``load``), a TOML table (``parse``) or the paper's Table 1 (``sample``); checked
    before any solver runs. A case keeps the values as the user wrote them, so that results quote ``"0.2 N"``,
    not 0.19999999999999998, and errors quote the user's value and unit.

    Attributes
    ----------
    name : str
        The case's name.
    thickness : float
        The sheet's thickness T, m.
    material : Material
        The rubber, its stresses in Pa.
    radius : float
        R, m: the clamp radius of a pocket, the radius of a capsule.
    initial : tuple
        ``("pressure", P_I)`` in Pa, ``("height", H0)`` in m or ``("volume", V)`` in m^3.
    load_kind : str
        ``"forces"`` (F in N) or ``"heights"`` (H in m: the indenter's lowest point above the clamp plane), or
        ``""`` for a case without loads (the validation suite chooses its own).
    loads : tuple of float
        The loads, SI.
    solver : str
        The solver's name; ``options`` its options, as (name, value) pairs.
    given : tuple
        Each physical key (``"sheet.thickness"``, ``"loads.forces[0]"``) -> the value as written (``as_given``).
    fluid : Fluid
        The fluid (a gas's ambient pressure in Pa).
    warnings : tuple of str
        About the inputs (a plain length that looks like millimetres, a thick sheet), one line each.
    indenter : Indenter
        What presses, dimensionless (lengths in units of the clamp radius).
    geometry : Geometry
        The membrane (``pocket.core.geometries``): the flat sheet clamped at R (``DISC``, the default) or the
        closed capsule of radius R (``CAPSULE``).

    Examples
    --------
    >>> from pocket.apps.cases import sample
    >>> case = sample(1)
    >>> print(case.thickness, case.radius, case.initial, case.load_kind, case.loads[:3])
    0.00025 0.02 ('pressure', 4812.75) forces (0.0, 0.5, 1.0)
    >>> print(case.alpha == 47 / 160, case.modulus, case.as_given("sheet.thickness"))
    True 1242000.0 0.25 mm
    """

    name: str
    thickness: float
    material: Material
    radius: float
    initial: tuple[str, float]
    load_kind: str = ""
    loads: tuple[float, ...] = ()
    solver: str = "shooting"
    options: tuple[tuple[str, object], ...] = ()
    label: str = ""
    tags: tuple[str, ...] = ()
    given: tuple[tuple[str, object], ...] = dataclasses.field(default=(), hash=False)  # values may be lists
    fluid: Fluid = LIQUID
    warnings: tuple[str, ...] = ()  # about the inputs: a plain length that looks like millimetres, a thick sheet
    indenter: Indenter = PLATE
    geometry: Geometry = DISC

    @property
    def radius_key(self) -> str:
        """The key that gives R: ``clamp.radius`` for a pocket, ``capsule.radius`` for a capsule."""
        return f"{RADIUS_TABLES[self.geometry.name]}.radius"

    @property
    def alpha(self) -> float | None:
        """C2 / C1 of a Mooney-Rivlin rubber (None for another law)."""
        return self.material["c2"] / self.material["c1"] if self.material.law == "mooney-rivlin" else None

    @property
    def modulus(self) -> float:
        """E = 3 mu_0, Pa (6 (C1 + C2) = 6 (1 + alpha) C1 for Mooney-Rivlin)."""
        if self.material.law == "mooney-rivlin":  # as it always was computed, to the last bit
            return 6.0 * (self.material["c1"] + self.material["c2"])
        return self.material.modulus

    def as_given(self, key: str):
        """The value of the physical ``key`` as the user wrote it (else None)."""
        return dict(self.given).get(key)

    def fields(self) -> dict:
        """The case as a flat JSON-ready dict: SI values, then the inputs as given.

        The rubber is ``material`` and its parameters, stresses in Pa (``c1_Pa``, ``c10_Pa``,
        Ogden's ``mu_Pa`` a list), numbers as they are (``jm``, ``exponents``), with ``modulus_Pa``
        (E = 3 mu_0) and, for Mooney-Rivlin, ``alpha``; the fluid is ``fluid`` and, for a gas,
        ``ambient_Pa`` and ``gamma``; the indenter is ``indenter`` (plate, sphere or profile) and a sphere's
        ``indenter_radius_m`` or a profile's ``indenter_file`` (``pocket.core.indenters.Indenter.columns``);
        ``geometry`` names the membrane (pocket or capsule) and ``radius_m`` is its R.
        """
        rubber: dict[str, object] = {"material": self.material.law}
        stresses = self.material.definition.stresses
        for name, value in self.material.describe().items():
            if name != "material":
                rubber[f"{name}_Pa" if name in stresses else name] = value
        rubber["modulus_Pa"] = self.modulus
        if self.alpha is not None:
            rubber["alpha"] = self.alpha
        fluid: dict[str, object] = {"fluid": self.fluid.kind}
        if self.fluid.is_gas:
            fluid.update(ambient_Pa=self.fluid.ambient, gamma=self.fluid.gamma)
        return {"name": self.name, "geometry": self.geometry.name, "thickness_m": self.thickness, **rubber,
                "radius_m": self.radius, **fluid,
                f"initial_{self.initial[0]}": self.initial[1], "load_kind": self.load_kind,
                "loads": list(self.loads), **self.indenter.columns(self.radius),
                "solver": self.solver, **dict(self.options),
                "given": dict(self.given), "warnings": list(self.warnings)}


def _table(data, section, where) -> dict:
    if section not in data:
        raise InputError(f"{where}: missing key '{section}'")
    table = data[section]
    if not isinstance(table, dict):
        raise InputError(f"{where}: '{section}' must be a table ([{section}]), got {quote(table)}")
    return table


def _one_of(table, keys, section, where) -> str:
    given = [k for k in keys if k in table]
    if len(given) != 1:
        names = " or ".join(f"'{section}.{k}'" for k in keys)
        raise InputError(f"{where}: missing key {names}" if not given else
                         f"{where}: give one of {names}, not {len(given)}")
    return given[0]


def _need(table, key, section, where):
    if key not in table:
        raise InputError(f"{where}: missing key '{section}.{key}'")
    return table[key]


def _loads(table, where, given) -> tuple[str, tuple[float, ...]]:
    kind = _one_of(table, ("forces", "heights"), "loads", where)
    values = table[kind]
    key = f"loads.{kind}"
    if not isinstance(values, list) or not values:
        raise InputError(f"{key} = {quote(values)}, but it must be a non-empty list")
    if len(values) > MAX_LOADS:
        raise InputError(f"{key} has {len(values)} values, but a case takes at most {MAX_LOADS}")
    unit = "force" if kind == "forces" else "length"
    out = []
    for i, value in enumerate(values):
        si = quantity(f"{key}[{i}]", value, unit)
        if si < 0.0 or (kind == "heights" and si == 0.0):
            bound = ">= 0 (the indenter pushes)" if kind == "forces" else "> 0 (above the clamp plane)"
            raise InputError(f"{key}[{i}] = {quote(value)}, but it must be {bound}")
        given[f"{key}[{i}]"] = value
        out.append(si)
    return kind, tuple(out)


def _solver(table, base, given) -> tuple[str, tuple]:
    """The solver's name and its options checked; a relative file name (a mesh) is relative to ``base``."""
    name = table.get("name", "shooting")
    if not isinstance(name, str) or name not in SOLVERS:
        raise InputError(f"solver.name = {quote(name)}, but it must be one of {', '.join(SOLVERS)}")
    solver = record(name)
    asked = {k: v for k, v in table.items() if k != "name"}
    given.update({f"solver.{k}": v for k, v in table.items()})
    for key, value in asked.items():
        option = solver.option(key)
        if option is not None and option.kind == "path" and isinstance(value, str) and base is not None:
            asked[key] = str(pathlib.Path(base) / value)  # an absolute value stays as it is
    options = solver.checked(asked, "compress", spell=lambda key: f"solver.{key}")
    return name, tuple(options.items())


def _thickness_ratio(solver: str, options: tuple, thickness: float, radius: float, given: dict,
                     radius_key: str = "clamp.radius") -> tuple:
    """``options`` with T/R = sheet.thickness / clamp.radius for a solver that models the thickness (an option
    ``THICKNESS_RATIO``); an InputError if the case gives that option itself: the sheet says it already."""
    option = record(solver).option(THICKNESS_RATIO)
    if option is None:
        return options
    if f"solver.{THICKNESS_RATIO}" in given:
        raise InputError(f"solver.{THICKNESS_RATIO} = {quote(given[f'solver.{THICKNESS_RATIO}'])}, but a case's "
                         f"thickness ratio is sheet.thickness / {radius_key} (leave solver.{THICKNESS_RATIO} out)")
    why = (f"sheet.thickness / {radius_key} = {quote(given['sheet.thickness'])} / {quote(given[radius_key])}")
    return (*options, (THICKNESS_RATIO, option.checked(thickness / radius, spell=lambda _: why)))


def _text(data, key, where) -> str:
    value = data.get(key, "")
    if not isinstance(value, str):
        raise InputError(f"{where}: {key} = {quote(value)}, but it must be a string")
    return value


def _tags(data, where) -> tuple[str, ...]:
    value = data.get("tags", [])
    if not isinstance(value, list) or not all(isinstance(t, str) for t in value):
        raise InputError(f"{where}: tags = {quote(value)}, but it must be a list of strings")
    return tuple(value)


#: the keys of a case that are stresses (every law's, and Mooney-Rivlin's modulus) or other pressures
_PRESSURES = {f"sheet.{n}" for law in LAWS.values() for n in law.stresses} | {"sheet.modulus", "fluid.ambient",
                                                                               "initial.pressure"}


def _quantities(given) -> list[tuple[str, object, str]]:
    """(key, value as written, kind) of every pressure, volume and force of a case (its lengths are
    ``_sizes``'s), one entry per element of a list."""
    out = []
    for key, value in given.items():
        kind = "pressure" if key in _PRESSURES else "volume" if key == "initial.volume" else \
            "force" if key.startswith("loads.forces[") else None
        if kind is not None:
            values = value if isinstance(value, list) else [value]
            out += [(f"{key}[{i}]" if isinstance(value, list) else key, v, kind) for i, v in enumerate(values)]
    return out


def _sizes(given, thickness, radius, initial, loads, membrane: bool, radius_key: str = "clamp.radius") -> list[str]:
    """The warnings on the case's plain numbers (``pocket.core.units.plain_warnings``) and, for a ``membrane``
    solver, its sheet's thinness (``pocket.core.sizes``; a solver that models the thickness checks its own T/R
    and speaks for itself); an
    ``InputError`` naming the key for a length no pocket has or a sheet too thick for a membrane."""
    lengths = [("sheet.thickness", thickness), (radius_key, radius)]
    if initial[0] == "height":
        lengths.append(("initial.height", initial[1]))
    if loads[0] == "heights":
        lengths += [(f"loads.heights[{i}]", h) for i, h in enumerate(loads[1])]
    warnings = [w for key, si in lengths for w in length_warnings(key, given[key], si)]
    warnings += [w for key, value, kind in _quantities(given) for w in plain_warnings(key, value, kind)]
    why = f"sheet.thickness = {quote(given['sheet.thickness'])} on {radius_key} = {quote(given[radius_key])}"
    return warnings + thin_sheet(thickness, radius, why) if membrane else warnings


def parse(data: dict, where: str = "case", *, require_loads: bool = True, base=None) -> Case:
    """A ``Case`` from a TOML table (a case file's content as a dict), checked.

    Parameters
    ----------
    data : dict
        The tables ``sheet``, ``clamp``, ``initial``, ``loads`` and the optional ``fluid``, ``indenter``,
        ``solver``, ``name``, ``label``, ``tags`` (``pocket.apps.cases``); values with units, as strings (plain
        numbers are SI, with a warning).
    where : str, optional
        The case's name in error messages.
    require_loads : bool, optional
        Without it the ``[loads]`` table is optional (a pocket without loads).
    base : str or path, optional
        The folder relative file names (a mesh, a profile) are relative to (the case file's; by default the
        current folder).

    Returns
    -------
    Case

    Raises
    ------
    InputError
        For unknown, missing or misplaced keys, wrong dimensions, impossible or absurd values, more than
        ``MAX_LOADS`` loads; one line naming the key.

    Examples
    --------
    >>> from pocket.apps.cases import parse
    >>> case = parse({"sheet": {"thickness": "0.25 mm", "c1": "160 kPa", "c2": "47 kPa"},
    ...               "clamp": {"radius": "20 mm"}, "initial": {"pressure": "4.8 kPa"},
    ...               "loads": {"forces": ["0.5 N", "1 N"]}})
    >>> print(case.loads, case.solver)
    (0.5, 1.0) shooting
    >>> parse({"sheet": {"thickness": "0.25 kPa", "c1": "160 kPa", "c2": "47 kPa"},
    ...        "clamp": {"radius": "20 mm"}, "initial": {"pressure": "4.8 kPa"}, "loads": {"forces": ["1 N"]}})
    Traceback (most recent call last):
        ...
    pocket.core.errors.InputError: sheet.thickness = '0.25 kPa' has dimension [mass] / [length] / [time] ** 2, ...
    """
    if not isinstance(data, dict):
        raise InputError(f"{where}: a case must be a table, got {quote(data)}")
    for section, value in data.items():
        if section not in _SECTIONS:
            raise InputError(f"{where}: unknown key '{section}' (known: {', '.join(_SECTIONS)})")
        keys = _SECTIONS[section]
        if keys is not None and isinstance(value, dict):
            for key in value:
                if key not in keys:
                    raise InputError(f"{where}: unknown key '{section}.{key}' (known: {', '.join(keys)})")
    name = _text(data, "name", where) or where
    given: dict = {}
    thickness, material = sheet(_table(data, "sheet", where), where, given)
    liquid_or_gas = fluid(_table(data, "fluid", where), given) if "fluid" in data else LIQUID
    geometry = _geometry(data, where)
    section = RADIUS_TABLES[geometry.name]
    clamp = _table(data, section, where)
    radius = positive(f"{section}.radius", _need(clamp, "radius", section, where), "length")
    given[f"{section}.radius"] = clamp["radius"]
    initial = _table(data, "initial", where)
    kind = _one_of(initial, ("pressure", "height", "volume"), "initial", where)
    value = _initial(kind, initial[kind], geometry)
    given[f"initial.{kind}"] = initial[kind]
    if kind == "volume":  # V/R^3 within the model's range before anything is solved
        check_volume("initial.volume", value / radius**3, f"{quote(initial[kind])} (V/R^3 = {value / radius**3:.3g})")
    load_kind = ""
    loads: tuple[float, ...] = ()
    if require_loads or "loads" in data:
        load_kind, loads = _loads(_table(data, "loads", where), where, given)
    pressing: list[str] = []  # the indenter's size warnings
    indenter = (indentertable.parse(data["indenter"], radius, base, given, warnings=pressing) if "indenter" in data
                else PLATE)
    solver, options = _solver(_table(data, "solver", where) if "solver" in data else {}, base, given)
    options = _thickness_ratio(solver, options, thickness, radius, given, f"{section}.radius")
    membrane = record(solver).option(THICKNESS_RATIO) is None
    warnings = _sizes(given, thickness, radius, (kind, value), (load_kind, loads), membrane,
                      f"{section}.radius") + pressing
    return Case(name=name, thickness=thickness, material=material, fluid=liquid_or_gas, radius=radius,
                initial=(kind, value), load_kind=load_kind, loads=loads, solver=solver, options=options,
                label=_text(data, "label", where), tags=_tags(data, where), given=tuple(given.items()),
                warnings=tuple(warnings), indenter=indenter, geometry=geometry)


def _initial(kind: str, value, geometry: Geometry) -> float:
    """The SI value of ``initial.<kind>``: > 0, or a capsule's pressure 0 (an uninflated capsule)."""
    if kind == "pressure" and geometry != DISC and quantity("initial.pressure", value, "pressure") == 0.0:
        return 0.0
    return positive(f"initial.{kind}", value, {"height": "length"}.get(kind, kind))


def _geometry(data, where) -> Geometry:
    """The case's ``geometry`` (default pocket); an InputError for another value, or for a radius table of another
    geometry (a capsule's ``[clamp]``, a pocket's ``[capsule]``)."""
    name = data.get("geometry", DISC.name)
    if not isinstance(name, str) or name not in GEOMETRIES:
        raise InputError(f"{where}: geometry = {quote(name)}, but it must be one of {', '.join(GEOMETRIES)}")
    own = RADIUS_TABLES[name]
    for kind, table in RADIUS_TABLES.items():
        if table != own and table in data:
            raise InputError(f"{where}: [{table}] holds a {kind}'s radius, but the case is a {name} (geometry = "
                             f"{quote(name)}), whose radius is [{own}] radius")
    return GEOMETRIES[name]


def load(path, *, require_loads: bool = True) -> Case:
    """Read and check a case file (TOML); file names in it are relative to its folder.

    Parameters
    ----------
    path : str or path
        The case file.
    require_loads : bool, optional
        As for ``parse``.

    Returns
    -------
    Case

    Raises
    ------
    InputError
        For a file that cannot be read, is not UTF-8 TOML or is too large, and as ``parse``.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from pocket.apps.cases import load
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = pathlib.Path(folder) / "button.toml"
    ...     _ = path.write_text('''
    ... [sheet]
    ... thickness = "1 mm"
    ... material = "neo-hookean"
    ... mu = "0.4 MPa"
    ... [clamp]
    ... radius = "10 mm"
    ... [initial]
    ... pressure = "20 kPa"
    ... [loads]
    ... forces = ["1 N"]
    ... [indenter]
    ... shape = "sphere"
    ... radius = "5 mm"
    ... ''')
    ...     case = load(path)
    >>> print(case.material.law, case.indenter)
    neo-hookean Sphere(radius=0.5)
    """
    return parse(read_toml(path), where=str(path), require_loads=require_loads, base=pathlib.Path(path).parent)


#: Table 1 of the paper: sample number -> sheet thickness
SAMPLES = {1: "0.25 mm", 2: "0.5 mm", 3: "0.8 mm", 4: "1.6 mm"}


def sample(number) -> Case:
    """Sample ``number`` of the paper's Table 1, at P_I = 4.81275 kPa, forces 0 to 6 N (Fhat up to 0.99).

    The four silicone sheets: T = 0.25, 0.5, 0.8, 1.6 mm (``SAMPLES``), C1 = 160 kPa, C2 = 47 kPa, R = 20 mm.

    Parameters
    ----------
    number : int
        1 to 4.

    Returns
    -------
    Case

    Raises
    ------
    InputError
        For another number.

    Examples
    --------
    Sample 1 at P_I = 4.81275 kPa is the headline pocket, Phat_I = P_I R / (E T) = 0.31:

    >>> from pocket.apps.cases import sample
    >>> case = sample(1)
    >>> print(round(case.initial[1] * case.radius / (case.modulus * case.thickness), 12))
    0.31
    """
    if isinstance(number, bool) or number not in SAMPLES:
        raise InputError(f"sample = {number!r}, but Table 1 has samples {', '.join(map(str, SAMPLES))}")
    data = {"name": f"sample {number}",
            "sheet": {"thickness": SAMPLES[number], "c1": "160 kPa", "c2": "47 kPa"},
            "clamp": {"radius": "20 mm"}, "initial": {"pressure": "4.81275 kPa"},
            "loads": {"forces": [f"{f} N" for f in (0, 0.5, 1, 2, 3, 4.5, 6)]}}
    return parse(data, where=f"sample {number}")


def capsule_example() -> Case:
    """A microcapsule squeezed between two plates: R = 50 um, a 0.5 um wall of a neo-Hookean rubber of
    mu = 1 MPa, filled with a liquid at P_I = 3 kPa, forces 0 to 20 uN on each plate.

    E = 3 mu = 3 MPa and T/R = 0.01, so Phat_I = P_I R / (E T) = 0.1, and Fhat = F / (P_I pi R^2) runs to about
    0.85 (P_I pi R^2 = 23.6 uN).

    Returns
    -------
    Case

    Examples
    --------
    >>> from pocket.apps.cases import capsule_example
    >>> case = capsule_example()
    >>> print(case.geometry.name, case.as_given("capsule.radius"), case.as_given("sheet.thickness"), case.radius_key)
    capsule 50 um 0.5 um capsule.radius
    >>> print(round(case.initial[1] * case.radius / (case.modulus * case.thickness), 12))
    0.1
    """
    data = {"name": "capsule", "label": "a 50 um microcapsule with a 0.5 um neo-Hookean wall, squeezed",
            "geometry": "capsule",
            "sheet": {"thickness": "0.5 um", "material": "neo-hookean", "mu": "1 MPa"},
            "capsule": {"radius": "50 um"}, "initial": {"pressure": "3 kPa"},
            "loads": {"forces": [f"{f} uN" for f in (0, 1, 2, 5, 10, 15, 20)]}}
    return parse(data, where="example capsule")


def uninflated_capsule_example() -> Case:
    """The microcapsule of ``capsule_example`` uninflated: full of liquid at P_I = 0, squeezed by 0 to 40 uN on each
    plate, solved by the finite elements (the faster route to an uninflated capsule's forces).

    E T R = 3 MPa x 0.5 um x 50 um = 75 uN, the unit its forces go to the solvers in (``pocket.apps.physical``):
    0.067 to 0.53 E T R, all past where its states start (0.064 E T R, a compression of 21 %).

    Returns
    -------
    Case

    Examples
    --------
    >>> from pocket.apps.cases import uninflated_capsule_example
    >>> case = uninflated_capsule_example()
    >>> print(case.initial, case.as_given("loads.forces[1]"), case.solver)
    ('pressure', 0.0) 5 uN fem
    """
    data = {"name": "uninflated capsule", "label": "a 50 um microcapsule with a 0.5 um neo-Hookean wall, uninflated, "
                                                   "squeezed", "geometry": "capsule",
            "sheet": {"thickness": "0.5 um", "material": "neo-hookean", "mu": "1 MPa"},
            "capsule": {"radius": "50 um"}, "initial": {"pressure": "0 Pa"},
            "loads": {"forces": [f"{f} uN" for f in (0, 5, 10, 20, 40)]}, "solver": {"name": "fem"}}
    return parse(data, where="example uninflated-capsule")


#: the built-in example cases besides Table 1's samples: name -> the function that builds it
EXAMPLES = {"capsule": capsule_example, "uninflated-capsule": uninflated_capsule_example}


def example(name) -> Case:
    """The built-in example case ``name`` (``EXAMPLES``).

    Parameters
    ----------
    name : str
        A key of ``EXAMPLES``.

    Returns
    -------
    Case

    Raises
    ------
    InputError
        For another name.

    Examples
    --------
    >>> from pocket.apps.cases import example
    >>> print(example("capsule").geometry.name)
    capsule
    """
    if not isinstance(name, str) or name not in EXAMPLES:
        raise InputError(f"example = {name!r}, but the built-in examples are {', '.join(EXAMPLES)}")
    return EXAMPLES[name]()
