"""The compiled backend: the generated source under ``numba.njit(cache=True)``.

Generated modules are never imported from the cache directory. Each process writes the module text it
generated into a private staging directory of its own (``tempfile.mkdtemp``, mode 0700, removed at exit)
and executes that in-memory text under the module's real name (:func:`write_module`, :func:`import_module`),
so no ``.py`` or ``.pyc`` of the shared cache is ever run. Numba's on-disk cache (its ``.nbi`` index and
``.nbc`` code, both unpickled when loaded) is kept in the cache directory as one *sealed bundle* per module,
``<prefix>_<key>.numba`` (:func:`lagrange.codegen.cache.write_sealed`): before the module runs, a bundle that
passes authentication is unpacked into the staging directory, where numba finds it; after the module is
compiled, and again at exit, what numba wrote there (in this process, in a directory only this process
writes) is packed and sealed back. A bundle that fails authentication (planted, retagged, edited, damaged)
is ignored and numba recompiles. The module key (:func:`cache_key`) hashes the text and the lagrange,
numba, NumPy and Python versions, so a changed model or an upgrade gets a new entry. Numba is optional
(``pip install "lagrange-dynamics[fast]"``); a clear :class:`~lagrange.errors.BackendError` says so when it is
missing. The bundle costs nothing measurable against numba's own in-place cache: a warm compile and first
call of the three-link pendulum took 1.60 s of CPU (numba's import dominates) against 1.77 s before, a cold
one 3.8 s against 4.5 s (one loaded 2-core machine, three runs each).
"""

from __future__ import annotations

import atexit
import hashlib
import os
import platform
import shutil
import sys
import tempfile
import types
from collections.abc import Callable, Mapping
from pathlib import Path

from ..errors import BackendError
from ..records import record
from .cache import atomic_write, cache_dir, check_private, private_subdirectory, read_verified, write_sealed

__all__ = ["numba_rhs", "cache_dir", "cache_key", "write_module", "atomic_write", "import_module",
           "decorate", "purge_numba_cache"]

_HEADER = "import math\nimport numpy as np\nimport numba\n\n\n"


def _require_numba(what: str):
    try:
        import numba
    except ImportError as exc:  # pragma: no cover - exercised when numba is absent
        raise BackendError(f"{what} needs numba: install it with `pip install \"lagrange-dynamics[fast]\"`") from exc
    return numba


def cache_key(text: str) -> str:
    """The cache key of a generated module: a SHA-256 over everything that affects the compiled code.

    That is the module text itself (the model's generated source, its header and the numba decorator with
    its options; parameter values are not baked in, they are passed as the array ``p`` at run time) and
    the versions of lagrange, numba, NumPy and Python and the machine architecture. A new version of any
    of them or a changed model gives a new key, so a stale entry is never used.
    """
    import numpy

    numba = _require_numba("compiled code")
    lagrange_version = getattr(sys.modules.get("lagrange"), "__version__", "unknown")
    material = "\0".join([text, f"lagrange {lagrange_version}", f"numba {numba.__version__}",
                           f"numpy {numpy.__version__}", f"python {sys.version}", platform.machine()])
    return hashlib.sha256(material.encode()).hexdigest()[:24]


@record
class _Staged:
    """A module staged in this process: its text, its bundle's path and the bundle last read or written."""

    text: str
    bundle_path: Path
    bundle: bytes | None


_STAGED: dict[Path, _Staged] = {}
_STAMP = 946_684_800  # the staged files' fixed modification time (2000-01-01), so numba's stamp never changes
_STAGE: dict[str, object] = {}  # "pid": the process that made "dir", the staging directory


def _stage_dir() -> Path:
    """This process's private staging directory (made on first use, removed at exit; a forked child makes
    its own)."""
    if _STAGE.get("pid") != os.getpid():
        _STAGE["dir"] = Path(tempfile.mkdtemp(prefix="lagrange-stage-"))
        _STAGE["pid"] = os.getpid()
        atexit.register(_finish, _STAGE["dir"], os.getpid())
    return _STAGE["dir"]  # type: ignore[return-value]


def numba_cache_folder(path: Path) -> Path:
    """Where numba keeps the cache of the module file ``path``: ``$NUMBA_CACHE_DIR``'s subfolder for it when
    that is set, else ``__pycache__`` next to it (numba's ``UserProvidedCacheLocator`` and
    ``InTreeCacheLocator``)."""
    from numba.core import config
    from numba.core.caching import _CacheLocator

    if config.CACHE_DIR:
        return Path(config.CACHE_DIR) / _CacheLocator.get_suitable_cache_subpath(str(path))
    return path.parent / "__pycache__"


