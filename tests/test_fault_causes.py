"""Messages name the cause computed at the state, not a guess: gimbal lock only when Euler angles are at
θ = 0 or π there with ψ and φ both moving; an overflowing state is reported as an overflow; a NaN Lagrangian
is refused by from_mechanics.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
import sympy as sp

import lagrange as lg
from lagrange import t
from lagrange.errors import DeclarationError, IntegrationError, SingularMassMatrixError


def _tilting_body():
    """One coordinate: a body turning about its x axis only (Euler angles 0, θ, 0)."""
    th = lg.coordinates("theta")
    I1, I3 = lg.parameters("I1 I3")
    body = lg.RigidBody(1, (I1, I1, I3), orientation=lg.EulerAngles(0, th, 0))
    return lg.System([th], bodies=[body], V=0), th


def test_singular_mass_without_lockable_euler_angles_names_no_gimbal_lock():
    """θ = 0 with ψ and φ fixed cannot lock; a zero moment of inertia is the cause, and the message does not
    blame gimbal lock."""
    s, th = _tilting_body()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(SingularMassMatrixError) as info:
            s.simulate(0.1, {"theta": 0.0, "theta_dot": 1.0}, {"I1": 0.0, "I3": 1.0}, backend="python")
    assert "Gimbal" not in str(info.value) and "theta" in str(info.value)


def test_regular_one_coordinate_body_at_theta_zero_runs_quietly():
    """The quiet side: the same body with I1 > 0 at θ = 0 turns at constant rate, with no gimbal warning."""
    s, th = _tilting_body()
    with warnings.catch_warnings():
        warnings.simplefilter("error", lg.LagrangeWarning)
        warnings.simplefilter("ignore", lg.UnusedParameterWarning)
        sol = s.simulate(1.0, {"theta": 0.0, "theta_dot": 2.0}, {"I1": 1.0, "I3": 1.0}, backend="python")
    assert sol[th][-1] == pytest.approx(2.0, rel=1e-8)


def test_overflowing_state_is_reported_as_an_overflow_not_a_singularity():
    """A velocity of 1e200 makes the accelerations overflow at once: the message says so (a blow-up or values
    too large), and does not blame gimbal lock or stiffness."""
    th = lg.coordinates("theta")
    I1, m, g, l = lg.parameters("I1 m g l")
    s = lg.System([th], T=I1 * th.diff(t) ** 2 / 2, V=m * g * l * sp.cos(th))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(IntegrationError, match="overflow") as info:
            s.simulate(0.1, {"theta": 0.0, "theta_dot": 1e200}, {"I1": 1, "m": 1, "g": 9.81, "l": 1},
                       backend="python")
    assert "gimbal" not in str(info.value).lower() and "stiff" not in str(info.value)


def test_collapse_cause_at_a_singular_and_at_a_regular_state():
    """collapse_cause computed on both sides: a nearly singular mass matrix (a pendulum whose length is a
    coordinate, at zero length) is named as such; a regular state with huge forces is not."""
    from lagrange.integrate.faults import collapse_cause

    r, th = lg.coordinates("r theta")
    s = lg.System([r, th], T=(r.diff(t) ** 2 + r**2 * th.diff(t) ** 2) / 2, V=r**2 / 2)
    model = s.compile({}, backend="python")
    assert "nearly singular" in collapse_cause(model, 0.0, np.array([1e-9, 0.0, 0.0, 1.0]))
    assert "nearly singular" not in collapse_cause(model, 0.0, np.array([1.0, 0.0, 0.0, 1.0]))


@pytest.mark.parametrize("where", ["kinetic", "potential"])
def test_from_mechanics_refuses_a_nan_lagrangian(where):
    """A Lagrangian holding NaN (or an infinity) is refused with a DeclarationError naming it, not derived."""
    x = lg.coordinates("x")
    L = (sp.nan * x.diff(t) ** 2 + x**2) if where == "kinetic" else (x.diff(t) ** 2 / 2 + sp.nan * x)
    with pytest.raises(DeclarationError, match="nan|not finite"):
        lg.from_mechanics(L, [x])
    with pytest.raises(DeclarationError, match="zoo|oo|not finite"):
        lg.from_mechanics(x.diff(t) ** 2 / 2 + sp.oo * x, [x])


def test_from_mechanics_finite_lagrangian_still_derives():
    """The quiet side: a finite Lagrangian converts and gives the oscillator's equation (x'' = -x)."""
    x = lg.coordinates("x")
    s = lg.from_mechanics(x.diff(t) ** 2 / 2 - x**2 / 2, [x])
    sol = s.simulate(1.0, {"x": 1.0, "x_dot": 0.0}, {}, backend="python", rtol=1e-10, atol=1e-12)
    assert sol[x][-1] == pytest.approx(np.cos(1.0), rel=1e-7)
