"""Run the validation suite: every solve on worker processes (one per usable CPU, at most 8), then the checks.

The independent solves (a case's reference curves, FE curves, convergence
sequences, the evidence about the paper) are tasks of a
``concurrent.futures.ProcessPoolExecutor``; an FE curve that runs to the end of
the range waits for its case's reference, which finds that end. The longest
tasks (FE at the default mesh) start first. Any ``Executor`` works (a dask
``Client().get_executor()`` spreads a run over a cluster).
"""

from __future__ import annotations

import concurrent.futures as cf
import dataclasses
import sys
import time

from pocket.apps.provenance import cpus

from . import compute, convergence, evidence, findings, verdicts
from .plan import Plan
from .suite import Case, Design

__all__ = ["Results", "run", "convergence_tasks", "headline"]

WORKERS = min(8, cpus())


@dataclasses.dataclass(frozen=True)
class Results:
    plan: Plan
    cases: tuple[Case, ...]
    design: Design
    curves: tuple  # compute.Curves per case, in case order
    fem: tuple  # compute.FemCurve, in case order then element order
    sequences: tuple  # convergence.Sequence
    evidence: evidence.Evidence | None
    checks: tuple  # verdicts.Check
    findings: tuple  # findings.Finding
    seconds: float

    @property
    def failed(self) -> list:
        return [c for c in self.checks if c.verdict == "fail"]


def headline(cases) -> Case:
    """The case tagged "headline" (the first one if several)."""
    for case in cases:
        if "headline" in case.tags:
            return case
    return cases[0]


def convergence_tasks(case: Case, plan: Plan) -> list[tuple]:
    """Arguments of ``convergence.sequence`` for the study of ``plan``."""
    return convergence.tasks(case, plan)


class _Progress:
    """A one-line bar on stderr, only when stderr is a terminal."""

    def __init__(self, enabled: bool):
        self.enabled = enabled and sys.stderr.isatty()
        self.done = self.total = 0

    def add(self, count: int = 1):
        self.total += count
        self._draw()

    def step(self):
        self.done += 1
        self._draw()

    def _draw(self):
        if self.enabled:
            filled = int(30 * self.done / max(self.total, 1))
            sys.stderr.write(f"\r[{'#' * filled}{'.' * (30 - filled)}] {self.done}/{self.total} solves")
            sys.stderr.flush()

    def close(self):
        if self.enabled:
            sys.stderr.write("\n")


def run(cases, design, plan: Plan, *, executor=None, progress=True, convergence_only=False) -> Results:
    """All solves and checks of ``plan`` (only the convergence study if ``convergence_only``)."""
    start = time.perf_counter()
    own = executor is None
    pool = cf.ProcessPoolExecutor(max_workers=WORKERS) if own else executor
    bar = _Progress(progress)
    main = headline(cases)
    try:
        pending = {}  # future -> (kind, key)
        if not convergence_only:
            for k, case in sorted(enumerate(cases), key=lambda kc: "headline" not in kc[1].tags):
                pending[pool.submit(compute.reference, case, plan)] = ("reference", k)
            pending[pool.submit(evidence.collect, design)] = ("evidence", None)
        later = list(enumerate(convergence_tasks(main, plan)))  # after the FE curves: shorter
        bar.add(len(pending) + len(later))
        done = {"reference": {}, "fem": {}, "sequence": {}, "evidence": {}}
        while pending or later:
            if later and not any(kind == "reference" for kind, _ in pending.values()):
                for k, args in later:
                    pending[pool.submit(convergence.sequence, *args)] = ("sequence", k)
                later = []
            finished, _ = cf.wait(pending, return_when=cf.FIRST_COMPLETED)
            for future in finished:
                kind, key = pending.pop(future)
                done[kind][key] = future.result()
                bar.step()
                if kind == "reference":
                    for order in (1, 2):
                        forces = plan.fem_forces_of(cases[key])
                        if forces:
                            args = (cases[key], order, compute.fem_forces(forces, done[kind][key].force_end))
                            pending[pool.submit(compute.fem_curve, *args)] = ("fem", (key, order))
                            bar.add()
    except BaseException:
        pool.shutdown(wait=False, cancel_futures=True)
        raise
    finally:
        bar.close()
        if own:
            pool.shutdown()
    curves = tuple(done["reference"][k] for k in sorted(done["reference"]))
    fems = tuple(done["fem"][k] for k in sorted(done["fem"]))
    sequences = tuple(done["sequence"][k] for k in sorted(done["sequence"]))
    rows = []
    for curve in curves:
        rows += verdicts.reference_checks(curve) + verdicts.analytical_checks(curve)
    for fem in fems:
        rows += verdicts.fem_checks(curves[cases.index(fem.case)], fem)
    rows += convergence.checks(sequences)
    found = ()
    proof = done["evidence"].get(None)
    if proof is not None:
        head = curves[cases.index(main)]
        found = tuple(findings.findings(design, proof, evidence.eq9_residuals(head.shooting[0].inflated), head))
    return Results(plan=plan, cases=tuple(cases), design=design, curves=curves, fem=fems, sequences=sequences,
                   evidence=proof, checks=tuple(rows), findings=found, seconds=time.perf_counter() - start)
