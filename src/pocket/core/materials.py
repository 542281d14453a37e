r"""Incompressible hyperelastic rubbers: the one shared definition of each strain-energy law.

A law is its strain energy W per unit reference volume as a function of the
principal stretches, with lambda_3 = 1 / (lambda_1 lambda_2) (incompressible):

    I1 = l1^2 + l2^2 + l3^2,    I2 = l1^-2 + l2^-2 + l3^-2.

=============  ==========================================================  ============  =====================
law            W                                                           parameters    mu_0
=============  ==========================================================  ============  =====================
mooney-rivlin  C1 (I1 - 3) + C2 (I2 - 3)                                   c1, c2        2 (C1 + C2)
neo-hookean    (mu / 2) (I1 - 3)                                           mu            mu
yeoh           C10 (I1 - 3) + C20 (I1 - 3)^2 + C30 (I1 - 3)^3              c10, c20, c30 2 C10
gent           -(mu Jm / 2) ln(1 - (I1 - 3) / Jm)                          mu, jm        mu
ogden          sum_p (mu_p / alpha_p) (l1^alpha_p + l2^alpha_p + l3^alpha_p - 3)  mu, exponents  (1/2) sum mu_p alpha_p
=============  ==========================================================  ============  =====================

mu_0 is the small-strain shear modulus and E = 3 mu_0 the small-strain Young's
modulus, which makes the model's pressure dimensionless as Phat = P R / (E T)
for every law (for Mooney-Rivlin E = 6 (C1 + C2), as in the paper).

Conventions differ between codes. Here the Ogden law is written as Ogden did,
with stresses mu_p and mu_0 = (1/2) sum mu_p alpha_p. Abaqus writes the same
energy as sum 2 mu_i / alpha_i^2 (...), so its mu_i = mu_p alpha_p / 2 (and
mu_0 = sum mu_i); FEBio writes sum c_i / m_i^2 (...), so its c_i = mu_p alpha_p.
Convert before entering another code's fit. Yeoh's C_i0 and Mooney-Rivlin's C1, C2 multiply the invariants directly, so
neo-hookean(mu) = mooney-rivlin(mu/2, 0) = yeoh(mu/2, 0, 0) = ogden([mu], [2]),
and ogden([2 C1, -2 C2], [2, -2]) = mooney-rivlin(C1, C2).

Each law is one ``RubberLaw`` in the registry ``LAWS`` (name -> definition): its parameters
(``Parameter``: name, unit "stress" or "dimensionless", help text, whether it is a list), mu_0,
the strain energy, the admissible set (``admissible`` raises the one-line error) and the bound
on I1 - 3 where the law's domain ends (Gent's Jm; inf for the rest). The command line, case
files and tests read the registry; a new law is one ``register`` call here, and each solver
maps it to its kernel through its own table, which refuses a law it lacks in one line.

A ``Material`` holds the law's name and its parameters in any consistent unit
(Pa in case files, units of mu_0 inside the solvers: ``scaled`` divides the
stresses by mu_0). ``check`` refuses, in one line naming the parameter, what
is not a stable rubber: a non-positive mu_0, Jm <= 0, a Yeoh polynomial whose
slope dW/dI1 is not positive for every I1 >= 3, an Ogden term with
mu_p alpha_p <= 0; and what lies outside the model's ranges: Jm outside
``JM_RANGE``, an Ogden exponent outside ``EXPONENT_RANGE``, a prestretch past
``PRESTRETCH_LIMIT``. The solvers derive their tensions, residuals and tangents
from W each by its own route; tests compare them with finite differences of
``energy``.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Mapping

import numpy as np

from .errors import InputError
from .inputs import MAGNITUDES, check_alpha, check_finite, check_range, quote

__all__ = [
    "EXPONENT_RANGE",
    "JM_RANGE",
    "LAWS",
    "PRESTRETCH_LIMIT",
    "Material",
    "Parameter",
    "RubberLaw",
    "as_material",
    "check",
    "check_prestretch",
    "energy",
    "mooney_rivlin",
    "register",
]

#: the units a parameter may have
UNITS = ("stress", "dimensionless")

#: the largest prestretch lambda_p of the clamped sheet: the sheet at rest, before any load, stretched 10-fold
#: each way (thinned 100-fold) is past the break of rubbers (stretches of 5 to 10, less when equibiaxial)
PRESTRETCH_LIMIT = 10.0
#: Gent's Jm: from where the rubber locks at an equibiaxial strain of 1 % (I1 - 3 ~ 12 s^2: s = sqrt(Jm / 12)),
#: stiffer than any rubber (Gent's fits: 20 to 120; soft tissues near 1), to the largest of ``MAGNITUDES``
#: (larger Jm are the neo-Hookean rubber)
JM_RANGE = (1e-3, MAGNITUDES[1])
#: |alpha_p| of an Ogden term: fitted exponents lie well inside (Treloar's rubber 1.3, 5, -2; brain tissue near
#: -25). The principal stretches the model reaches lie within 1e-6 to 1e6 (a sheet prestretched 10-fold and
#: stretched 100-fold more is thinned 1e6-fold), where l^alpha_p stays below the largest double (1.8e308) while
#: |alpha_p| <= 50 (1e6^50 = 1e300); below 0.01 the term's tension, mu_p times a difference of powers l^alpha_p near 1,
#: keeps fewer digits than the solvers resolve at small strain
EXPONENT_RANGE = (1e-2, 50.0)


@dataclasses.dataclass(frozen=True)
class Parameter:
    """One parameter of a law, as case files, flags and the command line's help name it.

    Attributes
    ----------
    name : str
        As in case files and flags.
    unit : {"stress", "dimensionless"}
        A stress is in Pa in case files, in units of mu_0 inside the solvers.
    help : str
        The command line's help text.
    listed : bool
        One value per term (Ogden's ``mu`` and ``exponents``).

    Examples
    --------
    >>> from pocket.core.materials import LAWS
    >>> print(LAWS["gent"].parameter("jm").unit, LAWS["ogden"].parameter("mu").listed)
    dimensionless True
    """

    name: str
    unit: str
    help: str
    listed: bool = False


@dataclasses.dataclass(frozen=True)
class RubberLaw:
    """A strain-energy law of an incompressible rubber, as the registry ``LAWS`` holds it.

    Each callable takes the parameters as a dict name -> value (floats; tuples for listed parameters).

    Attributes
    ----------
    name : str
        The law's name (``"mooney-rivlin"``, ``"neo-hookean"``, ``"yeoh"``, ``"gent"``, ``"ogden"``).
    parameters : tuple of Parameter
        In order.
    mu0 : callable
        ``mu0(p)``: the small-strain shear modulus, in the unit of the stresses.
    energy : callable
        ``energy(p, l1, l2, l3, i1, i2)``: W per unit reference volume (arrays broadcast, l3 = 1/(l1 l2), I1, I2
        the invariants).
    admissible : callable
        ``admissible(p, where)``: raises a one-line ``InputError`` naming ``where.<parameter>`` for a rubber that
        is not stable.
    example : Mapping
        A typical rubber of the law in Pa (a case-file table): the tests check every law's kernels on it.
    domain : callable
        ``domain(p)``: the bound on I1 - 3 below which W exists (inf: everywhere).

    Examples
    --------
    >>> from pocket.core.materials import LAWS
    >>> law = LAWS["yeoh"]
    >>> print(law.names, law.stresses)
    ('c10', 'c20', 'c30') ('c10', 'c20', 'c30')
    >>> print(law.mu0(law.example) == 2 * law.example["c10"])
    True
    """

    name: str
    parameters: tuple[Parameter, ...]
    mu0: Callable[[dict], float]
    energy: Callable
    admissible: Callable[[dict, str], None]
    example: Mapping
    domain: Callable[[dict], float] = lambda p: math.inf

    @property
    def names(self) -> tuple[str, ...]:
        """The parameters' names, in order."""
        return tuple(q.name for q in self.parameters)

    @property
    def stresses(self) -> tuple[str, ...]:
        """The names of the parameters that are stresses."""
        return tuple(q.name for q in self.parameters if q.unit == "stress")

    def parameter(self, name: str) -> Parameter:
        """The parameter called ``name`` (KeyError if the law has none)."""
        return {q.name: q for q in self.parameters}[name]


#: law name -> its definition, in the order the laws were registered
LAWS: dict[str, RubberLaw] = {}


def register(law: RubberLaw) -> RubberLaw:
    """Add ``law`` to the registry ``LAWS``: a new law is one call.

    The command line, case files and tests read the registry; each solver maps a law to its kernel through its
    own table, which refuses a law it lacks in one line.

    Parameters
    ----------
    law : RubberLaw
        The definition.

    Returns
    -------
    RubberLaw
        ``law``.

    Raises
    ------
    ValueError
        For a parameter without a help text or with an unknown unit, a name used twice, or an example that fails
        the law's own check: refused here, not at run time.

    Examples
    --------
    >>> from pocket.core.materials import LAWS, register
    >>> register(LAWS["gent"])
    Traceback (most recent call last):
        ...
    ValueError: a law named 'gent' is registered already
    >>> print(list(LAWS))
    ['mooney-rivlin', 'neo-hookean', 'yeoh', 'gent', 'ogden']
    """
    if law.name in LAWS:
        raise ValueError(f"a law named {law.name!r} is registered already")
    if not law.parameters:
        raise ValueError(f"the {law.name} law has no parameters")
    for q in law.parameters:
        if q.unit not in UNITS or not q.help.strip():
            raise ValueError(f"{law.name}.{q.name}: a parameter needs a unit in {UNITS} and a help text")
    if len(set(law.names)) != len(law.names):
        raise ValueError(f"the {law.name} law names a parameter twice")
    LAWS[law.name] = law
    try:
        check(law.name, dict(law.example), where=f"{law.name}.example")
    except (InputError, KeyError, TypeError) as err:
        del LAWS[law.name]
        raise ValueError(f"the {law.name} law's example is not a rubber of it: {err}") from None
    return law


def _stress(name: str, text: str, listed: bool = False) -> Parameter:
    return Parameter(name, "stress", text, listed)


def _mooney_rivlin_admissible(v: dict, where: str) -> None:
    if v["c1"] <= 0.0 or v["c1"] + v["c2"] <= 0.0:
        raise InputError(f"{where}.c1 = {quote(v['c1'])}, {where}.c2 = {quote(v['c2'])}, but a Mooney-Rivlin "
                         "rubber needs C1 > 0 and C1 + C2 > 0 (alpha = C2/C1 > -1)")


def _shear_admissible(v: dict, where: str) -> None:
    if v["mu"] <= 0.0:
        raise InputError(f"{where}.mu = {quote(v['mu'])}, but the shear modulus must be > 0")


def _gent_admissible(v: dict, where: str) -> None:
    _shear_admissible(v, where)
    if v["jm"] <= 0.0:
        raise InputError(f"{where}.jm = {quote(v['jm'])}, but the locking parameter Jm must be > 0")
    check_range(f"{where}.jm", v["jm"], *JM_RANGE, "below it the rubber locks at an equibiaxial strain under "
                "1 %, sqrt(Jm / 12): no rubber; fitted Jm are 20 to 120 for rubbers, near 1 for soft tissues")


def _yeoh_stable(c10: float, c20: float, c30: float) -> bool:
    """dW/dI1 = c10 + 2 c20 x + 3 c30 x^2 > 0 for every x = I1 - 3 >= 0."""
    if c10 <= 0.0 or c30 < 0.0:
        return False
    if c20 >= 0.0:
        return True
    if c30 == 0.0:
        return False  # the slope falls without bound
    x = -c20 / (3.0 * c30)  # the minimum of the quadratic, at x > 0
    return c10 + 2.0 * c20 * x + 3.0 * c30 * x * x > 0.0


def _yeoh_admissible(v: dict, where: str) -> None:
    if not _yeoh_stable(v["c10"], v["c20"], v["c30"]):
        raise InputError(f"{where}.c10, c20, c30 = {v['c10']:g}, {v['c20']:g}, {v['c30']:g}, but a stable Yeoh "
                         "rubber needs C10 > 0 and dW/dI1 = C10 + 2 C20 x + 3 C30 x^2 > 0 for all x = I1 - 3 >= 0")


def _ogden_admissible(v: dict, where: str) -> None:
    mu, exponents = v["mu"], v["exponents"]
    if len(mu) != len(exponents):
        raise InputError(f"{where}.mu has {len(mu)} terms but {where}.exponents has {len(exponents)}")
    for k, (m, a) in enumerate(zip(mu, exponents, strict=True)):
        if not m * a > 0.0:
            raise InputError(f"{where}.mu[{k}] = {m:g} with exponent {a:g}, but a stable Ogden term needs "
                             "mu_p alpha_p > 0")
        low, high = EXPONENT_RANGE
        if not low <= abs(a) <= high:
            raise InputError(f"{where}.exponents[{k}] = {quote(a)}, but |alpha_p| must lie in [{low:g}, {high:g}] "
                             "(fitted exponents lie well inside; past it l^alpha_p overflows at stretches the model "
                             "reaches, below it the term's tension is a difference of numbers near 1)")


def _yeoh_energy(p, l1, l2, l3, i1, i2):
    x = i1 - 3.0
    return p["c10"] * x + p["c20"] * x**2 + p["c30"] * x**3


# a parameter's value: a float, or a tuple of floats for a listed parameter (Ogden's mu and exponents)
ParamValue = float | tuple[float, ...]


def _ogden_energy(p, l1, l2, l3, i1, i2):
    return sum(m / a * (l1**a + l2**a + l3**a - 3.0) for m, a in zip(p["mu"], p["exponents"], strict=True))


@dataclasses.dataclass(frozen=True)
class Material:
    """A rubber: a law of ``LAWS`` by name with its parameters, in any consistent stress unit.

    Parameters
    ----------
    law : str
        The law's name in ``LAWS``.
    params : Mapping or tuple of (str, value) pairs
        Each parameter of the law -> a float (a listed parameter, as Ogden's ``mu`` and ``exponents``, a tuple of
        floats). A mapping is checked as ``check`` does (a name that is not the law's is an InputError listing
        the law's names); pairs, in the law's order, are taken as stored.
    exact_alpha : float, optional
        The C2/C1 a Mooney-Rivlin rubber was given by (``mooney_rivlin``), kept because C2/C1 recomputed from
        its C1, C2 differs from it in the last bit for some alphas; ``alpha`` returns it, and a state reports it
        as its ``alpha``. It takes part in comparisons: the solvers take a Mooney-Rivlin rubber by this alpha
        where there is one, so two rubbers that differ in it are solved as two rubbers.
    prestretch : float, optional
        The equibiaxial stretch lambda_p >= 1 of the clamped flat sheet (checked by ``check_prestretch``); the
        parameters stay those of the unstretched rubber.

    Raises
    ------
    InputError
        For parameters that are not the law's, or not a stable rubber, or a prestretch out of range.

    Examples
    --------
    A Yeoh rubber in Pa; the solvers take it as it is (only its stresses' ratios and E = 3 mu_0 enter the
    model's units):

    >>> from pocket.core.materials import Material
    >>> rubber = Material("yeoh", {"c10": 85e3, "c20": -2e3, "c30": 0.2e3})
    >>> print(rubber.mu0, rubber.modulus, rubber["c20"])
    170000.0 510000.0 -2000.0
    >>> print(rubber.scaled().mu0)
    1.0
    >>> Material("yeoh", {"c10": 85e3, "c2": 1.0})
    Traceback (most recent call last):
        ...
    pocket.core.errors.InputError: material.c2 is not a parameter of the yeoh law (its parameters: c10, c20, c30)
    """

    law: str
    params: tuple[tuple[str, ParamValue], ...]
    exact_alpha: float | None = dataclasses.field(default=None, repr=False)
    prestretch: float = 1.0

    def __post_init__(self):
        if isinstance(self.params, Mapping):
            object.__setattr__(self, "params", check(self.law, dict(self.params), where="material").params)
        if self.prestretch != 1.0 or not isinstance(self.prestretch, float):
            object.__setattr__(self, "prestretch", check_prestretch(self.prestretch, self, "prestretch"))

    def __getitem__(self, name: str):
        return dict(self.params)[name]

    @property
    def definition(self) -> RubberLaw:
        """The law's definition in the registry (an InputError for a name it lacks)."""
        return _definition(self.law)

    @property
    def mu0(self) -> float:
        """The small-strain shear modulus mu_0, in the unit of the stresses."""
        return self.definition.mu0(dict(self.params))

    @property
    def modulus(self) -> float:
        """E = 3 mu_0, the small-strain Young's modulus."""
        return 3.0 * self.mu0

    @property
    def domain(self) -> float:
        """The bound on I1 - 3 below which the energy exists (inf: everywhere)."""
        return self.definition.domain(dict(self.params))

    @property
    def alpha(self) -> float | None:
        """C2/C1 for a Mooney-Rivlin rubber (the alpha it was given by, if any), else None."""
        if self.law != "mooney-rivlin":
            return None
        return self["c2"] / self["c1"] if self.exact_alpha is None else self.exact_alpha

    def scaled(self) -> Material:
        """The same law with its stresses in units of mu_0 (so that mu_0 = 1)."""
        mu0 = self.mu0
        stresses = self.definition.stresses
        out: list[tuple[str, ParamValue]] = []
        for name, value in self.params:
            if name in stresses:
                value = tuple(v / mu0 for v in value) if isinstance(value, tuple) else value / mu0
            out.append((name, value))
        return Material(self.law, tuple(out), self.exact_alpha, self.prestretch)

    def describe(self) -> dict:
        """The law and its parameters as a flat JSON-ready dict, with ``prestretch`` where it is not 1."""
        out: dict[str, str | float | list[float]] = {"material": self.law}
        for name, value in self.params:
            out[name] = list(value) if isinstance(value, tuple) else value
        if self.prestretch != 1.0:
            out["prestretch"] = self.prestretch
        return out


def check_prestretch(value, material: Material, key: str = "prestretch") -> float:
    """The prestretch lambda_p of ``material``'s clamped sheet, checked.

    Parameters
    ----------
    value : float
        lambda_p, a plain number (a stretch has no unit).
    material : Material
        The rubber, whose domain bounds the stretch (Gent's locking).
    key : str, optional
        The name of the value in error messages.

    Returns
    -------
    float
        lambda_p, a finite float in [1, ``PRESTRETCH_LIMIT``] whose clamped flat sheet lies inside the law's domain.

    Raises
    ------
    InputError
        Otherwise, one line naming ``key``.

    Examples
    --------
    >>> from pocket.core.materials import check_prestretch, mooney_rivlin
    >>> print(check_prestretch(1.2, mooney_rivlin(0.1)))
    1.2
    >>> check_prestretch(0.9, mooney_rivlin(0.1))
    Traceback (most recent call last):
        ...
    pocket.core.errors.InputError: prestretch = 0.9, but a prestretch of the clamped sheet must be >= 1
    """
    if isinstance(value, str):
        raise InputError(f"{key} = {quote(value)} is not a number (a stretch has no unit)")
    number = check_finite(key, value)
    if not number >= 1.0:
        raise InputError(f"{key} = {quote(value)}, but a prestretch of the clamped sheet must be >= 1")
    if number > PRESTRETCH_LIMIT:
        raise InputError(f"{key} = {quote(value)}, but a prestretch of the clamped sheet must be at most "
                         f"{PRESTRETCH_LIMIT:g} (a sheet stretched {PRESTRETCH_LIMIT:g}-fold each way at rest is past "
                         "the break of rubbers, stretches of 5 to 10)")
    bound = material.domain
    excess = 2.0 * number * number + number**-4 - 3.0  # I1 - 3 of the clamped flat sheet
    if not excess < bound:
        raise InputError(f"{key} = {quote(value)} puts the clamped flat sheet at I1 - 3 = {excess:.6g}, past the "
                         f"{material.law} rubber's locking (I1 - 3 < {bound:.6g})")
    return number



def mooney_rivlin(alpha) -> Material:
    """The Mooney-Rivlin rubber with C2/C1 = ``alpha``, in units of mu_0.

    C1 = 1 / (2 (1 + alpha)), C2 = alpha C1, so that mu_0 = 2 (C1 + C2) = 1. The one conversion of an alpha,
    wherever one is given (``--alpha``, a case file's ``sheet.alpha``, a sweep's alphas, a number given to a
    solver).

    Parameters
    ----------
    alpha : float
        C2/C1 > -1.

    Returns
    -------
    Material
        Keeping ``alpha`` exactly (``Material.exact_alpha``).

    Raises
    ------
    InputError
        For alpha <= -1 or not a finite number.

    Examples
    --------
    >>> from pocket.core.materials import mooney_rivlin
    >>> rubber = mooney_rivlin(47 / 160)
    >>> print(rubber.alpha == 47 / 160, round(rubber.mu0, 15))
    True 1.0
    """
    alpha = check_alpha(alpha)
    c1 = 0.5 / (1.0 + alpha)
    return Material("mooney-rivlin", (("c1", c1), ("c2", alpha * c1)), alpha)


def as_material(value) -> Material:
    """The rubber every solver entry point works with.

    Parameters
    ----------
    value : Material or float
        A ``Material``, re-checked and returned as given (in its own stress unit); a number is taken, as a
        convenience for Python callers, as the Mooney-Rivlin alpha = C2/C1 and converted here, and only here, by
        ``mooney_rivlin``.

    Returns
    -------
    Material

    Raises
    ------
    InputError
        For a rubber that is not stable, or a number that is not an alpha > -1.

    Examples
    --------
    >>> from pocket.core.materials import as_material, mooney_rivlin
    >>> print(as_material(0.3) == mooney_rivlin(0.3))
    True
    >>> as_material(-1)
    Traceback (most recent call last):
        ...
    pocket.core.errors.InputError: alpha = -1, ...
    """
    if isinstance(value, Material):
        check(value.law, dict(value.params))
        return value
    return mooney_rivlin(value)


def _definition(law, where: str = "") -> RubberLaw:
    """The registered law called ``law``; an InputError naming ``where.material`` (or ``material``) otherwise."""
    if not isinstance(law, str) or law not in LAWS:
        key = f"{where}.material" if where else "material"
        raise InputError(f"{key} = {quote(law)}, but it must be one of {', '.join(LAWS)}")
    return LAWS[law]


def energy(material: Material, l1, l2):
    """The strain energy W(lambda_1, lambda_2) per unit reference volume of ``material`` (lambda_3 = 1/(l1 l2)).

    Parameters
    ----------
    material : Material
        The rubber.
    l1, l2 : float or numpy.ndarray
        The in-plane principal stretches; arrays broadcast.

    Returns
    -------
    numpy.ndarray
        W, in the unit of the rubber's stresses.

    Examples
    --------
    The neo-Hookean energy (mu / 2)(I1 - 3) under equibiaxial stretch 1.1:

    >>> from pocket.core.materials import Material, energy
    >>> rubber = Material("neo-hookean", {"mu": 1.0})
    >>> print(round(float(energy(rubber, 1.1, 1.1)), 12), round(0.5 * (2 * 1.1**2 + 1.1**-4 - 3), 12))
    0.051506727683 0.051506727683
    """
    l1, l2 = np.asarray(l1, dtype=float), np.asarray(l2, dtype=float)
    l3 = 1.0 / (l1 * l2)
    i1, i2 = l1**2 + l2**2 + l3**2, l1**-2 + l2**-2 + l3**-2
    return _definition(material.law).energy(dict(material.params), l1, l2, l3, i1, i2)


def check(law, params: dict, where: str = "sheet") -> Material:
    """A ``Material`` from a law's name and its parameters, checked.

    Every parameter of the law must be given and no other.

    Parameters
    ----------
    law : str
        The law's name in ``LAWS``.
    params : dict
        Parameter name -> number, or list of numbers for a listed parameter (in any stress unit).
    where : str, optional
        The prefix of the names in error messages (``sheet`` for a case file's ``[sheet]`` table).

    Returns
    -------
    Material

    Raises
    ------
    InputError
        For an unknown law, a missing or unknown parameter, a value that is not a finite number, or a rubber that
        is not stable (a non-positive mu_0, Jm <= 0, a Yeoh polynomial whose slope dW/dI1 is not positive for
        every I1 >= 3, an Ogden term with mu_p alpha_p <= 0); one line naming ``where.<parameter>``.

    Examples
    --------
    >>> from pocket.core.materials import check
    >>> print(check("gent", {"mu": 0.3e6, "jm": 10.0}).describe())
    {'material': 'gent', 'mu': 300000.0, 'jm': 10.0}
    >>> check("neo-hookean", {"mu": -1.0})
    Traceback (most recent call last):
        ...
    pocket.core.errors.InputError: sheet.mu = -1.0, ...
    """
    definition = _definition(law, where)
    names = definition.names
    extra = sorted(set(params) - set(names))
    if extra:
        raise InputError(f"{where}.{extra[0]} is not a parameter of the {law} law (its parameters: "
                         f"{', '.join(names)})")
    missing = [n for n in names if n not in params]
    if missing:
        raise InputError(f"{where}.{missing[0]} is missing: the {law} law needs {', '.join(names)}")
    values: dict[str, ParamValue] = {}
    for q in definition.parameters:
        value = params[q.name]
        if q.listed:
            if not isinstance(value, (list, tuple)) or not value:
                raise InputError(f"{where}.{q.name} = {quote(value)}, but the {law} law needs a non-empty list")
            values[q.name] = tuple(check_finite(f"{where}.{q.name}[{i}]", v) for i, v in enumerate(value))
        else:
            values[q.name] = check_finite(f"{where}.{q.name}", value)
    definition.admissible(values, where)
    mu0 = definition.mu0(values)
    if not (math.isfinite(mu0) and mu0 > 0.0):
        raise InputError(f"{where}: the small-strain shear modulus mu_0 of these parameters is not > 0")
    return Material(law, tuple((n, values[n]) for n in names))


# the laws, in the order the command line and the tables list them
register(RubberLaw(
    "mooney-rivlin", (_stress("c1", "Mooney-Rivlin's C1"), _stress("c2", "Mooney-Rivlin's C2")),
    mu0=lambda p: 2.0 * (p["c1"] + p["c2"]),
    energy=lambda p, l1, l2, l3, i1, i2: p["c1"] * (i1 - 3.0) + p["c2"] * (i2 - 3.0),
    admissible=_mooney_rivlin_admissible, example={"c1": 160e3, "c2": 47e3}))
register(RubberLaw(
    "neo-hookean", (_stress("mu", "the shear modulus mu"),),
    mu0=lambda p: p["mu"], energy=lambda p, l1, l2, l3, i1, i2: 0.5 * p["mu"] * (i1 - 3.0),
    admissible=_shear_admissible, example={"mu": 0.4e6}))
register(RubberLaw(
    "yeoh", (_stress("c10", "Yeoh's C10"), _stress("c20", "Yeoh's C20"), _stress("c30", "Yeoh's C30")),
    mu0=lambda p: 2.0 * p["c10"], energy=_yeoh_energy, admissible=_yeoh_admissible,
    example={"c10": 85e3, "c20": -2e3, "c30": 0.2e3}))  # softens, then stiffens
register(RubberLaw(
    "gent", (_stress("mu", "the shear modulus mu"),
             Parameter("jm", "dimensionless", "Gent's locking parameter Jm (a number, at least 1e-3)")),
    mu0=lambda p: p["mu"],
    energy=lambda p, l1, l2, l3, i1, i2: -0.5 * p["mu"] * p["jm"] * np.log1p(-(i1 - 3.0) / p["jm"]),
    admissible=_gent_admissible, example={"mu": 0.3e6, "jm": 10.0}, domain=lambda p: p["jm"]))
register(RubberLaw(
    "ogden", (_stress("mu", "Ogden's mu_p, one per term", listed=True),
              Parameter("exponents", "dimensionless", "Ogden's exponents alpha_p, one per term, each "
                        "|alpha_p| from 0.01 to 50", listed=True)),
    mu0=lambda p: 0.5 * sum(m * a for m, a in zip(p["mu"], p["exponents"], strict=True)),
    energy=_ogden_energy, admissible=_ogden_admissible,
    example={"mu": [630e3, 1.2e3, -10e3], "exponents": [1.3, 5.0, -2.0]}))  # Treloar's data, Ogden's fit
