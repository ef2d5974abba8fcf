"""Cache integrity (lagrange.codegen.cache): the cache directory is private, and every entry is authenticated
with the per-user key before it is unpickled, executed or loaded. Each test is one attack or one directory
state; the attacks plant code that would create a canary file if it ran.

``INTEGRITY_SCENARIOS`` counts the scenarios tested here (docs/guarantees.md cites it).
"""

from __future__ import annotations

import multiprocessing as mp
import os
import pickle
import py_compile
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import lagrange as lg
from lagrange import t
from lagrange.codegen import cache as lc
from lagrange.codegen import derivation_cache as dc
from lagrange.errors import CacheError, CacheIntegrityWarning, LagrangeError

#: the directory states and attacks below, one test each (the parametrized ones count their cases)
DIRECTORY_STATES = ("group_writable", "others_writable", "foreign_owned")
SIDECAR_ATTACKS = ("truncated", "bit_flip", "retagged", "no_tag", "other_key")
INTEGRITY_SCENARIOS = (1 + len(DIRECTORY_STATES) + 1 + 1 + 1 + 1 + 1 + 1 + 1 + 1 + 1 + 1 + 1
                       + len(SIDECAR_ATTACKS))


class _Touch:
    """Unpickling this runs ``touch path``: what a planted pickle would do."""

    def __init__(self, path):
        self.path = str(path)

    def __reduce__(self):
        return (os.system, (f"touch {self.path}",))


@pytest.fixture
def fresh(tmp_path, monkeypatch):
    """An empty cache directory (no key yet), the derivation cache on, the warning not yet given."""
    root = tmp_path / "cache"
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(root))
    monkeypatch.delenv(lc.TRUST_VAR, raising=False)
    monkeypatch.setenv(dc.ENV_VAR, "1")
    monkeypatch.setattr(lc, "_warned", False)
    return root


def _pendulum(g_sign=1):
    th = lg.coordinates("theta")
    m, g, l = lg.parameters("m g l")
    return lg.System([th], T=m * l**2 * th.diff(t) ** 2 / 2, V=-g_sign * m * g * l * sp.cos(th))


def _theta2(system) -> float:
    traj = system.simulate(2.0, {"theta": 1.0, "theta_dot": 0.0}, {"m": 1.0, "g": 9.81, "l": 1.0},
                           backend="python", rtol=1e-10, atol=1e-12)
    return float(traj.y[-1, 0])


def _uncached(system):
    from lagrange.derive.lagrange import lagrange_equations

    return lagrange_equations(system)


def _same(a, b) -> bool:
    return all(sp.simplify(x - y) == 0 for x, y in zip(list(a.forcing) + list(a.mass_matrix),
                                                       list(b.forcing) + list(b.mass_matrix)))


# --- the directory -------------------------------------------------------------------------------------------

def test_directory_created_private_whatever_the_umask(fresh):
    old = os.umask(0)
    try:
        path = lc.cache_dir()
    finally:
        os.umask(old)
    assert path == fresh and (os.stat(path).st_mode & 0o777) == 0o700
    lc.write_sealed(path / "entry", b"x")
    key = path / lc.SECRET_NAME
    assert (os.stat(key).st_mode & 0o777) == 0o600 and len(key.read_bytes()) == 32
    assert (os.stat(path / "entry").st_mode & 0o777) == 0o600


def _make(state: str, path, monkeypatch) -> None:
    path.mkdir(mode=0o700)
    if state == "group_writable":
        os.chmod(path, 0o770)
    elif state == "others_writable":
        os.chmod(path, 0o707)
    elif hasattr(os, "geteuid") and os.geteuid() == 0:  # foreign_owned: really another user's
        os.chown(path, 4242, 4242)
    else:  # not root: this process pretends to be another user
        monkeypatch.setattr(lc, "_euid", lambda: os.stat(path).st_uid + 1)


