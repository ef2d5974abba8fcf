"""Time to first result: derivation + code generation/compilation + one integration, cold.

Each route runs in a fresh Python process — three, median by total, when it takes under a second — (after its
imports, numba's included, and after sympy's deferred imports: sympy loads ``sympy.tensor`` and
``sympy.combinatorics`` on the first ``Add`` it builds, ~25 ms that every route pays once — heyoka's too, in the
untimed ``build`` that forms T − V) with empty lagrange, numba and heyoka caches (``*_primed`` routes: an earlier
process compiled the generic kernel, as after a first use; ``*_rerun`` routes: the same run once before):
``LAGRANGE_CACHE_DIR``, ``NUMBA_CACHE_DIR`` and ``XDG_CACHE_HOME`` (where heyoka keeps compiled code on disk,
``heyoka/cache.db``: a second process with the same equations skips LLVM, about 10 ms instead of 80–100 ms) point
to a new temporary directory, so JIT and LLVM compilation are paid as a new user pays them. heyoka's "derive" is
``heyoka.lagrangian`` on the T − V that lagrange formed (forming it is not counted, which favours heyoka).

Bytecode: lagrange's own modules are byte-compiled (``compileall``) before anything is timed, as ``pip
install`` does for every installed package (sympy's, scipy's and heyoka's ``.pyc`` files come from their
installs). Without it an editable install run with ``PYTHONDONTWRITEBYTECODE=1`` (set on the benchmark
machine) recompiles lagrange's sources in every fresh process: about 10–15 ms of each first result (modules
imported on first use) and part of ``import lagrange``.

CPU time: each phase is also timed with ``time.process_time`` in the child (``cpu``: derive + compile +
integrate, imports not counted), and the parent reads the whole child process's CPU time (interpreter start and
imports counted) from ``resource.getrusage(RUSAGE_CHILDREN)`` (``process_cpu``, with its wall time
``process_wall``). An N-link pendulum can be built with extra :class:`~lagrange.System` keywords
(``system_kwargs``, e.g. ``{"derivation": "structural"}``).

Run one route by hand: ``python -m lagrange.bench.first_result '{"problem": "kepler", "route": "python"}'``.
"""

from __future__ import annotations

import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from functools import lru_cache
from pathlib import Path

import numpy as np

from ..records import record

__all__ = ["ROUTES", "FirstResult", "first_result", "first_result_once", "median_by_total", "routes_for",
           "import_times", "byte_compile_lagrange"]

#: what each package costs to import in a fresh process (:func:`import_times`; not in the route timings)
IMPORTS = {
    "lagrange": "import lagrange, sympy; sympy.Symbol('x') + sympy.Symbol('y')",
    "numba": "import numba",
    "heyoka": "import heyoka",
}

#: route → label
ROUTES = {
    "python": "lagrange, python backend, DOP853",
    "numba": "lagrange, numba backend (cold JIT), DOP853, scipy loop",
    "compiled": "lagrange, numba compiled loop (cold JIT), DOP853",
    "compiled_primed": "lagrange, numba compiled loop, DOP853, loops compiled by an earlier process (new model)",
    "taylor": "lagrange, taylor (interpreted tape), empty caches: includes the one-time build of the interpreter",
    "taylor_primed": "lagrange, taylor (interpreted tape), interpreter built by an earlier process (new model)",
    "taylor_numba_primed": "lagrange, taylor without C (the compiled series: numba JIT of the new model's "
                           "series), driver compiled by an earlier process",
    "python_rerun": "lagrange, python backend, DOP853, re-run (derivation and code from the on-disk cache)",
    "python_auto": "lagrange, python backend, method='auto' (its pick in the label note)",
    "taylor_rerun": "lagrange, taylor (interpreted tape), re-run (derivation, code and interpreter cached)",
    "sympy": "plain sympy.physics.mechanics + lambdify(cse) + solve_ivp DOP853",
    "sympy_kane": "sympy KanesMethod + lambdify(cse) + solve_ivp DOP853",
    "heyoka": "heyoka.py (lagrangian + taylor_adaptive, cold LLVM compile)",
    "heyoka_rerun": "heyoka.py, re-run (compiled code from heyoka's on-disk cache)",
    "heyoka_default": "heyoka.py, default mode (cold LLVM compile)",
}


