"""Coverage of Wells' catalog by the problem corpus: which book cases have a checked problem, by chapter.

The catalog (``shared/reference/wells/*.md``, one Markdown file per group of chapters) lists the book's cases,
each tagged ``[FULL]`` (the book states a complete, checkable answer) or ``[PARTIAL]``. Its case labels come in
several spellings (``Ex 3.2``, ``P2.16``, ``Prob 5.3, 5.4``, ``Sec 1.9``, ``(2.26)/(2.42)``, ``14-Eq14.17``,
``13-Ex13.5 / P13.5``, ``P12.14–12.16``, ``5.5(1)``, and bare numbers in the Ch. 2 answer key); each is reduced
to a case key: ``ex3.2``, ``p2.16``, ``sec1.9``, ``eq2.42``, ``tab14.1`` (a part letter kept, ``ex8.6a``).

A corpus problem covers a case when its ``source`` cites it (``"Wells, Example 3.2"``, ``"Problem 6.1 (P form:
Problem 6.17)"``, ``"eqs. (2.18), (2.43)"``) or its id names it (``ex3.2-multipliers``). A part-lettered case
(``ex8.6a``) is covered by a problem citing that part or the whole case.

The parsed catalog is committed as ``problems/_catalog.json`` (the reference files are not shipped), so
coverage is computed from that file and the corpus index without importing any problem::

    python -m lagrange.corpus.coverage --write-catalog DIR   # after the catalog changes: parse DIR/*.md
    python -m lagrange.corpus.coverage --write-doc           # regenerate docs/coverage.md
    python -m lagrange.corpus.coverage                       # print the coverage by chapter

Each [FULL] case the corpus does not cover has a decision in :mod:`lagrange.corpus._catalog_notes` (not
checkable and why, or needs a capability still in progress); ``tests/problems/test_coverage.py`` requires one
for every uncovered case and none for a covered one.
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from collections import defaultdict
from pathlib import Path

from ..errors import SpecError
from ..records import record

__all__ = ["CatalogCase", "ChapterCoverage", "parse_catalog", "parse_label", "cited_cases", "load_catalog",
           "case_coverage", "chapter_coverage", "uncovered_full", "format_table", "coverage_markdown", "main"]

CATALOG_NAME = "_catalog.json"
_KINDS = {"ex": "Example", "p": "Problem", "sec": "Section", "eq": "Equation", "tab": "Table", "app": "Appendix"}


@record(frozen=True)
class CatalogCase:
    """One case of the catalog: ``key`` (``"p2.16"``), ``chapter``, the catalog's ``label`` line (shortened),
    ``full`` (tagged [FULL] at least once), and where it is listed (``file:line``)."""

    key: str
    chapter: int
    label: str
    full: bool
    where: str


@record(frozen=True)
class ChapterCoverage:
    """Coverage of one chapter: corpus problems, distinct book cases they cite, answers checked, misprints
    recorded, and the catalog's [FULL] cases covered and uncovered (keys)."""

    chapter: int
    problems: int
    cases: int
    answers: int
    misprints: int
    full_covered: tuple[str, ...]
    full_uncovered: tuple[str, ...]


# --- labels -------------------------------------------------------------------------------------------------

_NUM = r"(\d{1,2})\.(\d{1,2})([A-Za-z]?)"
_PART = r"(?:\s*\(([a-z])\))?"
_TAG = re.compile(r"\[(FULL|PARTIAL)[^\]]*\]")
_LABEL_PATTERNS = [  # (kind, regex); the number groups are chapter, number, letter, part
    ("ex", re.compile(r"\bEx(?:ample)?\.?\s*" + _NUM + _PART)),
    ("p", re.compile(r"(?:\bProb(?:lem)?s?\.?\s*|(?<![A-Za-z])P)" + _NUM + _PART)),
    ("sec", re.compile(r"\bSec(?:tion)?\.?\s*" + _NUM + _PART)),
    ("eq", re.compile(r"(?:\bEq\.?\s*|\()" + _NUM + r"\)?")),
    ("tab", re.compile(r"\bTab(?:le)?\.?\s*" + _NUM)),
]


def _key(kind: str, ch: str, num: str, letter: str = "", part: str | None = None) -> str:
    return f"{kind}{int(ch)}.{int(num)}{letter}{part or ''}"


_HEAD = re.compile(r"^(?:\s*(?:(?:\d{1,2}-)?(?:Ex|Prob|P|Sec|Eq|Tab)?\s*\(?\d{1,2}\.\d{1,2}[A-Za-z]?\)?"
                   r"(?:\s*\([a-z0-9]{1,3}\))*(?:/\d{1,2})?|,|/|and|[–-]))+")


