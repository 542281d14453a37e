"""``pocket fit DATA.csv [DATA2.csv ...] --law LAW --radius R [--thickness T]``: a law's parameters from tests."""

from __future__ import annotations

import json
import sys

from pocket.apps.fitdata import QUANTITIES
from pocket.core.errors import InputError
from pocket.core.inputs import quote
from pocket.core.materials import LAWS

from .common import EXIT_CODES

__all__ = ["register"]


def _pairs(values, flag: str) -> dict:
    out = {}
    for text in values or ():
        name, sep, value = text.partition("=")
        if not sep or not name.strip() or not value.strip():
            raise InputError(f"{flag} = {quote(text)}, but it must be KEY=VALUE")
        out[name.strip()] = value.strip()
    return out


def _fixed(args, thickness) -> dict:
    """--fix KEY=VALUE: stresses with a unit (they need --thickness), numbers plain."""
    from pocket.apps.fitkeys import key_named, keys
    from pocket.core.units import quantity

    all_keys = keys(args.law, args.terms)
    out = {}
    for name, text in _pairs(args.fix, "--fix").items():
        key = key_named(all_keys, name, "--fix")
        if key.unit == "stress":
            if thickness is None:
                raise InputError(f"--fix {name}={text}: a stress can be held only with --thickness (without it the "
                                 "fit works with stress * T)")
            out[name] = quantity(f"--fix {name}", text, "pressure")
        else:
            try:
                out[name] = float(text)
            except ValueError:
                raise InputError(f"--fix {name} = {quote(text)} is not a number") from None
    return out


def _sigma(args) -> dict:
    from pocket.core.units import positive

    out = {}
    for name, text in _pairs(args.sigma, "--sigma").items():
        if name not in QUANTITIES:
            raise InputError(f"--sigma {name}: not a column of test data ({', '.join(QUANTITIES)})")
        out[name] = positive(f"--sigma {name}", text, QUANTITIES[name])
    return out


def _main(args) -> int:
    import pathlib

    from pocket.apps.fit import fit
    from pocket.apps.fitdata import read
    from pocket.apps.fitmodel import Setup
    from pocket.apps.fitreport import KIND, summary, write
    from pocket.apps.folders import check_replaceable
    from pocket.core.units import positive

    radius = positive("--radius", args.radius, "length")
    thickness = None if args.thickness is None else positive("--thickness", args.thickness, "length")
    initial = None if args.initial_pressure is None else positive("--initial-pressure", args.initial_pressure,
                                                                  "pressure")
    fixed, sigma = _fixed(args, thickness), _sigma(args)
    tests = tuple(read(path, initial) for path in args.data)
    for name in sigma:
        if not any(name in t.responses for t in tests):
            raise InputError(f"--sigma {name}: no test has {name} data")
    target = None if args.out is None else check_replaceable(pathlib.Path(args.out), KIND, "--out")
    result = fit(Setup(tests, radius, thickness, args.solver, {}, sigma), args.law, terms=args.terms, fixed=fixed,
                 prestretch=args.fit_prestretch)
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
    if not thickness:
        print("# no --thickness: the membrane model sees the rubber only through mu_0 T, so stresses are given "
              "times T (N/m)")
    print(f"{'key':>14}  {'value':>14}  {'std. error':>11}  {'95 % interval':>31}  unit")
    for name, p in out["parameters"].items():
        lo, hi = p["interval_95"]
        print(f"{name:>14}  {p['value']:>14.8g}  {p['standard_error']:>11.3g}  [{lo:>14.8g}, {hi:>14.8g}]  {p['unit']}")
    for name, p in out["fixed"].items():
        print(f"{name:>14}  {p['value']:>14.8g}  {'(fixed)':>11}  {'':>31}  {p['unit']}")
    print(f"{'mu_0':>14}  {out['mu0']['value']:>14.8g}  {out['mu0']['standard_error']:>11.3g}  {'':>31}  "
          f"{out['mu0']['unit']}")
    print(f"residual RMS {out['residual_rms']:.4g} ({out['residuals']})")
    if target is not None:
        print(f"wrote {target}")
    return 0


def register(subparsers) -> None:
    """Add ``pocket fit``."""
    text = "fit a rubber law's parameters to bulge (inflation) and compression test data, with uncertainties"
    p = subparsers.add_parser(
        "fit", help=text, epilog=EXIT_CODES,
        description=f"{text}. Each CSV file is one test; its header names each column's quantity and unit. An "
        "inflation test: 'pressure [kPa],height [mm]' (and/or 'volume [mL]'), pressures increasing. A compression "
        "test by the flat plate: 'force [N],pressure [kPa]' (and optionally 'height [mm]'), at --initial-pressure "
        "or the pressure of its row at zero force. Several files are fitted jointly. Residuals are relative, or in "
        "units of a column's --sigma. Reports each parameter with its standard error (from the Jacobian and the "
        "residual variance), 95 %% interval, the correlations and warnings where the data do not determine a "
        "parameter.")
    p.add_argument("data", nargs="+", metavar="DATA.csv", help="test data files")
    p.add_argument("--law", choices=tuple(LAWS), default="mooney-rivlin", help="the law to fit")
    p.add_argument("--radius", required=True, help="clamp radius R, e.g. '20 mm'")
    p.add_argument("--thickness", help="sheet thickness T, e.g. '1 mm' (without it: stresses times T, N/m)")
    p.add_argument("--initial-pressure", help="initial pressure P_I of the compression tests, e.g. '5 kPa'")
    p.add_argument("--terms", type=int, default=1, help="Ogden terms (1 to 3; default 1)")
    p.add_argument("--fix", action="append", metavar="KEY=VALUE",
                   help="hold a parameter: a stress with a unit ('c1=160 kPa'), a number plain ('jm=10', "
                   "'prestretch=1.1')")
    p.add_argument("--fit-prestretch", action="store_true",
                   help="also fit the equibiaxial prestretch of the clamped sheet (key prestretch; otherwise "
                   "held at 1, or at its --fix value)")
    p.add_argument("--sigma", action="append", metavar="COLUMN=VALUE",
                   help="a column's measurement uncertainty ('height=0.01 mm'): its residuals in units of it")
    p.add_argument("--solver", choices=("shooting", "fem"), default="shooting", help="the model's solver")
    p.add_argument("--json", action="store_true", help="print the result as one JSON object")
    p.add_argument("--out", metavar="DIR", help="also write DIR/fit.png (data, fitted curve, residuals) and "
                   "DIR/fitted.toml (the fitted sheet, for pocket run)")
    p.set_defaults(handler=_main)
