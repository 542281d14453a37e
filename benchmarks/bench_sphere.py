"""Benchmark of the shooting solver under a sphere (a fingertip) against the flat plate.

    python benchmarks/bench_sphere.py

Prints medians of repeated runs (machines here are noisy; the load average is printed with them)
of a 40-point compression curve under the plate and under spheres of R_s/R = 0.8 (an 8 mm fingertip on
a 20 mm button) and 4, with their ratios to the plate's, for the Mooney-Rivlin sample with a liquid and
with a gas; and the range end under each (uncached). Each curve ends below its range end.
"""

from __future__ import annotations

import os

import numpy as np
from pocket.shooting import end as ends
from timing import median_time

from pocket import shooting
from pocket.core.fluids import gas
from pocket.core.indenters import Sphere

ALPHA, PHAT = 47 / 160, 0.31
INDENTERS = {"plate": None, "sphere R_s/R = 0.8": Sphere(0.8), "sphere R_s/R = 4": Sphere(4.0)}


def main():
    load = os.getloadavg()[0]
    print(f"shooting under a sphere (alpha = {ALPHA}, Phat_I = {PHAT}, rtol 1e-10), medians; load average "
          f"{load:.1f} on {os.cpu_count()} cores:")
    for fluid_name, fluid in (("liquid", None), ("gas (ambient 1, gamma 1.4)", gas(1.0, 1.4))):
        print(f"  {fluid_name}")
        plate_curve = None
        for name, indenter in INDENTERS.items():
            end = shooting.range_end(ALPHA, PHAT, fluid=fluid, indenter=indenter)  # compiles/loads once
            forces = np.linspace(0.025, 0.9, 40) * min(1.0, end)
            t_curve = median_time(lambda f=forces, i=indenter, g=fluid: shooting.compression_curve(
                ALPHA, PHAT, f, fluid=g, indenter=i), 5)
            t_end = median_time(lambda i=indenter, g=fluid: (ends._ENDS.clear(), shooting.range_end(
                ALPHA, PHAT, fluid=g, indenter=i)), 3)
            plate_curve = plate_curve or t_curve
            print(f"    {name:20s} 40-point curve {t_curve * 1e3:8.1f} ms ({t_curve / plate_curve:4.1f}x the "
                  f"plate's)   range end {t_end * 1e3:8.1f} ms   Fhat_end = {end:.8g}")


if __name__ == "__main__":
    main()
