"""The corpus index: every problem's id, title, chapter and module, read without importing the corpus.

Importing the 350-odd problem modules builds every System (tens of seconds); ``lagrange problems``,
"did you mean" and the lookup of one id read ``problems/_index.json`` instead (milliseconds, no sympy).
The index is generated from the modules and committed::

    python -m lagrange.corpus.index --write     # after adding, removing or editing a problem module
    python -m lagrange.corpus.index --check     # exit 1 when the index is stale

It records a SHA-256 of every module file, so :func:`stale_modules` notices an edited, added or removed
module without importing anything (``tests/problems/test_corpus_index.py`` runs it; a slow test also
rebuilds the index by importing every module and compares).

Index format (JSON): ``{"version": 1, "problems": [{"id", "title", "chapter", "source", "module",
"system", "dynamics", "answers" (how many), "correction" (a misprint is recorded)}, …],
"modules": {module name: sha256}, "greenspan": [{"number", "V", "alpha_deg", "masses"}, …]}``;
problems in corpus order (chapter, then the numbers in the id).
"""

from __future__ import annotations

import argparse
import difflib
import hashlib
import importlib.util
import json
import sys
from functools import lru_cache
from pathlib import Path

from ..errors import SpecError

__all__ = ["IndexEntry", "index_path", "load_index", "entries", "find", "suggestions", "unknown_id_error",
           "greenspan_examples", "build_index", "write_index", "stale_modules", "main"]

PACKAGE = "lagrange_problems"
INDEX_NAME = "_index.json"
VERSION = 1

IndexEntry = dict  # {"id", "title", "chapter", "source", "module", "system", "dynamics", "answers", "correction"}


def _package_dir() -> Path:
    spec = importlib.util.find_spec(PACKAGE)
    if spec is None or not spec.submodule_search_locations:
        raise SpecError(f"the problem corpus ({PACKAGE}) is not installed: reinstall lagrange-dynamics")
    return Path(next(iter(spec.submodule_search_locations)))


def index_path() -> Path:
    """Where the index lives: ``_index.json`` in the corpus package."""
    return _package_dir() / INDEX_NAME


def _module_files(folder: Path) -> dict[str, Path]:
    return {p.stem: p for p in sorted(folder.glob("*.py")) if not p.stem.startswith("_")}


def _digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


@lru_cache(maxsize=1)
def load_index() -> dict:
    """The committed index (parsed once per process)."""
    path = index_path()
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise SpecError(f"the corpus index {path} is missing: run `python -m lagrange.corpus.index --write`") from None
    except (OSError, ValueError) as exc:
        raise SpecError(f"the corpus index {path} is unreadable ({exc}): run "
                        "`python -m lagrange.corpus.index --write`") from None
    if data.get("version") != VERSION:
        raise SpecError(f"the corpus index {path} has version {data.get('version')!r}, expected {VERSION}: run "
                        "`python -m lagrange.corpus.index --write`")
    return data


def entries(chapter: int | None = None) -> list[IndexEntry]:
    """The index entries (of one chapter), in corpus order."""
    return [e for e in load_index()["problems"] if chapter is None or e["chapter"] == chapter]


def find(problem_id: str) -> IndexEntry | None:
    """The entry with this id (case-insensitive), or None."""
    key = problem_id.strip().lower()
    return next((e for e in load_index()["problems"] if e["id"].lower() == key), None)


def suggestions(problem_id: str, n: int = 5) -> list[str]:
    """Ids close to a mistyped one (difflib), best first."""
    ids = [e["id"] for e in load_index()["problems"]]
    by_lower = {i.lower(): i for i in ids}
    return [by_lower[m] for m in difflib.get_close_matches(problem_id.strip().lower(), list(by_lower), n=n)]


def unknown_id_error(problem_id: str) -> SpecError | None:
    """The error for an id the index does not know (with "did you mean"), or None when the index knows it
    or is stale (then only importing the corpus can tell)."""
    if find(problem_id) is not None or stale_modules():
        return None
    close = suggestions(problem_id)
    hint = f"; did you mean {', '.join(close)}?" if close else "; run `lagrange problems` for the list"
    return SpecError(f"no problem with id {problem_id!r}{hint}")


def greenspan_examples() -> list[dict]:
    """Greenspan's 14 examples of the tetrahedral top ({number, V, alpha_deg, masses})."""
    return list(load_index()["greenspan"])


def stale_modules(folder: Path | None = None) -> list[str]:
    """Modules whose file differs from the index (edited, added or removed), without importing them."""
    folder = folder or _package_dir()
    files = _module_files(folder)
    recorded = load_index()["modules"]
    changed = [name for name, path in files.items() if recorded.get(name) != _digest(path)]
    return sorted(changed + [name for name in recorded if name not in files])


def build_index(folder: Path | None = None) -> dict:
    """Import every corpus module and build the index (what ``--write`` stores)."""
    from ..discrete.greenspan import EXAMPLES
    from .modules import _module_problems, _sort_key

    folder = folder or _package_dir()
    files = _module_files(folder)
    found = []
    for name in files:
        for p in _module_problems(name):
            found.append((p, name))
    ids = [p.id for p, _ in found]
    dups = sorted({i for i in ids if ids.count(i) > 1})
    if dups:
        raise SpecError(f"problem id(s) {', '.join(dups)} defined twice in the corpus")
    found.sort(key=lambda pn: _sort_key(pn[0]))
    problems = [{"id": p.id, "title": p.title, "chapter": int(p.chapter), "source": p.source, "module": name,
                 "system": p.system is not None, "dynamics": p.simulation is not None,
                 "answers": len(p.answers), "correction": bool(p.correction)} for p, name in found]
    greenspan = [{"number": ex.number, "V": float(ex.V), "alpha_deg": float(ex.alpha_deg),
                  "masses": [float(m) for m in ex.masses]} for ex in EXAMPLES.values()]
    return {"version": VERSION, "problems": problems, "modules": {n: _digest(p) for n, p in files.items()},
            "greenspan": greenspan}


def _dump(data: dict) -> str:
    return json.dumps(data, indent=1, ensure_ascii=False, sort_keys=False) + "\n"


def write_index(path: Path | None = None) -> Path:
    """Rebuild the index and write it (atomically enough for a committed file: write then rename)."""
    path = path or index_path()
    text = _dump(build_index(path.parent))
    tmp = path.with_suffix(".json.tmp")
    tmp.write_text(text, encoding="utf-8")
    tmp.replace(path)
    load_index.cache_clear()
    return path


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m lagrange.corpus.index", description=__doc__.split("\n")[0])
    group = ap.add_mutually_exclusive_group(required=True)
    group.add_argument("--write", action="store_true", help="import every problem module and write the index")
    group.add_argument("--check", action="store_true", help="exit 1 when a module changed since the index")
    args = ap.parse_args(argv)
    if args.write:
        path = write_index()
        print(f"wrote {path} ({len(load_index()['problems'])} problems)")
        return 0
    stale = stale_modules()
    if stale:
        print(f"the corpus index is stale for {', '.join(stale)}: run `python -m lagrange.corpus.index --write`")
        return 1
    print("the corpus index is up to date")
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
