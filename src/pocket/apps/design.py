r"""Designing a soft button (the paper's section 6, Table 2): P_I and T from R, H0, E, F, H/H0, or P_I and H0
from a sheet's T.

Given the clamp radius R, the inflated height H0, the modulus E = 3 mu_0 (and the
rubber: a Mooney-Rivlin alpha, or another law with its parameters in any unit,
only their ratios matter; or its stresses in Pa, which set E), the fluid, the finger force F and the
target height ratio H/H0 = h at that force (or the pressed height H = h H0), find the initial pressure
P_I and the thickness T.

The paper's rules (Table 2): P_I = 5.7 F / (pi R^2), T = 0.216 P_I R^4 / (E H0^3).

The full model. In the model's dimensionless variables the unknowns enter only as
Phat_I = P_I R / (E T) and Fhat = F / (P_I pi R^2), and

    H0 / R = h0(Phat_I)                       (inflation)
    H / H0 = g(Phat_I, Fhat)                  (compression of a liquid at fixed volume)

The inflated height depends on Phat_I alone, so the problem decouples:

    1. Phat_I* solves h0(Phat_I) = H0 / R            (pocket.apps.inverse.pressure_for_height)
    2. Fhat*   solves g(Phat_I*, Fhat) = h           (pocket.apps.inverse.force_where)
    3. P_I = F / (pi R^2 Fhat*)                      (definition of Fhat)
    4. T   = P_I R / (E Phat_I*)                     (definition of Phat)

Two scalar roots, each monotone on the first branch, so the answer is unique.
P_I depends on R, H0, F and h but not on E, which scales T alone. In the same
terms the paper's rules say Fhat* = 1/5.7 and H0/R = (0.216 Phat_I)^(1/3),
the small-strain law H0/R = c Phat_I^(1/3) with c = 0.6 (the corrected
analytical model has c = 0.5726, ``pocket.core.smallstrain.height_constant``).
The paper's (P_I, T) are also fed to the full model, which shows the H0 and
H/H0 they really give.

A gas-filled button (ambient pressure P_atm, exponent gamma) is softer: its gas is
compressed too. Its compression depends also on Phat_atm = P_atm R / (E T), which
holds the unknown T; with steps 3 and 4, Phat_atm = P_atm Phat_I* / P_I =
P_atm Phat_I* pi R^2 Fhat / F. So step 2 becomes

    2'. Fhat* solves g(Phat_I*, Fhat, Phat_atm = P_atm Phat_I* pi R^2 Fhat / F) = h,

one scalar root again. It lies in (0, Fhat*_liquid]: at Fhat = 0, H/H0 = 1 > h, and a
gas at any ambient pressure is softer than the liquid, so g is at most the liquid's
value h at Fhat*_liquid (Brent's method on that bracket). Along this path both Fhat
and Phat_atm grow (a larger Fhat is a lower P_I and a thinner sheet); the tests
check that H/H0 still falls monotonically on it, so the root is unique.

A designer who already has the sheet knows T instead of H0. Then Fhat = F / (P_I pi R^2) =
c / Phat_I with c = F / (pi R E T), and the one unknown is Phat_I:

    2''. Phat_I* solves g(Phat_I, c / Phat_I) = h    (pocket.apps.inverse.pressure_for_sheet)

(or H/R = h0(Phat_I) g(Phat_I, c / Phat_I) = H / R for a pressed height), then P_I = Phat_I* E T / R and
H0 = R h0(Phat_I*). A gas is simpler here: T is known, so Phat_atm = P_atm R / (E T) is too. The
paper's rules read the other way: P_I = 5.7 F / (pi R^2), H0 = (0.216 P_I R^4 / (E T))^(1/3). Given
both T and H0, P_I follows from step 1 alone and H/H0 at F is the answer.

Feel: the force-travel curve F(H0 - H) at forces up to twice F (or to just
inside the end of the model's range, if that comes first), and its
stiffness dF/d(travel) = -(P_I pi R^2 / H0) / (d(H/H0)/dFhat), the slope from
``pocket.apps.slopes`` (central differences), with the designed fluid.
"""

