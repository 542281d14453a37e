r"""The paper's small-strain analytical model (section 3, eqs (14)-(26)), corrected.

Range of validity. A small-strain approximation: good while lambda - 1 << 1 (the
paper: lambda_0 <= 1.1, i.e. Phat_I <= 4 sqrt(6) 0.1^1.5 = 0.31) and at small force.
Every state whose pole or contact stretch exceeds 1.1 carries a ``warnings`` entry
saying so with the numbers (``STRETCH_LIMIT``); nothing here knows the full model's
range (e.g. its pressure maximum for alpha <= 0: the model returns a dome at any
pressure). Measured against the shooting solver (``tests/test_analytical.py``): within
2 % at Fhat = 0.01 and 8 % at 0.05; it misplaces the contact area by > 20 % at
Fhat = 0.5; and its pressure does not tend to P_I as the force vanishes: eq (26)
does not reduce to (17b) as a_c -> 0 (the paper says so), so P/P_I -> 10 / (4 sqrt 6)
= 1.0206 there.

Inflation. Eqs (14)-(16): lambda_1 = lambda_0, lambda_2 = lambda_0 - s r^2 with
s = lambda_0 - 1, eta = sqrt(3 s / 2) (1 - r^2), H0 = sqrt(3 s / 2),
V = (pi / 4) sqrt(6 s). Linearising eq (6) about lambda = 1 gives
T = 12 C1 (1 + alpha) T (lambda - 1) = 2 E T (lambda - 1) at the pole: the paper's
eqs (17a) and (25) lack the factor (1 + alpha). With kappa R = sqrt(6 s), eq (18)
becomes Phat_I = 2 kappa T / (E T) = 4 sqrt(6) s^(3/2), independent of alpha.

Compression. Eqs (19)-(24): eta = sqrt(s_c) G(r, a), s_c = lambda_c - 1, with
G(r, a) = c int_max(r,a)^1 sqrt(3 t^2 - a^2) dt, c = sqrt(2 / (1 - a^2)). The
volume 2 pi sqrt(s_c) int_0^1 r G dr = V fixes s_c / s (eq (24)); integrating
by parts, int_0^1 r G dr = (c / 2) int_a^1 t^2 sqrt(3 t^2 - a^2) dt. At the
contact edge, with T = 2 E T s_c (eq (25) corrected) and the curvatures of
eq (26) (which follow from eq (20)), normal equilibrium gives
Phat = 2 s_c (3 + 2) sqrt(s_c / (1 - a^2)) = 10 s_c^(3/2) / sqrt(1 - a^2). The
force is F = P A_c with A_c = pi (lambda_c a R)^2: Fhat = (Phat / Phat_I) lambda_c^2 a^2.
Fhat(a) grows without bound as a -> 1, but past the force at which the deformed
contact radius lambda_c a reaches the clamp radius the model no longer describes
a pocket: that force is its range. Tensions in the profiles are the plane-stress linear law with
Poisson ratio 1/2: T1 / (E T) = (4/3) (e1 + e2 / 2), e = lambda - 1.

Any rubber. Linearised about the flat sheet every incompressible law is the linear law above
with E = 3 mu_0 (mu_0 its small-strain shear modulus; for Mooney-Rivlin E = 6 (C1 + C2)), and in
the units Phat = P R / (E T) nothing else of the law is left: the model accepts any material
(``pocket.core.materials``) and gives every law the same numbers. How soon the full model departs
from it does depend on the law (a rubber that stiffens or locks departs sooner); the warnings
above still mark stretches past 1.1, and the shooting solver is the measure.

A prestretched sheet (``Material.prestretch`` > 1) is not modelled: it is taut before any pressure,
and the small-strain dome above is that of a slack one. It is refused in one line (InputError);
the shooting and finite-element solvers take it.

A gas sealed at P_I (``pocket.core.fluids``). The volume constraint V = V_I becomes
V = V_I ((Phat_I + Phat_atm) / (Phat + Phat_atm))^(1/gamma). With u = sqrt(s_c / s) and
eq (16b), V / V_I = 2 pi sqrt(s) u M(a) / ((pi / 4) sqrt(6 s)) = u / u_L(a), where
M(a) = int_0^1 r G dr and u_L = sqrt(6) / (8 M(a)) is the liquid's u (eq (24)); and the contact
pressure is Phat(u) = 10 s^(3/2) u^3 / sqrt(1 - a^2). So u solves

    ln u - ln u_L(a) + (1/gamma) ln((Phat(u) + Phat_atm) / (Phat_I + Phat_atm)) = 0,

whose left side rises monotonically from -inf (u -> 0) and is >= 0 at
u = u_L ((Phat_I + Phat_atm) / Phat_atm)^(1/gamma) (Phat >= 0): one root, found by Brent's
method. Then s_c = s u^2, and the force and the range follow as for a liquid. As Phat_atm grows
the logarithm vanishes and u -> u_L: the liquid.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq

from pocket.core import geometries, smallstrain
from pocket.core.errors import InputError, OutOfRangeError
from pocket.core.fluids import LIQUID, as_fluid
from pocket.core.indenters import Indenter, Plate, posed
from pocket.core.inputs import check_forces, check_positive
from pocket.core.materials import as_material
from pocket.core.solver import FluidLike, GeometryLike, MaterialLike, Numbers, Progress
from pocket.core.states import CompressedState, InflatedState, Profile

__all__ = [
    "CONTACTS",
    "GEOMETRIES",
    "STRETCH_LIMIT",
    "compress",
    "compression_curve",
    "inflate",
    "range_end",
    "shape_function",
]

_N = 201  # profile points

#: largest pole or contact stretch of the model's range of validity (the paper's lambda_0 <= 1.1)
STRETCH_LIMIT = 1.1


def _warnings(**stretches) -> tuple[str, ...]:
    """One warning per stretch (name -> value) above STRETCH_LIMIT."""
    return tuple(f"{name} = {value:.6g} exceeds {STRETCH_LIMIT:g}, the small-strain model's range of validity "
                 f"(lambda - 1 << 1; the paper's lambda_0 <= 1.1): expect errors of several per cent or more"
                 for name, value in stretches.items() if value > STRETCH_LIMIT)


def _antiderivative(t, a):
    """A primitive of sqrt(3 t^2 - a^2) for t >= a / sqrt(3)."""
    root3 = np.sqrt(3.0)
    u = np.sqrt(np.maximum(3.0 * t * t - a * a, 0.0))
    if a == 0.0:
        return 0.5 * t * u
    return 0.5 * t * u - a * a / (2.0 * root3) * np.log(root3 * t + u)


def shape_function(r, a):
    """The shape function G(r, a) of eq (21): the compressed dome's height is eta = sqrt(lambda_c - 1) G(r, a) R.

    Parameters
    ----------
    r : float or numpy.ndarray
        Lagrangian radius r / R in [0, 1], a scalar or shape (n,).
    a : float
        Lagrangian contact radius a_c / R, 0 <= a < 1.

    Returns
    -------
    float or numpy.ndarray
        G(r, a), dimensionless, of the shape of ``r``: constant on the contact zone r <= a (flat under the
        plate), 0 at the clamp r = 1.

    Examples
    --------
    >>> import numpy as np
    >>> from pocket import analytical
    >>> g = analytical.shape_function(np.array([0.0, 0.15, 0.3, 1.0]), 0.3)
    >>> print(np.round(g, 6))
    [1.120344 1.120344 1.120344 0.      ]
    """
    c = np.sqrt(2.0 / (1.0 - a * a))
    lower = np.maximum(r, a)
    return c * (_antiderivative(1.0, a) - _antiderivative(lower, a))


def _volume_moment(a):
    """int_0^1 r G(r, a) dr, by parts (module docstring)."""
    c = np.sqrt(2.0 / (1.0 - a * a))
    return 0.5 * c * quad(lambda t: t * t * np.sqrt(3.0 * t * t - a * a), a, 1.0, epsabs=1e-14)[0]


def _tensions(l1, l2):
    e1, e2 = l1 - 1.0, l2 - 1.0
    return 4.0 / 3.0 * (e1 + 0.5 * e2), 4.0 / 3.0 * (e2 + 0.5 * e1)


def _profile(r, rho, eta, l1, l2, contact):
    t1, t2 = _tensions(l1, l2)
    return Profile(r=r, rho=rho, eta=eta, stretch_1=l1, stretch_2=l2,
                   tension_1=t1, tension_2=t2, contact=contact)


#: reference surface -> the model of it (``pocket.core.geometries``): the paper's is the flat clamped sheet's
GEOMETRIES = {"pocket": "the small-strain dome over the flat sheet clamped at r = R, eqs (14)-(26)"}


def inflate(material: MaterialLike, pressure: float, *, geometry: GeometryLike = None) -> InflatedState:
    """The small-strain dome at Phat = ``pressure``, by eqs (14)-(18) (corrected).

    Parameters
    ----------
    material : Material or float
        The rubber, any ``pocket.core.materials.Material`` or a Mooney-Rivlin alpha (``as_material``); only
        mu_0 enters, through Phat (``pocket.analytical.model``). Echoed by the state.
    pressure : float
        Phat = P R / (E T) > 0.
    geometry : Geometry or str, optional
        The reference surface: None (the flat clamped disc) or one of ``GEOMETRIES``.

    Returns
    -------
    InflatedState
        Lengths in units of R, the volume V / R^3; a ``warnings`` entry when the pole stretch exceeds 1.1,
        the model's range of validity.

    Raises
    ------
    InputError
        For an invalid rubber or pressure, a prestretched rubber, or another geometry.

    Examples
    --------
    The pole stretch follows the corrected eq (18), Phat = 4 sqrt(6) (lambda_0 - 1)^(3/2), whatever alpha:

    >>> import math
    >>> from pocket import analytical
    >>> state = analytical.inflate(47 / 160, 0.1)
    >>> print(round(4 * math.sqrt(6) * (state.stretch_pole - 1) ** 1.5, 12), state.warnings)
    0.1 ()

    At Phat = 0.31 the pole stretch passes 1.1, and the state says so:

    >>> print(analytical.inflate(47 / 160, 0.31).warnings[0])
    lambda_0 = 1.10003 exceeds 1.1, the small-strain model's range of validity ...
    """
    geometry, _ = geometries.posed(GEOMETRIES, "analytical", geometry)
    material = as_material(material)
    if material.prestretch != 1.0:
        raise InputError(f"prestretch = {material.prestretch!r}, but the analytical model is that of a sheet "
                         "clamped without prestretch (the shooting and fem solvers take one)")
    pressure = check_positive("pressure", pressure)
    s = smallstrain.pole_strain(pressure)
    r = np.linspace(0.0, 1.0, _N)
    l2 = 1.0 + s - s * r * r
    height = smallstrain.height_of_strain(s)
    profile = _profile(r, l2 * r, height * (1.0 - r * r), np.full_like(r, 1.0 + s), l2, np.zeros(r.size, bool))
    return InflatedState(material=material, pressure=pressure, stretch_pole=1.0 + s, height=height,
                         volume=smallstrain.volume_of_strain(s), stretch_clamp=1.0 + s,
                         profile=profile, solver="analytical", warnings=_warnings(lambda_0=1.0 + s), geometry=geometry)


def _contact_strain(a, s0, pressure_initial=None, fluid=LIQUID):
    """lambda_c - 1 at contact radius a, from the volume constraint: eq (24) for a liquid, the gas law
    for a gas (module docstring)."""
    liquid = s0 * (np.sqrt(6.0) / (8.0 * _volume_moment(a))) ** 2
    if not fluid.is_gas:
        return liquid
    u_liquid = np.sqrt(liquid / s0)
    sealed = pressure_initial + fluid.ambient
    shape = 10.0 * s0**1.5 / np.sqrt(1.0 - a * a)

    def miss(log_u):
        u = np.exp(log_u)
        return log_u - np.log(u_liquid) + np.log((shape * u**3 + fluid.ambient) / sealed) / fluid.gamma

    hi = np.log(u_liquid) + np.log(sealed / fluid.ambient) / fluid.gamma
    lo = hi - 1.0
    while miss(lo) > 0.0:
        lo -= 2.0 * (hi - lo)
    return s0 * np.exp(2.0 * brentq(miss, lo, hi, xtol=1e-15, rtol=1e-15))


def _force(a, s0, pressure_initial, fluid=LIQUID):
    sc = _contact_strain(a, s0, pressure_initial, fluid)
    phat = 10.0 * sc**1.5 / np.sqrt(1.0 - a * a)
    return phat / pressure_initial * (1.0 + sc) ** 2 * a * a


def _compressed(inflated, force, a, fluid, indenter):
    """The flat plate's compressed state at contact radius ``a`` (eqs (19)-(26), corrected)."""
    s0 = inflated.stretch_pole - 1.0
    sc = _contact_strain(a, s0, inflated.pressure, fluid) if a > 0.0 else s0
    phat = 10.0 * sc**1.5 / np.sqrt(1.0 - a * a) if a > 0.0 else inflated.pressure
    r = np.union1d(np.linspace(0.0, a, 33), np.linspace(a, 1.0, _N))
    l2 = np.where(r <= a, 1.0 + sc, 1.0 + sc - sc * (r * r - a * a) / (1.0 - a * a))
    profile = _profile(r, l2 * r, np.sqrt(sc) * shape_function(r, a), np.full_like(r, 1.0 + sc), l2,
                       r <= a if a > 0.0 else np.zeros(r.size, bool))
    height = np.sqrt(sc) * shape_function(0.0, a)
    return CompressedState(
        pressure_initial=inflated.pressure, force=force, pressure=phat,
        pressure_ratio=phat / inflated.pressure, contact_area=((1.0 + sc) * a) ** 2,
        contact_radius=a, stretch_contact=1.0 + sc, height=height,
        height_ratio=height / inflated.height,
        volume=2.0 * np.pi * np.sqrt(sc) * _volume_moment(a), profile=profile,
        inflated=inflated, solver="analytical",
        warnings=_warnings(lambda_0=inflated.stretch_pole, lambda_c=1.0 + sc),
        material=inflated.material, fluid=fluid, indenter=indenter,
    )


