"""``pocket sweep``: a grid over alpha, Phat_I and Fhat on local processes or a dask cluster, resumable."""

from __future__ import annotations

from concurrent.futures import ProcessPoolExecutor

from pocket.apps.solvers import SOLVERS
from pocket.apps.sweep import run_sweep
from pocket.core.errors import InputError

from .common import EXIT_CODES, number

__all__ = ["register"]


def _executor(args):
    """(executor, client): local processes, or a dask.distributed cluster's executor and its client."""
    if args.scheduler is None:
        return ProcessPoolExecutor(max_workers=args.workers), None
    if args.workers is not None:
        raise InputError("--workers applies to local processes, not to --scheduler")
    try:
        from dask.distributed import Client
    except ImportError:
        raise InputError("--scheduler needs dask.distributed: pip install 'pocket-mechanics[sweep]'") from None
    try:
        client = Client(args.scheduler, timeout="10s")
    except OSError as err:
        raise InputError(f"--scheduler {args.scheduler}: cannot connect ({err})") from None
    return client.get_executor(), client


def _main(args) -> int:
    executor, client = _executor(args)
    try:
        computed, reused = run_sweep(args.out, args.alpha, args.pressure, args.force, executor,
                                     solver=args.solver)
    finally:
        executor.shutdown()
        if client is not None:
            client.close()
    print(f"sweep: {computed} points computed, {reused} reused; wrote {args.out}")
    return 0


def register(subparsers) -> None:
    """Add ``pocket sweep``."""
    text = "parameter sweep over alpha, Phat_I and Fhat (parallel, resumable)"
    p = subparsers.add_parser("sweep", help=text, description=f"{text}: one compressed state per grid point, "
                              "one CSV row each, with a status (ok, out_of_range, failed); rerun on the same "
                              "file to compute only the missing points.", epilog=EXIT_CODES)
    p.add_argument("--alpha", type=number, nargs="+", required=True, help="values of C2/C1")
    p.add_argument("--pressure", type=number, nargs="+", required=True, help="values of Phat_I = P_I R/(E T)")
    p.add_argument("--force", type=number, nargs="+", required=True, help="values of Fhat = F/(P_I pi R^2)")
    p.add_argument("--out", required=True, metavar="FILE.csv", help="results; an existing sweep file is resumed")
    p.add_argument("--solver", choices=tuple(SOLVERS), default="shooting", help="solver (default shooting)")
    p.add_argument("--workers", type=int, help="local worker processes (default: one per core)")
    p.add_argument("--scheduler", metavar="ADDRESS", help="dask.distributed scheduler, e.g. tcp://host:8786")
    p.set_defaults(handler=_main)
