"""Fuzz the whole derive path with growth-prone expressions, each in a subprocess under a CPU and memory limit.

Every case declares a system whose potential V is a hostile expression (or, for the many-coordinate
cases, a large system) and runs what ``lagrange derive`` and the first half of ``lagrange simulate`` do:
the spec is parsed (TOML route) or the System is built (Python route), the equations are derived, printed
as the CLI prints them (with the conserved momenta), and compiled (CSE and code generation). A case must
end within the limits either

* in a :class:`~lagrange.errors.LagrangeError` (a ``SpecError`` from the parser, an ``ExpressionTooLarge``
  naming the stage), or
* with a correct result: M equals the declared mass matrix and every generalized force equals ``−∂V/∂q``
  computed independently (plain ``sympy.diff`` of the declared V), checked at random points.

A case that is killed by the limits, raises anything else, or derives a wrong result is a failure.

Usage::

    python benchmarks/fuzz_derive.py                 # the default cases, each in a fresh interpreter
    python benchmarks/fuzz_derive.py --random 200    # plus 200 random growth-prone expressions
    python benchmarks/fuzz_derive.py --markdown      # a table for docs/guarantees.md

The figures (CPU seconds and peak memory of each child, imports included) are measured by ``os.wait4``.
"""

from __future__ import annotations

import argparse
import json
import os
import random
import resource
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass

#: per-case limits of the child process
CPU_SECONDS = 60
MEMORY_BYTES = 2 * 1024**3


@dataclass(frozen=True)
class Case:
    """One fuzz case. ``route`` is "spec" (V written as TOML text and parsed by the spec parser), "api" (V
    built with sympy's operators and given to :class:`~lagrange.System`), or "oscillators"/"chain" (``tree``
    is the number of coordinates). ``tree`` describes V (see :func:`build` and :func:`render`); ``expect`` is
    "ok", "refused" or "either"."""

    label: str
    route: str
    tree: object
    expect: str = "either"

    @property
    def text(self) -> str:
        return str(self.tree) if self.route in ("oscillators", "chain") else render(self.tree)


# An expression tree: ["sum", [atoms]] (atoms "x", "-y", "m", "1"), ["pow", tree, exponent],
# ["exp", tree], ["explog", factor, tree] = exp(factor*log(tree)), ["fn", name, tree], ["mul", a, b],
# ["add", a, b], ["const", number]. Exponents and numbers: "7", "99/2", "99.5" (a float), "10**30".

def render(tree) -> str:
    """The spec text of ``tree``."""
    op = tree[0]
    if op == "sum":
        return "(" + "+".join(tree[1]) + ")"
    if op == "pow":
        return f"{render(tree[1])}**({tree[2]})"
    if op == "exp":
        return f"exp({render(tree[1])})"
    if op == "explog":
        return f"exp({tree[1]}*log({render(tree[2])}))"
    if op == "fn":
        return f"{tree[1]}({render(tree[2])})"
    if op in ("mul", "add"):
        return render(tree[1]) + ("*" if op == "mul" else "+") + render(tree[2])
    return f"({tree[1]})"


def _number(text: str):
    import sympy as sp

    if "**" in text:
        base, exp = text.split("**")
        return sp.Integer(int(base)) ** int(exp)
    if "." in text or "e" in text:
        return sp.Float(float(text))
    if "/" in text:
        a, b = text.split("/")
        return sp.Rational(int(a), int(b))
    return sp.Integer(int(text))


def build(tree, names: dict):
    """``tree`` built with sympy's operators (no string is parsed): what a Python user would write."""
    import sympy as sp

    op = tree[0]
    if op == "sum":
        return sp.Add(*((-names[a[1:]] if a.startswith("-") else names[a]) if not a.lstrip("-").isdigit()
                        else sp.Integer(int(a)) for a in tree[1]))
    if op == "pow":
        return build(tree[1], names) ** _number(tree[2])
    if op == "exp":
        return sp.exp(build(tree[1], names))
    if op == "explog":
        return sp.exp(_number(tree[1]) * sp.log(build(tree[2], names)))
    if op == "fn":
        return getattr(sp, tree[1])(build(tree[2], names))
    if op == "mul":
        return build(tree[1], names) * build(tree[2], names)
    if op == "add":
        return build(tree[1], names) + build(tree[2], names)
    return _number(tree[1])


