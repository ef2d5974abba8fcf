"""Tidy tables of sweep results, and the on-disk store that makes a sweep resumable.

One row per run: ``run_id``, the point's values, ``status`` (``"ok"``, ``"error"`` — the run raised —,
``"died"`` — its worker process died), ``error`` (the message, empty when ok), the task's columns and
``wall_time`` (seconds in the worker).

Store formats (``sweep(..., store=path)``), chosen by the suffix:

``.csv``
    One line appended per finished run, flushed and fsync'ed, so an interruption loses at most the line
    being written (a torn last line is ignored on reading). A row bringing new columns rewrites the file
    once with the wider header (atomically: temporary file + rename).
``.parquet``
    A directory of one Parquet file per run (``<run_id>.parquet``, written to a temporary name and
    renamed), read back as one table. Needs ``pyarrow``.

``resume=True`` reads the store and skips every run already there with status ``ok`` or ``error`` (an
exception of the task is deterministic) whose run id *and* ``run_config`` match the sweep being resumed
(:mod:`lagrange.sweep.identity`); ``died`` runs and runs of another configuration are computed again.
"""

from __future__ import annotations

import csv
import io
import math
import os
import tempfile
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from typing import Any

from ..errors import SweepError

__all__ = ["require_pandas", "Store", "to_frame", "FIRST_COLUMNS"]

FIRST_COLUMNS = ("run_id", "status", "error")
FINISHED = ("ok", "error")


def require_pandas():
    """Import pandas or raise SweepError naming the extra that provides it."""
    try:
        import pandas
    except ImportError:
        raise SweepError('sweeps return a pandas DataFrame: install the sweep extra, '
                         'pip install "lagrange-dynamics[sweep]" (pandas, tqdm, cloudpickle)') from None
    return pandas


def to_frame(rows: Iterable[Mapping[str, Any]], point_names: Sequence[str], order: Sequence[str] | None = None):
    """A DataFrame with columns run_id, the point's names, status, error, the rest (in order of first
    appearance), wall_time last; rows sorted by ``order`` (run ids) when given."""
    pd = require_pandas()
    rows = list(rows)
    if order is not None:
        rank = {rid: i for i, rid in enumerate(order)}
        rows.sort(key=lambda r: rank.get(r["run_id"], len(rank)))
    cols: list[str] = ["run_id", *point_names, "status", "error"]
    for r in rows:
        cols += [c for c in r if c not in cols and c != "wall_time"]
    cols.append("wall_time")
    frame = pd.DataFrame.from_records(rows, columns=cols)
    return frame.reset_index(drop=True)


class Store:
    """Append-as-you-go storage of finished rows (see the module docstring)."""

    def __init__(self, path: str | os.PathLike, *, resume: bool = False):
        self.path = Path(path)
        suffix = self.path.suffix.lower()
        if suffix not in (".csv", ".parquet"):
            raise SweepError(f"store {self.path}: the suffix must be .csv or .parquet")
        self.kind = suffix[1:]
        if self.kind == "parquet":
            try:
                import pyarrow  # noqa: F401
            except ImportError:
                raise SweepError('a .parquet store needs pyarrow: pip install pyarrow, or use a .csv store') from None
        if self.path.exists() and not resume:
            raise SweepError(f"store {self.path} already exists: pass resume=True to continue that sweep, or "
                             "remove it to start over")
        self._header: list[str] | None = None
        self._rows: list[dict] = self._read() if self.path.exists() else []
        if self._rows and self.kind == "csv":
            self._header = list(self._rows[0])

    # --- reading --------------------------------------------------------------------------------------
    def _read(self) -> list[dict]:
        pd = require_pandas()
        if self.kind == "parquet":
            files = sorted(self.path.glob("*.parquet"))
            frames = [pd.read_parquet(f) for f in files]
            if not frames:
                return []
            return [_clean(r) for r in pd.concat(frames, ignore_index=True).to_dict("records")]
        text = self.path.read_text()
        if not text.endswith("\n"):  # a torn last line (interrupted while writing): drop it from the file
            text = text[: text.rfind("\n") + 1]
            with self.path.open("r+b") as fh:
                fh.truncate(len(text.encode()))
        if not text.strip():
            return []
        frame = pd.read_csv(io.StringIO(text), keep_default_na=False, na_values=[""],
                            dtype={"run_id": str, "run_config": str, "status": str, "error": str})
        return [_clean(r) for r in frame.to_dict("records")]

    def rows(self) -> list[dict]:
        """Every stored row (as read at opening, plus those appended since)."""
        return list(self._rows)

    def finished(self, config: str | None = None) -> set[str]:
        """Run ids with status ok or error (and, when ``config`` is given, that ``run_config``): resume skips
        them. Rows stored without a ``run_config`` (older stores) never match a given one."""
        return {str(r["run_id"]) for r in self._rows if r.get("status") in FINISHED
                and (config is None or str(r.get("run_config", "")) == config)}

    # --- writing --------------------------------------------------------------------------------------
    def append(self, row: Mapping[str, Any]) -> None:
        """Persist one finished row before returning."""
        row = dict(row)
        self._rows = [r for r in self._rows if str(r["run_id"]) != row["run_id"]] + [row]
        if self.kind == "parquet":
            self._write_parquet(row)
        else:
            self._append_csv(row)

    def _write_parquet(self, row: dict) -> None:
        pd = require_pandas()
        self.path.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=self.path, suffix=".tmp")
        os.close(fd)
        pd.DataFrame.from_records([row]).to_parquet(tmp, index=False)
        os.replace(tmp, self.path / f"{row['run_id']}.parquet")

    def _append_csv(self, row: dict) -> None:
        if self._header is None or any(k not in self._header for k in row):
            self._header = (self._header or []) + [k for k in row if k not in (self._header or [])]
            self._rewrite_csv()
            return
        with self.path.open("a", newline="") as fh:
            csv.DictWriter(fh, self._header).writerow(_csv_values(row))
            fh.flush()
            os.fsync(fh.fileno())

    def _rewrite_csv(self) -> None:
        self.path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=self.path.parent, suffix=".tmp")
        with os.fdopen(fd, "w", newline="") as fh:
            w = csv.DictWriter(fh, self._header)
            w.writeheader()
            for r in self._rows:
                w.writerow(_csv_values(r))
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, self.path)


def _csv_values(row: Mapping[str, Any]) -> dict:
    """Floats as repr (round-trips exactly), NaN as empty."""
    out = {}
    for k, v in row.items():
        if isinstance(v, float):
            out[k] = "" if math.isnan(v) else repr(v)
        else:
            out[k] = v
    return out


def _clean(record: Mapping[str, Any]) -> dict:
    """pandas scalars → Python scalars; ids and messages as strings (an empty error is '')."""
    out = {}
    for k, v in record.items():
        v = v.item() if hasattr(v, "item") else v
        if k in ("run_id", "run_config", "status", "error"):
            v = "" if v is None or (isinstance(v, float) and math.isnan(v)) else str(v)
        out[k] = v
    return out
