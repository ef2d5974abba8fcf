"""Events with method="heyoka": the user's scipy-style callables traced into heyoka events.

Independent truth: the pendulum's zero crossings from its closed form (the complete elliptic integral K: the
angle released from rest at θ0 crosses zero at (2j + 1)·K(k²)/ω), a falling mass's impact time √(2h/g) and
speed √(2gh), and scipy's own event location (DOP853) at tight tolerance on the same callables (same result
fields: ``t_events``, ``y_events``, the truncated output, the message). Callables that cannot be traced are
refused by name, never integrated without their event.
"""

import math

import numpy as np
import pytest
from scipy.special import ellipk

from lagrange import System, coordinates, parameters, t
from lagrange.errors import MethodError
from lagrange.examples import n_link_pendulum
from lagrange.integrate import registry

hy = pytest.importorskip("heyoka")

TIGHT = {"rtol": 1e-13, "atol": 1e-13}
G = 9.81


def _crossings(theta0, count, g=G):
    """The zero crossings of the pendulum released from rest at theta0 (unit length)."""
    k = math.sin(theta0 / 2)
    quarter = ellipk(k * k) / math.sqrt(g)
    return np.array([(2 * j + 1) * quarter for j in range(count)])


def _angle(tt, y):
    return y[0]


def test_pendulum_zero_crossings_match_the_closed_form_and_scipy():
    s = n_link_pendulum(1)
    start = {"q1": 1.2, "q1_dot": 0.0}
    sol = s.simulate((0.0, 4.0), start, {"g": G}, method="heyoka", events=[_angle], n_points=41, **TIGHT)
    assert sol.success and "end of the integration interval" in sol.message
    truth = _crossings(1.2, 6)
    truth = truth[truth < 4.0]
    assert len(sol.t_events) == 1 and sol.t_events[0].shape == truth.shape
    assert np.max(np.abs(sol.t_events[0] - truth)) < 1e-11
    assert sol.y_events[0].shape == (truth.size, 2) and np.max(np.abs(sol.y_events[0][:, 0])) < 1e-12
    energy = G * (1 - math.cos(1.2))  # |θ̇| at the bottom: θ̇²/2 = g (1 − cos θ0)
    assert np.allclose(np.abs(sol.y_events[0][:, 1]), math.sqrt(2 * energy), rtol=1e-11, atol=0)
    ref = s.simulate((0.0, 4.0), start, {"g": G}, method="DOP853", events=[_angle], n_points=41, rtol=1e-12,
                     atol=1e-14)
    assert np.max(np.abs(sol.t_events[0] - ref.t_events[0])) < 1e-10
    assert np.max(np.abs(sol.y_events[0] - ref.y_events[0])) < 1e-9
    assert np.max(np.abs(sol.y - ref.y)) < 1e-9


def test_direction_filters_the_crossings():
    s = n_link_pendulum(1)
    start = {"q1": 1.2, "q1_dot": 0.0}

    def falling(tt, y):
        return y[0]

    def rising(tt, y):
        return y[0]

    falling.direction, rising.direction = -1, 1.0
    sol = s.simulate((0.0, 4.0), start, {"g": G}, method="heyoka", events=[falling, rising, _angle], **TIGHT)
    truth = _crossings(1.2, 6)
    truth = truth[truth < 4.0]
    assert np.max(np.abs(sol.t_events[0] - truth[0::2])) < 1e-11  # released at +1.2: the first crossing falls
    assert np.max(np.abs(sol.t_events[1] - truth[1::2])) < 1e-11
    assert np.all(sol.y_events[0][:, 1] < 0) and np.all(sol.y_events[1][:, 1] > 0)
    assert sol.t_events[2].size == truth.size


