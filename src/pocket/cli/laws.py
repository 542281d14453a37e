"""The rubber and fluid flags shared by ``inflate``, ``compress``, ``sweep`` and ``design``.

``--law NAME`` (default mooney-rivlin, which takes ``--alpha`` = C2/C1, as it always
did) and the law's parameters as flags, built from the registry of laws
(``pocket.core.materials.LAWS``: each parameter's help text, and one value or a list): ``--mu``
(neo-hookean, gent: one value; ogden: one per term), ``--c10 --c20 --c30`` (yeoh), ``--jm``
(gent, a number), ``--exponents`` (ogden, one per term). In the commands of the model's units the
stresses are numbers in any one unit (a value with a unit is refused): they are rescaled to units of
mu_0 (so that mu_0 = 1), the unit of the model and of every output, since only their ratios enter
the dimensionless model (``pocket.apps.rubbers.rubber``). In ``design``, which works in physical units,
each stress carries its unit ('20 kPa'; a plain number is Pa, with a warning) and they set E = 3 mu_0.

``--prestretch LAMBDA_P`` (default 1): the sheet clamped with an equibiaxial stretch already in it,
the law's parameters being those of the unstretched rubber (``Material.prestretch``).

``--fluid {liquid,gas}`` with, for a gas, ``--ambient`` and ``--gamma`` (default 1,
isothermal; at most 5/3). The dimensionless commands take the ambient pressure as
Phat_atm = P_atm R / (E T) (required with a gas: it depends on the pocket);
``design`` takes it as a pressure (default 101.325 kPa). A parameter that is not the
law's, a missing one, or a gas option without ``--fluid gas`` is a one-line error.
"""

from __future__ import annotations

from collections.abc import Callable

from pocket.apps.rubbers import DEFAULT_LAW, FLUIDS, gas_of, prestretched, rubber
from pocket.core.errors import InputError
from pocket.core.fluids import AMBIENT
from pocket.core.inputs import check_positive
from pocket.core.materials import LAWS, mooney_rivlin
from pocket.core.units import plain_warnings, quantity

from .common import model_value, number, physical_help

__all__ = ["add_fluid_flags", "add_rubber_flags", "fluid_of", "law_flags", "material_of"]

_UNITS = ("stresses in any one unit, rescaled to units of mu_0 (mu_0 = 1: the unit of the model and of the "
          "output; only their ratios matter)")
_PHYSICAL = ("each stress with its unit, setting E = 3 mu_0; rescaled to units of mu_0 in the output")
#: what a stress flag of a command in the model's units takes
_MODEL_STRESS = "a stress in any one unit shared by the law's stresses (only their ratios count)"


def _flag(name: str) -> str:
    return f"--{name}"


def law_flags() -> dict[str, list]:
    """The parameter flags of the registered laws other than Mooney-Rivlin (which takes --alpha): each
    parameter name -> the (law, ``Parameter``) pairs that use it, in the registry's order."""
    flags: dict[str, list] = {}
    for law in LAWS.values():
        if law.name != DEFAULT_LAW:
            for q in law.parameters:
                flags.setdefault(q.name, []).append((law.name, q))
    return flags


def _help(uses) -> str:
    """A flag's help from its parameters' help texts, each with the laws it serves."""
    texts: dict[str, list] = {}
    for law, q in uses:
        texts.setdefault(q.help, []).append(law)
    return "; ".join(f"{text} ({', '.join(laws)})" for text, laws in texts.items())


def add_rubber_flags(parser, *, command: str | None = None, alphas: bool = False) -> None:
    """``--law``, ``--alpha`` (several values if ``alphas``: a sweep's axis) and the other laws' parameter
    flags, in one group, from the registry ``pocket.core.materials.LAWS``. ``command``: the name of a command
    in the model's units (its stresses numbers in any one unit), None for ``design`` (stresses with units)."""
    group = parser.add_argument_group("rubber", "the strain-energy law and its parameters "
                                      f"({_UNITS if command else _PHYSICAL})")
    group.add_argument("--law", choices=tuple(LAWS), default=DEFAULT_LAW,
                       help="strain-energy law of the rubber (default mooney-rivlin)")
    several = "; several values" if alphas else ""
    group.add_argument("--alpha", type=number, nargs="+" if alphas else None,
                       help=f"C2/C1 of the Mooney-Rivlin rubber, > -1 (fractions allowed: 47/160){several}; "
                       "required with --law mooney-rivlin, refused with another law")
    for name, uses in law_flags().items():
        listed = any(q.listed for _, q in uses)
        kind: Callable[[str], object]  # how the flag's text is read: a number, a stress in the model's units, text
        if uses[0][1].unit != "stress":
            kind, unit = number, "a number"
        elif command:
            kind, unit = model_value(command, _MODEL_STRESS), _MODEL_STRESS
        else:
            kind, unit = str, physical_help("pressure", "20 kPa", noun="stress")
        text = _help(uses)
        group.add_argument(_flag(name), type=kind, nargs="+" if listed else None, metavar=name.upper(),
                           help=text if unit in text else f"{text}: {unit}")
    group.add_argument("--prestretch", type=number, metavar="LAMBDA_P",
                       help="equibiaxial stretch of the sheet as clamped, from 1 to 10 (default 1: none); the law's "
                       "parameters and the thickness are the unstretched rubber's")


