"""The derivation cache: derived equations and generated source on disk, so a re-run of the same declared
model in a fresh process skips both the sympy derivation and the code generation (CSE, printing).

Its entries live in :func:`~lagrange.codegen.cache.cache_dir` (``$LAGRANGE_CACHE_DIR``, else
``$XDG_CACHE_HOME/lagrange``, else ``~/.cache/lagrange``; private, see :mod:`lagrange.codegen.cache`), next
to the numba bundles:

``derived_<key>.pkl``
    the pickled :class:`~lagrange.derive.equations.Equations` of a :class:`~lagrange.System`, under
    :func:`declaration_key`: a BLAKE2b over a hash tree of everything the derivation reads from the
    declaration (coordinates with their assumptions, T — or, when it comes wholly from Particles and
    RigidBodies, the fields it is built from (:func:`~lagrange.derive.derivation_choice.kinetic_declaration`),
    so that a re-run never builds it — V, P, the Rayleigh function, the generalized forces, the constraints,
    prescribed motions, declared parameters, name) and of :func:`environment`;
``source_<key>.txt``
    the generated source of one backend, under a BLAKE2b of the equations' fingerprint
    (:func:`equations_fingerprint`), the code generator's options and :func:`environment`. Equations
    derived from a declaration are fingerprinted by their declaration key (the derivation is a function of
    the declaration and the environment, both in the key); equations built any other way by the hash tree
    of their content, so they hit exactly when their content is the same;
``code_<key>.pyc``
    the generated python-backend module compiled (:func:`cached_code`: its code object marshalled, as in a
    ``.pyc``), under a BLAKE2b of the source and :func:`environment` (whose Python version is the
    marshal format's);
``tape_<key>.arrays``
    the Taylor tape (:class:`~lagrange.codegen.tape.Tape`: the CSE translated into numbered instructions) of
    a model, under a BLAKE2b of the equations' fingerprint and :func:`environment`; plain integer and float
    arrays, each a name, a numeric dtype, a shape and its bytes (:func:`_pack_arrays`; nothing in it is
    unpickled; not ``.npz``, whose zip reader cost 10–20 ms of a warm re-run's 0.4 s), so a
    re-run of ``method="taylor"`` skips the CSE and the translation (1.1 s of a warm re-run of the 10-link
    pendulum before it was cached).

:func:`statistics` counts, per kind of entry, the hits, misses and refused entries of this process (what a
test or a benchmark reads to see a re-run load instead of rebuild).

:func:`environment` names the entry format, the lagrange version *and a hash of the source files of the
stages that make the entries* (:data:`SOURCES`: an edited checkout never reuses an entry made by other
code), the sympy, symengine (or its absence) and Python versions and the machine. Each entry starts with
one header line holding its key, the BLAKE2b of its payload and the environment; an entry whose header does
not match (damaged, truncated, renamed, or written by other versions) is ignored and rebuilt, so a stale or
damaged entry never gives a wrong answer. Every entry is sealed with a MAC (keyed BLAKE2b) under the per-user key of the
cache directory (:func:`~lagrange.codegen.cache.write_sealed`) and authenticated before it is unpickled or
used (:func:`~lagrange.codegen.cache.read_verified`): a planted entry, a valid entry copied under another
key, an edited or a damaged one is rebuilt, never loaded. Writes are atomic and fsynced. A
declaration holding a sympy class defined outside sympy and lagrange (a user's ``Function`` subclass: its
behaviour is not in its ``srepr``) is never cached.

Set ``LAGRANGE_DERIVATION_CACHE=0`` (or ``off``, ``false``, ``no``) to turn the cache off: every run then
derives and generates afresh and writes no entry. The numba backend still writes its module (numba needs a
file to cache the compiled code).
"""

from __future__ import annotations

import io
import marshal
import os
import pickle
import platform
import sys
import weakref
from collections.abc import Callable
from dataclasses import fields
from functools import lru_cache
from pathlib import Path
from types import CodeType

import numpy as np
import sympy as sp
from sympy.core.function import AppliedUndef, UndefinedFunction
from sympy.printing.repr import ReprPrinter

from ..derive.equations import Equations
from ..errors import CacheError
from .cache import cache_dir, read_verified, write_sealed
from .digest import hasher, hexdigest

