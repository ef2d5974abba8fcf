"""Generate ``docs/api.md``, the API reference of :mod:`lagrange`, from the docstrings.

Usage::

    python docs/build_api.py                 # writes docs/api.md next to this script
    python docs/build_api.py OUT.md          # writes OUT.md instead (e.g. into a temporary directory)

Covered: everything in ``lagrange.__all__``, then the public functions and classes of
``lagrange.analysis.*``, ``lagrange.model.inertia``, ``lagrange.model.standard_bodies``,
``lagrange.model.frames``, ``lagrange.derive.euler``, ``lagrange.corpus`` and
``lagrange.discrete.greenspan`` ("public" = the module's ``__all__``, or else every name not starting
with ``_`` that the module itself defines), and finally the simulation driver
(``lagrange.integrate.run.simulate``, whose options ``System.simulate`` forwards) and its result
(``lagrange.results.trajectory.Trajectory``). Classes also list their own public methods and properties.

Each entry gives the signature (:func:`inspect.signature`) and the docstring **verbatim** in a ``text``
block (never a ``python`` block: nothing in the API reference is meant to be executed, and the
docstrings are reStructuredText, which Markdown would otherwise mangle). An object exported at the top
level is documented once, under ``lagrange``; the module sections link to it.

Needs only the core dependencies (sympy, numpy, scipy, matplotlib): nothing here imports numba or runs
a simulation. Entries without a docstring are marked in the output and listed on stderr.
"""

from __future__ import annotations

import dataclasses
import importlib
import inspect
import re
import sys
from pathlib import Path

MODULES = [
    "lagrange.analysis.driving",
    "lagrange.analysis.hamilton",
    "lagrange.analysis.small_oscillations",
    "lagrange.analysis.steady_motion",
    "lagrange.analysis.variational",
    "lagrange.model.inertia",
    "lagrange.model.standard_bodies",
    "lagrange.model.frames",
    "lagrange.derive.euler",
    "lagrange.corpus",
    "lagrange.discrete.greenspan",
]

#: Not asked for by name, but ``System.simulate`` and its result point here: documented after the above.
EXTRA_MODULES = {
    "lagrange.integrate.run": ["simulate", "choose_method"],
    "lagrange.results.trajectory": ["Trajectory"],
}

MISSING = "*(no docstring)*"

#: Special methods that are part of how a class is used (``sol[theta]``), documented with the rest.
DUNDERS = {"__getitem__", "__call__"}


class _Raw:
    """An annotation shown exactly as written (annotations are strings under ``from __future__``)."""

    def __init__(self, text: str):
        self.text = text

    def __repr__(self) -> str:
        return self.text


def _raw(annotation):
    if annotation is inspect.Parameter.empty:
        return annotation
    if isinstance(annotation, str):
        return _Raw(annotation)
    return _Raw(inspect.formatannotation(annotation))


def signature(obj) -> str | None:
    """``(a, b=1, *, c) -> T`` or None when Python cannot tell."""
    try:
        sig = inspect.signature(obj)
    except (TypeError, ValueError):
        return None
    params = [p.replace(annotation=_raw(p.annotation)) for p in sig.parameters.values()]
    sig = sig.replace(parameters=params, return_annotation=_raw(sig.return_annotation))
    return str(sig)


def docstring(obj) -> str | None:
    """The object's own docstring (not inherited), dedented; None when there is none."""
    doc = obj.fget.__doc__ if isinstance(obj, property) else getattr(obj, "__doc__", None)
    if isinstance(obj, (staticmethod, classmethod)):
        doc = obj.__func__.__doc__
    if not doc or not doc.strip():
        return None
    if inspect.isclass(obj) and dataclasses.is_dataclass(obj) and doc.startswith(obj.__name__ + "("):
        return None  # the signature dataclasses writes when the class has no docstring
    return inspect.cleandoc(doc)


def fenced(text: str) -> str:
    """``text`` verbatim in a fenced ``text`` block longer than any backtick run inside it."""
    longest = max((len(m) for m in re.findall(r"`+", text)), default=0)
    fence = "`" * max(3, longest + 1)
    return f"{fence}text\n{text}\n{fence}"


def anchor(name: str) -> str:
    return name.replace(".", "-").replace("_", "-").lower()


def kind(obj) -> str:
    if inspect.isclass(obj):
        return "exception" if issubclass(obj, BaseException) else "class"
    if callable(obj):
        return "function"
    return "data"


