"""The hard-case suite: every method of the registry on Andrews' squeezer, the stiff car axis, a chaotic double
pendulum, a Kepler orbit of eccentricity 0.9, a kinked potential, a stick-slip block and a spherical pendulum
through its pole; error against an independent reference, CPU, constraint drift and each run's own verdict
(lagrange/bench/hard.py).

Writes benchmarks/results/hard_cases.md (the table) and hard_cases_<problem>.png (error against CPU per method).

    python benchmarks/hard_cases.py            # full: every method, two tolerances
    python benchmarks/hard_cases.py --quick    # what the tests run: six methods, one tolerance
"""

import argparse
from pathlib import Path

from lagrange.bench.hard import run_hard_suite, write_hard_report

if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--out", default=str(Path(__file__).parent / "results"))
    args = parser.parse_args()
    runs = run_hard_suite(quick=args.quick)
    paths = write_hard_report(runs, args.out, quick=args.quick)
    print(f"wrote {paths['md']} and {len(paths['png'])} PNG(s)")
