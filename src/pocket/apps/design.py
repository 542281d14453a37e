r"""Designing a soft button (the paper's section 6, Table 2): P_I and T from R, H0, E, F, H/H0.

Given the clamp radius R, the inflated height H0, the modulus E = 3 mu_0 (and the
rubber: a Mooney-Rivlin alpha, or another law with its parameters in any unit,
only their ratios matter), the fluid, the finger force F and the target height
ratio H/H0 = h at that force, find the initial pressure P_I and the thickness T.

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

Feel: the force-travel curve F(H0 - H) at forces up to twice F (or to just
inside the end of the model's range, if that comes first), and its
stiffness dF/d(travel) = -(P_I pi R^2 / H0) / (d(H/H0)/dFhat), the slope from
``pocket.apps.slopes`` (central differences), with the designed fluid.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from pocket.core.errors import InputError, OutOfRangeError
from pocket.core.fluids import Fluid, as_fluid
from pocket.core.indenters import FLAT
from pocket.core.inputs import quote
from pocket.core.materials import Material, as_material
from pocket.core.sizes import length_warnings, thin_sheet
from pocket.core.units import positive

from . import indenters
from .inverse import force_where, pressure_for_height, range_end
from .slopes import curve_with_slopes
from .solvers import entry, record

__all__ = ["Design", "design", "paper_rules", "PAPER_FORCE_FACTOR", "PAPER_THICKNESS_FACTOR"]

PAPER_FORCE_FACTOR = 5.7  # P_I = 5.7 F / (pi R^2): Fhat = 1/5.7 gives H/H0 ~ 0.8 (paper's figure 3b)
PAPER_THICKNESS_FACTOR = 0.216  # T = 0.216 P_I R^4 / (E H0^3) (Bouremel et al. 2017)


@dataclasses.dataclass(frozen=True)
class Design:
    """A button design: SI values carry their unit in the name; ``pressure_initial`` (Phat_I*)
    and ``force`` (Fhat*) are the model's dimensionless answer."""

    pressure_initial_Pa: float
    thickness_m: float
    paper_pressure_initial_Pa: float
    paper_thickness_m: float
    paper_model_height_m: float | None  # H0 that the paper's (P_I, T) give in the full model
    paper_model_height_ratio: float | None  # H/H0 that they give at F (None: no such state)
    pressure_initial: float
    force: float
    stiffness_N_per_m: float  # dF/d(travel) at F
    curve_force_N: np.ndarray  # shape (n,)
    curve_travel_m: np.ndarray  # H0 - H, shape (n,)
    curve_stiffness_N_per_m: np.ndarray  # dF/d(travel), shape (n,)
    curve_limited: bool  # the curve stops short of 2 F, at the end of the model's range
    material: Material  # the rubber, in units of mu_0
    fluid: Fluid  # the fluid, a gas's ambient pressure in Pa
    ambient: float | None = None  # a gas's Phat_atm = P_atm R / (E T) at the designed T
    warnings: tuple[str, ...] = ()  # on the inputs and the design: a plain length in m, a thick sheet

    def report(self) -> dict:
        """JSON-ready: the full model's answer, the paper's, their ratios, the rubber (units of mu_0) and
        the fluid (``ambient_Pa``, and ``ambient`` as Phat_atm of the design), the warnings (a list), the curve."""
        skip = ("material", "fluid", "ambient", "warnings")
        out = {f.name: getattr(self, f.name) for f in dataclasses.fields(self)
               if not f.name.startswith("curve_") and f.name not in skip}
        out.update(self.material.describe())
        out["fluid"] = self.fluid.kind
        if self.fluid.is_gas:
            out.update(ambient_Pa=self.fluid.ambient, gamma=self.fluid.gamma, ambient=self.ambient)
        out["pressure_initial_ratio_paper_to_model"] = self.paper_pressure_initial_Pa / self.pressure_initial_Pa
        out["thickness_ratio_paper_to_model"] = self.paper_thickness_m / self.thickness_m
        out["curve_limited"] = self.curve_limited
        out["warnings"] = list(self.warnings)
        out["curve"] = [{"force_N": f, "travel_m": t, "stiffness_N_per_m": k} for f, t, k in
                        zip(self.curve_force_N.tolist(), self.curve_travel_m.tolist(),
                            self.curve_stiffness_N_per_m.tolist(), strict=True)]
        return out


def paper_rules(radius, height, modulus, force) -> tuple[float, float]:
    """(P_I, T) by the paper's Table 2."""
    p_i = PAPER_FORCE_FACTOR * force / (math.pi * radius**2)
    return p_i, PAPER_THICKNESS_FACTOR * p_i * radius**4 / (modulus * height**3)


def _check(radius, height, modulus, material, force, height_ratio, fluid):
    values = [positive(k, v, kind) for k, v, kind in (("radius", radius, "length"), ("height", height, "length"),
                                                      ("modulus", modulus, "pressure"), ("force", force, "force"))]
    try:
        ratio = float(height_ratio)
    except (TypeError, ValueError):
        raise InputError(f"height_ratio = {height_ratio!r} is not a number") from None
    if not 0.0 < ratio < 1.0:
        raise InputError(f"height_ratio = {height_ratio!r}, but a pressed button needs 0 < H/H0 < 1")
    rubber = as_material(material)
    if rubber.exact_alpha is None:  # a rubber given by alpha is in units of mu_0 already (mooney_rivlin)
        rubber = rubber.scaled()
    return (*values, rubber, ratio, as_fluid(fluid))


