"""``pocket fit DATA.csv [DATA2.csv ...] --law LAW --radius R [--thickness T]`` or ``pocket fit CASE.toml``: a
law's parameters from tests; with ``--geometry capsule``, from a closed capsule's tests between two plates."""

from __future__ import annotations

import json
import math
import pathlib
import sys

from pocket.core.errors import InputError
from pocket.core.inputs import quote
from pocket.core.materials import LAWS

from .common import solvers_epilog

__all__ = ["register"]


def _pairs(values, flag: str) -> dict:
    out = {}
    for text in values or ():
        name, sep, value = text.partition("=")
        if not sep or not name.strip() or not value.strip():
            raise InputError(f"{flag} = {quote(text)}, but it must be KEY=VALUE")
        out[name.strip()] = value.strip()
    return out


#: the flags a case file's tables replace, with the table that gives each
_CASE_GIVES = {"law": "sheet.material", "radius": "clamp.radius", "thickness": "sheet.thickness",
               "initial_pressure": "initial.pressure", "terms": "fit.terms", "fix": "fit.fix", "sigma": "fit.sigma",
               "fit_prestretch": "fit.prestretch", "solver": "solver.name"}


def _request(args):
    """What the user asks (``pocket.apps.fit.case.Request``): from a case file, or from the flags."""
    from pocket.apps.fit.capsuledata import QUANTITIES as CAPSULE
    from pocket.apps.fit.case import Request, held, load, uncertainties, unit_warnings
    from pocket.apps.fit.data import QUANTITIES
    from pocket.apps.fit.keys import PRESTRETCH
    from pocket.apps.rubbers import DEFAULT_LAW
    from pocket.core.units import positive

    capsule = args.geometry == "capsule"
    if len(args.data) == 1 and args.data[0].endswith(".toml"):
        if capsule or args.fit_initial_pressure:
            raise InputError(f"{'--geometry capsule' if capsule else '--fit-initial-pressure'}: a case file sets up "
                             "a fit of the clamped sheet; a capsule's fit is set up by the flags")
        for name, key in _CASE_GIVES.items():
            if getattr(args, name) not in (None, False):
                flag = "--" + name.replace("_", "-")
                raise InputError(f"{flag}: the case file {args.data[0]} sets up the fit: give it there ({key})")
        return load(args.data[0])
    if capsule:
        _capsule_flags(args)
    elif args.fit_initial_pressure:
        raise InputError("--fit-initial-pressure: only a capsule's fit (--geometry capsule) fits the initial "
                         "pressure; a compression test of the clamped sheet gives it (or its row at zero force)")
    if args.radius is None:
        raise InputError("--radius is missing: the fit needs the clamp radius (or a case file with a [fit] table)")
    law, terms = args.law or DEFAULT_LAW, 1 if args.terms is None else args.terms
    thickness = None if args.thickness is None else positive("--thickness", args.thickness, "length")
    initial = None if args.initial_pressure is None else _initial(args, capsule)
    fix, sigma = _pairs(args.fix, "--fix"), _pairs(args.sigma, "--sigma")
    if capsule and PRESTRETCH in fix:
        raise InputError(f"--fix {PRESTRETCH}: a capsule's reference sphere is unstressed, it has no prestretch")
    radius = positive("--radius", args.radius, "length")
    quantities = CAPSULE if capsule else QUANTITIES
    fixed, sigma_si = held(law, terms, fix, thickness, "--fix"), uncertainties(sigma, "--sigma", quantities)
    given = {"--radius": (args.radius, "length"), "--thickness": (args.thickness, "length"),
             "--initial-pressure": (args.initial_pressure, "pressure")}
    warnings = unit_warnings(law, terms, given, fix, "--fix", sigma, "--sigma", quantities)
    return Request(tuple(pathlib.Path(p) for p in args.data), law, radius, thickness, initial, terms, fixed, sigma_si,
                   args.fit_prestretch, args.solver or ("fem" if initial == 0.0 else "shooting"), warnings,
                   geometry=args.geometry,
                   fit_initial_pressure=args.fit_initial_pressure)


def _initial(args, capsule: bool) -> float:
    """``--initial-pressure`` in Pa: > 0, or 0 for a capsule (an uninflated one, its P_I held)."""
    from pocket.core.units import positive, quantity

    if capsule and quantity("--initial-pressure", args.initial_pressure, "pressure") == 0.0:
        if args.fit_initial_pressure:
            raise InputError("--fit-initial-pressure from --initial-pressure = 0: an uninflated capsule's P_I is held "
                             "(its fit starts from a positive P_I)")
        return 0.0
    return positive("--initial-pressure", args.initial_pressure, "pressure")


