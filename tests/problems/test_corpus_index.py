"""The committed corpus index (problems/_index.json) matches the problem modules.

If this fails, run ``python -m lagrange.corpus.index --write`` and commit problems/_index.json.
"""

import pytest

from lagrange.corpus import index


def test_index_is_fresh_for_every_module_file():
    # a SHA-256 per module file: an edited, added or removed module makes the index stale
    assert index.stale_modules() == [], "run `python -m lagrange.corpus.index --write`"


def test_index_entries_are_consistent():
    data = index.load_index()
    ids = [e["id"] for e in data["problems"]]
    assert len(ids) == len(set(ids)) > 300
    assert {e["module"] for e in data["problems"]} <= set(data["modules"])
    assert [e["number"] for e in data["greenspan"]] == list(range(1, 15))
    assert index.find("EX3.2")["module"] == "ch03_ex3_2"
    assert index.suggestions("ex3.44")[0] == "ex3.4"


def test_stale_index_is_detected(tmp_path):
    folder = index.index_path().parent
    (tmp_path / "ch99_new.py").write_text("x = 1\n")
    for name in list(index.load_index()["modules"])[:3]:
        (tmp_path / f"{name}.py").write_bytes((folder / f"{name}.py").read_bytes())
    stale = index.stale_modules(tmp_path)
    assert "ch99_new" in stale  # added
    assert len(stale) == len(index.load_index()["modules"]) - 3 + 1  # every other module counts as removed


@pytest.mark.slow
def test_index_equals_what_importing_the_modules_yields():
    built = index.build_index()
    assert built == index.load_index()
