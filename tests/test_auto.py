"""``method="auto"`` (lagrange/integrate/auto.py): the numerical stiffness estimate, the choice, and that the
choice always covers the request's combination (constraints, events, friction switches, inputs)."""

from types import SimpleNamespace

import numpy as np
import pytest
import sympy as sp

from lagrange import Holonomic, Particle, System, coordinates, parameters, t
from lagrange.integrate import auto, registry
from lagrange.integrate.taylor import available_interpreter

HAS_C = available_interpreter() == "c"


def _damped(c_value=None):
    """Mass-spring-damper m x'' + c x' + k x = 0 (Rayleigh c x'^2 / 2)."""
    x = coordinates("x")
    m, k, c = parameters("m k c")
    return System([x], T=m * x.diff(t) ** 2 / 2, V=k * x**2 / 2, rayleigh=c * x.diff(t) ** 2 / 2), x


def _overdamped_exact(tt, c, k=1.0, x0=1.0):
    """x(t) of x'' + c x' + k x = 0, x(0) = x0, x'(0) = 0 (two real roots)."""
    d = np.sqrt(c * c - 4 * k)
    r1, r2 = (-c + d) / 2, (-c - d) / 2
    a = x0 * r2 / (r2 - r1)
    return a * np.exp(r1 * tt) + (x0 - a) * np.exp(r2 * tt)


def _linear(A):
    A = np.asarray(A, dtype=float)
    return lambda t_, y: A @ y


# --- the estimate ---------------------------------------------------------------------------------------
def test_estimate_matches_the_eigenvalues_of_a_linear_system():
    A = [[0.0, 1.0], [-4.0, -5.0]]  # λ = −1, −4
    st = auto.estimate_stiffness(_linear(A), 0.0, np.array([0.3, -0.2]))
    assert st.decay == pytest.approx(4.0, rel=1e-6)
    assert st.radius == pytest.approx(4.0, rel=1e-6)
    assert st.ratio == pytest.approx(4.0, rel=1e-6)
    assert not st.is_stiff(10.0)
    stiff = auto.estimate_stiffness(_linear([[0.0, 1.0], [-1.0, -1e5]]), 0.0, np.zeros(2))
    assert stiff.decay == pytest.approx(1e5, rel=1e-6) and stiff.ratio >= 1e7  # 1e10, resolved to ~1e8
    assert stiff.is_stiff(1.0)


def test_estimate_is_not_fooled_by_a_sign_switch_at_the_state():
    """Coulomb friction sign(v) at v = 0: one of the one-sided differences jumps by 2μg/h; the smaller is kept."""
    def f(t_, y):
        return np.array([y[1], -y[0] - 0.5 * np.sign(y[1])])

    st = auto.estimate_stiffness(f, 0.0, np.array([1.0, 0.0]))
    assert st is not None and st.decay < 10.0


def test_estimate_gives_up_on_a_failing_or_non_finite_rhs():
    assert auto.estimate_stiffness(lambda t_, y: np.array([np.nan, 0.0]), 0.0, np.zeros(2)) is None

    def boom(t_, y):
        raise ZeroDivisionError("singular")

    assert auto.estimate_stiffness(boom, 0.0, np.zeros(2)) is None


# --- the choice through simulate, against closed forms --------------------------------------------------
def test_truly_stiff_linear_system_gets_an_implicit_method():
    """c = 1e6: decay 1e6/s over t = 10 (the Taylor method would need ~2e7 passes) → LSODA."""
    s, x = _damped()
    tt = np.linspace(0, 10, 11)
    sol = s.simulate(10, {x: 1.0, x.diff(t): 0.0}, {"m": 1, "k": 1, "c": 1e6}, method="auto", t_eval=tt,
                     rtol=1e-8, atol=1e-10)
    assert sol.method.startswith("LSODA (auto: stiff") and "would take" in sol.method
    assert np.max(np.abs(sol["x"] - _overdamped_exact(tt, 1e6))) < 1e-6
    assert sol.nfev < 5_000


