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

__all__ = [
    "CLAMP_PLANE",
    "STRETCH_LIMIT",
    "UNINFLATED_CAPSULE",
    "ClusterError",
    "ConvergenceError",
    "InputError",
    "OutOfRangeError",
    "OutputError",
    "PocketError",
    "above_pressure_maximum",
    "beyond_range",
    "capsule_gap",
    "exit_status",
    "past_stretch_limit",
]

#: what happens at the end of the compression range (unless the force has a maximum first)
CLAMP_PLANE = "the free part of the sheet reaches the clamp plane"
#: the end of a capsule's range (``pocket.shooting.capsule``), as every solver and application words it
CAPSULE_EDGE = ("the meridional tension at the contact edge vanishes (the patch under the plate is slack up to its "
                "edge): the free membrane would leave the plate with unbounded curvature, outside membrane theory")

#: why an uninflated capsule (P_I = 0) is pressed by the plates' height or a force in units of E T R only: its
#: Fhat = F / (P_I pi R^2) is undefined.
#: Its states start deep: from the touch the patch under a plate is compressed (its meridional stretch falls towards
#: the edge by a strain of order the compression, which only an inflation's tension keeps taut) and the contact edge's
#: meridional tension vanishes at once; only at a compression of about 21 % (neo-Hookean, a liquid) does the free
#: membrane's tension, growing like the compression squared, hold the edge again (``capsule_gap``)
UNINFLATED_CAPSULE = ("an uninflated capsule (P_I = 0) has no Fhat = F / (P_I pi R^2): it is pressed by the plates' "
                      "height (compress_height; pocket compress --height) or by a force F / (E T R) (force_unit = "
                      "'ETR'; --force-etr), its states starting at the compression where its contact edge's "
                      "meridional tension first holds")

#: the largest pole stretch lambda_0 at which the membrane solvers (shooting, FE) seek an inflated state. A rubber
#: whose pressure maximum has just vanished (Mooney-Rivlin alpha just above 0.05544) reaches Phat = 2 only at
#: lambda_0 ~ 28, V/R^3 ~ 1e4: those are states of the model and are solved. But a first branch may climb towards
#: a pressure it never reaches, and a search must end somewhere that says why: at lambda_0 = 100 the pole has
#: thinned 1e4-fold and the sheet at the clamp is stretched some 2000-fold, far past the break of any rubber
#: (stretches of 5 to 10), where no strain-energy law fitted to one means anything. The two solvers agree there
#: still (the FE on its default mesh to 1e-4 in V).
STRETCH_LIMIT = 100.0


class PocketError(Exception):
    """The base class of pocket's errors; the message is one line.

    The command line prints it on stderr and exits with ``exit_status``: 2 for bad input or a state outside the
    model, 1 for a solver failure, an output that could not be written or a cluster that cannot run the work.

    Examples
    --------
    >>> from pocket import shooting
    >>> from pocket.core.errors import PocketError, exit_status
    >>> try:
    ...     shooting.compress(-2.0, 0.31, 0.19)
    ... except PocketError as err:
    ...     print(type(err).__name__, exit_status(err))
    InputError 2
    """


class InputError(PocketError, ValueError):
    """Invalid input, detected before any work (alpha <= -1, Phat <= 0, a negative force, a bad mesh file).

    Also a ``ValueError``. Exit status 2.

    Examples
    --------
    >>> from pocket import shooting
    >>> shooting.inflate(47 / 160, -0.31)
    Traceback (most recent call last):
        ...
    pocket.core.errors.InputError: pressure = -0.31, but it must be > 0
    """


class OutOfRangeError(PocketError, ValueError):
    """Valid input for which the model has no (first-branch) solution.

    No inflated state above the first branch's pressure maximum, a force past the end of the compression range
    (the free sheet reaching the clamp plane), a height above the pocket. Also a ``ValueError``. Exit status 2.

    Examples
    --------
    >>> from pocket import shooting
    >>> shooting.compress(47 / 160, 0.31, 20.0)
    Traceback (most recent call last):
        ...
    pocket.core.errors.OutOfRangeError: force = 20.0 is beyond the model's range, which ends at ...
    """

    #: the end of the range the refusal quotes, where a load stepping found it (``pocket.fem.continuation``):
    #: for a caller that words the refusal again
    end: str | None = None
    #: that end as a number, in the unit of the load asked (``pocket.shooting.descent``: a height H/R)
    bound: float | None = None


