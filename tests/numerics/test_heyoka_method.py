"""method="heyoka" through the registry: ``simulate(method="heyoka")``, the command line and the spec.

Independent truth: the pendulum's closed form (Jacobi's sn), Kepler's equation, the damped oscillator's closed
form and its work/energy balance (P, Wells' power function), a constant input's closed form, and the project's
own Taylor method at tight tolerance. A second run with other parameter (or constant input) values by name
reuses the compiled heyoka integrator (counted by ``heyoka_backend.compilations``). Every unsupported
combination is refused by the registry, naming the methods that support it.
"""

import math

import numpy as np
import pytest
import sympy as sp
from scipy.special import ellipj, ellipk

import lagrange as lg
from lagrange import System, coordinates, parameters, t
from lagrange.bench.problems import get_problem, kepler_state
from lagrange.cli import main
from lagrange.errors import BackendError, InputError, LagrangeError, MethodError
from lagrange.examples import n_link_pendulum
from lagrange.integrate import heyoka_run, registry

hy = pytest.importorskip("heyoka")
from lagrange.integrate import heyoka_backend  # noqa: E402  (imports heyoka only when it runs)

TIGHT = {"rtol": 1e-13, "atol": 1e-13}


def _pendulum_closed_form(theta0, tt, g=9.81):
    """Released from rest at theta0 (unit length): sin(θ/2) = k sn(K(k) − ω t; k), k = sin(θ0/2), ω = √g."""
    k = math.sin(theta0 / 2)
    sn, *_ = ellipj(ellipk(k * k) - math.sqrt(g) * tt, k * k)
    return 2 * np.arcsin(k * sn)


@pytest.mark.parametrize("name", ["pendulum", "double_pendulum", "kepler"])
def test_simulate_heyoka_against_taylor_and_closed_forms(name):
    if name == "pendulum":
        s, params, initial, T = n_link_pendulum(1), {"g": 9.81}, {"q1": 1.2, "q1_dot": 0.0}, 10.0
    else:
        p = get_problem(name, quick=True)
        s, params, initial, T = p.build(), p.params, p.initial, p.t_end
    sol = s.simulate((0.0, T), initial, params, method="HeyOka", n_points=11, **TIGHT)
    assert sol.success and sol.method.startswith("heyoka")
    ours = s.simulate((0.0, T), initial, params, method="taylor", n_points=11, **TIGHT)
    scale = max(1.0, float(np.max(np.abs(ours.y))))
    assert np.max(np.abs(sol.y - ours.y)) < 1e-10 * scale
    assert sol.energy_error() < 1e-11
    if name == "pendulum":
        assert np.max(np.abs(sol.y[:, 0] - _pendulum_closed_form(1.2, sol.t))) < 1e-10
    if name == "kepler":
        assert np.max(np.abs(sol.y - kepler_state(sol.t))) < 1e-10


def test_damped_system_with_P_work_balance_and_parameters_by_name_reuse_the_integrator():
    """Wells' power function P = −c ẋ²/2: closed form, the work/energy balance h(t) − h(0) = ∫ P-work, and a
    second run with other k, c (by name) integrates with the same compiled heyoka integrator."""
    x = coordinates("x")
    m, k, c = parameters("m k c")
    s = System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, P=-c * x.diff(t) ** 2 / 2)
    tt = np.linspace(0, 8, 17)
    built = []
    for kk, cc in ((4.0, 0.4), (9.0, 1.0)):
        before = heyoka_backend.compilations()
        sol = s.simulate((0.0, 8.0), {"x": 1.0, "x_dot": 0.0}, {"m": 1.0, "k": kk, "c": cc}, method="heyoka",
                         t_eval=tt, **TIGHT)
        built.append(heyoka_backend.compilations() - before)
        g, wd = cc / 2, math.sqrt(kk - cc**2 / 4)
        xe = np.exp(-g * tt) * (np.cos(wd * tt) + g / wd * np.sin(wd * tt))
        ve = -np.exp(-g * tt) * (wd + g * g / wd) * np.sin(wd * tt)
        assert np.max(np.abs(sol.y[:, 0] - xe)) < 1e-11 and np.max(np.abs(sol.y[:, 1] - ve)) < 1e-11
        assert np.max(np.abs(sol.work - (0.5 * ve**2 + kk / 2 * xe**2 - kk / 2))) < 1e-11
        assert np.max(np.abs(sol.power_balance())) < 1e-11
    assert built[1] == 0 and built[0] in (0, 1)  # 0 when an earlier test built it already


