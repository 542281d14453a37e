"""``pocket inflate`` and ``pocket compress``: one state or a compression curve, dimensionless.

Quantities (the model's own units): Phat = P R / (E T), Fhat = F / (P_I pi R^2),
lengths in R; a value with a unit is refused, naming the unit the option wants
(``pocket.cli.common.model_value``). Output: a table (or ``--json``, with each state's ``warnings``) of
the reported keys of ``pocket.core.states``; the warnings also go to stderr as
``pocket: warning: ...`` lines; ``--vtk DIR`` writes the states for ParaView. A
curve shows a progress bar on a terminal (``progress`` of ``compression_curve``).
"""

from __future__ import annotations

import json
import math

from pocket.apps.folders import check_replaceable
from pocket.apps.solvers import SOLVERS, entry
from pocket.core.errors import ConvergenceError, InputError, OutOfRangeError
from pocket.core.indenters import PLATE
from pocket.core.inputs import check_positive, check_volume, forces_in_fhat

from .common import (
    MODEL_UNITS,
    add_solver_flags,
    model_value,
    path_name,
    progress_bar,
    report,
    solver_flags,
    solvers_epilog,
    warn,
)
from .geometryflags import add_geometry_flag, capsule_units, geometry_of
from .indenterflags import add_indenter_flags, indenter_of
from .laws import add_fluid_flags, add_rubber_flags, fluid_of, material_of

__all__ = ["register"]


def register(subparsers) -> None:
    """Add ``inflate`` and ``compress``."""

    for name, text in (("inflate", "step 1: inflate the pocket at pressure Phat"),
                       ("compress", "step 2: press the inflated pocket with a flat plate or another indenter, its "
                                    "fluid sealed in (a liquid keeps its volume, a gas is compressed)")):
        p = subparsers.add_parser(name, help=text, description=f"{text}. {_units(name)}. {capsule_units(name)} "
                                  f"{MODEL_UNITS}",
                                  epilog=solvers_epilog())
        if name == "inflate":
            control = p.add_mutually_exclusive_group(required=True)
            control.add_argument("--pressure", type=model_value(name, "Phat = P R / (E T)"), metavar="PHAT",
                                 help="pressure control, Phat = P R / (E T)")
            control.add_argument("--volume", type=model_value(name, "V/R^3"), metavar="V/R^3",
                                 help="volume control: the enclosed volume in V/R^3, at most 5.2e5 (more needs the "
                                 "sheet stretched past the model's limit of 100); passes a pressure maximum; "
                                 f"solvers {_serving('inflate_volume')}")
        else:
            p.add_argument("--pressure", type=model_value(name, "Phat_I = P_I R / (E T)"), required=True,
                           metavar="PHAT_I", help="initial pressure, Phat_I = P_I R / (E T) (0: an uninflated "
                           "capsule, pressed by --height, its force reported as force_ETR = F / (E T R))")
            load = p.add_mutually_exclusive_group(required=True)
            load.add_argument("--force", type=model_value(name, "Fhat = F / (P_I pi R^2)"), nargs="+", metavar="FHAT",
                              help="force, Fhat = F / (P_I pi R^2); several give a curve (by continuation)")
            load.add_argument("--force-etr", type=model_value(name, "F/(E T R)"), nargs="+", metavar="F/(ETR)",
                              help="a capsule's force on each plate in units of its wall's E T and its radius R, F / "
                                   "(E T R): the force of an uninflated capsule (--pressure 0), whose Fhat is "
                                   f"undefined; several give a curve (solvers {_serving('compression_curve')})")
            load.add_argument("--height", type=model_value(name, "H/R"), nargs="+", metavar="H/R",
                              help="travel control: the indenter's lowest point at a height in H/R above the clamp "
                                   "plane, at most the inflated height H0/R (a capsule's: each plate's distance from "
                                   "its equatorial plane, half the gap between the plates; solvers "
                                   f"{_serving('compress_height')})")
        p.add_argument("--solver", choices=tuple(SOLVERS), default="shooting",
                       help="which model solves (each is listed below)")
        p.add_argument("--json", action="store_true",
                       help="print JSON (a list for several forces)" if name == "compress" else "print JSON")
        p.add_argument("--vtk", type=path_name, metavar="DIR",
                       help="also write the states as VTK files for ParaView (the steps in order of force, the time "
                       "of each its force)")
        p.add_argument("--overwrite", action="store_true",
                       help="replace a VTK series pocket wrote in --vtk DIR (any other non-empty folder is refused)")
        add_geometry_flag(p)
        add_rubber_flags(p, command=name)
        if name == "compress":
            add_fluid_flags(p, command=name)
            add_indenter_flags(p, command=name)
        add_solver_flags(p, "inflate" if name == "inflate" else "compress")
        p.set_defaults(handler=_main)


def _serving(entry: str) -> str:
    """The solvers whose records list the entry point ``entry``, as a help text names them ("a, b and c")."""
    names = [n for n, s in SOLVERS.items() if s.serves(entry)]
    return ", ".join(names[:-1]) + f" and {names[-1]}" if len(names) > 1 else names[0]


def _units(step: str) -> str:
    """The help's paragraph on units and on what a state of ``step`` ("inflate" or "compress") reports."""
    compress = step == "compress"
    return ("units: Phat = P R / (E T) with E = 3 mu_0 the small-strain Young's modulus (6 (C1 + C2) for "
            "Mooney-Rivlin) and T the thickness, " + ("Fhat = F / (P_I pi R^2), " if compress else "")
            + "lengths in units of the clamp radius R; a state reports its law and parameters (units of mu_0), "
            + ("its fluid, " if compress else "") + "and its smallest tensions (units E T) with 'wrinkled' true "
            "where one is not positive (outside membrane theory, also a warning)")


