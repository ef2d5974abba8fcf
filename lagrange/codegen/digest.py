"""Digests and MACs of the on-disk caches: BLAKE2b, plain for keys and keyed for authentication tags.

BLAKE2b (RFC 7693) is both: a cryptographic hash, and, with a secret key, a MAC (its keyed mode is the
construction its designers give as a replacement for HMAC). It is taken from CPython's built-in ``_blake2``
module, the very implementation ``hashlib.blake2b`` hands out: importing :mod:`hashlib` (or :mod:`hmac`,
or :mod:`secrets`) loads OpenSSL's libcrypto, about 7 million instructions on every warm re-run of a model
(``perf stat``; lagrange's own work on a re-run of a top is about 130 million). When ``_blake2`` is absent
(another Python implementation), the public :mod:`hashlib` and :mod:`hmac` are used: the same digests, only
the import costs more.

>>> hexdigest(b"abc", size=8)
'd8bb14d833d59559'
>>> len(mac(b"k" * 32, b"data"))
64
"""

from __future__ import annotations

try:  # CPython's own BLAKE2 (what hashlib.blake2b is), without hashlib's OpenSSL load
    from _blake2 import blake2b
except ImportError:  # pragma: no cover - other interpreters
    from hashlib import blake2b
try:  # constant-time comparison (as hmac.compare_digest), without hmac's OpenSSL load
    from _operator import _compare_digest as compare_digest
except ImportError:  # pragma: no cover - other interpreters
    from hmac import compare_digest

__all__ = ["blake2b", "compare_digest", "hasher", "hexdigest", "mac"]

#: digest size in bytes (256 bits, the strength of the SHA-256 it replaces)
SIZE = 32


def hasher(data: bytes = b"", *, size: int = SIZE):
    """An incremental BLAKE2b of ``size`` bytes (``update`` / ``digest`` / ``hexdigest``)."""
    return blake2b(data, digest_size=size)


def hexdigest(data: bytes, *, size: int = SIZE) -> str:
    """BLAKE2b of ``data``, ``size`` bytes, as ``2 * size`` hex digits."""
    return blake2b(data, digest_size=size).hexdigest()


def mac(key: bytes, data: bytes) -> bytes:
    """Keyed BLAKE2b (the MAC) of ``data`` under ``key`` (at most 64 bytes), as hex digits in bytes."""
    if not 0 < len(key) <= 64:
        raise ValueError(f"a BLAKE2b key has 1 to 64 bytes, not {len(key)}")
    return blake2b(data, key=key, digest_size=SIZE).hexdigest().encode()
