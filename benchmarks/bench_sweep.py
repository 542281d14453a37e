"""Benchmark of sweeps: one task per curve (by continuation) against one task per point.

    python benchmarks/bench_sweep.py

A grid of 50 curves (5 alphas x 10 Phat_I, shooting solver, a liquid) of 40 forces each,
2000 points, all in the model's range. Prints medians of repeated runs (machines here are
noisy; the load average is printed with them) of

- per point: every point a task of its own from a fresh inflation (``solve_point``), on
  local worker processes, results gathered in memory (no file);
- per curve: ``run_sweep`` as ``pocket sweep`` runs it (one task per curve, ``solve_curve``,
  the file written), on the same workers;
- continuation in one process: the 50 ``compression_curve`` calls one after the other;

and the ratios. The workers are started and warmed (imports, compiled code loaded) before
timing, so the figures are the tasks' cost, not the workers' start. The bar: per-curve
tasks within 1.5 times the one-process continuation cost divided by the workers (one per
usable CPU).
"""

from __future__ import annotations

import os
import pathlib
import tempfile
from concurrent.futures import wait

import numpy as np
from timing import median_time

from pocket import shooting
from pocket.apps.provenance import cpus
from pocket.apps.sweep.grid import run_sweep, solve_point
from pocket.apps.sweep.workers import local_executor

ALPHAS = [0.1, 0.2, 0.3, 0.6, 1.2]
PRESSURES = [float(p) for p in np.linspace(0.05, 0.3, 10)]
FORCES = [float(f) for f in np.linspace(0.025, 1.0, 40)]
REPEAT = 3
#: the bar: per-curve tasks on N workers within this factor of the one-process continuation over N
BAR = 1.5


def per_point(executor) -> None:
    futures = [executor.submit(solve_point, "shooting", a, p, f, {}) for a in ALPHAS for p in PRESSURES
               for f in FORCES]
    for future in futures:
        assert future.result()["status"] == "ok"


def per_curve(executor) -> None:
    with tempfile.TemporaryDirectory() as folder:
        computed, _ = run_sweep(pathlib.Path(folder) / "s.csv", ALPHAS, PRESSURES, FORCES, executor)
    assert computed == len(ALPHAS) * len(PRESSURES) * len(FORCES)


def one_process() -> None:
    for alpha in ALPHAS:
        for pressure in PRESSURES:
            shooting.compression_curve(alpha, pressure, FORCES)


def main() -> None:
    workers = cpus()
    points = len(ALPHAS) * len(PRESSURES) * len(FORCES)
    print(f"sweep of {len(ALPHAS) * len(PRESSURES)} curves x {len(FORCES)} forces = {points} points, shooting; "
          f"{workers} workers; load average {os.getloadavg()[0]:.2f}; medians of {REPEAT}")
    one_process()  # compiled code loaded in this process
    with local_executor(workers) as executor:
        wait([executor.submit(solve_point, "shooting", 0.3, 0.1, 0.5, {}) for _ in range(4 * workers)])
        point = median_time(lambda: per_point(executor), REPEAT)
        curve = median_time(lambda: per_curve(executor), REPEAT)
    alone = median_time(one_process, REPEAT)
    bar = BAR * alone / workers
    print(f"per-point tasks:              {point:7.3f} s")
    print(f"per-curve tasks:              {curve:7.3f} s   {point / curve:5.1f}x faster than per point")
    print(f"continuation in one process:  {alone:7.3f} s   per-curve tasks / (this / {workers} workers) = "
          f"{curve / (alone / workers):.2f}")
    print(f"bar: per-curve tasks <= {BAR} x {alone:.3f} / {workers} = {bar:.3f} s: "
          f"{'met' if curve <= bar else 'NOT met'}")
    print(f"load average after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
