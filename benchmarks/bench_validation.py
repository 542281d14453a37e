"""Where the time of a validation run goes, for re-tuning the plan (``pocket.validation.plan``).

    python benchmarks/bench_validation.py [--default] [--repeat N]

Runs the suite's solves (``pocket.validation.run``, no report) with the quick
plan (and the default one with ``--default``) on all usable CPUs, ``repeat``
times, and prints the median wall time of the run, the solve time summed per
kind of task (CPU seconds spent in the workers, comparable across machines
with different core counts), their share, and the ten longest tasks of the
last repeat. The budgets: ``--quick`` under 20 s and the default under 60 s
for the whole ``pocket validate`` on 2 cores, report included (drawing, the
3-D picture and the VTK series add a few seconds on the same workers).
"""

from __future__ import annotations

import argparse
import collections
import statistics
import time

from pocket.validation import DEFAULT, QUICK, load, run
from pocket.validation.runner import WORKERS


def _bench(plan, repeat: int) -> None:
    pockets, button = load()
    walls, results = [], None
    for _ in range(repeat):
        start = time.perf_counter()
        results = run(pockets, button, plan, progress=False)
        walls.append(time.perf_counter() - start)
    kinds = collections.defaultdict(float)
    for task in results.tasks:
        kinds[task.kind] += task.seconds
    total = sum(kinds.values())
    print(f"plan {plan.name}: run {statistics.median(walls):.1f} s wall (median of {repeat}, {WORKERS} processes), "
          f"{total:.1f} s of solves in the workers")
    for kind, seconds in sorted(kinds.items(), key=lambda kv: -kv[1]):
        print(f"  {kind:<12} {seconds:7.1f} s  {100 * seconds / total:5.1f} %")
    print("  longest tasks:")
    for task in sorted(results.tasks, key=lambda t: -t.seconds)[:10]:
        print(f"    {task.seconds:7.2f} s  {task.kind:<12} {task.case:<18} {task.what}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--default", action="store_true", help="also the default plan (minutes with today's FE)")
    parser.add_argument("--repeat", type=int, default=1, help="runs per plan (default 1)")
    args = parser.parse_args()
    for plan in (QUICK, DEFAULT) if args.default else (QUICK,):
        _bench(plan, args.repeat)


if __name__ == "__main__":
    main()
