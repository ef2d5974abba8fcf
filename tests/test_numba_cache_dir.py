"""Numba's cache folder under ``$NUMBA_CACHE_DIR`` (lagrange.codegen.numba_backend.private_numba_folder): its
name is predictable, so another user could make it first and plant an index that numba unpickles. The
directory falls under the cache directory's rules and the folder must be this user's own private directory;
a planted index (a pickle whose loading creates a canary file) is never loaded, and never sealed into the
bundle a later run would unpack.
"""

from __future__ import annotations

import os
import pickle
import sys

import numpy as np
import pytest

from lagrange.codegen import cache as lc
from lagrange.errors import CacheError

numba = pytest.importorskip("numba")


class _Touch:
    def __init__(self, path):
        self.path = str(path)

    def __reduce__(self):
        return (os.system, (f"touch {self.path}",))


def _forget(nb) -> None:
    for name in [k for k in sys.modules if k.startswith("lagrange_rhs_")]:
        sys.modules.pop(name)
    for path in [p for p in nb._STAGED if p.stem.startswith("rhs_")]:
        nb.purge_numba_cache("", path)
        nb._STAGED.pop(path)


def _build(y):
    from lagrange.examples import n_link_pendulum

    model = n_link_pendulum(2).compile({"g": 9.81}, backend="numba")
    return model, model.fun(0.0, y)


@pytest.fixture
def module(tmp_path, monkeypatch):
    """The two-link pendulum's module built once in a scratch cache: numba_backend, the module's stem, the
    names of the index files numba wrote for it, a state and the rhs there. Then a fresh cache, so the next
    build compiles (nothing to unpack) and numba looks for its index in the folder."""
    from lagrange.codegen import numba_backend as nb

    monkeypatch.delenv(lc.TRUST_VAR, raising=False)
    monkeypatch.setattr(lc, "_warned", False)
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path / "scratch"))
    monkeypatch.setattr(numba.core.config, "CACHE_DIR", "")
    _forget(nb)
    y = np.array([0.3, -0.2, 0.1, 0.4])
    model, values = _build(y)
    stem = model.dynamics.py_func.__module__.removeprefix("lagrange_")
    bundle = lc.read_verified(tmp_path / "scratch" / f"{stem}.numba")
    index = [name for name, _ in nb._unpack(bundle, stem) if name.endswith(".nbi")]
    assert index
    _forget(nb)
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path / "fresh"))
    yield nb, stem, index, y, values
    _forget(nb)


def _plant(nb, stem, index, shared, canary, *, folder_mode=0o700, owner=None, link=None):
    """Make the folder numba will use for ``stem`` under ``shared`` and put a code-running index in it."""
    folder = nb.numba_cache_folder(nb._stage_dir() / f"{stem}.py")
    assert folder.parent == shared
    target = link if link is not None else folder
    target.mkdir(parents=True, exist_ok=True)
    for name in index:
        (target / name).write_bytes(pickle.dumps(_Touch(canary)))
    if link is not None:
        folder.symlink_to(link, target_is_directory=True)
    os.chmod(target, folder_mode)
    if owner is not None:
        for p in [target, *target.iterdir()]:
            os.chown(p, owner, owner)
    return folder


def _use(monkeypatch, shared):
    monkeypatch.setattr(numba.core.config, "CACHE_DIR", str(shared))


def test_private_numba_cache_dir_is_used(module, tmp_path, monkeypatch):
    """Quiet side: a private $NUMBA_CACHE_DIR works, the folder is made private, and what numba cached is
    sealed into the bundle."""
    nb, stem, index, y, values = module
    shared = tmp_path / "numba"
    _use(monkeypatch, shared)
    model, again = _build(y)
    assert np.array_equal(again, values)
    folder = nb.numba_cache_folder(nb._stage_dir() / f"{stem}.py")
    assert folder.parent == shared and oct(os.lstat(folder).st_mode & 0o777) == oct(0o700)
    assert lc.read_verified(lc.cache_dir() / f"{stem}.numba") is not None


@pytest.mark.parametrize("state", ["others_writable", "foreign_owned"])
def test_shared_numba_cache_dir_is_refused(module, tmp_path, monkeypatch, state):
    """A $NUMBA_CACHE_DIR writable by others, or owned by another uid, is refused before numba reads the
    index planted in it."""
    if state == "foreign_owned" and os.geteuid() != 0:
        pytest.skip("simulating another user's directory needs chown (root)")
    nb, stem, index, y, values = module
    canary = tmp_path / "canary"
    shared = tmp_path / "numba"
    shared.mkdir()
    _use(monkeypatch, shared)
    _plant(nb, stem, index, shared, canary)
    if state == "others_writable":
        os.chmod(shared, 0o777)
    else:
        os.chmod(shared, 0o755)
        os.chown(shared, 12345, 12345)
    with pytest.raises(CacheError, match="NUMBA_CACHE_DIR"):
        _build(y)
    assert not canary.exists()


@pytest.mark.parametrize("attack", ["foreign_folder", "open_folder", "symlinked_folder"])
def test_planted_folder_is_refused_even_when_trusted(module, tmp_path, monkeypatch, attack):
    """With the shared directory accepted on purpose ($LAGRANGE_CACHE_TRUST=1), the module's own folder is
    still forced private: one made by another uid, open to others, or a symbolic link to another directory
    is refused, and its planted index never runs."""
    if attack == "foreign_folder" and os.geteuid() != 0:
        pytest.skip("simulating another user's folder needs chown (root)")
    nb, stem, index, y, values = module
    canary = tmp_path / "canary"
    shared = tmp_path / "numba"
    shared.mkdir(mode=0o1777)
    os.chmod(shared, 0o1777)
    monkeypatch.setenv(lc.TRUST_VAR, "1")
    kwargs = {"foreign_folder": {"owner": 12345, "folder_mode": 0o755}, "open_folder": {"folder_mode": 0o777},
              "symlinked_folder": {"link": tmp_path / "elsewhere"}}[attack]
    _use(monkeypatch, shared)
    _plant(nb, stem, index, shared, canary, **kwargs)
    with pytest.raises(CacheError, match="numba cache folder"):
        _build(y)
    assert not canary.exists()


def test_planted_index_in_own_folder_is_deleted_not_loaded(module, tmp_path, monkeypatch):
    """An index found in the module's (private) folder before the module runs did not come from its sealed
    bundle: it is deleted, numba compiles, and the bundle sealed afterwards holds no planted bytes, so a later
    run without $NUMBA_CACHE_DIR never loads it either."""
    nb, stem, index, y, values = module
    canary = tmp_path / "canary"
    shared = tmp_path / "numba"
    shared.mkdir(mode=0o700)
    _use(monkeypatch, shared)
    _plant(nb, stem, index, shared, canary)
    model, again = _build(y)
    assert np.array_equal(again, values) and not canary.exists()
    sealed = lc.read_verified(lc.cache_dir() / f"{stem}.numba")
    assert sealed is not None and b"touch" not in sealed
    _forget(nb)
    monkeypatch.setattr(numba.core.config, "CACHE_DIR", "")
    model, again = _build(y)
    assert np.array_equal(again, values) and not canary.exists()
