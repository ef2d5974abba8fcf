"""The catalog coverage report (lagrange.corpus.coverage): label parsing, citations, the committed case list,
a decision for every uncovered [FULL] case, docs/coverage.md and the README's counts."""

import re
from pathlib import Path

import pytest

from lagrange.corpus import coverage
from lagrange.corpus._catalog_notes import NOTES, STATUSES

ROOT = Path(__file__).resolve().parents[2]
REFERENCE = Path("/work/shared/reference/wells")


@pytest.mark.parametrize("label, context, keys", [
    ("Ex 1.1 Ball in a railroad car (Fig. 1-1)", "", ["ex1.1"]),
    ("P2.3 (a) / (b) Parabola-family coordinates", "", ["p2.3a"]),
    ("Ex 4.3A", "", ["ex4.3A"]),
    ("Sec 2.14(ii), (2.66)–(2.68) Virtual work", "", ["sec2.14", "eq2.66", "eq2.68"]),
    ("Sec 7.8 / Ex 7.7 Foci and spherical points", "", ["sec7.8", "ex7.7"]),
    ("Ex 12.7: τ_α of Ex 12.6 by Euler's equations.", "", ["ex12.7"]),  # Ex 12.6 is in the description
    ("14-Tab14.1 — geodesy formulas (14.1)–(14.13)", "", ["tab14.1"]),
    ("14-P14.2, P14.3, P14.4", "", ["p14.2", "p14.3", "p14.4"]),
    ("5.5(1) Pendulum V", "Chapter 5", ["sec5.5"]),
    ("2.10–2.12", "Answer key for Chapter 2 problems", ["p2.10", "p2.11", "p2.12"]),
    ("A.8(m)", "", ["app.a8m"]),
    ("18-Fq — property test", "", ["sec18.fq"]),
])
def test_label_forms(label, context, keys):
    assert coverage.parse_label(label, context) == keys


@pytest.mark.parametrize("pid, source, keys", [
    ("ex8.6-b", "Wells, Example 8.6 (b)", {"ex8.6b"}),
    ("sec2.14", "Wells, Sec. 2.14(ii), eqs. (2.66)-(2.68); T as in (2.43)", {"sec2.14", "eq2.66", "eq2.67", "eq2.68"}),
    ("p3.24", "Wells, Problem 3.24 (with eq. 2.46)", {"p3.24"}),  # "eq. 2.46" without parentheses: not a citation
    ("p13.9", "Wells, Problem 13.9 (Fig. 2-29, Prob. 2.20)", {"p13.9", "p2.20"}),
    ("tab14.1", "Wells, Table 14.1, eqs. (14.11)-(14.13)", {"tab14.1", "eq14.11", "eq14.12", "eq14.13"}),
])
def test_citations(pid, source, keys):
    assert coverage.cited_cases(pid, source) == keys


def test_parts_cover_whole_cases_and_back():
    cases = [coverage.CatalogCase("ex8.6a", 8, "Ex 8.6(a)", True, "x:1"),
             coverage.CatalogCase("p2.10", 2, "P2.10", True, "x:2"),
             coverage.CatalogCase("ex9.10b", 9, "Ex 9.10(b)", True, "x:3")]
    entries = [{"id": "ex8.6", "source": "Wells, Example 8.6", "chapter": 8},
               {"id": "p2.10", "source": "Wells, Problem 2.10(a)", "chapter": 2},
               {"id": "ex9.10-a", "source": "Wells, Example 9.10(a)", "chapter": 9}]
    cov = coverage.case_coverage(entries, cases)
    assert cov == {"ex8.6a": ["ex8.6"], "p2.10": ["p2.10"], "ex9.10b": []}  # part (a) does not cover part (b)


def test_parse_catalog_merges_full_tags_and_reads_the_answer_key(tmp_path):
    (tmp_path / "a.md").write_text(
        "## Chapter 2\n**P2.4 [PARTIAL]** text\n**P2.6 [FULL]** text\n"
        "### Answer key for Chapter 2 problems\n- **2.4** [FULL]: answer\nplain line [FULL] ignored\n",
        encoding="utf-8")
    cases = {c.key: c for c in coverage.parse_catalog(tmp_path)}
    assert set(cases) == {"p2.4", "p2.6"}
    assert cases["p2.4"].full and cases["p2.4"].where == "a.md:2"  # FULL in the answer key wins; first listing kept
    with pytest.raises(coverage.SpecError, match="no catalog files"):
        coverage.parse_catalog(tmp_path / "missing")


