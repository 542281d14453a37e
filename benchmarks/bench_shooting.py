"""Benchmark of the shooting solver, with scipy's ``solve_bvp`` as the peer on step 1.

    python benchmarks/bench_shooting.py

Prints medians of repeated runs (machines here are noisy; the load average is
printed with them) of one inflation, one compressed state, a 40-point compression
curve and a range end; the same inflation and curve for each other rubber law and for
a gas-filled pocket, with their ratios to the Mooney-Rivlin alpha path; ``solve_bvp`` on
the same inflation problem at matched accuracy, with the ratio; and a whole
``pocket compress`` process with 100 forces
(the first run, which may compile, excluded), with its start-up split into imports
(``python -X importtime``), the first call (numba's runtime and the cached machine
code) and solving.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys

import numpy as np
from pocket.shooting import end as ends
from pocket.shooting.equations import pole_state
from pocket.shooting.laws import law_of
from pocket.shooting.shots import R_POLE
from pocket.shooting.tensions import tensions
from scipy.integrate import solve_bvp
from timing import median_time

from pocket import shooting
from pocket.core.fluids import gas
from pocket.core.materials import check

ALPHA, PHAT = 47 / 160, 0.31
FORCES_100 = [f"{f:.4f}" for f in np.linspace(0.01, 1.0, 100)]
FIRST_CALL = """
import time
import numpy as np
from pocket.shooting.integrator import integrate
from pocket.shooting.equations import pole_state
from pocket.shooting.laws import law_of
law = law_of(0.3)
t = time.perf_counter()
integrate(pole_state(1.1, law, 1.0, 1e-5), 1e-5, law, 1.0, rtol=1e-10)
print(time.perf_counter() - t)
"""
#: the other laws, in Pa, with the Mooney-Rivlin sample's peers
OTHERS = {
    "mooney-rivlin (c1, c2)": check("mooney-rivlin", {"c1": 160e3, "c2": 47e3}),
    "neo-hookean": check("neo-hookean", {"mu": 0.4e6}),
    "yeoh": check("yeoh", {"c10": 85e3, "c20": -2e3, "c30": 0.2e3}),
    "gent": check("gent", {"mu": 0.3e6, "jm": 10.0}),
    "ogden (3 terms)": check("ogden", {"mu": [630e3, 1.2e3, -10e3], "exponents": [1.3, 5.0, -2.0]}),
}


def bvp_inflate(tol):
    """Step 1 as a boundary-value problem: unknown lambda_0, y(r0) on the pole series, rho(1) = 1."""
    law = law_of(ALPHA)
    p = law.pressure_factor * PHAT

    def f(r, y, par):
        rho, _, psi, l1, _ = y
        l2 = rho / r
        t1, t2, a11, a12 = tensions(l1, l2, law.code, law.params)
        drho = l1 * np.cos(psi)
        dl2 = (drho - l2) / r
        return np.vstack([drho, -l1 * np.sin(psi), l1 * (p - t2 * np.sin(psi) / rho) / t1,
                          ((t2 - t1) * drho / rho - a12 * dl2) / a11, np.pi * rho**2 * l1 * np.sin(psi)])

    def bc(ya, yb, par):
        return np.append(ya - pole_state(par[0], law, p, R_POLE), yb[0] - 1.0)

    r = np.linspace(R_POLE, 1, 50)
    s = (PHAT / (4 * np.sqrt(6))) ** (2 / 3)
    guess = np.vstack([r * (1 + s - s * r * r), -np.sqrt(1.5 * s) * r * r, 2 * np.sqrt(1.5 * s) * r,
                       np.full_like(r, 1 + s), np.zeros_like(r)])
    sol = solve_bvp(f, bc, r, guess, p=[1 + s], tol=tol, max_nodes=100000)
    if not sol.success:
        raise RuntimeError(sol.message)
    return sol


def _python(*args, **kw):
    return subprocess.run([sys.executable, *args], check=True, capture_output=True, text=True, **kw)


def import_breakdown() -> dict[str, float]:
    """Cumulative import time (s) of the modules a ``pocket compress`` loads, median of 5 processes."""
    names = ("numpy", "numba", "pocket.cli.main", "pocket.shooting.compression")
    runs = []
    for _ in range(5):
        err = _python("-X", "importtime", "-c", "import pocket.cli.main, pocket.shooting.compression").stderr
        pattern = r"^import time:\s*\d+ \|\s*(\d+) \|\s*(\S+)"
        found = {name: int(total) for total, name in re.findall(pattern, err, re.M)}
        runs.append([found.get(n, 0) * 1e-6 for n in names])
    return dict(zip(names, np.median(runs, axis=0), strict=True))


def main():
    load = os.getloadavg()[0]
    ref = shooting.inflate(ALPHA, PHAT, rtol=1e-13)
    shooting.compression_curve(ALPHA, PHAT, [0.1])  # compile/load once

    t_inf = median_time(lambda: shooting.inflate(ALPHA, PHAT), 21)
    err_inf = abs(shooting.inflate(ALPHA, PHAT).stretch_pole - ref.stretch_pole)
    t_one = median_time(lambda: shooting.compress(ALPHA, PHAT, 0.19), 11)
    forces = np.linspace(0.025, 1.0, 40)
    t_curve = median_time(lambda: shooting.compression_curve(ALPHA, PHAT, forces), 11)
    t_end = median_time(lambda: (ends._ENDS.clear(), shooting.range_end(ALPHA, PHAT)), 5)

    print(f"shooting (alpha = {ALPHA}, Phat_I = {PHAT}, rtol 1e-10), medians; load average {load:.1f} on "
          f"{os.cpu_count()} cores:")
    print(f"  one inflation            {t_inf * 1e3:8.2f} ms   |lambda_0 error| {err_inf:.1e}")
    print(f"  one compressed state     {t_one * 1e3:8.2f} ms   (includes its inflation)")
    print(f"  40-point curve           {t_curve * 1e3:8.2f} ms")
    print(f"  range end (uncached)     {t_end * 1e3:8.2f} ms   Fhat_end = {shooting.range_end(ALPHA, PHAT):.10g}")
    rows = [(name, rubber, None) for name, rubber in OTHERS.items()] + [("gas (alpha, ambient 1, gamma 1.4)", ALPHA,
                                                                          gas(1.0, 1.4))]
    for name, rubber, fluid in rows:
        shooting.compression_curve(rubber, PHAT, [0.1], fluid=fluid)  # compile/load once
        t_i = median_time(lambda r=rubber: shooting.inflate(r, PHAT), 11)
        t_c = median_time(lambda r=rubber, f=fluid: shooting.compression_curve(r, PHAT, forces, fluid=f), 5)
        print(f"  {name:<34s} inflation {t_i * 1e3:6.2f} ms ({t_i / t_inf:4.2f}x), 40-point curve "
              f"{t_c * 1e3:7.2f} ms ({t_c / t_curve:4.2f}x)")

    # The peer at matched accuracy: tighten tol until its lambda_0 error is no worse than ours.
    for tol in (1e-6, 1e-8, 1e-10):
        sol = bvp_inflate(tol)
        err_bvp = abs(sol.p[0] - ref.stretch_pole)
        if err_bvp <= max(err_inf, 1e-10):
            break
    t_bvp = median_time(lambda: bvp_inflate(tol), 3)
    print(f"  solve_bvp inflation      {t_bvp * 1e3:8.2f} ms   |lambda_0 error| {err_bvp:.1e} "
          f"(tol {tol:g}, {sol.x.size} nodes)")
    print(f"  ratio solve_bvp / shooting: {t_bvp / t_inf:.1f}x")

    cmd = ["-m", "pocket.cli", "compress", "--alpha", "47/160", "--pressure", "0.31", "--force", *FORCES_100]
    _python(*cmd)  # a first run may compile
    t_proc = median_time(lambda: _python(*cmd), 9)
    t_bare = median_time(lambda: _python("-c", "pass"), 9)
    first = np.median([float(_python("-c", FIRST_CALL).stdout) for _ in range(5)])
    t_solve = median_time(lambda: shooting.compression_curve(ALPHA, PHAT, np.linspace(0.01, 1, 100)), 5)
    print(f"whole process `pocket compress` with 100 forces (median of 9; load average now "
          f"{os.getloadavg()[0]:.1f}):")
    print(f"  total                    {t_proc * 1e3:8.0f} ms")
    print(f"  python itself            {t_bare * 1e3:8.0f} ms")
    for name, seconds in import_breakdown().items():
        print(f"  import {name:<28s}{seconds * 1e3:6.0f} ms (cumulative)")
    print(f"  first call (numba runtime, cached code) {first * 1e3:5.0f} ms")
    print(f"  solving 100 states       {t_solve * 1e3:8.0f} ms; the rest is the command line, printing and exit")


if __name__ == "__main__":
    main()