#: what an earlier process leaves in the cache for the ``*_primed`` routes: the generic kernels only
_PRIME = {"taylor_primed": "from lagrange.integrate.taylor import interpreter; from lagrange.integrate.compiled "
                           "import kernel; interpreter() == 'c' or "
                           "kernel('_taylor_loop.py', 'taylorloop', 'taylor').entry('taylor_fn')",
          "taylor_numba_primed": "from lagrange.integrate.compiled import kernel; "
                                 "kernel('_taylor_loop.py', 'taylorloop', 'taylor').entry('taylor_fn')",
          "compiled_primed": "from lagrange.integrate.compiled import loops; loops()"}

#: routes that run the compiled series (numba) even where a C interpreter is available
_NO_C = ("taylor_numba_primed",)


@record(frozen=True)
class FirstResult:
    """Seconds spent deriving, compiling and integrating (None when the route failed: see ``note``)."""

    route: str
    derive: float | None
    compile: float | None
    integrate: float | None
    error: float | None
    note: str = ""
    cpu: float | None = None  # CPU seconds of derive + compile + integrate in the child (imports not counted)
    process_cpu: float | None = None  # CPU seconds of the whole child process (interpreter start, imports counted)
    process_wall: float | None = None  # wall seconds of the whole child process

    @property
    def total(self) -> float | None:
        if self.derive is None:
            return None
        return self.derive + self.compile + self.integrate


def routes_for(problem, *, heyoka: bool) -> list[str]:
    """The routes that apply to ``problem`` (numba ones only when numba is installed)."""
    import importlib.util

    from ..integrate.taylor import available_interpreter

    out = ["python", "python_rerun"] + ([] if problem.conservative else ["python_auto"])
    has_numba = importlib.util.find_spec("numba") is not None
    engine = available_interpreter()
    if has_numba:
        out += ["numba"]
        if problem.name != "stick_slip":  # no friction switches in the compiled loop
            out += ["compiled", "compiled_primed"]
    if engine and problem.name != "stick_slip":  # no sign() in a Taylor series
        out += ["taylor", "taylor_primed", "taylor_rerun"]
        if has_numba and engine == "c":
            out += ["taylor_numba_primed"]
    if problem.pendulum_links:
        out.append("sympy")
    if heyoka and problem.name != "stick_slip":
        out += ["heyoka", "heyoka_rerun"]
    return out


@lru_cache(maxsize=1)
def byte_compile_lagrange() -> bool:
    """Write the ``.pyc`` files of lagrange's modules (no-op when they are current); see the module docstring."""
    import compileall

    return bool(compileall.compile_dir(str(Path(__file__).resolve().parents[1]), quiet=2))


def import_times(repeats: int = 3) -> dict[str, float]:
    """Median seconds of each :data:`IMPORTS` statement in a fresh process (packages not installed are
    left out; lagrange byte-compiled first, :func:`byte_compile_lagrange`)."""
    import importlib.util

    byte_compile_lagrange()
    out = {}
    for name, stmt in IMPORTS.items():
        if importlib.util.find_spec(name) is None:
            continue
        code = f"import time; t0 = time.perf_counter(); {stmt}; print(time.perf_counter() - t0)"
        runs = []
        for _ in range(repeats):
            r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
            if r.returncode == 0 and r.stdout.strip():
                runs.append(float(r.stdout.strip().splitlines()[-1]))
        if runs:
            out[name] = float(np.median(runs))
    return out


def _warm_sympy() -> None:
    """Trigger sympy's deferred imports (``sympy.tensor``, ``sympy.combinatorics``: first ``Add``)."""
    import sympy as sp

    a, b = sp.symbols("a b")
    _ = (a + b) * 2


