"""What a user asks a fit: from the command line's flags or from a case file with a ``[fit]`` table.

A case file names the data instead of the flags (TOML, read as ``pocket.apps.cases`` reads a case):

    [sheet]
    material = "yeoh"                    # the law to fit (default mooney-rivlin)
    thickness = "1 mm"                   # optional: without it stresses are fitted times T (N/m)
    # prestretch = 1.1                   # optional: held at this value (default 1)
    [clamp]
    radius = "20 mm"
    [initial]                            # optional: the initial pressure of the compression tests
    pressure = "5 kPa"
    [fit]
    data = ["bulge.csv", "press.csv"]    # the tests, relative to the case file's folder
    terms = 2                            # optional: Ogden's terms (default 1)
    fix = {c30 = "0 kPa"}                # optional: parameters held, named and written as --fix takes them
    sigma = {height = "0.02 mm"}         # optional: a column's measurement uncertainty, as --sigma
    prestretch = true                    # optional: also fit the prestretch (default false)
    [solver]                             # optional: "shooting" (default) or "fem"
    name = "fem"

The law's parameters are what the fit finds, so ``[sheet]`` names none (``[fit] fix`` holds some).
Every problem is a one-line ``InputError`` naming the key, before any file of data is read; a case
file without ``[fit]`` says that ``pocket fit`` needs one. A dimensional value written without a unit,
in a case file or on the command line, is read as SI and said so (``pocket.core.units.plain_warnings``:
``Request.warnings``); the data read then bound what such a value can be (``pocket.apps.fit.checks``).
"""

from __future__ import annotations

import dataclasses
import pathlib
from collections.abc import Callable

from pocket.core.errors import InputError
from pocket.core.inputs import quote
from pocket.core.units import plain_warnings, positive, quantity

from ..rubbers import DEFAULT_LAW, law_name
from ..tomlfiles import read_toml
from . import capsuledata, checks
from .data import CONTROLS, QUANTITIES, read
from .keys import PRESTRETCH, key_named, keys
from .model import Setup
from .start import MAX_TERMS

__all__ = ["Request", "held", "load", "parse", "uncertainties", "unit_warnings"]

_SECTIONS = {"name": None, "label": None, "sheet": ("material", "thickness", "prestretch"), "clamp": ("radius",),
             "initial": ("pressure",), "fit": ("data", "terms", "fix", "sigma", "prestretch"), "solver": ("name",)}
_SOLVERS = ("shooting", "fem")


@dataclasses.dataclass(frozen=True)
class Request:
    r"""A fit asked for, from the command line's flags or a case file's ``[fit]`` table (``load``).

    Attributes
    ----------
    data : tuple of pathlib.Path
        The tests' CSV files (``pocket.apps.fit.data.read``).
    law : str
        The law to fit (``pocket.core.materials.LAWS``); ``terms`` its Ogden terms.
    radius : float
        The clamp radius R, m.
    thickness : float or None
        The sheet's thickness T, m; None: stresses are fitted times T, in N/m.
    initial_pressure : float or None
        The compression tests' P_I, Pa (None: each test's zero-force row).
    fixed : dict
        The keys held, name -> value (stresses in Pa).
    sigma : dict
        The columns' stated uncertainties, column -> SI value (a column not named has relative residuals).
    prestretch : bool
        Whether to fit the clamped sheet's prestretch.
    solver : str
        The solver by name, ``"shooting"`` or ``"fem"``.
    warnings : tuple of str
        On its inputs, one line each (a value without a unit).
    case : str or None
        The case file it was read from (None: the command line's flags).
    geometry : {"pocket", "capsule"}
        The clamped sheet's tests (``pocket.apps.fit.data``), or a closed capsule's between two plates
        (``pocket.apps.fit.capsuledata``: ``radius`` is then the capsule's, ``initial_pressure`` its P_I).
    fit_initial_pressure : bool
        Whether a capsule's fit also fits P_I (``initial_pressure`` is then its start).

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from pocket.apps.fit.case import Request
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = pathlib.Path(folder) / "bulge.csv"
    ...     _ = path.write_text("pressure [kPa],height [mm]\n6,6.04\n12,8.13\n18,10.0\n")
    ...     setup = Request((path,), "neo-hookean", 0.020, 0.001).setup()
    >>> print(setup.count, setup.radius, setup.thickness)
    3 0.02 0.001
    """

    data: tuple[pathlib.Path, ...]
    law: str = DEFAULT_LAW
    radius: float = 0.0
    thickness: float | None = None
    initial_pressure: float | None = None
    terms: int = 1
    fixed: dict = dataclasses.field(default_factory=dict)
    sigma: dict = dataclasses.field(default_factory=dict)
    prestretch: bool = False
    solver: str = "shooting"
    warnings: tuple[str, ...] = ()
    case: str | None = None
    geometry: str = "pocket"
    fit_initial_pressure: bool = False

    def setup(self) -> Setup:
        """The tests read (``pocket.apps.fit.data.read``, a capsule's ``pocket.apps.fit.capsuledata.read``) and
        what the fit compares; bad data, or data that make a unit absurd (``pocket.apps.fit.checks.check``,
        ``pocket.apps.fit.capsuledata.check``), is an InputError."""
        capsule = self.geometry == "capsule"
        tests = tuple(capsuledata.read(path) if capsule else read(path, self.initial_pressure) for path in self.data)
        spell = _spelling("--sigma" if self.case is None else "fit.sigma")
        for name in self.sigma:
            if any(name in t.responses for t in tests):
                continue
            controlled = sorted({t.kind for t in tests if CONTROLS[t.kind] == name})
            if controlled:
                raise InputError(f"{spell(name)}: {name} is the controlled variable of {' and '.join(controlled)} "
                                 f"tests (the model is solved at each {name} given), so it has no residual for an "
                                 "uncertainty to weight")
            raise InputError(f"{spell(name)}: an uncertainty for {name} is stated, but no test has {name} data")
        setup = Setup(tests, self.radius, self.thickness, self.solver, {}, self.sigma)
        if capsule:
            capsuledata.check(setup, spell)
        else:
            checks.check(setup, spell, slack=not self.prestretch and self.fixed.get(PRESTRETCH, 1.0) == 1.0)
        return setup


