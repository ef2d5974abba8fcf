"""Animations drawn from the systems' own transformation equations."""

import numpy as np
import pytest

from lagrange import EulerAngles, LagrangeError, RigidBody, System, coordinates, parameters, t
from lagrange.examples import n_link_pendulum
from lagrange.plot import animate, scene_points


def test_planar_chain_gif_and_points(tmp_path):
    s = n_link_pendulum(2)
    sol = s.simulate(1, {"q1": 1, "q2": 0.5, "q1_dot": 0, "q2_dot": 0}, {"g": 9.81}, n_points=51)
    P, axes = scene_points(s, sol)
    assert P.shape == (51, 2, 3) and not axes
    q1, q2 = sol["q1"], sol["q2"]
    assert np.allclose(P[:, 1, 0], np.sin(q1) + np.sin(q2))  # second bob from the transformation equations
    path = tmp_path / "chain.gif"
    animate(s, sol, path, frames=10)
    assert path.stat().st_size > 5_000 and path.read_bytes()[:3] == b"GIF"


def test_rigid_body_is_drawn_in_3d_with_its_axes(tmp_path):
    psi, th, ph = coordinates("psi theta phi")
    M, g, l = parameters("M g l")
    top = RigidBody(M, (1, 1, 2), orientation=EulerAngles(psi, th, ph), com=(0, 0, l))
    s = System([psi, th, ph], bodies=[top], V=M * g * top.centre_of_mass[2])
    sol = s.simulate(0.5, {psi: 0, th: 0.4, ph: 0, psi.diff(t): 1, th.diff(t): 0, ph.diff(t): 20},
                     {"M": 1, "g": 9.81, "l": 0.5}, n_points=21)
    P, axes = scene_points(s, sol)
    (i, A), = axes
    assert np.allclose(np.einsum("mij,mik->mjk", A, A), np.eye(3))  # orthonormal body axes
    assert np.allclose(np.linalg.norm(P[:, 0], axis=1), 0.5)  # the c.m. stays at distance l
    animate(s, sol, tmp_path / "top.gif", frames=5)


def test_bad_animation_targets():
    x = coordinates("x")
    s = System([x], T=x.diff(t) ** 2 / 2, V=x**2 / 2)
    sol = s.simulate(1, {x: 1, x.diff(t): 0}, {}, n_points=5)
    with pytest.raises(LagrangeError, match="no bodies"):
        animate(s, sol)
    chain = n_link_pendulum(1)
    sol = chain.simulate(0.2, {"q1": 0.1, "q1_dot": 0}, {"g": 9.81}, n_points=5)
    with pytest.raises(LagrangeError, match=".gif or .mp4"):
        animate(chain, sol, "x.avi")
