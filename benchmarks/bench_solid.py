"""Benchmark of the solid model: a compression curve's time, its mesh convergence, the membrane and the peer.

    python benchmarks/bench_solid.py [--quick]

1. The headline pocket (Mooney-Rivlin alpha = 47/160, Phat_I = 0.31, a liquid) at T/R = 0.0125: a 10-force
   curve (Fhat 0.1 .. 1) on the mesh ``MESH``, its median time over 3 repeats (one with --quick) beside the
   FElupe baseline the solid was set against (37-40 s for a 17-force curve on this machine: the ratios
   FElupe / solid per curve and per force). Then the mesh's convergence in P/P_I, measured: the same curve
   on meshes refined twice along the radius, through the thickness, and both, and on 256 elements along the
   radius (the reference the default's accuracy is quoted against), each its largest relative
   difference in P/P_I from ``MESH``'s over the 10 forces, with its time (a mesh whose Newton iteration
   stalls says after which force). --quick skips the refined meshes.
2. Each state's P/P_I and H/H0 against the membrane's (``pocket.shooting``), and the shooting curve's time.
3. The peer: FElupe's axisymmetric solid (``felupe_pocket.py``) timed on the first forces of the same curve, if
   felupe and tensortrax are installed (never dependencies of pocket: ``pip install felupe tensortrax`` by
   hand); without them, this section says so and is skipped.
"""

from __future__ import annotations

import importlib.util
import itertools
import os
import sys
import time

import numpy as np
from timing import median_time

from pocket import shooting, solid
from pocket.core.errors import ConvergenceError
from pocket.core.materials import mooney_rivlin

MATERIAL, PHAT_I, THICKNESS = mooney_rivlin(47 / 160), 0.31, 0.0125
FORCES = np.linspace(0.1, 1.0, 10)
#: (elements along the radius, layers through the thickness): the solid's default
MESH = (solid.DEFAULT_ELEMENTS, solid.DEFAULT_LAYERS)
#: the refined meshes of the convergence check, with what each refines
REFINED = (((2 * MESH[0], MESH[1]), "radius x 2"), ((MESH[0], 2 * MESH[1]), "thickness x 2"),
           ((2 * MESH[0], 2 * MESH[1]), "both x 2"), ((256, MESH[1]), "256 elements"))
#: the issue's FElupe baseline on this machine: a 17-force curve in 37-40 s
FELUPE_SECONDS, FELUPE_FORCES = (37.0, 40.0), 17
#: FElupe's mesh (``bench_felupe.MESH``) and the forces it is timed on here
FELUPE_MESH, FELUPE_TIMED = (64, 4), FORCES[:3]


def curve(elements: int, layers: int):
    """P/P_I at ``FORCES`` on the mesh, the wall time, and the last force reached (all of them, or fewer when
    Newton stalls: then P/P_I is None)."""
    done = []
    tic = time.perf_counter()
    try:
        states = solid.compression_curve(MATERIAL, PHAT_I, FORCES, thickness_ratio=THICKNESS, elements=elements,
                                         layers=layers, progress=lambda k, n: done.append(k))
    except ConvergenceError as err:
        reached = FORCES[done[-1] - 1] if done else 0.0
        return None, time.perf_counter() - tic, f"stalled after Fhat = {reached:.1f} ({err})"
    return np.array([s.pressure_ratio for s in states]), time.perf_counter() - tic, ""