def _spelling(flag: str) -> Callable[[str], str]:
    """How a key under ``flag`` is named in errors: ``--fix c1`` on the command line, ``fit.fix.c1`` in a file."""
    return (lambda name: f"{flag} {name}") if flag.startswith("--") else (lambda name: f"{flag}.{name}")


def held(law: str, terms: int, given: dict, thickness: float | None, flag: str) -> dict:
    """The keys of ``given`` (key name -> value as written: a stress with its unit, a number plain) in SI, each
    checked against the law's keys; ``flag`` names them in errors (``--fix``, ``fit.fix``)."""
    all_keys, spell = keys(law, terms), _spelling(flag)
    out = {}
    for name, value in given.items():
        key = key_named(all_keys, name, flag)
        if key.unit == "stress":
            if thickness is None:
                raise InputError(f"{spell(name)} = {quote(value)}: a stress can be held only with a thickness "
                                 "(without it the fit works with stress * T)")
            out[name] = quantity(spell(name), value, "pressure")
        elif isinstance(value, bool) or not isinstance(value, (int, float, str)):
            raise InputError(f"{spell(name)} = {quote(value)} is not a number")
        else:
            try:
                out[name] = float(value)
            except ValueError:
                raise InputError(f"{spell(name)} = {quote(value)} is not a number") from None
    return out


def uncertainties(given: dict, flag: str, quantities: dict = QUANTITIES) -> dict:
    """The columns' stated uncertainties of ``given`` (column -> value with its unit) in SI; ``flag`` names them
    in errors (``--sigma``, ``fit.sigma``); ``quantities`` the columns the tests may have, with their kinds (a
    capsule's: ``pocket.apps.fit.capsuledata.QUANTITIES``)."""
    out, spell = {}, _spelling(flag)
    for name, value in given.items():
        if name not in quantities:
            raise InputError(f"{spell(name)}: not a column of test data ({', '.join(quantities)})")
        out[name] = positive(spell(name), value, quantities[name])
    return out


def unit_warnings(law: str, terms: int, values: dict, fix: dict, fix_flag: str, sigma: dict,
                  sigma_flag: str, quantities: dict = QUANTITIES) -> tuple[str, ...]:
    """The warnings on a fit's dimensional inputs written without a unit (``pocket.core.units.plain_warnings``):
    ``values`` (key -> (value as written or None, kind)), the stresses held by ``fix`` and the uncertainties
    ``sigma`` (name -> value as written, already checked by ``held`` and ``uncertainties``; their columns' kinds in
    ``quantities``), named with ``fix_flag`` and ``sigma_flag``."""
    all_keys, spell_fix, spell_sigma = keys(law, terms), _spelling(fix_flag), _spelling(sigma_flag)
    given = [(key, value, kind) for key, (value, kind) in values.items() if value is not None]
    given += [(spell_fix(name), value, "pressure") for name, value in fix.items()
              if key_named(all_keys, name, fix_flag).unit == "stress"]
    given += [(spell_sigma(name), value, quantities[name]) for name, value in sigma.items()]
    return tuple(w for key, value, kind in given for w in plain_warnings(key, value, kind))


def _table(data: dict, section: str, where: str, required: bool = True) -> dict:
    if section not in data:
        if required:
            raise InputError(f"{where}: missing table [{section}]" if section != "fit" else
                             f"{where}: no [fit] table, so no data to fit: name the tests in it "
                             "(data = [\"bulge.csv\"]) or give the CSV files and --radius on the command line")
        return {}
    table = data[section]
    if not isinstance(table, dict):
        raise InputError(f"{where}: '{section}' must be a table ([{section}]), got {quote(table)}")
    return table


