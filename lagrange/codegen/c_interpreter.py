"""Where the C Taylor interpreter (:file:`lagrange/integrate/_taylor_interp.c`) comes from: the extension module
built at install time, else a library built once per machine into the cache, verified before every load.

1. **Installed**: ``pip install`` compiles the source as the optional extension module
   ``lagrange.integrate._ctaylor`` when a C compiler is present (``setup.py``: ``Extension(optional=True)``, so
   the install succeeds without one). It lives in site-packages next to the Python code and is trusted as
   that code is.
2. **Built at run time** (no extension module, e.g. a source checkout): the system's compiler (``$CC``, else
   Python's configured compiler, else ``cc``) builds ``ctaylor_<key>.so`` in
   :func:`~lagrange.codegen.numba_backend.cache_dir` (about 0.3 s, once per machine): compiled to a temporary
   file, fsynced, sealed with the cache's keyed MAC (:func:`lagrange.codegen.cache.seal`, ``.so.mac``: a
   keyed BLAKE2b with the per-user secret, so a planted or retagged library is refused too) and moved into place with
   ``os.replace``. Before each load the library is checked against its seal (:func:`_verify`); a truncated or
   bit-flipped library (a crash mid-write, a full disk, an edit) is deleted and rebuilt instead of being
   loaded — loading a truncated library would die with SIGBUS.

:func:`_seal`/:func:`_verify` are the only two places that know how the library is authenticated.

``LAGRANGE_C_TAYLOR=0`` (or off/false/no) disables both; :func:`library_path_or_reason` then says so.
"""

from __future__ import annotations

import importlib.util
import os
import platform
import shutil
import sys
from pathlib import Path

from .digest import hexdigest

__all__ = ["ENV_VAR", "SOURCE", "FLAGS", "EXTENSION", "compiler", "library_path", "library_path_or_reason",
           "extension_path"]

#: set to 0 / off / false / no to never build or load the C interpreter
ENV_VAR = "LAGRANGE_C_TAYLOR"
SOURCE = Path(__file__).resolve().parent.parent / "integrate" / "_taylor_interp.c"
FLAGS = ("-O2", "-std=c99", "-fPIC", "-shared", "-ffp-contract=off")
#: the extension module built at install time (setup.py)
EXTENSION = "lagrange.integrate._ctaylor"

_FOUND: dict = {}  # cache directory -> library path (str) or the reason there is none ("!" + text)


def disabled() -> bool:
    """Whether ``$LAGRANGE_C_TAYLOR`` switches the C interpreter off."""
    return os.environ.get(ENV_VAR, "1").strip().lower() in ("0", "off", "false", "no")


def compiler() -> list[str] | None:
    """The command that builds the library: ``$CC``, else Python's configured compiler, else ``cc`` (split into
    argv), or None when its program is not on PATH."""
    import shlex  # (here: a run that finds the installed extension never needs them)
    import sysconfig

    cc = os.environ.get("CC") or sysconfig.get_config_var("CC") or "cc"
    argv = shlex.split(cc)
    return argv if argv and shutil.which(argv[0]) else None


def extension_path() -> Path | None:
    """The installed extension module's file, or None when the package was installed without it."""
    try:
        spec = importlib.util.find_spec(EXTENSION)
    except (ImportError, ValueError):
        return None
    return Path(spec.origin) if spec is not None and spec.origin else None


def library_path(cc: list[str]) -> Path:
    """Where the library built by ``cc`` lives: the cache directory, named by a hash of the source, the
    compiler command, the flags and the platform."""
    from .cache import cache_dir

    key = hexdigest(b"\0".join([SOURCE.read_bytes(), " ".join(cc + list(FLAGS)).encode(),
                                 platform.machine().encode(), sys.platform.encode()]), size=12)
    return cache_dir() / f"ctaylor_{key}.so"


# --- the seal: the one place that knows how a built library is authenticated ---------------------------------
def _seal_path(path: Path) -> Path:
    """Where the tag of ``path`` is kept (``<name>.mac``)."""
    from .cache import _sidecar

    return _sidecar(path)


def _seal(path: Path, data: bytes) -> None:
    """Authenticate ``data`` (the bytes about to be moved to ``path``) with the cache's keyed MAC
    (:func:`lagrange.codegen.cache.seal`: keyed BLAKE2b with the per-user secret, in ``<name>.mac``)."""
    from .cache import seal

    seal(path, data)


def _verify(path: Path) -> bool:
    """Whether ``path`` exists and its bytes match its keyed MAC (a missing or foreign tag fails)."""
    from .cache import verify

    return verify(path)


def _fsync_dir(folder: Path) -> None:
    try:
        fd = os.open(folder, os.O_RDONLY)
    except OSError:  # e.g. Windows: directories cannot be opened
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def _build(cc: list[str], target: Path) -> str | None:
    """Compile the source into ``target``: temporary file, fsync, seal, ``os.replace``; None on success, else
    the reason."""
    import subprocess
    import tempfile

    fd, tmp = tempfile.mkstemp(dir=target.parent, prefix=f".{target.stem}.", suffix=".so")
    os.close(fd)
    try:
        proc = subprocess.run([*cc, *FLAGS, str(SOURCE), "-o", tmp, "-lm"], capture_output=True, text=True,
                              timeout=120)
        if proc.returncode != 0:
            return f"the C compiler failed: {(proc.stderr or proc.stdout).strip()[:300]}"
        with open(tmp, "rb+") as fh:
            data = fh.read()
            os.fsync(fh.fileno())
        _seal(target, data)
        os.replace(tmp, target)
        _fsync_dir(target.parent)
        return None
    except (OSError, subprocess.SubprocessError) as exc:
        return f"the C compiler could not run: {exc}"
    finally:
        Path(tmp).unlink(missing_ok=True)


def _runtime_library() -> str:
    """The verified runtime-built library's path, built (or rebuilt when damaged) first; or "!" + the reason."""
    cc = compiler()
    if cc is None:
        return "!no C compiler found (set $CC)"
    try:
        target = library_path(cc)
        for _ in range(2):  # a racing writer can replace the library between our seal and our check: once more
            if _verify(target):
                return str(target)
            if target.exists():
                from ..progress import note

                note(f"the cached C Taylor interpreter {target.name} does not match its seal (damaged, or built "
                     "before libraries were sealed): rebuilt")
                target.unlink(missing_ok=True)
            else:
                from ..progress import note

                note(f"building the C Taylor interpreter (one time; cached in {target.parent})")
            reason = _build(cc, target)
            if reason is not None:
                return "!" + reason
        return "!the C interpreter was rebuilt but does not match its seal (another process keeps replacing it)"
    except OSError as exc:
        return f"!the C interpreter could not be built: {exc}"


def library_path_or_reason() -> tuple[Path | None, str | None]:
    """``(path, None)`` of the C interpreter to load — the installed extension module, else the verified
    runtime-built library — or ``(None, reason)`` when there is none (disabled, no compiler, a failed build).
    Looked up once per process and cache directory; a damaged runtime library is rebuilt here."""
    if disabled():
        return None, f"{ENV_VAR}={os.environ.get(ENV_VAR)}"
    key = os.environ.get("LAGRANGE_CACHE_DIR")
    if key not in _FOUND:
        ext = extension_path()
        _FOUND[key] = str(ext) if ext is not None else _runtime_library()
    found = _FOUND[key]
    return (None, found[1:]) if found.startswith("!") else (Path(found), None)


def forget() -> None:
    """Forget what :func:`library_path_or_reason` found (tests that damage or remove a library)."""
    _FOUND.clear()
