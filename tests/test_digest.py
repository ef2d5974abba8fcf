"""The caches' digests (lagrange.codegen.digest) against the standard library's hashlib and hmac."""

import hashlib
import hmac

import pytest

from lagrange.codegen import digest


@pytest.mark.parametrize("data", [b"", b"abc", bytes(range(256)) * 40])
def test_digests_are_hashlibs_blake2b(data):
    assert digest.hexdigest(data) == hashlib.blake2b(data, digest_size=32).hexdigest()
    assert digest.hexdigest(data, size=12) == hashlib.blake2b(data, digest_size=12).hexdigest()
    h = digest.hasher(data[:7])
    h.update(data[7:])
    assert h.hexdigest() == hashlib.blake2b(data, digest_size=32).hexdigest()


def test_mac_is_keyed_blake2b_and_depends_on_key_and_data():
    key = bytes(range(32))
    tag = digest.mac(key, b"entry")
    assert tag == hashlib.blake2b(b"entry", key=key, digest_size=32).hexdigest().encode()
    assert tag != digest.mac(bytes(32), b"entry")
    assert tag != digest.mac(key, b"entrY")
    assert tag != digest.hexdigest(b"entry").encode()  # keyed, not a plain digest
    for bad in (b"", bytes(65)):
        with pytest.raises(ValueError, match="BLAKE2b key"):
            digest.mac(bad, b"entry")


def test_compare_digest_agrees_with_hmac():
    for a, b in [(b"ab", b"ab"), (b"ab", b"ac"), (b"ab", b"abc"), (b"", b"")]:
        assert digest.compare_digest(a, b) == hmac.compare_digest(a, b)
