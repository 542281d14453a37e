r"""Designing a soft button (the paper's section 6, Table 2): P_I and T from R, H0, E, F, H/H0.

Given the clamp radius R, the inflated height H0, the modulus E (and alpha),
the finger force F and the target height ratio H/H0 = h at that force, find
the initial pressure P_I and the thickness T.

The paper's rules (Table 2): P_I = 5.7 F / (pi R^2), T = 0.216 P_I R^4 / (E H0^3).

The full model. In the model's variables (DESIGN.md) the unknowns enter only as
Phat_I = P_I R / (E T) and Fhat = F / (P_I pi R^2), and

    H0 / R = h0(alpha, Phat_I)                (inflation)
    H / H0 = g(alpha, Phat_I, Fhat)           (compression at fixed volume)

The inflated height depends on Phat_I alone, so the problem decouples:

    1. Phat_I* solves h0(alpha, Phat_I) = H0 / R     (pocket.inverse.pressure_for_height)
    2. Fhat*   solves g(alpha, Phat_I*, Fhat) = h    (pocket.inverse.force_where)
    3. P_I = F / (pi R^2 Fhat*)                      (definition of Fhat)
    4. T   = P_I R / (E Phat_I*)                     (definition of Phat)

Two scalar roots, each monotone on the first branch, so the answer is unique.
P_I depends on R, H0, F and h but not on E, which scales T alone. In the same
terms the paper's rules say Fhat* = 1/5.7 and H0/R = (0.216 Phat_I)^(1/3),
the small-strain law H0/R = c Phat_I^(1/3) with c = 0.6 (the corrected
analytical model has c = 0.5726, ``pocket.analytical.height_constant``).
The paper's (P_I, T) are also fed to the full model, which shows the H0 and
H/H0 they really give.

Feel: the force-travel curve F(H0 - H) at forces up to twice F (or to just
inside the end of the model's range, if that comes first), and its
stiffness dF/d(travel) = -(P_I pi R^2 / H0) / (d(H/H0)/dFhat), the slope from
``pocket.slopes`` (central differences).
"""

from __future__ import annotations

import dataclasses
import json
import math

import numpy as np

from .checks import check_alpha
from .errors import InputError, OutOfRangeError
from .inverse import force_where, pressure_for_height, range_end
from .slopes import curve_with_slopes
from .solvers import get_solver
from .units import positive

__all__ = ["Design", "design", "paper_rules", "register"]

PAPER_FORCE_FACTOR = 5.7  # P_I = 5.7 F / (pi R^2): Fhat = 1/5.7 gives H/H0 ~ 0.8 (paper's figure 3b)
PAPER_THICKNESS_FACTOR = 0.216  # T = 0.216 P_I R^4 / (E H0^3) (Bouremel et al. 2017)


@dataclasses.dataclass(frozen=True)
class Design:
    """A button design, SI units; ``pressure_initial`` and ``force_hat`` are Phat_I* and Fhat*."""

    initial_pressure: float
    thickness: float
    paper_initial_pressure: float
    paper_thickness: float
    paper_model_height: float | None  # H0 that the paper's (P_I, T) give in the full model, m
    paper_model_height_ratio: float | None  # H/H0 that they give at F (None: no such state)
    pressure_initial: float
    force_hat: float
    stiffness: float  # dF/d(travel) at F, N/m
    curve_force: np.ndarray  # N, shape (n,)
    curve_travel: np.ndarray  # H0 - H, m
    curve_stiffness: np.ndarray  # dF/d(travel), N/m
    curve_limited: bool  # the curve stops short of 2 F, at the end of the model's range

    def report(self) -> dict:
        """JSON-ready: the full model's answer, the paper's, their ratio, the curve."""
        return {"initial_pressure": self.initial_pressure, "thickness": self.thickness,
                "paper_initial_pressure": self.paper_initial_pressure, "paper_thickness": self.paper_thickness,
                "initial_pressure_ratio_paper_to_model": self.paper_initial_pressure / self.initial_pressure,
                "thickness_ratio_paper_to_model": self.paper_thickness / self.thickness,
                "paper_model_height": self.paper_model_height,
                "paper_model_height_ratio": self.paper_model_height_ratio,
                "pressure_initial_hat": self.pressure_initial, "force_hat": self.force_hat,
                "stiffness": self.stiffness, "curve_limited": self.curve_limited,
                "curve": [{"force_N": f, "travel_m": t, "stiffness_N_per_m": k} for f, t, k in
                          zip(self.curve_force.tolist(), self.curve_travel.tolist(), self.curve_stiffness.tolist(),
                              strict=True)]}


def paper_rules(radius, height, modulus, force) -> tuple[float, float]:
    """(P_I, T) by the paper's Table 2."""
    p_i = PAPER_FORCE_FACTOR * force / (math.pi * radius**2)
    return p_i, PAPER_THICKNESS_FACTOR * p_i * radius**4 / (modulus * height**3)