def test_terminal_event_stops_the_run_like_scipy():
    """A falling mass stops at the floor (terminal, falling): t = √(2h/g), speed √(2gh); the output ends
    there, as scipy's does."""
    y = coordinates("y")
    m, g = parameters("m g")
    drop = System([y], T=m * y.diff(t) ** 2 / 2, V=m * g * y)

    def floor(tt, z):
        return z[0]

    floor.terminal, floor.direction = True, -1
    args = ((0.0, 5.0), {"y": 2.0, "y_dot": 0.0}, {"m": 1.0, "g": G})
    sol = drop.simulate(*args, method="heyoka", events=[floor], n_points=51, **TIGHT)
    ref = drop.simulate(*args, method="DOP853", events=[floor], n_points=51, rtol=1e-12, atol=1e-14)
    t_hit = math.sqrt(2 * 2.0 / G)
    assert sol.success and sol.message.startswith("A termination event occurred.")
    assert abs(sol.t_events[0][0] - t_hit) < 1e-12 and sol.t_events[0].size == 1
    assert abs(sol.y_events[0][0, 1] + math.sqrt(2 * G * 2.0)) < 1e-11
    assert np.array_equal(sol.t, ref.t) and sol.t[-1] <= t_hit < sol.t[-1] + 0.1
    assert np.max(np.abs(sol.y - ref.y)) < 1e-10
    assert abs(ref.t_events[0][0] - sol.t_events[0][0]) < 1e-10


def test_terminal_count_time_and_work_integral_as_scipy():
    """scipy's ``terminal=k`` (stop at the k-th occurrence), an event of t alone, and an event on the work
    integral of a damped oscillator (scipy passes ``[q, q̇, w]``; so does the trace)."""
    x = coordinates("x")
    k, c = parameters("k c")
    osc = System([x], T=x.diff(t) ** 2 / 2, V=k * x**2 / 2, P=-c * x.diff(t) ** 2 / 2)

    def second_zero(tt, z):
        return z[0]

    def clock(tt, z):
        return tt - 0.7

    def lost(tt, z):  # a tenth of the initial energy dissipated
        return z[2] + 0.05 * np.square(1.0) * 4.0 / 2 * 0.5

    second_zero.terminal = 2
    args = ((0.0, 10.0), {"x": 1.0, "x_dot": 0.0}, {"k": 4.0, "c": 0.3})
    sol = osc.simulate(*args, method="heyoka", events=[second_zero, clock, lost], n_points=101, **TIGHT)
    ref = osc.simulate(*args, method="DOP853", events=[second_zero, clock, lost], n_points=101, rtol=1e-12,
                       atol=1e-14)
    assert sol.message.startswith("A termination event occurred.") and ref.success
    assert [e.size for e in sol.t_events] == [e.size for e in ref.t_events] == [2, 1, 1]
    for mine, theirs in zip(sol.t_events, ref.t_events):
        assert np.max(np.abs(mine - theirs)) < 1e-10
    assert abs(sol.t_events[1][0] - 0.7) < 1e-13
    wd = math.sqrt(4.0 - 0.3**2 / 4)  # closed form of the zero crossings: tan(ωd t) = −ωd/(c/2)
    t_zero = (math.pi - math.atan(wd / 0.15)) / wd
    assert abs(sol.t_events[0][0] - t_zero) < 1e-12 and abs(sol.t_events[0][1] - t_zero - math.pi / wd) < 1e-12
    assert np.array_equal(sol.t, ref.t) and np.max(np.abs(sol.y - ref.y)) < 1e-9


def test_events_that_cannot_be_traced_are_refused_by_name():
    s = n_link_pendulum(1)
    args = ((0.0, 1.0), {"q1": 1.2, "q1_dot": 0.0}, {"g": G})

    def with_math(tt, y):
        return math.sin(y[0])

    def branching(tt, y):
        return y[0] if y[1] > 0 else -y[0]

    calls = [0]

    def stateful(tt, y):
        calls[0] += 1
        return y[0] - 0.01 * calls[0]

    for ev, why in ((with_math, "with_math.*could not be traced"), (branching, "branching.*could not be traced"),
                    (stateful, "stateful.*symbolic trace"), (lambda tt, y: 1.0, "returned float")):
        with pytest.raises(MethodError, match=why):
            s.simulate(*args, method="heyoka", events=[ev])
    ok = s.simulate(*args, method="heyoka", events=[lambda tt, y: np.sin(y[0]) + 0 * tt])  # numpy functions trace
    assert ok.t_events[0].size == 1 and abs(ok.t_events[0][0] - _crossings(1.2, 1)[0]) < 1e-8


def test_registry_and_methods_table_declare_heyoka_events():
    entry = registry.get("heyoka")
    assert entry.events and "heyoka" in registry.supporting("events")
    row = next(ln for ln in registry.table().splitlines() if ln.startswith("heyoka "))
    assert row.split()[5] == "yes"  # method, family (2 words), order, step, events
