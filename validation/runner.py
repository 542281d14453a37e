"""Run the validation suite: every solve on worker processes (one per usable CPU, at most 8), then the checks.

The independent solves (a pocket's reference curves, its FE columns, the
convergence sequences, the evidence about the paper, the fits of each law to FE
bulge data, each capsule pressed between two plates and the FE model's convergence
on one) are tasks of a
``concurrent.futures.ProcessPoolExecutor``; an FE column waits for its pocket's
reference, which finds the end of the range. The reference curves start first
(headline first), the convergence sequences once no reference is pending. Any
``Executor`` works (a dask ``Client().get_executor()`` spreads a run over a
cluster). Each task's wall time is kept (``Results.tasks``) for re-tuning the plan.

An interrupt (Ctrl-C) or any other exception ends the executor's workers at once
(``pocket.apps.sweep.workers.stop``) and passes on. Local workers come from
``pocket.apps.sweep.workers.local_executor``: they ignore SIGINT, which the terminal sends
to them too, so that only the main process answers it (one line), not every worker
with a traceback.

Progress is a tqdm bar on stderr, labelled with the command, shown only when stderr is a terminal.
"""

from __future__ import annotations

import concurrent.futures as cf
import dataclasses
import sys
import time

from tqdm import tqdm

from pocket.apps.cases import SAMPLES
from pocket.apps.provenance import cpus
from pocket.apps.sweep.workers import local_executor, stop

from . import (
    capsulechecks,
    capsules,
    compute,
    convergence,
    evidence,
    findings,
    identification,
    solidstudy,
    thickness,
    uninflated,
    verdicts,
)
from .plan import Plan
from .suite import Button, headline

__all__ = ["WORKERS", "Results", "Task", "convergence_tasks", "progress_bar", "run"]

WORKERS = min(8, cpus())


@dataclasses.dataclass(frozen=True)
class Task:
    """One solve of a run and its wall time (in the worker)."""

    kind: str  # "reference" | "column" | "convergence" | "evidence" | "fit" | "solid" | "solid study" | "capsule"
    case: str
    what: str
    seconds: float


@dataclasses.dataclass(frozen=True)
class Results:
    plan: Plan
    pockets: tuple  # pocket.apps.physical.Pocket, in file order
    button: Button
    curves: tuple  # compute.Curves per pocket, in pocket order
    columns: tuple  # compute.ColumnCurve, in pocket order then column order
    sequences: tuple  # convergence.Sequence
    evidence: evidence.Evidence | None
    fits: tuple  # identification.Identification, in the plan's order
    thicknesses: tuple  # thickness.Comparison, by sample then pressure
    capsules: tuple  # capsules.Curve, in the order of capsules.CASES
    capsule_sequence: convergence.Sequence | None  # the FE model's mesh convergence on a capsule
    uninflated: uninflated.Uninflated | None  # the uninflated capsule by both solvers
    solid_studies: tuple  # solidstudy.Study, by sample then axis
    checks: tuple  # verdicts.Check
    findings: tuple  # findings.Finding
    tasks: tuple  # Task, in order of submission
    seconds: float

    @property
    def failed(self) -> list:
        return [c for c in self.checks if c.verdict == "fail"]

    def curves_of(self, pocket):
        """The ``compute.Curves`` of ``pocket``."""
        return self.curves[self.pockets.index(pocket)]


def convergence_tasks(pocket, plan: Plan) -> list[tuple]:
    """Arguments of ``convergence.sequence`` for the study of ``plan``."""
    return convergence.tasks(pocket, plan)


def progress_bar(enabled: bool, stream=None, label: str = "validate") -> tqdm:
    """A tqdm bar counting solves on ``stream`` (stderr), labelled ``label``, disabled unless ``enabled``
    and a terminal; cleared when closed."""
    stream = sys.stderr if stream is None else stream
    return tqdm(total=0, desc=label, unit=" solves", file=stream, disable=not (enabled and stream.isatty()),
                leave=False, dynamic_ncols=True)


