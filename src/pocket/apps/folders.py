"""Output files and folders that appear whole or not at all.

A result (a file, a VTK series, a report folder) is written into a hidden sibling
``.NAME[.XXXXXXXXXXXX].partial`` and renamed onto its target only once complete,
so an error or an interrupt never leaves a half-written result looking finished.
"""

from __future__ import annotations

import contextlib
import os
import pathlib
import secrets
import shutil
from collections.abc import Iterator

__all__ = ["staged", "write_whole"]


@contextlib.contextmanager
def staged(target: pathlib.Path) -> Iterator[pathlib.Path]:
    """Yield an empty sibling folder of ``target`` to fill; on leaving it replaces ``target``.

    ``target`` must be an absolute path (``.`` has no name for a sibling). A
    previous ``target`` is removed only after the new one is in place; on any
    exception the sibling is deleted and ``target`` is left as it was.
    """
    target.parent.mkdir(parents=True, exist_ok=True)
    partial = target.with_name(f".{target.name}.{secrets.token_hex(6)}.partial")
    partial.mkdir()  # not mkdtemp: its mode 0700 would stay with the result
    try:
        yield partial
        _replace(partial, target)
    except BaseException:
        shutil.rmtree(partial, ignore_errors=True)
        raise


def write_whole(path: pathlib.Path, text: str) -> None:
    """Write ``text`` to the file ``path`` through a hidden sibling renamed onto it."""
    partial = path.with_name(f".{path.name}.partial")
    partial.write_text(text, newline="")
    os.replace(partial, path)


def _replace(source: pathlib.Path, target: pathlib.Path) -> None:
    """Rename ``source`` to ``target``; an existing ``target`` is removed only after."""
    if not target.exists():
        os.rename(source, target)
        return
    trash = target.with_name(f".{target.name}.{secrets.token_hex(6)}.old")
    os.rename(target, trash)
    os.rename(source, target)
    shutil.rmtree(trash, ignore_errors=True)
