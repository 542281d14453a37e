"""Benchmark of the uninflated capsule (P_I = 0): a state at a plate height, and at a force in units of E T R.

    python benchmarks/bench_uninflated.py

Prints medians of repeated runs (the load average with them), after one run that compiles (or loads the compiled
code), of a neo-Hookean capsule filled with a liquid at P_I = 0 pressed to the plate height H = 0.6 R and by the
force F = 0.5 E T R on each plate, and along a curve of five forces, by each solver, with the shooting solver's time
over the finite elements'. The uninflated capsule is reached by a descent from a capsule inflated to Phat_I = 0.1
(``pocket.shooting.descent``, ``pocket.fem.descent``); under force control the shooting solver finds the height by
Brent's method on its descents (each about a tenth of a second) after locating the branch's start (once for a
curve), the finite elements by their force continuation on the deep branch.
"""

from __future__ import annotations

import os

from timing import median_time

from pocket import fem, shooting

NEO = 0.0  # Mooney-Rivlin alpha = 0: the neo-Hookean rubber
HEIGHT, FORCE_ETR = 0.6, 0.5
CURVE_ETR = (0.1, 0.2, 0.5, 1.0, 2.0)
REPEAT = 5

CALLS = {
    "P_I = 0, H = 0.6 R": lambda solver: solver.compress_height(NEO, 0.0, HEIGHT, geometry="capsule"),
    "P_I = 0, F = 0.5 E T R": lambda solver: solver.compress(NEO, 0.0, FORCE_ETR, geometry="capsule",
                                                             force_unit="ETR"),
    "P_I = 0, F = 0.1 to 2 E T R, 5 forces": lambda solver: solver.compression_curve(
        NEO, 0.0, CURVE_ETR, geometry="capsule", force_unit="ETR"),
}


def main():
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores; medians of {REPEAT} runs")
    print(f"  {'state':<38s} {'shooting':>10s} {'fem':>10s} {'shooting / fem':>15s}")
    for name, call in CALLS.items():
        times = []
        for solver in (shooting, fem):
            call(solver)  # compiles, and caches the inflations
            times.append(median_time(lambda solver=solver, call=call: call(solver), REPEAT))
        print(f"  {name:<38s} {times[0]:>9.3f}s {times[1]:>9.3f}s {times[0] / times[1]:>15.1f}")


if __name__ == "__main__":
    main()
