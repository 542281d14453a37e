"""Errors every solver raises, so that the command line can map them to exit codes.

``InputError``: the input is invalid (alpha <= -1, Phat <= 0, a negative force,
a bad mesh file). ``OutOfRangeError``: the input is valid but outside what the
model describes (no inflated state on the first branch, the free part reaching
the clamp plane). Both exit with status 2 on the command line.
``ConvergenceError``: the numerics failed; it says where (load level), after
how many iterations and with what residual. ``OutputError``: a result could
not be written (a read-only folder, a full disk); nothing half-written is left.
``ClusterError``: the workers of a cluster cannot run the work (none, without
pocket, the scheduler lost). These exit with status 1.
"""

from __future__ import annotations

__all__ = ["PocketError", "InputError", "OutOfRangeError", "ConvergenceError", "OutputError", "ClusterError",
           "exit_status", "beyond_range", "CLAMP_PLANE"]

#: what happens at the end of the compression range (unless the force has a maximum first)
CLAMP_PLANE = "the free part of the sheet reaches the clamp plane"


class PocketError(Exception):
    """Base class of the errors below; the message is one line."""


class InputError(PocketError, ValueError):
    """Invalid input, detected before any work."""


class OutOfRangeError(PocketError, ValueError):
    """Valid input for which the model has no (first-branch) solution."""


class ConvergenceError(PocketError, RuntimeError):
    """A nonlinear solve failed after step cutting.

    Attributes: ``load`` (the load level reached), ``iterations``, ``residual``.
    """

    def __init__(self, message: str, *, load=float("nan"), iterations=0, residual=float("nan")):
        super().__init__(message)
        self.load = load
        self.iterations = iterations
        self.residual = residual


class OutputError(PocketError, OSError):
    """A result could not be written; the partial output has been removed."""


class ClusterError(PocketError, RuntimeError):
    """A cluster's workers cannot run the work: none, without pocket, or the scheduler lost."""


def exit_status(err: PocketError) -> int:
    """The command line's exit status for ``err``: 1 for a solver failure, an output that could not
    be written or a cluster that cannot run the work, 2 for bad input or a state outside the model."""
    return 1 if isinstance(err, (ConvergenceError, OutputError, ClusterError)) else 2


def beyond_range(asked: str, end: str, reason: str = CLAMP_PLANE) -> OutOfRangeError:
    """The one wording, for every solver and unit, of a load past the end of the model's compression range:
    ``"<asked> is beyond the model's range, which ends at <end>: there <reason>"`` (``asked`` and ``end``
    as ``"force = 10.1"``, ``"loads.forces[0] = '61 N'"``, ``"60.1 N (Fhat = 9.94)"``)."""
    return OutOfRangeError(f"{asked} is beyond the model's range, which ends at {end}: there {reason}")
