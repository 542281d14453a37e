"""The rubber and fluid flags shared by ``inflate``, ``compress``, ``sweep`` and ``design``.

``--law NAME`` (default mooney-rivlin, which takes ``--alpha`` = C2/C1, as it always
did) and the law's parameters as flags, built from the registry of laws
(``pocket.core.materials.LAWS``: each parameter's help text, and one value or a list): ``--mu``
(neo-hookean, gent: one value; ogden: one per term), ``--c10 --c20 --c30`` (yeoh), ``--jm``
(gent, a number), ``--exponents`` (ogden, one per term). The stresses may be given in any one unit:
they are rescaled to units of mu_0 (so that mu_0 = 1), the unit of the model and
of every output, since only their ratios enter the dimensionless model
(``pocket.apps.rubbers.rubber``).

``--prestretch LAMBDA_P`` (default 1): the sheet clamped with an equibiaxial stretch already in it,
the law's parameters being those of the unstretched rubber (``Material.prestretch``).

``--fluid {liquid,gas}`` with, for a gas, ``--ambient`` and ``--gamma`` (default 1,
isothermal; at most 5/3). The dimensionless commands take the ambient pressure as
Phat_atm = P_atm R / (E T) (required with a gas: it depends on the pocket);
``design`` takes it as a pressure (default 101.325 kPa). A parameter that is not the
law's, a missing one, or a gas option without ``--fluid gas`` is a one-line error.
"""

from __future__ import annotations

from pocket.apps.rubbers import DEFAULT_LAW, FLUIDS, gas_of, prestretched, rubber
from pocket.core.errors import InputError
from pocket.core.fluids import AMBIENT
from pocket.core.inputs import check_positive
from pocket.core.materials import LAWS, mooney_rivlin
from pocket.core.units import quantity

from .common import number

__all__ = ["add_rubber_flags", "add_fluid_flags", "material_of", "fluid_of", "law_flags"]

_UNITS = ("stresses in any one unit, rescaled to units of mu_0 (mu_0 = 1: the unit of the model and of the "
          "output; only their ratios matter)")


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


def add_rubber_flags(parser, *, alphas: bool = False) -> None:
    """``--law``, ``--alpha`` (several values if ``alphas``: a sweep's axis) and the other laws' parameter
    flags, in one group, from the registry ``pocket.core.materials.LAWS``."""
    group = parser.add_argument_group("rubber", f"the strain-energy law and its parameters ({_UNITS})")
    group.add_argument("--law", choices=tuple(LAWS), default=DEFAULT_LAW,
                       help="strain-energy law of the rubber (default mooney-rivlin)")
    several = "; several values" if alphas else ""
    group.add_argument("--alpha", type=number, nargs="+" if alphas else None,
                       help=f"C2/C1 of the Mooney-Rivlin rubber, > -1 (fractions allowed: 47/160){several}; "
                       "required with --law mooney-rivlin, refused with another law")
    for name, uses in law_flags().items():
        listed = any(q.listed for _, q in uses)
        group.add_argument(_flag(name), type=number, nargs="+" if listed else None, metavar=name.upper(),
                           help=_help(uses))
    group.add_argument("--prestretch", type=number, metavar="LAMBDA_P",
                       help="equibiaxial stretch of the sheet as clamped, >= 1 (default 1: none); the law's "
                       "parameters and the thickness are the unstretched rubber's")


def material_of(args):
    """The rubber of the command line, a ``Material``: Mooney-Rivlin by its ``--alpha`` (``mooney_rivlin``,
    the one conversion), else the law's in units of mu_0, clamped with ``--prestretch`` if given; a sweep's
    several ``--alpha`` values stay a list of floats (its axis, converted by the sweep, ``--prestretch``
    checked here all the same)."""
    material = _unstretched(args)
    if isinstance(material, list):
        prestretched(mooney_rivlin(material[0]), getattr(args, "prestretch", None), "--prestretch")
        return material
    return prestretched(material, getattr(args, "prestretch", None), "--prestretch")


def _unstretched(args):
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
        params[name] = values
    return rubber(args.law, params, _flag)


def add_fluid_flags(parser, *, physical: bool) -> None:
    """``--fluid``, ``--ambient`` and ``--gamma``; ``physical``: the ambient is a pressure with a unit
    (default 101.325 kPa), else Phat_atm (required for a gas)."""
    group = parser.add_argument_group("fluid", "the fluid sealed in the pocket once it is inflated")
    group.add_argument("--fluid", choices=FLUIDS, default="liquid",
                       help="liquid (fixed volume) or an ideal gas, (P + P_atm) V^gamma fixed (default liquid)")
    if physical:
        group.add_argument("--ambient", help="gas only: ambient (absolute) pressure P_atm ('101.325 kPa', SI if "
                           "plain; default 101.325 kPa)")
    else:
        group.add_argument("--ambient", type=number, metavar="PHAT_ATM", help="gas only, required: ambient "
                           "(absolute) pressure as Phat_atm = P_atm R / (E T), E = 3 mu_0 (for air at 101.325 kPa "
                           "and the paper's sample 1, 6.53)")
    group.add_argument("--gamma", type=number, help="gas only: polytropic exponent in [1, 5/3]: 1 isothermal (slow), "
                       "1.4 air compressed adiabatically (fast) (default 1)")


def fluid_of(args, *, physical: bool):
    """The fluid of the command line: None for a liquid, else the gas (its ambient in Pa if ``physical``,
    else Phat_atm)."""
    if args.fluid == "liquid":
        extra = [name for name in ("ambient", "gamma") if getattr(args, name) is not None]
        if extra:
            raise InputError(f"--{extra[0]} applies to a gas: give --fluid gas")
        return None
    gamma = 1.0 if args.gamma is None else args.gamma
    if physical:
        ambient = AMBIENT if args.ambient is None else args.ambient
        return gas_of(quantity("--ambient", ambient, "pressure"), ambient, gamma, _flag)
    if args.ambient is None:
        raise InputError("--fluid gas needs --ambient PHAT_ATM, the ambient pressure P_atm R / (E T)")
    return gas_of(check_positive("--ambient", args.ambient), args.ambient, gamma, _flag)
