"""Output files and folders: checked before any work, then written whole or not at all.

Before solving, ``check_output_file`` and ``check_output_dir`` make sure a
result can go where the user asked: not onto a folder (for a file) or a file
(for a folder), not below a file, not into a folder that cannot be written.
Each failure is a one-line ``InputError`` (exit status 2) raised before any
work.

What pocket did not write it never deletes or overwrites, and what it wrote it
replaces only while it is unchanged. Every folder it writes whole (a VTK series,
a validation or convergence report, a fit's plots) holds a marker file,
``.pocket-output.json``, naming its kind, what it is of (the case of ``pocket run
--vtk``), pocket's version, every entry written and the SHA-256 of each file.
``check_replaceable`` lets a result replace an existing folder only if that
marker names the same kind and case, the folder holds nothing else and every
file still has its checksum; anything else is refused, naming what was found.
The current folder, pocket's own install and every folder above them are never
replaced. A file is replaced only if it is not there yet or the ledger of its
folder records that pocket wrote it, unchanged, for the same case
(``pocket.apps.ledger``: ``write_files`` records every file it writes); a sweep
file, which a rerun resumes, is read and kept row by row instead
(``pocket.apps.sweep.journal``).

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
import json
import os
import pathlib
import secrets
import shutil
from collections.abc import Iterator

from pocket.core.errors import InputError, OutputError

from .ledger import LEDGER, changed, check_ledger, check_recorded, digest, updated
from .provenance import version

__all__ = [
    "MARKER",
    "check_output_dir",
    "check_output_file",
    "check_replaceable",
    "created_parents",
    "remove_created",
    "staged",
    "write_files",
    "write_whole",
]

#: the file pocket writes into every folder it writes whole: {"written by", "kind", "of", "version", "entries",
#: "sha256": {file: checksum}}
MARKER = ".pocket-output.json"


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


def check_output_file(path, what: str = "output", *, of: str | None = None, resumed: bool = False) -> pathlib.Path:
    """The absolute path of a file that may be created or replaced; InputError (before any work) if not.

    An existing link is followed: the path returned is its target's, which is written (the
    link stays). Only a regular file is replaced: not a device, a pipe or ``/dev/stdout``;
    and only one that pocket wrote for ``of`` (the case the output is computed for) and no one
    changed since (``pocket.apps.ledger.check_recorded``), unless ``resumed``: the caller reads
    the existing file and keeps all it holds (a sweep file).
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
    if not resumed:  # a resumed file is not recorded (``write_files``' ``record``)
        check_ledger(target.parent, what, path)
        if target.exists():
            check_recorded(target, of, what, path)
    return target


def check_output_dir(path, what: str = "output") -> pathlib.Path:
    """The absolute path of a folder that may be created or filled; InputError (before any work) if not."""
    target = pathlib.Path(path).absolute()
    if target.exists() and not target.is_dir():
        raise InputError(f"{what} {path}: is a file, not a folder")
    if target.is_dir() and not os.access(target, os.W_OK | os.X_OK):
        raise InputError(f"{what} {path}: the folder is not writable")
    _writable_parent(target, what, path)
    return target


def _protected() -> set[pathlib.Path]:
    """The current folder, the folder of pocket's own package and every folder above either."""
    here, install = pathlib.Path.cwd().resolve(), pathlib.Path(__file__).resolve().parents[1]
    return {here, *here.parents, install, *install.parents}


def _entries(folder: pathlib.Path) -> set[str]:
    """Every file and folder below ``folder``, as paths relative to it (``/`` separated)."""
    return {entry.relative_to(folder).as_posix() for entry in folder.rglob("*")}


