"""Where a capsule's first branch of states ends at low inflation pressures, and where the deep branch starts.

    python benchmarks/capsule_low_pressure.py

A neo-Hookean capsule filled with a liquid, inflated to Phat_I = 0.1 down to 0.001 (and 0) and pressed between two
plates. First, the end of the branch pressed from the touch (where the slack patch under a plate has spread to
the contact edge and the meridional tension there vanishes; "none" where it has no end), by both solvers
independently: the shooting solver's ``range_end`` (down to Phat_I = 0.003: below, its shots need more segments
than it takes), and the largest force the finite elements solve from the touch (without the deep branch's
descent), bisected between a force they solve and one they refuse (``OutOfRangeError``) to a relative 1e-5; then
F / (E T R) and the compression 1 - H / lambda_I there, from the finite elements' state. Above Phat_I ~ 0.02 that
branch has no end; below, it ends the sooner the lower P_I, at a compression that tends to about 4 Phat_I.
Second, where the states resume (``pocket.fem.descent``): the plates' height bracket the finite elements quote for
a height just below the first branch's end (near the top at P_I = 0), and at its upper end F / (E T R), the
compression and the edge's tension. The shots at low pressure take many segments: the script takes about seven
minutes on 2 cores.
"""

from __future__ import annotations

import math
import os
import re
import time

import numpy as np
from pocket.fem import api, capsulestates, curves

from pocket import fem, shooting
from pocket.core.errors import CAPSULE_EDGE, OutOfRangeError
from pocket.core.geometries import CAPSULE
from pocket.core.materials import mooney_rivlin

NEO_HOOKEAN = mooney_rivlin(0.0)
PRESSURES = (0.1, 0.03, 0.02, 0.01, 0.005, 0.003, 0.001)
SHOOTING_LOWEST = 0.003  # the lowest Phat_I whose shots the shooting solver's segments take
BISECTION = 1e-5
NO_END = 10.0  # a range that reaches this Fhat is taken to have no end (the shooting solver finds none there)


def _first_branch(phat: float, force: float):
    """The finite elements' state at Fhat = ``force`` pressed from the touch (without the deep branch's descent)."""
    m, _, _, tol, y_i, inflated, fill, _ = api._setup(NEO_HOOKEAN, phat, None, None, CAPSULE, None, None, 2, "fitted",
                                                      None, None, 1e-10)
    return curves.fitted_curve(m, y_i, inflated, fill, [force], tol, builder=capsulestates)[0]


def _on_first_branch(phat: float, force: float):
    """The state of ``_first_branch``, or None past the end of that branch (the contact edge's tension vanished:
    any other refusal is raised)."""
    try:
        return _first_branch(phat, force)
    except OutOfRangeError as err:
        if CAPSULE_EDGE not in str(err):
            raise
        return None


def fem_end(phat: float):
    """(the largest Fhat the finite elements solve from the touch, to ``BISECTION``, and its state), or (inf, None)
    if they reach ``NO_END``."""
    low, high, state = 0.0, NO_END, None
    if _on_first_branch(phat, high) is not None:
        return math.inf, None
    while high - low > BISECTION * high:
        middle = 0.5 * (low + high)
        found = _on_first_branch(phat, middle)
        low, high, state = (middle, high, found) if found is not None else (low, middle, state)
    return low, state


def fem_start(phat: float, end_state):
    """The start of the finite elements' deep branch (``pocket.fem.descent``): (the height bracket [reached,
    beyond] its refusal quotes for a height just below the first branch's end state ``end_state``, or near the top
    at P_I = 0; the state at the reached height)."""
    probe = end_state.height - 1e-3 if end_state is not None else 0.999
    try:
        fem.compress_height(NEO_HOOKEAN, phat, probe, geometry="capsule")
    except OutOfRangeError as err:
        found = re.search(r"start(?:s)? (?:deeper, )?at plate height h/R = (\S+) to (\S+) \(", str(err))
        if found is None:
            raise
        reached, beyond = (float(v) for v in found.groups())
        return (reached, beyond), fem.compress_height(NEO_HOOKEAN, phat, reached, geometry="capsule")
    raise AssertionError(f"Phat_I = {phat}: a state at H = {probe}, past the first branch: no gap")


def main():
    print(f"a neo-Hookean capsule filled with a liquid; load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} "
          "cores")
    print("the end of the first branch (pressed from the touch):")
    print("  Phat_I    end Fhat (shooting)   end Fhat (FE)   F/(E T R)    compression   seconds")
    ends = {0.0: None}
    for phat in PRESSURES:
        start = time.perf_counter()
        shot = shooting.range_end(NEO_HOOKEAN, phat, geometry="capsule") if phat >= SHOOTING_LOWEST else None
        end, state = fem_end(phat)
        shot_text = "(not shot)" if shot is None else ("none" if math.isinf(shot) else f"{shot:.6g}")
        if state is None:
            print(f"  {phat:<7g}   {shot_text:<19s}   none")
            continue
        ends[phat] = state
        compression = 1.0 - state.height / state.inflated.stretch_pole
        print(f"  {phat:<7g}   {shot_text:<19s}   {end:<13.6g}   {end * math.pi * phat:<10.3e}   "
              f"{100 * compression:5.2f} %       {time.perf_counter() - start:.1f}")
    print("the start of the deep branch (the finite elements, the plates' height bracketed; the state at its top):")
    print("  Phat_I    H/R start (FE)               F/(E T R)    compression   edge T_1 (E T)   seconds")
    for phat, end_state in ends.items():
        start = time.perf_counter()
        (reached, beyond), state = fem_start(phat, end_state)
        edge = state.profile.tension_1[np.flatnonzero(state.profile.contact)[-1]]
        compression = 1.0 - state.height / state.inflated.stretch_pole
        print(f"  {phat:<7g}   [{reached:.7f}, {beyond:.7f}]   {state.extra['force_ETR']:<10.4g}   "
              f"{100 * compression:5.2f} %       {edge:<14.2e}   {time.perf_counter() - start:.1f}")

if __name__ == "__main__":
    main()