#: indenter class -> the compressed state of its contact at a contact radius (the paper's model is the flat plate's)
CONTACTS: dict[type[Indenter], Callable[..., CompressedState]] = {Plate: _compressed}


def _contact_limit(s0, pressure_initial, fluid=LIQUID):
    """(a, Fhat) where the deformed contact radius (1 + s_c) a reaches the clamp: the model's range."""
    a_max = brentq(lambda a: (1.0 + _contact_strain(a, s0, pressure_initial, fluid)) * a - 1.0, 0.0, 1.0 - 1e-12)
    return a_max, _force(a_max, s0, pressure_initial, fluid)


def _contact_radius(force, s0, pressure_initial, a_max, fluid=LIQUID):
    """a with Fhat(a) = ``force`` (0 < force <= Fhat(a_max)), to 1e-14 relative in the force: solved
    for b = a / sqrt(force), of order one however small the force (Fhat ~ a^2 as a -> 0)."""
    scale = np.sqrt(force)

    def miss(b):
        return _force(b * scale, s0, pressure_initial, fluid) / force - 1.0

    hi = min(a_max / scale, 10.0)  # for small forces b ~ 1 / lambda_0: the bracket stays of order one
    if miss(hi) < 0.0:
        hi = a_max / scale
        if miss(hi) < 0.0:  # force = Fhat(a_max) to its rounding: the range's end itself
            return a_max
    return min(brentq(miss, 0.0, hi, xtol=1e-300, rtol=1e-14) * scale, a_max)


