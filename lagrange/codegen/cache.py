"""The on-disk cache: a private directory, and entries authenticated with a per-user key before use.

Everything lagrange keeps between runs lives in one directory, :func:`cache_dir`:
``$LAGRANGE_CACHE_DIR``, else ``$XDG_CACHE_HOME/lagrange`` (when that variable holds an absolute path),
else ``~/.cache/lagrange``. What is found there is executed or unpickled (derived equations, generated
source, compiled numba code, the C Taylor library), so the directory and every entry are checked:

* **The directory is private.** It is created with mode ``0700`` whatever the umask, and an existing one
  is refused with :class:`~lagrange.errors.CacheError` when it is owned by another user or writable by
  group or others (the message says how to fix it). ``LAGRANGE_CACHE_TRUST=1`` is the explicit opt-out,
  for a directory shared on purpose (e.g. by the workers of a Dask cluster): the entries are still
  authenticated, with the key found in that directory.
* **Every entry is authenticated.** The directory holds a per-user secret (``secret.key``: 32 random
  bytes, created atomically with mode ``0600``; refused when another user owns it or can read it). An entry
  carries a MAC of its file name and its bytes under that key (keyed BLAKE2b,
  :mod:`lagrange.codegen.digest`): :func:`write_sealed` writes ``tag + data`` in one file, :func:`seal`
  writes the tag next to a file another tool produced (``<name>.mac``, for the C library). An entry that is
  planted, copied under another key (retagged), edited, truncated or written by an older lagrange fails
  :func:`read_verified` / :func:`verify`: it is ignored and rebuilt, never loaded, and one
  :class:`~lagrange.errors.CacheIntegrityWarning` per process says so.
* **Writes are atomic and durable**: a temporary file in the same directory (mode ``0600``), ``fsync``, then
  ``os.replace`` (:func:`atomic_write`), so racing writers and readers see a whole entry or none.

The key is what an attacker lacks: anyone who can read ``secret.key`` can forge entries, so copying a cache
to another user or machine means copying (sharing) its key deliberately.

Examples
--------
>>> import os, tempfile
>>> from pathlib import Path
>>> old = os.environ.get("LAGRANGE_CACHE_DIR")
>>> os.environ["LAGRANGE_CACHE_DIR"] = os.path.join(tempfile.mkdtemp(), "cache")
>>> entry = cache_dir() / "example.bin"
>>> write_sealed(entry, b"payload")
>>> read_verified(entry)
b'payload'
>>> _ = os.environ.pop("LAGRANGE_CACHE_DIR") if old is None else os.environ.update(LAGRANGE_CACHE_DIR=old)
"""

from __future__ import annotations

import os
import stat
import tempfile
import warnings
from pathlib import Path

from ..errors import CacheError, CacheIntegrityWarning
from .digest import compare_digest, mac

__all__ = ["DIR_VAR", "TRUST_VAR", "SECRET_NAME", "cache_root", "cache_dir", "trusted", "check_private",
           "private_subdirectory", "atomic_write", "write_sealed", "read_verified", "seal", "verify", "tag"]

#: the cache directory, when set (else ``$XDG_CACHE_HOME/lagrange``, else ``~/.cache/lagrange``)
DIR_VAR = "LAGRANGE_CACHE_DIR"
#: ``1`` (or ``yes``, ``true``, ``on``): use a directory owned by another user or writable by others anyway
TRUST_VAR = "LAGRANGE_CACHE_TRUST"
#: the per-user key's file name inside the cache directory
SECRET_NAME = "secret.key"
_SECRET_BYTES = 32
_MAGIC = b"lagrange-sealed-v2 "
_SIDECAR = ".mac"
_warned = False


def trusted() -> bool:
    """True when ``$LAGRANGE_CACHE_TRUST`` is ``1``, ``yes``, ``true`` or ``on`` (read at each use)."""
    return os.environ.get(TRUST_VAR, "").strip().lower() in ("1", "yes", "true", "on")


def cache_root() -> Path:
    """Where the cache directory is (not created, not checked): ``$LAGRANGE_CACHE_DIR``, else
    ``$XDG_CACHE_HOME/lagrange`` (an absolute path, as the XDG specification requires; a relative one is
    ignored), else ``~/.cache/lagrange``."""
    explicit = os.environ.get(DIR_VAR)
    if explicit:
        return Path(explicit)
    xdg = os.environ.get("XDG_CACHE_HOME", "")
    if xdg and os.path.isabs(xdg):
        return Path(xdg) / "lagrange"
    return Path.home() / ".cache" / "lagrange"


def _euid() -> int | None:
    return os.geteuid() if hasattr(os, "geteuid") else None