def material_of(args, warnings: list | None = None):
    """The rubber of the command line, a ``Material``: Mooney-Rivlin by its ``--alpha`` (``mooney_rivlin``,
    the one conversion), else the law's in units of mu_0, clamped with ``--prestretch`` if given; a sweep's
    several ``--alpha`` values stay a list of floats (its axis, converted by the sweep, ``--prestretch``
    checked here all the same).

    ``warnings``: given for a command in physical units, whose stress flags are text with units; the law's
    stresses are then in Pa (not rescaled: they set E), and a line per plain stress is appended to it."""
    material = _unstretched(args, warnings)
    if isinstance(material, list):
        prestretched(mooney_rivlin(material[0]), getattr(args, "prestretch", None), "--prestretch")
        return material
    return prestretched(material, getattr(args, "prestretch", None), "--prestretch")


def _unstretched(args, warnings):
    """``material_of`` before its prestretch."""
    given = {name: getattr(args, name) for name in law_flags() if getattr(args, name, None) is not None}
    if args.law == DEFAULT_LAW:
        if given:
            first = next(iter(given))
            raise InputError(f"--{first} is not a parameter of the mooney-rivlin law (it takes --alpha; choose "
                             "another law with --law)")
        if args.alpha is None:
            raise InputError("--alpha is missing: the mooney-rivlin law (the default --law) needs it")
        return args.alpha if isinstance(args.alpha, list) else mooney_rivlin(args.alpha)
    definition = LAWS[args.law]
    if args.alpha is not None:
        raise InputError(f"--alpha is not a parameter of the {args.law} law (its parameters: "
                         f"{', '.join(map(_flag, definition.names))})")
    params = {}
    for name, values in given.items():
        if isinstance(values, list) and not (name in definition.names and definition.parameter(name).listed):
            if len(values) != 1:
                raise InputError(f"--{name} takes one value for the {args.law} law, got {len(values)}")
            values = values[0]
        params[name] = values if warnings is None else _stresses(name, values, warnings)
    return rubber(args.law, params, _flag, scaled=warnings is None)


def _stresses(name: str, values, warnings: list):
    """The stress flag ``--name``'s ``values`` (text, or a list of text) in Pa, a warning appended per plain one;
    a dimensionless flag's numbers as they are."""
    if not any(q.unit == "stress" for _, q in law_flags()[name]):
        return values
    texts = values if isinstance(values, list) else [values]
    keys = [_flag(name)] if len(texts) == 1 else [f"{_flag(name)}[{i}]" for i in range(len(texts))]
    si = [quantity(key, text, "pressure") for key, text in zip(keys, texts, strict=True)]
    warnings.extend(w for key, text in zip(keys, texts, strict=True) for w in plain_warnings(key, text, "pressure"))
    return si if isinstance(values, list) else si[0]


def add_fluid_flags(parser, *, command: str | None = None) -> None:
    """``--fluid``, ``--ambient`` and ``--gamma``; ``command``: the name of a command in the model's units (the
    ambient as Phat_atm, required for a gas), None for ``design`` (a pressure with a unit, default 101.325 kPa)."""
    group = parser.add_argument_group("fluid", "the fluid sealed in the pocket once it is inflated")
    group.add_argument("--fluid", choices=FLUIDS, default="liquid",
                       help="liquid (fixed volume) or an ideal gas, (P + P_atm) V^gamma fixed (default liquid)")
    if command is None:
        group.add_argument("--ambient", metavar="PRESSURE", help="gas only: ambient (absolute) pressure P_atm, "
                           f"{physical_help('pressure', '101.325 kPa')} (default 101.325 kPa)")
    else:
        group.add_argument("--ambient", type=model_value(command, "Phat_atm = P_atm R / (E T)"), metavar="PHAT_ATM",
                           help="gas only, required: ambient (absolute) pressure as Phat_atm = P_atm R / (E T), "
                           "E = 3 mu_0 (for air at 101.325 kPa and the paper's sample 1, 6.53)")
    group.add_argument("--gamma", type=number, help="gas only: polytropic exponent in [1, 5/3]: 1 isothermal (slow), "
                       "1.4 air compressed adiabatically (fast) (default 1)")


def fluid_of(args, warnings: list | None = None):
    """The fluid of the command line: None for a liquid, else the gas: its ambient in Pa for a command in
    physical units, which gives ``warnings`` (a line appended for a plain ``--ambient``), else Phat_atm."""
    if args.fluid == "liquid":
        extra = [name for name in ("ambient", "gamma") if getattr(args, name) is not None]
        if extra:
            raise InputError(f"--{extra[0]} applies to a gas: give --fluid gas")
        return None
    gamma = 1.0 if args.gamma is None else args.gamma
    if warnings is not None:
        if args.ambient is None:
            return gas_of(AMBIENT, AMBIENT, gamma, _flag)
        found = gas_of(quantity("--ambient", args.ambient, "pressure"), args.ambient, gamma, _flag)
        warnings.extend(plain_warnings("--ambient", args.ambient, "pressure"))
        return found
    if args.ambient is None:
        raise InputError("--fluid gas needs --ambient PHAT_ATM, the ambient pressure P_atm R / (E T)")
    return gas_of(check_positive("--ambient", args.ambient), args.ambient, gamma, _flag)