def _capsule_flags(args) -> None:
    """Refuse, in one line, what a capsule's fit cannot take (``pocket.apps.fit.capsuletest``)."""
    if args.radius is None:
        raise InputError("--radius is missing: a capsule's fit needs the capsule's undeformed radius R")
    if args.initial_pressure is None:
        raise InputError("--initial-pressure is missing: a capsule's fit needs its initial pressure P_I (held, 0 for "
                         "an uninflated capsule, or the start of --fit-initial-pressure)")
    if args.fit_prestretch:
        raise InputError("--fit-prestretch: a capsule's reference sphere is unstressed, it has no prestretch to fit")


def _main(args) -> int:
    from pocket.apps.fit.leastsquares import fit
    from pocket.apps.fit.report import KIND, summary, write
    from pocket.apps.folders import check_replaceable

    request = _request(args)
    for text in request.warnings:  # before the data are read: a refusal of them may be the plain number's doing
        print(f"pocket: warning: {text}", file=sys.stderr)
    setup = request.setup()
    target = None if args.out is None else check_replaceable(pathlib.Path(args.out), KIND, "--out")
    if request.geometry == "capsule":
        from pocket.apps.fit import capsuletest

        assert request.initial_pressure is not None  # required by _capsule_flags
        capsule = capsuletest.fit(setup, request.law, request.initial_pressure, terms=request.terms,
                                  fixed=request.fixed, fit_pressure=request.fit_initial_pressure)
        if target is not None:
            write(capsule, target)
        out = capsuletest.summary(capsule)
    else:
        result = fit(setup, request.law, terms=request.terms, fixed=request.fixed, prestretch=request.prestretch)
        if target is not None:
            write(result, target)
        out = summary(result)
    for text in out["warnings"]:
        print(f"pocket: warning: {text}", file=sys.stderr)
    if args.json:
        print(json.dumps(out, indent=1))
        return 0
    print(f"# {out['law']} fitted to {out['data']} data ({', '.join(out['files'])}), solver {out['solver']}: "
          f"{out['solver_calls']} solver calls, {out['seconds']:.2f} s")
    if not request.thickness:
        print("# no thickness: the membrane model sees the rubber only through mu_0 T, so stresses are given "
              "times T (N/m)")
    if "capsule" in out:
        c = out["capsule"]
        print(f"# capsule of radius {out['radius_m']:.6g} m inflated at P_I = {c['initial_pressure_Pa']:.6g} Pa: "
              f"Phat_I = P_I R / (E T) = {c['pressure_initial']:.6g}, stretch lambda_I = {c['stretch_initial']:.8g}, "
              f"gap at first touch {c['gap_initial_m']:.8g} m")
    w = max(14, *(len(name) for name in (*out["parameters"], *out["fixed"])))  # a capsule's initial_pressure
    cw = max(11, *(len(name) for name in out["parameters"]))
    print(f"{'key':>{w}}  {'value':>14}  {'std. error':>11}  {'95 % interval':>31}  unit")
    for name, p in out["parameters"].items():
        lo, hi = (math.inf * sign if end is None else end for end, sign in zip(p["interval_95"], (-1, 1), strict=True))
        print(f"{name:>{w}}  {p['value']:>14.8g}  {p['standard_error']:>11.3g}  [{lo:>14.8g}, {hi:>14.8g}]  "
              f"{p['unit']}")
    for name, p in out["fixed"].items():
        print(f"{name:>{w}}  {p['value']:>14.8g}  {'(fixed)':>11}  {'':>31}  {p['unit']}")
    lo, hi = out["mu0"]["interval_95"]
    print(f"{'mu_0':>{w}}  {out['mu0']['value']:>14.8g}  {out['mu0']['standard_error']:>11.3g}  [{lo:>14.8g}, "
          f"{hi:>14.8g}]  {out['mu0']['unit']}")
    names = out["correlation"]["keys"]
    if len(names) > 1:
        print(f"{'correlation':>{w}}  " + "  ".join(f"{n:>{cw}}" for n in names))
        for name, row in zip(names, out["correlation"]["matrix"], strict=True):
            print(f"{name:>{w}}  " + "  ".join(f"{x:>+{cw}.4f}" for x in row))
    methods: dict[str, list[str]] = {}
    for name, p in out["parameters"].items():
        methods.setdefault(p["interval_method"], []).append(name)
    print("95 % intervals: " + "; ".join(f"{method} for {', '.join(names)}" for method, names in methods.items()) +
          "; linearised for mu_0")
    print(f"residual RMS {out['residual_rms']:.4g} ({out['residuals']})")
    if target is not None:
        print(f"wrote {target}")
    return 0


