"""``pocket validate`` and ``pocket converge``: the validation suite and its report (``pocket.validation``).

    pocket validate [--out DIR] [--quick] [--cases FILE]
    pocket converge [--out DIR] [--quick] [--cases FILE]

Both print a short summary and exit 1 if any verdict fails (0 otherwise; 2 for
bad input, through ``pocket.cli``).
"""

from __future__ import annotations

import sys
import time
from concurrent.futures import ProcessPoolExecutor

__all__ = ["register"]

EXIT_CODES_VALIDATE = ("exit status: 0 every verdict passes; 1 a verdict fails, a solver failed or the report "
                       "could not be written; 2 bad input (one line on stderr, nothing written)")


def register(subparsers) -> None:
    """Add the ``validate`` and ``converge`` parsers."""
    for name, handler, text, out in (
            ("validate", _validate, "run the validation suite and write the report", "validation-report"),
            ("converge", _converge, "mesh-convergence study of the FE model against shooting", "convergence-report")):
        p = subparsers.add_parser(name, help=text, description=text, epilog=EXIT_CODES_VALIDATE)
        p.add_argument("--out", default=out, help=f"report folder (default: {out}); a previous report is replaced")
        p.add_argument("--quick", action="store_true", help="fewer cases, forces and meshes (CI, under 30 s)")
        p.add_argument("--cases", help="cases file (default: the built-in cases of the suite)")
        p.set_defaults(handler=handler)


def _setup(args):
    from pocket.validation.plan import DEFAULT, QUICK
    from pocket.validation.report import check_target
    from pocket.validation.suite import CASES_FILE, load

    check_target(args.out)
    cases, design = load(args.cases or CASES_FILE)
    return cases, design, QUICK if args.quick else DEFAULT


def _finish(results, out, start, pool) -> int:
    from pocket.validation.report import write_report
    from pocket.validation.sections import counts

    path = write_report(results, out, executor=pool)
    n = counts(results)
    print(f"{'FAIL' if n['fail'] else 'PASS'}: {n['pass']} checks pass, {n['fail']} fail, {n['info']} informational "
          f"({time.perf_counter() - start:.1f} s, plan {results.plan.name})")
    for check in results.failed[:10]:
        print(f"  fail: {check.case} {check.comparison} {check.quantity} ({check.where}): error {check.error:.3g} "
              f"> {check.tolerance:.3g}")
    for finding in results.findings:
        print(f"  paper: {finding.title}: {finding.verdict}")
    print(f"report: {path / 'index.html'} (also report.md)")
    return 1 if n["fail"] else 0


def _validate(args) -> int:
    from pocket.validation.runner import WORKERS, run

    start = time.perf_counter()
    cases, design, plan = _setup(args)
    with ProcessPoolExecutor(max_workers=WORKERS) as pool:
        results = run(cases, design, plan, executor=pool, progress=sys.stderr.isatty())
        return _finish(results, args.out, start, pool)


def _converge(args) -> int:
    from pocket.validation.runner import WORKERS, run

    start = time.perf_counter()
    cases, design, plan = _setup(args)
    with ProcessPoolExecutor(max_workers=WORKERS) as pool:
        results = run(cases, design, plan, executor=pool, progress=sys.stderr.isatty(), convergence_only=True)
        _print_orders(results)
        return _finish(results, args.out, start, pool)


def _print_orders(results) -> None:
    from pocket.validation.convergence import richardson

    for check in results.checks:
        if check.step == "order":
            print(f"  {check.comparison:<24} {check.where:<22} {check.quantity:<15} observed order {check.value:.2f}"
                  + (f" (expected {check.reference:g} +- {check.tolerance:g}: {check.verdict})"
                     if check.tolerance is not None else ""))
    for seq in results.sequences:
        for quantity, values in seq.values.items():
            extrapolated = richardson(seq.sizes, values)
            text = (f"{extrapolated[0]:.12g} +- {extrapolated[1]:.2g}" if extrapolated
                    else "not monotone, no extrapolation")
            print(f"  Richardson P{seq.order} {seq.mesh:<8} {seq.study:<12} {quantity:<15} {text:<32} "
                  f"shooting {seq.reference[quantity]:.12g}")
