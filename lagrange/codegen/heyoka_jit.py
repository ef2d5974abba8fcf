"""heyoka integrators built (LLVM-compiled) once, and kept on disk between processes.

Building a ``heyoka.taylor_adaptive`` compiles the Taylor recurrences with LLVM: 0.1 s for a pendulum, seconds
for a 5-link chain (compact mode), the whole first-result time of a small run. A ``taylor_adaptive`` pickles
with its compiled object code, and un-pickling skips the compile (measured in
``benchmarks/results/heyoka_backend.md``). So :func:`integrator` stores each integrator it builds in the
project's cache directory (:func:`lagrange.codegen.cache.cache_dir`), as ``heyoka_<key>.pkl``, sealed with the
per-user MAC key (:func:`~lagrange.codegen.cache.write_sealed`), and a later process loads it instead of
compiling, **after** the entry authenticated (:func:`~lagrange.codegen.cache.read_verified`): a planted, edited,
damaged or renamed entry is never unpickled — it is rebuilt (one
:class:`~lagrange.errors.CacheIntegrityWarning` per process), and a cache directory others can write is refused
with :class:`~lagrange.errors.CacheError`, as for every entry of the cache.

The key is a SHA-256 of everything the compiled code depends on: the equations' fingerprint
(:func:`lagrange.codegen.derivation_cache.equations_fingerprint`), :func:`~lagrange.codegen.derivation_cache.
environment` (lagrange's version and the hash of its code-generation sources, sympy, Python, the machine), the
heyoka version, the host CPU (heyoka compiles for the native CPU), the tolerance, the batch size, and each
event's expression, ``terminal`` and ``direction`` (compact mode, the state size and the runtime parameters
follow from the equations and the sources). A hit needs neither the CSE nor the conversion to heyoka
expressions: only the cheap checks of :func:`~lagrange.codegen.heyoka_expr.heyoka_shape` run. The state, time
and parameter values are not in it: the caller resets them. ``LAGRANGE_DERIVATION_CACHE=0`` turns this cache
off with the others.
"""

from __future__ import annotations

import hashlib
import pickle
from functools import lru_cache
from pathlib import Path

import numpy as np

from ..errors import CacheError
from .cache import cache_dir, read_verified, write_sealed
from .derivation_cache import enabled, environment, equations_fingerprint, prune
from .heyoka_events import HeyokaEvent, to_heyoka
from .heyoka_expr import heyoka_odes, heyoka_shape

__all__ = ["integrator", "cache_key", "HEADER"]

#: first line of every entry's payload (the format; the key follows)
HEADER = b"lagrange-heyoka-integrator-v1"


@lru_cache(maxsize=1)
def _cpu() -> str:
    """The host CPU's model and feature flags (heyoka's code is compiled for them), as far as the OS says."""
    try:
        text = Path("/proc/cpuinfo").read_text(errors="replace")
    except OSError:
        import platform

        return platform.processor() or platform.machine()
    keep = [line for line in text.splitlines() if line.split(":")[0].strip() in ("model name", "flags", "Features")]
    return hashlib.sha256("\n".join(sorted(set(keep))).encode()).hexdigest()[:16]


def cache_key(eqs, tol: float, events: tuple[HeyokaEvent, ...], batch: int = 0) -> str | None:
    """The entry key of the integrator of ``eqs`` at ``tol`` with ``events`` (``batch``: the
    batch size of a ``taylor_adaptive_batch``, 0 for the scalar integrator; module docstring), or None when the
    equations cannot be fingerprinted or the cache is off."""
    if not enabled():
        return None
    fingerprint = equations_fingerprint(eqs)
    if fingerprint is None:
        return None
    import heyoka as hy

    text = "\n".join([fingerprint, environment(), f"heyoka {hy.__version__}", f"cpu {_cpu()}", repr(float(tol)),
                      f"batch {int(batch)}",
                      *(ev.key for ev in events)])
    return hashlib.sha256(text.encode()).hexdigest()


