"""``import lagrange`` pays only for what is used (issue #23 item 5): checked in a fresh interpreter.

Not a timing test: it asserts which modules a fresh process has loaded, which does not depend on the load
of the machine. The time it costs is measured by ``benchmarks/imports.py``.
"""

import json
import subprocess
import sys

HEAVY = ("scipy", "scipy.integrate", "numba", "matplotlib", "pandas", "sympy", "symengine", "heyoka", "dask",
         "tqdm", "llvmlite")


def _loaded_after(code: str) -> set:
    probe = f"import sys\n{code}\nimport json\nprint(json.dumps(sorted(sys.modules)))"
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True, timeout=300)
    return set(json.loads(out.stdout.strip().splitlines()[-1]))


def test_import_lagrange_loads_no_heavy_dependency():
    loaded = _loaded_after("import lagrange")
    assert "lagrange" in loaded
    assert not loaded & set(HEAVY), sorted(loaded & set(HEAVY))


def test_declaring_a_system_loads_no_integrator_compiler_or_plotting():
    """Declaring and deriving needs sympy (and numpy), never scipy.integrate, numba, matplotlib or pandas."""
    code = ("import lagrange as lg\nx = lg.coordinates('x')\nk = lg.parameters('k')\n"
            "s = lg.System([x], bodies=[lg.Particle(1, (x,))], V=k * x**2 / 2)\n"
            "assert s.derived.n == 1")
    loaded = _loaded_after(code)
    assert "sympy" in loaded  # the probe really derived something
    unwanted = {"scipy.integrate", "numba", "matplotlib", "pandas"}
    assert not loaded & unwanted, sorted(loaded & unwanted)
