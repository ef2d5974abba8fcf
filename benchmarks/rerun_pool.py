"""Pool several runs of ``rerun.py`` (their ``.json`` files) into one verdict per problem.

For each problem: the lagrange Taylor route's warm runs paired with heyoka's fastest warm route of the same
run file, repeat by repeat (the pairing of ``rerun._paired_ratio``: two runs made side by side), then over all
files: the median of the paired ratios, in how many pairs lagrange was the cheaper, and the least CPU of
lagrange's runs over the least of heyoka's (any route).

    python benchmarks/rerun_pool.py benchmarks/results/rerun_taylor.json benchmarks/results/rerun_taylor_second.json
"""

from __future__ import annotations

import json
import statistics
import sys
from pathlib import Path


def pool(paths: list[Path]) -> dict[str, dict]:
    """``{problem: {"pairs", "median", "cheaper", "fastest"}}`` over the run files ``paths``."""
    out = {}
    problems = json.loads(paths[0].read_text())["results"]
    for problem in problems:
        ratios, ours, theirs = [], [], []
        for path in paths:
            runs = json.loads(path.read_text())["results"][problem]
            heyoka = [label for label in runs if label.startswith("heyoka")]
            best = min(heyoka, key=lambda label: statistics.median(r["cpu"] for r in runs[label]["warm"]))
            lagrange = runs["lagrange taylor"]["warm"]
            ratios += [a["cpu"] / b["cpu"] for a, b in zip(lagrange, runs[best]["warm"])]
            ours += [r["cpu"] for r in lagrange]
            theirs += [r["cpu"] for label in heyoka for r in runs[label]["warm"]]
        out[problem] = {"pairs": len(ratios), "median": statistics.median(ratios),
                        "cheaper": sum(r < 1 for r in ratios), "fastest": min(ours) / min(theirs)}
    return out


def main(argv: list[str]) -> None:
    if not argv:
        raise SystemExit(__doc__)
    print("| problem | pairs | median of paired ratios | lagrange the cheaper | fastest / heyoka's fastest |")
    print("|---|---|---|---|---|")
    for problem, v in pool([Path(a) for a in argv]).items():
        print(f"| {problem} | {v['pairs']} | {v['median']:.2f}× | {v['cheaper']}/{v['pairs']} | {v['fastest']:.2f}× |")


if __name__ == "__main__":
    main(sys.argv[1:])