_S6 = ["sum", ["x", "y", "m", "g", "k", "1"]]
_S3 = ["sum", ["x", "y", "1"]]
_X = ["sum", ["x"]]
_TOWER5 = ["exp", ["exp", ["exp", ["exp", ["exp", _X]]]]]

#: the default hostile set: every expression of issue #21 on both routes, and the other growth-prone forms
DEFAULT_CASES = (
    Case("rational power of a 6-term sum (issue #21)", "spec", ["pow", _S6, "99/2"], "refused"),
    Case("rational power of a 6-term sum (issue #21)", "api", ["pow", _S6, "99/2"], "ok"),
    Case("exp of a 20th power (issue #21)", "spec", ["exp", ["pow", _S3, "20"]], "ok"),
    Case("exp of a 20th power (issue #21)", "api", ["exp", ["pow", _S3, "20"]], "ok"),
    Case("exp(c*log(x)) = x**(10**30) (issue #21)", "spec", ["explog", "10**30", _X], "refused"),
    Case("exp(c*log(x)) = x**(10**30) (issue #21)", "api", ["explog", "10**30", _X], "refused"),
    Case("tower of five exponentials (issue #21)", "spec", _TOWER5, "refused"),
    Case("tower of five exponentials (issue #21)", "api", _TOWER5, "refused"),
    Case("300 uncoupled oscillators (issue #21)", "oscillators", 300, "ok"),
    Case("float power of a sum", "spec", ["pow", _S3, "99.5"], "refused"),
    Case("float exponent 1e30", "api", ["pow", _X, "1e30"], "refused"),
    Case("tower of three exponentials", "api", ["exp", ["exp", ["exp", ["pow", ["sum", ["x", "y"]], "2"]]]], "ok"),
    Case("product of 20th powers", "api", ["mul", ["pow", _S3, "20"], ["pow", ["sum", ["x", "-y", "2"]], "20"]], "ok"),
    Case("trigonometric powers", "api", ["mul", ["pow", ["fn", "sin", ["sum", ["x", "y"]]], "40"],
                                         ["pow", ["fn", "cos", ["sum", ["x", "-y"]]], "40"]], "ok"),
    Case("coefficient 10**400", "api", ["mul", ["const", "10**400"], ["pow", _X, "2"]], "refused"),
    Case("power at the exponent limit", "api", ["pow", ["sum", ["x", "y", "1"]], "1000"], "ok"),
)


def _chain_system(n: int, kind: str):
    import sympy as sp

    import lagrange as lg

    qs = lg.coordinates(" ".join(f"q{i}" for i in range(n)))
    m, k = lg.parameters("m k")
    T = m * sp.Add(*(sp.diff(q, lg.t) ** 2 for q in qs)) / 2
    if kind == "oscillators":
        V = k * sp.Add(*(q**2 for q in qs)) / 2
    else:  # a chain of springs between neighbours, ends fixed
        V = k * (qs[0] ** 2 + sp.Add(*((qs[i + 1] - qs[i]) ** 2 for i in range(n - 1))) + qs[-1] ** 2) / 2
    return lg.System(qs, T=T, V=V, name=f"{n} {kind}"), {"m": 1.0, "k": 4.0}


def _api_system(tree):
    import sympy as sp

    import lagrange as lg

    x, y = lg.coordinates("x y")
    m, g, k = lg.parameters("m g k")
    V = build(tree, {"x": x, "y": y, "m": m, "g": g, "k": k})
    T = m * (sp.diff(x, lg.t) ** 2 + sp.diff(y, lg.t) ** 2) / 2
    return lg.System([x, y], T=T, V=V, name="fuzz"), {"m": 1.0, "g": 1.0, "k": 1.0}


def _spec_system(text: str):
    from lagrange.spec.loader import load_toml

    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "fuzz.toml")
        with open(path, "w", encoding="utf-8") as fh:
            fh.write('coordinates = ["x", "y"]\nparameters = ["m", "g", "k"]\nT = "m*(x_dot**2 + y_dot**2)/2"\n'
                     f'V = {json.dumps(text)}\n[params]\nm = 1\ng = 1\nk = 1\n')
        from pathlib import Path

        spec = load_toml(Path(path))
    return spec.system, {"m": 1.0, "g": 1.0, "k": 1.0}