def test_constant_input_is_a_runtime_parameter():
    """x'' = −4x + F with F constant: x = F/4 + (1 − F/4) cos 2t; another F reuses the integrator."""
    x = coordinates("x")
    F = lg.inputs("F")
    s = System([x], T=x.diff(t) ** 2 / 2, V=2 * x**2, forces={x: F})
    tt = np.linspace(0, 3, 7)
    counts = []
    for f in (1.0, -3.0):
        before = heyoka_backend.compilations()
        sol = s.simulate((0.0, 3.0), {"x": 1.0, "x_dot": 0.0}, {}, inputs={"F": f}, method="heyoka", t_eval=tt,
                         **TIGHT)
        counts.append(heyoka_backend.compilations() - before)
        assert np.max(np.abs(sol.y[:, 0] - (f / 4 + (1 - f / 4) * np.cos(2 * tt)))) < 1e-11
    assert counts[1] == 0


def test_unsupported_combinations_are_refused_naming_the_methods_that_support_them():
    x, y = coordinates("x y")
    ok = ", ".join(registry.supporting("holonomic"))
    assert "heyoka" not in ok and "DOP853" in ok
    ring = System([x, y], T=(x.diff(t) ** 2 + y.diff(t) ** 2) / 2, V=y, constraints=[x**2 + y**2 - 1])
    with pytest.raises(MethodError, match=r"method='heyoka'.*holonomic constraints.*methods that do: DOP853"):
        ring.simulate(1.0, {"x": 1.0, "y": 0.0, "x_dot": 0.0, "y_dot": 0.0}, {}, method="heyoka")
    osc = System([x], T=x.diff(t) ** 2 / 2, V=x**2 / 2)  # events run (tests/numerics/test_heyoka_events.py)
    assert osc.simulate(1.0, {"x": 1.0, "x_dot": 0.0}, {}, method="heyoka", events=[lambda tt, yy: yy[0]]).t_events
    mu = parameters("mu")
    block = System([x], T=x.diff(t) ** 2 / 2, V=x**2 / 2, forces={x: -mu * sp.sign(x.diff(t))})
    with pytest.raises(MethodError, match=r"method='heyoka'.*dry-friction sign\(\) switches.*methods that do: "
                                          r"DOP853"):
        block.simulate(1.0, {"x": 1.0, "x_dot": 0.0}, {"mu": 0.1}, method="heyoka", friction="events")
    F = lg.inputs("F")
    driven = System([x], T=x.diff(t) ** 2 / 2, V=x**2 / 2, forces={x: F})
    with pytest.raises(InputError, match=r"method='heyoka'.*time-varying inputs.*methods that do: DOP853"):
        driven.simulate(1.0, {"x": 1.0, "x_dot": 0.0}, {}, inputs={"F": math.cos}, method="heyoka")


def test_missing_heyoka_is_a_backend_error_naming_the_extra(monkeypatch):
    monkeypatch.setattr(heyoka_run, "heyoka_available", lambda: False)
    x = coordinates("x")
    with pytest.raises(BackendError, match=r'pip install "lagrange-dynamics\[heyoka\]"') as info:
        System([x], T=x.diff(t) ** 2 / 2, V=x**2 / 2).simulate(1.0, {"x": 1.0, "x_dot": 0.0}, {}, method="heyoka")
    assert isinstance(info.value, LagrangeError)


def test_auto_never_chooses_heyoka():
    p = get_problem("kepler", quick=True)
    from lagrange.integrate.run import choose_method

    eqs = p.build().derived
    for rtol in (1e-6, 1e-13):
        name, _ = choose_method(eqs, p.params, (0.0, 1.0), np.array(list(p.initial.values()), float), rtol=rtol,
                                backend="python", events=None, varying_inputs=False)
        assert name != "heyoka"


def _state(out: str) -> dict[str, float]:
    line = next(ln for ln in out.splitlines() if ln.startswith("state at t="))
    return {k: float(v) for k, v in (kv.split("=") for kv in line.split(": ", 1)[1].split(", "))}


