"""Output files and folders: checked before any work, then written whole or not at all.

Before solving, ``check_output_file`` and ``check_output_dir`` make sure a
result can go where the user asked: not onto a folder (for a file) or a file
(for a folder), not below a file, not into a folder that cannot be written.
Each failure is a one-line ``InputError`` (exit status 2) raised before any
work.

A result (a file, a VTK series, a report folder) is then written into a hidden
sibling ``.NAME.XXXXXXXXXXXX.partial`` (a random name, so that two writers of one
target never share a temporary) and renamed onto its target only once
complete, so an error or an interrupt never leaves a half-written result
looking finished. An operating-system error while writing (a full disk, a
folder made read-only meanwhile) removes the partial result and becomes an
``OutputError`` (exit status 1) naming the target.
"""

from __future__ import annotations

import contextlib
import os
import pathlib
import secrets
import shutil
from collections.abc import Iterator

from pocket.core.errors import InputError, OutputError

__all__ = ["check_output_file", "check_output_dir", "staged", "write_whole", "write_files", "created_parents",
           "remove_created"]


def _writable_parent(target: pathlib.Path, what: str, path) -> None:
    """The nearest existing ancestor of ``target`` (``path`` as the user wrote it) is a folder this
    process may create entries in."""
    for parent in target.parents:
        if parent.exists():
            if not parent.is_dir():
                raise InputError(f"{what} {path}: {parent} is a file, not a folder")
            if not os.access(parent, os.W_OK | os.X_OK):
                raise InputError(f"{what} {path}: the folder {parent} is not writable")
            return
        if parent.is_symlink():  # a dangling link in the way
            raise InputError(f"{what} {path}: {parent} is a broken link")


def check_output_file(path, what: str = "output") -> pathlib.Path:
    """The absolute path of a file that may be created or replaced; InputError (before any work) if not.

    An existing link is followed: the path returned is its target's, which is written (the
    link stays). Only a regular file is replaced: not a device, a pipe or ``/dev/stdout``.
    """
    target = pathlib.Path(path).absolute()
    if target.is_symlink():
        if not target.exists():
            raise InputError(f"{what} {path}: is a broken link")
        target = target.resolve()
    if target.is_dir():
        raise InputError(f"{what} {path}: is a folder, not a file")
    if target.exists() and not target.is_file():
        raise InputError(f"{what} {path}: is not a regular file (a device or a pipe), so it cannot be replaced")
    if target.exists() and not os.access(target, os.W_OK):
        raise InputError(f"{what} {path}: the file is not writable")
    _writable_parent(target, what, path)
    return target


def check_output_dir(path, what: str = "output", *, overwrite: bool = True) -> pathlib.Path:
    """The absolute path of a folder that may be created or filled; InputError (before any work) if not.

    Without ``overwrite`` an existing folder must be empty (a result would replace it whole).
    """
    target = pathlib.Path(path).absolute()
    if target.exists() and not target.is_dir():
        raise InputError(f"{what} {path}: is a file, not a folder")
    if target.is_dir() and not os.access(target, os.W_OK | os.X_OK):
        raise InputError(f"{what} {path}: the folder is not writable")
    if not overwrite and target.is_dir() and any(target.iterdir()):
        raise InputError(f"{what} {path}: the folder exists and is not empty (--overwrite replaces it)")
    _writable_parent(target, what, path)
    return target


def _partial(target: pathlib.Path) -> pathlib.Path:
    return target.with_name(f".{target.name}.{secrets.token_hex(6)}.partial")


@contextlib.contextmanager
def staged(target: pathlib.Path) -> Iterator[pathlib.Path]:
    """Yield an empty sibling folder of ``target`` to fill; on leaving it replaces ``target``.

    ``target`` must be an absolute path (``.`` has no name for a sibling). A
    previous ``target`` is removed only after the new one is in place; on any
    exception the sibling and the folders made for it are deleted and ``target``
    is left as it was.
    """
    partial, made = _partial(target), created_parents(target)
    try:
        for folder in made:
            folder.mkdir(exist_ok=True)
        partial.mkdir()  # not mkdtemp: its mode 0700 would stay with the result
    except OSError as err:
        remove_created(made)
        raise OutputError(f"cannot write {target}: {err.strerror or err}") from None
    try:
        yield partial
        _replace(partial, target)
    except BaseException as err:
        shutil.rmtree(partial, ignore_errors=True)
        remove_created(made)
        if isinstance(err, OSError):
            raise OutputError(f"cannot write {target}: {err.strerror or err}") from None
        raise


def created_parents(path: pathlib.Path) -> list[pathlib.Path]:
    """The missing folders above ``path``, outermost first: what writing ``path`` creates."""
    return [parent for parent in reversed(pathlib.Path(path).absolute().parents) if not parent.exists()]


def remove_created(folders: list[pathlib.Path]) -> None:
    """Remove ``folders`` (from ``created_parents``), innermost first, where they are still empty."""
    for folder in reversed(folders):
        with contextlib.suppress(OSError):
            folder.rmdir()


def write_files(texts: dict) -> None:
    """Write each ``{path: text}`` whole, all or none (each through a hidden sibling renamed onto it).

    Every text is written to its sibling before any is renamed, so an error while
    writing (``OutputError``: a full disk, a folder made read-only) or an interrupt
    leaves none of the files, no sibling and no folder it created. Only the renames
    at the end, which need no space, come one after the other.
    """
    paths = [pathlib.Path(path).absolute() for path in texts]
    made = list(dict.fromkeys(folder for path in paths for folder in created_parents(path)))
    partials = {path: _partial(path) for path in paths}
    target = paths[0]
    try:
        for folder in made:
            folder.mkdir(exist_ok=True)
        for (target, partial), text in zip(partials.items(), texts.values(), strict=True):
            partial.write_text(text, encoding="utf-8", newline="")
        for target, partial in partials.items():
            os.replace(partial, target)
    except BaseException as err:
        for partial in partials.values():
            partial.unlink(missing_ok=True)
        remove_created(made)
        if isinstance(err, OSError):
            raise OutputError(f"cannot write {target}: {err.strerror or err}") from None
        raise


def write_whole(path, text: str) -> None:
    """Write ``text`` to the file ``path`` whole or not at all (``write_files``)."""
    write_files({path: text})


def _replace(source: pathlib.Path, target: pathlib.Path) -> None:
    """Rename ``source`` to ``target``; an existing ``target`` is removed only after."""
    if not target.exists():
        os.rename(source, target)
        return
    trash = target.with_name(f".{target.name}.{secrets.token_hex(6)}.old")
    os.rename(target, trash)
    os.rename(source, target)
    shutil.rmtree(trash, ignore_errors=True)
