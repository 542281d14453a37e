"""The rubber and the fluid as users give them: case-file tables and command-line flags, checked.

A rubber is a law by name (``pocket.core.materials.LAWS``: mooney-rivlin, the
default, neo-hookean, yeoh, gent, ogden) with that law's parameters, and
nothing else. In a case file they are stresses with units (Ogden's ``mu`` a list
of stresses, ``exponents`` a list of numbers, Gent's ``jm`` a number); on the
command line they are numbers in any one stress unit (``rubber``), rescaled to
units of mu_0. Mooney-Rivlin keeps its own spellings: ``c1`` and ``c2`` (or
``modulus`` and ``alpha``) in a case file, ``--alpha`` on the command line, and
the solvers get ``mooney_rivlin`` of its alpha = C2/C1, solved by that alpha as it always was.

A sheet clamped with an equibiaxial prestretch lambda_p >= 1 already in it (``Material.prestretch``)
says so by ``prestretch`` in a case file's ``[sheet]`` table (a number, default 1: none) and
``--prestretch`` on the command line; the thickness and the law's parameters stay those of the
unstretched rubber.

A fluid is a liquid (the default) or an ideal gas with its ambient (absolute)
pressure P_atm > 0 and polytropic exponent gamma in [1, 5/3]
(``pocket.core.fluids``); a gas option given for a liquid is an error, not
ignored.

Every problem is a one-line ``InputError`` naming the key or flag as the user
spelled it (``spell``) and quoting the value.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

from pocket.core.errors import InputError
from pocket.core.fluids import AMBIENT, LIQUID, Fluid, gas
from pocket.core.inputs import check_alpha, check_finite, quote
from pocket.core.materials import LAWS, Material, check, check_prestretch
from pocket.core.units import positive, quantity

__all__ = ["DEFAULT_LAW", "FLUIDS", "PARAMETERS", "fluid", "gas_of", "law_name", "prestretched", "rubber", "sheet"]

DEFAULT_LAW = "mooney-rivlin"
#: every parameter name of every law, in order (c1, c2, mu, c10, c20, c30, jm, exponents)
PARAMETERS = tuple(dict.fromkeys(name for law in LAWS.values() for name in law.names))
#: the kinds of fluid
FLUIDS = ("liquid", "gas")
#: Mooney-Rivlin in a case file: c1 and c2, or modulus E = 6 (C1 + C2) and alpha = C2/C1
_MOONEY_RIVLIN = ("c1", "c2", "modulus", "alpha")
_WHERE = "sheet"  # the prefix pocket.core.materials.check gives parameter names


def law_name(law, spell: str = "sheet.material") -> str:
    """``law`` if it names a law of ``LAWS``."""
    if not isinstance(law, str) or law not in LAWS:
        raise InputError(f"{spell} = {quote(law)}, but it must be one of {', '.join(LAWS)}")
    return law


def _only(law: str, given, allowed, spell: Callable[[str], str], listed: str | None = None) -> None:
    """Every name of ``given`` is in ``allowed`` (the law's parameters; ``listed`` names them in the message,
    by default spelled as ``spell`` spells them)."""
    extra = [name for name in given if name not in allowed]
    if extra:
        listed = listed or ", ".join(map(spell, allowed))
        raise InputError(f"{spell(extra[0])} is not a parameter of the {law} law (its parameters: {listed})")


def rubber(law, params: dict, spell: Callable[[str], str] = lambda name: f"--{name}", *,
           scaled: bool = True) -> Material:
    """The rubber ``law`` with ``params`` (name -> number, a list of numbers for Ogden's mu and exponents),
    all stresses in one unit, checked and rescaled to units of mu_0 (mu_0 = 1), or left in their unit if
    not ``scaled`` (stresses in Pa, which set E = 3 mu_0).

    Only the ratios of the stresses enter the dimensionless model (Phat = P R / (E T), E = 3 mu_0 of these
    same parameters), so any unit gives the same rubber. Errors name a parameter as ``spell(name)``.
    """
    law = law_name(law, "--law")
    names = LAWS[law].names
    _only(law, params, names, spell)
    missing = [name for name in names if name not in params]
    if missing:
        raise InputError(f"{spell(missing[0])} is missing: the {law} law needs {', '.join(map(spell, names))}")
    try:
        material = check(law, params, _WHERE)
    except InputError as err:  # spelled as the user wrote the names
        raise InputError(_respelled(str(err), spell)) from None
    return material.scaled() if scaled else material


def _respelled(message: str, spell) -> str:
    for name in sorted({n for law in LAWS.values() for n in law.names}, key=len, reverse=True):
        message = message.replace(f"{_WHERE}.{name}", spell(name))
    return message.replace(f"{_WHERE}: ", "")


def _stress(key: str, value) -> float:
    """A stress as written, in Pa."""
    return quantity(key, value, "pressure")


def _number(key: str, value) -> float:
    """A dimensionless number as written (text is refused: it would carry a unit)."""
    if isinstance(value, str):
        raise InputError(f"{key} = {quote(value)} is not a number (it has no unit)")
    return check_finite(key, value)


def _mooney_rivlin(table, where, given) -> Material:
    """Today's two spellings: c1 and c2, or modulus and alpha (E = 6 (1 + alpha) C1)."""
    _only(DEFAULT_LAW, [k for k in table if k not in ("thickness", "material")], _MOONEY_RIVLIN,
          lambda name: f"sheet.{name}", "c1 and c2, or modulus and alpha")
    if "c1" in table or "c2" in table:
        if "modulus" in table or "alpha" in table:
            raise InputError(f"{where}: give either sheet.c1 and sheet.c2 or sheet.modulus and sheet.alpha")
        c1 = positive("sheet.c1", _need(table, "c1", where), "pressure")
        c2 = quantity("sheet.c2", _need(table, "c2", where), "pressure")
        given.update({"sheet.c1": table["c1"], "sheet.c2": table["c2"]})
        if not c2 / c1 > -1.0:
            raise InputError(f"sheet.c2 = {quote(table['c2'])}, but C2/C1 must be > -1")
        return Material(DEFAULT_LAW, (("c1", c1), ("c2", c2)))
    if "modulus" not in table and "alpha" not in table:
        raise InputError(f"{where}: missing key 'sheet.c1' (with 'sheet.c2') or 'sheet.modulus' (with 'sheet.alpha')")
    modulus = positive("sheet.modulus", _need(table, "modulus", where), "pressure")
    alpha = _need(table, "alpha", where)
    given.update({"sheet.modulus": table["modulus"], "sheet.alpha": alpha})
    if isinstance(alpha, str):
        raise InputError(f"sheet.alpha = {quote(alpha)} is not a number (C2/C1 has no unit)")
    try:
        alpha = check_alpha(alpha)
    except InputError as err:
        raise InputError(f"sheet.{err}") from None
    c1 = modulus / (6.0 * (1.0 + alpha))
    return Material(DEFAULT_LAW, (("c1", c1), ("c2", alpha * c1)))


def _need(table, key, where):
    if key not in table:
        raise InputError(f"{where}: missing key 'sheet.{key}'")
    return table[key]


def prestretched(material: Material, value, spell: str) -> Material:
    """``material`` clamped with the prestretch ``value`` (None: as it is), checked, errors naming ``spell``."""
    if value is None:
        return material
    return dataclasses.replace(material, prestretch=check_prestretch(value, material, spell))


def sheet(table: dict, where: str, given: dict) -> tuple[float, Material]:
    """The ``[sheet]`` table of a case: (thickness T in m, the rubber with its stresses in Pa, and its
    ``prestretch`` if given).

    ``given`` collects each key as written (``"sheet.c10": "85 kPa"``).
    """
    if "prestretch" in table:
        given["sheet.prestretch"] = table["prestretch"]
        table = {k: v for k, v in table.items() if k != "prestretch"}
        thickness, material = sheet(table, where, given)
        return thickness, prestretched(material, given["sheet.prestretch"], "sheet.prestretch")
    thickness = positive("sheet.thickness", _need(table, "thickness", where), "length")
    given["sheet.thickness"] = table["thickness"]
    law = law_name(table.get("material", DEFAULT_LAW))
    if "material" in table:
        given["sheet.material"] = law
    if law == DEFAULT_LAW:
        return thickness, _mooney_rivlin(table, where, given)
    params = {k: v for k, v in table.items() if k not in ("thickness", "material")}
    definition = LAWS[law]
    _only(law, params, definition.names, lambda name: f"sheet.{name}", ", ".join(definition.names))
    parsed = {}
    for name, value in params.items():
        listed = definition.parameter(name).listed and isinstance(value, list)
        parse = _stress if definition.parameter(name).unit == "stress" else _number
        parsed[name] = [parse(f"sheet.{name}[{i}]", v) for i, v in enumerate(value)] if listed else \
            parse(f"sheet.{name}", value)
        given[f"sheet.{name}"] = value
    return thickness, check(law, parsed, "sheet")


def gas_of(ambient_si: float, ambient_given, gamma, spell: Callable[[str], str]) -> Fluid:
    """A gas at the ambient pressure ``ambient_si`` (``ambient_given`` as the user wrote it) and ``gamma``."""
    if not ambient_si > 0.0:
        raise InputError(f"{spell('ambient')} = {quote(ambient_given)}, but the ambient (absolute) pressure "
                         "must be > 0")
    if isinstance(gamma, str):
        raise InputError(f"{spell('gamma')} = {quote(gamma)} is not a number (it has no unit)")
    try:
        return gas(ambient_si, gamma, "fluid")
    except InputError as err:
        raise InputError(str(err).replace("fluid.gamma", spell("gamma"))) from None


def fluid(table: dict, given: dict) -> Fluid:
    """The ``[fluid]`` table of a case (optional: a liquid), with its ambient pressure in Pa.

    ``kind`` is "liquid" (the default) or "gas"; a gas has ``ambient`` (a pressure, default the
    standard atmosphere, 101.325 kPa) and ``gamma`` (default 1, isothermal).
    """
    kind = table.get("kind", "liquid")
    if kind not in FLUIDS:
        raise InputError(f"fluid.kind = {quote(kind)}, but it must be one of {', '.join(FLUIDS)}")
    given.update({f"fluid.{k}": v for k, v in table.items()})
    if kind == "liquid":
        extra = [k for k in ("ambient", "gamma") if k in table]
        if extra:
            raise InputError(f"fluid.{extra[0]} applies to a gas (fluid.kind = 'gas'), not to a liquid")
        return LIQUID
    ambient = table.get("ambient", AMBIENT)
    return gas_of(quantity("fluid.ambient", ambient, "pressure"), ambient, table.get("gamma", 1.0),
                  lambda name: f"fluid.{name}")