def _label_head(label: str) -> str:
    """The leading run of case references of a label (``"Sec 7.8 / Ex 7.7"`` of ``"Sec 7.8 / Ex 7.7 Foci"``):
    references in the description that follows name other cases and are not this case."""
    m = _HEAD.match(label)
    return m.group(0) if m else ""


def parse_label(label: str, context: str = "") -> list[str]:
    """The case keys a catalog label names (several for ``Prob 5.3, 5.4`` or ``P12.14–12.16``).

    Only the label's leading references count (``"Ex 12.7: τ_α of Ex 12.6"`` is Ex 12.7). ``context`` is the
    heading the label sits under: in the Ch. 2 answer key bare numbers are problems; elsewhere a bare leading
    number (``5.5(1)``, ``5.1a-1``) is a section.

    >>> parse_label("Prob 5.3, 5.4")
    ['p5.3', 'p5.4']
    >>> parse_label("13-Ex13.5 / P13.5 — particle m on disk D2")
    ['ex13.5', 'p13.5']
    >>> parse_label("(2.26)/(2.42) Planar double pendulum")
    ['eq2.26', 'eq2.42']
    >>> parse_label("P12.14–12.16: Bearing torques")
    ['p12.14', 'p12.15', 'p12.16']
    >>> parse_label("14-Eq14.19/20 and P14.25 — polar-parallel frame")
    ['eq14.19', 'eq14.20', 'p14.25']
    """
    head = _label_head(label)
    keys: list[tuple[int, str]] = []
    for kind, rx in _LABEL_PATTERNS:
        for m in rx.finditer(head):
            g = m.groups()
            keys.append((m.start(), _key(kind, g[0], g[1], g[2] if kind != "eq" else "",
                                         g[3] if len(g) > 3 else None)))
            rest = head[m.end():]
            if kind == "eq" and rest.startswith("/") and rest[1:2].isdigit():  # "Eq14.19/20"
                keys.append((m.start(), _key(kind, g[0], re.match(r"/(\d+)", rest).group(1))))
            rng = re.match(r"\s*[–-]\s*(\d{1,2})\.(\d{1,2})", rest)
            if rng and kind == "p":  # "P12.14–12.16"
                for n in range(int(g[1]) + 1, int(rng.group(2)) + 1):
                    keys.append((m.start(), _key(kind, g[0], str(n))))
            while kind != "eq":  # "Prob 5.3, 5.4"
                more = re.match(r"\s*(?:,|and)\s*(\d{1,2})\.(\d{1,2})", rest)
                if not more:
                    break
                keys.append((m.start(), _key(kind, more.group(1), more.group(2))))
                rest = rest[more.end():]
    if not keys:
        m = re.match(r"\s*" + _NUM, label)
        if m:
            kind = "p" if "answer key" in context.lower() else "sec"
            keys.append((0, _key(kind, m.group(1), m.group(2), m.group(3))))
            rng = re.match(r"\s*[–-]\s*(\d{1,2})\.(\d{1,2})", label[m.end():])
            if rng:
                for n in range(int(m.group(2)) + 1, int(rng.group(2)) + 1):
                    keys.append((0, _key(kind, m.group(1), str(n))))
        else:
            m = re.match(r"\s*A\.(\d+)\s*\(([a-z])\)", label)
            if m:
                keys.append((0, f"app.a{m.group(1)}{m.group(2)}"))
            else:
                m = re.match(r"\s*(\d{1,2}|A)-([A-Za-z][\w-]*)", label)
                if m:
                    ch = "18" if m.group(1) == "A" else m.group(1)
                    keys.append((0, f"sec{int(ch)}.{m.group(2).lower()}"))
    out: list[str] = []
    for _, k in sorted(keys, key=lambda x: x[0]):
        if k not in out:
            out.append(k)
    return out


def _chapter_of(key: str) -> int:
    m = re.match(r"[a-z]+(\d+)\.", key)
    return int(m.group(1)) if m else 0


def _label_of(line: str) -> str:
    """The label text of a catalog line: the bold head before the [FULL]/[PARTIAL] tag."""
    text = line.strip().lstrip("-").strip()
    tag = _TAG.search(text)
    head = text[: tag.start()] if tag else text
    bold = re.match(r"\*\*(.+?)\*\*", text)
    if bold and (tag is None or bold.start() < tag.start()):
        head = _TAG.sub("", bold.group(1)).replace("  ", " ")
    return head.replace("**", "").strip(" :—")


