"""Benchmark of ``pocket fit``: a Yeoh fit to 30 bulge points, the whole process.

    python benchmarks/bench_fit.py

Writes a bulge test of the Yeoh example rubber (30 heights with 0.2 % seeded noise, pole stretch up to
2.3) to a temporary CSV, then times ``pocket fit bulge.csv --law yeoh ...`` as a new process each time
(imports, numba's cached code, reading, the fit and its statistics): the median of a few runs after
a first one that may compile, with the load average (the machine is shared), and the solver calls
(entry points called: an inflation test's 30 pressures are one ``inflation_curve`` call).
"""

from __future__ import annotations

import json
import os
import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np

from pocket import shooting
from pocket.core.materials import LAWS, check

R, T, RUNS = 0.02, 1e-3, 3


def _bulge(path: pathlib.Path) -> None:
    truth = check("yeoh", dict(LAWS["yeoh"].example))
    tension = 3.0 * truth.mu0 * T
    rng = np.random.default_rng(1)
    rows = []
    for p in np.linspace(0.02, 0.6, 30):
        height = shooting.inflate(truth.scaled(), p).height * R * (1.0 + 0.002 * rng.standard_normal())
        rows.append(f"{float(p * tension / R / 1e3)!r},{float(height * 1e3)!r}")
    path.write_text("pressure [kPa],height [mm]\n" + "\n".join(rows) + "\n")


def main() -> None:
    with tempfile.TemporaryDirectory() as folder:
        data = pathlib.Path(folder) / "bulge.csv"
        _bulge(data)
        command = [sys.executable, "-m", "pocket", "fit", str(data), "--law", "yeoh", "--radius", "20 mm",
                   "--thickness", "1 mm", "--json"]
        times, out = [], {}
        for _ in range(RUNS + 1):
            start = time.perf_counter()
            out = json.loads(subprocess.run(command, check=True, capture_output=True, text=True).stdout)
            times.append(time.perf_counter() - start)
    print(f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores")
    print(f"yeoh fit, 30 bulge points, whole process: median {np.median(times[1:]):.2f} s over {RUNS} runs "
          f"(first run {times[0]:.2f} s); {out['solver_calls']} solver calls, fit {out['seconds']:.2f} s")


if __name__ == "__main__":
    main()