__all__ = ["ENV_VAR", "MAX_ENTRIES_VAR", "prune",
           "enabled", "environment", "declaration_key", "equations_fingerprint", "cached_equations",
           "stored_equations", "cached_source", "cached_code", "cached_arrays", "statistics"]

#: environment variable that turns the cache off (``0``, ``off``, ``false``, ``no``)
ENV_VAR = "LAGRANGE_DERIVATION_CACHE"
_FORMAT = 1
#: how declarations and equations are turned into keys (:class:`_KeyHasher`; the srepr text before)
_KEY_FORMAT = "merkle-blake2b v3 (T by its bodies' fields)"
_OFF = ("0", "off", "false", "no")
#: System attributes that are not in the key, and why (tests check every other attribute is keyed)
UNKEYED_ATTRIBUTES = {
    "bodies": "their kinetic energy is in T (or in _T_declaration) and their constraints in constraints",
    "T_given": "part of T (zero when _T_declaration stands for T)",
    "_T_declaration": "keyed as T when not None: the fields T is built from",
    "description": "text only",
    "derivation": "only expanded derivations are cached (structural ones are derived directly, in a fraction of it)",
    "_kinematic_bodies": "the bodies with prescribed motion substituted: in T",
    "symbolic_timeout": "limits whether a derivation may finish, never what it derives (lagrange.limits)",
    "symbolic_budget": "limits whether a derivation may finish, never what it derives (lagrange.limits)",
}


_STATS: dict[tuple[str, str], int] = {}


def _count(kind: str, outcome: str) -> None:
    _STATS[kind, outcome] = _STATS.get((kind, outcome), 0) + 1


def statistics() -> dict[str, dict[str, int]]:
    """What the cache did in this process: ``{kind: {"hit": n, "miss": n, "refused": n}}`` for the kinds
    ``"derived"``, ``"source"``, ``"code"`` and ``"tape"`` (a *miss* builds and stores the entry; *refused* counts
    entries that were present but did not authenticate, did not match their header or did not load, and were
    rebuilt; a refused entry is also a miss). Runs with the cache off count nothing.

    >>> sorted(statistics())
    ['code', 'derived', 'source', 'tape']
    """
    return {kind: {outcome: _STATS.get((kind, outcome), 0) for outcome in ("hit", "miss", "refused")}
            for kind in ("derived", "source", "code", "tape")}


def enabled() -> bool:
    """False when ``$LAGRANGE_DERIVATION_CACHE`` is ``0``, ``off``, ``false`` or ``no`` (read at each use)."""
    return os.environ.get(ENV_VAR, "").strip().lower() not in _OFF


#: the parts of lagrange that make the entries (the stages before integration): their source is hashed
SOURCES = ("conventions.py", "simplification.py", "symengine_bridge.py", "model", "derive", "codegen")


def _source_files(root: str) -> list[str]:
    """The ``.py`` files of :data:`SOURCES` under ``root`` (paths relative to it, ``/``-separated), in
    :data:`SOURCES` order (``os.walk`` and plain strings: pathlib's ``rglob`` and ``relative_to`` doubled its
    cost)."""
    files = []
    for part in SOURCES:
        if part.endswith(".py"):
            files.append(part)
            continue
        for folder, dirs, names in os.walk(os.path.join(root, part)):
            dirs[:] = [d for d in dirs if d != "__pycache__"]
            rel = os.path.relpath(folder, root).replace(os.sep, "/")
            files += [f"{rel}/{name}" for name in names if name.endswith(".py")]
    return sorted(files, key=lambda r: (SOURCES.index(r.split("/")[0]), r))


def _content_digest(root: str, files: list[str]) -> str:
    """BLAKE2b of the paths and bytes of ``files``."""
    h = hasher()
    for rel in files:
        with open(os.path.join(root, *rel.split("/")), "rb") as fh:
            h.update(rel.encode() + b"\0" + fh.read() + b"\0")
    return h.hexdigest()


