"""Load stepping with a secant predictor and automatic step cutting.

The load goes from ``start`` to ``stop`` through a parameter s in [0, 1].
Each step solves at the new load from the secant extrapolation of the last
two converged states. A step that fails is halved; a step that converges in
few iterations is doubled. Below ``min_step`` the stepping gives up with a
``ConvergenceError`` naming the load it reached.

A step that lands outside the model (``OutOfRangeError``: the free part below
the clamp plane, a capsule's contact edge slack: ``steps.check_range``) is cut
like a failed one: a long step's Newton iterates can wander out of the model
although the load itself is inside it. Only a step
shorter than ``min_step`` beyond the last converged load that still lands
outside is reported as outside the model, in the words of
``pocket.core.errors.beyond_range``: the range then ends between that load and
the one tried beyond it, and both are quoted.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

import numpy as np

from pocket.core.errors import ConvergenceError, OutOfRangeError, beyond_range

__all__ = ["follow"]

_EASY = 4  # iterations at or below which the next step is doubled


def follow(
    solve: Callable[[float, np.ndarray], tuple[np.ndarray, int]],
    y0: np.ndarray,
    start: float,
    stop: float,
    *,
    first_step: float = 0.25,
    min_step: float = 1e-5,
    max_step: float = 1.0,
    name: str = "load",
    show: Callable[[float], float] = float,
) -> Iterator[tuple[float, np.ndarray, int]]:
    """Yield (load, y, iterations) for each converged step; the last is at ``stop``.

    ``solve(load, guess)`` returns (y, iterations) or raises ``ConvergenceError``
    or ``OutOfRangeError``; the error messages give a load as ``name = show(load)``.
    """
    s, ds = 0.0, min(first_step, max_step)
    y = np.asarray(y0, dtype=float)
    previous: tuple[float, np.ndarray] | None = None  # the converged step before the last, (s, y)
    while s < 1.0:
        ds = min(ds, 1.0 - s)
        s_new = 1.0 if s + ds > 1.0 - 1e-12 else s + ds
        if previous is None:
            guess = y
        else:
            s_prev, y_prev = previous
            guess = y + ((s_new - s) / (s - s_prev)) * (y - y_prev)
        load = stop if s_new == 1.0 else start + s_new * (stop - start)
        try:
            y_new, iterations = solve(load, guess)
        except (ConvergenceError, OutOfRangeError) as err:
            reached = start + s * (stop - start)
            ds *= 0.5
            if ds >= min_step:
                continue
            if isinstance(err, OutOfRangeError):
                end = f"{name} = {show(reached):.10g} to {show(load):.10g} (the last load converged and the " \
                    "nearest beyond it tried)"
                refusal = beyond_range(f"{name} = {show(stop):.10g}", end, str(err))
                refusal.end = end
                raise refusal from err
            raise ConvergenceError(
                f"load stepping gave up at {name} = {show(reached):.6g} on the way to {show(stop):.6g}: {err}",
                load=reached,
                iterations=err.iterations,
                residual=err.residual,
            ) from err
        previous, s, y = (s, y), s_new, y_new
        yield load, y, iterations
        if iterations <= _EASY:
            ds = min(2.0 * ds, max_step)