class ConvergenceError(PocketError, RuntimeError):
    """A nonlinear solve failed after step cutting: the numerics, not the input. Exit status 1.

    Also a ``RuntimeError``.

    Parameters
    ----------
    message : str
        One line: where (load level), after how many iterations, with what residual, and why.
    load : float, optional
        The load level reached.
    iterations : int, optional
        The iterations made.
    residual : float, optional
        The last residual.

    Examples
    --------
    >>> from pocket.core.errors import ConvergenceError, exit_status
    >>> err = ConvergenceError("Newton failed at Fhat = 0.5", load=0.5, iterations=40, residual=1e-3)
    >>> print(err.load, err.iterations, exit_status(err))
    0.5 40 1
    """

    def __init__(self, message: str, *, load=float("nan"), iterations=0, residual=float("nan")):
        super().__init__(message)
        self.load = load
        self.iterations = iterations
        self.residual = residual


class OutputError(PocketError, OSError):
    """A result could not be written (a read-only folder, a full disk); the partial output has been removed.

    Also an ``OSError``. Exit status 1.

    Examples
    --------
    >>> from pocket.core.errors import OutputError, exit_status
    >>> print(exit_status(OutputError("cannot write out/: read-only")))
    1
    """


class ClusterError(PocketError, RuntimeError):
    """A cluster's workers cannot run the work: none, without pocket, or the scheduler lost. Exit status 1.

    Also a ``RuntimeError``.

    Examples
    --------
    >>> from pocket.core.errors import ClusterError, exit_status
    >>> print(exit_status(ClusterError("no worker joined the cluster")))
    1
    """


def above_pressure_maximum(pressure: float, maximum: float, volume: float, where: str) -> OutOfRangeError:
    """The error of an inflation by pressure asked above the first branch's pressure maximum: it quotes
    the maximum Phat and the volume V / R^3 there (``where``: more about the maximum, e.g. the pole
    stretch) and points to volume control, which passes the maximum."""
    return OutOfRangeError(f"no inflated state on the first branch: Phat = {pressure:.6g} is above its pressure "
                           f"maximum Phat = {maximum:.6g}, reached at V/R^3 = {volume:.6g} ({where}); volume "
                           "control passes the maximum (inflate_volume; pocket inflate --volume V)")


def past_stretch_limit(asked: str) -> OutOfRangeError:
    """The one wording, for every solver, of an inflation target (``asked``, e.g. ``"Phat = 7.5"``) that the
    first branch does not reach by the pole stretch ``STRETCH_LIMIT``."""
    return OutOfRangeError(f"no inflated state: {asked} is not reached on the first branch up to the pole stretch "
                           f"lambda_0 = {STRETCH_LIMIT:g}, where the solvers stop (the sheet thinned 1e4-fold at the "
                           "pole, far past any rubber's break)")


def exit_status(err: PocketError) -> int:
    """The command line's exit status for a pocket error.

    Parameters
    ----------
    err : PocketError
        The error.

    Returns
    -------
    int
        1 for a solver failure, an output that could not be written or a cluster that cannot run the work
        (``ConvergenceError``, ``OutputError``, ``ClusterError``); 2 for bad input or a state outside the model
        (``InputError``, ``OutOfRangeError``).

    Examples
    --------
    >>> from pocket.core.errors import ConvergenceError, InputError, OutOfRangeError, exit_status
    >>> print([exit_status(e("...")) for e in (InputError, OutOfRangeError, ConvergenceError)])
    [2, 2, 1]
    """
    return 1 if isinstance(err, (ConvergenceError, OutputError, ClusterError)) else 2


def above_the_pocket(height: float, top: float) -> OutOfRangeError:
    """The one wording, for every solver, of an indenter height H/R = ``height`` above the inflated pocket's
    top H0/R = ``top``: there is no compressed state there."""
    return OutOfRangeError(f"height = {height!r} is above the inflated pocket (H0/R = {top:.10g}): the indenter "
                           "would not touch it")


def capsule_gap(asked: str, start: str, end: str | None = None) -> OutOfRangeError:
    """The one wording, for every solver, of a capsule's load where the membrane has no state: above the start
    ``start`` of the branch of states reached deep (the plates' height or force there, as ``"height = 0.785"``) and,
    for P_I > 0, past the ``end`` of the branch pressed from the touch; between them ``CAPSULE_EDGE``."""
    if end is None:
        return OutOfRangeError(f"{asked} is outside the capsule's range, whose states start deeper, at {start}: "
                               f"before it {CAPSULE_EDGE}")
    return OutOfRangeError(f"{asked} lies between the capsule's two branches of states: the one pressed from the "
                           f"touch ends at {end}, the one reached deeper starts at {start}; between them "
                           f"{CAPSULE_EDGE}")


def beyond_range(asked: str, end: str, reason: str = CLAMP_PLANE) -> OutOfRangeError:
    """The one wording, for every solver and unit, of a load past the end of the model's compression range:
    ``"<asked> is beyond the model's range, which ends at <end>: there <reason>"`` (``asked`` and ``end``
    as ``"force = 10.1"``, ``"loads.forces[0] = '61 N'"``, ``"60.1 N (Fhat = 9.94)"``)."""
    return OutOfRangeError(f"{asked} is beyond the model's range, which ends at {end}: there {reason}")
