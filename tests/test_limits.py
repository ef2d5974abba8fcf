"""Budgets on the symbolic work actually done (lagrange.limits): a CPU-time deadline and a node budget, public
settings by argument and by environment variable.

Growth the size estimates miss ends within seconds — in a correct result (a clean-up that runs out of its share
is skipped; the equations are checked against an independent derivation) or in SymbolicTimeoutError /
ExpressionTooLarge naming the setting — and a model that derives in seconds is not refused: the Whipple bicycle
declared as in sympy.physics.mechanics' test_kane3 derives and agrees with KanesMethod's linearization.
"""

from __future__ import annotations

import random
import signal
import threading
import time

import numpy as np
import pytest
import sympy as sp
from scipy.optimize import brentq

import lagrange as lg
from lagrange import limits, t
from lagrange.errors import ExpressionTooLarge, OptionError, SymbolicTimeoutError

CPU_BOUND = 30.0  # CPU seconds any of the cases below may take at the default settings (the deadline is 8)


@pytest.fixture(autouse=True)
def _fresh_derivation_cache(tmp_path, monkeypatch):
    """Each test derives (a derivation loaded from the cache does no symbolic work, so no budget applies)."""
    monkeypatch.setenv("LAGRANGE_CACHE_DIR", str(tmp_path / "cache"))


def _cpu(fn):
    start = time.process_time()
    try:
        return fn(), None, time.process_time() - start
    except (SymbolicTimeoutError, ExpressionTooLarge) as exc:
        return None, exc, time.process_time() - start


def _check_against_hessian(system, eqs, rows=1):
    """M and f of ``eqs`` (their first ``rows`` rows) against M = ∂²T/∂q̇², f = ∂T/∂q − Σ ∂²T/∂q̇∂q q̇ − ∂V/∂q by
    plain sympy.diff (the independent derivation), in floats at a random point."""
    T, V = lg.to_symbols(system.T, system.coordinates), lg.to_symbols(system.V, system.coordinates)
    rnd = random.Random(7)
    n = eqs.n
    symbols = sorted(set(eqs.q) | set(eqs.qd) | set(eqs.parameters), key=str)
    point = [rnd.uniform(0.3, 0.9) for _ in symbols]

    def value(e):
        return float(sp.lambdify(symbols, e, "math")(*point))

    for i in range(min(rows, n)):
        dT = sp.diff(T, eqs.qd[i])
        for j in range(n):
            ref = value(sp.diff(dT, eqs.qd[j]))
            assert abs(value(eqs.mass_matrix[i, j]) - ref) <= 1e-9 * (1 + abs(ref))
        f_ref = value(sp.diff(T, eqs.q[i]) - sum(sp.diff(dT, eqs.q[j]) * eqs.qd[j] for j in range(n))
                      - sp.diff(V, eqs.q[i]))
        assert abs(value(eqs.forcing[i]) - f_ref) <= 1e-9 * (1 + abs(f_ref))


def _bounded_outcome(build, cpu_bound=CPU_BOUND):
    """Derive ``build()``'s system at the default settings: within ``cpu_bound`` CPU seconds, either equations that
    match the independent derivation or the budget's error naming the setting that raises it."""
    system = build()
    eqs, exc, cpu = _cpu(lambda: system.derived)
    assert cpu < cpu_bound, cpu
    if exc is not None:
        assert ("symbolic_timeout" in str(exc) and "LAGRANGE_SYMBOLIC_TIMEOUT" in str(exc)) or (
            "symbolic_budget" in str(exc) and "LAGRANGE_SYMBOLIC_BUDGET" in str(exc)), exc
        return "refused"
    _check_against_hessian(system, eqs)
    return "derived"


# --------------------------------------------------------------------------------------- growth-prone models

def nested_sines(depth, **kw):
    x, y = lg.coordinates("x y")
    m = lg.parameters("m")
    e = x + y
    for _ in range(depth):
        e = sp.sin(e)
    return lg.System([x, y], bodies=[lg.Particle(m, (e, y))], **kw)


def product_of_sines(n, **kw):
    qs = lg.coordinates(" ".join(f"q{i}" for i in range(n)))
    m = lg.parameters("m")
    e = sp.Mul(*[sp.sin(q) for q in qs])
    return lg.System(list(qs), T=m * e.diff(t) ** 2 / 2 + m * sum(q.diff(t) ** 2 for q in qs) / 2, **kw)