class Builder:
    def __init__(self):
        self.out: list[str] = []
        self.missing: list[str] = []
        self.top_level: dict[int, str] = {}  # id(object) -> documented qualified name

    def emit(self, *lines: str) -> None:
        self.out.extend(lines)

    def doc_block(self, qualname: str, obj) -> None:
        doc = docstring(obj)
        if doc is None:
            self.missing.append(qualname)
            self.emit(MISSING, "")
        else:
            self.emit(fenced(doc), "")

    def entry(self, qualname: str, obj, level: int = 3) -> None:
        hashes = "#" * level
        k = kind(obj)
        self.emit(f'<a id="{anchor(qualname)}"></a>', "", f"{hashes} `{qualname}` ({k})", "")
        if k == "data":
            self.emit(f"Value: `{obj!r}` (`{type(obj).__name__}`)", "")
            if isinstance(obj, (str, int, float, tuple, dict, list)):
                return  # a plain value carries its type's docstring, not its own
            if type(obj).__module__.startswith("sympy"):
                return
            self.doc_block(qualname, obj)
            return
        sig = signature(obj)
        if sig is not None and inspect.isclass(obj):
            sig = sig.removesuffix(" -> None")
        name = qualname.rsplit(".", 1)[-1]
        if sig is not None:
            self.emit(f"Signature: `{name}{sig}`", "")
        origin = getattr(obj, "__module__", None)
        if origin and not qualname.startswith(origin + "."):
            self.emit(f"Defined in `{origin}`.", "")
        self.doc_block(qualname, obj)
        if inspect.isclass(obj):
            self.members(qualname, obj, level + 1)

    def members(self, qualname: str, cls, level: int) -> None:
        for name, member in vars(cls).items():
            if name.startswith("_") and name not in DUNDERS:
                continue
            is_prop = isinstance(member, property) or type(member).__name__ == "cached_property"
            is_method = inspect.isfunction(member) or isinstance(member, (staticmethod, classmethod))
            if not (is_prop or is_method):
                continue
            full = f"{qualname}.{name}"
            hashes = "#" * level
            if is_prop:
                target = member.func if type(member).__name__ == "cached_property" else member
                self.emit(f"{hashes} `{full}` (property)", "")
                self.doc_block(full, target)
            else:
                func = member.__func__ if isinstance(member, (staticmethod, classmethod)) else member
                label = "staticmethod" if isinstance(member, staticmethod) else (
                    "classmethod" if isinstance(member, classmethod) else "method")
                self.emit(f"{hashes} `{full}` ({label})", "")
                sig = signature(func)
                if sig is not None:
                    if isinstance(member, classmethod) or (label == "method"):
                        sig = re.sub(r"^\((self|cls)(, )?", "(", sig)
                    self.emit(f"Signature: `{name}{sig}`", "")
                self.doc_block(full, func)

    def module_docstring(self, module) -> None:
        doc = docstring(module)
        if doc is None:
            self.missing.append(module.__name__ + " (module)")
            self.emit(MISSING, "")
        else:
            self.emit(fenced(doc), "")

    def public_names(self, module) -> list[str]:
        names = getattr(module, "__all__", None)
        if names is None:
            names = [n for n, v in vars(module).items()
                     if not n.startswith("_") and getattr(v, "__module__", None) == module.__name__
                     and (inspect.isclass(v) or inspect.isfunction(v))]
        return list(names)

    def build(self) -> str:
        import lagrange

        self.emit(
            "# lagrange — API reference",
            "",
            "Generated by `docs/build_api.py` from the docstrings (do not edit by hand; re-run the script).",
            "Conventions are stated once in [guide.md](guide.md). Docstrings are quoted verbatim",
            "(reStructuredText, as written in the source).",
            "",
            "## Contents",
            "",
            "* [`lagrange` (top-level API)](#lagrange)",
        )
        for name in [*MODULES, *EXTRA_MODULES]:
            self.emit(f"* [`{name}`](#{anchor(name)})")
        self.emit("")

        # --- top level ---------------------------------------------------------------------------
        self.emit('<a id="lagrange"></a>', "", "## `lagrange`", "")
        self.module_docstring(lagrange)
        for name in lagrange.__all__:
            obj = getattr(lagrange, name)
            self.entry(f"lagrange.{name}", obj)
            if kind(obj) != "data":
                self.top_level[id(obj)] = f"lagrange.{name}"

        # --- modules -----------------------------------------------------------------------------
        for modname in [*MODULES, *EXTRA_MODULES]:
            module = importlib.import_module(modname)
            self.emit(f'<a id="{anchor(modname)}"></a>', "", f"## `{modname}`", "")
            self.module_docstring(module)
            for name in EXTRA_MODULES.get(modname) or self.public_names(module):
                obj = getattr(module, name)
                if id(obj) in self.top_level:
                    ref = self.top_level[id(obj)]
                    self.emit(f"* `{modname}.{name}`: see [`{ref}`](#{anchor(ref)}).", "")
                    continue
                self.entry(f"{modname}.{name}", obj)

        text = "\n".join(self.out).rstrip() + "\n"
        return re.sub(r"\n{3,}", "\n\n", text)


def main(argv: list[str]) -> int:
    out = Path(argv[1]) if len(argv) > 1 else Path(__file__).resolve().parent / "api.md"
    builder = Builder()
    text = builder.build()
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(text, encoding="utf-8")
    print(f"wrote {out} ({len(text.splitlines())} lines)", file=sys.stderr)
    if builder.missing:
        print(f"{len(builder.missing)} entries without a docstring:", file=sys.stderr)
        for name in builder.missing:
            print(f"  {name}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
