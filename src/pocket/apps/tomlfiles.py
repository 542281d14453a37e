"""TOML files as case files are read: bounded in size, UTF-8, well formed, or a one-line ``InputError``.

A UTF-8 byte-order mark at the start (some Windows editors write one) is dropped: TOML forbids it, but it
says nothing a reader needs.
"""

from __future__ import annotations

import pathlib
import tomllib

from pocket.core.errors import InputError

__all__ = ["MAX_BYTES", "read_toml"]

#: largest case file read: a bound on the work a case can ask for
MAX_BYTES = 1_000_000


def read_toml(path) -> dict:
    """The TOML file ``path`` as a dict; a missing, huge, non-UTF-8 or malformed file is an InputError."""
    path = pathlib.Path(path)
    try:
        size = path.stat().st_size
        if path.is_dir():
            raise InputError(f"{path}: is a directory, not a case file")
        if size > MAX_BYTES:
            raise InputError(f"{path}: {size} bytes, but a case file has at most {MAX_BYTES}")
        raw = path.read_bytes()
    except OSError as err:
        raise InputError(f"{path}: cannot read the file ({err.strerror})") from None
    try:
        text = raw.decode("utf-8").removeprefix("\ufeff")
    except UnicodeDecodeError as err:
        raise InputError(f"{path}: not a UTF-8 text file (byte {err.start}), so not a TOML case file") from None
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as err:
        raise InputError(f"{path}: not valid TOML ({err})") from None
    except RecursionError:
        raise InputError(f"{path}: values nested too deeply to be a case file") from None
