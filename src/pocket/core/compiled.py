"""``compiled``: numba's ``njit`` with an on-disk cache kept outside the package, that can never stop a solver.

Both solvers compile their inner loops with numba (seconds), and cache the machine
code on disk, so that later processes load it in milliseconds. numba's own cache
(``njit(cache=True)``) writes beside the sources, in the package's ``__pycache__``,
and has four ways to hurt a program that is otherwise fine:

- files written into the installed package survive ``pip uninstall``; the folder
  they leave then shadows a later editable install as an empty namespace package
  (``pocket.shooting`` without its contents);
- its stamp is the source file of the cached function alone, not of the compiled
  functions it inlines: after an edit of ``fem/laws.py`` the cached element loop
  still runs the old law;
- where the package folder is not writable and no cache folder of the user is
  either, decorating a function raises "no locator available";
- an entry written for the same source under another module name (a module that
  moved), or a damaged one, raises while it is loaded, at the first call.

Here a function is compiled with ``njit`` and given a cache that lives, first
writable of:

1. ``$POCKET_CACHE_DIR``, if set;
2. the user's cache folder (``platformdirs.user_cache_dir``: ``~/.cache/pocket-mechanics``
   on Linux, ``$XDG_CACHE_HOME`` honoured);
3. a private folder under the temporary directory (``<tmp>/pocket-numba-<uid>``,
   created for this user only, mode 0700, and used only if this user owns it and no
   one else can write to it: the cache holds pickles);

each time in a subfolder named for pocket's version and for the folder of the
function's source (two installations of one version do not overwrite each other).
Where none is writable the function is simply not cached. Nothing is ever written
into the package.

An entry's stamp is a hash of the contents of every source file of the function's
package (``shooting/*.py`` or ``fem/*.py``): a kernel inlines only compiled functions
of its own package, so editing any of them, or installing another release, makes the
entry stale, and it is compiled afresh and overwritten. An entry that fails to load
is a cache miss; one that cannot be written leaves the function uncached. A cache
costs or saves compile time, never a result.

A Ctrl-C while numba compiles can land in a callback of the compiler whose
exceptions are ignored; every compilation (or load of an entry) checks, when it
returns, whether an interrupt was recorded meanwhile and raises it then
(``pocket.core.interrupts``).

Loading an entry initialises only numba's runtime, not its whole compiler (see
``_Cache.load_overload``): that halves the start-up of a command.

This uses numba's cache classes (``numba.core.caching``), as custom cache locators
do; ``tests/test_compiled_cache.py`` runs the failures in subprocesses. Those classes
are numba internals: should a numba release rename them, ``compiled`` falls back to
plain ``njit`` without an on-disk cache (every process then compiles, in seconds)
rather than failing to import.
"""

from __future__ import annotations

import contextlib
import functools
import hashlib
import importlib.metadata
import os
import stat
import tempfile

from numba import njit

from . import interrupts

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
    _DISK_CACHE = False
else:
    _DISK_CACHE = True

__all__ = ["CACHE_ENV", "cache_roots", "compiled", "private_cache_root"]

#: the environment variable naming the folder to cache compiled code in (tried first)
CACHE_ENV = "POCKET_CACHE_DIR"

_DISTRIBUTION = "pocket-mechanics"


@functools.cache
def _version() -> str:
    """pocket's installed version, or ``unknown`` when run from sources that were never installed."""
    try:
        return importlib.metadata.version(_DISTRIBUTION)
    except importlib.metadata.PackageNotFoundError:
        return "unknown"


def private_cache_root() -> str:
    """The last-resort cache folder: ``<tempdir>/pocket-numba-<uid>`` (private to this user)."""
    return os.path.join(tempfile.gettempdir(), f"pocket-numba-{os.getuid()}")


def cache_roots() -> list[tuple[str, bool]]:
    """The cache folders to try, first first, as (path, must be private to this user): the folder of
    ``$POCKET_CACHE_DIR`` if set, the user's cache folder, the private temporary folder."""
    import platformdirs  # imported here: only a process that compiles or loads needs it

    roots = []
    if os.environ.get(CACHE_ENV):
        roots.append((os.environ[CACHE_ENV], False))
    roots.append((platformdirs.user_cache_dir(_DISTRIBUTION, appauthor=False), False))
    roots.append((private_cache_root(), True))
    return roots