def _thin(thickness, radius, given: dict) -> list[str]:
    """``pocket.core.sizes.thin_sheet`` of the designed ``thickness`` (m), naming the inputs it comes from."""
    inputs = ", ".join(f"{key} = {quote(value)}" for key, value in given.items())
    return thin_sheet(thickness, radius, f"{inputs} give T = {thickness:.6g} m")


def _sealed(fluid: Fluid, scale: float) -> dict:
    """The ``fluid`` keyword of a pocket of pressure scale E T / R (Pa): a gas's Phat_atm; nothing for a liquid."""
    return {"fluid": fluid.scaled(scale)} if fluid.is_gas else {}


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


def design(radius, height, modulus, material, force, height_ratio=0.8, *, fluid=None, solver="shooting", points=20,
           indenter=None, spell=None, **options) -> Design:
    """Design by the paper's rules and by the full model (module docstring); SI numbers or strings with units.

    ``material``: a ``pocket.core.materials.Material`` (any stress unit: ``modulus`` sets E = 3 mu_0; a
    number is taken as a Mooney-Rivlin alpha = C2/C1, ``as_material``). ``fluid``: None (a liquid) or a
    gas (``pocket.core.fluids.gas``) with its ambient pressure in Pa. ``indenter``: None (the flat plate)
    or an ``[indenter]`` table in physical units (``pocket.apps.indenters.parse``: ``{"shape": "sphere",
    "radius": "8 mm"}``), what the finger is; ``spell(key)``, if given, names its keys in messages (a command
    line's flags), else they are ``indenter.<key>``.

    A length outside the sizes of a pocket, or a designed sheet too thick for a membrane, is an ``InputError``;
    a plain length above 1 m (probably meant in mm) or T/R above 0.1 is one of the design's ``warnings``
    (``pocket.core.sizes``).
    """
    given = {"radius": radius, "height": height, "modulus": modulus, "force": force}
    radius, height, modulus, force, rubber, ratio, fluid = _check(radius, height, modulus, material, force,
                                                                  height_ratio, fluid)
    warnings = [w for key, si in (("radius", radius), ("height", height)) for w in length_warnings(key, given[key], si)]
    named = {} if spell is None else {"spell": spell}
    finger = FLAT if indenter is None else indenters.parse(indenter, radius, warnings=warnings, **named)
    pressing = {**options, **({} if finger == FLAT else {"indenter": finger})}  # the compressions' options
    model = record(solver)
    compress = entry(model, "compress", "a design")
    try:
        phat_i = pressure_for_height(model, rubber, height / radius, **options)
    except OutOfRangeError as err:
        raise OutOfRangeError(f"height = {quote(given['height'])}: no inflated state of the model's first branch is "
                              f"that high ({err})") from None
    fhat = force_where(model, rubber, phat_i, "height_ratio", ratio, increasing=False, **pressing)
    if fluid.is_gas:
        fhat = _gas_force(compress, rubber, phat_i, ratio, fluid, fluid.ambient * phat_i * math.pi * radius**2 / force,
                          fhat, pressing)
    p_i = force / (math.pi * radius**2 * fhat)
    thickness = p_i * radius / (modulus * phat_i)
    warnings += _thin(thickness, radius, given)
    sealed = _sealed(fluid, modulus * thickness / radius)
    paper_p, paper_t = paper_rules(radius, height, modulus, force)
    paper_phat = paper_p * radius / (modulus * paper_t)
    try:
        paper_state = compress(rubber, paper_phat, force / (paper_p * math.pi * radius**2),
                                     **_sealed(fluid, modulus * paper_t / radius), **pressing)
        paper_model = paper_state.inflated.height * radius, paper_state.height_ratio
    except OutOfRangeError:  # the paper's rules can ask for a state the model does not have
        paper_model = None, None
    top = range_end(model, rubber, phat_i, below=2.0 * fhat, **sealed, **pressing)
    limited = top < 2.0 * fhat
    top *= 1.0 - 1e-3 if limited else 1.0  # room for the slope's stencil (pocket/slopes.py, 1e-4 f)
    forces = top * np.arange(1, points + 1) / points
    states, slopes = curve_with_slopes(model, rubber, phat_i, [fhat, *forces], ["height_ratio"], **sealed, **pressing)
    scale = p_i * math.pi * radius**2
    stiffness = -scale / (height * slopes["height_ratio"])
    return Design(pressure_initial_Pa=p_i, thickness_m=thickness, paper_pressure_initial_Pa=paper_p,
                  paper_thickness_m=paper_t, paper_model_height_m=paper_model[0],
                  paper_model_height_ratio=paper_model[1], pressure_initial=phat_i, force=fhat,
                  stiffness_N_per_m=float(stiffness[0]), curve_force_N=forces * scale,
                  curve_travel_m=np.array([height * (1.0 - s.height_ratio) for s in states[1:]]),
                  curve_stiffness_N_per_m=stiffness[1:], curve_limited=limited,
                  material=rubber, fluid=fluid,
                  ambient=sealed["fluid"].ambient if sealed else None, warnings=tuple(warnings))