def product_of_factors(n, **kw):
    x, y = lg.coordinates("x y")
    m = lg.parameters("m")
    e = sp.Mul(*[sp.sin(x) + k * sp.cos(y) for k in range(1, n + 1)])
    return lg.System([x, y], T=m * (e.diff(t) ** 2 + x.diff(t) ** 2 + y.diff(t) ** 2) / 2, **kw)


def inverse_distance_bodies(n, **kw):
    m, G = lg.parameters("m G")
    r = lg.coordinates(" ".join(f"r{i}" for i in range(n)))
    a = lg.coordinates(" ".join(f"a{i}" for i in range(n)))
    pos = [(ri * sp.cos(ai), ri * sp.sin(ai)) for ri, ai in zip(r, a)]
    T = sum(m * (sp.diff(px, t) ** 2 + sp.diff(py, t) ** 2) / 2 for px, py in pos)
    V = -sum(G * m * m / sp.sqrt((pos[i][0] - pos[j][0]) ** 2 + (pos[i][1] - pos[j][1]) ** 2)
             for i in range(n) for j in range(i))
    return lg.System(list(r) + list(a), T=T, V=V, **kw)


@pytest.mark.parametrize("depth", [12, pytest.param(16, marks=pytest.mark.slow)])
def test_nested_sines_end_within_the_budget(depth):
    assert _bounded_outcome(lambda: nested_sines(depth)) in ("derived", "refused")


@pytest.mark.slow
def test_a_product_of_sines_over_14_coordinates_ends_within_the_budget():
    assert _bounded_outcome(lambda: product_of_sines(14)) in ("derived", "refused")


@pytest.mark.slow
def test_a_product_of_18_factors_ends_within_the_budget():
    assert _bounded_outcome(lambda: product_of_factors(18)) in ("derived", "refused")


@pytest.mark.slow
def test_a_30_body_inverse_distance_system_ends_within_the_budget():
    outcome = _bounded_outcome(lambda: inverse_distance_bodies(30), cpu_bound=60.0)  # its declaration alone: ~4 s
    assert outcome in ("derived", "refused")


def test_a_tight_timeout_ends_the_derivation_in_symbolic_timeout_error():
    system = inverse_distance_bodies(8, symbolic_timeout=0.2)
    _, exc, cpu = _cpu(lambda: system.derived)
    assert isinstance(exc, SymbolicTimeoutError) and isinstance(exc, TimeoutError)
    assert "0.2 CPU seconds" in str(exc) and "LAGRANGE_SYMBOLIC_TIMEOUT" in str(exc) and "derivation" in str(exc)
    assert cpu < 2.0
    assert inverse_distance_bodies(3, symbolic_timeout=0.2).derived.n == 6  # a small one derives within it


def test_a_small_budget_ends_the_derivation_in_expression_too_large():
    system = nested_sines(6, symbolic_budget=50)
    with pytest.raises(ExpressionTooLarge, match="more than 50 nodes.*LAGRANGE_SYMBOLIC_BUDGET") as exc:
        _ = system.derived
    assert "derivation" in exc.value.stage
    assert nested_sines(6, symbolic_budget=10**6).derived.n == 2  # the same model under a larger budget


def test_the_environment_variables_set_the_limits(monkeypatch):
    monkeypatch.setenv("LAGRANGE_SYMBOLIC_TIMEOUT", "0.2")
    with pytest.raises(SymbolicTimeoutError, match="0.2 CPU seconds"):
        _ = inverse_distance_bodies(8).derived
    monkeypatch.setenv("LAGRANGE_SYMBOLIC_TIMEOUT", "60")
    monkeypatch.setenv("LAGRANGE_SYMBOLIC_BUDGET", "50")
    with pytest.raises(ExpressionTooLarge, match="more than 50 nodes"):
        _ = nested_sines(6).derived
    assert nested_sines(6, symbolic_budget=10**6).derived.n == 2  # the argument wins over the environment