@pytest.mark.parametrize("state", DIRECTORY_STATES)
def test_unsafe_directory_is_refused(fresh, monkeypatch, state):
    """Refused with a CacheError (a PermissionError) naming the path, the problem and the fixes, by the cache
    and by a derivation that would use it; accepted only with the explicit opt-out."""
    _make(state, fresh, monkeypatch)
    with pytest.raises(CacheError, match="will not use the cache directory") as info:
        lc.cache_dir()
    message = str(info.value)
    assert isinstance(info.value, PermissionError) and str(fresh) in message and lc.TRUST_VAR in message
    assert ("owned by uid" in message) == (state == "foreign_owned")
    assert ("writable by group" in message) == (state == "group_writable")
    with pytest.raises(CacheError):
        _pendulum().derived  # noqa: B018 - the derivation cache refuses too, it does not skip silently
    monkeypatch.setenv(lc.TRUST_VAR, "1")
    assert lc.cache_dir() == fresh
    lc.write_sealed(fresh / "entry", b"payload")
    assert lc.read_verified(fresh / "entry") == b"payload"  # still authenticated


def test_key_readable_by_others_is_refused(fresh):
    lc.write_sealed(lc.cache_dir() / "entry", b"payload")
    os.chmod(fresh / lc.SECRET_NAME, 0o644)
    with pytest.raises(CacheError, match="cache key .* accessible by group and others"):
        lc.read_verified(fresh / "entry")


def test_xdg_cache_home_is_honoured(tmp_path, monkeypatch):
    monkeypatch.delenv("LAGRANGE_CACHE_DIR", raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    assert lc.cache_dir() == tmp_path / "xdg" / "lagrange" and (tmp_path / "xdg" / "lagrange").is_dir()
    monkeypatch.setenv("XDG_CACHE_HOME", "relative/path")  # the XDG specification: ignored
    assert lc.cache_root() == Path.home() / ".cache" / "lagrange"
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path / "explicit"))
    assert lc.cache_root() == tmp_path / "explicit"


def _tag_in_process(args):
    root, barrier = args
    os.environ["LAGRANGE_CACHE_DIR"] = root
    barrier.wait(timeout=60)
    return lc.tag("entry", b"data")


@pytest.mark.skipif("fork" not in mp.get_all_start_methods(), reason="needs the fork start method")
def test_racing_processes_share_one_key(fresh):
    """Six processes create the key of a new cache at the same moment: one key wins, all use it."""
    ctx = mp.get_context("fork")
    with ctx.Manager() as manager:
        barrier = manager.Barrier(6)
        with ctx.Pool(6) as pool:
            tags = pool.map(_tag_in_process, [(str(fresh), barrier)] * 6)
    assert len(set(tags)) == 1 and tags[0] == lc.tag("entry", b"data")
    assert sorted(p.name for p in fresh.iterdir()) == [lc.SECRET_NAME]  # no temporary file left


# --- derivation entries ---------------------------------------------------------------------------------------

def test_planted_pickle_before_the_first_run_is_not_loaded(fresh, tmp_path):
    """A derived_*.pkl planted under the key lagrange will compute (keys are computable offline), with the
    header the old checksum format accepted, is never unpickled: the canary does not appear."""
    canary = tmp_path / "canary"
    system = _pendulum()
    key = dc.declaration_key(system)
    payload = pickle.dumps(_Touch(canary))
    fresh.mkdir(mode=0o700)
    (fresh / f"derived_{key}.pkl").write_bytes(dc._header(key, payload) + b"\n" + payload)
    with pytest.warns(CacheIntegrityWarning, match="authentication tag"):
        eqs = system.derived
    assert not canary.exists()
    assert _same(eqs, _uncached(_pendulum()))
    assert lc.read_verified(fresh / f"derived_{key}.pkl") is not None  # rebuilt, sealed
    # control: the planted payload is live (unpickling it in a child process creates the canary)
    subprocess.run([sys.executable, "-c", f"import pickle; pickle.loads({payload!r})"], check=True, timeout=60)
    assert canary.exists()
    canary.unlink()


