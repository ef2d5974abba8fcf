"""Bounded, reproducible sympy calls (lagrange.simplification) and the zero test."""

import signal
import threading
import time

import pytest
import sympy as sp
from sympy.core.random import rng

from lagrange import SymbolicTimeoutError, coordinates, t
from lagrange import simplification as simp
from lagrange.simplification import is_zero, run_bounded


def _spin(seconds):
    end = time.perf_counter() + seconds
    while time.perf_counter() < end:
        pass


def test_caller_random_state_is_restored():
    rng.seed(99)
    expected = [rng.random() for _ in range(3)]
    rng.seed(99)
    run_bounded(lambda: [rng.random() for _ in range(10)], what="draws")
    assert [rng.random() for _ in range(3)] == expected


def test_each_attempt_is_seeded_the_same_way():
    first = run_bounded(lambda: rng.random(), what="a draw")
    rng.seed(12345)
    assert run_bounded(lambda: rng.random(), what="a draw") == first


def test_unlucky_seed_is_retried_with_the_next(monkeypatch):
    monkeypatch.setattr(simp, "SECONDS", 0.2)
    draws = []

    def unlucky_first_seed():
        x = rng.random()
        draws.append(x)
        if len(draws) == 1:
            _spin(5)  # the pathological path: interrupted after 0.2 s
        return x

    t0 = time.perf_counter()
    got = run_bounded(unlucky_first_seed, what="an unlucky factorization")
    assert time.perf_counter() - t0 < 2
    assert len(draws) == 2 and draws[0] != draws[1] and got == draws[1]


def test_every_attempt_timing_out_raises_naming_the_work(monkeypatch):
    monkeypatch.setattr(simp, "SECONDS", 0.05)
    with pytest.raises(SymbolicTimeoutError, match="the frequency equation.*4 attempts.*LAGRANGE_SYMPY_SECONDS"):
        run_bounded(_spin, 10, what="the frequency equation")
    assert signal.getitimer(signal.ITIMER_REAL)[0] == 0.0


def test_simplify_returns_its_input_when_out_of_time(monkeypatch):
    monkeypatch.setattr(simp, "SECONDS", 0.05)
    x = sp.Symbol("x")
    e = sp.sin(x) ** 2 + sp.cos(x) ** 2

    def slow_simplify(expr, *a, **k):
        _spin(10)

    monkeypatch.setattr(sp, "simplify", slow_simplify)
    assert simp.simplify(e) is e


def test_nested_calls_share_the_outer_seed_and_timer(monkeypatch):
    monkeypatch.setattr(simp, "SECONDS", 0.3)
    seen = []

    def inner():
        seen.append((signal.getitimer(signal.ITIMER_REAL)[0] > 0, rng.random()))

    def outer():
        rng.random()
        run_bounded(inner, what="inner")

    run_bounded(outer, what="outer")
    rng.seed(0)
    rng.random()
    assert seen == [(True, rng.random())]  # inner did not reseed; the outer's timer was running


def test_a_caller_timer_and_handler_are_left_alone(monkeypatch):
    fired = []

    def mine(*a):
        fired.append(1)

    previous = signal.signal(signal.SIGALRM, mine)
    try:
        signal.setitimer(signal.ITIMER_REAL, 5.0)
        run_bounded(lambda: None, what="nothing")
        assert signal.getitimer(signal.ITIMER_REAL)[0] > 0  # still armed: not replaced by ours
        signal.setitimer(signal.ITIMER_REAL, 0)
        run_bounded(lambda: None, what="nothing")
        assert signal.getsignal(signal.SIGALRM) is mine  # restored after use
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
    assert not fired


def test_runs_outside_the_main_thread_without_a_timer():
    out = []
    th = threading.Thread(target=lambda: out.append(run_bounded(lambda: 7, what="seven")))
    th.start()
    th.join()
    assert out == [7]


# ------------------------------------------------------------------------------------------- is_zero

th, al, x = sp.symbols("theta alpha x", real=True)
m, R = sp.symbols("m R", positive=True)


@pytest.mark.parametrize("expr", [
    sp.sin(th) ** 2 + sp.cos(th) ** 2 - 1,
    sp.sin(th + al) - sp.sin(th) * sp.cos(al) - sp.cos(th) * sp.sin(al),
    m * R**2 * (sp.sin(th) ** 4 - sp.cos(th) ** 4) - m * R**2 * (sp.sin(th) ** 2 - sp.cos(th) ** 2),
    sp.tan(th) * sp.cos(th) - sp.sin(th),
    (sp.sin(2 * th) - 2 * sp.sin(th) * sp.cos(th)) / (m + sp.cos(al) ** 2),
    sp.sqrt(m**2 * R**2) - m * R,  # not a trigonometric polynomial: proven by (bounded) simplify
])
def test_identities_are_proven_zero(expr):
    assert is_zero(expr)


@pytest.mark.parametrize("expr", [
    sp.sin(th) ** 2 + sp.cos(th) ** 2 - 1 + sp.Rational(1, 10**12) * m,  # tiny but not zero
    sp.sin(th) - th,
    sp.sqrt(x**2) - x,  # x real: not zero for x < 0
])
def test_nonzero_is_not_zero(expr):
    assert not is_zero(expr)


def test_functions_of_time_and_their_derivatives():
    q = sp.Function("q")(t)
    assert is_zero(sp.diff(sp.sin(q) ** 2, t) - 2 * sp.sin(q) * sp.cos(q) * q.diff(t))
    assert not is_zero(sp.diff(sp.sin(q) ** 2, t) - sp.sin(q) * sp.cos(q) * q.diff(t))


def test_nonzero_expressions_are_decided_without_simplify(monkeypatch):
    """Regression (Wells P2.6 under `lagrange derive`): simplify of a nonzero ∂L/∂θ ran for minutes in
    unlucky processes. The numeric probe now decides it; simplify is never called."""
    from problems.ch02_p2_6 import system

    def forbidden(*a, **k):
        raise AssertionError("simplify called")

    monkeypatch.setattr(sp, "simplify", forbidden)
    _, phi, _ = coordinates("theta phi alpha")
    assert list(system.ignorable_coordinates()) == [phi]
