"""One wall time for a whole validation run, quoted alike by the report and the console.

``pocket validate`` starts a ``Stopwatch`` before its first solve; the report
stops it once its figures and tables are written (only the two text files,
milliseconds, remain) and quotes its ``seconds``; the console prints the same
figure.
"""

from __future__ import annotations

import time

__all__ = ["Stopwatch"]


class Stopwatch:
    """Wall time from construction to the first ``stop()``, in seconds (``time.perf_counter``)."""

    def __init__(self):
        self.start = time.perf_counter()
        self._seconds = None

    def stop(self) -> float:
        """Stop (once: later calls keep the first reading); returns the seconds."""
        if self._seconds is None:
            self._seconds = time.perf_counter() - self.start
        return self._seconds

    @property
    def seconds(self) -> float:
        """The stopped time; ValueError if not stopped yet."""
        if self._seconds is None:
            raise ValueError("the stopwatch is still running")
        return self._seconds
