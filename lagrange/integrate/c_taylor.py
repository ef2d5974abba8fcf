"""The Taylor tape interpreter built in C (:file:`_taylor_interp.c`) and called through ctypes.

Why a second build of the interpreter: a first result is dominated by fixed costs, and numba's first call in
a process costs about 0.2 s (its typing and lowering registries load, even when the kernel comes from its
cache), more than deriving and integrating a textbook system. The C library, compiled once per machine by
the system's C compiler (about 0.3 s) and kept in :func:`~lagrange.codegen.numba_backend.cache_dir`, loads
in about a millisecond. The source is a line-for-line transcription of
:func:`lagrange.integrate._taylor_loop.taylor` (same operations in the same order, no fused multiply-adds,
the same libm), so the two give identical results; the tests compare them bit for bit.

Optional: with no C compiler (``$CC``, else Python's configured compiler, else ``cc``), a failed build, or
``LAGRANGE_C_TAYLOR=0``, :func:`library` returns None and ``method="taylor"`` runs the numba interpreter
(which needs numba). :func:`unavailable_reason` says why.
"""

from __future__ import annotations

import ctypes
import hashlib
import os
import platform
import shlex
import shutil
import subprocess
import sys
import sysconfig
import tempfile
import weakref
from pathlib import Path

import numpy as np

__all__ = ["CTaylor", "library", "library_path", "compiler", "unavailable_reason", "ENV_VAR"]

#: set to 0 / off / false / no to never build or load the C interpreter
ENV_VAR = "LAGRANGE_C_TAYLOR"
SOURCE = Path(__file__).with_name("_taylor_interp.c")
FLAGS = ("-O2", "-std=c99", "-fPIC", "-shared", "-ffp-contract=off")

_LOADED: dict = {}  # cache directory -> CTaylor, or the reason it is unavailable (str)

_I64, _F64, _P = ctypes.c_int64, ctypes.c_double, ctypes.c_void_p
_ARGTYPES = [_P, _P, _I64, _P, _P, _I64, _I64, _I64, _I64, _P, _P, _I64, _I64, _F64, _F64, _P, _P, _F64, _I64, _F64,
             _P, _I64, _I64, _P, _P, _P, _P, _P]


def _disabled() -> bool:
    return os.environ.get(ENV_VAR, "1").strip().lower() in ("0", "off", "false", "no")


def compiler() -> list[str] | None:
    """The command that builds the library: ``$CC``, else Python's configured compiler, else ``cc`` (split into
    argv), or None when its program is not on PATH."""
    cc = os.environ.get("CC") or sysconfig.get_config_var("CC") or "cc"
    argv = shlex.split(cc)
    return argv if argv and shutil.which(argv[0]) else None


class CTaylor:
    """The loaded library; :meth:`run` has the signature and results of the numba interpreter's entry."""

    def __init__(self, path: Path):
        self.path = path
        self._lib = ctypes.CDLL(str(path))
        self._fn = self._lib.lagrange_taylor
        self._fn.argtypes = _ARGTYPES
        self._fn.restype = _I64

    def run(self, tape, t0: float, t1: float, z0: np.ndarray, p: np.ndarray, floor: float, order: int,
            max_step: float, t_eval: np.ndarray, max_steps: int):
        """``(status, t reached, z reached, Y, n_out, steps)`` as :func:`lagrange.integrate._taylor_loop.taylor`
        (``z0``, ``p``, ``t_eval``: contiguous float64 arrays)."""
        nz = int(tape.nz)
        Y = np.empty((t_eval.size, nz))
        z_end = np.empty(nz)
        out_t = np.empty(1)
        counts = np.zeros(2, dtype=np.int64)
        status = self._fn(*_tape_arguments(tape), t0, t1, z0.ctypes.data, p.ctypes.data, floor, order, max_step,
                          t_eval.ctypes.data, t_eval.size, max_steps, Y.ctypes.data, out_t.ctypes.data,
                          z_end.ctypes.data, counts.ctypes.data, counts[1:].ctypes.data)
        if status == 5:
            raise MemoryError(f"the C Taylor interpreter could not allocate its work arrays ({tape.n_slots} slots "
                              f"× order {order})")
        return status, float(out_t[0]), z_end, Y, int(counts[0]), int(counts[1])


