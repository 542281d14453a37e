"""Wall time of a call as the median of repeats (these machines are noisy)."""

import statistics
import time


def median_time(fun, repeat: int) -> float:
    """Median wall time of ``fun()`` over ``repeat`` calls, in seconds."""
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fun()
        times.append(time.perf_counter() - t)
    return statistics.median(times)