def test_moderately_stiff_analytic_system_gets_the_taylor_method():
    """c = 100 over t = 100: stiff for DOP853 (decay·T = 1e4) but the Taylor method's stability-limited
    steps are cheap → taylor (when a tape interpreter is here; an implicit method otherwise)."""
    s, x = _damped()
    tt = np.linspace(0, 100, 11)
    sol = s.simulate(100, {x: 1.0, x.diff(t): 0.0}, {"m": 1, "k": 1, "c": 100}, method="auto", t_eval=tt)
    assert "auto: stiff" in sol.method
    assert sol.method.split(" ")[0] == ("taylor" if HAS_C else "LSODA")
    assert np.max(np.abs(sol["x"] - _overdamped_exact(tt, 100.0))) < 1e-7


def test_smooth_conservative_system_gets_taylor_or_dop853():
    s, x = _damped()
    tt = np.linspace(0, 10, 21)
    sol = s.simulate(10, {x: 1.0, x.diff(t): 0.0}, {"m": 1, "k": 4, "c": 0}, method="auto", t_eval=tt,
                     rtol=1e-10, atol=1e-12)
    assert sol.method.split(" ")[0] == ("taylor" if HAS_C else "DOP853") and "not stiff" in sol.method
    assert np.max(np.abs(sol["x"] - np.cos(2 * tt))) < 1e-8


def test_auto_builds_no_symbolic_jacobian_to_decide(monkeypatch):
    """The decision differentiates the compiled rhs numerically: a broken symbolic Jacobian does not matter
    unless an implicit method is chosen."""
    import lagrange.codegen.run_functions as rf

    def refuse(*args, **kwargs):
        raise AssertionError("symbolic Jacobian built")

    monkeypatch.setattr(rf, "jacobian_function", refuse)
    s, x = _damped()
    sol = s.simulate(5, {x: 1.0, x.diff(t): 0.0}, {"m": 1, "k": 4, "c": 0.1}, method="auto")
    assert "auto:" in sol.method


# --- combinations: the choice always covers what the request needs --------------------------------------
_NEEDS = {
    "events": {"events": "1 event function"},
    "holonomic": {"holonomic": "string"},
    "nonholonomic": {"nonholonomic": "rolling"},
    "friction": {"friction_switches": "1 switch"},
    "rough": {"rough": ""},
    "inputs": {"inputs": "F"},
    "varying inputs": {"inputs": "F", "varying_inputs": "F(t)"},
    "dense output": {"dense_output": ""},
}


#: the combinations the Taylor method does not cover (those it covers are run through simulate below)
_WITHOUT_TAYLOR = [combo for combo, needs in _NEEDS.items() if "taylor" not in auto.candidates(needs)]


def test_some_combinations_exclude_the_taylor_method():
    assert {"events", "holonomic", "nonholonomic"} <= set(_WITHOUT_TAYLOR)


@pytest.mark.parametrize("stiff", [False, True])
@pytest.mark.parametrize("combo", _WITHOUT_TAYLOR)
def test_choice_covers_every_combination(combo, stiff):
    needs = _NEEDS[combo]
    A = [[0.0, 1.0], [-1.0, -1e6 if stiff else -0.1]]
    eqs = SimpleNamespace(n=1)  # only n is read when the Taylor method is not a candidate
    name, why = auto.choose(eqs, _linear(A), 0.0, np.array([1.0, 0.0]), t_end=10.0, rtol=1e-9, backend="python",
                            needs=needs, projection=combo == "holonomic")
    registry.check_supported(registry.get(name), needs)  # raises if the choice cannot honour the request
    assert name != "taylor"
    if stiff:
        assert name == ("Radau" if combo == "holonomic" else "LSODA") and why.startswith("stiff")
    else:
        assert name == "DOP853" and why.startswith("non-stiff")


def test_candidates_follow_the_registry():
    for needs in _NEEDS.values():
        for name in auto.candidates(needs):
            registry.check_supported(registry.get(name), needs)
    assert "taylor" not in auto.candidates({"events": "1"}) and "heyoka" not in auto.candidates({})