def private_numba_folder(path: Path) -> Path:
    """:func:`numba_cache_folder` of the staged module ``path``, made safe before numba looks into it.

    Without ``$NUMBA_CACHE_DIR`` it is ``__pycache__`` inside this process's private staging directory. With
    it, the folder's name is predictable (numba derives it from the staging directory's path), so another
    local user could make it first and plant an index there, which numba unpickles. So ``$NUMBA_CACHE_DIR``
    falls under the cache directory's rules (:func:`~lagrange.codegen.cache.check_private`: yours, not
    writable by group or others, unless ``$LAGRANGE_CACHE_TRUST`` is set), the folder itself must be a
    private directory of this user (:func:`~lagrange.codegen.cache.private_subdirectory`: made with mode
    0700, checked with ``lstat``, never a symbolic link, whatever the trust setting), and any numba files of
    this module already there are deleted: numba's cache of a staged module comes only from its sealed bundle.
    Raises :class:`~lagrange.errors.CacheError` when a check fails.
    """
    folder = numba_cache_folder(path)
    if folder.parent != path.parent:  # under $NUMBA_CACHE_DIR, not next to the staged module
        root = folder.parent
        root.mkdir(mode=0o700, parents=True, exist_ok=True)
        check_private(root, "numba cache directory ($NUMBA_CACHE_DIR)",
                      "; or unset NUMBA_CACHE_DIR (lagrange keeps its compiled code in its own cache anyway)")
    private_subdirectory(folder, "numba cache folder")
    for stale in _numba_files(path):
        stale.unlink(missing_ok=True)
    return folder


def _numba_files(path: Path) -> list[Path]:
    folder = numba_cache_folder(path)
    return sorted(p for p in folder.glob(f"{path.stem}.*") if p.suffix in (".nbi", ".nbc")) \
        if folder.is_dir() else []


def _pack_members(members: list[tuple[str, bytes]]) -> bytes:
    """``name NUL length LF bytes`` for each ``(name, bytes)``."""
    return b"".join(name.encode() + b"\0" + str(len(data)).encode() + b"\n" + data for name, data in members)


def _pack(files: list[Path]) -> bytes:
    return _pack_members([(f.name, f.read_bytes()) for f in files])


def _unpack(bundle: bytes, stem: str) -> list[tuple[str, bytes]]:
    """The files of a bundle; ValueError when it is malformed or names a file outside ``stem``'s cache."""
    out, i = [], 0
    while i < len(bundle):
        j = bundle.index(b"\0", i)
        k = bundle.index(b"\n", j)
        name, size = bundle[i:j].decode(), int(bundle[j + 1:k])
        if not (name.startswith(stem + ".") and name.endswith((".nbi", ".nbc")) and "/" not in name
                and "\\" not in name and 0 <= size <= len(bundle) - k - 1):
            raise ValueError(f"bad bundle member {name!r}")
        out.append((name, bundle[k + 1:k + 1 + size]))
        i = k + 1 + size
    return out


def write_module(prefix: str, text: str) -> tuple[str, Path]:
    """Stage generated module ``text`` as ``<prefix>_<key>.py`` and return its import name and staged path
    (``key`` is :func:`cache_key`); :func:`import_module` runs it.

    The module goes to this process's private staging directory, never to the shared cache; the numba
    cache of an earlier run is unpacked next to it when its sealed bundle ``<prefix>_<key>.numba`` in
    :func:`~lagrange.codegen.cache.cache_dir` passes authentication. Raises
    :class:`~lagrange.errors.CacheError` when the cache directory is not private.
    """
    key = cache_key(text)
    stem = f"{prefix}_{key}"
    path = _stage_dir() / f"{stem}.py"
    staged = _STAGED.get(path)
    if staged is not None and staged.bundle_path != cache_dir() / f"{stem}.numba":
        # the cache directory changed in this process ($LAGRANGE_CACHE_DIR): the module stays staged and
        # compiled, and what numba cached is sealed into the current directory from now on (load_cached
        # harvests it there at once)
        staged.bundle_path = cache_dir() / f"{stem}.numba"
        staged.bundle = read_verified(staged.bundle_path)
    if staged is None:
        bundle_path = cache_dir() / f"{stem}.numba"
        bundle = read_verified(bundle_path)
        path.write_text(text, encoding="utf-8")
        os.utime(path, (_STAMP, _STAMP))  # numba < 0.60 stamps its index with the file's (mtime, size)
        folder = private_numba_folder(path)
        try:
            members = _unpack(bundle, stem) if bundle is not None else []
        except (ValueError, UnicodeDecodeError):  # sealed by us yet malformed: rebuild
            members, bundle = [], None
        if members:
            for name, data in members:
                (folder / name).write_bytes(data)
        else:
            from ..progress import note

            note(f"compiling the generated {prefix} code with numba (one time for this model; cached in "
                 f"{bundle_path.parent})")
        _STAGED[path] = _Staged(text, bundle_path, bundle)
    return f"lagrange_{prefix}_{key}", path


