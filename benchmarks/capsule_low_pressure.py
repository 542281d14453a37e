"""Where a capsule's compression ends at low inflation pressures, and why an uninflated one is not posed.

    python benchmarks/capsule_low_pressure.py

A neo-Hookean capsule filled with a liquid, inflated to Phat_I = 0.1 down to 0.003 and pressed between two
plates: the end of its range by the shooting solver (``pocket.shooting.range_end``: where the slack patch under a
plate has spread to the contact edge and the meridional tension there vanishes; inf where the range has no end),
as Fhat, as F / (E T R) and as the compression 1 - H / lambda_I at a force just inside it. Above Phat_I ~ 0.02
the range has no end; below, it ends the sooner the lower P_I, at a compression falling about in proportion to
Phat_I, towards none at P_I = 0: the figures the solvers' refusal of an uninflated capsule quotes
(``pocket.core.errors.UNINFLATED_CAPSULE``). A low pressure's curve is shot in many segments: the script takes
about six minutes on 2 cores.
"""

from __future__ import annotations

import math
import os
import time

from pocket import shooting
from pocket.core.materials import mooney_rivlin

NEO_HOOKEAN = mooney_rivlin(0.0)
PRESSURES = (0.1, 0.03, 0.02, 0.01, 0.005, 0.003)
INSIDE = 0.999


def main():
    print(f"a neo-Hookean capsule filled with a liquid; load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} "
          "cores")
    print("  Phat_I    end Fhat     end F/(E T R)   compression at the end   seconds")
    for phat in PRESSURES:
        start = time.perf_counter()
        end = shooting.range_end(NEO_HOOKEAN, phat, geometry="capsule")
        if math.isinf(end):
            print(f"  {phat:<7g}   inf (no end)")
            continue
        state = shooting.compress(NEO_HOOKEAN, phat, INSIDE * end, geometry="capsule")
        compression = 1.0 - state.height / state.inflated.stretch_pole
        print(f"  {phat:<7g}   {end:<10.6g}   {end * math.pi * phat:<13.4e}   {compression:<22.4f}   "
              f"{time.perf_counter() - start:.1f}")


if __name__ == "__main__":
    main()
