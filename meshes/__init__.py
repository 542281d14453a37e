"""1-D meshes of the Lagrangian radius r in [0, 1], as sorted node arrays.

A mesh is just its nodes: a strictly increasing float array from exactly 0.0
to exactly 1.0 (elements join consecutive nodes).

- ``uniform(n)``, ``graded(n, towards=, ratio=)``, ``refined(n, at=, width=,
  factor=)``, ``polar(n, power=)`` make meshes (``meshes/generate.py`` documents each);
- ``read(path)`` / ``write(path, nodes)`` move them through any meshio format,
  with checks that a file really holds a 1-D mesh of [0, 1];
- ``named(name)`` loads one of ``NAMES``, meshes stored in this folder.
"""

from pocket.core.importname import require_import_name

require_import_name(__name__, "pocket.meshes")  # before the modules below load under a wrong name

from .files import check, read, write  # noqa: E402
from .generate import graded, polar, refined, uniform  # noqa: E402
from .named import NAMES, named  # noqa: E402

__all__ = ["NAMES", "check", "graded", "named", "polar", "read", "refined", "uniform", "write"]
