"""Write a validation run as one folder: index.html, report.md, checks.html, checks.md, PNGs, CSVs, the VTK series.

``check_target`` runs before any solve (``pocket validate`` and ``pocket
converge`` call it first): the folder must be one this process may create or
fill, and an existing non-empty folder is replaced only if it holds a previous
report of the same kind (``KINDS``) that pocket wrote and nothing else
(``pocket.apps.folders.check_replaceable``); else an ``InputError``. The
report is then built in a temporary sibling folder and renamed into place at
the end (``pocket.apps.folders.staged``), so a failed run leaves no
complete-looking report; an error while writing is an ``OutputError`` and
leaves nothing behind.
"""

from __future__ import annotations

import csv
import dataclasses
import pathlib
import time

from pocket.apps.folders import check_replaceable, staged
from pocket.core.errors import InputError
from pocket.core.states import CHECKS, CompressedState

from . import capsulereport, checkpage, document, draw, figures, pockets, render, sections, solidstudy, thickness
from . import verdicts as checks_module
from .plan import VTK, VTK_STEPS
from .suite import headline

__all__ = ["KINDS", "check_target", "vtk_steps", "write_report"]

#: the kinds of report folder: the whole suite's and the convergence study's alone
KINDS = ("validation report", "convergence report")


def check_target(out, kind: str = KINDS[0]) -> pathlib.Path:
    """The report folder as an absolute path; InputError if a ``kind`` may not be written there (before any
    work)."""
    return check_replaceable(out, kind, "--out")