def test_constrained_pendulum_gets_a_method_that_supports_constraints():
    x, y = coordinates("x y")
    m, g, l = parameters("m g l")
    s = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y,
               constraints=[Holonomic(sp.sqrt(x**2 + y**2) - l, "string")])
    sol = s.simulate(2, {x: 1.0, y: 0.0, x.diff(t): 0.0, y.diff(t): 0.0}, {"m": 1, "g": 9.81, "l": 1},
                     method="auto", rtol=1e-10, atol=1e-12)
    assert sol.method.startswith("DOP853") and "auto:" in sol.method
    r = np.hypot(sol["x"], sol["y"])
    assert np.max(np.abs(r - 1.0)) < 1e-8
    energy = 0.5 * (sol["x_dot"] ** 2 + sol["y_dot"] ** 2) + 9.81 * sol["y"]
    assert np.max(np.abs(energy)) < 1e-7  # starts at rest at y = 0: E = 0


def test_friction_switches_and_events_run_on_a_method_that_supports_them():
    from lagrange.bench.problems import belt_state, belt_system

    tt = np.linspace(0, 8, 81)
    s = belt_system()
    p = {"m": 1.0, "k": 1.0, "mu": 0.5, "g": 1.0}

    def crossing(t_, y):
        return y[0] - 0.3

    sol = s.simulate(8, {"x": 0.0, "x_dot": 0.5}, p, method="auto", t_eval=tt, rtol=1e-10, atol=1e-12,
                     events=[crossing])
    assert sol.method.startswith("DOP853") and "auto:" in sol.method
    assert np.max(np.abs(sol.y - belt_state(tt))) < 1e-7


# --- the cheap decision: 2n + 1 evaluations, a bound before eigenvalues, one model ----------------------
def _counting(fun):
    calls = []

    def counted(t_, y):
        calls.append(np.array(y))
        return fun(t_, y)

    return counted, calls


def test_difference_jacobian_of_analytic_equations_takes_2n_plus_1_evaluations():
    A = np.array([[0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0], [-3.0, 1.0, -0.2, 0.1], [1.0, -2.0, 0.1, -0.3]])
    fun, calls = _counting(lambda t_, y: list(A @ y))  # a list, as the generated python rhs returns
    J, seconds = auto.difference_jacobian(fun, 0.0, np.array([0.3, -0.2, 0.1, 0.5]), smooth=True)
    assert len(calls) == 2 * 2 + 1 and seconds >= 0
    assert np.allclose(J, A, atol=1e-6)
    fun, calls = _counting(lambda t_, y: A @ y)
    assert np.allclose(auto.difference_jacobian(fun, 0.0, np.zeros(4))[0], A, atol=1e-6)
    assert len(calls) == 4 * 2 + 1  # not known to be smooth: every column checked for a jump


def test_difference_jacobian_keeps_the_jump_check_for_non_analytic_equations():
    def f(t_, y):
        return np.array([y[1], -y[0] - 0.5 * np.sign(y[1])])

    J, _ = auto.difference_jacobian(f, 0.0, np.array([1.0, 0.0]))
    assert np.allclose(J, [[0.0, 1.0], [-1.0, 0.0]], atol=1e-6)  # not the 1/h jump of sign(v) at v = 0


@pytest.mark.parametrize("size", [2, 4, 8, 12, 14, 20, 40])
def test_decay_bound_is_an_upper_bound_of_the_fastest_decay_rate(size):
    """Gershgorin on the balanced matrix (plain-Python path up to 12 states, numpy beyond): never below the
    eigenvalues' max(−Re λ), on random matrices with rows of very different scales."""
    rng = np.random.default_rng(size)
    for _ in range(40):
        J = rng.normal(size=(size, size)) * rng.uniform(1e-2, 1e3, size=(size, 1))
        decay = max(0.0, float(np.max(-np.linalg.eigvals(J).real)))
        assert auto.decay_bound(J) >= decay * (1 - 1e-12)


def test_decay_bound_is_tight_for_oscillators():
    """An undamped oscillator of frequency ω: bound ω (the balancing), not ω²; with damping c: ≤ ω + c."""
    for omega in (0.5, 3.0, 100.0):
        J = np.array([[0.0, 1.0], [-omega**2, 0.0]])
        assert auto.decay_bound(J) == pytest.approx(omega, rel=1e-12)
        damped = np.array([[0.0, 1.0], [-omega**2, -2.0]])
        decay = float(np.max(-np.linalg.eigvals(damped).real))
        assert decay <= auto.decay_bound(damped) <= omega + 2.0 + 1e-12


