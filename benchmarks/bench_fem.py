"""Benchmark of the finite-element solver: cost against element count, and where it goes.

    python benchmarks/bench_fem.py [--quick]

Prints, for P2 meshes of 1e2 .. 1e5 elements, medians of repeated runs of one
Newton iteration split into residual assembly, tangent assembly and the sparse
solve, and the time of one converged inflated state (Phat = 0.31 from the small
dome); then the time of a 40-point compression curve at the default mesh with
the share of assembly and solve in it. Cost per iteration should grow about
linearly with the element count (the ratio column).
"""

from __future__ import annotations

import sys
import time

import numpy as np
import scipy.sparse.linalg as spla
from pocket.fem import inflation, model
from pocket.fem.newton import Tolerances
from timing import median_time

from pocket import fem, meshes

ALPHA, PHAT = 47 / 160, 0.31


def per_iteration(n, repeat):
    """(residual, tangent, solve) medians at the inflated state on n P2 elements."""
    m = model.discretize(ALPHA, meshes.uniform(n), 2, 1e5)
    lam = m.zero_multiplier()
    y, _ = inflation.to_pressure(m, PHAT, lam, Tolerances())
    control = model.Control(pressure=PHAT)
    r, jac = model.residual(m, y, control, lam), model.jacobian(m, y, control, lam)
    return (
        median_time(lambda: model.residual(m, y, control, lam), repeat),
        median_time(lambda: model.jacobian(m, y, control, lam), repeat),
        median_time(lambda: spla.spsolve(jac, -r), repeat),
    )


def converged_state(n, repeat):
    """(seconds, Newton iterations) of one inflation to Phat from the small dome."""
    state = fem.inflate(ALPHA, PHAT, mesh=meshes.uniform(n))
    return median_time(lambda: fem.inflate(ALPHA, PHAT, mesh=meshes.uniform(n)), repeat), state


class _Timer:
    """Wraps a function and accumulates its wall time."""

    def __init__(self, fun):
        self.fun, self.seconds, self.calls = fun, 0.0, 0

    def __call__(self, *args, **kwargs):
        t = time.perf_counter()
        try:
            return self.fun(*args, **kwargs)
        finally:
            self.seconds += time.perf_counter() - t
            self.calls += 1


def curve_breakdown(points):
    """Time a compression curve at the default mesh, split into assembly and solve."""
    from pocket.fem import newton, steps

    timers = {"residual": _Timer(model.residual), "tangent": _Timer(model.jacobian),
              "solve": _Timer(spla.spsolve)}
    originals = steps.residual, steps.jacobian, newton.spla
    steps.residual, steps.jacobian = timers["residual"], timers["tangent"]
    newton.spla = type("spla", (), {"spsolve": staticmethod(timers["solve"])})
    forces = np.linspace(0.02, 0.8, points)
    try:
        t = time.perf_counter()
        states = fem.compression_curve(ALPHA, PHAT, forces)
        total = time.perf_counter() - t
    finally:
        steps.residual, steps.jacobian, newton.spla = originals
    return total, states, timers


def main(argv=None):
    quick = "--quick" in (sys.argv[1:] if argv is None else argv)
    sizes = [100, 1000, 10000] if quick else [100, 1000, 10000, 100000]
    print("P2 elements | residual [ms] | tangent [ms] | solve [ms] | iteration [ms] | ratio"
          " | inflation [s] | Newton its | per it [ms]")
    base = None
    for n in sizes:
        repeat = 7 if n <= 10000 else 3
        r, j, s = per_iteration(n, repeat)
        it = r + j + s
        base = base or it / n
        seconds, state = converged_state(n, 3 if n <= 10000 else 1)
        iterations = state.extra["newton_iterations"]
        print(f"{n:11d} | {1e3 * r:13.2f} | {1e3 * j:12.2f} | {1e3 * s:10.2f} | {1e3 * it:14.2f} |"
              f" {it / n / base:5.2f} | {seconds:13.3f} | {iterations:10d} | {1e3 * seconds / iterations:11.2f}")
    points = 10 if quick else 40
    total, states, timers = curve_breakdown(points)
    iterations = sum(s.extra["newton_iterations"] for s in states) + states[0].inflated.extra["newton_iterations"]
    print(f"\n{points}-point compression curve, default mesh ({states[0].extra['elements']} P2 elements,"
          f" Fhat 0.02..0.8): {total:.2f} s, {iterations} Newton iterations, {total / points:.3f} s per state")
    for name, timer in timers.items():
        print(f"  {name:8s}: {timer.seconds:7.2f} s ({100 * timer.seconds / total:4.1f} %), {timer.calls} calls")
    rest = total - sum(t.seconds for t in timers.values())
    print(f"  other   : {rest:7.2f} s ({100 * rest / total:4.1f} %) (post-processing, predictors, checks)")


if __name__ == "__main__":
    main()
