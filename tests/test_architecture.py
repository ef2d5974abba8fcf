"""The package's structure, read from the source (ast): integration only consumes compiled models, and no
module of lagrange imports (directly or through others) itself."""

from __future__ import annotations

import ast
from pathlib import Path

import lagrange

ROOT = Path(lagrange.__file__).parent

#: what lagrange/integrate may take from lagrange/codegen: the compiled models' types, nothing that generates code
ALLOWED_FROM_CODEGEN = {"lagrange.codegen.numeric": {"NumericModel"},
                        "lagrange.codegen.hamiltonian_model": {"HamiltonianModel"}}
# TEMP until the taylor branch merges
TAYLOR_ALLOW: set[str] = set()


def _module_name(path: Path) -> str:
    parts = path.relative_to(ROOT.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imports(path: Path):
    """``(module imported, names taken from it)`` for every import statement anywhere in the file (top level,
    functions, methods), relative imports resolved."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    package = _module_name(path) if path.name == "__init__.py" else _module_name(path).rpartition(".")[0]
    for node in _executed(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                yield alias.name, ()
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[: len(base) - (node.level - 1)]
                module = ".".join(base + ([node.module] if node.module else []))
            else:
                module = node.module or ""
            yield module, tuple(a.name for a in node.names)


def _executed(tree):
    """Every node of ``tree`` except those under ``if TYPE_CHECKING:`` (never executed)."""
    todo = [tree]
    while todo:
        node = todo.pop()
        yield node
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.If) and "TYPE_CHECKING" in ast.unparse(child.test):
                todo.extend(child.orelse)
                continue
            todo.append(child)


def _modules() -> dict[str, Path]:
    return {_module_name(p): p for p in ROOT.rglob("*.py")}


def test_integrate_imports_no_sympy_and_only_model_types_from_codegen():
    offences = []
    for path in sorted((ROOT / "integrate").glob("*.py")):
        if path.name in TAYLOR_ALLOW:
            continue
        for module, names in _imports(path):
            if module == "sympy" or module.startswith("sympy."):
                offences.append(f"{path.name}: imports {module}")
            elif module == "lagrange.codegen" or module.startswith("lagrange.codegen."):
                allowed = ALLOWED_FROM_CODEGEN.get(module, set())
                extra = [n for n in names if n not in allowed] if names else [module]
                if extra:
                    offences.append(f"{path.name}: imports {', '.join(extra)} from {module}")
    assert not offences, "lagrange/integrate must not generate code (see its __init__):\n" + "\n".join(offences)


def test_the_rule_test_sees_function_level_imports(tmp_path):
    """The reader above finds imports inside functions, resolves relative ones, and so would catch a violation."""
    f = tmp_path / "lagrange" / "integrate" / "bad.py"
    f.parent.mkdir(parents=True)
    f.write_text("from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    import numba\n\n\ndef g():\n"
                 "    import sympy as sp\n    from ..codegen.cse import rename_map\n")
    global ROOT
    saved, ROOT = ROOT, tmp_path / "lagrange"
    try:
        found = list(_imports(f))
    finally:
        ROOT = saved
    assert ("sympy", ()) in found and ("lagrange.codegen.cse", ("rename_map",)) in found
    assert ("numba", ()) not in found  # TYPE_CHECKING imports never run


def _graph() -> dict[str, set[str]]:
    """Module → the lagrange modules it imports (a ``from pkg import sub`` of a submodule counts as importing
    ``pkg.sub``; names the package exports lazily through ``_EXPORTS`` are not imports of their modules)."""
    mods = _modules()
    graph: dict[str, set[str]] = {m: set() for m in mods}
    for name, path in mods.items():
        for module, names in _imports(path):
            if not module.startswith("lagrange"):
                continue
            targets = {f"{module}.{n}" for n in names if f"{module}.{n}" in mods}
            if module in mods and (module != "lagrange" or not targets):
                targets.add(module)
            graph[name] |= {t for t in targets if t != name and t != "lagrange"}  # lagrange: lazy (_lazy.py)
    return graph


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan)."""
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def test_no_import_cycles():
    cycles = _cycles(_graph())
    assert not cycles, "import cycles in lagrange/: " + "; ".join(" <-> ".join(c) for c in cycles)


def test_cycle_finder_finds_a_cycle():
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert _cycles({"a": {"b"}, "b": set()}) == []