@pytest.mark.parametrize("value", [0, -1, float("nan"), "soon", True, [3]])
def test_bad_settings_are_refused(value, monkeypatch):
    with pytest.raises(OptionError, match="symbolic_timeout.*positive number"):
        nested_sines(1, symbolic_timeout=value)
    with pytest.raises(OptionError, match="symbolic_budget"):
        nested_sines(1, symbolic_budget=value)
    monkeypatch.setenv("LAGRANGE_SYMBOLIC_TIMEOUT", str(value))
    with pytest.raises(OptionError, match=r"\$LAGRANGE_SYMBOLIC_TIMEOUT"):
        _ = nested_sines(1).derived
    monkeypatch.delenv("LAGRANGE_SYMBOLIC_TIMEOUT")
    with pytest.raises(OptionError, match="symbolic_timeout"):
        lg.hamiltonian(nested_sines(1), symbolic_timeout=value)


def test_eliminate_keeps_the_settings():
    x, y = lg.coordinates("x y")
    m, g, b = lg.parameters("m g b")
    s = lg.System([x, y], bodies=[lg.Particle(m, (x, y))], V=m * g * y,
                  constraints=[lg.Holonomic(y - b * x**2, "wire")], symbolic_timeout=0.5, symbolic_budget=123)
    reduced = lg.eliminate(s, [y])
    assert (reduced.symbolic_timeout, reduced.symbolic_budget) == (0.5, 123)


def test_whole_numbers_of_nodes_only_and_no_limit_on_time():
    with pytest.raises(OptionError, match="whole number"):
        limits.symbolic_budget(2.5)
    assert limits.symbolic_timeout("inf") == float("inf")
    assert nested_sines(2, symbolic_timeout=float("inf")).derived.n == 2


# ----------------------------------------------------------------------------------------- the mechanism

def LONG_EXPANSION(x, y):  # noqa: N802 - a constant of the tests
    """About 13 CPU-s of sympy work when nothing interrupts it (bounded, so a broken timer fails the test instead of
    filling the memory), against deadlines of 0.3 s."""
    return (x + y + 1) ** 30 * (x - y + 2) ** 30


def test_the_deadline_interrupts_one_long_sympy_call_and_restores_the_timer():
    x, y = sp.symbols("x y")
    before = signal.getsignal(signal.SIGPROF)
    assert limits._can_time(), (signal.getitimer(signal.ITIMER_PROF), before)  # no timer or handler left over
    start = time.process_time()
    with pytest.raises(SymbolicTimeoutError, match="a long expansion did not finish within 0.3 CPU seconds"):
        with limits.stage("a long expansion", timeout=0.3):
            sp.expand(LONG_EXPANSION(x, y))
    assert time.process_time() - start < 2.0
    assert signal.getitimer(signal.ITIMER_PROF) == (0.0, 0.0) and signal.getsignal(signal.SIGPROF) is before
    with limits.stage("a short expansion", timeout=5.0):
        assert sp.expand((x + 1) ** 2) == x**2 + 2 * x + 1  # ends quietly


def test_an_inner_stage_ends_no_later_than_the_outer_one():
    x, y = sp.symbols("x y")
    start = time.process_time()
    with pytest.raises(SymbolicTimeoutError, match="inner"):
        with limits.stage("outer", timeout=0.3), limits.stage("inner", timeout=100):
            sp.expand(LONG_EXPANSION(x, y))
    assert time.process_time() - start < 2.0


def test_a_clean_up_that_runs_out_keeps_the_expression_and_the_stage_goes_on():
    x, y = sp.symbols("x y")
    e = (x + y + 1) ** 300 * (x - y + 2) ** 300
    with limits.stage("a stage", timeout=2.0):
        start = time.process_time()
        assert limits.tidy(sp.expand, e) is e  # a quarter of the stage's 2 s, then the input
        assert time.process_time() - start < 1.5
        assert limits.tidy(sp.expand, (x + 1) ** 2) == (x + 1) ** 2  # the stage gave up clean-ups
    with limits.stage("another stage", timeout=2.0):
        assert limits.tidy(sp.expand, (x + 1) ** 2) == x**2 + 2 * x + 1


def test_off_the_main_thread_the_deadline_is_checked_between_steps():
    out = {}

    def work():
        try:
            with limits.stage("work in a thread", timeout=0.05):
                end = time.process_time() + 0.3
                while time.process_time() < end:
                    pass
                limits.checkpoint()
            out["result"] = "finished"
        except SymbolicTimeoutError as exc:
            out["result"] = str(exc)

    th = threading.Thread(target=work)
    th.start()
    th.join()
    assert "work in a thread did not finish within 0.05 CPU seconds" in out["result"]


# ------------------------------------------------------------------------------------------- analysis

