"""``pocket sweep``: a grid over alpha (or one rubber of another law), Phat_I and Fhat, with a liquid or a
gas, pressed by the flat plate or a sphere, a pocket or a capsule (``--geometry``), on local processes or a dask
cluster, resumable."""

from __future__ import annotations

from pocket.apps.folders import check_output_file
from pocket.apps.solvers import SOLVERS
from pocket.apps.sweep.cluster import PATIENCE, connect
from pocket.apps.sweep.grid import MAX_POINTS, run_sweep
from pocket.apps.sweep.workers import local_executor, max_workers, stop
from pocket.core.errors import InputError
from pocket.core.inputs import check_positive

from .common import (
    MODEL_UNITS,
    add_solver_flags,
    model_value,
    number,
    path_name,
    progress_bar,
    solver_flags,
    solvers_epilog,
)
from .geometryflags import add_geometry_flag, capsule_units, geometry_of
from .indenterflags import add_indenter_flags, indenter_of
from .laws import add_fluid_flags, add_rubber_flags, fluid_of, material_of

__all__ = ["register"]


def _executor(args):
    """Local processes, or the executor of a dask.distributed cluster (``pocket.apps.sweep.cluster``)."""
    if args.scheduler is None:
        if args.patience is not None:
            raise InputError("--patience applies to --scheduler, not to local processes")
        return local_executor(args.workers)
    if args.workers is not None:
        raise InputError("--workers applies to local processes, not to --scheduler")
    patience = PATIENCE if args.patience is None else check_positive("--patience", args.patience)
    return connect(args.scheduler, patience)


def _main(args) -> int:
    check_output_file(args.out, "--out", resumed=True)  # the journal reads the file and keeps its rows
    options = solver_flags(args, args.solver, "compress")
    rubber = material_of(args)
    alphas, material = (rubber, None) if isinstance(rubber, list) else (None, rubber)
    fluid = fluid_of(args)
    indenter = indenter_of(args)
    executor = _executor(args)
    try:
        with progress_bar("sweep", " points") as progress:
            computed, reused = run_sweep(args.out, alphas, args.pressure, args.force or args.force_etr, executor,
                                         solver=args.solver, force_unit="Fhat" if args.force else "ETR",
                                         options=options, progress=progress, material=material, fluid=fluid,
                                         indenter=indenter, prestretch=args.prestretch or 1.0,
                                         geometry=geometry_of(args))
        executor.shutdown()
    except BaseException:
        stop(executor)
        raise
    print(f"sweep: {computed} points computed, {reused} reused; wrote {args.out}")
    return 0


def register(subparsers) -> None:
    """Add ``pocket sweep``."""
    text = "parameter sweep over alpha (or one rubber of another law), Phat_I and Fhat (parallel, resumable)"
    p = subparsers.add_parser(
        "sweep", help=text, epilog=solvers_epilog(),
        description=f"{text}: one compressed state per grid point (at most {MAX_POINTS}), one CSV row each, "
        "with a status (ok, out_of_range, failed) and a message, and the indenter that pressed it (plate, or "
        "sphere K=... with K = R_s/R, or profile sha256=... naming a profile table by its content; sweeps of several "
        "indenters can share a file); rerun the same command to "
        "compute only the missing points. While it runs the file collects finished points; at the end it is "
        "rewritten in grid order. Stopped early (interrupt, error), the file keeps its complete rows only. "
        f"{capsule_units('compress')} {MODEL_UNITS}")
    p.add_argument("--pressure", type=model_value("sweep", "Phat_I = P_I R / (E T)"), nargs="+", required=True,
                   metavar="PHAT_I", help="values of the initial pressure, Phat_I = P_I R / (E T) (0 with "
                   "--force-etr: an uninflated capsule)")
    load = p.add_mutually_exclusive_group(required=True)
    load.add_argument("--force", type=model_value("sweep", "Fhat = F / (P_I pi R^2)"), nargs="+", metavar="FHAT",
                      help="values of the force, Fhat = F / (P_I pi R^2)")
    load.add_argument("--force-etr", type=model_value("sweep", "F/(E T R)"), nargs="+", metavar="F/(ETR)",
                      help="or a capsule's forces on each plate in units of its wall's E T and its radius R, "
                           "F / (E T R), the same forces at every --pressure (each row's force_ETR, and its Fhat "
                           "where P_I > 0); the only forces of an uninflated capsule (--pressure 0), whose Fhat is "
                           "undefined (solvers shooting and fem)")
    p.add_argument("--out", required=True, type=path_name, metavar="FILE.csv",
                   help="results; an existing sweep file is resumed")
    p.add_argument("--solver", choices=tuple(SOLVERS), default="shooting",
                   help="solver of every point (each is listed below)")
    p.add_argument("--workers", type=int, help=f"local worker processes (default: one per usable CPU; at most "
                   f"{max_workers()}, 4 per CPU)")
    p.add_argument("--scheduler", metavar="ADDRESS", help="dask.distributed scheduler, e.g. tcp://host:8786; its "
                   "workers need the same pocket installed")
    p.add_argument("--patience", type=number, metavar="SECONDS", help=f"with --scheduler: how long to wait "
                   f"while no worker is connected before stopping (default {PATIENCE:g})")
    add_rubber_flags(p, command="sweep", alphas=True)
    add_fluid_flags(p, command="sweep")
    add_indenter_flags(p, command="sweep")
    add_geometry_flag(p)
    add_solver_flags(p, "compress")
    p.set_defaults(handler=_main)
