"""The compiled backend: the generated source under ``numba.njit(cache=True)``.

The source is written as a real module file in the cache directory, named by a hash of its text and of
the lagrange, numba, NumPy and Python versions (:func:`cache_key`), so numba's on-disk cache is valid
exactly when the model is: a re-run with the same model skips the JIT, a changed model or an upgrade gets a
new file. Entries are written atomically and checked on use; a corrupted numba cache is purged and rebuilt
(``tests/test_cache.py``). Numba is optional
(``pip install "lagrange-dynamics[fast]"``); a clear :class:`~lagrange.errors.BackendError` says so when it is
missing.
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
import platform
import sys
import tempfile
from collections.abc import Callable, Mapping
from pathlib import Path

from ..errors import BackendError

__all__ = ["numba_rhs", "cache_dir", "cache_key", "write_module", "atomic_write", "import_module",
           "decorate", "purge_numba_cache"]

_HEADER = "import math\nimport numpy as np\nimport numba\n\n\n"


def cache_dir() -> Path:
    """``$LAGRANGE_CACHE_DIR``, else ``~/.cache/lagrange`` (created on demand)."""
    root = os.environ.get("LAGRANGE_CACHE_DIR") or os.path.join(Path.home(), ".cache", "lagrange")
    path = Path(root)
    path.mkdir(parents=True, exist_ok=True)
    return path


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


def write_module(prefix: str, text: str) -> tuple[str, Path]:
    """Write generated module ``text`` to the cache as ``<prefix>_<key>.py`` and return its import name and
    path; ``key`` is :func:`cache_key`.

    An existing entry is reused only when its bytes equal ``text`` (a corrupted or truncated file is
    rewritten). Writes are atomic: the text goes to a temporary file in the same directory, is flushed to
    disk, and replaces the entry with ``os.replace``, so processes building the same model at once never
    see or leave a partial file.
    """
    key = cache_key(text)
    path = cache_dir() / f"{prefix}_{key}.py"
    try:
        current = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        current = None
    if current != text:
        from ..progress import note

        note(f"compiling the generated {prefix} code with numba (one time for this model; cached in {path.parent})")
        atomic_write(path, text)
    return f"lagrange_{prefix}_{key}", path


def atomic_write(path: Path, text: str | bytes) -> None:
    """Replace ``path`` by ``text`` (str: written as UTF-8; or bytes) atomically (temporary file in the same
    directory, fsync, ``os.replace``): a reader sees the old or the new content, never a mix or a truncated
    file."""
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.stem}.", suffix=".tmp")
    try:
        with (os.fdopen(fd, "wb") if isinstance(text, bytes) else os.fdopen(fd, "w", encoding="utf-8")) as fh:
            fh.write(text)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def import_module(name: str, path: Path):
    """Import a generated module under a real name (numba's cache records it)."""
    loaded = sys.modules.get(name)
    if loaded is not None and getattr(loaded, "__file__", None) == str(path):
        return loaded
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    assert spec.loader is not None
    sys.modules[name] = module
    spec.loader.exec_module(module)
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
        return load(name, path)
    except Exception:  # noqa: BLE001 - a stale or corrupted numba cache entry: purge it and rebuild once
        purge_numba_cache(name, path)
        try:
            return load(name, path)
        except Exception as exc:  # noqa: BLE001 - report a failure that survives the rebuild as one line
            raise BackendError(f"compiling {what} {path} with numba failed after purging its cache: "
                               f"{type(exc).__name__}: {exc}") from exc


def purge_numba_cache(name: str, path: Path) -> None:
    """Delete numba's cache files (``.nbi``/``.nbc``, next to the module or in its ``__pycache__``) of the
    generated module ``path`` and forget the imported module ``name``, so the next import recompiles."""
    for folder in (path.parent, path.parent / "__pycache__"):
        for stale in folder.glob(f"{path.stem}.*"):
            if stale.suffix in (".nbi", ".nbc"):
                stale.unlink(missing_ok=True)
    sys.modules.pop(name, None)


_SIGNATURE = "float64[::1](float64, float64[::1], float64[::1])"


def _load(name: str, path: Path) -> Callable:
    """Import the generated module and compile eagerly, so a broken cache shows up here, not in the
    middle of an integration."""
    module = import_module(name, path)
    module.rhs.compile(_SIGNATURE)
    return module.rhs
