"""Progress reports on stderr for long work: tqdm bars when installed, plain lines otherwise, one-line notes.

Library code calls :func:`note` (e.g. "compiling … (one time)") and :func:`track` (wrap a loop) and is
silent by default. Reports are switched on only inside :func:`reporting` — the ``lagrange`` command does
so unless given ``--no-progress`` or ``-q`` — and only when stderr is a terminal (set
``LAGRANGE_PROGRESS=1`` to report to a non-terminal, e.g. a log file; ``LAGRANGE_PROGRESS=0`` to never
report). The switch is a :class:`contextvars.ContextVar`, not a module flag, so threads and nested calls do
not leak it. Standard output is never used: results stay clean for pipes.
"""

from __future__ import annotations

import os
import sys
import threading
import time
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar

__all__ = ["reporting", "active", "note", "track", "counter", "heartbeat"]

_ACTIVE: ContextVar[bool] = ContextVar("lagrange_progress", default=False)
#: plain-text reports (no tqdm) print at most one line per this many seconds
_PLAIN_INTERVAL = 2.0


def _wanted(enabled: bool) -> bool:
    env = os.environ.get("LAGRANGE_PROGRESS", "").strip()
    if env == "0" or not enabled:
        return False
    if env == "1":
        return True
    try:
        return sys.stderr.isatty()
    except (AttributeError, ValueError):  # stderr replaced or closed
        return False


@contextmanager
def reporting(enabled: bool = True) -> Iterator[bool]:
    """Switch progress reports on (when ``enabled`` and stderr is a terminal) for the ``with`` block;
    yields whether they are on."""
    token = _ACTIVE.set(_wanted(enabled))
    try:
        yield _ACTIVE.get()
    finally:
        _ACTIVE.reset(token)


def active() -> bool:
    """Whether progress reports are on here."""
    return _ACTIVE.get()


def note(message: str) -> None:
    """One line ``lagrange: message`` on stderr when reports are on."""
    if _ACTIVE.get():
        from ._text import printable  # may quote a user's file name

        print(f"lagrange: {printable(message)}", file=sys.stderr, flush=True)


def _tqdm():
    try:
        from tqdm import tqdm
    except ImportError:
        return None
    return tqdm


def track(items: Iterable, *, total: int | None = None, desc: str = "") -> Iterable:
    """``items`` unchanged when reports are off; else wrapped in a tqdm bar on stderr (or, without tqdm,
    a line ``desc: i/total`` at most every 2 s)."""
    if not _ACTIVE.get():
        return items
    if total is None and hasattr(items, "__len__"):
        total = len(items)  # type: ignore[arg-type]
    tqdm = _tqdm()
    if tqdm is not None:
        return tqdm(items, total=total, desc=desc, file=sys.stderr, leave=False, dynamic_ncols=True)
    return _plain(items, total, desc)


def _plain(items: Iterable, total: int | None, desc: str) -> Iterator:
    last = time.monotonic()
    for i, item in enumerate(items):
        now = time.monotonic()
        if now - last >= _PLAIN_INTERVAL:
            print(f"lagrange: {desc}: {i}/{total if total is not None else '?'}", file=sys.stderr, flush=True)
            last = now
        yield item


def counter(total: int, *, desc: str = "") -> tuple[Callable[[int], None], Callable[[], None]]:
    """``(update, close)`` for work reported by callbacks: ``update(done)`` with the number of finished
    items (absolute), ``close()`` at the end. Both do nothing when reports are off."""
    if not _ACTIVE.get():
        return (lambda done: None), (lambda: None)
    tqdm = _tqdm()
    if tqdm is not None:
        bar = tqdm(total=total, desc=desc, file=sys.stderr, leave=False, dynamic_ncols=True)

        def update(done: int) -> None:
            bar.update(max(0, done - bar.n))

        return update, bar.close
    state = {"last": time.monotonic()}

    def update_plain(done: int) -> None:
        now = time.monotonic()
        if now - state["last"] >= _PLAIN_INTERVAL:
            print(f"lagrange: {desc}: {done}/{total}", file=sys.stderr, flush=True)
            state["last"] = now

    return update_plain, (lambda: None)


@contextmanager
def heartbeat(what: str, *, every: float = 2.0) -> Iterator[None]:
    """For work that cannot report its own progress (an integration, a compiled loop): when reports are
    on, a note ``what …`` at the start and, from a background thread, the elapsed time every ``every``
    seconds until the block ends (on one line on a terminal)."""
    if not _ACTIVE.get():
        yield
        return
    from ._text import printable  # a spec's label is user text: never a terminal escape

    what = printable(what)
    print(f"lagrange: {what} …", file=sys.stderr, flush=True)
    done = threading.Event()
    start = time.monotonic()
    tty = sys.stderr.isatty()

    def beat() -> None:
        while not done.wait(every):
            text = f"lagrange: {what} … {time.monotonic() - start:.0f} s"
            print("\r" + text if tty else text, end="" if tty else "\n", file=sys.stderr, flush=True)

    thread = threading.Thread(target=beat, daemon=True)
    thread.start()
    try:
        yield
    finally:
        done.set()
        thread.join()
        if tty and time.monotonic() - start >= every:
            print(file=sys.stderr, flush=True)
