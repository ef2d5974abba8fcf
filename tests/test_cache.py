"""The on-disk cache of generated numba modules: keyed by everything that affects the code, numba's cache
kept as one sealed bundle per module (lagrange.codegen.numba_backend), damaged bundles rebuilt, concurrent
writers safe, stale entries never used. The attacks (planted, retagged, edited entries) are in
tests/test_cache_integrity.py.

``CACHE_SCENARIOS`` counts the scenarios tested here (the README's guarantees section cites it).
"""

from __future__ import annotations

import multiprocessing as mp
import shutil
import sys

import numpy as np
import pytest

pytest.importorskip("numba")

from lagrange.codegen import cache as lc  # noqa: E402
from lagrange.codegen import numba_backend as nb  # noqa: E402
from lagrange.errors import CacheIntegrityWarning  # noqa: E402
from lagrange.examples import n_link_pendulum  # noqa: E402

Y = np.array([0.3, -0.2, 0.1, 0.4])
#: damage done to a module's bundle of numba cache files
CORRUPTIONS = ("garbage", "truncated", "empty", "bit_flip", "index_swapped")
#: key material, cache hit, numba cache written and sealed, 5 bundle corruptions, version bumps
#: (lagrange, numba, numpy, python), source change, concurrent builders, concurrent writers/readers
CACHE_SCENARIOS = 1 + 1 + 1 + len(CORRUPTIONS) + 4 + 1 + 1 + 1


def _forget_loaded_modules() -> None:
    """Drop generated modules from ``sys.modules`` and from this process's staging area, with the numba
    cache files numba wrote there: the next build behaves like a fresh process."""
    for name in [k for k in sys.modules if k.startswith("lagrange_rhs_")]:
        sys.modules.pop(name)
    for path in [p for p in nb._STAGED if p.stem.startswith("rhs_")]:
        nb.purge_numba_cache("", path)
        nb._STAGED.pop(path)


@pytest.fixture(scope="module")
def warm(tmp_path_factory):
    """A cache directory holding the compiled two-link pendulum (built once) and its rhs values."""
    root = tmp_path_factory.mktemp("warm_cache")
    with pytest.MonkeyPatch.context() as m:
        m.setenv("LAGRANGE_CACHE_DIR", str(root))
        values = _compile().fun(0.0, Y)
    _forget_loaded_modules()
    return root, values


@pytest.fixture
def cache(tmp_path, monkeypatch, warm):
    """A private copy of the warm cache, as the cache directory of this test."""
    shutil.copytree(warm[0], tmp_path, dirs_exist_ok=True)
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path))
    monkeypatch.setattr(lc, "_warned", False)
    _forget_loaded_modules()
    yield tmp_path
    _forget_loaded_modules()


@pytest.fixture
def empty_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path))
    _forget_loaded_modules()
    yield tmp_path
    _forget_loaded_modules()


def _compile(g: float = 9.81):
    return n_link_pendulum(2).compile({"g": g}, backend="numba")


def _reference():
    return n_link_pendulum(2).compile({"g": 9.81}, backend="reference").fun(0.0, Y)


def _rhs_modules(cache) -> list:
    """The sealed numba bundles of generated rhs modules."""
    return sorted(cache.glob("rhs_*.numba"))


def test_cache_key_covers_text_and_versions(monkeypatch):
    base = nb.cache_key("text")
    assert nb.cache_key("text") == base and nb.cache_key("text ") != base
    import numba
    import numpy

    import lagrange

    for module, attr in ((lagrange, "__version__"), (numba, "__version__"), (numpy, "__version__")):
        with monkeypatch.context() as m:
            m.setattr(module, attr, getattr(module, attr) + ".post999")
            assert nb.cache_key("text") != base, module.__name__
    with monkeypatch.context() as m:
        m.setattr(sys, "version", sys.version + " patched")
        assert nb.cache_key("text") != base


def test_cache_reused(empty_cache):
    first = _compile()
    assert first.dynamics.stats.cache_misses and not first.dynamics.stats.cache_hits
    modules = _rhs_modules(empty_cache)
    assert len(modules) == 1
    members = [name for name, _ in nb._unpack(lc.read_verified(modules[0]), modules[0].stem)]
    assert any(n.endswith(".nbi") for n in members) and any(n.endswith(".nbc") for n in members)
    assert not list(empty_cache.glob("rhs_*.py")) and not (empty_cache / "__pycache__").exists()
    stamp = modules[0].stat().st_mtime_ns
    _forget_loaded_modules()
    again = _compile()
    assert again.dynamics.stats.cache_hits and not again.dynamics.stats.cache_misses  # loaded, not compiled
    assert np.array_equal(first.fun(0.0, Y), again.fun(0.0, Y))
    assert _rhs_modules(empty_cache) == modules and modules[0].stat().st_mtime_ns == stamp  # not rewritten
    assert np.allclose(first.fun(0.0, Y), _reference(), rtol=1e-12, atol=1e-12)


