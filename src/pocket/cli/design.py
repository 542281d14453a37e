"""``pocket design``: a soft button's P_I and T from R, H0, E, F and H/H0 (or P_I and H0 from a sheet's T), by the
paper's rules and the full model, every dimensional value with its unit."""

from __future__ import annotations

import dataclasses
import json
import sys

from pocket.apps.design import design
from pocket.apps.rubbers import DEFAULT_LAW
from pocket.core.errors import InputError
from pocket.core.inputs import quote
from pocket.core.materials import LAWS

from .common import PHYSICAL_UNITS, flag, number, physical_help, solvers_epilog
from .indenterflags import add_indenter_flags, indenter_table
from .indenterflags import flag as indenter_flag
from .laws import add_fluid_flags, add_rubber_flags, fluid_of, material_of

__all__ = ["register"]


def _name(key: str) -> str:
    """The flag of a design's input ``key`` (``indenter.radius``: ``--indenter-radius``), for messages."""
    return indenter_flag(key.removeprefix("indenter.")) if key.startswith("indenter.") else flag(key)


def _main(args) -> int:
    warnings: list[str] = []
    material = material_of(args, warnings)
    if args.law != DEFAULT_LAW and args.modulus is not None:
        stresses = ", ".join(f"--{q.name}" for q in LAWS[args.law].parameters if q.unit == "stress")
        raise InputError(f"--modulus = {quote(args.modulus)} is given beside the {args.law} law's stresses "
                         f"({stresses}), which set E = 3 mu_0 (here {material.modulus:.6g} Pa) themselves: leave out "
                         "--modulus, or scale the stresses to it")
    fluid = fluid_of(args, warnings)
    result = design(args.radius, args.height, args.modulus, material, args.force, args.height_ratio,
                    thickness=args.thickness, pressed_height=args.pressed_height, fluid=fluid, solver=args.solver,
                    indenter=indenter_table(args), name=_name)
    result = dataclasses.replace(result, warnings=(*warnings, *(w for w in result.warnings if w not in warnings)))
    for text in result.warnings:
        print(f"pocket: warning: {text}", file=sys.stderr)
    if args.json:
        print(json.dumps(result.report()))
        return 0
    fluid = "a liquid" if not result.fluid.is_gas else \
        f"a gas (ambient {result.fluid.ambient:.6g} Pa, gamma {result.fluid.gamma:g}; Phat_atm = {result.ambient:.6g})"
    print(f"# a {result.material.law} rubber, {fluid}")
    print(f"{'':24}{'full model':>14}{'paper rules':>14}{'paper/model':>14}")
    rows = {"pressure_initial": ("initial pressure P_I, Pa", result.pressure_initial_Pa,
                                 result.paper_pressure_initial_Pa),
            "thickness": ("thickness T, m", result.thickness_m, result.paper_thickness_m),
            "height": ("inflated height H0, m", result.height_m, result.paper_height_m)}
    for label, a, b in (rows[key] for key in result.solved if key in rows):
        print(f"{label:24}{a:>14.6g}{b:>14.6g}{b / a:>14.6g}")
    if "height_ratio" in result.solved:
        print(f"H/H0 at F in the full model: {result.height_ratio:.6g}")
    if result.paper_model_height_m is None:
        print("the paper's design in the full model: outside its range (no inflated state on the first branch, "
              "or none compressed at F)")
    else:
        print(f"the paper's design in the full model: H0 = {result.paper_model_height_m:.6g} m, "
              f"H/H0 = {result.paper_model_height_ratio:.6g} at F")
    print(f"Phat_I = {result.pressure_initial:.10g}, Fhat = {result.force:.10g}, "
          f"stiffness at F = {result.stiffness_N_per_m:.6g} N/m")
    if result.curve_limited:
        print(f"the curve stops at F = {result.curve_force_N[-1]:.6g} N, short of 2 F: there the model's range ends "
              "(the free part of the sheet folds onto the clamp plane)")
    print(f"{'force, N':>12}{'travel, m':>14}{'dF/dtravel, N/m':>18}")
    for f, t, k in zip(result.curve_force_N, result.curve_travel_m, result.curve_stiffness_N_per_m, strict=True):
        print(f"{f:>12.6g}{t:>14.6g}{k:>18.6g}")
    return 0


def register(subparsers) -> None:
    """Add ``pocket design``."""
    text = "soft-button design: P_I and T from R, H0, E, F and H/H0, or P_I and H0 from a sheet's T"
    p = subparsers.add_parser("design", help=text, description=f"{text}, by the paper's rules (P_I = 5.7 F / "
                              "(pi R^2), T = 0.216 P_I R^4 / (E H0^3)) and by the full model, with the "
                              "force-travel curve to 2 F and its stiffness. Give --height H0 to find T, or "
                              "--thickness T (a sheet you have) to find H0, or both to find H/H0 at F. "
                              f"{PHYSICAL_UNITS}", epilog=solvers_epilog(("shooting", "fem")))
    p.add_argument("--radius", required=True, metavar="LENGTH", help=f"clamp radius R: {physical_help('length')}")
    p.add_argument("--height", metavar="LENGTH", help="inflated height H0 (T is found): "
                   f"{physical_help('length', '10 mm')}")
    p.add_argument("--thickness", metavar="LENGTH", help="thickness T of the sheet you have (H0 is found): "
                   f"{physical_help('length', '0.5 mm')}")
    p.add_argument("--modulus", metavar="PRESSURE", help="small-strain Young's modulus E = 3 mu_0 of the "
                   "mooney-rivlin rubber (E = 6 (1 + alpha) C1): " + physical_help("pressure") + "; another "
                   "law's stresses set E themselves")
    p.add_argument("--force", required=True, metavar="FORCE", help=f"finger force F: {physical_help('force')}")
    target = p.add_mutually_exclusive_group()
    target.add_argument("--height-ratio", type=number, metavar="H/H0", help="target H/H0 at F, a number "
                        "(default 0.8; not with both --height and --thickness)")
    target.add_argument("--pressed-height", metavar="LENGTH", help="target height H at F instead: "
                        f"{physical_help('length', '8 mm')}")
    p.add_argument("--solver", choices=("shooting", "fem"), default="shooting",
                   help="solver of the full model (each is listed below; default shooting)")
    p.add_argument("--json", action="store_true", help="print JSON (SI units)")
    add_rubber_flags(p)
    add_fluid_flags(p)
    add_indenter_flags(p)
    p.set_defaults(handler=_main)