def range_end(material: MaterialLike, pressure_initial: float, *, fluid: FluidLike = None,
              indenter: Indenter | None = None, geometry: GeometryLike = None) -> float:
    """The force Fhat = F / (P_I pi R^2) at which the model's contact reaches the clamp (A_c = pi R^2).

    Parameters
    ----------
    material : Material or float
        The rubber, as for ``inflate``.
    pressure_initial : float
        Phat_I = P_I R / (E T) > 0.
    fluid, indenter, geometry
        As for ``compression_curve``.

    Returns
    -------
    float
        Fhat at the end of the model's range.

    Raises
    ------
    InputError
        For invalid input, or an indenter other than the flat plate.

    Examples
    --------
    >>> from pocket import analytical
    >>> end = analytical.range_end(47 / 160, 0.1)
    >>> print(round(end, 4))
    8.3358

    Just below it the contact covers nearly the whole clamped disc; past it, no state:

    >>> print(round(analytical.compress(47 / 160, 0.1, 0.999 * end).contact_area, 3))
    1.0
    >>> analytical.compress(47 / 160, 0.1, 1.01 * end)
    Traceback (most recent call last):
        ...
    pocket.core.errors.OutOfRangeError: force = 8.41912 is beyond the analytical model's range: ...
    """
    posed(CONTACTS, "analytical", indenter)
    inflated = inflate(material, pressure_initial, geometry=geometry)
    fluid = as_fluid(fluid)
    return float(_contact_limit(inflated.stretch_pole - 1.0, inflated.pressure, fluid)[1])