def _entry(key: str) -> Path | None:
    try:
        return cache_dir() / f"heyoka_{key}.pkl"
    except CacheError:
        raise
    except OSError:  # no usable cache directory: run uncached
        return None


def _load(path: Path, key: str, hy, shape, n_events: int, batch: int):
    """The integrator stored at ``path`` after it authenticated, or None."""
    data = read_verified(path)  # None unless the MAC matched: nothing else is unpickled
    if data is None:
        return None
    head, newline, payload = data.partition(b"\n")
    if not newline or head != HEADER + b" " + key.encode():
        return None
    try:
        ta = pickle.loads(payload)  # noqa: S301 - our own entry, authenticated (keyed MAC) above
    except Exception:  # noqa: BLE001 - an entry that does not load is rebuilt
        return None
    kind, dims = ("taylor_adaptive_batch_dbl", (shape.nz, batch)) if batch else ("taylor_adaptive_dbl", (shape.nz,))
    if type(ta).__name__ != kind or tuple(ta.state.shape) != dims or len(ta.pars) < shape.n_params:
        return None
    ok = (len(ta.nt_events) + len(ta.t_events) == n_events) if getattr(ta, "with_events", False) else n_events == 0
    return ta if ok else None


def integrator(eqs, tol: float, events: tuple[HeyokaEvent, ...] = (), batch: int = 0) -> tuple[object, str, list]:
    """A ``heyoka.taylor_adaptive`` for :func:`lagrange.codegen.heyoka_expr.heyoka_odes` of ``eqs`` at
    tolerance ``tol`` with ``events`` — or, with ``batch`` > 0, a ``heyoka.taylor_adaptive_batch`` of that batch
    size (SIMD lanes; no events); its time, state and parameters are placeholders for the caller to set.

    Returns
    -------
    (ta, origin, order)
        ``origin`` is ``"disk"`` (loaded from the cache, no compile) or ``"compiled"``; ``order[k]`` is
        ``("nt" | "t", i)``: where user event ``k`` is in ``ta.nt_events`` / ``ta.t_events``.

    Raises
    ------
    CacheError
        The cache directory or its key is not private (see :mod:`lagrange.codegen.cache`).
    """
    import heyoka as hy

    order = []
    counts = {"nt": 0, "t": 0}
    for ev in events:
        kind = "t" if ev.terminal else "nt"
        order.append((kind, counts[kind]))
        counts[kind] += 1
    if batch and events:
        raise ValueError("heyoka's batch integrators are built without events here")
    shape = heyoka_shape(eqs)  # the refusals; an entry loaded from disk needs neither the CSE nor the conversion
    key = cache_key(eqs, tol, events, batch)
    path = _entry(key) if key is not None else None
    if path is not None:
        ta = _load(path, key, hy, shape, len(events), batch)
        if ta is not None:
            return ta, "disk", order
    odes = heyoka_odes(eqs)
    if batch:
        ta = hy.taylor_adaptive_batch(odes.system, np.zeros((odes.nz, batch)), tol=tol,
                                      pars=np.zeros((odes.n_params, batch)), compact_mode=odes.compact)
        return _store(ta, path, key), "compiled", order
    nt, te, _ = to_heyoka(events, hy)
    ta = hy.taylor_adaptive(odes.system, [0.0] * odes.nz, tol=tol, pars=[0.0] * odes.n_params,
                            compact_mode=odes.compact, nt_events=nt, t_events=te)
    return _store(ta, path, key), "compiled", order


def _store(ta, path: Path | None, key: str | None):
    """Write ``ta`` to its sealed entry (when the cache is on); returns ``ta``."""
    if path is not None:
        try:
            payload = pickle.dumps(ta, protocol=pickle.HIGHEST_PROTOCOL)
            write_sealed(path, HEADER + b" " + key.encode() + b"\n" + payload)
            prune(path.parent)
        except CacheError:
            raise
        except OSError:  # a cache that cannot be written only costs time
            pass
    return ta
