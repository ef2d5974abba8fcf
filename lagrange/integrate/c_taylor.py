"""The Taylor tape interpreter in C (:file:`_taylor_interp.c`), called through ctypes.

Why C: a first result is dominated by fixed costs; the C interpreter loads in about a millisecond and
needs nothing compiled per model, where numba's first call in a process costs about 0.2 s and a written-out
series costs a JIT compile per model (``benchmarks/taylor_engines.py``; docs/guide.md, "The Taylor method:
what is kept and why"). The library is the extension module built at install time or, without it, a library
built once per machine and verified before each load — both found by
:mod:`lagrange.codegen.c_interpreter` and reached through the compiled model
(:meth:`~lagrange.codegen.numeric.NumericModel.taylor_interpreter`); this module only loads and calls it.
"""

from __future__ import annotations

import ctypes
from pathlib import Path

import numpy as np

__all__ = ["CTaylor", "load"]

_I64, _F64, _P = ctypes.c_int64, ctypes.c_double, ctypes.c_void_p
_ARGTYPES = [_P, _P, _I64, _P, _P, _I64, _I64, _I64, _I64, _P, _P, _I64, _I64, _F64, _F64, _P, _P, _F64, _I64, _F64,
             _P, _I64, _I64, _P, _P, _P, _P, _P]
_LOADED: dict[str, CTaylor] = {}


class CTaylor:
    """The loaded library; :meth:`run` integrates a tape."""

    def __init__(self, path: Path):
        self.path = path
        self._lib = ctypes.CDLL(str(path))
        self._fn = self._lib.lagrange_taylor
        self._fn.argtypes = _ARGTYPES
        self._fn.restype = _I64
        self._tapes: dict[int, tuple] = {}

    def run(self, tape, t0: float, t1: float, z0: np.ndarray, p: np.ndarray, floor: float, order: int,
            max_step: float, t_eval: np.ndarray, max_steps: int, Y: np.ndarray):
        """Integrate from ``(t0, z0)`` towards ``t1`` for at most ``max_steps`` steps, writing the outputs at
        ``t_eval`` into the rows of ``Y`` (shape ``(len(t_eval), nz)``, C-contiguous); ``(status, t reached,
        z reached, n_out, steps)`` with the status codes of :class:`lagrange.integrate.compiled.LoopStatus`.
        ``z0``, ``p``, ``t_eval``: contiguous float64 arrays. The call releases the GIL."""
        nz = int(tape.nz)
        z_end = np.empty(nz)
        out_t = np.empty(1)
        counts = np.zeros(2, dtype=np.int64)
        status = self._fn(*self._tape_arguments(tape), t0, t1, z0.ctypes.data, p.ctypes.data, floor, order,
                          max_step, t_eval.ctypes.data, t_eval.size, max_steps, Y.ctypes.data, out_t.ctypes.data,
                          z_end.ctypes.data, counts.ctypes.data, counts[1:].ctypes.data)
        if status == 5:
            raise MemoryError(f"the C Taylor interpreter could not allocate its work arrays ({tape.n_slots} slots "
                              f"× order {order})")
        return int(status), float(out_t[0]), z_end, int(counts[0]), int(counts[1])

    def _tape_arguments(self, tape) -> tuple:
        """The tape's part of the C call (array addresses and sizes), once per tape: each ``.ctypes.data``
        costs about 0.7 µs, and the tape's arrays do not change (the entry keeps the tape alive)."""
        entry = self._tapes.get(id(tape))
        if entry is None or entry[0] is not tape:
            c = tape.const_code, tape.const_vals, tape.code, tape.consts, tape.mass, tape.force
            args = (c[0].ctypes.data, c[1].ctypes.data, c[0].shape[0], c[2].ctypes.data, c[3].ctypes.data,
                    c[2].shape[0], tape.n_slots, tape.n, int(tape.nz), c[4].ctypes.data, c[5].ctypes.data,
                    tape.power, tape.slot_t)
            if len(self._tapes) > 256:
                self._tapes.clear()
            entry = self._tapes[id(tape)] = (tape, args)
        return entry[1]


def load(path: Path) -> CTaylor:
    """The library at ``path`` (already verified by :mod:`lagrange.codegen.c_interpreter`), loaded once per
    process. Raises OSError when it is not a loadable library."""
    key = str(path)
    if key not in _LOADED:
        _LOADED[key] = CTaylor(path)
    return _LOADED[key]