def section_1(quick: bool):
    repeat = 1 if quick else 3
    states = []

    def run():
        states[:] = solid.compression_curve(MATERIAL, PHAT_I, FORCES, thickness_ratio=THICKNESS, elements=MESH[0],
                                            layers=MESH[1])

    seconds = median_time(run, repeat)
    low, high = FELUPE_SECONDS
    iterations = sum(s.extra["iterations"] for s in states)
    print(f"1. 10-force curve (Fhat 0.1 .. 1) at T/R = {THICKNESS}, mesh {MESH[0]} x {MESH[1]}: {seconds:.2f} s "
          f"(median of {repeat}; {iterations} Newton iterations after the inflation; load average "
          f"{os.getloadavg()[0]:.1f} on {os.cpu_count()} cores)")
    own = seconds / FORCES.size
    print(f"   FElupe baseline {low:.0f}-{high:.0f} s for {FELUPE_FORCES} forces: per curve FElupe / solid = "
          f"{low / seconds:.1f}-{high / seconds:.1f}; per force ({low / FELUPE_FORCES:.2f}-"
          f"{high / FELUPE_FORCES:.2f} s against {own:.3f} s) {low / FELUPE_FORCES / own:.1f}-"
          f"{high / FELUPE_FORCES / own:.1f}")
    base = np.array([s.pressure_ratio for s in states])
    if quick:
        print("   mesh convergence: skipped (--quick)")
        return states, seconds
    print(f"   mesh convergence of P/P_I: each refined mesh against {MESH[0]} x {MESH[1]} (largest relative "
          "difference over the 10 forces):")
    rows = {MESH: base}
    for (n, k), what in REFINED:
        ratios, spent, note = curve(n, k)
        if ratios is None:
            print(f"   {n:4d} x {k:<2d} ({what:13s}) {spent:7.1f} s  {note}")
            continue
        rows[(n, k)] = ratios
        worst = np.abs(ratios / base - 1.0)
        print(f"   {n:4d} x {k:<2d} ({what:13s}) {spent:7.1f} s  max |dP/P_I| / (P/P_I) = {worst.max():.1e} "
              f"(at Fhat = {FORCES[np.argmax(worst)]:.1f})")
    layers = sorted(k for n, k in rows if n == MESH[0])
    for a, b in itertools.pairwise(layers):
        step = np.abs(rows[(MESH[0], b)] / rows[(MESH[0], a)] - 1.0).max()
        print(f"   through the thickness, {a} -> {b} layers ({MESH[0]} elements): max relative change {step:.1e}")
    return states, seconds


def section_2(states):
    membrane = []

    def run():
        membrane[:] = shooting.compression_curve(MATERIAL, PHAT_I, FORCES)

    reference = median_time(run, 3)
    print(f"2. the membrane (pocket.shooting, its curve in {reference:.2f} s): the solid's difference")
    print("   Fhat    P/P_I solid   membrane    rel. diff    H/H0 solid   membrane    rel. diff")
    for s, m in zip(states, membrane, strict=True):
        print(f"   {s.force:4.2f}   {s.pressure_ratio:.6f}   {m.pressure_ratio:.6f}   "
              f"{s.pressure_ratio / m.pressure_ratio - 1:+.2e}    {s.height_ratio:.6f}   {m.height_ratio:.6f}   "
              f"{s.height_ratio / m.height_ratio - 1:+.2e}")


def section_3(seconds_per_force: float):
    if importlib.util.find_spec("felupe") is None or importlib.util.find_spec("tensortrax") is None:
        print("3. FElupe peer: skipped, felupe and tensortrax are not installed (pip install felupe tensortrax; "
              "never dependencies)")
        return
    sys.path.insert(0, os.path.dirname(__file__))
    import felupe_pocket as fp

    m = fp.build(elements=FELUPE_MESH[0], layers=FELUPE_MESH[1])
    tic = time.perf_counter()
    inflated = fp.inflate(m)
    inflation = time.perf_counter() - tic
    rows = fp.compress(m, inflated, FELUPE_TIMED)
    per_force = rows[-1]["seconds"] / len(rows)
    print(f"3. FElupe (mesh {FELUPE_MESH[0]} x {FELUPE_MESH[1]}, load average {os.getloadavg()[0]:.1f}): inflation "
          f"{inflation:.1f} s, {len(rows)} forces (Fhat {', '.join(f'{f:.1f}' for f in FELUPE_TIMED)}) in "
          f"{rows[-1]['seconds']:.1f} s: {per_force:.2f} s per force against the solid's {seconds_per_force:.3f} s "
          f"(ratio {per_force / seconds_per_force:.1f})")


def main():
    quick = "--quick" in sys.argv
    tic = time.perf_counter()
    states, seconds = section_1(quick)
    section_2(states)
    section_3(seconds / FORCES.size)
    print(f"(benchmark wall time {time.perf_counter() - tic:.0f} s)")


if __name__ == "__main__":
    main()
