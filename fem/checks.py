"""Input checks, done before any work; each failure is a one-line ``InputError``."""

from __future__ import annotations

import math

import numpy as np

from pocket.errors import InputError

__all__ = ["MIN_ELEMENTS", "alpha", "positive", "non_negative", "order", "mesh"]

MIN_ELEMENTS = 4  # the pole stretch uses the first two vertices off the axis


def alpha(value) -> float:
    value = float(value)
    if not value > -1.0:
        raise InputError(f"alpha = {value!r}, but the Mooney-Rivlin model needs alpha > -1")
    return value


def positive(name: str, value) -> float:
    value = float(value)
    if not (value > 0.0 and math.isfinite(value)):
        raise InputError(f"{name} = {value!r}, but it must be positive and finite")
    return value


def non_negative(name: str, value) -> float:
    value = float(value)
    if not (value >= 0.0 and math.isfinite(value)):
        raise InputError(f"{name} = {value!r}, but it must be non-negative and finite")
    return value


def order(value) -> int:
    if value not in (1, 2):
        raise InputError(f"order = {value!r}, but the elements are P1 or P2 (order 1 or 2)")
    return int(value)


def mesh(nodes) -> np.ndarray:
    """A sorted 1-D float array spanning [0, 1] with at least MIN_ELEMENTS elements."""
    nodes = np.asarray(nodes, dtype=float)
    if nodes.ndim != 1:
        raise InputError(f"mesh has shape {nodes.shape}, but it must be a 1-D array of node radii")
    if nodes.size < MIN_ELEMENTS + 1:
        raise InputError(f"mesh has {nodes.size - 1} elements, but at least {MIN_ELEMENTS} are needed")
    if not np.all(np.isfinite(nodes)) or not np.all(np.diff(nodes) > 0):
        raise InputError("mesh nodes must be finite and strictly increasing")
    if abs(nodes[0]) > 1e-12 or abs(nodes[-1] - 1.0) > 1e-12:
        raise InputError(f"mesh spans [{nodes[0]!r}, {nodes[-1]!r}], but it must span [0, 1]")
    nodes = nodes.copy()
    nodes[0], nodes[-1] = 0.0, 1.0
    return nodes