def _damage(path, how: str) -> None:
    data = path.read_bytes()
    if how == "garbage":
        path.write_bytes(b"\x80garbage" * 7)
    elif how == "truncated":
        path.write_bytes(data[: len(data) // 2])
    elif how == "empty":
        path.write_bytes(b"")
    elif how == "bit_flip":
        path.write_bytes(data[:-100] + bytes([data[-100] ^ 1]) + data[-99:])
    else:  # the bundle's own content, the index of one function put in place of another's
        head, _, body = data.partition(b"\n")
        members = nb._unpack(body, path.stem)
        names = [n for n, _ in members if n.endswith(".nbi")]
        swapped = {names[0]: dict(members)[names[-1]], names[-1]: dict(members)[names[0]]}
        path.write_bytes(head + b"\n" + nb._pack_members([(n, swapped.get(n, d)) for n, d in members]))


@pytest.mark.parametrize("how", [pytest.param(c, marks=pytest.mark.slow) if c not in ("garbage", "bit_flip")
                                 else c for c in CORRUPTIONS])
def test_corrupted_numba_bundle_rebuilt(cache, warm, how):
    """A damaged bundle of numba's cache fails authentication: it is not unpacked, numba recompiles, the
    result is unchanged and the bundle is rewritten intact."""
    (bundle,) = _rhs_modules(cache)
    _damage(bundle, how)
    with pytest.warns(CacheIntegrityWarning, match="authentication tag"):
        model = _compile()
    assert model.dynamics.stats.cache_misses and not model.dynamics.stats.cache_hits
    assert np.array_equal(warm[1], model.fun(0.0, Y))
    assert _rhs_modules(cache) == [bundle] and lc.read_verified(bundle) is not None


@pytest.mark.parametrize("target", ["lagrange", pytest.param("numba", marks=pytest.mark.slow),
                                    pytest.param("numpy", marks=pytest.mark.slow),
                                    pytest.param("python", marks=pytest.mark.slow)])
def test_version_bump_gives_new_entry(cache, monkeypatch, target):
    """After an upgrade the old entry is not used: a new module file (new key) is built and imported."""
    (old,) = _rhs_modules(cache)
    if target == "python":
        monkeypatch.setattr(sys, "version", sys.version + " (upgraded)")
    else:
        module = __import__(target)
        monkeypatch.setattr(module, "__version__", module.__version__ + ".post1")
    model = _compile()
    modules = _rhs_modules(cache)
    assert len(modules) == 2 and old in modules
    new = next(m for m in modules if m != old)
    assert model.dynamics.py_func.__globals__["__file__"].endswith(new.stem + ".py")
    assert model.dynamics.stats.cache_misses and not model.dynamics.stats.cache_hits
    assert np.allclose(model.fun(0.0, Y), _reference(), rtol=1e-12, atol=1e-12)


def test_changed_model_gets_new_entry(cache):
    """A different model (here: one link instead of two) never reuses the two-link entry."""
    one = n_link_pendulum(1).compile({"g": 9.81}, backend="numba")
    assert len(_rhs_modules(cache)) == 2
    y1 = np.array([0.3, -0.2])
    ref = n_link_pendulum(1).compile({"g": 9.81}, backend="reference").fun(0.0, y1)
    assert np.allclose(one.fun(0.0, y1), ref, rtol=1e-12, atol=1e-12)


def _build_in_process(args):
    cache_dir, barrier = args
    import os

    os.environ["LAGRANGE_CACHE_DIR"] = cache_dir
    from lagrange.examples import n_link_pendulum as nlp

    system = nlp(2)
    system.derived  # derive before the barrier, so the builds really overlap  # noqa: B018
    barrier.wait(timeout=120)
    model = system.compile({"g": 9.81}, backend="numba")
    return list(model.fun(0.0, np.array([0.3, -0.2, 0.1, 0.4])))


def _concurrent_builds(cache, n: int, method: str) -> None:
    ctx = mp.get_context(method)
    with ctx.Manager() as manager:
        barrier = manager.Barrier(n)
        with ctx.Pool(n) as pool:
            results = pool.map(_build_in_process, [(str(cache), barrier)] * n)
    ref = _reference()
    for r in results:
        assert np.allclose(r, ref, rtol=1e-12, atol=1e-12)
    (module,) = _rhs_modules(cache)
    assert not list(cache.glob(".*.tmp"))
    assert lc.read_verified(module) is not None
    _forget_loaded_modules()
    assert np.array_equal(_compile().fun(0.0, Y), np.array(results[0]))


@pytest.mark.skipif("fork" not in mp.get_all_start_methods(), reason="needs the fork start method")
def test_concurrent_builders_all_succeed(empty_cache):
    """Several processes build the same model into an empty cache at the same moment: all succeed with
    the same result and the cache entry is complete (no temporary files left)."""
    _concurrent_builds(empty_cache, 4, "fork")


@pytest.mark.slow
def test_concurrent_builders_fresh_interpreters(empty_cache):
    """The same with 8 freshly started interpreters (spawn): nothing shared but the directory."""
    _concurrent_builds(empty_cache, 8, "spawn")


def _writer(args):
    path, text, rounds = args
    from pathlib import Path

    from lagrange.codegen.cache import atomic_write

    for _ in range(rounds):
        atomic_write(Path(path), text)
    return True


def _reader(args):
    path, texts, rounds = args
    from pathlib import Path

    seen = 0
    for _ in range(rounds):
        try:
            content = Path(path).read_text()
        except FileNotFoundError:
            continue
        assert content in texts, f"partial file seen ({len(content)} characters)"
        seen += 1
    return seen


def test_concurrent_writes_are_atomic(tmp_path):
    """Writers keep replacing one entry with long texts while readers read it: a reader only ever sees
    one complete text (a plain ``open(path, 'w').write`` fails this test)."""
    path = tmp_path / "entry.py"
    texts = ["# a\n" + "a = 1\n" * 200_000, "# b\n" + "b = 2\n" * 150_000]
    ctx = mp.get_context("fork") if "fork" in mp.get_all_start_methods() else mp.get_context()
    with ctx.Pool(4) as pool:
        jobs = [pool.apply_async(_writer, ((path, texts[i % 2], 30),)) for i in range(2)]
        jobs += [pool.apply_async(_reader, ((path, texts, 300),)) for _ in range(2)]
        out = [j.get(timeout=120) for j in jobs]
    assert out[2] + out[3] > 0
    assert path.read_text() in texts
    assert not list(tmp_path.glob(".*.tmp"))