def _refuse(path: Path, st: os.stat_result, what: str, private_bits: int, fix: str) -> None:
    """Raise :class:`CacheError` when ``path`` (stat ``st``) is another user's or has ``private_bits`` set."""
    if trusted():
        return
    problems = []
    uid = _euid()
    if uid is not None and st.st_uid != uid:
        problems.append(f"owned by uid {st.st_uid}, not by you (uid {uid})")
    if st.st_mode & private_bits:
        who = " and ".join(w for w, bit in (("group", 0o070), ("others", 0o007)) if st.st_mode & private_bits & bit)
        access = "writable" if private_bits == 0o022 else "accessible"
        problems.append(f"{access} by {who} (mode {stat.S_IMODE(st.st_mode):04o})")
    if problems:
        raise CacheError(
            f"lagrange will not use the {what} {path}: it is {' and '.join(problems)}, so someone else could "
            f"make lagrange run their code as you. Fix: {fix}, or set {DIR_VAR} to a private directory, or set "
            f"{TRUST_VAR}=1 to accept it deliberately (a cache shared on purpose, e.g. by Dask workers)")


def cache_dir() -> Path:
    """The private cache directory (:func:`cache_root`), created with mode ``0700`` when missing.

    Raises
    ------
    CacheError
        (a :class:`PermissionError`) when the directory is owned by another user or writable by group or
        others and ``$LAGRANGE_CACHE_TRUST`` is not set; or when the path is not a directory.
    """
    path = cache_root()
    try:
        os.mkdir(path, 0o700)
        os.chmod(path, 0o700)  # the umask can only clear bits of 0o700; a umask of 0o777 would leave none
    except FileNotFoundError:
        path.parent.mkdir(parents=True, exist_ok=True)
        try:
            os.mkdir(path, 0o700)
            os.chmod(path, 0o700)
        except FileExistsError:
            pass
    except FileExistsError:
        pass
    st = os.stat(path)
    if not stat.S_ISDIR(st.st_mode):
        raise CacheError(f"the cache directory {path} is not a directory: set {DIR_VAR} to a directory")
    _refuse(path, st, "cache directory", 0o022, f"`chmod 700 {path}` if it is yours")
    return path


def check_private(path: Path, what: str, fix: str = "") -> None:
    """Apply the cache directory's rules to another directory lagrange keeps code in (``what`` names it,
    ``fix`` adds a remedy to the message): :class:`CacheError` when ``path`` is owned by another user or
    writable by group or others, unless ``$LAGRANGE_CACHE_TRUST`` is set."""
    _refuse(path, os.stat(path), what, 0o022, f"`chmod 700 {path}` if it is yours{fix}")


def private_subdirectory(path: Path, what: str) -> Path:
    """The directory ``path``, made by this user with mode ``0700`` when missing; an existing one must be a
    real directory (checked with ``lstat``: never a symbolic link), owned by this user and closed to group and
    others. Nothing else is accepted, whatever ``$LAGRANGE_CACHE_TRUST`` says, so a directory someone else
    made under a predictable name is refused (:class:`CacheError`) instead of being read."""
    path = Path(path)
    try:
        os.mkdir(path, 0o700)
        os.chmod(path, 0o700)
    except FileExistsError:
        pass
    st = os.lstat(path)
    uid = _euid()
    problems = []
    if stat.S_ISLNK(st.st_mode):
        problems.append("a symbolic link")
    elif not stat.S_ISDIR(st.st_mode):
        problems.append("not a directory")
    else:
        if uid is not None and st.st_uid != uid:
            problems.append(f"owned by uid {st.st_uid}, not by you (uid {uid})")
        if st.st_mode & 0o077:
            problems.append(f"open to group or others (mode {stat.S_IMODE(st.st_mode):04o})")
    if problems:
        raise CacheError(f"lagrange will not use the {what} {path}: it is {' and '.join(problems)}, so someone "
                         f"else could have put code there for lagrange to load. Fix: remove {path} (lagrange "
                         "makes it again, privately), or use a private directory")
    return path


def _create_secret(path: Path) -> None:
    """Write a new random key at ``path`` atomically (mode 0600); a key another process wrote first wins."""
    import secrets  # (here: once per cache directory; a run that reads the key never needs it)

    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=".secret.", suffix=".tmp")  # mode 0600
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(secrets.token_bytes(_SECRET_BYTES))
            fh.flush()
            os.fsync(fh.fileno())
        try:
            os.link(tmp, path)  # atomic, and never replaces a key another process created meanwhile
        except FileExistsError:
            pass
    finally:
        Path(tmp).unlink(missing_ok=True)


def _read_file(path: Path) -> bytes:
    """The bytes of the regular file at ``path``, opened without following a symbolic link and without
    blocking: a FIFO, device or socket found under an entry's name (which would block the run or never end)
    or a link is refused with :class:`OSError`, never read."""
    fd = os.open(path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0))
    with os.fdopen(fd, "rb") as fh:
        if not stat.S_ISREG(os.fstat(fh.fileno()).st_mode):
            raise OSError(f"{path} is not a regular file")
        return fh.read()


