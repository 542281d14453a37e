"""``interrupts``: a Ctrl-C that is acted on wherever it lands, even where Python ignores exceptions.

Python turns SIGINT into a KeyboardInterrupt raised in whatever Python code the
main thread runs next. When that code is a callback whose exceptions are
ignored, the interrupt is printed ("Exception ignored ...") and dropped, and the
program carries on as if no key had been pressed. numba's compiler runs such a
callback (llvmlite's object-cache hook) each time it emits machine code, so a
Ctrl-C during the first run's compilation could be lost.

``remembered()``, for the duration of a command, installs a SIGINT handler that
records the interrupt before raising it, and a hook that keeps an ignored
KeyboardInterrupt quiet once recorded. Code that returns from such a callback
calls ``check()``, which raises the recorded interrupt again: ``compiled`` does
after every compilation, the command line after its command. Outside
``remembered()`` (pocket used as a library) nothing is recorded and ``check()``
does nothing.
"""

from __future__ import annotations

import contextlib
import signal
import sys
import threading

__all__ = ["check", "remembered"]

_received = False


def _record(signum, frame) -> None:
    """The SIGINT handler: remember the interrupt, then raise it as Python's own handler does."""
    global _received
    _received = True
    raise KeyboardInterrupt


def check() -> None:
    """Raise KeyboardInterrupt if an interrupt was recorded (module docstring)."""
    if _received:
        raise KeyboardInterrupt


@contextlib.contextmanager
def remembered():
    """Record interrupts while the block runs (module docstring); the previous SIGINT handler and
    unraisable hook are restored after it. Outside the main thread (where no signal handler can be
    installed), or where SIGINT is not Python's own handler (ignored, as in a background job, or
    handled by the program calling pocket), a no-op."""
    global _received
    if threading.current_thread() is not threading.main_thread() or \
            signal.getsignal(signal.SIGINT) is not signal.default_int_handler:
        yield
        return
    previous_hook = sys.unraisablehook

    def quiet(unraisable):
        if not (_received and isinstance(unraisable.exc_value, KeyboardInterrupt)):
            previous_hook(unraisable)

    _received = False
    previous_handler = signal.signal(signal.SIGINT, _record)
    sys.unraisablehook = quiet
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous_handler)
        sys.unraisablehook = previous_hook
        _received = False