def _write_rows(path: pathlib.Path, header, rows) -> None:
    with path.open("w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(header)
        writer.writerows(rows)


def _states_rows(results):
    """(header, rows): every compressed state of every solver, its keys (alpha empty for another law), its
    smallest tensions and wrinkling flag."""
    keys = (*CompressedState.KEYS, *CHECKS)
    rows = []
    for curves in results.curves:
        runs = [("shooting", curves.reference), ("analytical", [a for a in curves.approximate if a is not None])]
        runs += [(c.column.label, c.states) for c in results.columns if c.pocket == curves.pocket]
        for solver, states in runs:
            for state in states:
                values = [getattr(state, k) for k in keys]
                rows.append([curves.pocket.case.name, solver, state.material.law, state.fluid.kind]
                            + ["" if v is None else v if isinstance(v, bool) else repr(float(v)) for v in values])
    return ["case", "solver", "material", "fluid", *keys], rows


def _write_tables(results, directory: pathlib.Path) -> list[str]:
    """Write the CSV tables; returns a line per file for the report's list of files."""
    fields = [f.name for f in dataclasses.fields(checks_module.Check)]
    _write_rows(directory / "checks.csv", fields, [[getattr(c, f) for f in fields] for c in results.checks])
    summary = checks_module.summary(results.checks)
    _write_rows(directory / "summary.csv", list(summary[0]) if summary else [],
                [list(row.values()) for row in summary])
    _write_rows(directory / "cases.csv", *pockets.case_table(results))
    _write_rows(directory / "convergence_study.csv", *sections.sequence_rows(results))
    _write_rows(directory / "timing.csv", *sections.task_rows(results))
    if results.thicknesses:
        _write_rows(directory / "membrane_vs_solid.csv", *thickness.rows(results.thicknesses))
    names = ["checks.csv: every check (value, reference, error, tolerance, verdict)",
             "summary.csv: the verdicts per pocket, comparison and step",
             "cases.csv: the pockets, SI and dimensionless",
             "convergence_study.csv: every FE value of the convergence study", "timing.csv: each solve task's seconds"]
    if results.thicknesses:
        names.append("membrane_vs_solid.csv: the membrane against the solid for the paper's four samples, every value")
    if results.solid_studies:
        _write_rows(directory / "solid_convergence.csv", *solidstudy.rows(results.solid_studies))
        names.append("solid_convergence.csv: the solid on each mesh of its convergence study, the observed orders and "
                     "the default mesh's error")
    if results.capsules:
        _write_rows(directory / capsulereport.CSV, *capsulereport.state_rows(results.capsules, results.uninflated))
        names.append(f"{capsulereport.CSV}: every capsule state of every solver (the dimensionless keys, the "
                     "compression 1 - H / lambda_I)")
    if results.curves:
        _write_rows(directory / "states.csv", *_states_rows(results))
        names.append("states.csv: every state of every solver (the dimensionless keys)")
    return names


def vtk_steps(count: int, vtk: str) -> list[int]:
    """The indices of a path of ``count`` states that the VTK series ``vtk`` (one of ``VTK``) writes:
    ``VTK_STEPS`` spread evenly along it, both ends included ("few"), every one ("all"), none."""
    if vtk == "none":
        return []
    if vtk == "all" or count <= VTK_STEPS:
        return list(range(count))
    return sorted({round(k * (count - 1) / (VTK_STEPS - 1)) for k in range(VTK_STEPS)})


def _write_vtk(curves, directory: pathlib.Path, steps) -> None:
    """The headline pocket's reference compression path at the indices ``steps`` as a VTK series, time = Fhat."""
    from pocket.apps.vtk.files import write_series

    write_series(directory / "vtk", [curves.reference[k] for k in steps], times=curves.forces[steps])


def _picture(curves, directory):
    k = int(abs(curves.forces - 0.19).argmin())
    return render.render_pocket(curves.reference[0].inflated, curves.reference[k], directory / "pocket3d.png")


def write_report(results, out, *, kind=KINDS[0], executor=None, watch=None, vtk=VTK[0]) -> pathlib.Path:
    """Write the report of ``results`` (a ``run.Results``) to the folder ``out``; returns its path.

    ``kind`` (one of ``KINDS``) marks the folder and titles the report. ``vtk`` (one of ``VTK``) says how
    many states of the headline pocket's compression path the VTK series holds (``vtk_steps``): the default
    keeps the folder a few MB, small enough to mail; "all" adds about 0.6 MB per force.

    The figures, the 3-D picture and the VTK series are made on ``executor`` (an Executor) if given,
    else here. ``watch`` (a ``clock.Stopwatch``, started with the run) is stopped once all but the
    report's pages (report.md, index.html, checks.md, checks.html) are written, and the report quotes its
    seconds as the run's wall time; without it the time is counted from the solves' start.
    """
    begun = time.perf_counter()
    if vtk not in VTK:
        raise InputError(f"vtk = {vtk!r}, but the VTK series is one of {', '.join(VTK)}")
    target = check_target(out, kind)
    with staged(target, kind) as partial:
        figs = figures.figures(results) if results.curves else [figures.convergence_figure(results)]
        submit = executor.submit if executor is not None else _Now
        head = results.curves_of(headline(results.pockets)) if results.curves else None
        steps = vtk_steps(len(head.forces), vtk) if head else []
        # the longest jobs first: the VTK series (seconds of zlib), then the 3-D picture (pyvista's start)
        extra = [submit(_picture, head, partial)] if head else []
        series = [submit(_write_vtk, head, partial, steps)] if steps else []
        jobs = series + extra + [submit(draw.draw, fig, partial) for fig in figs]
        for fig in figs:
            draw.write_csv(fig, partial)
        tables = _write_tables(results, partial)
        for job in jobs:
            job.result()
        picture, why = extra[-1].result() if extra else (None, "")
        title = f"pocket {kind}"
        wall = watch.stop() if watch is not None else results.seconds + (time.perf_counter() - begun)
        written = (len(steps), len(head.forces)) if steps and head else None
        blocks = sections.blocks(results, figs, picture is not None, why, tables, written, title, wall)
        (partial / "report.md").write_text(document.markdown(blocks))
        (partial / "index.html").write_text(document.html_page(title, blocks))
        page = checkpage.blocks(results.checks, title)
        (partial / checkpage.PAGE[0]).write_text(document.html_page(f"{title}: every check", page))
        (partial / checkpage.PAGE[1]).write_text(document.markdown(page))
    return target


class _Now:
    """A finished future: ``_Now(f, *args).result()`` is ``f(*args)``, run at construction."""

    def __init__(self, function, *args):
        self.value = function(*args)

    def result(self):
        return self.value
