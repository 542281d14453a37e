"""Where a capsule's compression ends at low inflation pressures, and why an uninflated one is not pressed.

    python benchmarks/capsule_low_pressure.py

A neo-Hookean capsule filled with a liquid, inflated to Phat_I = 0.1 down to 0.001 and pressed between two
plates: the end of its range (where the slack patch under a plate has spread to the contact edge and the
meridional tension there vanishes; "none" where the range has no end), by both solvers independently: the
shooting solver's ``range_end`` (down to Phat_I = 0.003: below, its shots need more segments than it takes),
and the largest force the finite elements solve, bisected between a force they solve and one they refuse
(``OutOfRangeError``) to a relative 1e-5; then F / (E T R) and the compression 1 - H / lambda_I there, from the
finite elements' state. Above Phat_I ~ 0.02 the range has no end; below, it ends the sooner the lower P_I, at a
compression that tends to about 4 Phat_I: none at P_I = 0, the figures the solvers' refusal of an uninflated
capsule quotes (``pocket.core.errors.UNINFLATED_CAPSULE``). The shots at low pressure take many segments: the
script takes about six minutes on 2 cores.
"""

from __future__ import annotations

import math
import os
import time

from pocket import fem, shooting
from pocket.core.errors import CAPSULE_EDGE, OutOfRangeError
from pocket.core.materials import mooney_rivlin

NEO_HOOKEAN = mooney_rivlin(0.0)
PRESSURES = (0.1, 0.03, 0.02, 0.01, 0.005, 0.003, 0.001)
SHOOTING_LOWEST = 0.003  # the lowest Phat_I whose shots the shooting solver's segments take
NO_END = 10.0  # a range that reaches this Fhat is taken to have no end (the shooting solver finds none there)
BISECTION = 1e-5


def _fem_state(phat: float, force: float):
    """The finite elements' state at Fhat = ``force``, or None past the end of the range (the contact edge's
    tension vanished: any other refusal is raised)."""
    try:
        return fem.compress(NEO_HOOKEAN, phat, force, geometry="capsule")
    except OutOfRangeError as err:
        if CAPSULE_EDGE not in str(err):
            raise
        return None


def fem_end(phat: float):
    """(the largest Fhat the finite elements solve, to ``BISECTION``, and its state), or (inf, None) if they reach
    ``NO_END``."""
    low, high, state = 0.0, NO_END, None
    if _fem_state(phat, high) is not None:
        return math.inf, None
    while high - low > BISECTION * high:
        middle = 0.5 * (low + high)
        found = _fem_state(phat, middle)
        low, high, state = (middle, high, found) if found is not None else (low, middle, state)
    return low, state


def main():
    print(f"a neo-Hookean capsule filled with a liquid; load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} "
          "cores")
    print("  Phat_I    end Fhat (shooting)   end Fhat (FE)   F/(E T R)    compression   seconds")
    for phat in PRESSURES:
        start = time.perf_counter()
        shot = shooting.range_end(NEO_HOOKEAN, phat, geometry="capsule") if phat >= SHOOTING_LOWEST else None
        end, state = fem_end(phat)
        shot_text = "(not shot)" if shot is None else ("none" if math.isinf(shot) else f"{shot:.6g}")
        if state is None:
            print(f"  {phat:<7g}   {shot_text:<19s}   none")
            continue
        compression = 1.0 - state.height / state.inflated.stretch_pole
        print(f"  {phat:<7g}   {shot_text:<19s}   {end:<13.6g}   {end * math.pi * phat:<10.3e}   "
              f"{100 * compression:5.2f} %       {time.perf_counter() - start:.1f}")


if __name__ == "__main__":
    main()
