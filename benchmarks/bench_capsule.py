"""Benchmark of a capsule's compression between two plates against a pocket's under the plate.

    python benchmarks/bench_capsule.py

Prints medians of repeated runs (machines here are noisy; the load average is printed with them), after one
run that compiles (or loads the compiled code) and caches each problem's range end, of a 20-force compression
curve of a closed capsule (Mooney-Rivlin, alpha = 47/160, a liquid, Phat_I = 0.31, forces Fhat = 0.25 to 5: the
compression 1 - H/lambda_I to about 0.66) and of the pocket of the same rubber at the same Phat_I (20 forces
to 0.9 of its range end, or Fhat = 1), by each solver that poses the capsule, with the capsule's time over the
pocket's. The capsule's shots run over a quarter circle from the pole to the equator, the pocket's over the
sheet's radius; both solve one force from the last by Newton on three unknowns.
"""

from __future__ import annotations

import importlib
import os

import numpy as np
from timing import median_time

from pocket import shooting
from pocket.core.errors import InputError

ALPHA, PHAT = 47 / 160, 0.31
CAPSULE_FORCES = np.linspace(0.25, 5.0, 20)
REPEAT = 5


def _poses_capsules(solver) -> bool:
    """Whether ``solver`` takes geometry="capsule" (the FE model does once its capsule is in)."""
    try:
        solver.inflate(ALPHA, PHAT, geometry="capsule")
    except InputError:  # "solver fem does not implement the capsule geometry"
        return False
    return True


def main():
    load = os.getloadavg()[0]
    pocket_forces = np.linspace(0.05, 1.0, 20) * min(1.0, 0.9 * shooting.range_end(ALPHA, PHAT))
    print(f"a capsule against a pocket (alpha = {ALPHA:.4g}, Phat_I = {PHAT}, a liquid, 20 forces each), medians of "
          f"{REPEAT} runs; load average {load:.1f} on {os.cpu_count()} cores:")
    for name in ("shooting", "fem"):
        solver = importlib.import_module(f"pocket.{name}")
        if not _poses_capsules(solver):
            print(f"  {name:8s} poses no capsule: skipped")
            continue
        def capsule(solver=solver):
            return solver.compression_curve(ALPHA, PHAT, CAPSULE_FORCES, geometry="capsule")

        def pocket(solver=solver):
            return solver.compression_curve(ALPHA, PHAT, pocket_forces)

        last = capsule()[-1]
        pocket()  # compiled, range ends cached
        t_capsule, t_pocket = median_time(capsule, REPEAT), median_time(pocket, REPEAT)
        print(f"  {name:8s} capsule {t_capsule * 1e3:8.1f} ms   pocket {t_pocket * 1e3:8.1f} ms   capsule / pocket "
              f"{t_capsule / t_pocket:5.2f}   (capsule's last state: 1 - H/lambda_I = "
              f"{1 - last.height / last.inflated.stretch_pole:.3f}, F/(E T R) = {last.extra['force_ETR']:.3f})")


if __name__ == "__main__":
    main()