def _keys(data: dict, where: str) -> None:
    for section, value in data.items():
        if section not in _SECTIONS:
            raise InputError(f"{where}: '{section}' is not a key of a fit's case file (known: {', '.join(_SECTIONS)})")
        allowed = _SECTIONS[section]
        if allowed is None or not isinstance(value, dict):
            continue
        for key in value:
            if key not in allowed:
                hint = " (the fit finds the law's parameters: hold one with [fit] fix)" if section == "sheet" else ""
                raise InputError(f"{where}: unknown key '{section}.{key}' (known: {', '.join(allowed)}){hint}")


def _data(table: dict, base: pathlib.Path) -> tuple[pathlib.Path, ...]:
    files = table.get("data")
    if not isinstance(files, list) or not files or not all(isinstance(f, str) and f for f in files):
        raise InputError(f"fit.data = {quote(files)}, but it must be a non-empty list of CSV file names")
    return tuple(base / f for f in files)


def _terms(table: dict) -> int:
    terms = table.get("terms", 1)
    if isinstance(terms, bool) or not isinstance(terms, int) or not 1 <= terms <= MAX_TERMS:
        raise InputError(f"fit.terms = {quote(terms)}, but it must be a whole number from 1 to {MAX_TERMS}")
    return terms


def _mapping(table: dict, key: str) -> dict:
    value = table.get(key, {})
    if not isinstance(value, dict):
        raise InputError(f"fit.{key} = {quote(value)}, but it must be a table ({key} = {{name = value}})")
    return value


def parse(data: dict, where: str = "case", base=None) -> Request:
    """The ``Request`` of the case table ``data`` (module docstring); ``base`` the folder the data files are
    relative to (the case file's; by default the current folder)."""
    if not isinstance(data, dict):
        raise InputError(f"{where}: a case must be a table, got {quote(data)}")
    fit_table = _table(data, "fit", where)
    _keys(data, where)
    sheet = _table(data, "sheet", where, required=False)
    law = law_name(sheet.get("material", DEFAULT_LAW))
    thickness = positive("sheet.thickness", sheet["thickness"], "length") if "thickness" in sheet else None
    clamp = _table(data, "clamp", where)
    if "radius" not in clamp:
        raise InputError(f"{where}: missing key 'clamp.radius'")
    radius = positive("clamp.radius", clamp["radius"], "length")
    initial = _table(data, "initial", where, required=False)
    pressure = positive("initial.pressure", initial["pressure"], "pressure") if "pressure" in initial else None
    terms = _terms(fit_table)
    fixed = held(law, terms, _mapping(fit_table, "fix"), thickness, "fit.fix")
    fit_prestretch = fit_table.get("prestretch", False)
    if not isinstance(fit_prestretch, bool):
        raise InputError(f"fit.prestretch = {quote(fit_prestretch)}, but it must be true or false")
    if "prestretch" in sheet:
        if fit_prestretch or PRESTRETCH in fixed:
            raise InputError(f"sheet.prestretch = {quote(sheet['prestretch'])} holds the prestretch that "
                             f"{'fit.prestretch fits' if fit_prestretch else 'fit.fix holds too'}: give one of them")
        fixed[PRESTRETCH] = held(law, terms, {PRESTRETCH: sheet["prestretch"]}, thickness, "sheet")[PRESTRETCH]
    solver = _table(data, "solver", where, required=False).get("name", "shooting")
    if solver not in _SOLVERS:
        raise InputError(f"solver.name = {quote(solver)}, but a fit's solver is one of {', '.join(_SOLVERS)}")
    sigma = _mapping(fit_table, "sigma")
    sigma_si = uncertainties(sigma, "fit.sigma")
    warnings = unit_warnings(law, terms, {"clamp.radius": (clamp["radius"], "length"),
                                          "sheet.thickness": (sheet.get("thickness"), "length"),
                                          "initial.pressure": (initial.get("pressure"), "pressure")},
                             _mapping(fit_table, "fix"), "fit.fix", sigma, "fit.sigma")
    return Request(_data(fit_table, pathlib.Path(base or ".")), law, radius, thickness, pressure, terms, fixed,
                   sigma_si, fit_prestretch, solver, warnings, where)


def load(path) -> Request:
    """The fit a case file asks for: its ``[fit]`` table, checked before any data is read.

    Parameters
    ----------
    path : str or path
        The case file (TOML); the data files are relative to its folder.

    Returns
    -------
    Request

    Raises
    ------
    InputError
        For a file that cannot be read, a case without ``[fit]``, unknown or misplaced keys, values of the wrong
        dimension; one line naming the key.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from pocket.apps.fit.case import load
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = pathlib.Path(folder) / "fit.toml"
    ...     _ = path.write_text('''
    ... [sheet]
    ... material = "yeoh"
    ... thickness = "1 mm"
    ... [clamp]
    ... radius = "20 mm"
    ... [fit]
    ... data = ["bulge.csv"]
    ... fix = {c30 = "0 kPa"}
    ... ''')
    ...     request = load(path)
    >>> print(request.law, request.radius, request.fixed, [p.name for p in request.data])
    yeoh 0.02 {'c30': 0.0} ['bulge.csv']
    """
    return parse(read_toml(path), where=str(path), base=pathlib.Path(path).parent)