from __future__ import annotations

import dataclasses
import math

from pocket.core.errors import InputError, OutOfRangeError
from pocket.core.fluids import as_fluid
from pocket.core.indenters import PLATE
from pocket.core.inputs import quote
from pocket.core.materials import as_material
from pocket.core.sizes import length_warnings, thin_sheet
from pocket.core.units import plain_warnings, positive

from . import indentertable
from .designresult import PAPER_FORCE_FACTOR, PAPER_THICKNESS_FACTOR, Design, finish, paper_rules, sealed
from .inverse import force_where, pressure_for_height, pressure_for_sheet
from .solvers import entry, record

__all__ = ["PAPER_FORCE_FACTOR", "PAPER_THICKNESS_FACTOR", "Design", "design", "paper_rules"]


def _rubber(modulus, material, name):
    """(E in Pa, the rubber in units of mu_0): E is ``modulus`` if given, else that of ``material``'s stresses
    in Pa; a rubber given by alpha needs ``modulus``."""
    rubber = as_material(material)
    by_alpha = rubber.exact_alpha is not None  # in units of mu_0 already (mooney_rivlin)
    if modulus is not None:
        return positive(name("modulus"), modulus, "pressure"), rubber if by_alpha else rubber.scaled()
    if by_alpha:
        raise InputError(f"{name('modulus')} is missing: a Mooney-Rivlin rubber given by alpha = C2/C1 needs the "
                         "modulus E")
    return rubber.modulus, rubber.scaled()


def _target(height_ratio, pressed, name, given, warnings):
    """("height_ratio", h) or ("height", H in m) of the target at F: ``pressed`` if given, else ``height_ratio``
    (0.8 if None)."""
    if pressed is not None:
        if height_ratio is not None:
            raise InputError(f"give {name('height_ratio')} or {name('pressed_height')}, not both")
        si = positive(name("pressed_height"), pressed, "length")
        given["pressed_height"] = pressed
        warnings += length_warnings(name("pressed_height"), pressed, si)
        return "height", si
    ratio = 0.8 if height_ratio is None else height_ratio
    try:
        value = float(ratio)
    except (TypeError, ValueError):
        raise InputError(f"{name('height_ratio')} = {ratio!r} is not a number") from None
    if not 0.0 < value < 1.0:
        raise InputError(f"{name('height_ratio')} = {ratio!r}, but a pressed button needs 0 < H/H0 < 1")
    return "height_ratio", value


def _thin(thickness, radius, given: dict, name) -> list[str]:
    """``pocket.core.sizes.thin_sheet`` of the designed ``thickness`` (m), naming the inputs it comes from."""
    inputs = ", ".join(f"{name(key)} = {quote(value)}" for key, value in given.items())
    return thin_sheet(thickness, radius, f"{inputs} give T = {thickness:.6g} m")


def _gas_force(compress, rubber, phat_i, ratio, fluid, per_fhat, liquid, options) -> float:
    """Step 2' of the module docstring: Fhat* of a gas, Phat_atm = ``per_fhat`` Fhat, in (0, ``liquid``], by the
    solver's entry point ``compress``."""
    from scipy.optimize import brentq

    def miss(f):
        if f == 0.0:
            return 1.0 - ratio
        sealed = {"fluid": dataclasses.replace(fluid, ambient=per_fhat * f)}
        return compress(rubber, phat_i, f, **sealed, **options).height_ratio - ratio

    return brentq(miss, 0.0, liquid, xtol=1e-15, rtol=1e-13)


def _inflated(model, rubber, height, radius, given, name, options) -> float:
    """Step 1: Phat_I* of the inflated height ``height`` (m)."""
    try:
        return pressure_for_height(model, rubber, height / radius, **options)
    except OutOfRangeError as err:
        raise OutOfRangeError(f"{name('height')} = {quote(given['height'])}: no inflated state of the model's first "
                              f"branch is that high ({err})") from None