def _correct(system) -> str:
    """"" when M and f agree with an independent derivation (M from T's Hessian, f = −∂V/∂q by plain
    ``sympy.diff``) at random points, else what disagrees."""
    import sympy as sp

    from lagrange.model.coordinates import to_symbols

    eqs = system.derived
    V = to_symbols(system.V, system.coordinates)
    T = to_symbols(system.T, system.coordinates)
    rnd = random.Random(7)
    if eqs.n > 10:  # a large system: M must be diagonal (checked below for a few coordinates, counted here)
        if sum(1 for e in eqs.mass_matrix if e != 0) != eqs.n:
            return "M is not diagonal"
    for i, q in enumerate(eqs.q):
        if eqs.n > 10 and i not in (0, 1, eqs.n - 1):
            continue
        want_f = -sp.diff(V, q)
        for j in (i,) if eqs.n > 10 else range(eqs.n):
            want_m = sp.diff(T, eqs.qd[i], eqs.qd[j])
            if sp.expand(want_m - eqs.mass_matrix[i, j]) != 0:
                return f"M[{i},{j}] = {eqs.mass_matrix[i, j]}, expected {want_m}"
        for _ in range(3):
            at = {s: sp.Rational(rnd.randint(1, 9), 10) for s in (*eqs.q, *eqs.qd, *eqs.parameters)}
            got, want = (e.xreplace(at).evalf(30) for e in (eqs.forcing[i], want_f))  # any exponent range
            if not (got.is_finite and want.is_finite):
                continue
            if abs(got - want) > sp.Float(1e-20, 30) * max(1, abs(want)):
                return f"f[{i}] = {sp.Float(got, 5)} at {at}, expected {sp.Float(want, 5)}"
    return ""


def run_in_child(case: Case) -> dict:
    """The body of one child process: the whole derive path for ``case``; a JSON-able outcome."""
    from lagrange.errors import LagrangeError
    from lagrange.printing import format_equations, format_momenta

    try:
        if case.route == "spec":
            system, params = _spec_system(render(case.tree))
        elif case.route == "api":
            system, params = _api_system(case.tree)
        else:
            system, params = _chain_system(int(case.tree), case.route)
        _ = system.derived
        text = format_equations(system) + format_momenta(system)
        declared = {p.name for p in system.parameters}
        system.compile({name: v for name, v in params.items() if name in declared})
        wrong = _correct(system)
    except LagrangeError as exc:
        return {"outcome": "refused", "error": type(exc).__name__, "message": str(exc)[:300]}
    return {"outcome": "wrong" if wrong else "ok", "message": wrong, "printed_lines": text.count("\n") + 1}


