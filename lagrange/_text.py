"""User text made safe for a terminal (no sympy: the command line imports this before anything heavy)."""

from __future__ import annotations

import unicodedata

__all__ = ["printable"]

_UNPRINTABLE = ("Cc", "Cf", "Zl", "Zp", "Cs", "Co", "Cn")


def printable(text: str, *, keep: str = "") -> str:
    r"""``text`` with every control or format character (terminal escapes such as ``\x1b[2J``, carriage
    returns, bidirectional overrides such as U+202E) written as its Python escape, except those in ``keep``
    (e.g. ``"\n"`` for a multi-line message). Every user string the CLI prints (a system's name, a spec's
    label, an error message quoting a spec) goes through it, so a spec cannot drive the terminal.

    >>> printable("pendulum\x1b[2J")
    'pendulum\\x1b[2J'
    """
    text = str(text)
    if text.isprintable():
        return text
    return "".join(ch if ch in keep or unicodedata.category(ch) not in _UNPRINTABLE
                   else ch.encode("unicode_escape").decode("ascii") for ch in text)