def _secret(directory: Path) -> bytes:
    """The per-user key in ``directory``, created when missing."""
    path = directory / SECRET_NAME
    for _ in range(3):
        try:
            fd = os.open(path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0))
        except FileNotFoundError:
            _create_secret(path)
            continue
        except OSError as exc:  # a symbolic link (O_NOFOLLOW) or unreadable
            raise CacheError(f"cannot read the cache key {path}: {exc}; delete it (a new one is made)") from exc
        with os.fdopen(fd, "rb") as fh:
            st = os.fstat(fh.fileno())
            data = fh.read(_SECRET_BYTES + 1)
        if not stat.S_ISREG(st.st_mode):
            raise CacheError(f"the cache key {path} is not a regular file: delete it (a new one is made)")
        _refuse(path, st, "cache key", 0o077, f"delete {path} (a new key is made and the cache rebuilt)")
        if len(data) != _SECRET_BYTES:
            raise CacheError(f"the cache key {path} is damaged ({len(data)} bytes, not {_SECRET_BYTES}): delete "
                             "it (a new key is made and the cache rebuilt)")
        return data
    raise CacheError(f"cannot create the cache key {path}")  # pragma: no cover - deleted as fast as it is made


def tag(name: str, data: bytes, *, kind: bytes = b"entry", directory: Path | None = None) -> bytes:
    """Keyed BLAKE2b (:func:`lagrange.codegen.digest.mac`), under the key of ``directory`` (default
    :func:`cache_dir`), of ``kind``, the entry's file ``name`` (so an entry copied under another key fails) and
    ``data``; hex digits, as bytes."""
    if directory is None:
        directory = cache_dir()
    else:
        _refuse(directory, os.stat(directory), "cache directory", 0o022, f"`chmod 700 {directory}` if it is yours")
    key = _secret(directory)
    return mac(key, b"lagrange cache " + kind + b"\0" + name.encode() + b"\0" + data)


def atomic_write(path: Path, data: str | bytes) -> None:
    """Replace ``path`` by ``data`` (str: written as UTF-8) atomically: a temporary file in the same
    directory (mode 0600), ``fsync``, ``os.replace``. A reader sees the old or the new content, never a mix."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data.encode("utf-8") if isinstance(data, str) else data)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def _reject(path: Path, why: str) -> None:
    """Warn (once per process) that the entry at ``path`` failed authentication and will be rebuilt."""
    global _warned
    if not _warned:
        _warned = True
        warnings.warn(f"ignored the cache entry {path}: {why} (planted, copied under another name, edited, "
                      "damaged, or written by an older lagrange); it is rebuilt, never loaded. Further "
                      "rejected entries are not reported in this process.", CacheIntegrityWarning, stacklevel=3)


def write_sealed(path: Path, data: bytes) -> None:
    """Store ``data`` at ``path`` (inside :func:`cache_dir`) with its authentication tag, atomically."""
    path = Path(path)
    atomic_write(path, _MAGIC + tag(path.name, data, directory=path.parent) + b"\n" + data)


def read_verified(path: Path) -> bytes | None:
    """The data of the entry :func:`write_sealed` stored at ``path``, or None when it is missing or fails
    authentication (then a :class:`~lagrange.errors.CacheIntegrityWarning`, once per process).

    Raises :class:`~lagrange.errors.CacheError` when the directory or its key is not private."""
    path = Path(path)
    try:
        raw = _read_file(path)
    except FileNotFoundError:
        return None
    except OSError as exc:
        _reject(path, f"it cannot be read ({exc})")
        return None
    head, newline, data = raw.partition(b"\n")
    if not (newline and head.startswith(_MAGIC)):
        _reject(path, "it carries no authentication tag")
        return None
    if not compare_digest(head[len(_MAGIC):], tag(path.name, data, directory=path.parent)):
        _reject(path, "its authentication tag does not match")
        return None
    return data


def _sidecar(path: Path) -> Path:
    return path.with_name(path.name + _SIDECAR)


def seal(path: Path, data: bytes | None = None) -> None:
    """Authenticate the file at ``path`` (inside :func:`cache_dir`, written by another tool, e.g. a
    compiler): its tag goes to ``<name>.mac`` next to it. Seal only bytes you made. ``data``: the bytes that
    will be at ``path`` (to seal a file before it is moved into place), else the file's current bytes."""
    path = Path(path)
    data = path.read_bytes() if data is None else data
    atomic_write(_sidecar(path), _MAGIC + tag(path.name, data, kind=b"file", directory=path.parent))


def verify(path: Path) -> bool:
    """True when the file at ``path`` and its ``<name>.mac`` (:func:`seal`) match; False (and a
    :class:`~lagrange.errors.CacheIntegrityWarning`, once per process, when the file exists) otherwise."""
    path = Path(path)
    try:
        data = _read_file(path)
    except FileNotFoundError:
        return False
    except OSError as exc:
        _reject(path, f"it cannot be read ({exc})")
        return False
    try:
        mark = _read_file(_sidecar(path))
    except OSError:
        _reject(path, "it carries no authentication tag")
        return False
    if not (mark.startswith(_MAGIC)
            and compare_digest(mark[len(_MAGIC):], tag(path.name, data, kind=b"file", directory=path.parent))):
        _reject(path, "its authentication tag does not match")
        return False
    return True

