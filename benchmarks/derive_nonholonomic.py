"""3-D, non-holonomic derivation speed: the Whipple bicycle and the rolling disc, lagrange against sympy's
KanesMethod on the same model, declare / derive / compile broken out (issue #23, item 1).

Each cell runs in a fresh process (sympy's caches cold; imports — sympy, numpy, lagrange, symengine — and
sympy's deferred imports done first and **not** timed); the three routes alternate (structural, expanded, Kane,
…) so all see the same machine load; CPU time (``time.process_time``) and wall time are reported, median
over the repetitions.

* **lagrange (structural)** and **lagrange (expanded)**: ``System(..., derivation=...)``; *declare* builds the
  :class:`lagrange.System` (bodies, constraints, validation, the Frobenius test of each non-holonomic
  constraint; the expanded route also builds the whole T); *derive* is ``system.derived`` (structural: each
  body's kinematics J, a, W, α, :mod:`lagrange.derive.structural`; expanded: ``lagrange_equations``, the on-disk
  derivation cache off); *compile* is ``system.compile(params)`` (default Python backend: CSE, generated
  source, ``exec``; the equations derived once, in *derive*).
* **KanesMethod**: *declare* builds frames, points, bodies, loads and the ``KanesMethod`` object; *derive* is
  ``kanes_equations``; *compile* is ``lambdify(..., cse=True)`` of ``mass_matrix_full`` and ``forcing_full``
  (sympy's fastest documented route to a callable).

Models. Bicycle: lagrange's corpus problem ``bicycle`` (Meijaard et al. 2007: 8 coordinates, 4 rolling
constraints, 1 holonomic); Kane: sympy's own Whipple bicycle (``sympy/physics/mechanics/tests/test_kane3.py``,
Moore's port of the Autolev model: 4 coordinates, 6 speeds, 3 velocity constraints, the wheel angles and the
contact position left out) — the same bicycle, each in its tool's idiomatic form. Rolling disc: contact point
(x, y), yaw, lean and spin, rolling without slip as 2 non-holonomic constraints (the contact point's material
velocity), in both tools. Writes ``benchmarks/results/derive_nonholonomic.md``::

    python benchmarks/derive_nonholonomic.py [--quick] [--reps N]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

RESULTS = Path(__file__).parent / "results"
HERE = Path(__file__).resolve().parent

_PRELUDE = r"""
import json, os, sys, time
os.environ["LAGRANGE_DERIVATION_CACHE"] = "0"
if os.environ.get("BENCH_NO_SYMENGINE") == "1":
    sys.modules["symengine"] = None  # as if not installed: lagrange takes its sympy-only path
import numpy as np, sympy as sp
import sympy.physics.mechanics as me
import lagrange
from lagrange.bench.first_result import _warm_sympy
_warm_sympy()
try:
    import symengine  # noqa: F401 - an import, not timed
except ImportError:
    pass
_marks = []
def mark():
    _marks.append((time.process_time(), time.perf_counter()))
"""

_LAGRANGE_BICYCLE = r"""
from lagrange_problems import bench_bicycle as bb
mark(); system = bb.whipple_bicycle(derivation=DERIVATION)
mark(); eqs = system.derived
mark(); model = system.compile(bb.PARAMS)
mark()
"""

_LAGRANGE_DISC = r"""
from lagrange import Nonholonomic, RigidBody, RotationSequence, System, coordinates, parameters, t
mark()
x, y, q1, q2, q3 = coordinates("x y q1 q2 q3")
m, g, r = parameters("m g r")
orientation = RotationSequence(("z", q1), ("x", q2), ("y", q3))
lean = lagrange.rot_z(q1) * lagrange.rot_x(q2)
centre = sp.Matrix([x, y, 0]) + r * lean * sp.Matrix([0, 0, 1])
disc = RigidBody(m, (m * r**2 / 4, m * r**2 / 2, m * r**2 / 4), origin=centre, orientation=orientation)
omega = orientation.space_angular_velocity()
v_contact = centre.diff(t) + omega.cross(-r * lean * sp.Matrix([0, 0, 1]))
system = System([x, y, q1, q2, q3], bodies=[disc], V=m * g * centre[2], derivation=DERIVATION,
                constraints=[Nonholonomic(v_contact[0], "roll x"), Nonholonomic(v_contact[1], "roll y")])
