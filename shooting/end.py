"""The end of a pocket's compression range, as every contact problem finds it, and the cache of those found.

Each formulation finds its own (``Contact.end``): the plate's by continuation in the clamp angle
(``pocket.shooting.plateend``), a curved indenter's by continuation in the force while every end of the model
stays ahead (``pocket.shooting.surfaceend``). Either is computed once per pocket and indenter (``end_of``).
"""

from __future__ import annotations

import dataclasses

from pocket.core.errors import CLAMP_PLANE

__all__ = ["End", "end_of"]


@dataclasses.dataclass(frozen=True)
class End:
    """The end of one pocket's range: ``force`` (Fhat_end), the clamp angle there (pi, or less at a
    ``fold``) and the branch up to it, ``path``: (theta, z = (q, e, Fhat)) with theta increasing.
    A rubber that ``locks`` first has no end: ``force`` is inf, ``angle`` the last clamp angle solved.
    ``reason``: what happens there (the plate's: the clamp plane; a curved indenter's,
    ``pocket.shooting.surfaceend``)."""

    force: float
    angle: float
    fold: bool
    path: tuple
    locks: bool = False
    reason: str = CLAMP_PLANE


_ENDS: dict[tuple, End] = {}  # Contact.key (rubber, Phat_I, rtol, fluid, indenter) -> End


def end_of(problem, seed=None) -> End:
    """The ``End`` of ``problem`` (a ``pocket.shooting.contact.Contact``; cached); ``seed``: an optional solved
    (force, x) on its branch."""
    key = problem.key
    if key not in _ENDS:
        _ENDS[key] = problem.end(seed)
    return _ENDS[key]


def cached(key) -> End | None:
    """The ``End`` found for the problem whose ``Contact.key`` is ``key``, or None if none was."""
    return _ENDS.get(key)
