"""What a design answers (``pocket.apps.design``): the ``Design`` record, the paper's rules, and the pocket
found made into one, with what the paper's rules give in the full model and the feel (the force-travel
curve to twice the force, or to just inside the end of the model's range, and its stiffness)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from pocket.core.errors import OutOfRangeError
from pocket.core.fluids import Fluid
from pocket.core.materials import Material

from .inverse import range_end
from .slopes import curve_with_slopes
from .solvers import entry

__all__ = [
    "PAPER_FORCE_FACTOR",
    "PAPER_THICKNESS_FACTOR",
    "Design",
    "finish",
    "paper_height",
    "paper_rules",
    "sealed",
]

PAPER_FORCE_FACTOR = 5.7  # P_I = 5.7 F / (pi R^2): Fhat = 1/5.7 gives H/H0 ~ 0.8 (paper's figure 3b)
PAPER_THICKNESS_FACTOR = 0.216  # T = 0.216 P_I R^4 / (E H0^3) (Bouremel et al. 2017)


@dataclasses.dataclass(frozen=True)
class Design:
    """A button design (``pocket.apps.design.design``): SI values carry their unit in the name.

    Attributes
    ----------
    pressure_initial_Pa, thickness_m, height_m, height_ratio : float
        The design: P_I, T, the inflated height H0 and H/H0 at F.
    paper_pressure_initial_Pa, paper_thickness_m, paper_height_m : float
        The paper's rules' answer (``paper_rules``).
    paper_model_height_m, paper_model_height_ratio : float or None
        The H0 and H/H0 that the paper's (P_I, T) give in the full model (None: no such state).
    pressure_initial, force : float
        The model's dimensionless answer, Phat_I* and Fhat*.
    stiffness_N_per_m : float
        dF/d(travel) at F.
    curve_force_N, curve_travel_m, curve_stiffness_N_per_m : numpy.ndarray
        The feel: force, travel H0 - H and stiffness, shape (n,).
    curve_limited : bool
        Whether the curve stops short of 2 F, at the end of the model's range.
    material : Material
        The rubber, in units of mu_0.
    fluid : Fluid
        The fluid, a gas's ambient pressure in Pa.
    ambient : float or None
        A gas's Phat_atm = P_atm R / (E T) at the designed T.
    warnings : tuple of str
        On the inputs and the design (a plain length in m, a thick sheet).
    solved : tuple of str
        The SI values found (the others were given): ``("pressure_initial", "thickness")`` from H0,
        ``("pressure_initial", "height")`` from T, ``("pressure_initial", "height_ratio")`` from both.

    Examples
    --------
    Its SI values carry their unit in their names (``design`` shows one made):

    >>> import dataclasses
    >>> from pocket.apps.design import Design
    >>> print([field.name for field in dataclasses.fields(Design) if field.name.endswith("_Pa")])
    ['pressure_initial_Pa', 'paper_pressure_initial_Pa']
    """

    pressure_initial_Pa: float
    thickness_m: float
    height_m: float  # the inflated height H0
    height_ratio: float  # H/H0 at F
    paper_pressure_initial_Pa: float
    paper_thickness_m: float
    paper_height_m: float
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
    solved: tuple[str, ...] = ("pressure_initial", "thickness")

    def report(self) -> dict:
        """JSON-ready: the full model's answer, the paper's, their ratios, what was ``solved`` (a list), the rubber
        (units of mu_0) and the fluid (``ambient_Pa``, and ``ambient`` as Phat_atm of the design), the warnings (a
        list), the curve."""
        skip = ("material", "fluid", "ambient", "warnings", "solved")
        out = {f.name: getattr(self, f.name) for f in dataclasses.fields(self)
               if not f.name.startswith("curve_") and f.name not in skip}
        out.update(self.material.describe())
        out["fluid"] = self.fluid.kind
        if self.fluid.is_gas:
            out.update(ambient_Pa=self.fluid.ambient, gamma=self.fluid.gamma, ambient=self.ambient)
        out["pressure_initial_ratio_paper_to_model"] = self.paper_pressure_initial_Pa / self.pressure_initial_Pa
        out["thickness_ratio_paper_to_model"] = self.paper_thickness_m / self.thickness_m
        out["height_ratio_paper_to_model"] = self.paper_height_m / self.height_m
        out["solved"] = list(self.solved)
        out["curve_limited"] = self.curve_limited
        out["warnings"] = list(self.warnings)
        out["curve"] = [{"force_N": f, "travel_m": t, "stiffness_N_per_m": k} for f, t, k in
                        zip(self.curve_force_N.tolist(), self.curve_travel_m.tolist(),
                            self.curve_stiffness_N_per_m.tolist(), strict=True)]
        return out


def paper_rules(radius, height, modulus, force) -> tuple[float, float]:
    """(P_I, T) by the paper's Table 2: P_I = 5.7 F / (pi R^2), T = 0.216 P_I R^4 / (E H0^3).

    Parameters
    ----------
    radius : float
        R, m.
    height : float
        H0, m.
    modulus : float
        E, Pa.
    force : float
        F, N.

    Returns
    -------
    tuple of float
        P_I in Pa and T in m.

    Examples
    --------
    >>> import math
    >>> from pocket.apps.design import paper_rules
    >>> p_i, t = paper_rules(0.01, 0.003, 1e6, 1.0)
    >>> print(round(p_i * math.pi * 0.01**2, 12), round(t * 1e3, 4))
    5.7 1.4515
    """
    p_i = PAPER_FORCE_FACTOR * force / (math.pi * radius**2)
    return p_i, PAPER_THICKNESS_FACTOR * p_i * radius**4 / (modulus * height**3)


def paper_height(radius, thickness, modulus, force) -> float:
    """H0 by the paper's Table 2 read for a given sheet: T = 0.216 P_I R^4 / (E H0^3) solved for H0."""
    p_i = PAPER_FORCE_FACTOR * force / (math.pi * radius**2)
    return (PAPER_THICKNESS_FACTOR * p_i * radius**4 / (modulus * thickness)) ** (1.0 / 3.0)


