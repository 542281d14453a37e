"""One copy of each solver: the top-level folders answer only to their installed names.

The repository keeps the solvers, the meshes and the validation suite in top-level
folders (``shooting/``, ``fem/``, ``analytical/``, ``meshes/``, ``validation/``) that are
installed as subpackages of pocket (``pocket.shooting``, ...). From the repository's root
the current folder is on ``sys.path``, so ``import shooting`` would otherwise load a second
copy of the solver, with its own compiled kernels and its own classes, beside
``pocket.shooting``. Each of those folders' ``__init__`` calls ``require_import_name`` first.
"""

__all__ = ["require_import_name"]


def require_import_name(name: str, installed: str) -> None:
    """Raise ``ImportError`` (one line naming ``installed``) unless the package's ``__name__``,
    ``name``, is the name it is installed under, ``installed`` (e.g. ``"pocket.shooting"``)."""
    if name != installed:
        raise ImportError(f"import {installed}, not {name}: this folder is installed as {installed}, "
                          "and a second copy of it would run beside that one")
