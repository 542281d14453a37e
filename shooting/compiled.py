"""``compiled``: numba's ``njit`` with an on-disk cache that can never stop the solver.

numba compiles the integrator in seconds and caches the machine code on disk, so
that later processes load it in milliseconds. Its own cache (``njit(cache=True)``)
has two ways to crash a program that is otherwise fine:

- in an installation whose package folder is not writable (system-wide, or a
  container run as another user) with no writable home either, decorating the
  function raises "cannot cache function ...: no locator available";
- a cache entry written for the same source under another module name (a module
  that moved: the entry's index still matches, the pickled data names the old
  module), or a damaged one, raises while it is loaded, at the first call.

Here a function is compiled with ``njit`` and given a cache that looks in numba's
usual places (``NUMBA_CACHE_DIR``, the package's ``__pycache__``, the user's cache
folder) and then in a private folder under the temporary directory (created for
this user only, mode 0700, and used only if this user owns it and no one else can
write to it: the cache holds pickles). If none is writable the function is simply
not cached. An entry that fails to load is treated as absent: the function is
compiled afresh and the entry overwritten. A cache that cannot be written costs
compile time, never a result.

Loading an entry initialises only numba's runtime, not its whole compiler (see
``_Cache.load_overload``): that halves the start-up of a command.

numba's own cache index checks only the source file of the cached function, not of the
compiled functions it calls (the integrator inlines ``equations.rhs`` and the tensions of
``tensions.py``). Here an entry's stamp is that of every source file of this package
(name, modification time, size), so editing any of them, or installing another release,
makes every entry stale: it is then compiled afresh.

This uses numba's cache classes (``numba.core.caching``), as custom cache locators
do; ``tests/test_shooting_cache.py`` runs the failures in subprocesses. Those
classes are numba internals: should a numba release rename them, ``compiled``
falls back to plain ``njit`` without an on-disk cache (every process then
compiles, in seconds) rather than failing to import.
"""

from __future__ import annotations

import os
import stat
import tempfile

from numba import njit

try:
    from numba.core.caching import (
        CompileResultCacheImpl,
        FunctionCache,
        IndexDataCacheFile,
        _CacheLocator,
        _SourceFileBackedLocatorMixin,
    )
    from numba.core.runtime import rtsys
except ImportError:  # a numba without these internals: no on-disk cache (module docstring)
    FunctionCache = None

__all__ = ["compiled", "private_cache_root"]


def _package_stamp() -> tuple:
    """(name, mtime, size) of every source file of this package: what a cache entry depends on."""
    folder = os.path.dirname(os.path.abspath(__file__))
    out = []
    for name in sorted(os.listdir(folder)):
        if name.endswith(".py"):
            info = os.stat(os.path.join(folder, name))
            out.append((name, info.st_mtime, info.st_size))
    return tuple(out)


def private_cache_root() -> str:
    """The fallback cache folder: ``<tempdir>/pocket-numba-<uid>``."""
    return os.path.join(tempfile.gettempdir(), f"pocket-numba-{os.getuid()}")


if FunctionCache is not None:

    class _PrivateTempLocator(_SourceFileBackedLocatorMixin, _CacheLocator):
        """The last place to cache: a folder under the temporary directory that only this user can write."""

        def __init__(self, py_func, py_file):
            self._py_file = py_file
            self._lineno = py_func.__code__.co_firstlineno
            self._cache_path = os.path.join(private_cache_root(), self.get_suitable_cache_subpath(py_file))

        def get_cache_path(self):
            return self._cache_path

        def ensure_cache_path(self):
            root = private_cache_root()
            os.makedirs(root, mode=0o700, exist_ok=True)
            info = os.lstat(root)
            if not stat.S_ISDIR(info.st_mode) or info.st_uid != os.getuid() or info.st_mode & 0o022:
                raise PermissionError(f"{root} is not a private folder of this user")
            super().ensure_cache_path()


    class _Impl(CompileResultCacheImpl):
        _locator_classes = [*CompileResultCacheImpl._locator_classes, _PrivateTempLocator]


    class _Cache(FunctionCache):
        """numba's function cache, where an entry that cannot be loaded or saved is a cache miss."""

        _impl_class = _Impl

        def __init__(self, py_func):
            super().__init__(py_func)
            own = self._cache_file._source_stamp  # the function's own file, as numba stamps it
            self._cache_file = IndexDataCacheFile(cache_path=self._cache_path, filename_base=self._impl.filename_base,
                                                  source_stamp=(own, _package_stamp()))

        def load_overload(self, sig, target_context):
            try:
                # numba refreshes its whole target context here (every typing and lowering registry,
                # and, for its BLAS check, scipy.linalg): 0.3 s of start-up that only compiling needs,
                # and compiling refreshes it itself. Loading machine code needs the runtime (NRT) that
                # the refresh would have initialised; the C helpers and math symbols are installed
                # when the context is created.
                rtsys.initialize(target_context)
                return self._load_overload(sig, target_context)
            except Exception:  # stale (a module that moved), foreign or damaged: compile afresh
                return None

        def save_overload(self, sig, data):
            try:
                super().save_overload(sig, data)
            except OSError:  # a full disk or a folder that went read-only: stay uncached
                pass


def compiled(function, **options):
    """``numba.njit(function)``, cached on disk where possible (module docstring), with numpy's error model:
    a division by zero gives inf or nan (which the integrator rejects as a failed step) rather than raising
    ZeroDivisionError from compiled code (a stage that lands exactly on Gent's locking limit)."""
    dispatcher = njit(function, error_model="numpy", **options)
    if FunctionCache is None:
        return dispatcher
    try:
        dispatcher._cache = _Cache(function)  # what njit(cache=True) does, with the cache above
    except Exception:  # no writable place at all, or a numba whose cache differs: compile in every process
        pass
    return dispatcher