def parse_catalog(folder: Path | str) -> list[CatalogCase]:
    """Every case of the catalog files ``folder/*.md``, merged by key (``full`` if any listing is [FULL])."""
    folder = Path(folder)
    files = sorted(folder.glob("*.md"))
    if not files:
        raise SpecError(f"no catalog files (*.md) in {folder}")
    found: dict[str, CatalogCase] = {}
    for path in files:
        heading = ""
        for lineno, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            if line.startswith("#"):
                heading = line.strip("# ")
                continue
            if not re.match(r"\s*(?:-\s*)?\*\*", line):
                continue
            tags = list(_TAG.finditer(line))
            if not tags:
                continue
            label = _label_of(line)
            full = any(t.group(1) == "FULL" for t in tags)
            if "PARTIAL" in tags[0].group(0) and not line.lstrip().startswith("**"):
                full = False
            for key in parse_label(label, heading):
                ch = _chapter_of(key) or 18  # the appendix (app.a8m) goes with ch. 18
                short = label if len(label) <= 90 else label[:87] + "..."
                old = found.get(key)
                if old is None:
                    found[key] = CatalogCase(key, ch, short, full, f"{path.name}:{lineno}")
                elif full and not old.full:
                    found[key] = CatalogCase(key, ch, old.label, True, old.where)
    return sorted(found.values(), key=_case_sort)


def _case_sort(c: CatalogCase):
    nums = [int(x) for x in re.findall(r"\d+", c.key)]
    return (c.chapter, nums, c.key)


# --- citations ----------------------------------------------------------------------------------------------

_CITE_PATTERNS = [
    ("ex", re.compile(r"\bEx(?:ample|s?\.)?\s*" + _NUM + _PART)),
    ("p", re.compile(r"\b(?:Prob(?:lem)?s?\.?|P)\s*" + _NUM + _PART)),
    ("sec", re.compile(r"\bSec(?:tion|s?\.)?\s*" + _NUM + _PART)),
    ("tab", re.compile(r"\bTable\s*" + _NUM)),
]
_EQ_CITE = re.compile(r"\beqs?\.\s*((?:\(\d{1,2}\.\d{1,2}\)(?:\s*[-–,]\s*|\s*and\s*)?)+)")
_ID = re.compile(r"^(ex|p|sec|eq|tab)(\d{1,2})\.(\d{1,2})([A-Za-z]?)(?:-([a-z]))?(?=$|[-_])")


def cited_cases(problem_id: str, source: str) -> set[str]:
    """The case keys a problem cites: its id's case and every case its ``source`` names.

    >>> sorted(cited_cases("p6.1", "Wells, Problem 6.1 (P form: Problem 6.17)"))
    ['p6.1', 'p6.17']
    >>> sorted(cited_cases("eq2.43", "Wells, Sec. 2.9, eqs. (2.18), (2.43)"))
    ['eq2.18', 'eq2.43', 'sec2.9']
    """
    keys: set[str] = set()
    m = _ID.match(problem_id)
    if m:
        keys.add(_key(m.group(1), m.group(2), m.group(3), m.group(4), m.group(5)))
    for kind, rx in _CITE_PATTERNS:
        for c in rx.finditer(source):
            g = c.groups()
            keys.add(_key(kind, g[0], g[1], g[2], g[3] if len(g) > 3 else None))
            # "Problems 6.17, 6.18" / "Problems 7.9 and 7.10"
            for more in re.finditer(r"^(?:\s*(?:,|and)\s*)(\d{1,2})\.(\d{1,2})", source[c.end():]):
                keys.add(_key(kind, more.group(1), more.group(2)))
    for c in _EQ_CITE.finditer(source):
        nums = re.findall(r"\((\d{1,2})\.(\d{1,2})\)", c.group(1))
        for a, b in nums:
            keys.add(_key("eq", a, b))
        rng = re.search(r"\((\d{1,2})\.(\d{1,2})\)\s*[-–]\s*\((\d{1,2})\.(\d{1,2})\)", c.group(1))
        if rng and rng.group(1) == rng.group(3):
            for n in range(int(rng.group(2)), int(rng.group(4)) + 1):
                keys.add(_key("eq", rng.group(1), str(n)))
    return keys


def _covered_keys(cited: set[str]) -> set[str]:
    """The case keys a set of citations covers: each key, and the whole case of a part (p2.10a covers p2.10)."""
    return cited | {k[:-1] for k in cited if re.search(r"\d[a-zA-Z]$", k)}


