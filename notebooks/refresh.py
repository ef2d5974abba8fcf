"""Execute the notebooks and store their outputs, small and with stable diffs.

Usage (from the repository root, with lagrange importable)::

    python notebooks/refresh.py                 # every notebooks/*.ipynb
    python notebooks/refresh.py 08_hamilton     # some of them (name with or without .ipynb)
    python notebooks/refresh.py --dry-run       # execute and report timings, write nothing

Each notebook runs in a fresh kernel from the ``notebooks/`` folder. A hidden first cell (removed before
writing) makes inline figures small: PNG at :data:`DPI` dpi. After the run, execution counts, per-cell
timings and kernel-specific metadata are stripped so that re-running an unchanged notebook changes
nothing but the pixels of its figures. The time of every cell is printed, the slowest first; a cell over
:data:`SLOW_CELL` seconds or a notebook over :data:`MAX_BYTES` bytes is reported as a problem and the
exit status is 1 (the notebook is still written, so you can look at it).

:func:`structure` is the shape of a notebook's outputs that ``tests/test_notebooks.py`` compares between
the stored file and a fresh run.
"""

from __future__ import annotations

import argparse
import sys
import time
from datetime import datetime
from pathlib import Path

import nbformat
from nbclient import NotebookClient

HERE = Path(__file__).resolve().parent
DPI = 60  # inline figure resolution of the stored outputs
SLOW_CELL = 20.0  # seconds: a cell slower than this is a problem
MAX_BYTES = 1_000_000  # a stored notebook larger than this is a problem

SETUP = f"""%matplotlib inline
%config InlineBackend.figure_formats = ["png"]
import matplotlib
matplotlib.rcParams["figure.dpi"] = {DPI}
"""

__all__ = ["notebooks", "execute", "strip", "structure", "refresh", "main"]


def notebooks(names: list[str] | None = None) -> list[Path]:
    """The notebook files: all of ``notebooks/*.ipynb``, or those named (with or without ``.ipynb``)."""
    if not names:
        return sorted(HERE.glob("*.ipynb"))
    paths = []
    for name in names:
        p = HERE / (name if name.endswith(".ipynb") else name + ".ipynb")
        if not p.exists():
            raise SystemExit(f"no notebook {p.name} in {HERE}")
        paths.append(p)
    return paths


def execute(path: Path, *, timeout: int = 600, small_figures: bool = True):
    """Run a notebook in a fresh kernel from its folder; returns (executed notebook, seconds per code cell).

    ``small_figures`` runs :data:`SETUP` first (inline PNG at :data:`DPI` dpi) in a hidden cell."""
    nb = nbformat.read(path, as_version=4)
    hidden = nbformat.v4.new_code_cell(SETUP) if small_figures else None
    if hidden is not None:
        nb.cells.insert(0, hidden)
    client = NotebookClient(nb, timeout=timeout, kernel_name="python3", record_timing=True,
                            resources={"metadata": {"path": str(path.parent)}})
    client.execute()
    if hidden is not None:
        nb.cells.pop(0)
    seconds = []
    for i, cell in enumerate(nb.cells):
        if cell.cell_type != "code":
            continue
        timing = cell.get("metadata", {}).get("execution", {})
        start, end = timing.get("iopub.execute_input"), timing.get("shell.execute_reply")
        if start and end:
            dt = (datetime.fromisoformat(end.replace("Z", "+00:00"))
                  - datetime.fromisoformat(start.replace("Z", "+00:00"))).total_seconds()
            seconds.append((i, dt))
    return nb, seconds


def strip(nb) -> None:
    """Remove what changes from run to run without a change of content: execution counts, timings,
    the kernel's language version."""
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        cell.execution_count = None
        cell.metadata.pop("execution", None)
        for out in cell.get("outputs", []):
            if "execution_count" in out:
                out["execution_count"] = None
            out.get("metadata", {}).pop("execution", None)
    lang = nb.metadata.get("language_info")
    if lang is not None:
        lang.pop("version", None)


def structure(nb) -> list[tuple]:
    """Per code cell, the kinds of its outputs: ``("stream", "stdout")``, or the output type with its sorted
    MIME types. Warnings and progress bars on stderr are left out (they depend on caches and extras), and
    consecutive stdout chunks count as one."""
    shape = []
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        kinds: list[tuple] = []
        for out in cell.get("outputs", []):
            if out["output_type"] == "stream":
                if out.get("name") != "stdout":
                    continue
                kind = ("stream", "stdout")
                if kinds and kinds[-1] == kind:
                    continue
            elif out["output_type"] == "error":
                kind = ("error", out.get("ename", ""))
            else:
                kind = (out["output_type"], *sorted(out.get("data", {})))
            kinds.append(kind)
        shape.append(tuple(kinds))
    return shape


def refresh(path: Path, *, write: bool = True) -> list[str]:
    """Execute, strip and (unless ``write`` is false) store one notebook; returns the problems found."""
    t0 = time.perf_counter()
    nb, seconds = execute(path)
    total = time.perf_counter() - t0
    strip(nb)
    text = nbformat.writes(nb) + "\n"
    problems = []
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", []) if o.output_type == "error"]
    if errors:
        problems.append(f"{path.name}: {len(errors)} error output(s): {errors[0].get('ename')}")
    slow = sorted(seconds, key=lambda s: -s[1])
    print(f"{path.name}: {total:.1f} s in all, {len(text.encode()) / 1e3:.0f} kB; slowest cells: "
          + ", ".join(f"#{i} {dt:.1f} s" for i, dt in slow[:3]))
    problems += [f"{path.name}: cell #{i} took {dt:.1f} s (> {SLOW_CELL:g} s)" for i, dt in slow if dt > SLOW_CELL]
    if len(text.encode()) > MAX_BYTES:
        problems.append(f"{path.name}: {len(text.encode()) / 1e6:.2f} MB stored (> {MAX_BYTES / 1e6:g} MB)")
    if write:
        path.write_text(text, encoding="utf-8")
    return problems


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("names", nargs="*", help="notebooks to refresh (default: all)")
    parser.add_argument("--dry-run", action="store_true", help="execute and report, write nothing")
    args = parser.parse_args(argv)
    problems = []
    for path in notebooks(args.names):
        problems += refresh(path, write=not args.dry_run)
    for p in problems:
        print("PROBLEM:", p, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