def compression_curve(material: MaterialLike, pressure_initial: float, forces: Numbers, *, fluid: FluidLike = None,
                      indenter: Indenter | None = None, geometry: GeometryLike = None,
                      progress: Progress | None = None) -> list[CompressedState]:
    """Compressed states at each force Fhat = F / (P_I pi R^2) of ``forces``, by eqs (19)-(26) (corrected).

    Parameters
    ----------
    material : Material or float
        The rubber, as for ``inflate``.
    pressure_initial : float
        Phat_I = P_I R / (E T) > 0.
    forces : sequence of float
        Fhat >= 0 of each state.
    fluid : Fluid or str, optional
        None or ``"liquid"``, or a gas (``pocket.core.fluids.gas``, its ambient pressure as Phat_atm =
        P_atm R / (E T)); echoed by the states.
    indenter : Indenter, optional
        None (the flat plate) or an ``Indenter`` this model poses (``CONTACTS``: the plate alone).
    geometry : Geometry or str, optional
        As for ``inflate``: the inflated state's surface.
    progress : callable, optional
        ``progress(done, total)``, called after each force.

    Returns
    -------
    list of CompressedState
        In the order of ``forces``; each carries a warning where a stretch exceeds 1.1.

    Raises
    ------
    InputError
        For invalid input (another indenter, a negative force).
    OutOfRangeError
        For a force past the model's maximum (``range_end``).

    Examples
    --------
    >>> from pocket import analytical
    >>> states = analytical.compression_curve(47 / 160, 0.1, [0.01, 0.05])
    >>> print([f"{s.pressure_ratio:.4f}" for s in states])
    ['1.0208', '1.0246']

    As the force vanishes the model's pressure does not tend to P_I (eq (26) does not reduce to (17b), as
    the paper says) but to 10 / (4 sqrt(6)) P_I:

    >>> import math
    >>> print(round(analytical.compress(47 / 160, 0.1, 1e-12).pressure_ratio, 4), round(10 / (4 * math.sqrt(6)), 4))
    1.0206 1.0206
    """
    indenter, compressed = posed(CONTACTS, "analytical", indenter)
    inflated = inflate(material, pressure_initial, geometry=geometry)
    fluid = as_fluid(fluid)
    forces = check_forces(forces)
    s0 = inflated.stretch_pole - 1.0
    a_max, f_max = _contact_limit(s0, inflated.pressure, fluid)
    states = []
    for f in forces:
        if f > f_max:
            raise OutOfRangeError(f"force = {f:.6g} is beyond the analytical model's range: the contact "
                                  f"would reach the clamp (at force = {f_max:.6g})")
        a = 0.0 if f == 0.0 else _contact_radius(f, s0, inflated.pressure, a_max, fluid)
        states.append(compressed(inflated, f, a, fluid, indenter))
        if progress is not None:
            progress(len(states), len(forces))
    return states


