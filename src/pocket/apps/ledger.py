"""What pocket wrote, by checksum: an output is replaced only while it holds what pocket wrote there.

Every file pocket writes outside a folder of its own (a run's JSON and CSV results, a calibration
table, a finished sweep file) is recorded in the ledger of the folder that holds it, the hidden
file ``.pocket-files.json``: the file's name, the SHA-256 of the bytes written and what it is
``of``: the case it was computed for (``"case file /abs/path/sensor.toml"``, ``"built-in
sample 1"``), or nothing. ``check_recorded`` lets a writer replace an existing file only if its
folder's ledger records it, its bytes still have the recorded checksum (no row appended, no cell
edited) and it is of the same case; otherwise it is an ``InputError`` (exit status 2) naming the
file, raised before any work. A folder pocket writes whole keeps the checksums of its files in
its own marker (``pocket.apps.folders``), checked by ``changed``.

``updated`` gives a folder's ledger with new entries added, for ``pocket.apps.folders.write_files`` to
write with the files themselves. Two writers of one folder at the same moment may each record
only their own files; a file a ledger then misses is refused by the next writer, never lost.
"""

from __future__ import annotations

import hashlib
import json
import pathlib

from pocket.core.errors import InputError

from .provenance import version

__all__ = ["LEDGER", "changed", "check_ledger", "check_recorded", "digest", "updated"]

#: the ledger of a folder holding files pocket wrote: {"written by", "version", "files": {name: {"sha256", "of"}}}
LEDGER = ".pocket-files.json"


def digest(data: bytes) -> str:
    """The SHA-256 of ``data``, as hexadecimal."""
    return hashlib.sha256(data).hexdigest()


def _digest_file(path: pathlib.Path) -> str | None:
    """The SHA-256 of the file ``path``; None if it cannot be read."""
    try:
        return digest(path.read_bytes())
    except OSError:
        return None


def _read(folder: pathlib.Path) -> dict | None:
    """The files the ledger of ``folder`` records, {name: {"sha256": ..., "of": ...}}; None if it has
    no ledger pocket wrote."""
    try:
        data = json.loads((folder / LEDGER).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    files = data.get("files") if isinstance(data, dict) and data.get("written by") == "pocket" else None
    if not isinstance(files, dict):
        return None
    return {name: entry for name, entry in files.items() if isinstance(entry, dict)}


def _files(folder: pathlib.Path) -> dict:
    """The files the ledger of ``folder`` records (``_read``), none if it has no ledger."""
    return _read(folder) or {}


def check_ledger(folder: pathlib.Path, what: str, path) -> None:
    """Nothing if pocket may write the ledger of ``folder`` (for the output ``path`` of option ``what``): there
    is none yet, or pocket wrote it; else an ``InputError``, so that a user's file of that name is kept."""
    ledger = folder / LEDGER
    if (ledger.exists() or ledger.is_symlink()) and _read(folder) is None:
        raise InputError(f"{what} {path}: {ledger} is not a record pocket wrote, and pocket would replace it; "
                         "choose another folder")


def check_recorded(target: pathlib.Path, of: str | None, what: str, path) -> None:
    """Nothing if the existing file ``target`` (an absolute path; ``path`` as the user wrote it) may be
    replaced by pocket's output of ``of`` (module docstring); else the ``InputError`` saying why not."""
    entry = _files(target.parent).get(target.name)
    if entry is None:
        raise InputError(f"{what} {path}: the file exists and pocket did not write it (its folder's {LEDGER} "
                         "has no record of it); choose another name")
    if _digest_file(target) != entry.get("sha256"):
        raise InputError(f"{what} {path}: the file was changed after pocket wrote it (a row or a line added or "
                         "edited); pocket keeps it: save it under another name, or choose another name")
    if entry.get("of") != of:
        raise InputError(f"{what} {path}: holds pocket's output for {entry.get('of') or 'another command'}, not for "
                         f"{of}; choose another name or folder")


def updated(folder: pathlib.Path, texts: dict, of: str | None) -> str:
    """The ledger of ``folder`` as JSON text with ``texts`` ({name: text written}) recorded as of ``of``;
    entries whose file is gone are dropped."""
    files = {name: entry for name, entry in _files(folder).items() if (folder / name).is_file()}
    files.update({name: {"sha256": digest(text.encode("utf-8")), "of": of} for name, text in texts.items()})
    data = {"written by": "pocket", "version": version(), "files": dict(sorted(files.items()))}
    return json.dumps(data, indent=1) + "\n"


def changed(folder: pathlib.Path, sha256: dict) -> set[str]:
    """The files of ``sha256`` ({entry: checksum}, a folder marker's) below ``folder`` whose bytes differ."""
    return {name for name, value in sha256.items() if _digest_file(folder / name) != value}