def harvest(path: Path) -> None:
    """Seal what numba cached for the staged module ``path`` in this process into its bundle (when it
    changed). Called after a module is compiled and at exit; a cache that cannot be written is skipped."""
    staged = _STAGED.get(path)
    if staged is None:
        return
    try:
        private_subdirectory(numba_cache_folder(path), "numba cache folder")  # still this user's own
        files = _numba_files(path)
        bundle = _pack(files) if files else None
        if bundle is not None and bundle != staged.bundle:
            write_sealed(staged.bundle_path, bundle)
            staged.bundle = bundle
    except OSError:  # (a CacheError too: a folder no longer private is not harvested)
        pass


def _finish(stage: Path, pid: int) -> None:
    """At exit: seal what numba cached, then remove the staging directory (and its numba folder)."""
    if os.getpid() != pid:
        return
    for path in list(_STAGED):
        if path.parent == stage:
            harvest(path)
            try:
                folder = numba_cache_folder(path)
            except ImportError:
                continue
            if folder.parent != stage:
                shutil.rmtree(folder, ignore_errors=True)
    shutil.rmtree(stage, ignore_errors=True)


def import_module(name: str, path: Path):
    """Run the module :func:`write_module` staged at ``path`` under the import name ``name`` (numba's
    cache records it), from the text this process generated (never from a file another process could
    have written)."""
    loaded = sys.modules.get(name)
    if loaded is not None and getattr(loaded, "__file__", None) == str(path):
        return loaded
    staged = _STAGED.get(Path(path))
    if staged is None:
        raise BackendError(f"{path} is not a module staged by lagrange.codegen.numba_backend.write_module")
    module = types.ModuleType(name)
    module.__file__ = str(path)
    sys.modules[name] = module
    try:
        exec(compile(staged.text, str(path), "exec"), module.__dict__)  # noqa: S102 - text generated in-process
    except BaseException:
        sys.modules.pop(name, None)
        raise
    return module


def decorate(source: str, signatures: Mapping[str, str] | None = None,
             options: str = "cache=True, error_model='python'") -> str:
    """Put ``@numba.njit(options)`` above every top-level ``def`` of ``source`` that has no decorator of its
    own (one compiled eagerly with an explicit signature keeps its own); a function named in ``signatures``
    gets ``@numba.njit(signature, options)``, compiled eagerly for that signature."""
    signatures = signatures or {}
    lines = source.splitlines(keepends=True)
    out = []
    for k, line in enumerate(lines):
        if line.startswith("def ") and not (k and lines[k - 1].startswith("@")):
            name = line[4:line.index("(")]
            sig = f"{signatures[name]!r}, " if name in signatures else ""
            out.append(f"@numba.njit({sig}{options})\n")
        out.append(line)
    return "".join(out)


def numba_rhs(source: str) -> Callable:
    """Compile generated ``source`` (one or more top-level functions, among them ``rhs(t, y, p)``) as a
    cached module and return its ``rhs``; the module's other functions are reachable through
    ``rhs.py_func.__globals__`` (compiled lazily, on first call)."""
    _require_numba("backend='numba' (or use backend='python')")
    return load_cached("rhs", _HEADER + decorate(source), "the generated module", _load)


def load_cached(prefix: str, text: str, what: str, load: Callable = import_module):
    """``load(name, path)`` of module ``text`` written to the cache (:func:`write_module`); a stale or
    corrupted numba cache entry is purged and the load retried once, and a failure that survives the rebuild
    is one :class:`BackendError` line naming ``what`` and the module's path."""
    name, path = write_module(prefix, text)
    try:
        loaded = load(name, path)
    except Exception:  # noqa: BLE001 - a stale or corrupted numba cache entry: purge it and rebuild once
        purge_numba_cache(name, path)
        try:
            loaded = load(name, path)
        except Exception as exc:  # noqa: BLE001 - report a failure that survives the rebuild as one line
            raise BackendError(f"compiling {what} {path} with numba failed after purging its cache: "
                               f"{type(exc).__name__}: {exc}") from exc
    harvest(path)
    return loaded


def purge_numba_cache(name: str, path: Path) -> None:
    """Delete numba's cache files (``.nbi``/``.nbc``, where :func:`numba_cache_folder` says) of the
    generated module ``path`` and forget the imported module ``name``, so the next import recompiles."""
    for stale in _numba_files(path):
        stale.unlink(missing_ok=True)
    staged = _STAGED.get(path)
    if staged is not None:
        staged.bundle = None
    sys.modules.pop(name, None)


_SIGNATURE = "float64[::1](float64, float64[::1], float64[::1])"


def _load(name: str, path: Path) -> Callable:
    """Import the generated module and compile eagerly, so a broken cache shows up here, not in the
    middle of an integration."""
    module = import_module(name, path)
    module.rhs.compile(_SIGNATURE)
    return module.rhs
