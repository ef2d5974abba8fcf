"""Every notebook under notebooks/ executes without error (they carry their own assertions), and the outputs
stored in it (refreshed by ``python notebooks/refresh.py``) have the structure of a fresh run: the same code
cells have outputs, of the same kinds. Pixels and numbers are not compared."""

import importlib.util
import sys
from pathlib import Path

import nbformat
import pytest

FOLDER = Path(__file__).parent.parent / "notebooks"
NOTEBOOKS = sorted(FOLDER.glob("*.ipynb"))


def _refresh_module():
    spec = importlib.util.spec_from_file_location("notebooks_refresh", FOLDER / "refresh.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules.setdefault(spec.name, module)
    spec.loader.exec_module(module)
    return module


refresh = _refresh_module()


#: executed in the default run; the others run in the slow set (CI runs both): executing all eleven costs
#: about 4 CPU-minutes, a third of the default run
QUICK = {"01_quickstart.ipynb"}
EXECUTED = [pytest.param(p, id=p.name, marks=() if p.name in QUICK else pytest.mark.slow) for p in NOTEBOOKS]


@pytest.mark.parametrize("path", EXECUTED)
def test_notebook_executes_and_matches_its_stored_outputs(path):
    stored = nbformat.read(path, as_version=4)
    # run from notebooks/ (relative paths to the shipped data), with the same small-figure setup as refresh.py
    fresh, _ = refresh.execute(path)
    errors = [o for c in fresh.cells if c.cell_type == "code" for o in c.get("outputs", []) if o.output_type == "error"]
    assert not errors, f"{path.name}: {errors[0].get('ename')}: {errors[0].get('evalue')}"
    hint = f"stored outputs of {path.name} are out of date: run `python notebooks/refresh.py {path.stem}`"
    assert len(stored.cells) == len(fresh.cells)
    old, new = refresh.structure(stored), refresh.structure(fresh)
    for k, (a, b) in enumerate(zip(old, new)):
        assert a == b, f"{hint} (code cell {k}: stored {a}, fresh run {b})"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_stored_notebook_is_small_stable_and_self_contained(path):
    text = path.read_text(encoding="utf-8")
    assert len(text.encode()) < refresh.MAX_BYTES, f"{path.name} is over {refresh.MAX_BYTES / 1e6:g} MB"
    nb = nbformat.reads(text, as_version=4)
    code = [c for c in nb.cells if c.cell_type == "code"]
    assert any(c.get("outputs") for c in code), f"{path.name} has no stored outputs: run notebooks/refresh.py"
    for c in code:  # volatile metadata stripped (stable diffs)
        assert c.execution_count is None and "execution" not in c.metadata
        assert all(o.get("execution_count") is None for o in c.get("outputs", []))
        assert "../benchmarks" not in c.source and '"benchmarks"' not in c.source, f"{path.name} reads ../benchmarks"


def test_structure_sees_a_missing_or_changed_output():
    """The comparison can fail: a cell that lost its figure, or printed instead of displaying, differs."""
    cell = nbformat.v4.new_code_cell("x")
    cell.outputs = [nbformat.v4.new_output("stream", name="stdout", text="a"),
                    nbformat.v4.new_output("stream", name="stdout", text="b"),
                    nbformat.v4.new_output("stream", name="stderr", text="warning"),
                    nbformat.v4.new_output("display_data", data={"image/png": "", "text/plain": ""})]
    nb = nbformat.v4.new_notebook(cells=[cell])
    assert refresh.structure(nb) == [(("stream", "stdout"), ("display_data", "image/png", "text/plain"))]
    cell.outputs = cell.outputs[:3]
    assert refresh.structure(nb) == [(("stream", "stdout"),)]


def test_an_inline_animation_is_stored():
    """The quick start stores an animation player: HTML output with its frames embedded as PNG."""
    nb = nbformat.read(FOLDER / "01_quickstart.ipynb", as_version=4)
    players = [o["data"]["text/html"] for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
               if "text/html" in o.get("data", {}) and "Animation" in o["data"]["text/html"]]
    assert len(players) == 1 and players[0].count("data:image/png;base64") >= 20


def test_quickstart_exists():
    assert any(p.name == "01_quickstart.ipynb" for p in NOTEBOOKS)
