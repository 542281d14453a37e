"""``pocket validate`` and ``pocket converge``: the validation suite and its report (``pocket.validation``).

    pocket validate [--out DIR] [--quick] [--cases FILE] [--vtk {few,all,none}]
    pocket converge [--out DIR] [--quick] [--cases FILE]

The report folder and the cases file are checked before any solve (a bad one
is one line on stderr, exit 2, nothing written). Both print a short summary and
exit 1 if any verdict fails, a solver fails or the report cannot be written
(then nothing is left behind), 130 if interrupted (Ctrl-C: no report is left),
0 otherwise. The summary quotes the run's wall time, the same figure as the
report, and counts the paper's statements where the paper and the model differ
apart from the verdicts (they are findings about the paper, not failures).
On a terminal a labelled progress bar counts the solves, then a line says the
report is being written.
"""

from __future__ import annotations

import argparse
import contextlib
import sys
import textwrap

from pocket.apps.sweep.workers import local_executor, stop

from .common import path_name

__all__ = ["EXIT_CODES_VALIDATE", "register"]

EXIT_CODES_VALIDATE = ("exit status: 0 every verdict passes; 1 a verdict fails, a solver failed or the report "
                       "could not be written (nothing is left behind); 2 bad input: an --out folder that cannot "
                       "be written or holds something other than a previous report of its kind that pocket wrote, "
                       "a bad cases file (one line on stderr, checked before any solve, nothing written); "
                       "130 interrupted (Ctrl-C: no report is left)")

_VALIDATE = """\
Run the validation suite and write its report: the shooting solver (the
reference), the finite-element model (P1 and P2) and the paper's analytical
model compared on the pockets of the cases file (the paper's Table 1 samples,
alpha = 0 and 1, a Yeoh silicone, an Ogden natural rubber, a Gent rubber near
its lock, and the headline pocket filled with air, isothermal and adiabatic),
each comparison of the solvers with a tolerance and a pass/fail verdict, the
analytical model's error reported (a model's error, not a verdict), and a
wrinkling verdict (both tensions positive) for every state; the paper's figures 2-5
recomputed, a liquid against a gas in one pocket, the other rubbers; a
mesh-convergence study of the FE model; the paper's statements checked against
the full model; a 3-D picture (with the 'render' extra) and the headline
pocket's compression path as VTK files for ParaView. The report opens with two
verdicts: the numerics (the solvers agree and converge: pass or fail) and the
models' limits (where the membrane is within 1 % of the solid, the analytical
model within 1 % of the membrane: measured, not judged). The report folder
holds index.html and report.md (the same content), checks.html and checks.md
(every check), the PNGs and a CSV of every number. Progress shows on a
terminal."""

_CONVERGE = """\
Run the mesh-convergence study alone: the FE model (P1 and P2, uniform meshes
and meshes refined at the contact edge) against the shooting solver on the
headline pocket, inflated and compressed; prints the observed orders against
the theory's and Richardson extrapolations against the shooting values, and
writes them as a report folder (index.html, report.md, CSVs, the plot)."""


def register(subparsers) -> None:
    """Add the ``validate`` and ``converge`` parsers."""
    from pocket.validation.plan import VTK, VTK_STEPS

    for name, handler, text, description, out in (
            ("validate", _validate, "run the validation suite and write its report", _VALIDATE,
             "validation-report"),
            ("converge", _converge, "mesh-convergence study of the FE model against shooting", _CONVERGE,
             "convergence-report")):
        # raw: the description's paragraphs as written, so the epilog is wrapped here
        p = subparsers.add_parser(name, help=text, description=description,
                                  epilog=textwrap.fill(EXIT_CODES_VALIDATE, 79),
                                  formatter_class=argparse.RawDescriptionHelpFormatter)
        p.add_argument("--out", default=out, type=path_name, metavar="DIR",
                       help=f"report folder (default: {out}); a previous report of this command that pocket wrote "
                            "there is replaced, any other non-empty folder is refused")
        p.add_argument("--quick", action="store_true",
                       help="the quick plan: fewer forces, FE columns and meshes (for CI; default: the full plan)")
        p.add_argument("--cases", type=path_name, metavar="FILE",
                       help="cases file (default: the suite's own cases.toml): [[case]] tables, each with a label "
                            "and a case file's [case.sheet], [case.clamp] and [case.initial]; optional name (not "
                            "repeated), tags ('headline' picks the pocket of figure 2 and the convergence study, "
                            "else the first), [case.fluid] and [case.indenter]; no [case.loads] or [case.solver]; "
                            "and one [design] table (the paper's soft button) with exactly radius, height (H0), "
                            "modulus (E), force, alpha and height_ratio (0 < H/H0 < 1), as in cases.toml")
        if name == "validate":
            p.add_argument("--vtk", choices=VTK, default=VTK[0],
                           help=f"the headline pocket's compression path as VTK files for ParaView: {VTK[0]} "
                                f"(default) {VTK_STEPS} of its forces, spread along it, a few MB; all: every force "
                                "of its curve (about 0.6 MB each: tens of MB); none: no VTK")
        p.set_defaults(handler=handler)