def test_chapter_totals_count_answers_corrections_and_full_cases():
    cases = [coverage.CatalogCase("ex3.1", 3, "Ex 3.1", True, "x:1"),
             coverage.CatalogCase("p3.2", 3, "P3.2", True, "x:2"),
             coverage.CatalogCase("p3.3", 3, "P3.3", False, "x:3")]
    entries = [{"id": "ex3.1", "source": "Wells, Example 3.1", "chapter": 3, "answers": 2, "correction": True},
               {"id": "ex3.1-polar", "source": "Wells, Example 3.1", "chapter": 3, "answers": 1, "correction": False},
               {"id": "p3.3", "source": "Wells, Problem 3.3", "chapter": 3, "answers": 4, "correction": False}]
    (row,) = coverage.chapter_coverage(entries, cases)
    assert (row.problems, row.cases, row.answers, row.misprints) == (3, 2, 7, 1)
    assert row.full_covered == ("ex3.1",) and row.full_uncovered == ("p3.2",)
    assert "total" in coverage.format_table([row]).splitlines()[-1]


@pytest.mark.skipif(not REFERENCE.is_dir(), reason="the catalog's Markdown files are not on this machine")
def test_committed_case_list_matches_the_catalog():
    parsed = coverage.parse_catalog(REFERENCE)
    assert [coverage._as_dict(c) for c in parsed] == [coverage._as_dict(c) for c in coverage.load_catalog()]


def test_every_uncovered_full_case_has_a_decision_and_no_covered_case_has_one():
    uncovered = {c.key for c in coverage.uncovered_full()}
    assert uncovered, "the catalog has [FULL] cases the corpus does not cover; the list must not come back empty"
    missing = sorted(uncovered - set(NOTES))
    assert not missing, f"uncovered [FULL] cases without a decision in _catalog_notes: {missing}"
    stale = sorted(set(NOTES) - uncovered)
    assert not stale, f"decisions for cases that are covered now (remove them): {stale}"
    for key, (status, reason) in NOTES.items():
        assert status in STATUSES and len(reason) > 20, key


def test_coverage_doc_is_current():
    assert (ROOT / "docs" / "coverage.md").read_text(encoding="utf-8") == coverage.coverage_markdown(), \
        "docs/coverage.md is stale: run `python -m lagrange.corpus.coverage --write-doc`"


def test_readme_counts_come_from_the_coverage_report():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    rows = coverage.chapter_coverage()
    s = coverage.totals(rows)
    m = re.search(r"\*\*(\d+) problems\*\* \(([\d,]+) distinct book cases.*?\) with \*\*([\d,]+) checked answers\*\* "
                  r"\(([^)]*)\)", text, re.S)
    assert m, "README: the corpus paragraph's counts were not found"
    assert int(m.group(1)) == s["problems"]
    assert int(m.group(2).replace(",", "")) == s["cases"]
    assert int(m.group(3).replace(",", "")) == s["answers"]
    per_chapter = dict(re.findall(r"ch\.\s+(\d+):\s+(\d+)", m.group(4)))
    assert per_chapter == {str(r.chapter): str(r.answers) for r in rows if r.answers}


def _cli(*args, capsys):
    from lagrange.cli import main

    try:
        status = main(list(args))
    except SystemExit as exc:
        status = exc.code
    out = capsys.readouterr()
    return status, out.out, out.err


def test_verify_prints_the_coverage_by_chapter(capsys):
    status, out, _ = _cli("verify", "--coverage", capsys=capsys)
    assert status == 0
    rows = coverage.chapter_coverage()
    s = coverage.totals(rows)
    lines = out.splitlines()
    assert lines[1].split()[:5] == ["chapter", "problems", "cases", "answers", "misprints"]
    assert len(lines) == 2 + len(rows) + 1
    assert lines[-1].split() == ["total", *(str(s[k]) for k in ("problems", "cases", "answers", "misprints",
                                                               "full_covered", "full_uncovered"))]
    status, out, _ = _cli("verify", "--coverage", "--chapter", "6", capsys=capsys)
    row = next(r for r in rows if r.chapter == 6)
    assert out.splitlines()[2].split() == [str(v) for v in (6, row.problems, row.cases, row.answers, row.misprints,
                                                            len(row.full_covered), len(row.full_uncovered))]
    status, _, err = _cli("verify", "ex1.1", "--coverage", capsys=capsys)
    assert status != 0 and "give no problem ids" in err