def test_tampered_source_entry_is_not_used(fresh):
    """The generated source of a model, edited on disk with a matching checksum header, is not executed:
    θ(2) stays the right value. Control: the same edit sealed with the user's key does change θ(2)."""
    right = _theta2(_pendulum())
    # the right-hand side's entry (the diagnostics have their own)
    (entry,) = [e for e in fresh.glob("source_*.txt") if b"math.sin(y0)" in lc.read_verified(e)]
    key = entry.stem.split("_", 1)[1]
    head, _, text = lc.read_verified(entry).partition(b"\n")
    edited = text.replace(b"math.sin(y0)", b"math.sin(5*y0)")  # the code, not the checksum, is what changed
    assert edited != text
    entry.write_bytes(dc._header(key, edited) + b"\n" + edited)
    with pytest.warns(CacheIntegrityWarning):
        assert _theta2(_pendulum()) == pytest.approx(right, rel=1e-12, abs=1e-12)
    lc.write_sealed(entry, dc._header(key, edited) + b"\n" + edited)  # as if the user's own lagrange wrote it
    assert abs(_theta2(_pendulum()) - right) > 0.01


def test_retagged_entry_is_not_used(fresh):
    """A valid entry of another model copied under this model's key fails authentication (the tag covers the
    name): the model is derived afresh, not given the other model's equations."""
    upright, hanging = _pendulum(-1), _pendulum(1)
    upright.derived  # noqa: B018 - writes its sealed entry
    source = fresh / f"derived_{dc.declaration_key(upright)}.pkl"
    target = fresh / f"derived_{dc.declaration_key(hanging)}.pkl"
    target.write_bytes(source.read_bytes())
    with pytest.warns(CacheIntegrityWarning):
        eqs = hanging.derived
    assert _same(eqs, _uncached(_pendulum(1))) and not _same(eqs, _uncached(_pendulum(-1)))


def test_entry_sealed_with_another_key_is_not_used(fresh, tmp_path, monkeypatch):
    """An entry made in another cache (another user's key) and copied in under the right name is refused."""
    system = _pendulum()
    other = tmp_path / "other"
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(other))
    system.derived  # noqa: B018
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(fresh))
    lc.cache_dir()
    (entry,) = other.glob("derived_*.pkl")
    (fresh / entry.name).write_bytes(entry.read_bytes())
    with pytest.warns(CacheIntegrityWarning):
        assert lc.read_verified(fresh / entry.name) is None


# --- generated modules and numba's cache ---------------------------------------------------------------------

def _forget(nb) -> None:
    for name in [k for k in sys.modules if k.startswith("lagrange_rhs_")]:
        sys.modules.pop(name)
    for path in [p for p in nb._STAGED if p.stem.startswith("rhs_")]:
        nb.purge_numba_cache("", path)
        nb._STAGED.pop(path)


@pytest.fixture
def compiled(fresh, tmp_path, monkeypatch):
    """The numba module of the two-link pendulum built in a scratch cache: its stem and its rhs values."""
    pytest.importorskip("numba")
    from lagrange.codegen import numba_backend as nb
    from lagrange.examples import n_link_pendulum

    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path / "scratch"))
    y = np.array([0.3, -0.2, 0.1, 0.4])
    model = n_link_pendulum(2).compile({"g": 9.81}, backend="numba")
    stem = model.dynamics.py_func.__module__.removeprefix("lagrange_")
    values = model.fun(0.0, y)
    _forget(nb)
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(fresh))
    yield nb, stem, y, values
    _forget(nb)


def _rebuild(y):
    from lagrange.examples import n_link_pendulum

    model = n_link_pendulum(2).compile({"g": 9.81}, backend="numba")
    return model, model.fun(0.0, y)