def _pressure_for_sheet(model, rubber, lengths, given, name, key, target, force, modulus, gas, pressing):
    """(H0 in m or None, Phat_I*, what is solved) of a sheet of known thickness: step 1 alone with H0 given
    too, else step 2''. of the module docstring."""
    radius, thickness = lengths["radius"], lengths["thickness"]
    if "height" in lengths:
        options = {k: v for k, v in pressing.items() if k != "indenter"}
        phat_i = _inflated(model, rubber, lengths["height"], radius, given, name, options)
        return lengths["height"], phat_i, ("pressure_initial", "height_ratio")
    per = force / (math.pi * radius * modulus * thickness)
    spelled = "pressed_height" if key == "height" else "height_ratio"
    what = f"{name(spelled)} = {quote(given.get(spelled, target))}"
    phat_i = pressure_for_sheet(model, rubber, per, key, target / radius if key == "height" else target, what=what,
                                **gas, **pressing)
    return None, phat_i, ("pressure_initial", "height")


def design(radius, height, modulus, material, force, height_ratio=None, *, thickness=None, pressed_height=None,
           fluid=None, solver="shooting", points=20, indenter=None, name=None, **options) -> Design:
    """A soft button designed by the paper's rules (Table 2) and by the full model; SI numbers or strings with units.

    Give the inflated ``height`` H0 (the thickness T is found), or the sheet's ``thickness`` T (H0 is found), or
    both (H/H0 at F is found). The target at the force F is ``height_ratio`` H/H0 (default 0.8) or the
    ``pressed_height`` H, except when both H0 and T are given. The full model's answer is two scalar roots
    (``pocket.apps.design``): Phat_I* from H0 / R, then Fhat* from the target; P_I = F / (pi R^2 Fhat*) and
    T = P_I R / (E Phat_I*).

    Parameters
    ----------
    radius : float or str
        The clamp radius R (m, or a length with its unit).
    height : float or str or None
        The inflated height H0 (a length), or None with ``thickness``.
    modulus : float or str or None
        E = 3 mu_0 (a pressure); None to take it from ``material``'s stresses in Pa.
    material : Material or float
        The rubber: a ``pocket.core.materials.Material`` (with ``modulus``, any stress unit: only the ratios
        matter), or a Mooney-Rivlin alpha = C2/C1.
    force : float or str
        The finger's force F (N, or a force with its unit).
    height_ratio : float, optional
        The target H/H0 at F (default 0.8).
    thickness : float or str, optional
        The sheet's thickness T (a length), if known.
    pressed_height : float or str, optional
        The target H at F (a length), instead of ``height_ratio``.
    fluid : Fluid, optional
        None (a liquid) or a gas (``pocket.core.fluids.gas``) with its ambient pressure in Pa.
    solver : str, optional
        The solver by name (``"shooting"``, ``"fem"``, ...); ``**options`` its options.
    points : int, optional
        Points of the force-travel curve (the feel), at forces up to 2 F.
    indenter : dict, optional
        None (the flat plate) or an ``[indenter]`` table in physical units (``{"shape": "sphere",
        "radius": "8 mm"}``): what the finger is.
    name : callable, optional
        ``name(key)`` names the inputs in messages (a command line's flags), else their keys.

    Returns
    -------
    Design
        SI values named with their unit, the model's ``pressure_initial`` (Phat_I*) and ``force`` (Fhat*), the
        paper's answer and what it gives in the full model, and the feel.

    Raises
    ------
    InputError
        For missing or contradictory inputs, a length outside the sizes of a pocket, a sheet too thick for a
        membrane. A value without a unit, or T/R above 0.1, is one of the design's ``warnings``.
    OutOfRangeError
        For a target the model's first branch does not reach.

    Examples
    --------
    A button of R = 10 mm and H0 = 3 mm that a 1 N press takes to 80 % of its height:

    >>> from pocket.apps.design import design
    >>> button = design("10 mm", "3 mm", "1 MPa", 0.3, "1 N", points=3)
    >>> print(f"P_I = {button.pressure_initial_Pa / 1e3:.3f} kPa, T = {button.thickness_m * 1e3:.3f} mm")
    P_I = 14.650 kPa, T = 1.462 mm
    >>> print(round(button.height_ratio, 9), button.solved, button.curve_force_N)
    0.8 ('pressure_initial', 'thickness') [0.66666667 1.33333333 2.        ]

    Its model numbers are the definitions Phat_I = P_I R / (E T) and Fhat = F / (P_I pi R^2):

    >>> import math
    >>> print(abs(button.pressure_initial - button.pressure_initial_Pa * 0.01 / (1e6 * button.thickness_m)) < 1e-12,
    ...       abs(button.force - 1 / (button.pressure_initial_Pa * math.pi * 0.01**2)) < 1e-12)
    True True
    """
    name = name or (lambda key: key)
    given = {key: value for key, value in (("radius", radius), ("height", height), ("thickness", thickness),
                                           ("modulus", modulus), ("force", force)) if value is not None}
    if height is None and thickness is None:
        raise InputError(f"give the inflated height {name('height')} (T is found) or the sheet's "
                         f"{name('thickness')} (H0 is found)")
    lengths = {key: positive(name(key), given[key], "length") for key in ("radius", "height", "thickness")
               if key in given}
    force = positive(name("force"), force, "force")
    modulus, rubber = _rubber(modulus, material, name)
    warnings = [w for key, si in lengths.items() for w in length_warnings(name(key), given[key], si)]
    warnings += [w for key, kind in (("modulus", "pressure"), ("force", "force")) if key in given
                 for w in plain_warnings(name(key), given[key], kind)]
    radius = lengths["radius"]
    if "height" in lengths and "thickness" in lengths:
        if height_ratio is not None or pressed_height is not None:
            raise InputError(f"{name('height')} and {name('thickness')} fix the pocket: H/H0 at F is found, so "
                             f"{name('height_ratio')} and {name('pressed_height')} are not given with both")
        key, target = "height_ratio", None
    else:
        key, target = _target(height_ratio, pressed_height, name, given, warnings)
    fluid = as_fluid(fluid)
    finger = PLATE if indenter is None else indentertable.parse(indenter, radius, warnings=warnings,
                                                                spell=lambda k: name(f"indenter.{k}"))
    pressing = {**options, **({} if finger == PLATE else {"indenter": finger})}  # the compressions' options
    model = record(solver)
    if "thickness" in lengths:
        thickness = lengths["thickness"]
        warnings += thin_sheet(thickness, radius, f"{name('thickness')} = {quote(given['thickness'])}, "
                               f"{name('radius')} = {quote(given['radius'])}")
        height, phat_i, solved = _pressure_for_sheet(model, rubber, lengths, given, name, key, target, force,
                                                     modulus, sealed(fluid, modulus * thickness / radius), pressing)
        p_i = phat_i * modulus * thickness / radius
        fhat = force / (p_i * math.pi * radius**2)
    else:
        height = lengths["height"]
        assert target is not None  # a height without a thickness: _target gave the pressed height's target
        ratio = target if key == "height_ratio" else target / height
        if not ratio < 1.0:
            raise InputError(f"{name('pressed_height')} = {quote(pressed_height)}, but it must be below the "
                             f"inflated height {name('height')} = {quote(given['height'])}")
        phat_i = _inflated(model, rubber, height, radius, given, name, options)
        fhat = force_where(model, rubber, phat_i, "height_ratio", ratio, increasing=False, **pressing)
        if fluid.is_gas:
            fhat = _gas_force(entry(model, "compress", "a design"), rubber, phat_i, ratio, fluid,
                              fluid.ambient * phat_i * math.pi * radius**2 / force, fhat, pressing)
        p_i = force / (math.pi * radius**2 * fhat)  # steps 3 and 4
        thickness = p_i * radius / (modulus * phat_i)
        warnings += _thin(thickness, radius, given, name)
        solved = ("pressure_initial", "thickness")
    return finish(model, rubber, fluid, pressing, radius=radius, height=height, thickness=thickness,
                   modulus=modulus, force=force, p_i=p_i, phat_i=phat_i, fhat=fhat, points=points, solved=solved,
                   warnings=warnings)