def _child(problem_name: str, route: str, tol: float, quick: bool, system_kwargs: dict | None = None) -> dict:
    out = _child_timed(problem_name, route, tol, quick, system_kwargs)
    out["cpu"] = time.process_time() - out.pop("cpu_start")
    return out


def _child_timed(problem_name: str, route: str, tol: float, quick: bool, system_kwargs) -> dict:
    """The route's phases; ``cpu_start`` in the result: the process time where its timed work began."""
    from .common import initial_vector
    from .problems import get_problem

    _warm_sympy()  # an import cost, not timed for any route
    p = get_problem(problem_name, quick=quick, system_kwargs=system_kwargs)
    times = p.times()
    if route.startswith(("numba", "compiled")) or route in _NO_C:
        import numba  # noqa: F401 - imports are not timed (heyoka's import is not either)
    if route in ("sympy", "sympy_kane"):
        from scipy.integrate import solve_ivp

        from .sympy_route import kane_pendulum_route, plain_pendulum_route

        # y0 = [q1..qN, q̇1..q̇N] straight from the problem: no lagrange derivation in this route
        n = p.pendulum_links
        y0 = np.array([p.initial[f"q{i + 1}"] for i in range(n)] + [p.initial[f"q{i + 1}_dot"] for i in range(n)])
        c0 = time.process_time()
        d, c, rhs = (plain_pendulum_route if route == "sympy" else kane_pendulum_route)(n, float(p.params["g"]))
        t0 = time.perf_counter()
        Y = solve_ivp(rhs, (0.0, p.t_end), y0, method="DOP853", rtol=tol, atol=tol * p.atol_scale, t_eval=times).y.T
        return dict(derive=d, compile=c, integrate=time.perf_counter() - t0, states=Y.tolist(), cpu_start=c0)
    c0 = time.process_time()
    t0 = time.perf_counter()
    system = p.build()
    derive = time.perf_counter() - t0
    if route.startswith("heyoka"):
        from .heyoka_adapter import heyoka_model

        c1 = time.process_time()
        _ = system.derived
        heyoka_untimed = time.process_time() - c1 + (c1 - c0)  # lagrange's build and derivation, not heyoka's
        hm = heyoka_model(system, p.params)
        y0 = initial_vector(p, system)
        ta, c = hm.integrator(y0, tol, compact=False if route == "heyoka_default" else None)
        t0 = time.perf_counter()
        Y, _ = hm.propagate(ta, y0, times)
        # heyoka's CPU: its derivation, compile and integration (forming T − V in lagrange is not counted)
        return dict(derive=hm.derive_s, compile=c, integrate=time.perf_counter() - t0, states=Y.tolist(),
                    note="compact_mode" if (hm.compact and route == "heyoka") else "", cpu_start=c0 + heyoka_untimed)
    backend = "python" if route.startswith(("python", "taylor")) else "numba"
    t0 = time.perf_counter()
    _ = system.derived  # a problem's build may leave the derivation to its first use: count it as derive
    derive += time.perf_counter() - t0
    t0 = time.perf_counter()
    model = system.compile(p.params, backend=backend)
    compile_s = time.perf_counter() - t0
    method = "taylor" if route.startswith("taylor") else "auto" if route == "python_auto" else "DOP853"
    loop = {"compiled": {"loop": "compiled"}, "numba": {"loop": "scipy"}}.get(route.split("_")[0], {})
    t0 = time.perf_counter()
    sol = system.simulate((0.0, p.t_end), p.initial, p.params, method=method, rtol=tol, atol=tol * p.atol_scale,
                          backend=backend, model=model, t_eval=times, **p.options, **loop)
    note = sol.method.split(" ")[0] if method == "auto" else ""
    if method == "taylor":
        note = "interpreter: " + ("C" if "tape, c" in sol.method else "numba")
    return dict(derive=derive, compile=compile_s, integrate=time.perf_counter() - t0, states=sol.y.tolist(),
                note=note, cpu_start=c0)


#: a route whose first result came within this many seconds is run twice more (median of three)
REPEAT_BELOW_S = 1.0