mark(); eqs = system.derived
mark(); model = system.compile({m: 2.0, g: 9.81, r: 0.4})
mark()
"""

_KANE_DISC = r"""
mark()
x, y, q1, q2, q3 = me.dynamicsymbols("x y q1 q2 q3")
us = me.dynamicsymbols("u1:6")
m, g, r = sp.symbols("m g r", positive=True)
N = me.ReferenceFrame("N")
Y = N.orientnew("Y", "Axis", [q1, N.z])
L = Y.orientnew("L", "Axis", [q2, Y.x])
R = L.orientnew("R", "Axis", [q3, L.y])
O = me.Point("O")
O.set_vel(N, 0)
C = O.locatenew("C", x * N.x + y * N.y)
Dmc = C.locatenew("Dmc", r * L.z)
Dmc.set_vel(N, Dmc.pos_from(O).dt(N))
disc = me.RigidBody("disc", Dmc, R, m, (me.inertia(L, m * r**2 / 4, m * r**2 / 2, m * r**2 / 4), Dmc))
P = Dmc.locatenew("P", -r * L.z)
vP = P.v2pt_theory(Dmc, N, R)
qs = [x, y, q1, q2, q3]
kd = [q.diff(me.dynamicsymbols._t) - u for q, u in zip(qs, us)]
km = me.KanesMethod(N, qs, us[2:], kd_eqs=kd, u_dependent=us[:2], velocity_constraints=[vP.dot(N.x), vP.dot(N.y)])
loads = [(Dmc, -m * g * N.z)]
mark(); km.kanes_equations([disc], loads)
mark(); f = sp.lambdify([qs, us, [m, g, r]], [km.mass_matrix_full, km.forcing_full], cse=True)
mark()
"""


def _kane_bicycle_source() -> str:
    """sympy's test_kane3 bicycle up to ``kanes_equations``, split into the three phases."""
    import sympy.physics.mechanics.tests.test_kane3 as k3

    lines = Path(k3.__file__).read_text().splitlines()
    start = next(i for i, s in enumerate(lines) if "q1, q2, q4, q5 = dynamicsymbols" in s)
    stop = next(i for i, s in enumerate(lines) if "KM.kanes_equations(BL, FL)" in s)
    body = [s[4:] for s in lines[start:stop]]  # the test function's body, dedented
    return ("from sympy import *\nfrom sympy.physics.mechanics import *\nmark()\n" + "\n".join(body)
            + "\nmark(); (fr, frstar) = KM.kanes_equations(BL, FL)\n"
            + "mark(); params = sorted(KM.mass_matrix_full.free_symbols | KM.forcing_full.free_symbols, key=str)\n"
            + "f = lambdify([KM.q, KM.u, params], [KM.mass_matrix_full, KM.forcing_full], cse=True)\nmark()\n")


_EPILOGUE = r"""
cpu = [b[0] - a[0] for a, b in zip(_marks, _marks[1:])]
wall = [b[1] - a[1] for a, b in zip(_marks, _marks[1:])]
print(json.dumps({"cpu": cpu, "wall": wall}))
"""


#: the tools compared: lagrange's two derivations (``System(derivation=...)``) and sympy's KanesMethod;
#: ``--without-symengine`` adds both derivations with symengine hidden (the sympy-only path, item 6 of issue #23)
TOOLS = ("structural", "expanded", "kane")
NO_SYMENGINE = ("structural, no symengine", "expanded, no symengine")