def _bar_on_a_rotating_frame():
    phi, th = lg.coordinates("phi theta")
    I, m, l, k, b, d, c, g = lg.parameters("I m l k b d c g")
    A = I + m * l**2 * sp.sin(th) ** 2 / 3
    T = A * phi.diff(t) ** 2 / 2 + m * l**2 * th.diff(t) ** 2 / 6
    V = k * (sp.sqrt(b - d * sp.cos(th)) - c) ** 2 / 2 - m * g * l * sp.cos(th) / 2
    return lg.System([phi, th], T=T, V=V, name="bar on a rotating frame"), th, A, V


def test_oscillations_about_steady_motion_with_a_spring_under_a_root_end_within_the_budget():
    """Routh: with one ignorable coordinate, c = V_eff''(θ0) for V_eff = V + p²/(2A(θ)) and a = m l²/3."""
    system, th, A, V = _bar_on_a_rotating_frame()
    r = lg.routhian(system)
    th0 = lg.parameters("theta0")
    lin, exc, cpu = _cpu(lambda: lg.oscillations_about_steady_motion(r, {th: th0}))
    assert cpu < CPU_BOUND, cpu
    if exc is not None:
        assert "symbolic_timeout" in str(exc) or "symbolic_budget" in str(exc)
        return
    p = r.momenta[0]
    q = lg.to_symbols(th, system.coordinates)
    V_eff = lg.to_symbols(V + p**2 / (2 * A), system.coordinates)
    c_ref = sp.diff(V_eff, q, 2).subs(q, th0)
    rnd = random.Random(3)
    symbols = c_ref.free_symbols | lin.c.free_symbols
    for _ in range(3):
        at = {s: sp.Rational(rnd.randint(20, 90), 100) for s in symbols}
        at.update({s: 2 for s in symbols if s.name == "b"})  # b > d: the root stays real
        got, ref = complex(lin.c[0, 0].xreplace(at).evalf(30)), complex(c_ref.xreplace(at).evalf(30))
        assert abs(got - ref) <= 1e-12 * (1 + abs(ref))
    l, m = (s for s in sorted(system.declared_symbols, key=str) if s.name in ("m", "l"))
    assert sp.simplify(lin.a[0, 0] - l**2 * m / 3) == 0 and lin.b[0, 0] == 0


def test_analysis_takes_the_settings_by_argument(monkeypatch):
    system, th, _, _ = _bar_on_a_rotating_frame()
    r = lg.routhian(system)
    th0 = lg.parameters("theta0")
    with pytest.raises(SymbolicTimeoutError, match="oscillations about a steady motion.*0.01 CPU seconds"):
        lg.oscillations_about_steady_motion(r, {th: th0}, symbolic_timeout=0.01)
    slow = lg.System(system.coordinates, T=system.T, V=system.V, symbolic_timeout=0.01)
    with pytest.raises(SymbolicTimeoutError):
        lg.routhian(slow)  # the system's own setting is the default of its analysis
    monkeypatch.setenv("LAGRANGE_SYMBOLIC_TIMEOUT", "0.01")
    with pytest.raises(SymbolicTimeoutError, match="Routhian.*0.01 CPU seconds"):
        lg.routhian(system)  # and the environment's when neither is given
    assert lg.routhian(system, symbolic_timeout=60).R is not None  # the argument wins


# ------------------------------------------------------------------------------- the bicycle of test_kane3

KANE3_NAMES = ("WFrad WRrad htangle forkoffset forklength framelength forkcg1 forkcg3 framecg1 framecg3 Iwr11 "
               "Iwr22 Iwf11 Iwf22 Iframe11 Iframe22 Iframe33 Iframe31 Ifork11 Ifork22 Ifork33 Ifork31 g mframe "
               "mfork mwf mwr")


