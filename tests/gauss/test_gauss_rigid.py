"""Rigid bodies as linked point clouds vs Newton–Euler (E17–E20, design T-F)."""

import numpy as np
import pytest

from lagrange.gauss.rigid import (
    cloud_inertia,
    integrate_rigid_body,
    newton_euler_accelerations,
    rigid_cloud,
    rigid_velocities,
)


def test_e18_inertia_of_a_planar_cloud():
    J = cloud_inertia([1, 1, 1, 1], [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0]])
    assert np.allclose(J, np.diag([2.0, 2.0, 4.0]))


@pytest.mark.parametrize("N, links, rank", [(4, 6, 6), (5, 10, 9), (7, 21, 15)])
def test_e19_point_cloud_kkt_equals_newton_euler(N, links, rank):
    rng = np.random.default_rng(N)
    m = rng.uniform(0.5, 2.0, N)
    x = rng.normal(size=(N, 3))
    v = rigid_velocities(m, x, rng.normal(size=3), rng.normal(size=3))
    F = rng.normal(size=(N, 3))
    body = rigid_cloud(m, x, forces=lambda t, x_, v_: F)
    r = body.accelerations(0.0, x, v)
    assert len(body.constraints) == links and r.rank == rank and r.redundant == links - rank
    assert np.max(np.abs(r.a - newton_euler_accelerations(m, x, v, F))) < 1e-12


def test_e17_e20_torque_free_symmetric_top():
    ts = np.array([0.0, 0.5, 1.0, 2.0])
    mo = integrate_rigid_body(1.0, np.diag([1.0, 1.0, 2.0]), ts, omega0=(1.0, 0.0, 3.0))
    wb = mo.body_omega()
    assert np.allclose(wb, np.c_[np.cos(3 * ts), np.sin(3 * ts), 3 * np.ones(4)], atol=1e-9)
    assert np.allclose(mo.H, [1.0, 0.0, 6.0], atol=1e-9)  # angular momentum constant in space
    QQt = np.einsum("kij,klj->kil", mo.Q, mo.Q)
    assert np.max(np.abs(QQt - np.eye(3))) < 1e-9  # Q̇ = ΩQ keeps Q orthogonal (E17)
    energy = 0.5 * np.einsum("ki,ij,kj->k", wb, np.diag([1.0, 1.0, 2.0]), wb)
    assert np.allclose(energy, 9.5)


def test_e20_point_cloud_follows_the_top():
    """Six equimomental points of the top, all pairs linked and moved by Gauss' principle, reproduce
    Euler's solution (T-F, three-way: analytic / Newton–Euler / point cloud)."""
    from lagrange.gauss.masspoints import equimomental_offsets
    from lagrange.gauss.points import simulate_points

    J0 = np.diag([2.0, 2.0, 3.0])  # a solid symmetric top (the reference's diag(1, 1, 2) is a flat lamina)
    off, mk = equimomental_offsets(6.0, J0)
    cloud = rigid_cloud(mk, off)
    w0 = np.array([1.0, 0.0, 3.0])
    ts = np.linspace(0.0, 1.0, 21)
    traj = simulate_points(cloud, ts, off, np.cross(w0, off))
    mo = integrate_rigid_body(6.0, J0, ts, omega0=w0)
    expected = np.einsum("kij,nj->kni", mo.Q, off)
    assert np.max(np.abs(traj.x - expected)) < 1e-7
    Omega = (3.0 - 2.0) / 2.0 * 3.0  # body-frame precession rate (I3 − I1) ω3 / I1
    assert np.allclose(mo.body_omega()[:, :2], np.c_[np.cos(Omega * ts), np.sin(Omega * ts)], atol=1e-9)
