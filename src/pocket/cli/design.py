"""``pocket design``: a soft button's P_I and T from R, H0, E, F and H/H0, by the paper's rules and the full model."""

from __future__ import annotations

import json
import sys

from pocket.apps.design import design

from .common import EXIT_CODES, number
from .indenters import add_indenter_flags, flag, indenter_table
from .laws import add_fluid_flags, add_rubber_flags, fluid_of, material_of

__all__ = ["register"]


def _main(args) -> int:
    result = design(args.radius, args.height, args.modulus, material_of(args), args.force, args.height_ratio,
                    fluid=fluid_of(args, physical=True), solver=args.solver, indenter=indenter_table(args),
                    spell=flag)
    for text in result.warnings:
        print(f"pocket: warning: {text}", file=sys.stderr)
    if args.json:
        print(json.dumps(result.report()))
        return 0
    fluid = "a liquid" if not result.fluid.is_gas else \
        f"a gas (ambient {result.fluid.ambient:.6g} Pa, gamma {result.fluid.gamma:g}; Phat_atm = {result.ambient:.6g})"
    print(f"# a {result.material.law} rubber, {fluid}")
    print(f"{'':24}{'full model':>14}{'paper rules':>14}{'paper/model':>14}")
    for label, a, b in (("initial pressure P_I, Pa", result.pressure_initial_Pa, result.paper_pressure_initial_Pa),
                        ("thickness T, m", result.thickness_m, result.paper_thickness_m)):
        print(f"{label:24}{a:>14.6g}{b:>14.6g}{b / a:>14.6g}")
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
    text = "soft-button design: P_I and T from R, H0, E, F and H/H0"
    p = subparsers.add_parser("design", help=text, description=f"{text}, by the paper's rules (P_I = 5.7 F / "
                              "(pi R^2), T = 0.216 P_I R^4 / (E H0^3)) and by the full model, with the "
                              "force-travel curve to 2 F and its stiffness. Values carry units ('20 mm'); "
                              "plain numbers are SI.", epilog=EXIT_CODES)
    p.add_argument("--radius", required=True, help="clamp radius R (SI or with unit: '20 mm')")
    p.add_argument("--height", required=True, help="inflated height H0 ('10 mm')")
    p.add_argument("--modulus", required=True, help="small-strain Young's modulus E = 3 mu_0 ('1 MPa'; "
                   "E = 6 (1 + alpha) C1 for Mooney-Rivlin); it scales the law's parameters, which count only by "
                   "their ratios")
    p.add_argument("--force", required=True, help="finger force F ('0.67 N')")
    p.add_argument("--height-ratio", type=number, default=0.8, help="target H/H0 at F (default 0.8)")
    p.add_argument("--solver", choices=("shooting", "fem"), default="shooting",
                   help="solver of the full model (default shooting)")
    p.add_argument("--json", action="store_true", help="print JSON (SI units)")
    add_rubber_flags(p)
    add_fluid_flags(p, physical=True)
    add_indenter_flags(p, physical=True)
    p.set_defaults(handler=_main)