def _timed(function, *args):
    start = time.perf_counter()
    return function(*args), time.perf_counter() - start


def _task(kind, key, pockets, args) -> Task:
    if kind == "reference":
        return Task(kind, pockets[key].case.name, "reference and analytical curves", 0.0)
    if kind == "column":
        return Task(kind, pockets[key[0]].case.name, f"{args[1].label} at {len(args[2])} forces", 0.0)
    if kind == "convergence":
        _, study, order, mesh, sizes = args
        return Task(kind, args[0].case.name, f"{study} P{order} {mesh}, {len(sizes)} meshes", 0.0)
    if kind == "fit":
        return Task(kind, "", f"{args[0]} ({args[1]} terms) fitted to FE bulge data", 0.0)
    if kind == "solid":
        return Task(kind, f"sample {args[0]}", f"membrane and solid at {args[1]:g} kPa, {len(args[2])} forces", 0.0)
    if kind == "solid study":
        return Task(kind, f"sample {args[0]}", f"solid on {args[3]} x {args[4]} elements, corner {args[5]:g} T, "
                    f"{len(args[2])} forces", 0.0)
    if kind == "capsule":
        fe = f", FE P2 at {len(args[2])}" if args[0].fem and args[2] else ""
        return Task(kind, args[0].name, f"capsule: shooting at {len(args[1])} forces{fe}", 0.0)
    if kind == "capsule convergence":
        return Task(kind, capsules.STUDY.name, f"capsule: FE P2 on {len(args[0])} meshes", 0.0)
    if kind == "capsule uninflated":
        return Task(kind, uninflated.NAME, f"uninflated capsule: shooting at {len(uninflated.HEIGHTS)} heights, FE P2 "
                    f"at {len(uninflated.FEM_HEIGHTS)}", 0.0)
    return Task(kind, "", "the paper's statements", 0.0)


def run(pockets, button, plan: Plan, *, executor=None, progress=True, convergence_only=False,
        label="validate") -> Results:
    """All solves and checks of ``plan`` (only the convergence study if ``convergence_only``); ``label``
    names the progress bar."""
    start = time.perf_counter()
    pockets = tuple(pockets)
    own = executor is None
    pool = local_executor(WORKERS) if own else executor
    bar = progress_bar(progress, label=label)
    main = headline(pockets)
    pending: dict = {}  # future -> (kind, key, index into tasks)
    tasks: list = []
    done: dict = {"reference": {}, "column": {}, "convergence": {}, "evidence": {}, "fit": {}, "solid": {},
                  "solid study": {}, "capsule": {}, "capsule convergence": {}, "capsule uninflated": {}}

    def submit(kind, key, function, *args):
        pending[pool.submit(_timed, function, *args)] = (kind, key, len(tasks))
        tasks.append(_task(kind, key, pockets, args))
        bar.total += 1
        bar.refresh()

    try:
        if not convergence_only:
            for k in sorted(range(len(pockets)), key=lambda k: pockets[k] is not main):
                submit("reference", k, compute.reference, pockets[k], plan)
            if plan.thickness:  # the longest tasks: started early
                pressures, forces = plan.thickness
                for k, (number, pressure) in enumerate((n, p) for n in sorted(SAMPLES) for p in pressures):
                    submit("solid", k, thickness.compare, number, pressure, forces, plan.thickness_refined)
            for number in plan.solid_study:
                grids = (solidstudy.meshes(axis, counts) for axis, counts in
                         zip(solidstudy.AXES, plan.solid_refined, strict=True))
                for mesh in dict.fromkeys(m for grid in grids for m in grid):
                    submit("solid study", (number, *mesh), solidstudy.solve, number, solidstudy.PRESSURE_KPA,
                           solidstudy.FORCES, *mesh)
            submit("evidence", None, evidence.collect, button)
            for k, (law, terms) in enumerate(plan.fits):
                submit("fit", k, identification.identify, law, terms)
            if plan.capsules:
                for k, capsule in enumerate(capsules.CASES):
                    submit("capsule", k, capsules.solve, capsule, plan.capsules, plan.capsule_fem)
                if plan.capsule_sizes:
                    submit("capsule convergence", None, capsules.sequence, plan.capsule_sizes)
                if plan.capsule_fem:
                    submit("capsule uninflated", None, uninflated.solve)
        later = convergence_tasks(main, plan)
        while pending or later:
            if later and not any(kind == "reference" for kind, _, _ in pending.values()):
                for k, args in enumerate(later):
                    submit("convergence", k, convergence.sequence, *args)
                later = []
            finished, _ = cf.wait(pending, return_when=cf.FIRST_COMPLETED)
            for future in finished:
                kind, key, index = pending.pop(future)
                done[kind][key], seconds = future.result()
                tasks[index] = dataclasses.replace(tasks[index], seconds=seconds)
                bar.update()
                if kind == "reference":
                    forces = plan.fem_forces_of(pockets[key])
                    if forces:
                        forces = compute.fem_forces(forces, done[kind][key].force_end)
                        for j, column in enumerate(plan.columns_of(pockets[key])):
                            submit("column", (key, j), compute.column_curve, pockets[key], column, forces)
    except BaseException:  # not shutdown(cancel_futures=True): killed workers and cancelled futures break it
        stop(pool)
        raise
    finally:
        bar.close()
        if own:
            pool.shutdown()
    return _results(plan, pockets, button, done, tuple(tasks), time.perf_counter() - start)