def test_planted_module_bytecode_and_numba_index_are_not_run(compiled, tmp_path):
    """A generated module, its .pyc and a numba index planted in the cache directory where an older lagrange
    imported them from: modules are run from the text generated in this process and numba's cache comes only
    from a sealed bundle, so none of the three is read."""
    nb, stem, y, values = compiled
    canary = tmp_path / "canary"
    evil = f"import os\nos.system('touch {canary}')\n"
    cache = lc.cache_dir()
    (cache / f"{stem}.py").write_text(evil)
    (cache / "__pycache__").mkdir()
    py_compile.compile(str(cache / f"{stem}.py"), cfile=str(cache / "__pycache__" / f"{stem}.cpython-"
                                                              f"{sys.version_info[0]}{sys.version_info[1]}.pyc"))
    py = f"py{sys.version_info[0]}{sys.version_info[1]}"
    for name in ("rhs", "field", "dynamics"):
        (cache / "__pycache__" / f"{stem}.{name}-1.{py}.nbi").write_bytes(pickle.dumps(_Touch(canary)))
    model, again = _rebuild(y)
    assert not canary.exists() and np.array_equal(again, values)
    assert model.dynamics.stats.cache_misses  # compiled here, nothing loaded


@pytest.mark.parametrize("sealed_by", ["nobody", "another key"])
def test_planted_numba_bundle_is_not_unpacked(compiled, tmp_path, monkeypatch, sealed_by):
    """A bundle of numba cache files holding a pickle that runs code, planted under the module's name
    (unsealed, or sealed with another cache's key), is refused before numba could unpickle it."""
    nb, stem, y, values = compiled
    canary = tmp_path / "canary"
    py = f"py{sys.version_info[0]}{sys.version_info[1]}"
    bundle = nb._pack_members([(f"{stem}.rhs-1.{py}.nbi", pickle.dumps(_Touch(canary)))])
    target = lc.cache_dir() / f"{stem}.numba"
    if sealed_by == "nobody":
        target.write_bytes(bundle)
    else:
        other = tmp_path / "other"
        other.mkdir(mode=0o700)
        lc.write_sealed(other / target.name, bundle)
        target.write_bytes((other / target.name).read_bytes())
    with pytest.warns(CacheIntegrityWarning):
        model, again = _rebuild(y)
    assert not canary.exists() and np.array_equal(again, values)
    assert lc.read_verified(target) is not None and b"touch" not in lc.read_verified(target)  # rebuilt


# --- files sealed with a sidecar tag (the C Taylor library) ---------------------------------------------------

@pytest.mark.parametrize("attack", SIDECAR_ATTACKS)
def test_sealed_file_attacks_fail_verification(fresh, tmp_path, attack):
    lib = lc.cache_dir() / "ctaylor_0123.so"
    lib.write_bytes(os.urandom(4096))
    lc.seal(lib)
    assert lc.verify(lib)
    if attack == "truncated":
        lib.write_bytes(lib.read_bytes()[:2048])
    elif attack == "bit_flip":
        data = bytearray(lib.read_bytes())
        data[100] ^= 1
        lib.write_bytes(bytes(data))
    elif attack == "retagged":  # a valid library and tag copied under another key
        other = lib.with_name("ctaylor_4567.so")
        other.write_bytes(lib.read_bytes())
        other.with_name(other.name + ".mac").write_bytes(lib.with_name(lib.name + ".mac").read_bytes())
        lib = other
    elif attack == "no_tag":
        lib.with_name(lib.name + ".mac").unlink()
    else:  # sealed by another cache's key
        elsewhere = tmp_path / "elsewhere"
        elsewhere.mkdir(mode=0o700)
        (elsewhere / lib.name).write_bytes(lib.read_bytes())
        lc.seal(elsewhere / lib.name)
        lib.with_name(lib.name + ".mac").write_bytes((elsewhere / (lib.name + ".mac")).read_bytes())
    with pytest.warns(CacheIntegrityWarning):
        assert not lc.verify(lib)


def test_cache_error_is_a_lagrange_error():
    assert issubclass(CacheError, LagrangeError) and issubclass(CacheError, PermissionError)
