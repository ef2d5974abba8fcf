"""Make the small data files the notebooks read, from the benchmarks' stored results.

Run from the repository root after the benchmarks were re-run::

    python notebooks/data/make_data.py

* ``greenspan_paths.npz`` (for ``greenspan_top.ipynb``): from ``benchmarks/results/greenspan_paths.npz``
  (``python benchmarks/greenspan.py``), every second point (the last one kept) in single precision, only what
  the notebook draws: the contact point P1 of both models, the centre Pbar and the times of the molecular one.
* ``stability_map.csv`` (for ``greenspan_stability_map.ipynb``): from
  ``benchmarks/results/sweep_stability_map.csv`` (``python benchmarks/sweep.py``), the columns run_id, V,
  alpha_deg, fell, fall_time.
"""

import csv
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RESULTS = HERE.parent.parent / "benchmarks" / "results"


def _every_second(a: np.ndarray) -> np.ndarray:
    idx = np.arange(0, len(a), 2)
    if idx[-1] != len(a) - 1:
        idx = np.append(idx, len(a) - 1)
    return a[idx].astype(np.float32)


def greenspan_paths() -> Path:
    src = np.load(RESULTS / "greenspan_paths.npz")
    keep = {}
    for key in src.files:
        model, _, what = key.split("_")
        if what == "P1" or (model == "molecular" and what in ("Pbar", "t")):
            keep[key] = _every_second(src[key])
    out = HERE / "greenspan_paths.npz"
    np.savez_compressed(out, **keep)
    return out


def stability_map() -> Path:
    cols = ["run_id", "V", "alpha_deg", "fell", "fall_time"]
    out = HERE / "stability_map.csv"
    with (RESULTS / "sweep_stability_map.csv").open() as src, out.open("w", newline="") as dst:
        w = csv.writer(dst)
        w.writerow(cols)
        for row in csv.DictReader(src):
            w.writerow([row[c] for c in cols])
    return out


if __name__ == "__main__":
    for path in (greenspan_paths(), stability_map()):
        print(f"{path}: {path.stat().st_size / 1e3:.0f} kB")
