"""Benchmark of the solid model: a compression curve's time and its distance from the membrane, and the peer.

    python benchmarks/bench_solid.py [--quick]

1. The headline pocket (Mooney-Rivlin alpha = 47/160, Phat_I = 0.31, a liquid) at T/R = 0.0125: a 10-force
   curve (Fhat 0.1 .. 1) with the solid's default mesh, its median time over repeats (one with --quick), the
   Newton iterations per state, and the shooting (membrane) solver's curve time beside it; then each state's
   P/P_I and H/H0 against the membrane's.
2. The peer: FElupe's axisymmetric solid on the same pocket, if felupe is installed (it is never a
   dependency of pocket: ``pip install felupe`` by hand); without it, this section says so and is skipped.
   The comparison itself is not written yet: the section reports that.
"""

from __future__ import annotations

import sys

import numpy as np
from timing import median_time

from pocket import shooting, solid
from pocket.core.materials import mooney_rivlin

MATERIAL, PHAT_I, THICKNESS = mooney_rivlin(47 / 160), 0.31, 0.0125
FORCES = np.linspace(0.1, 1.0, 10)


def main():
    quick = "--quick" in sys.argv
    repeat = 1 if quick else 3
    states = []

    def run_solid():
        states[:] = solid.compression_curve(MATERIAL, PHAT_I, FORCES, thickness_ratio=THICKNESS)

    seconds = median_time(run_solid, repeat)
    membrane = []

    def run_membrane():
        membrane[:] = shooting.compression_curve(MATERIAL, PHAT_I, FORCES)

    reference = median_time(run_membrane, repeat)
    iterations = np.mean([s.extra["iterations"] for s in states])
    print(f"1. 10-force curve at T/R = {THICKNESS}: solid {seconds:.1f} s (median of {repeat}; "
          f"{iterations:.0f} Newton iterations per state), shooting {reference:.2f} s")
    print("   Fhat    P/P_I solid   membrane    rel. diff    H/H0 solid   membrane    rel. diff")
    for s, m in zip(states, membrane, strict=True):
        print(f"   {s.force:4.2f}   {s.pressure_ratio:.6f}   {m.pressure_ratio:.6f}   "
              f"{s.pressure_ratio / m.pressure_ratio - 1:+.2e}    {s.height_ratio:.6f}   {m.height_ratio:.6f}   "
              f"{s.height_ratio / m.height_ratio - 1:+.2e}")
    try:
        import felupe  # noqa: F401
    except ImportError:
        print("2. FElupe peer: skipped, felupe is not installed (pip install felupe; never a dependency)")
        return
    print("2. FElupe peer: felupe is installed, but the side-by-side model is not written yet")


if __name__ == "__main__":
    main()