def sealed(fluid: Fluid, scale: float) -> dict:
    """The ``fluid`` keyword of a pocket of pressure scale E T / R (Pa): a gas's Phat_atm; nothing for a liquid."""
    return {"fluid": fluid.scaled(scale)} if fluid.is_gas else {}


def finish(model, rubber, fluid, pressing, *, radius, height, thickness, modulus, force, p_i, phat_i, fhat, points,
            solved, warnings) -> Design:
    """The ``Design`` of the pocket found, SI values (``height`` None: the inflated one's) and the model's
    (``phat_i``, ``fhat``): the paper's answer and what it gives in the full model, and the feel."""
    compress = entry(model, "compress", "a design")
    gas = sealed(fluid, modulus * thickness / radius)
    if "thickness" in solved or "height_ratio" in solved:
        paper_p, paper_t = paper_rules(radius, height, modulus, force)
        paper_h = height
    else:
        paper_p, paper_t = PAPER_FORCE_FACTOR * force / (math.pi * radius**2), thickness
        paper_h = paper_height(radius, thickness, modulus, force)
    paper_model: tuple[float | None, float | None]
    try:
        paper_state = compress(rubber, paper_p * radius / (modulus * paper_t), force / (paper_p * math.pi * radius**2),
                               **sealed(fluid, modulus * paper_t / radius), **pressing)
        paper_model = paper_state.inflated.height * radius, paper_state.height_ratio
    except OutOfRangeError:  # the paper's rules can ask for a state the model does not have
        paper_model = None, None
    top = range_end(model, rubber, phat_i, below=2.0 * fhat, **gas, **pressing)
    limited = top < 2.0 * fhat
    top *= 1.0 - 1e-3 if limited else 1.0  # room for the slope's stencil (pocket/slopes.py, 1e-4 f)
    forces = top * np.arange(1, points + 1) / points
    states, slopes = curve_with_slopes(model, rubber, phat_i, [fhat, *forces], ["height_ratio"], **gas, **pressing)
    height = states[0].inflated.height * radius if height is None else height
    scale = p_i * math.pi * radius**2
    stiffness = -scale / (height * slopes["height_ratio"])
    return Design(pressure_initial_Pa=p_i, thickness_m=thickness, height_m=height,
                  height_ratio=float(states[0].height_ratio), paper_pressure_initial_Pa=paper_p,
                  paper_thickness_m=paper_t, paper_height_m=paper_h, paper_model_height_m=paper_model[0],
                  paper_model_height_ratio=paper_model[1], pressure_initial=phat_i, force=fhat,
                  stiffness_N_per_m=float(stiffness[0]), curve_force_N=forces * scale,
                  curve_travel_m=np.array([height * (1.0 - s.height_ratio) for s in states[1:]]),
                  curve_stiffness_N_per_m=stiffness[1:], curve_limited=limited,
                  material=rubber, fluid=fluid,
                  ambient=gas["fluid"].ambient if gas else None, warnings=tuple(warnings), solved=solved)