def test_cli_method_heyoka_and_methods_table(capsys):
    assert main(["methods"]) == 0
    row = next(ln for ln in capsys.readouterr().out.splitlines() if ln.startswith("heyoka "))
    assert "Taylor series" in row and "constant" in row and "LLVM" in row
    assert main(["simulate", "ex3.4", "--method", "HEYOKA", "-q", "--rtol", "1e-12", "--atol", "1e-12"]) == 0
    out = capsys.readouterr().out
    assert "method heyoka" in out
    theirs = _state(out)
    assert main(["simulate", "ex3.4", "--method", "taylor", "-q", "--rtol", "1e-12", "--atol", "1e-12"]) == 0
    ours = _state(capsys.readouterr().out)
    assert ours.keys() == theirs.keys() and all(abs(ours[k] - theirs[k]) < 1e-8 for k in ours)


def test_spec_simulate_method_heyoka(tmp_path, capsys):
    path = tmp_path / "osc.toml"
    path.write_text('name = "osc"\ncoordinates = ["x"]\nparameters = ["m", "k"]\nT = "m/2*x_dot**2"\n'
                    'V = "k/2*x**2"\n[params]\nm = 1.0\nk = 4.0\n[initial]\nx = 1.0\nx_dot = 0.0\n'
                    '[simulate]\nt_end = 1.0\nmethod = "heyoka"\nrtol = 1e-12\natol = 1e-12\n')
    assert main(["simulate", str(path), "-q"]) == 0
    out = capsys.readouterr().out
    assert "method heyoka" in out and abs(_state(out)["x"] - math.cos(2.0)) < 1e-10


def test_sweep_with_method_heyoka_compiles_once():
    """A sweep over k (in this process): every row matches x = cos(√k t), and the integrator is built at most
    once for the whole sweep (parameters are heyoka runtime parameters)."""
    from lagrange.sweep.driver import sweep

    x = coordinates("x")
    m, k = parameters("m k")
    s = System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2)
    before = heyoka_backend.compilations()
    df = sweep(s, {"k": [4.0, 9.0, 16.0]}, t_end=2.0, initial={"x": 1.0, "x_dot": 0.0}, params={"m": 1.0},
               method="heyoka", progress=False, workers=0, **TIGHT)
    assert heyoka_backend.compilations() - before <= 1
    assert list(df["status"]) == ["ok"] * 3
    for kk, xf in zip(df["k"], df["final_x"]):
        assert abs(xf - math.cos(2 * math.sqrt(kk))) < 1e-10


def test_ctrl_c_stops_a_heyoka_run_within_a_step_with_the_finished_outputs(monkeypatch):
    """SIGINT (here an alarm whose handler raises KeyboardInterrupt, as Ctrl-C's does) during a long heyoka run:
    IntegrationInterrupted (a KeyboardInterrupt) arrives at once, its ``partial`` holds the outputs of the
    finished chunks, each on the pendulum's closed form."""
    import signal
    import time

    from lagrange.integrate import heyoka_backend

    s = n_link_pendulum(1)
    s.simulate(1.0, {"q1": 1.2, "q1_dot": 0.0}, {"g": 9.81}, method="heyoka", **TIGHT)  # compiled beforehand
    previous = signal.signal(signal.SIGALRM, signal.default_int_handler)
    propagate = heyoka_backend._propagate

    def armed(*args, **kwargs):  # the alarm starts with the run's loop, not before: on a loaded machine the
        signal.setitimer(signal.ITIMER_REAL, 0.5)  # set-up alone can take 0.5 s, and an interrupt there has
        return propagate(*args, **kwargs)  # no partial trajectory (a plain KeyboardInterrupt, by design)

    monkeypatch.setattr(heyoka_backend, "_propagate", armed)
    start = time.monotonic()
    try:
        with pytest.raises(lg.IntegrationInterrupted) as info:
            s.simulate(1e7, {"q1": 1.2, "q1_dot": 0.0}, {"g": 9.81}, method="heyoka", n_points=2_000_001,
                       **TIGHT)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
    assert time.monotonic() - start < 30  # the uninterrupted run takes minutes
    err = info.value
    assert isinstance(err, KeyboardInterrupt) and not err.partial.success and err.t > 0
    part = err.partial
    assert len(part.t) > 0 and part.t[-1] <= err.t
    # the phase error (of the run and of the closed form's own evaluation) grows linearly with t
    assert np.all(np.abs(part.y[:, 0] - _pendulum_closed_form(1.2, part.t)) < 1e-10 * (1 + part.t))