def _check(radius, height, modulus, alpha, force, height_ratio):
    values = [positive(k, v, kind) for k, v, kind in (("radius", radius, "length"), ("height", height, "length"),
                                                      ("modulus", modulus, "pressure"), ("force", force, "force"))]
    try:
        ratio = float(height_ratio)
    except (TypeError, ValueError):
        raise InputError(f"height_ratio = {height_ratio!r} is not a number") from None
    if not 0.0 < ratio < 1.0:
        raise InputError(f"height_ratio = {height_ratio!r}, but a pressed button needs 0 < H/H0 < 1")
    return (*values, check_alpha(alpha), ratio)


def design(radius, height, modulus, alpha, force, height_ratio=0.8, *, solver="shooting", points=20,
           **options) -> Design:
    """Design by the paper's rules and by the full model (module docstring); SI numbers or strings with units."""
    radius, height, modulus, force, alpha, ratio = _check(radius, height, modulus, alpha, force, height_ratio)
    model = get_solver(solver)
    phat_i = pressure_for_height(model, alpha, height / radius, **options)
    fhat = force_where(model, alpha, phat_i, "height_ratio", ratio, increasing=False, **options)
    p_i = force / (math.pi * radius**2 * fhat)
    thickness = p_i * radius / (modulus * phat_i)
    paper_p, paper_t = paper_rules(radius, height, modulus, force)
    paper_phat = paper_p * radius / (modulus * paper_t)
    try:
        paper_state = model.compress(alpha, paper_phat, force / (paper_p * math.pi * radius**2), **options)
        paper_model = paper_state.inflated.height * radius, paper_state.height_ratio
    except OutOfRangeError:  # the paper's rules can ask for a state the model does not have
        paper_model = None, None
    top = range_end(model, alpha, phat_i, below=2.0 * fhat, **options)
    limited = top < 2.0 * fhat
    top *= 1.0 - 1e-3 if limited else 1.0  # room for the slope's stencil (pocket/slopes.py, 1e-4 f)
    forces = top * np.arange(1, points + 1) / points
    states, slopes = curve_with_slopes(model, alpha, phat_i, [fhat, *forces], ["height_ratio"], **options)
    scale = p_i * math.pi * radius**2
    stiffness = -scale / (height * slopes["height_ratio"])
    return Design(initial_pressure=p_i, thickness=thickness, paper_initial_pressure=paper_p,
                  paper_thickness=paper_t, paper_model_height=paper_model[0],
                  paper_model_height_ratio=paper_model[1], pressure_initial=phat_i, force_hat=fhat,
                  stiffness=float(stiffness[0]), curve_force=forces * scale,
                  curve_travel=np.array([height * (1.0 - s.height_ratio) for s in states[1:]]),
                  curve_stiffness=stiffness[1:], curve_limited=limited)


def _main(args) -> int:
    result = design(args.radius, args.height, args.modulus, args.alpha, args.force, args.height_ratio,
                    solver=args.solver)
    if args.json:
        print(json.dumps(result.report()))
        return 0
    print(f"{'':24}{'full model':>14}{'paper rules':>14}{'paper/model':>14}")
    for label, a, b in (("initial pressure P_I, Pa", result.initial_pressure, result.paper_initial_pressure),
                        ("thickness T, m", result.thickness, result.paper_thickness)):
        print(f"{label:24}{a:>14.6g}{b:>14.6g}{b / a:>14.6g}")
    if result.paper_model_height is None:
        print("the paper's design in the full model: outside its range (no inflated state on the first branch, "
              "or none compressed at F)")
    else:
        print(f"the paper's design in the full model: H0 = {result.paper_model_height:.6g} m, "
              f"H/H0 = {result.paper_model_height_ratio:.6g} at F")
    print(f"Phat_I = {result.pressure_initial:.10g}, Fhat = {result.force_hat:.10g}, "
          f"stiffness at F = {result.stiffness:.6g} N/m")
    if result.curve_limited:
        print(f"the curve stops at F = {result.curve_force[-1]:.6g} N, short of 2 F: there the model's range ends "
              "(the free part of the sheet folds onto the clamp plane)")
    print(f"{'force, N':>12}{'travel, m':>14}{'dF/dtravel, N/m':>18}")
    for f, t, k in zip(result.curve_force, result.curve_travel, result.curve_stiffness, strict=True):
        print(f"{f:>12.6g}{t:>14.6g}{k:>18.6g}")
    return 0


def register(subparsers) -> None:
    """Add ``pocket design``."""
    from .cli import number

    p = subparsers.add_parser("design", help="soft-button design: P_I and T from R, H0, E, F, H/H0")
    p.add_argument("--radius", required=True, help="clamp radius R (SI or with unit: '20 mm')")
    p.add_argument("--height", required=True, help="inflated height H0 ('10 mm')")
    p.add_argument("--modulus", required=True, help="Young's modulus E = 6 (1 + alpha) C1 ('1 MPa')")
    p.add_argument("--alpha", type=number, required=True, help="C2/C1 (fractions allowed: 47/160)")
    p.add_argument("--force", required=True, help="finger force F ('0.67 N')")
    p.add_argument("--height-ratio", type=number, default=0.8, help="target H/H0 at F (default 0.8)")
    p.add_argument("--solver", choices=("shooting", "fem"), default="shooting")
    p.add_argument("--json", action="store_true", help="print JSON (SI units)")
    p.set_defaults(handler=_main)