def _results(plan, pockets, button, done, tasks, seconds) -> Results:
    curves = tuple(done["reference"][k] for k in sorted(done["reference"]))
    columns = tuple(done["column"][k] for k in sorted(done["column"]))
    sequences = tuple(done["convergence"][k] for k in sorted(done["convergence"]))
    by_pocket = {c.pocket: c for c in curves}
    rows = []
    for curve in curves:
        rows += verdicts.reference_checks(curve) + verdicts.analytical_checks(curve)
        rows += verdicts.membrane_checks(curve.pocket.case.name, "shooting", curve.reference)
    for column in columns:
        rows += verdicts.fem_checks(by_pocket[column.pocket], column)
        rows += verdicts.membrane_checks(column.pocket.case.name, column.column.label, column.states)
    rows += convergence.checks(sequences)
    fits = tuple(done["fit"][k] for k in sorted(done["fit"]))
    rows += identification.checks(fits)
    thicknesses = tuple(done["solid"][k] for k in sorted(done["solid"]))
    rows += thickness.checks(thicknesses)
    solid_studies = tuple(solidstudy.studies(plan.solid_study, solidstudy.PRESSURE_KPA, solidstudy.FORCES,
                                             plan.solid_refined, done["solid study"])
                          if done["solid study"] else ())
    rows += solidstudy.checks(solid_studies)
    capsule_curves = tuple(done["capsule"][k] for k in sorted(done["capsule"]))
    rows += capsulechecks.checks(capsule_curves)
    capsule_sequence = done["capsule convergence"].get(None)
    if capsule_sequence is not None:
        rows += capsulechecks.order_checks(capsule_sequence)
    unpressurised = done["capsule uninflated"].get(None)
    if unpressurised is not None:
        rows += uninflated.checks(unpressurised)
    found: tuple = ()
    proof = done["evidence"].get(None)
    if proof is not None:
        head = by_pocket[headline(pockets)]
        found = tuple(findings.findings(button, proof, evidence.eq9_residuals(head.reference[0].inflated), head))
    return Results(plan=plan, pockets=pockets, button=button, curves=curves, columns=columns, sequences=sequences,
                   evidence=proof, fits=fits, thicknesses=thicknesses, capsules=capsule_curves,
                   capsule_sequence=capsule_sequence, uninflated=unpressurised, solid_studies=solid_studies,
                   checks=tuple(rows), findings=found, tasks=tasks, seconds=seconds)