def _table(rows: list[dict]) -> str:
    """The rows as aligned text: a column per key of any row (a state may lack a key another reports, as
    the FE model's inflated state at F = 0 lacks its contact's error), "-" where a row has none."""
    keys = [k for k in dict.fromkeys(k for r in rows for k in r) if k not in ("solver", "warnings")]
    if len(rows) == 1:
        width = max(map(len, keys))
        return "\n".join(f"{k:<{width}}  {_fmt(rows[0][k])}" for k in keys)
    cols = [[k] + [_fmt(r[k]) if k in r else "-" for r in rows] for k in keys]
    widths = [max(map(len, col)) for col in cols]
    lines = ["  ".join(col[i].rjust(w) for col, w in zip(cols, widths, strict=True)) for i in range(len(rows) + 1)]
    return "\n".join(lines)


def _fmt(value) -> str:
    return f"{value:.10g}" if isinstance(value, float) else str(value)


def _solve(args, step: str, material, options: dict) -> list:
    if step == "inflate" and args.volume is not None:
        return [entry(args.solver, "inflate_volume", "--volume")(material, args.volume, **options)]
    if step == "inflate":
        return [entry(args.solver, "inflate", "--pressure")(material, args.pressure, **options)]
    if args.height is not None:
        return _at_heights(args, material, options)
    curve = entry(args.solver, "compression_curve", "--force")
    forces = args.force or args.force_etr
    if args.force_etr is not None:
        options = {**options, **_in_etr(args)}
        forces = forces if "force_unit" in options else forces_in_fhat(forces, "ETR", args.pressure)
    with progress_bar(f"compress ({args.solver})", " forces") as progress:
        extra = {} if progress is None or len(forces) == 1 else {"progress": progress}
        try:
            return curve(material, args.pressure, forces, **options, **extra)
        except OutOfRangeError as err:
            if args.force_etr is None or "force_unit" in options:
                raise
            # the forces went to the solver as Fhat: the refusal says which --force-etr value that was
            raise OutOfRangeError(f"--force-etr {' '.join(map(_fmt, args.force_etr))} at --pressure "
                                  f"{_fmt(args.pressure)} are Fhat = F / (E T R) / (pi Phat_I) = "
                                  f"{' '.join(map(_fmt, forces))}: {err}") from None


def _in_etr(args) -> dict:
    """The options of forces given by ``--force-etr``: none where P_I > 0 (they are passed as Fhat), else the
    unit, for the solvers that press an uninflated capsule (an InputError for the others)."""
    if args.pressure != 0.0:
        check_positive("--pressure", args.pressure)
        return {}
    if args.solver not in ("shooting", "fem"):
        raise InputError(f"--force-etr at --pressure 0 (an uninflated capsule): solver {args.solver} does not "
                         "press one; the solvers shooting and fem do")
    return {"force_unit": "ETR"}


def _at_heights(args, material, options: dict) -> list:
    """The compressed states with the indenter's lowest point at each ``--height`` H/R; a height above the
    inflated pocket (where the indenter would not touch it) is the solver's ``OutOfRangeError``."""
    at_height = entry(args.solver, "compress_height", "--height")
    heights = [check_positive("--height", h) for h in args.height]
    states = []
    with progress_bar(f"compress ({args.solver})", " heights") as progress:
        for done, height in enumerate(heights, start=1):
            states.append(at_height(material, args.pressure, height, **options))
            if progress is not None:
                progress(done, len(heights))
    return states


def _time(state) -> float:
    """A state's time in a VTK series: its force Fhat (0 inflated), or F / (E T R) for an uninflated capsule."""
    force = getattr(state, "force", 0.0)
    return force if math.isfinite(force) else state.extra["force_ETR"]


def _main(args) -> int:
    step = "inflate" if args.command == "inflate" else "compress"
    options = solver_flags(args, args.solver, step)
    options["geometry"] = geometry_of(args)
    material = material_of(args)
    if getattr(args, "volume", None) is not None:
        check_volume("--volume", args.volume)
    if step == "compress":
        fluid = fluid_of(args)
        options.update({} if fluid is None else {"fluid": fluid})
        indenter = indenter_of(args)
        options.update({} if indenter == PLATE else {"indenter": indenter})
    if args.vtk is not None:
        from pocket.apps.vtk.files import KIND

        check_replaceable(args.vtk, KIND, "--vtk", overwrite=args.overwrite)
        loads, name = next(((given, name.replace("_", "-")) for name in ("height", "force_etr", "force")
                            if (given := getattr(args, name, None))), ((), "force"))
        repeated = sorted({f for f in loads if loads.count(f) > 1})
        if repeated:
            raise InputError(f"--{name} gives {', '.join(map(repr, repeated))} more than once, but the time of a "
                             f"--vtk step is its force: give each {name} once")
    states = _solve(args, step, material, options)
    rows = [report(s) for s in states]
    if any(isinstance(v, float) and not math.isfinite(v) for row in rows for v in row.values()):
        raise ConvergenceError(f"solver {args.solver} returned a non-finite value")
    if args.vtk is not None:
        from pocket.apps.vtk.files import write_series

        steps = sorted(states, key=_time)  # the time is the force, increasing
        write_series(args.vtk, steps, times=[_time(s) for s in steps], overwrite=args.overwrite)
    warn(states)
    if args.json:
        several = step == "compress" and len(args.force or args.force_etr or args.height) > 1
        print(json.dumps(rows if several else rows[0]))
    else:
        print(f"# solver: {rows[0]['solver']}")
        print(_table(rows))
    return 0
