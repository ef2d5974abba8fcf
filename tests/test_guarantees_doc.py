"""The counts quoted in docs/guarantees.md are the ones the test suite actually uses."""

import importlib.util
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DOC = (ROOT / "docs" / "guarantees.md").read_text(encoding="utf-8")


def _module(rel: str):
    spec = importlib.util.spec_from_file_location(rel.replace("/", "_")[:-3], ROOT / rel)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _quoted(pattern: str) -> int:
    m = re.search(pattern, DOC)
    assert m, f"docs/guarantees.md no longer states {pattern!r}"
    return int(m.group(1).replace(",", ""))


def test_hostile_input_count():
    hostile = _module("tests/spec/test_hostile.py")
    spec = _module("tests/spec/test_spec.py")
    n_expr, n_toml, n_old = len(hostile.HOSTILE_EXPRESSIONS), len(hostile.HOSTILE_TOML), len(spec.HOSTILE)
    assert _quoted(r"\*\*(\d+) hostile inputs\*\*") == n_expr + n_toml + n_old
    assert _quoted(r"(\d+) expressions \+") == n_expr
    assert _quoted(r"\+ (\d+) TOML files") == n_toml


def test_property_and_fault_counts():
    props = _module("tests/test_properties.py")
    assert _quoted(r"\*\*(\d+) random systems\*\*") == props.SYSTEM_EXAMPLES
    assert _quoted(r"\*\*(\d+) random malformed declarations\*\*") == props.MALFORMED_EXAMPLES
    assert _quoted(r"from (\d+) kinds of fault") == len(props.MALFORMED_KINDS)
    assert _quoted(r"feeds (\d+) random strings") == props.FUZZ_EXAMPLES
    assert _quoted(r"\*\*(\d+) injected faults\*\*") == _module("tests/numerics/test_faults.py").N_FAULTS
    assert _quoted(r"\*\*(\d+) scenarios\*\*") == _module("tests/test_cache.py").CACHE_SCENARIOS
    assert _quoted(r"\*\*(\d+) integrity scenarios\*\*") == _module("tests/test_cache_integrity.py").INTEGRITY_SCENARIOS
    assert _quoted(r"\*\*(\d+) entry points\*\*") == _module("tests/test_no_string_eval.py").CANARY_ENTRIES
    derivation = _module("tests/test_derivation_cache.py")
    assert _quoted(r"\*\*(\d+) derivation-cache scenarios\*\*") == derivation.DERIVATION_CACHE_SCENARIOS
    assert _quoted(r"\* (\d+) declared changes") == len(derivation.CHANGES)
    assert _quoted(r"\* (\d+) kinds of damage to each kind of entry") == len(derivation.DAMAGES)


def test_readme_cache_and_string_counts():
    """The README's guarantee table quotes the same cache, integrity and canary counts as the tests."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")

    def quoted(pattern: str) -> int:
        m = re.search(pattern, readme)
        assert m, f"README.md no longer states {pattern!r}"
        return int(m.group(1))

    assert quoted(r"\| (\d+) cache scenarios") == _module("tests/test_cache.py").CACHE_SCENARIOS
    assert quoted(r"\| (\d+) integrity scenarios") == _module("tests/test_cache_integrity.py").INTEGRITY_SCENARIOS
    assert quoted(r"\| (\d+) entry points") == _module("tests/test_no_string_eval.py").CANARY_ENTRIES