def _marker(folder: pathlib.Path) -> dict | None:
    """The marker of ``folder`` if pocket wrote one there (a dict with a kind and a list of entries)."""
    try:
        data = json.loads((folder / MARKER).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if isinstance(data, dict) and data.get("written by") == "pocket" and isinstance(data.get("entries"), list):
        return data
    return None


def _listed(names: set[str]) -> str:
    """Up to three of ``names``, sorted, and how many more."""
    shown = sorted(names)[:3]
    return ", ".join(shown) + (f" and {len(names) - len(shown)} more" if len(names) > len(shown) else "")


def check_replaceable(path, kind: str, what: str = "output", *, overwrite: bool = True,
                      of: str | None = None) -> pathlib.Path:
    """The absolute, resolved path of a folder that a result of ``kind`` (``"VTK series"``,
    ``"validation report"``, ...) for ``of`` (a case, or None) may be written to whole (``staged``);
    InputError (before any work) if not.

    A new or empty folder may be written; an existing one only if pocket wrote it as a ``kind``
    for ``of`` (its ``MARKER`` says so), it holds nothing the marker does not list, every file has
    the checksum the marker records, and ``overwrite``. Never the current folder, pocket's install
    or a folder above them.
    """
    target = check_output_dir(path, what).resolve()
    if target in _protected():
        raise InputError(f"{what} {path}: is the current folder, pocket's install or a folder above them, "
                         "which pocket never replaces; choose a new folder")
    if not target.is_dir() or not any(target.iterdir()):
        return target
    marker = _marker(target)
    if marker is None:
        raise InputError(f"{what} {path}: holds {_listed({p.name for p in target.iterdir()})}, which pocket did "
                         f"not write (it replaces only a {kind} of its own); choose another folder")
    if marker.get("kind") != kind:
        raise InputError(f"{what} {path}: holds a pocket {marker.get('kind')}, not a {kind}; choose another folder")
    others = _entries(target) - set(marker["entries"]) - {MARKER}
    if others:
        raise InputError(f"{what} {path}: holds {_listed(others)}, which pocket did not write, besides its {kind}; "
                         "choose another folder")
    if not isinstance(marker.get("sha256"), dict):
        raise InputError(f"{what} {path}: holds a {kind} of an earlier pocket, which kept no checksums to show it "
                         "is unchanged; remove it yourself or choose another folder")
    edited = changed(target, marker["sha256"])
    if edited:
        raise InputError(f"{what} {path}: {_listed(edited)} changed after pocket wrote its {kind}; pocket keeps it: "
                         "choose another folder")
    if marker.get("of") != of:
        raise InputError(f"{what} {path}: holds pocket's {kind} for {marker.get('of') or 'the command line'}, not "
                         f"for {of or 'the command line'}; choose another folder")
    if not overwrite:
        raise InputError(f"{what} {path}: holds a previous {kind} (--overwrite replaces it)")
    return target


def _partial(target: pathlib.Path) -> pathlib.Path:
    return target.with_name(f".{target.name}.{secrets.token_hex(6)}.partial")


@contextlib.contextmanager
def staged(target: pathlib.Path, kind: str, of: str | None = None) -> Iterator[pathlib.Path]:
    """Yield an empty sibling folder of ``target`` to fill; on leaving it replaces ``target``.

    ``target`` must be an absolute path (``.`` has no name for a sibling), checked by
    ``check_replaceable`` for the same ``kind`` and ``of``. Once filled the folder gets its ``MARKER``
    (``kind``, ``of``, pocket's version, the entries written and each file's SHA-256). A previous
    ``target`` is removed only
    after the new one is in place; on any exception the sibling and the folders made for it
    are deleted and ``target`` is left as it was.
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
        entries = sorted(_entries(partial))
        sha256 = {name: digest((partial / name).read_bytes()) for name in entries if (partial / name).is_file()}
        marker = {"written by": "pocket", "kind": kind, "of": of, "version": version(), "entries": entries,
                  "sha256": sha256}
        (partial / MARKER).write_text(json.dumps(marker, indent=1) + "\n", encoding="utf-8")
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


def write_files(texts: dict, *, of: str | None = None, record: bool = True) -> None:
    """Write each ``{path: text}`` whole, all or none (each through a hidden sibling renamed onto it), and,
    if ``record``, record them as pocket's output for ``of`` (the case they are computed for, or None) in
    the ledger of their folder (``pocket.apps.ledger``), renamed into place last. Only a file whose
    reader keeps all it holds (a sweep file) goes unrecorded.

    Every text is written to its sibling before any is renamed, so an error while
    writing (``OutputError``: a full disk, a folder made read-only) or an interrupt
    leaves none of the files, no sibling and no folder it created. Only the renames
    at the end, which need no space, come one after the other.
    """
    texts = {pathlib.Path(path).absolute(): text for path, text in texts.items()}
    folders: dict[pathlib.Path, dict[str, str]] = {path.parent: {} for path in texts}
    for path, text in texts.items():
        folders[path.parent][path.name] = text
    if record:
        texts.update({folder / LEDGER: updated(folder, names, of) for folder, names in folders.items()})
    paths = list(texts)
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


def write_whole(path, text: str, *, of: str | None = None, record: bool = True) -> None:
    """Write ``text`` to the file ``path`` whole or not at all, recorded as of ``of`` if ``record``
    (``write_files``)."""
    write_files({path: text}, of=of, record=record)


def _replace(source: pathlib.Path, target: pathlib.Path) -> None:
    """Rename ``source`` to ``target``; an existing ``target`` is removed only after."""
    if not target.exists():
        os.rename(source, target)
        return
    trash = target.with_name(f".{target.name}.{secrets.token_hex(6)}.old")
    os.rename(target, trash)
    os.rename(source, target)
    shutil.rmtree(trash, ignore_errors=True)
