"""driving_forces on a large rigid-body system (Wells Ex. 12.6 kind: products of inertia, three angles) stays
bounded: no simplify, and the forces agree with Lagrange's expression d/dt ∂L/∂q̇ − ∂L/∂q along the motion."""

import numpy as np
import pytest
import sympy as sp

import lagrange as lg
from lagrange import RigidBody, System, coordinates, parameters, rot_x, rot_y, rot_z, t


@pytest.mark.slow
def test_driving_forces_of_a_body_with_products_of_inertia():
    th1, th2, al = coordinates("theta1 theta2 alpha")
    M, g, s, Ix, Iy, Iz, Ixy, Ixz, Iyz, w, b, nu = parameters("M g s I_x I_y I_z I_xy I_xz I_yz omega beta nu")
    inertia = sp.Matrix([[Ix, -Ixy, -Ixz], [-Ixy, Iy, -Iyz], [-Ixz, -Iyz, Iz]])
    R = rot_z(th1) * rot_x(th2) * rot_y(al)
    V = M * g * (R * sp.Matrix([0, 0, s]))[2]
    body = RigidBody(M, inertia, orientation=R, com=(0, 0, s))
    system = System([th1, th2, al], bodies=[body], V=V)
    motion = {th1: w * t, th2: b * sp.sin(nu * t), al: sp.Rational(1, 3) + t**2 / 5}
    F = lg.driving_forces(system, motion)
    assert all(sp.count_ops(f) < 2000 for f in F.values())
    # independent: L = T − V differentiated by sympy in plain symbols, then evaluated along the motion
    L = body.kinetic_energy() - V
    qs = [th1, th2, al]
    Q, Qd = sp.symbols("Q0:3"), sp.symbols("Qd0:3")
    Ls = L.subs({q.diff(t): v for q, v in zip(qs, Qd)}).subs(dict(zip(qs, Q)))
    rng = np.random.default_rng(7)
    names = [M, g, s, Ix, Iy, Iz, Ixy, Ixz, Iyz, w, b, nu]
    vals = dict(zip(names, (sp.Rational(int(v * 1000), 1000) for v in rng.uniform(0.3, 1.7, len(names)))))
    Lv = Ls.xreplace(vals)
    along = {**{Qi: motion[q].xreplace(vals) for Qi, q in zip(Q, qs)},
             **{Qdi: motion[q].diff(t).xreplace(vals) for Qdi, q in zip(Qd, qs)}}
    t_val = sp.Rational(7, 10)
    for i, q in enumerate(qs):
        p_of_t = Lv.diff(Qd[i]).xreplace(along)
        expected = (p_of_t.diff(t) - Lv.diff(Q[i]).xreplace(along)).subs(t, t_val)
        got = F[q].xreplace(vals).subs(t, t_val)
        assert abs(float(got) - float(expected)) < 1e-9 * (1 + abs(float(expected)))