def _address_space() -> int:
    """This process's current virtual size in bytes (0 where /proc is missing)."""
    try:
        with open("/proc/self/status", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("VmSize:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    return 0


def _limits(forked: bool = False) -> None:
    """CPU and memory limits of a child. A fork inherits its parent's address space (a test worker that has
    loaded numba's or heyoka's LLVM reserves gigabytes of it), so its limit is that size plus the budget."""
    resource.setrlimit(resource.RLIMIT_CPU, (CPU_SECONDS, CPU_SECONDS + 5))
    limit = MEMORY_BYTES + (_address_space() if forked else 0)
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


def run_case(case: Case, *, fresh: bool = True) -> dict:
    """Run ``case`` in a child process under :data:`CPU_SECONDS` and :data:`MEMORY_BYTES`; the outcome with
    the child's CPU seconds and peak memory (MiB). ``fresh``: a new interpreter (imports counted); else a
    fork of this process (lagrange already imported: the test suite's cheap variant)."""
    start = time.monotonic()
    if fresh:
        cmd = [sys.executable, os.path.abspath(__file__), "--child", json.dumps(case.__dict__)]
        with tempfile.TemporaryFile() as errfile:
            proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=errfile, preexec_fn=_limits)
            out = proc.stdout.read()
            proc.stdout.close()
            _, status, usage = os.wait4(proc.pid, 0)  # the child's own CPU time and peak memory
            proc.returncode = code = os.waitstatus_to_exitcode(status)
            errfile.seek(0)
            stderr = errfile.read().decode(errors="replace")[-500:]
        text = out.decode(errors="replace").strip().splitlines()
    else:
        import lagrange.printing  # noqa: F401 - imported before the fork

        r, w = os.pipe()
        pid = os.fork()
        if pid == 0:  # the child
            os.close(r)
            try:
                _limits(forked=True)
                result = json.dumps(run_in_child(case))
            except BaseException as exc:  # noqa: BLE001 - reported to the parent, which fails the case
                result = json.dumps({"outcome": "crash", "error": type(exc).__name__, "message": str(exc)[:300]})
            os.write(w, result.encode() + b"\n")
            os._exit(0)
        os.close(w)
        chunks = []
        while chunk := os.read(r, 65536):
            chunks.append(chunk)
        os.close(r)
        _, status, usage = os.wait4(pid, 0)
        code = os.waitstatus_to_exitcode(status)
        text = b"".join(chunks).decode(errors="replace").strip().splitlines()
        stderr = ""
    result = json.loads(text[-1]) if text else {"outcome": "killed", "message": f"exit {code}: {stderr}"}
    result.update(label=case.label, route=case.route, text=case.text, expect=case.expect, exit=code,
                  cpu=round(usage.ru_utime + usage.ru_stime, 2), mib=round(usage.ru_maxrss / 1024, 1),
                  wall=round(time.monotonic() - start, 2))
    return result


def passed(result: dict) -> bool:
    """A case passes when it ended in a LagrangeError or a correct result, as expected."""
    if result["outcome"] not in ("ok", "refused"):
        return False
    return result["expect"] in ("either", result["outcome"])


def random_cases(n: int, seed: int = 0) -> list[Case]:
    """``n`` random growth-prone expression trees in x, y and the parameters, alternately on each route."""
    rnd = random.Random(seed)
    atoms = ["x", "y", "m", "g", "k", "1", "2", "-x"]

    def tree(depth):
        kind = rnd.randrange(7)
        if depth == 0 or kind == 0:
            return ["sum", [rnd.choice(atoms) for _ in range(rnd.randint(2, 6))]]
        if kind == 1:
            return ["pow", tree(depth - 1), rnd.choice(["3", "7", "20", "50", "99/2", "99.5", "1/3", "-5", "1000",
                                                          "10**30"])]
        if kind == 2:
            return ["exp", tree(depth - 1)]
        if kind == 3:
            return ["explog", rnd.choice(["3", "10**30", "1/2", "200"]), tree(depth - 1)]
        if kind == 4:
            return ["fn", rnd.choice(["sin", "cos", "cosh", "sqrt"]), tree(depth - 1)]
        return ["mul" if kind == 5 else "add", tree(depth - 1), tree(depth - 1)]

    return [Case(f"random {i}", "api" if i % 2 else "spec", tree(rnd.randint(1, 4))) for i in range(n)]


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--child", help=argparse.SUPPRESS)
    ap.add_argument("--random", type=int, default=0, help="also run this many random expressions")
    ap.add_argument("--no-default", action="store_true", help="skip the default cases")
    ap.add_argument("--markdown", action="store_true", help="print a markdown table")
    args = ap.parse_args(argv)
    if args.child:
        print(json.dumps(run_in_child(Case(**json.loads(args.child)))))
        return 0
    cases = ([] if args.no_default else list(DEFAULT_CASES)) + random_cases(args.random)
    results, failures = [], 0
    for case in cases:
        r = run_case(case)
        results.append(r)
        ok = passed(r)
        failures += not ok
        print(f"{'PASS' if ok else 'FAIL'} {r['cpu']:6.2f} s {r['mib']:7.1f} MiB  {r['route']:<11} {r['outcome']:<8}"
              f" {case.text[:60]!s:<60} {r.get('error', '')} {'' if ok else r.get('message', '')}", flush=True)
    worst_cpu = max(results, key=lambda r: r["cpu"])
    worst_mem = max(results, key=lambda r: r["mib"])
    print(f"{len(results)} cases, {failures} failures; worst CPU {worst_cpu['cpu']} s ({worst_cpu['text'][:50]}, "
          f"{worst_cpu['route']}), worst memory {worst_mem['mib']} MiB ({worst_mem['text'][:50]}, "
          f"{worst_mem['route']})")
    if args.markdown:
        print("\n| case | route | outcome | CPU s | MiB |\n|---|---|---|---|---|")
        for r in results:
            print(f"| {r['label']} | {r['route']} | {r['outcome']} {r.get('error', '')} | {r['cpu']} | {r['mib']} |")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
