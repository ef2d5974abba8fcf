"""The compiled backend: the generated source under ``numba.njit(cache=True)``.

The source is written as a real module file in the cache directory, named by a hash of its text (and
the numba and Python versions), so numba's on-disk cache is valid exactly when the model is: a re-run
with the same model skips the JIT, a changed model gets a new file. Numba is optional
(``pip install lagrange[fast]``); a clear :class:`~lagrange.errors.BackendError` says so when it is
missing.
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path

from ..errors import BackendError

__all__ = ["numba_rhs", "cache_dir", "write_module", "import_module"]

_HEADER = "import math\nimport numpy as np\nimport numba\n\n\n"
_DECORATOR = "@numba.njit(cache=True, error_model='python')\n"


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
        raise BackendError(f"{what} needs numba: install it with `pip install lagrange[fast]`") from exc
    return numba


def write_module(prefix: str, text: str) -> tuple[str, Path]:
    """Write generated module ``text`` to the cache as ``<prefix>_<hash>.py`` (atomically: concurrent
    writers never leave a truncated file) and return its import name and path. The hash covers the text
    and the numba and Python versions, so a stale entry is never reused."""
    numba = _require_numba("compiled code")
    key = hashlib.sha256((text + numba.__version__ + sys.version).encode()).hexdigest()[:24]
    path = cache_dir() / f"{prefix}_{key}.py"
    if not path.exists() or path.read_text() != text:
        fd, tmp = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
        with os.fdopen(fd, "w") as fh:
            fh.write(text)
        os.replace(tmp, path)
    return f"lagrange_{prefix}_{key}", path


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


def numba_rhs(source: str) -> Callable:
    _require_numba("backend='numba' (or use backend='python')")
    name, path = write_module("rhs", _HEADER + _DECORATOR + source)
    try:
        return _load(name, path)
    except Exception:  # noqa: BLE001 - a stale or corrupted numba cache entry: purge it and rebuild once
        for folder in (path.parent, path.parent / "__pycache__"):
            for stale in folder.glob(f"{path.stem}.*"):
                if stale.suffix in (".nbi", ".nbc"):
                    stale.unlink(missing_ok=True)
        sys.modules.pop(name, None)
        return _load(name, path)


_SIGNATURE = "float64[::1](float64, float64[::1], float64[::1])"


def _load(name: str, path: Path) -> Callable:
    """Import the generated module and compile eagerly, so a broken cache shows up here, not in the
    middle of an integration."""
    module = import_module(name, path)
    module.rhs.compile(_SIGNATURE)
    return module.rhs