@lru_cache(maxsize=1)
def _source_digest() -> str:
    """:func:`sources_digest` of lagrange's own package, once per process."""
    return sources_digest(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def sources_digest(root: str) -> str:
    """BLAKE2b of the ``.py`` files (paths and bytes) of :data:`SOURCES` under ``root``.

    Reading and hashing the 45 files costs about 4 ms of every warm re-run (1.8 ms with the memo), so the
    digest is remembered in the cache directory (``srcdigest_<fingerprint>.txt``, sealed like every entry)
    under a fingerprint of each file's path, size, inode, device and modification and change times in
    nanoseconds. That is stricter than
    the check Python's own bytecode cache trusts (modification time in seconds and size): an edit, a
    ``git checkout`` or a reinstall changes the change time, which no user can set back. With the cache off or
    unusable, the files are read every time.
    """
    files = _source_files(root)
    memo = None
    if enabled():
        try:
            stats = [root]
            for rel in files:
                st = os.stat(os.path.join(root, *rel.split("/")))
                stats.append(f"{rel} {st.st_size} {st.st_ino} {st.st_dev} {st.st_mtime_ns} {st.st_ctime_ns}")
            memo = _entry_path("srcdigest", hexdigest("\n".join(stats).encode(), size=16), ".txt")
            text = read_verified(memo) if memo is not None else None
        except (OSError, CacheError):  # no usable cache directory: read the files
            memo, text = None, None
        if text is not None and len(text) == 64 and all(c in b"0123456789abcdef" for c in text):
            return text.decode()
    digest = _content_digest(root, files)
    if memo is not None:
        try:
            write_sealed(memo, digest.encode())
        except OSError:
            pass
    return digest


@lru_cache(maxsize=1)
def _symengine_version() -> str:
    """symengine's installed version, or "none" (it differentiates large T's when installed, which orders
    terms differently). Read from the name of its ``symengine-<version>.dist-info`` directory next to the
    package: importing symengine (20–40 ms) is left to the models that use it, and ``importlib.metadata``
    (40–130 ms of imports, ``email`` among them, on a warm re-run) is only the fallback when that directory
    is not found."""
    import importlib.util

    spec = importlib.util.find_spec("symengine")
    if spec is None:
        return "none"
    for location in spec.submodule_search_locations or ():
        try:
            names = os.listdir(os.path.dirname(location))  # (a plain listing: pathlib's glob cost 1 ms more)
        except OSError:
            continue
        found = [name for name in names if name.startswith("symengine-") and name.endswith(".dist-info")]
        if len(found) == 1:
            return found[0][len("symengine-"):-len(".dist-info")]
    import importlib.metadata

    try:
        return importlib.metadata.version("symengine")
    except importlib.metadata.PackageNotFoundError:
        return "none"


def environment() -> str:
    """Everything besides the model that an entry depends on: the entry format, the lagrange version and
    the hash of its source files, the sympy, symengine and Python versions and the machine (one line)."""
    version = getattr(sys.modules.get("lagrange"), "__version__", "unknown")
    text = (f"format {_FORMAT}; lagrange {version} source {_source_digest()[:20]}; sympy {sp.__version__}; "
            f"symengine {_symengine_version()}; python {sys.version}; {platform.machine()}")
    return " ".join(text.split())


class _Uncacheable(Exception):
    """A sympy class whose behaviour the ``srepr`` does not pin down."""


def _known(cls: type) -> bool:
    return isinstance(cls, UndefinedFunction) or (cls.__module__ or "").split(".")[0] in ("sympy", "lagrange")


class _KeyPrinter(ReprPrinter):
    """``srepr`` that also prints the assumptions of undefined functions (plain ``srepr`` drops them:
    ``Function('x', real=True)`` and ``Function('x')`` print alike) and refuses unknown sympy classes.

    Terms and factors are printed in the order sympy stores them (``order="none"``), not re-sorted for
    display: the stored order is already canonical (``Add``/``Mul`` sort their arguments with
    ``Basic.compare``, which depends on content only, not on hashes), and skipping the display sort makes
    the key of a large model about 3× cheaper (Greenspan's top: 0.37 s → 0.12 s). Should two equal
    expressions ever print differently, the cost is a cache miss, never a wrong answer.
    """

    def __init__(self):
        super().__init__({"order": "none"})

    def _print(self, expr, **kwargs):
        if isinstance(expr, sp.Basic) and not _known(type(expr)):
            raise _Uncacheable(type(expr).__qualname__)
        return super()._print(expr, **kwargs)

    def _print_UndefinedFunction(self, expr) -> str:
        return f"Function({expr.__name__!r}, {sorted(getattr(expr, '_kwargs', {}).items())!r})"


def _digest(*parts: str) -> str:
    return hexdigest("\0".join(parts).encode(), size=16)


def _text(obj) -> str | None:
    """The ``srepr``-like text of ``obj`` (:class:`_KeyPrinter`), or None when it holds a sympy class defined
    outside sympy and lagrange."""
    try:
        return _KeyPrinter().doprint(obj)
    except _Uncacheable:
        return None


def _h(tag: bytes, *parts: bytes) -> bytes:
    """BLAKE2b of a one-byte ``tag`` and ``parts``, each prefixed with its length (no two different part
    lists give the same input)."""
    h = hasher(tag)
    for part in parts:
        h.update(len(part).to_bytes(8, "little"))
        h.update(part)
    return h.digest()


class _KeyHasher:
    """A content digest of a declaration or of equations: a hash tree (Merkle) over the expression graph.

    A sympy node with arguments hashes its class (module and name; for an applied undefined function the
    function's name and assumptions) and the digests of its ``args`` in the order sympy stores them, which
    determine the node (``expr.func(*expr.args) == expr``); a node without arguments — symbols with their
    assumptions, numbers with their exact value and precision, ``t`` — hashes its :class:`_KeyPrinter` text
    (``srepr``). Tuples, lists, strings, numbers, None and dictionaries (in their order) hash their type and
    content; any other object its type and printed text, as the printer-based key did. A sympy class defined
    outside sympy and lagrange, and a ``Poly`` (its domain is neither in its arguments nor in its ``srepr``:
    ``Poly(x**2, x)`` and ``Poly(x**2, x, domain="QQ")`` print alike) raise :class:`_Uncacheable`. Every
    digest is tagged with its kind and its parts are length-prefixed, so different content never gives the
    same input to BLAKE2b: two declarations sharing a key would need a BLAKE2b collision.

    A subexpression met again (the same object: ``sin(q1)`` in every term of a pendulum's T) is hashed once
    (memo by ``id``; the memo holds the objects, so an id is never reused while hashing), where the printed
    ``srepr`` repeated it. Against printing the ``srepr``: a declaration's key 3× (heavy top) to 18× (20-link
    pendulum) cheaper, equations' fingerprints 3× to 30×.
    """

    def __init__(self):
        self._memo: dict[int, tuple[object, bytes]] = {}
        self._printer = _KeyPrinter()

    def digest(self, obj) -> bytes:
        hit = self._memo.get(id(obj))
        if hit is not None:
            return hit[1]
        out = self._digest(obj)
        self._memo[id(obj)] = (obj, out)
        return out

    def _digest(self, obj) -> bytes:
        if isinstance(obj, sp.Basic):
            cls = type(obj)
            if not _known(cls) or isinstance(obj, sp.Poly):  # a Poly's domain is neither in args nor in srepr
                raise _Uncacheable(cls.__qualname__)
            args = obj.args
            if not args:
                return _h(b"a", self._printer.doprint(obj).encode())
            if isinstance(cls, UndefinedFunction):
                name = self._printer._print_UndefinedFunction(cls)
            else:
                name = f"{cls.__module__}.{cls.__qualname__}"
            return _h(b"n", name.encode(), *[self.digest(a) for a in args])
        if type(obj) is tuple or type(obj) is list:  # exact types: a subclass (a namedtuple) is an "other" object
            return _h(b"t" if type(obj) is tuple else b"l", *[self.digest(a) for a in obj])
        if type(obj) is str:
            return _h(b"s", obj.encode())
        if obj is None or type(obj) in (bool, int, float):
            return _h(b"p", type(obj).__name__.encode(), repr(obj).encode())
        if type(obj) is dict:
            return _h(b"d", *[self.digest(kv) for kv in obj.items()])
        return _h(b"o", f"{type(obj).__module__}.{type(obj).__qualname__}".encode(),
                  self._printer.doprint(obj).encode())


def _fingerprint(obj) -> str | None:
    """The hex digest of ``obj`` by :class:`_KeyHasher`, or None when it holds a sympy class defined outside
    sympy and lagrange."""
    try:
        return _KeyHasher().digest(obj).hex()
    except _Uncacheable:
        return None


def _declaration(system) -> tuple:
    """``(attribute name, value)`` of everything :func:`lagrange.derive.lagrange.lagrange_equations` can read
    from ``system`` (dictionaries as tuples sorted by key, constraints as tuples of their fields)."""
    declared = system._declared_parameters
    return (
        ("coordinates", tuple(system.coordinates)),
        # T by what it is built from when that pins it down (a warm re-run never builds it), else T itself
        ("T", system._T_declaration if getattr(system, "_T_declaration", None) is not None else system.T),
        ("V", system.V), ("P", system.P), ("rayleigh", system.rayleigh),
        ("forces", tuple(sorted(system.forces.items(), key=lambda kv: str(kv[0])))),
        ("constraints", tuple(tuple((f.name, getattr(c, f.name)) for f in fields(c)) for c in system.constraints)),
        ("prescribed", tuple(sorted(system.prescribed.items(), key=lambda kv: str(kv[0])))),
        ("_declared_parameters", None if declared is None else tuple(sorted(declared, key=str))),
        ("name", system.name),
    )


def declaration_key(system) -> str | None:
    """The key of ``system``'s derivation entry: a BLAKE2b over the hash tree (:class:`_KeyHasher`) of its
    declaration (every attribute the derivation reads) and :func:`environment`; None when the declaration
    cannot be cached.

    >>> import lagrange as lg
    >>> x = lg.coordinates("x"); m, k = lg.parameters("m k")
    >>> a = lg.System([x], T=m * x.diff(lg.t)**2 / 2, V=k * x**2 / 2)
    >>> b = lg.System([x], T=m * x.diff(lg.t)**2 / 2, V=k * x**2)
    >>> declaration_key(a) == declaration_key(lg.System([x], T=m * x.diff(lg.t)**2 / 2, V=k * x**2 / 2))
    True
    >>> declaration_key(a) == declaration_key(b)
    False
    """
    content = _fingerprint(_declaration(system))
    return None if content is None else _digest("derived", _KEY_FORMAT, content, environment())


_FINGERPRINTS: dict[int, tuple[weakref.ref, str | None]] = {}


def _remember(eqs: Equations, fingerprint: str | None) -> str | None:
    key = id(eqs)
    # the table is bound now: at interpreter shutdown the module's globals may already be None
    _FINGERPRINTS[key] = (weakref.ref(eqs, lambda _ref, table=_FINGERPRINTS: table.pop(key, None)), fingerprint)
    return fingerprint


def equations_fingerprint(eqs: Equations) -> str | None:
    """BLAKE2b of the hash tree (:class:`_KeyHasher`) of every field of ``eqs`` (None when it holds an unknown
    sympy class).

    Memoized per object; equations derived or loaded by :func:`cached_equations` come with the fingerprint
    of their entry (a digest of the declaration key), so they are never printed.
    """
    known = _FINGERPRINTS.get(id(eqs))
    if known is not None and known[0]() is eqs:
        return known[1]
    identity = getattr(eqs, "_identity", None)  # structural equations: without deriving their expanded fields
    content = _fingerprint(identity() if identity else tuple((f.name, getattr(eqs, f.name)) for f in fields(eqs)))
    return _remember(eqs, None if content is None else _digest("equations", _KEY_FORMAT, content))


def _entry_path(kind: str, key: str, suffix: str) -> Path | None:
    try:
        return cache_dir() / f"{kind}_{key}{suffix}"
    except CacheError:  # a directory others could write: refused loudly, never used
        raise
    except OSError:  # no usable cache directory (read-only home, ...): run uncached
        return None


def _header(key: str, payload: bytes) -> bytes:
    return f"lagrange-cache {key} blake2b {hexdigest(payload)} {environment()}".encode()


def _read(path: Path | None, key: str) -> bytes | None:
    """The payload of the entry at ``path``, or None when it is missing, fails authentication (planted,
    edited, damaged, copied under another key) or its header does not match (another key, environment)."""
    if path is None:
        return None
    data = read_verified(path)
    if data is None:
        return None
    head, newline, payload = data.partition(b"\n")
    return payload if newline and head == _header(key, payload) else None


def _write(path: Path | None, key: str, payload: bytes) -> None:
    """Store an entry atomically, then prune; a cache that cannot be written is skipped (it only saves time)."""
    if path is not None:
        try:
            write_sealed(path, _header(key, payload) + b"\n" + payload)
            prune(path.parent)
        except CacheError:
            raise
        except OSError:
            pass


#: entries kept (``$LAGRANGE_DERIVATION_CACHE_MAX``, default 2000): each edit of lagrange's sources, each
#: upgrade and each changed declaration makes new entries and strands the old ones
MAX_ENTRIES_VAR = "LAGRANGE_DERIVATION_CACHE_MAX"


def prune(directory: Path, max_entries: int | None = None) -> int:
    """Delete the least recently written entries (``derived_*.pkl``, ``source_*.txt``, ``code_*.pyc``,
    ``tape_*.arrays``, ``*.numba``, ``heyoka_*.pkl``, ``srcdigest_*.txt``) beyond
    ``max_entries`` (default ``$LAGRANGE_DERIVATION_CACHE_MAX`` or 2000), down to 90 % of it; returns the
    number deleted. Called after every write (a cache miss), so the directory never grows without bound."""
    if max_entries is None:
        try:
            max_entries = int(os.environ.get(MAX_ENTRIES_VAR, "2000"))
        except ValueError:
            max_entries = 2000
    entries = []
    for pattern in ("derived_*.pkl", "source_*.txt", "code_*.pyc", "tape_*.arrays", "*.numba", "heyoka_*.pkl",
                    "srcdigest_*.txt"):
        for path in directory.glob(pattern):
            try:
                entries.append((path.stat().st_mtime, path))
            except OSError:  # removed meanwhile by another process
                pass
    if len(entries) <= max_entries:
        return 0
    entries.sort()
    removed = 0
    for _, path in entries[: len(entries) - int(0.9 * max_entries)]:
        try:
            path.unlink()
            removed += 1
        except OSError:
            pass
    return removed


def _stored(cls: type, args: tuple, commutative: bool | None = None):
    """An ``Add`` or ``Mul`` rebuilt from the arguments it was stored with, without evaluating them again (nor
    deducing again whether it commutes: stored with it, a third of the load before)."""
    return cls._from_args(args, commutative)


def _stored_pow(base, exp):
    """A ``Pow`` rebuilt from its stored arguments, without evaluating it again."""
    return sp.Pow(base, exp, evaluate=False)


def _stored_function(cls: type, args: tuple):
    """An applied sympy function (``sin``, ``cos``, ``exp``, …) rebuilt from its stored arguments without
    evaluating it again (its ``eval`` looks for multiples of π, parities, …: half of loading a double pendulum's
    equations)."""
    return cls(*args, evaluate=False)


class _Pickler(pickle.Pickler):
    """Pickles ``Add``, ``Mul``, ``Pow`` and sympy's own functions (``sin``, ``cos``, …) as their stored arguments,
    rebuilt unevaluated on load.

    Plain pickling rebuilds every sympy node through its constructor, which evaluates (flattens, collects
    and sorts) again: 85 % of loading a derived entry (10-link pendulum: 0.33 s → 0.05 s). The arguments are
    those of an already canonical expression (what the constructor returned when the entry was made), so the
    rebuilt expression is the same (same ``srepr``, equal, same hash: checked by the tests); only these
    classes are treated so, every other node is rebuilt by its constructor as before.
    """

    def reducer_override(self, obj):
        cls = type(obj)
        if cls is sp.Add or cls is sp.Mul:
            return _stored, (cls, obj.args, obj.is_commutative)
        if cls is sp.Pow:
            return _stored_pow, obj.args
        if (isinstance(obj, sp.Function) and not isinstance(obj, AppliedUndef)
                and (cls.__module__ or "").startswith("sympy.functions.")):
            return _stored_function, (cls, obj.args)
        return NotImplemented


def _dumps(obj) -> bytes:
    buffer = io.BytesIO()
    _Pickler(buffer, protocol=pickle.HIGHEST_PROTOCOL).dump(obj)
    return buffer.getvalue()


def cached_equations(system, derive: Callable) -> Equations:
    """``derive(system)``, loaded from the derivation cache when an intact entry made by the same
    declaration and :func:`environment` exists, else derived and stored.

    Parameters
    ----------
    system : System
    derive : callable ``System -> Equations`` (:func:`lagrange.derive.lagrange.lagrange_equations`)
    """
    key = declaration_key(system) if enabled() else None
    if key is None:
        return derive(system)
    path = _entry_path("derived", key, ".pkl")
    eqs = _load_equations(system, key, path)
    if eqs is not None:
        return eqs
    _refused_or_missing("derived", path)
    eqs = derive(system)
    # equations derived from this declaration in this environment are named by its key: printing their
    # srepr for a content fingerprint would cost more than the derivation itself on a large model (Greenspan's
    # rigid top: 116 ms of a 0.6 s first result)
    fingerprint = _remember(eqs, _digest("equations derived from", key))
    if fingerprint is not None:
        try:
            payload = _dumps((eqs, fingerprint))
        except Exception:  # noqa: BLE001 - something in the equations does not pickle: not cached
            return eqs
        _write(path, key, payload)
    return eqs


def stored_equations(system) -> Equations | None:
    """The equations derived from ``system``'s declaration when the derivation cache holds an intact entry for
    it (what :func:`cached_equations` would load), else None: nothing is derived or stored, and a miss is not
    counted. Lets a caller use equations that are at hand without paying for a derivation (``method="auto"``
    on a structural system weighs the Taylor method only when the expanded equations are)."""
    key = declaration_key(system) if enabled() else None
    return None if key is None else _load_equations(system, key, _entry_path("derived", key, ".pkl"))


def _load_equations(system, key: str, path: Path | None) -> Equations | None:
    """The equations of the entry at ``path`` (counted as a hit), or None when it is missing or does not
    authenticate, match ``key`` or load."""
    payload = _read(path, key)
    if payload is None:
        return None
    try:
        eqs, fingerprint = pickle.loads(payload)  # noqa: S301 - our own entry, authenticated (keyed MAC)
    except Exception:  # noqa: BLE001 - an entry that does not load is rebuilt
        return None
    if isinstance(eqs, Equations) and isinstance(fingerprint, str) and eqs.coordinates == system.coordinates:
        _remember(eqs, fingerprint)
        _count("derived", "hit")
        return eqs
    return None


def cached_source(eqs: Equations, options: str, generate: Callable[[], str]) -> str:
    """``generate()``, the generated source for ``eqs`` with code-generator ``options`` (a string naming
    the backend flavour and anything else that changes the text), loaded from the cache when an intact
    entry exists, else generated and stored."""
    fingerprint = equations_fingerprint(eqs) if enabled() else None
    if fingerprint is None:
        return generate()
    return _entry("source", _digest("source", fingerprint, options, environment()), ".txt",
                  lambda payload: payload.decode("utf-8"), generate, lambda text: text.encode("utf-8"))


def _entry(kind: str, key: str, suffix: str, load: Callable[[bytes], object], build: Callable[[], object],
           dump: Callable[[object], bytes]):
    """The value of the entry ``<kind>_<key><suffix>``: ``load(payload)`` of an intact entry (a hit), else
    ``build()`` stored as ``dump(value)`` (a miss; a refusal too when the entry was there). An entry whose payload
    ``load`` rejects — by raising or by returning None — is rebuilt; exceptions of ``build`` propagate."""
    path = _entry_path(kind, key, suffix)
    payload = _read(path, key)
    if payload is not None:
        try:
            value = load(payload)
        except Exception:  # noqa: BLE001 - an entry that does not load is rebuilt
            value = None
        if value is not None:
            _count(kind, "hit")
            return value
    _refused_or_missing(kind, path)
    value = build()
    _write(path, key, dump(value))
    return value


#: compiled code by the BLAKE2b of its source, in this process (bounded): a re-run in the same process neither
#: reads the entry again nor unmarshals it
_CODE: dict[str, CodeType] = {}
_CODE_MEMO = 64


def cached_code(source: str, filename: str) -> CodeType:
    """``compile(source, filename, "exec")``, loaded from the cache when an intact entry exists (``code_<key>.pyc``:
    the code object marshalled, as in a ``.pyc`` file, under a BLAKE2b of the source, ``filename`` and
    :func:`environment`, which names the Python version that wrote it), else compiled and stored.

    The python backend's generated module of a 10-link pendulum takes 25–35 ms to compile and 1 ms to unmarshal.
    A marshalled entry is trusted as a pickle is: only after its seal (keyed MAC) and header are verified.
    """
    digest = hexdigest(source.encode("utf-8"))
    code = _CODE.get(digest)
    if code is not None:
        return code

    def load(payload: bytes) -> CodeType | None:
        code = marshal.loads(payload)
        return code if isinstance(code, CodeType) and code.co_filename == filename else None

    def build() -> CodeType:
        return compile(source, filename, "exec")

    code = (_entry("code", _digest("code", digest, filename, environment()), ".pyc", load, build, marshal.dumps)
            if enabled() else build())
    if len(_CODE) >= _CODE_MEMO:
        _CODE.pop(next(iter(_CODE)))
    _CODE[digest] = code
    return code


def _refused_or_missing(kind: str, path: Path | None) -> None:
    """Count a miss, and a refusal when an entry was there (it did not authenticate, match or load)."""
    _count(kind, "miss")
    if path is not None and path.exists():
        _count(kind, "refused")


_ARRAY_KINDS = "biufc"  # booleans, integers, floats, complex: no objects, strings or structured records


def _pack_arrays(arrays: dict[str, np.ndarray]) -> bytes:
    """``arrays`` as one byte string. Per array: its name (2-byte length, UTF-8), its dtype (1-byte length,
    ``numpy.dtype.str`` such as ``<f8``; numbers and booleans only), its shape (1-byte ndim, 8 bytes per
    dimension) and its bytes in C order (8-byte length). Not ``.npy`` records: numpy parses each ``.npy`` header
    with ``ast.literal_eval``, a compile per array (about 3 ms for a tape's eleven arrays on a warm re-run)."""
    out = bytearray()
    for name, value in arrays.items():
        array = np.asarray(value)
        if array.dtype.kind not in _ARRAY_KINDS:
            raise ValueError(f"array {name!r}: dtype {array.dtype} is not numeric")
        raw, dtype = name.encode("utf-8"), array.dtype.str.encode("ascii")
        out += len(raw).to_bytes(2, "little") + raw + len(dtype).to_bytes(1, "little") + dtype
        out += array.ndim.to_bytes(1, "little") + b"".join(d.to_bytes(8, "little") for d in array.shape)
        data = array.tobytes(order="C")
        out += len(data).to_bytes(8, "little") + data
    return bytes(out)


def _unpack_arrays(payload: bytes) -> dict[str, np.ndarray]:
    """The arrays of :func:`_pack_arrays` (raises ValueError on anything else: a truncated or inconsistent record,
    a dtype that is not a number). Each array is a writable copy."""
    view, at, out = memoryview(payload), 0, {}

    def take(n: int) -> bytes:
        nonlocal at
        if n < 0 or at + n > len(payload):
            raise ValueError("a truncated array record")
        at += n
        return bytes(view[at - n:at])

    while at < len(payload):
        name = take(int.from_bytes(take(2), "little")).decode("utf-8")
        dtype = np.dtype(take(int.from_bytes(take(1), "little")).decode("ascii"))
        shape = tuple(int.from_bytes(take(8), "little") for _ in range(int.from_bytes(take(1), "little")))
        size = int.from_bytes(take(8), "little")
        if name in out or dtype.kind not in _ARRAY_KINDS or size != dtype.itemsize * int(np.prod(shape)):
            raise ValueError(f"a damaged array record ({name!r})")
        out[name] = np.frombuffer(take(size), dtype=dtype).reshape(shape).copy()
    return out


def cached_arrays(eqs: Equations, kind: str, options: str, build: Callable[[], dict[str, np.ndarray]],
                  accept: Callable[[dict[str, np.ndarray]], bool] | None = None) -> dict[str, np.ndarray]:
    """``build()``, a dictionary of numeric arrays (integer, float or bool; no objects) made from ``eqs`` with
    ``options``, loaded from the cache (``<kind>_<key>.arrays``) when an intact entry exists, else built and
    stored. The entry is the arrays' records (:func:`_pack_arrays`: dtype, shape and bytes; never pickles),
    read after its seal is verified.

    ``kind`` names the entry (``"tape"``: :func:`lagrange.codegen.tape.tape_of`); an entry whose arrays do not
    load, hold objects or fail ``accept(arrays)`` (the caller's check of names, types and shapes) is refused
    and rebuilt. Exceptions of ``build`` propagate (nothing is stored).
    """
    fingerprint = equations_fingerprint(eqs) if enabled() else None
    if fingerprint is None:
        return build()

    def load(payload: bytes) -> dict[str, np.ndarray] | None:
        arrays = _unpack_arrays(payload)
        return arrays if accept is None or accept(arrays) else None

    return _entry(kind, _digest(kind, fingerprint, options, environment()), ".arrays", load, build, _pack_arrays)
