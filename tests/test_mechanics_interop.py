"""Interop with sympy.physics.mechanics both ways: dynamicsymbols in declarations, from_mechanics, to_mechanics.

The truth is sympy's own equations: accelerations from sympy's ``mass_matrix_full``/``forcing_full`` (Lagrange's
or Kane's method) are compared with lagrange's generated code at random states, to 1e-10 relative, for sympy's
pendulum (LagrangesMethod with a damping load), a cart-pole (KanesMethod and a mechanics System, with a rigid
rod, a driving force and viscous friction) and the rolling disc (non-holonomic).
"""

import numpy as np
import pytest
import sympy as sp
from sympy.physics import mechanics as me

import lagrange as lg
from lagrange import from_mechanics
from lagrange.interop.mechanics import to_mechanics
from lagrange.simplification import is_zero

RTOL = 1e-10
T_S = me.dynamicsymbols._t


def _close(a, b, rtol=RTOL):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    scale = max(float(np.max(np.abs(a))), float(np.max(np.abs(b))), 1.0)
    assert np.max(np.abs(a - b)) <= rtol * scale, f"\n{a}\n{b}"


def _solve_full(method, values) -> np.ndarray:
    """sympy's first-order form ``M_full x' = f_full`` solved at ``values``."""
    Mf = np.array(method.mass_matrix_full.xreplace(values).evalf(), dtype=float)
    ff = np.array(method.forcing_full.xreplace(values).evalf(), dtype=float).ravel()
    return np.linalg.solve(Mf, ff)


def _lagrange_accelerations(system, params, q, qd) -> np.ndarray:
    model = system.compile({s.name: v for s, v in params.items()})
    out = np.asarray(model.rhs(0.0, np.concatenate([q, qd]), model._pcall), dtype=float)
    return out[len(q):]


def _sympy_lagrange_accelerations(lm, params, coords, q, qd) -> np.ndarray:
    n = len(coords)
    values = {**params, **{c.diff(T_S): v for c, v in zip(coords, qd)}, **dict(zip(coords, q))}
    return _solve_full(lm, values)[n:2 * n]


# ------------------------------------------------------------------------------------- dynamicsymbols

def test_dynamicsymbols_are_accepted_everywhere():
    """The same model declared with sympy's dynamicsymbols and with lagrange's coordinates: rigid body, particle,
    force with a velocity, holonomic and non-holonomic constraints; identical equations."""
    m, l, g, c, I = lg.parameters("m l g c I")

    def build(x, th, s):
        d = x.args[0]  # lagrange.t, or sympy's Symbol('t')
        rod = lg.RigidBody(m, (I, I, I), origin=(x + l * sp.sin(th), -l * sp.cos(th)), orientation=lg.rot_z(th))
        bead = lg.Particle(m, (x, 0))
        return lg.System([x, th, s], bodies=[rod, bead], V=-m * g * l * sp.cos(th) + m * g * s,
                         forces=[lg.Force(bead, (-c * x.diff(d), 0)), {s: -c * s.diff(d)}],
                         T=m * s.diff(d) ** 2 / 2,
                         constraints=[lg.Holonomic(s - x * th),
                                      lg.Nonholonomic(x.diff(d) - l * sp.cos(th) * s.diff(d))])

    ours = build(*lg.coordinates("x theta s"))
    theirs = build(*me.dynamicsymbols("x theta s"))
    assert all(q.args == (lg.t,) for q in theirs.coordinates)
    a, b = ours.derived, theirs.derived
    assert [s.name for s in a.parameters] == [s.name for s in b.parameters]
    for e1, e2 in zip(list(a.mass_matrix) + list(a.forcing) + list(a.constraint_matrix),
                      list(b.mass_matrix) + list(b.forcing) + list(b.constraint_matrix)):
        assert is_zero(e1 - e2)


def test_another_time_symbol_is_refused_clearly():
    tau = sp.Symbol("tau")
    q = sp.Function("q")(tau)
    with pytest.raises(lg.DeclarationError, match="tau, which is not lagrange's time t") as err:
        lg.System([q], T=q.diff(tau) ** 2 / 2)
    assert isinstance(err.value, ValueError)
    x = me.dynamicsymbols("x")
    with pytest.raises(lg.DeclarationError, match="symbol 't' that is not lagrange.t"):
        lg.System([x], T=x.diff() ** 2 / 2 + sp.Symbol("t", positive=True))


# ------------------------------------------------------------------------------- sympy's pendulum

def _pendulum():
    """sympy's docs pendulum (LagrangesMethod), with a viscous drag load on the bob."""
    q = me.dynamicsymbols("q")
    qd = q.diff(T_S)
    m, l, g, b = sp.symbols("m l g b", positive=True)
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [q, N.z])
    A.set_ang_vel(N, qd * N.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    P = O.locatenew("P", l * A.x)
    P.v2pt_theory(O, N, A)
    bob = me.Particle("bob", P, m)
    bob.potential_energy = -m * g * l * sp.cos(q)  # N.x points down
    lm = me.LagrangesMethod(me.Lagrangian(N, bob), [q], forcelist=[(P, -b * P.vel(N))], frame=N)
    lm.form_lagranges_equations()
    return lm, [q], {m: 1.3, l: 0.8, g: 9.81, b: 0.35}


def test_pendulum_both_ways():
    lm, coords, params = _pendulum()
    system = from_mechanics(lm)
    assert isinstance(system, lg.System) and [c.func.__name__ for c in system.coordinates] == ["q"]
    rng = np.random.default_rng(1)
    back = to_mechanics(system)
    assert isinstance(back, me.LagrangesMethod)
    for _ in range(3):
        q, qd = rng.uniform(-2, 2, 1), rng.uniform(-2, 2, 1)
        expected = _sympy_lagrange_accelerations(lm, params, coords, q, qd)
        _close(_lagrange_accelerations(system, params, q, qd), expected)
        _close(_sympy_lagrange_accelerations(back, params, list(back.q), q, qd), expected)
    # the energy split: V = −L(q, 0) is the bob's potential energy, T its kinetic energy
    m, l, g = (next(s for s in params if s.name == n) for n in "mlg")
    qq = system.coordinates[0]
    assert is_zero(system.V + m * g * l * sp.cos(qq)) and is_zero(system.T - m * l**2 * qq.diff(lg.t) ** 2 / 2)