# --- coverage -----------------------------------------------------------------------------------------------


def _problems_dir() -> Path:
    from .index import _package_dir

    return _package_dir()


def load_catalog(path: Path | None = None) -> list[CatalogCase]:
    """The committed catalog case list (``problems/_catalog.json``)."""
    path = path or _problems_dir() / CATALOG_NAME
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise SpecError(f"the catalog case list {path} is missing: run "
                        "`python -m lagrange.corpus.coverage --write-catalog <catalog folder>`") from None
    return [CatalogCase(**c) for c in data["cases"]]


def case_coverage(entries: list[dict] | None = None, cases: list[CatalogCase] | None = None) -> dict[str, list[str]]:
    """For every catalog case key, the ids of the corpus problems that cover it (``[]`` if none)."""
    from . import index

    entries = index.entries() if entries is None else entries
    cases = load_catalog() if cases is None else cases
    by_key: dict[str, set[str]] = defaultdict(set)  # cited, or a part of it cited
    direct: dict[str, set[str]] = defaultdict(set)  # cited as such
    for e in entries:
        cited = cited_cases(e["id"], e["source"])
        for k in cited:
            direct[k].add(e["id"])
        for k in _covered_keys(cited):
            by_key[k].add(e["id"])
    order = {e["id"]: i for i, e in enumerate(entries)}
    out = {}
    for c in cases:
        m = re.match(r"^(.*\d)[a-zA-Z]$", c.key)  # a part (ex8.6a) is also covered by a citation of the whole case
        found = by_key.get(c.key, set()) | (direct.get(m.group(1), set()) if m else set())
        out[c.key] = sorted(found, key=order.__getitem__)
    return out


def _distinct_cases(entries: list[dict]) -> set[str]:
    """The distinct book cases of a list of problems: the case named by each id (variants share it)."""
    out = set()
    for e in entries:
        m = _ID.match(e["id"])
        out.add(_key(m.group(1), m.group(2), m.group(3), m.group(4), m.group(5)) if m else e["id"].split("-")[0])
    return out


def chapter_coverage(entries: list[dict] | None = None,
                     cases: list[CatalogCase] | None = None) -> list[ChapterCoverage]:
    """Coverage by chapter (every chapter that has problems or catalog cases)."""
    from . import index

    entries = index.entries() if entries is None else entries
    cases = load_catalog() if cases is None else cases
    covered = case_coverage(entries, cases)
    by_ch: dict[int, list[dict]] = defaultdict(list)
    for e in entries:
        by_ch[e["chapter"]].append(e)
    full_by_ch: dict[int, list[CatalogCase]] = defaultdict(list)
    for c in cases:
        if c.full:
            full_by_ch[c.chapter].append(c)
    out = []
    for ch in sorted(set(by_ch) | set(full_by_ch)):
        es = by_ch.get(ch, [])
        fulls = full_by_ch.get(ch, [])
        out.append(ChapterCoverage(
            chapter=ch, problems=len(es), cases=len(_distinct_cases(es)),
            answers=sum(e.get("answers", 0) for e in es),
            misprints=sum(1 for e in es if e.get("correction")),
            full_covered=tuple(c.key for c in fulls if covered[c.key]),
            full_uncovered=tuple(c.key for c in fulls if not covered[c.key])))
    return out


def uncovered_full(entries: list[dict] | None = None, cases: list[CatalogCase] | None = None) -> list[CatalogCase]:
    """The catalog's [FULL] cases that no corpus problem covers."""
    cases = load_catalog() if cases is None else cases
    covered = case_coverage(entries, cases)
    return [c for c in cases if c.full and not covered[c.key]]


def totals(rows: list[ChapterCoverage]) -> dict[str, int]:
    """Column sums of :func:`chapter_coverage` (cases are distinct per chapter, so they add up)."""
    return {"problems": sum(r.problems for r in rows), "cases": sum(r.cases for r in rows),
            "answers": sum(r.answers for r in rows), "misprints": sum(r.misprints for r in rows),
            "full_covered": sum(len(r.full_covered) for r in rows),
            "full_uncovered": sum(len(r.full_uncovered) for r in rows)}


