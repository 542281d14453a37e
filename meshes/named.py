"""Named meshes shipped as ``.vtu`` files beside this module.

``RECIPES`` says how each was made from ``meshes.generate``; the script
``pocket.meshes.make_named`` writes the files from it, and a test checks that
every file still equals its recipe. The names say what each is for:

- ``uniform-64``, ``uniform-256``: the default and a finer uniform mesh;
- ``graded-clamp-128``: 128 elements finest at the clamp r = 1 (ratio 10);
- ``contact-refined-128``: 128 uniform elements refined 8 times within 0.05
  of r = 0.5, the contact edge of a moderately pressed pocket.
"""

from __future__ import annotations

import pathlib

import numpy as np

from pocket.core.errors import InputError

from .files import read
from .generate import graded, refined, uniform

__all__ = ["NAMES", "RECIPES", "named", "path"]

RECIPES = {
    "uniform-64": lambda: uniform(64),
    "uniform-256": lambda: uniform(256),
    "graded-clamp-128": lambda: graded(128, towards=1.0, ratio=10.0),
    "contact-refined-128": lambda: refined(128, at=0.5, width=0.05, factor=8.0),
}
NAMES = tuple(RECIPES)


def path(name: str) -> pathlib.Path:
    """The ``.vtu`` file of the named mesh ``name``."""
    if name not in RECIPES:
        raise InputError(f"unknown mesh {name!r}; named meshes: {', '.join(NAMES)}")
    return pathlib.Path(__file__).with_name(f"{name}.vtu")


def named(name: str) -> np.ndarray:
    """Nodes of the named mesh ``name`` (one of ``NAMES``)."""
    return read(path(name))