@functools.cache
def _package_stamp(folder: str) -> str:
    """sha256 of the names and contents of every ``.py`` file in ``folder``: what a cache entry depends on."""
    digest = hashlib.sha256()
    for name in sorted(os.listdir(folder)):
        if name.endswith(".py"):
            with open(os.path.join(folder, name), "rb") as handle:
                digest.update(name.encode() + b"\0" + handle.read() + b"\0")
    return digest.hexdigest()


def _check_private(root: str) -> None:
    """Raise PermissionError unless ``root`` is a real folder owned by this user that no one else can write."""
    info = os.lstat(root)
    if not stat.S_ISDIR(info.st_mode) or info.st_uid != os.getuid() or info.st_mode & 0o022:
        raise PermissionError(f"{root} is not a private folder of this user")


if _DISK_CACHE:

    class _Locator(_SourceFileBackedLocatorMixin, _CacheLocator):
        """The first usable folder of ``cache_roots``, in a subfolder for pocket's version and the source's folder."""

        def __init__(self, py_func, py_file, root, private):
            self._py_file = py_file
            self._lineno = py_func.__code__.co_firstlineno
            self._root, self._private = root, private
            self._cache_path = os.path.join(root, _version(), self.get_suitable_cache_subpath(py_file))

        def get_cache_path(self):
            return self._cache_path

        def ensure_cache_path(self):
            if self._private:
                os.makedirs(self._root, mode=0o700, exist_ok=True)
                _check_private(self._root)
            super().ensure_cache_path()

        @classmethod
        def from_function(cls, py_func, py_file):
            if not os.path.exists(py_file):
                return None
            for root, private in cache_roots():
                locator = cls(py_func, py_file, root, private)
                try:
                    locator.ensure_cache_path()
                except OSError:  # not writable, not a folder, or not private: try the next
                    continue
                return locator
            return None

    class _Impl(CompileResultCacheImpl):
        # a tuple: numba only iterates it, calling each locator's from_function(py_func, py_file), which
        # _Locator has; mypy reads numba's list as one of its own locators' constructors
        _locator_classes = (_Locator,)  # type: ignore[assignment]

    class _Cache(FunctionCache):
        """numba's function cache, where an entry that cannot be loaded or saved is a cache miss."""

        _impl_class = _Impl

        def __init__(self, py_func):
            super().__init__(py_func)
            own = self._cache_file._source_stamp  # the function's own file, as numba stamps it
            package = _package_stamp(os.path.dirname(os.path.abspath(self._impl.locator._py_file)))
            self._cache_file = IndexDataCacheFile(cache_path=self._cache_path, filename_base=self._impl.filename_base,
                                                  source_stamp=(own, package))

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
            with contextlib.suppress(OSError):  # a full disk or a folder that went read-only: stay uncached
                super().save_overload(sig, data)


def _checking_interrupts(dispatcher):
    """``dispatcher``, whose compilations (numba calls ``compile`` for each new signature, also for a
    function compiled inside another) raise an interrupt recorded while they ran, when they return."""
    compile_signature = dispatcher.compile

    @functools.wraps(compile_signature)
    def compile_then_check(sig):
        try:
            return compile_signature(sig)
        finally:
            interrupts.check()

    dispatcher.compile = compile_then_check
    return dispatcher


def compiled(function=None, **options):
    """``numba.njit(function, **options)``, cached on disk outside the package where possible (module
    docstring), with numpy's error model: a division by zero gives inf or nan (which the solvers reject
    as a failed step) rather than raising ZeroDivisionError from compiled code, and an interrupt never
    lost while it compiles (module docstring). Used as ``@compiled`` or
    ``@compiled(inline="always")``."""
    if function is None:
        return functools.partial(compiled, **options)
    dispatcher = _checking_interrupts(njit(function, error_model="numpy", **options))
    if not _DISK_CACHE:
        return dispatcher
    # no writable place at all, or a numba whose cache differs: compile in every process
    with contextlib.suppress(Exception):
        dispatcher._cache = _Cache(function)  # what njit(cache=True) does, with the cache above
    return dispatcher