def _kind(args) -> str:
    """The kind of report folder the command writes."""
    from pocket.validation.report import KINDS

    return KINDS[args.command == "converge"]


def _setup(args):
    from pocket.validation.plan import DEFAULT, QUICK
    from pocket.validation.report import check_target
    from pocket.validation.suite import CASES_FILE, load

    check_target(args.out, _kind(args))
    pockets, button = load(args.cases or CASES_FILE)
    return pockets, button, QUICK if args.quick else DEFAULT


def _finish(results, args, watch, pool, name) -> int:
    """Write the report (saying so on a terminal), print the summary; the exit status."""
    from pocket.validation import limits
    from pocket.validation.report import write_report
    from pocket.validation.sections import counts

    if sys.stderr.isatty():
        print(f"{name}: writing the report to {args.out} ...", file=sys.stderr, flush=True)
    path = write_report(results, args.out, kind=_kind(args), executor=pool, watch=watch,
                        vtk=getattr(args, "vtk", "none"))
    n = counts(results)
    numerics = limits.tally(c for c in results.checks if limits.is_numerics(c))
    print(f"{'FAIL' if n['fail'] else 'PASS'}: numerics {'FAIL' if numerics['fail'] else 'PASS'}, "
          f"{numerics['pass']} checks pass, {numerics['fail']} fail, {numerics['info']} informational; "
          f"the models' limits: {n['info'] - numerics['info']} measured errors (not verdicts), "
          f"{n['pass'] + n['fail'] - numerics['pass'] - numerics['fail']} membrane-theory verdicts "
          f"({watch.seconds:.1f} s wall time, the report's writing included; plan {results.plan.name})")
    for sentence in limits.sentences(results):
        print(f"  {sentence}")
    for check in results.failed[:10]:
        print(f"  fail: {check.case} {check.comparison} {check.quantity} ({check.where}): error {check.error:.3g} "
              f"> {check.tolerance:.3g}")
    if results.findings:
        differ = sum(f.verdict != "agrees" for f in results.findings)
        print(f"findings about the paper (not verdicts): the paper and the model differ on {differ} of the "
              f"{len(results.findings)} statements checked; see 'Where the paper and the model disagree' in the "
              "report")
    print(f"report: {path / 'index.html'} (also report.md)")
    return 1 if n["fail"] else 0


@contextlib.contextmanager
def _workers(count: int):
    """``count`` local worker processes that ignore Ctrl-C (only this process answers it, in one line), ended
    at once if the command stops early (an interrupt, an error), else after their last task."""
    pool = local_executor(count)
    try:
        yield pool
    except BaseException:
        stop(pool)
        raise
    pool.shutdown()


def _solve(args, name, **options):
    """The suite's solves (``runner.run`` with ``options``) on a pool, then its report; the exit status."""
    from pocket.validation.clock import Stopwatch
    from pocket.validation.runner import WORKERS, run

    watch = Stopwatch()
    pockets, button, plan = _setup(args)
    with _workers(WORKERS) as pool:
        results = run(pockets, button, plan, executor=pool, progress=sys.stderr.isatty(), label=name, **options)
        if options.get("convergence_only"):
            _print_orders(results)
        return _finish(results, args, watch, pool, name)


def _validate(args) -> int:
    return _solve(args, "validate")


def _converge(args) -> int:
    return _solve(args, "converge", convergence_only=True)


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