def compress(material: MaterialLike, pressure_initial: float, force: float, *, fluid: FluidLike = None,
             indenter: Indenter | None = None, geometry: GeometryLike = None) -> CompressedState:
    """The compressed state at Fhat = ``force``, by eqs (19)-(26) (corrected): one state of ``compression_curve``.

    Parameters
    ----------
    material : Material or float
        The rubber, as for ``inflate``.
    pressure_initial : float
        Phat_I = P_I R / (E T) > 0.
    force : float
        Fhat = F / (P_I pi R^2) >= 0.
    fluid, indenter, geometry
        As for ``compression_curve``.

    Returns
    -------
    CompressedState
        Pressures in units of E T / R, lengths of R, the contact area in units of pi R^2.

    Raises
    ------
    InputError
        For invalid input.
    OutOfRangeError
        For a force past the model's maximum (``range_end``).

    Examples
    --------
    The model carries the force by the pressure on the contact area, F = P A_c:

    >>> from pocket import analytical
    >>> state = analytical.compress(47 / 160, 0.1, 0.01)
    >>> print(abs(state.force * state.pressure_initial - state.pressure * state.contact_area) < 1e-12)
    True

    At small force it is within 2 % of the shooting solver's (its range of validity):

    >>> from pocket import shooting
    >>> print(abs(state.pressure_ratio / shooting.compress(47 / 160, 0.1, 0.01).pressure_ratio - 1) < 0.02)
    True
    """
    return compression_curve(material, pressure_initial, [force], fluid=fluid, indenter=indenter,
                             geometry=geometry)[0]