def run(tool: str, model: str) -> dict:
    if tool == "kane":
        body = _KANE_DISC if model == "disc" else _kane_bicycle_source()
    else:
        body = f"DERIVATION = {tool.split(',')[0]!r}\n" + (_LAGRANGE_BICYCLE if model == "bicycle" else _LAGRANGE_DISC)
    env = dict(os.environ)
    env["BENCH_NO_SYMENGINE"] = "1" if tool.endswith("no symengine") else "0"
    r = subprocess.run([sys.executable, "-c", _PRELUDE + body + _EPILOGUE], capture_output=True, text=True,
                       timeout=900, env=env)
    if r.returncode != 0:
        raise RuntimeError(f"{tool} {model}: {r.stderr[-3000:]}")
    return json.loads(r.stdout.strip().splitlines()[-1])


def main() -> None:
    import numpy as np

    from lagrange.bench.report import machine_info

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="one repetition, the rolling disc only (< 60 s)")
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--without-symengine", action="store_true",
                    help="also run both derivations with symengine hidden (sympy-only CSE and printing)")
    ap.add_argument("--models", default=None, help="comma-separated subset of bicycle,disc")
    ap.add_argument("--out", default="derive_nonholonomic.md", help="file name under benchmarks/results/")
    args = ap.parse_args()
    models = ["disc"] if args.quick else ["bicycle", "disc"]
    if args.models:
        models = [m for m in args.models.split(",") if m in ("bicycle", "disc")]
    tools = TOOLS + (NO_SYMENGINE if args.without_symengine else ())
    reps = 1 if args.quick else args.reps
    cells: dict = {(tool, mdl): [] for mdl in models for tool in tools}
    for _ in range(reps):
        for mdl in models:
            for tool in tools:  # interleaved: A, B, C, A, B, C, …
                out = run(tool, mdl)
                cells[tool, mdl].append(out)
                print(tool, mdl, " ".join(f"{c:.2f}" for c in out["cpu"]), flush=True)

    def med(tool, mdl, kind, k=None):
        rows = cells[tool, mdl]
        vals = [sum(r[kind]) if k is None else r[kind][k] for r in rows]
        return float(np.median(vals))

    m = machine_info()
    lines = ["# 3-D and non-holonomic derivation: lagrange against sympy's KanesMethod", "",
             f"Machine: {m['cpu']}, {m['cores']} logical cores, shared with other jobs (ratios from one run, "
             "interleaved; absolute times are noisy). Versions: "
             + ", ".join(f"{k} {v}" for k, v in m["versions"].items() if v) + ".", "",
             f"Median of {reps} fresh processes per cell; imports and sympy's deferred imports not timed. "
             "See the docstring of `benchmarks/derive_nonholonomic.py` for what each phase covers and the two "
             "bicycle formulations.", "",
             "| model | tool | declare CPU | derive CPU | compile CPU | total CPU | total wall "
             "| Kane / lagrange (CPU) |",
             "|---|---|---|---|---|---|---|---|"]
    for mdl in models:
        for tool in tools:
            ph = [med(tool, mdl, "cpu", k) for k in range(3)]
            tot, wall = med(tool, mdl, "cpu"), med(tool, mdl, "wall")
            ratio = med("kane", mdl, "cpu") / med(tool, mdl, "cpu")
            label = "sympy KanesMethod" if tool == "kane" else f"lagrange ({tool})"
            lines.append(f"| {mdl} | {label} | {ph[0]:.2f} s | {ph[1]:.2f} s | {ph[2]:.2f} s | {tot:.2f} s "
                         f"| {wall:.2f} s | {f'×{ratio:.2f}' if tool != 'kane' else ''} |")
    text = "\n".join(lines) + "\n"
    print(text)
    if not args.quick:
        RESULTS.mkdir(exist_ok=True)
        (RESULTS / args.out).write_text(text)
        print(f"wrote {RESULTS / args.out}")


if __name__ == "__main__":
    main()