def first_result(problem, route: str, reference_states: np.ndarray, *, tol: float = 1e-10, quick: bool = False,
                 timeout: float = 400.0, system_kwargs: dict | None = None,
                 repeat_below: float = REPEAT_BELOW_S) -> FirstResult:
    """Run ``route`` on ``problem`` in a fresh process with empty caches; error against the reference.

    A result under ``repeat_below`` seconds (in full runs) is the median, by total, of three such processes
    (each with its own empty caches): one fresh process can be slowed by 50 % by what else the machine does.
    ``repeat_below=0`` runs once (a caller that interleaves routes repeats them itself: :func:`median_by_total`).
    """
    runs = [first_result_once(problem, route, reference_states, tol=tol, quick=quick, timeout=timeout,
                              system_kwargs=system_kwargs)]
    if not quick and runs[0].total is not None and runs[0].total < repeat_below:
        runs += [first_result_once(problem, route, reference_states, tol=tol, quick=quick, timeout=timeout,
                                   system_kwargs=system_kwargs) for _ in range(2)]
    return median_by_total(runs)


def median_by_total(runs: list[FirstResult]) -> FirstResult:
    """The median run by total time (failed runs left out; the first run when all failed)."""
    ok = sorted((r for r in runs if r.total is not None), key=lambda r: r.total)
    return ok[len(ok) // 2] if ok else runs[0]


def first_result_once(problem, route: str, reference_states: np.ndarray, *, tol: float = 1e-10,
                      quick: bool = False, timeout: float = 400.0, system_kwargs: dict | None = None) -> FirstResult:
    """One fresh process of ``route`` (see :func:`first_result`); a route that runs longer than ``timeout``
    seconds is killed and reported as timed out (``total`` None, ``note`` says so)."""
    byte_compile_lagrange()
    args = json.dumps(dict(problem=problem.name, route=route, tol=tol, quick=quick,
                           system_kwargs=system_kwargs or {}))
    with tempfile.TemporaryDirectory(prefix="lagrange-ttfr-") as tmp:
        # the derivation cache on, as by default (empty: a cold run pays for writing its entries)
        env = dict(os.environ, LAGRANGE_CACHE_DIR=tmp, NUMBA_CACHE_DIR=tmp, XDG_CACHE_HOME=tmp,
                   LAGRANGE_DERIVATION_CACHE="1")
        if route in _NO_C:
            env["LAGRANGE_C_TAYLOR"] = "0"
        if route.endswith("_primed"):  # an earlier process compiled the generic kernel, not this model
            subprocess.run([sys.executable, "-c", _PRIME[route]], env=env, capture_output=True, timeout=timeout)
        if route.endswith("_rerun"):  # the same run once before
            subprocess.run([sys.executable, "-m", "lagrange.bench.first_result", args], env=env, capture_output=True,
                           timeout=timeout)
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        w0 = time.perf_counter()
        try:
            out = subprocess.run([sys.executable, "-m", "lagrange.bench.first_result", args], env=env,
                                 capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return FirstResult(route, None, None, None, None, f"timed out after {timeout:g} s")
        wall = time.perf_counter() - w0
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        pcpu = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
    lines = [ln for ln in out.stdout.splitlines() if ln.startswith("{")]
    if out.returncode != 0 or not lines:
        msg = (out.stderr.strip().splitlines() or ["no output"])[-1]
        return FirstResult(route, None, None, None, None, msg[:200])
    r = json.loads(lines[-1])
    Y = np.array(r["states"])
    err = float(np.max(np.abs(Y - reference_states))) if Y.shape == reference_states.shape else None
    return FirstResult(route, r["derive"], r["compile"], r["integrate"], err, r.get("note", ""), r.get("cpu"), pcpu,
                       wall)


if __name__ == "__main__":  # pragma: no cover - exercised through first_result()
    a = json.loads(sys.argv[1])
    print(json.dumps(_child(a["problem"], a["route"], float(a.get("tol", 1e-10)), bool(a.get("quick", False)),
                            a.get("system_kwargs") or None)))