def format_table(rows: list[ChapterCoverage]) -> str:
    """The coverage by chapter as a plain-text table (what ``lagrange verify`` prints)."""
    head = f"{'chapter':>7}  {'problems':>8}  {'cases':>5}  {'answers':>7}  {'misprints':>9}  " \
           f"{'[FULL] covered':>14}  {'uncovered':>9}"
    lines = [head]
    for r in rows:
        lines.append(f"{r.chapter:>7}  {r.problems:>8}  {r.cases:>5}  {r.answers:>7}  {r.misprints:>9}  "
                     f"{len(r.full_covered):>14}  {len(r.full_uncovered):>9}")
    s = totals(rows)
    lines.append(f"{'total':>7}  {s['problems']:>8}  {s['cases']:>5}  {s['answers']:>7}  {s['misprints']:>9}  "
                 f"{s['full_covered']:>14}  {s['full_uncovered']:>9}")
    return "\n".join(lines)


def coverage_markdown(entries: list[dict] | None = None, cases: list[CatalogCase] | None = None) -> str:
    """docs/coverage.md: the coverage by chapter and every uncovered [FULL] case with its decision."""
    from ._catalog_notes import NOTES

    rows = chapter_coverage(entries, cases)
    s = totals(rows)
    out = ["# Corpus coverage of Wells' catalog", "",
           "Generated by `python -m lagrange.corpus.coverage --write-doc` from `problems/_catalog.json` (the case",
           "list parsed from the catalog `shared/reference/wells/*.md`) and the corpus index; do not edit by hand.",
           "A case is covered when a corpus problem cites it in its `source` or id. *Cases* counts distinct book",
           "cases (variants of one case count once, by problem id); *misprints* counts problems that record a",
           "`correction` (a misprint with its corrected form and why, or geometry inferred for a missing figure).",
           "",
           f"Totals: {s['problems']} problems, {s['cases']} distinct book cases, {s['answers']} checked answers, "
           f"{s['misprints']} misprints recorded; catalog [FULL] cases: {s['full_covered']} covered, "
           f"{s['full_uncovered']} not covered (each with its reason below).", "",
           "| chapter | problems | cases | answers | misprints | [FULL] covered | [FULL] uncovered |",
           "|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        out.append(f"| {r.chapter} | {r.problems} | {r.cases} | {r.answers} | {r.misprints} | "
                   f"{len(r.full_covered)} | {len(r.full_uncovered)} |")
    out += ["", "## [FULL] cases not covered", "",
            "Status: *not checkable* (the answer is a definition, a proof or a property of the method, nothing a",
            "System of the book's problem produces), *catalog gap* (the catalog lacks what a check needs: the",
            "statement, the figure's geometry or the system referred to), *needs <capability> (in progress)*",
            "(another branch adds the capability), or *checkable: to add* (not yet in the corpus).", "",
            "| case | chapter | catalog label | status | reason |", "|---|---:|---|---|---|"]
    cases = load_catalog() if cases is None else cases
    for c in uncovered_full(entries, cases):
        status, reason = NOTES.get(c.key, ("UNDECIDED", ""))
        label = c.label.replace("|", "\\|")
        out.append(f"| {c.key} | {c.chapter} | {label} | {status} | {reason.replace('|', chr(92) + '|')} |")
    return "\n".join(out) + "\n"


def doc_path() -> Path:
    """docs/coverage.md of the source tree."""
    return Path(__file__).resolve().parents[2] / "docs" / "coverage.md"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m lagrange.corpus.coverage", description=__doc__.split("\n")[0])
    ap.add_argument("--write-catalog", metavar="DIR", help="parse DIR/*.md and write problems/_catalog.json")
    ap.add_argument("--write-doc", action="store_true", help="write docs/coverage.md")
    ap.add_argument("--uncovered", action="store_true", help="list the uncovered [FULL] cases")
    args = ap.parse_args(argv)
    if args.write_catalog:
        cases = parse_catalog(args.write_catalog)
        path = _problems_dir() / CATALOG_NAME
        data = {"version": 1, "cases": [_as_dict(c) for c in cases]}
        path.write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
        print(f"wrote {path} ({len(cases)} cases, {sum(c.full for c in cases)} [FULL])")
    if args.write_doc:
        doc_path().write_text(coverage_markdown(), encoding="utf-8")
        print(f"wrote {doc_path()}")
    if args.uncovered:
        for c in uncovered_full():
            print(f"{c.key:12} {c.where:22} {c.label}")
    if not (args.write_catalog or args.write_doc or args.uncovered):
        print(format_table(chapter_coverage()))
    return 0


def _as_dict(c: CatalogCase) -> dict:
    return {"key": c.key, "chapter": c.chapter, "label": c.label, "full": c.full, "where": c.where}


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