def register(subparsers) -> None:
    """Add ``pocket fit``."""
    text = ("fit a rubber law's parameters to bulge (inflation) and compression test data (of the clamped sheet, or "
            "of a closed capsule between two plates), with uncertainties")
    p = subparsers.add_parser(
        "fit", help=text, epilog=solvers_epilog(("shooting", "fem")),
        description=f"{text}. Each CSV file is one test; its header names each column's quantity and unit. An "
        "inflation test: 'pressure [kPa],height [mm]' (and/or 'volume [mL]'), pressures increasing. A compression test "
        "by the flat plate: 'force [N],pressure [kPa]' (and optionally 'height [mm]'), at --initial-pressure or the "
        "pressure of its row at zero force. A closed capsule squeezed between two plates (--geometry capsule, the "
        "micromanipulation test): 'force [uN],gap [um]' (the force on each plate, the distance between the plates) or "
        "'force [uN],displacement [um]' (the plates' approach since first touch, 0 at zero force), at "
        "--initial-pressure (held, or fitted with --fit-initial-pressure); its residuals are the gaps' in units of the "
        "diameter 2R, or of --sigma. Several files are fitted jointly (a capsule's: of one capsule). The sheet's "
        "residuals are relative, or in units of a column's --sigma. Reports each parameter with its standard error "
        "(from the Jacobian and the residual variance), 95 % interval (by the profile likelihood where the fit can, "
        "else linearised: the report says which), the correlations and warnings where the data do not determine a "
        "parameter. A value without a unit ('--radius 15') is read in SI (15 m) and said so; data that make such a "
        "reading absurd are refused before solving.")
    p.add_argument("data", nargs="+", metavar="DATA.csv",
                   help="test data files, or one case file (CASE.toml) whose [fit] table names them and whose "
                   "[sheet], [clamp], [initial] and [solver] replace the flags")
    p.add_argument("--law", choices=tuple(LAWS), help="the law to fit (default mooney-rivlin)")
    p.add_argument("--geometry", choices=("pocket", "capsule"), default="pocket",
                   help="the tests' membrane: the clamped sheet (pocket, the default) or a closed capsule squeezed "
                   "between two plates (capsule)")
    p.add_argument("--radius", help="clamp radius R, e.g. '20 mm' (required without a case file); a capsule's "
                   "undeformed radius")
    p.add_argument("--thickness", help="sheet thickness T, e.g. '1 mm' (without it: stresses times T, N/m)")
    p.add_argument("--initial-pressure", help="initial pressure P_I of the compression tests, e.g. '5 kPa' "
                   "(a capsule's: required, > 0; held, or the start of --fit-initial-pressure)")
    p.add_argument("--fit-initial-pressure", action="store_true",
                   help="a capsule's fit: also fit P_I (key initial_pressure), from --initial-pressure")
    p.add_argument("--terms", type=int, help="Ogden terms (1 to 3; default 1)")
    p.add_argument("--fix", action="append", metavar="KEY=VALUE",
                   help="hold a parameter: a stress with a unit ('c1=160 kPa'), a number plain ('jm=10', "
                   "'prestretch=1.1')")
    p.add_argument("--fit-prestretch", action="store_true",
                   help="also fit the equibiaxial prestretch of the clamped sheet (key prestretch; otherwise "
                   "held at 1, or at its --fix value)")
    p.add_argument("--sigma", action="append", metavar="COLUMN=VALUE",
                   help="a column's measurement uncertainty ('height=0.01 mm'): its residuals in units of it")
    p.add_argument("--solver", choices=("shooting", "fem"),
                   help="the model's solver (each is listed below; default shooting, but fem for an uninflated "
                        "capsule, --initial-pressure 0: the shooting solver finds each of its forces by a root over "
                        "its plate heights, about sixty times slower)")
    p.add_argument("--json", action="store_true", help="print the result as one JSON object")
    p.add_argument("--out", metavar="DIR", help="also write DIR/fit.png (data, fitted curve, residuals) and "
                   "DIR/fitted.toml (the fitted sheet, for pocket run; not yet for a capsule)")
    p.set_defaults(handler=_main)