def kane3_bicycle(derivation="auto"):
    """The Whipple bicycle as sympy.physics.mechanics' test_kane3 declares it: yaw, roll, frame pitch (+ head
    angle), steer about the frame's x axis, the wheels spinning about the frame's and the fork's y axes, and the
    front contact point found by normalizing ``(Fork.y·Y.z) Fork.y − Y.z`` (z up). The rear contact point (x, y)
    and both wheels' rolling are constraints here (Kane's test builds the rear ones into its speeds)."""
    x, y, q1, q2, q3, q4, q5, q6 = lg.coordinates("x y q1 q2 q3 q4 q5 q6")
    p = dict(zip(KANE3_NAMES.split(), lg.parameters(KANE3_NAMES)))
    p.update({k: lg.parameters(k, real=True) for k in ("Iframe31", "Ifork31")})
    ht = p["htangle"]
    R_Y = lg.rot_z(q1)
    R_R = R_Y * lg.rot_x(q2)
    R_Frame = R_R * lg.rot_y(q4 + ht)
    R_Fork = R_Frame * lg.rot_x(q5)
    P = sp.Matrix([x, y, 0])
    WR_mc = P + p["WRrad"] * R_R[:, 2]
    steer = WR_mc + p["framelength"] * R_Frame[:, 2]
    frame_mc = WR_mc - p["framecg1"] * R_Frame[:, 0] + p["framecg3"] * R_Frame[:, 2]
    fork_mc = steer - p["forkcg1"] * R_Fork[:, 0] + p["forkcg3"] * R_Fork[:, 2]
    WF_mc = steer + p["forklength"] * R_Fork[:, 0] + p["forkoffset"] * R_Fork[:, 2]
    z = sp.Matrix([0, 0, 1])
    down = R_Fork[:, 1].dot(z) * R_Fork[:, 1] - z
    WF_cont = WF_mc + p["WFrad"] * down / sp.sqrt(down.dot(down))
    rate = {c: c.diff(t) for c in (q1, q2, q3, q4, q5, q6)}
    w_frame = rate[q1] * z + rate[q2] * R_Y[:, 0] + rate[q4] * R_R[:, 1]
    w_WR = w_frame + rate[q3] * R_Frame[:, 1]
    w_WF = w_frame + rate[q5] * R_Frame[:, 0] + rate[q6] * R_Fork[:, 1]
    base = (("z", q1), ("x", q2), ("y", q4 + ht))

    def tensor(a, b, c, ca):
        return sp.Matrix([[a, 0, ca], [0, b, 0], [ca, 0, c]])

    bodies = [
        lg.RigidBody(p["mframe"], tensor(p["Iframe11"], p["Iframe22"], p["Iframe33"], p["Iframe31"]),
                     origin=frame_mc, orientation=lg.RotationSequence(*base, ("y", -ht)), name="frame"),
        lg.RigidBody(p["mfork"], tensor(p["Ifork11"], p["Ifork22"], p["Ifork33"], p["Ifork31"]), origin=fork_mc,
                     orientation=lg.RotationSequence(*base, ("x", q5), ("y", -ht)), name="fork"),
        lg.RigidBody(p["mwr"], (p["Iwr11"], p["Iwr22"], p["Iwr11"]), origin=WR_mc,
                     orientation=lg.RotationSequence(*base, ("y", q3)), name="rear wheel"),
        lg.RigidBody(p["mwf"], (p["Iwf11"], p["Iwf22"], p["Iwf11"]), origin=WF_mc,
                     orientation=lg.RotationSequence(*base, ("x", q5), ("y", q6)), name="front wheel"),
    ]
    slip_R = WR_mc.diff(t) + w_WR.cross(P - WR_mc)
    slip_F = WF_mc.diff(t) + w_WF.cross(WF_cont - WF_mc)
    Yx, Yy = R_Y[:, 0], R_Y[:, 1]
    constraints = [lg.Nonholonomic(slip_R.dot(Yx), "rear wheel rolls (x)"),
                   lg.Nonholonomic(slip_R.dot(Yy), "rear wheel rolls (y)"),
                   lg.Nonholonomic(slip_F.dot(Yx), "front wheel rolls (x)"),
                   lg.Nonholonomic(slip_F.dot(Yy), "front wheel rolls (y)"),
                   lg.Holonomic(WF_cont[2], "front wheel touches the ground")]
    V = p["g"] * (p["mframe"] * frame_mc[2] + p["mfork"] * fork_mc[2] + p["mwf"] * WF_mc[2] + p["mwr"] * WR_mc[2])
    return lg.System([x, y, q1, q2, q3, q4, q5, q6], bodies=bodies, V=V, constraints=constraints,
                     name="Whipple bicycle (test_kane3)", derivation=derivation)