def test_non_stiff_choice_computes_no_eigenvalues(monkeypatch):
    """When the bound × horizon ≤ 10³ the eigenvalues are not needed; the reason gives the bound."""
    def refuse(*args):
        raise AssertionError("eigenvalues computed")

    monkeypatch.setattr(auto.np.linalg, "eigvals", refuse)
    s, x = _damped()
    sol = s.simulate(10, {x: 1.0, x.diff(t): 0.0}, {"m": 1, "k": 4, "c": 0.1}, method="auto", t_eval=[10.0])
    assert "decay rates ≤ 2.1/time over 10: not stiff" in sol.method  # ω = 2, c = 0.1
    exact = np.exp(-0.05 * 10) * (np.cos(np.sqrt(3.9975) * 10) + 0.05 / np.sqrt(3.9975) * np.sin(np.sqrt(3.9975) * 10))
    assert abs(sol["x"][-1] - exact) < 1e-7


def test_bound_does_not_hide_stiffness():
    """The same system with c = 10⁴: the bound exceeds 10³ / T, the eigenvalues decide, and it is stiff."""
    s, x = _damped()
    sol = s.simulate(1, {x: 1.0, x.diff(t): 0.0}, {"m": 1, "k": 1, "c": 1e4}, method="auto", t_eval=[1.0],
                     rtol=1e-8, atol=1e-10)
    assert "auto: stiff" in sol.method and sol.method.split(" ")[0] in ("taylor", "LSODA")
    assert abs(sol["x"][-1] - _overdamped_exact(np.array([1.0]), 1e4)[0]) < 1e-7


def test_auto_builds_one_model_and_binds_its_parameters_once(monkeypatch):
    """The python model built to decide is the run's model: one code generation, no second binding; the result
    is the chosen method's, number for number."""
    from lagrange.codegen.numeric import NumericModel

    s, x = _damped()
    ic, p = {x: 1.0, x.diff(t): 0.0}, {"m": 1, "k": 4, "c": 0.3}
    direct = s.simulate(3, ic, p, method="taylor" if HAS_C else "DOP853", t_eval=[1.0, 3.0])
    builds = []
    real_build = NumericModel.build

    def build(*args, **kwargs):
        builds.append(args)
        return real_build(*args, **kwargs)

    def rebind(self, params):
        raise AssertionError("parameters bound a second time")

    monkeypatch.setattr(NumericModel, "build", staticmethod(build))
    monkeypatch.setattr(NumericModel, "with_params", rebind)
    sol = s.simulate(3, ic, p, method="auto", t_eval=[1.0, 3.0])
    assert len(builds) == 1
    assert sol.method.split(" ")[0] == direct.method.split(" ")[0]
    assert np.array_equal(sol.y, direct.y)


def test_auto_with_baumgarte_still_compiles_the_stabilized_model():
    """A stiff constrained run on LSODA (no projection: Baumgarte) must not reuse the unstabilized model built
    to decide: the result is LSODA's with Baumgarte stabilization, number for number, and the constraint holds."""
    x, y = coordinates("x y")
    m, g, l, c = parameters("m g l c")
    s = System([x, y], bodies=[Particle(m, (x, y))], V=m * g * y,
               rayleigh=c * (x.diff(t) ** 2 + y.diff(t) ** 2) / 2,
               constraints=[Holonomic(sp.sqrt(x**2 + y**2) - l, "string")])
    args = (2, {x: 1.0, y: 0.0, x.diff(t): 0.0, y.diff(t): 0.0}, {"m": 1, "g": 9.81, "l": 1, "c": 1e4})
    opts = dict(rtol=1e-8, atol=1e-10, stabilization="baumgarte", t_eval=np.linspace(0, 2, 5))
    sol = s.simulate(*args, method="auto", **opts)
    assert sol.method.startswith("LSODA") and "auto: stiff" in sol.method
    direct = s.simulate(*args, method="LSODA", **opts)
    assert np.array_equal(sol.y, direct.y)
    assert np.max(np.abs(np.hypot(sol["x"], sol["y"]) - 1.0)) < 1e-5
    assert np.all(np.diff(sol["y"]) <= 1e-9)  # overdamped: the bob creeps down along the circle