_TAPE_ARGUMENTS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def _tape_arguments(tape) -> tuple:
    """The tape's part of the C call (array addresses and sizes), once per tape: each ``.ctypes.data`` costs
    about 0.7 µs, and the tape's arrays do not change (the tape holds them, so the addresses stay valid)."""
    args = _TAPE_ARGUMENTS.get(tape)
    if args is None:
        c = tape.const_code, tape.const_vals, tape.code, tape.consts, tape.mass, tape.force
        args = (c[0].ctypes.data, c[1].ctypes.data, c[0].shape[0], c[2].ctypes.data, c[3].ctypes.data,
                c[2].shape[0], tape.n_slots, tape.n, int(tape.nz), c[4].ctypes.data, c[5].ctypes.data, tape.power,
                tape.slot_t)
        _TAPE_ARGUMENTS[tape] = args
    return args


def _build(cc: list[str], target: Path) -> str | None:
    """Compile the source into ``target`` (atomically); None on success, else the reason."""
    fd, tmp = tempfile.mkstemp(dir=target.parent, prefix=f".{target.stem}.", suffix=".so")
    os.close(fd)
    try:
        proc = subprocess.run([*cc, *FLAGS, str(SOURCE), "-o", tmp, "-lm"], capture_output=True, text=True,
                              timeout=120)
        if proc.returncode != 0:
            return f"the C compiler failed: {(proc.stderr or proc.stdout).strip()[:300]}"
        os.replace(tmp, target)
        return None
    except (OSError, subprocess.SubprocessError) as exc:
        return f"the C compiler could not run: {exc}"
    finally:
        Path(tmp).unlink(missing_ok=True)


def library_path(cc: list[str]) -> Path:
    """Where the library built by ``cc`` lives: the cache directory, named by a hash of the source, the
    compiler command, the flags and the platform."""
    from ..codegen.numba_backend import cache_dir

    key = hashlib.sha256(b"\0".join([SOURCE.read_bytes(), " ".join(cc + list(FLAGS)).encode(),
                                     platform.machine().encode(), sys.platform.encode()])).hexdigest()[:24]
    return cache_dir() / f"ctaylor_{key}.so"


def _open(cc: list[str], target: Path) -> CTaylor | str:
    """The library at ``target``, built first when missing; or the reason it is unavailable."""
    if not target.exists():
        from ..progress import note

        note(f"building the C Taylor interpreter (one time; cached in {target.parent})")
        reason = _build(cc, target)
        if reason is not None:
            return reason
    try:
        return CTaylor(target)
    except (OSError, AttributeError) as exc:  # not a loadable library, or not ours
        return f"the C interpreter was built but does not load: {exc}"


def _load() -> CTaylor | str:
    cc = compiler()
    if cc is None:
        return "no C compiler found (set $CC)"
    try:
        target = library_path(cc)
        found = _open(cc, target)
        if isinstance(found, str) and target.exists():  # a damaged library (a crash mid-copy): rebuilt once
            target.unlink(missing_ok=True)
            found = _open(cc, target)
        return found
    except OSError as exc:
        return f"the C interpreter could not be built or loaded: {exc}"


def library() -> CTaylor | None:
    """The C interpreter (built on first use, once per machine), or None (see :func:`unavailable_reason`)."""
    if _disabled():
        return None
    key = os.environ.get("LAGRANGE_CACHE_DIR")
    if key not in _LOADED:
        _LOADED[key] = _load()
    found = _LOADED[key]
    return found if isinstance(found, CTaylor) else None


def unavailable_reason() -> str | None:
    """Why :func:`library` returns None (None when it does not)."""
    if _disabled():
        return f"{ENV_VAR}={os.environ.get(ENV_VAR)}"
    library()
    found = _LOADED[os.environ.get("LAGRANGE_CACHE_DIR")]
    return found if isinstance(found, str) else None