def kane3_values() -> dict:
    """test_kane3's numbers (its own conversion of Meijaard et al. 2007, Table 1), as floats."""
    from sympy import acos, cos, pi, sin, sqrt

    rr, rf, hta, trail, wb = 0.3, 0.35, (pi / 2 - pi / 10).evalf(), 0.08, 1.02
    rake = (-(trail * sin(hta) - rf * cos(hta))).evalf()
    fx, fz, kx, kz = 0.3, 0.9, 0.9, 0.7
    ta, tb = kz - rf, wb - kx
    tc = sqrt(ta**2 + tb**2).evalf()
    fork_l = (wb * cos(hta) - (rf - rr) * sin(hta)).evalf()
    v = {"WFrad": rf, "WRrad": rr, "htangle": hta, "forkoffset": rake, "forklength": fork_l,
         "framelength": (wb * sin(hta) - (rake - (rf - rr) * cos(hta))).evalf(),
         "forkcg1": (tc * cos((pi / 2 - hta) - acos(ta / tc)) - fork_l).evalf(),
         "forkcg3": (rake + tc * sin(pi / 2 - hta - acos(ta / tc))).evalf(),
         "framecg1": ((fz - rr - (fx / sin(hta)) * cos(hta)) * sin(hta)).evalf(),
         "framecg3": (fx / sin(hta) + (fz - rr - fx / sin(hta) * cos(hta)) * cos(hta)).evalf(),
         "Iwr11": 0.0603, "Iwr22": 0.12, "Iwf11": 0.1405, "Iwf22": 0.28, "Ifork11": 0.05892, "Ifork22": 0.06,
         "Ifork33": 0.00708, "Ifork31": 0.00756, "Iframe11": 9.2, "Iframe22": 11, "Iframe33": 2.8, "Iframe31": -2.4,
         "mfork": 4, "mframe": 85, "mwf": 3, "mwr": 2, "g": 9.81}
    return {k: float(val) for k, val in v.items()}


def kanes_lean_steer(speed: float) -> np.ndarray:
    """Rows (lean, steer accelerations) of the state matrix in (lean, steer, lean rate, steer rate) that
    KanesMethod gives in test_kane3 ("Precomputed for comparison" there)."""
    return np.array([[9.48977444677355, -0.891197738059089 * speed**2 - 0.571523173729245,
                      -0.105522449805691 * speed, -0.330515398992311 * speed],
                     [11.7194768719633, -1.97171508499972 * speed**2 + 30.9087533932407,
                      3.67680523332152 * speed, -3.08486552743311 * speed]])


def lean_steer(model, speed: float, step: float = 1e-3) -> np.ndarray:
    """The same two rows from the compiled model, on the constraint manifold: the pitch solves the contact
    constraint, the dependent rates solve ``A q̇ + b = 0`` with the rear wheel spinning at speed/r (central
    differences with one Richardson step)."""
    cf, n = model.constraint_functions, 8
    lean, wheel_r, pitch, steer = 3, 4, 5, 6
    free, dependent = [lean, steer, wheel_r], [0, 1, 2, 5, 7]

    def accelerations(z):
        q = np.zeros(n)
        q[lean], q[steer] = z[0], z[1]

        def contact(angle):
            qq = q.copy()
            qq[pitch] = angle
            return cf.phi(0.0, qq)[0]

        q[pitch] = brentq(contact, -0.5, 0.5, xtol=1e-15, rtol=1e-15)
        A, b = cf.matrix(0.0, q), cf.bias(0.0, q)
        qd = np.zeros(n)
        qd[free] = [z[2], z[3], speed / 0.3]
        qd[dependent] = np.linalg.solve(A[:, dependent], -b - A[:, free] @ qd[free])
        out = model.dynamics(0.0, np.concatenate([q, qd]), model.params)
        return np.array([out[n + lean], out[n + steer]])

    jac = np.zeros((2, 4))
    for k in range(4):
        def central(h, k=k):
            e = np.zeros(4)
            e[k] = h
            return (accelerations(e) - accelerations(-e)) / (2 * h)

        jac[:, k] = (4 * central(step / 2) - central(step)) / 3
    return jac


@pytest.mark.parametrize("derivation", ["auto", pytest.param("expanded", marks=pytest.mark.slow)])
def test_the_kane3_bicycle_derives_and_agrees_with_kanes_method(derivation):
    system = kane3_bicycle(derivation)
    start = time.process_time()
    model = system.compile(kane3_values())
    assert time.process_time() - start < CPU_BOUND
    for speed in range(6):
        assert np.max(np.abs(lean_steer(model, float(speed)) - kanes_lean_steer(speed))) < 1e-9, speed
