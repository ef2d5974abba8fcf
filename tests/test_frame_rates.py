"""Frame.angular_velocity composed level by level (elementary rotations read off, no simplification) equals
vee(Ṙ Rᵀ) of the multiplied-out inertial rotation, at random values."""

import numpy as np
import sympy as sp

from lagrange import coordinates, parameters, t
from lagrange.model.frames import Frame, _elementary_rate
from lagrange.model.rotations import rot_x, rot_y, rot_z


def _vee_of_chain(frame):
    _, R = frame.to_inertial()
    W = R.diff(t) * R.T
    return sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])


def test_composed_rates_match_the_matrix_formula():
    a, b = coordinates("a b")
    w = parameters("w")
    f1 = Frame(rotation=rot_z(w * t), name="spinning")
    f2 = Frame(origin=(1, 0, 0), rotation=rot_x(a), parent=f1)
    f3 = Frame(rotation=rot_y(b) * rot_x(2 * a), parent=f2)  # not elementary: the matrix formula at its level
    f4 = Frame(rotation=rot_z(b + w * t), parent=f3)
    rng = np.random.default_rng(5)
    for f in (f1, f2, f3, f4):
        got, want = f.angular_velocity(), _vee_of_chain(f)
        atoms = sorted((got - want).free_symbols | (got - want).atoms(sp.Derivative) | {a, b}, key=str)
        for _ in range(3):
            point = {s: float(v) for s, v in zip(atoms, rng.uniform(-2, 2, len(atoms)))}
            pt = {k: v for k, v in point.items() if isinstance(k, sp.Derivative)}  # derivatives before functions
            diff = (got - want).xreplace(pt).xreplace({k: v for k, v in point.items() if k not in pt})
            assert max(abs(float(e)) for e in diff) < 1e-12


def test_elementary_rotations_are_read_off_exactly():
    a = coordinates("a")
    assert _elementary_rate(rot_x(a)) == sp.Matrix([a.diff(t), 0, 0])
    assert _elementary_rate(rot_y(3 * a)) == sp.Matrix([0, 3 * a.diff(t), 0])
    assert _elementary_rate(rot_z(a)) == sp.Matrix([0, 0, a.diff(t)])
    assert _elementary_rate(rot_z(a).T) is None  # rot_z(−a) written as a transpose: not read off, still correct
    assert _elementary_rate(rot_x(a) * rot_y(a)) is None
