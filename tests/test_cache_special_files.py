"""Special files in the cache directory (lagrange.codegen.cache): a FIFO, a device or a symbolic link found
under an entry's name is never opened for reading (it would block every run, or never end); the entry is
treated as damaged and rebuilt. Each run here is a child process with a timeout, so a hang fails the test
instead of stopping the suite.
"""

from __future__ import annotations

import math
import os
import subprocess
import sys

import pytest

from lagrange.codegen import cache as lc

pytestmark = pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs FIFOs (POSIX)")

_RUN = """
import lagrange as lg, numpy as np
from lagrange import t
x = lg.coordinates("x")
m, k = lg.parameters("m k")
s = lg.System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2)
traj = s.simulate(0.5, {"x": 0.1, "x_dot": 0.0}, {"m": 1.0, "k": 4.0}, backend="python", rtol=1e-10, atol=1e-12)
print(repr(float(traj.y[-1, 0])))
"""


def _run(cache, timeout=240):
    env = dict(os.environ, LAGRANGE_CACHE_DIR=str(cache), LAGRANGE_DERIVATION_CACHE="1")
    env.pop(lc.TRUST_VAR, None)
    return subprocess.run([sys.executable, "-c", _RUN], env=env, capture_output=True, text=True, timeout=timeout)


def test_fifos_under_every_entry_name_do_not_block_a_run(tmp_path):
    """A run fills a cache; a second cache holds a FIFO under each of those entry names (and a link to one):
    a run there ends, with the oscillator's closed form, and rebuilds its entries."""
    first = _run(tmp_path / "a")
    assert first.returncode == 0, first.stderr[-2000:]
    names = [p.name for p in (tmp_path / "a").iterdir() if p.name != lc.SECRET_NAME and not p.name.startswith(".")]
    assert names
    planted = tmp_path / "b"
    planted.mkdir(mode=0o700)
    for name in names[1:]:
        os.mkfifo(planted / name)
    os.symlink(tmp_path / "a" / names[0], planted / names[0])
    again = _run(planted)
    assert again.returncode == 0, again.stderr[-2000:]
    assert float(again.stdout.split()[-1]) == pytest.approx(0.1 * math.cos(2 * 0.5), rel=1e-7)
    assert "CacheIntegrityWarning" in again.stderr or "ignored the cache entry" in again.stderr


def test_fifo_as_the_key_is_a_clear_error(tmp_path):
    """A FIFO where the per-user key belongs: a CacheError naming it, at once, not a run that waits for a
    writer."""
    root = tmp_path / "c"
    root.mkdir(mode=0o700)
    os.mkfifo(root / lc.SECRET_NAME)
    done = _run(root, timeout=120)
    assert done.returncode != 0 and "CacheError" in done.stderr and "not a regular file" in done.stderr


def test_read_verified_never_opens_a_fifo_for_long(tmp_path, monkeypatch):
    """In process: read_verified and verify answer None / False for a FIFO entry (opened without blocking)."""
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path / "d"))
    monkeypatch.setattr(lc, "_warned", True)  # (the warning itself is checked above)
    entry = lc.cache_dir() / "entry.bin"
    os.mkfifo(entry)
    assert lc.read_verified(entry) is None and lc.verify(entry) is False
    lc.write_sealed(tmp_path / "d" / "ok.bin", b"payload")  # the quiet side: a regular entry still reads back
    assert lc.read_verified(tmp_path / "d" / "ok.bin") == b"payload"
